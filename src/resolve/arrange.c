/* The arrangement: cuts per pair, pieces per triangle, identical pieces merged.
 *
 * Why merging suffices: two input triangles that overlap in their plane are each cut
 * along the other's boundary (pairs.c), so their common region is bounded by cuts in
 * both, carries the same points and cuts in both, and is triangulated alike (cdt.c).
 * What is left of an overlap is pieces with the same three vertices, which become one
 * piece listing every source triangle with the sign of its orientation relative to the
 * piece (what the winding number of the next step counts). */
#include <stdlib.h>
#include <string.h>

#include "resolve/resolve_impl.h"

void tr_arrangement_free(tr_arrangement *arr)
{
  for (uint32_t i = 0; arr->verts && i < arr->nverts; i++)
    if (arr->verts[i].q) {
      tr_qpoint_clear(arr->verts[i].q);
      free(arr->verts[i].q);
    }
  free(arr->verts);
  free(arr->pieces);
  free(arr->src);
  free(arr->of_input);
  memset(arr, 0, sizeof *arr);
}

/* The cuts grouped by triangle, each group in the order found: start[t] .. start[t+1). */
static tr_status group(const rs_cut *cuts, size_t n, uint32_t ntris, size_t **start,
                       rs_cut **sorted)
{
  *start = calloc((size_t)ntris + 1, sizeof **start);
  *sorted = malloc(sizeof **sorted * (n ? n : 1));
  if (!*start || !*sorted)
    return tr_error(TR_ERR_NOMEM, "arrangement: out of memory for %zu cuts", n);
  for (size_t i = 0; i < n; i++)
    (*start)[cuts[i].tri + 1]++;
  for (uint32_t t = 0; t < ntris; t++)
    (*start)[t + 1] += (*start)[t];
  for (size_t i = 0; i < n; i++)
    (*sorted)[(*start)[cuts[i].tri]++] = cuts[i];
  for (uint32_t t = ntris; t > 0; t--)
    (*start)[t] = (*start)[t - 1];
  (*start)[0] = 0;
  return TR_OK;
}

/* Pieces raw[3i..] from triangle rt[i], merged into arr (pieces and sources). */
static tr_status merge(tr_arrangement *arr, const struct tr_plc *plc, const uint32_t *raw,
                       const uint32_t *rt, size_t nraw)
{
  if (nraw >= TR_ARR_NONE)
    return tr_error(TR_ERR_NOMEM, "arrangement: more than 2^32 pieces");
  tr_vtmap map = {0};
  uint32_t *of = malloc(sizeof *of * (nraw ? nraw : 1)); /* raw piece -> piece */
  int32_t *sg = malloc(sizeof *sg * (nraw ? nraw : 1));
  arr->pieces = malloc(sizeof *arr->pieces * (nraw ? nraw : 1));
  arr->src = malloc(sizeof *arr->src * (nraw ? nraw : 1));
  tr_status st = TR_OK;
  if (!of || !sg || !arr->pieces || !arr->src) {
    st = tr_error(TR_ERR_NOMEM, "arrangement: out of memory for %zu pieces", nraw);
    goto done;
  }
  if ((st = tr_vtmap_reserve(&map, 3, (uint32_t)nraw)) != TR_OK)
    goto done;
  uint32_t np = 0;
  for (size_t i = 0; i < nraw; i++) {
    const uint32_t *v = raw + 3 * i;
    uint32_t k[3], p;
    tr_vtkey_face(v[0], v[1], v[2], k);
    if ((st = tr_vtmap_put(&map, 3, k, np, &p)) != TR_OK)
      goto done;
    of[i] = p;
    sg[i] = 1;
    if (p == np) {
      tr_arr_piece *x = arr->pieces + np++;
      memcpy(x->v, v, sizeof x->v);
      x->nsrc = 0;
      x->marker = plc->tri_marker ? plc->tri_marker[rt[i]] : 0;
    } else {
      const uint32_t *w = arr->pieces[p].v;
      int j = w[0] == v[0] ? 0 : w[1] == v[0] ? 1 : 2;
      sg[i] = w[(j + 1) % 3] == v[1] ? 1 : -1;
    }
    arr->pieces[p].nsrc++;
  }
  arr->npieces = np;
  arr->nsrc = (uint32_t)nraw;
  /* sources by piece, each piece's in triangle order (raw pieces come by triangle) */
  for (uint32_t p = 0, s = 0; p < np; p++) {
    arr->pieces[p].src = s;
    s += arr->pieces[p].nsrc;
    arr->pieces[p].nsrc = 0;
  }
  for (size_t i = 0; i < nraw; i++) {
    tr_arr_piece *x = arr->pieces + of[i];
    tr_arr_source *y = arr->src + x->src + x->nsrc++;
    y->tri = rt[i];
    y->sign = sg[i];
  }
done:
  tr_vtmap_free(&map);
  free(of);
  free(sg);
  return st;
}

tr_status tr_arrangement_build(const struct tr_plc *plc, tr_arrangement *arr)
{
  memset(arr, 0, sizeof *arr);
  rs_points ps;
  rs_input in;
  memset(&ps, 0, sizeof ps);
  memset(&in, 0, sizeof in);
  rs_cut *cuts = NULL, *sorted = NULL;
  size_t ncuts = 0, *start = NULL, nraw = 0, craw = 0, crt = 0;
  uint32_t *raw = NULL, *rt = NULL;
  rs_sub *sub = NULL;
  tr_status st;
  if (!(arr->of_input = malloc(sizeof *arr->of_input * (plc->npoints ? plc->npoints : 1)))) {
    st = tr_error(TR_ERR_NOMEM, "arrangement: out of memory for %u points", plc->npoints);
    goto done;
  }
  if ((st = rs_points_init(&ps, plc, arr->of_input, &arr->ndup_points)) != TR_OK ||
      (st = rs_input_init(&in, &ps, arr->of_input, &arr->ndropped)) != TR_OK ||
      (st = rs_pair_cuts(&in, &ps, &cuts, &ncuts, &arr->npairs, &arr->ncoplanar)) != TR_OK ||
      (st = group(cuts, ncuts, in.ntris, &start, &sorted)) != TR_OK ||
      (st = rs_sub_create(&sub)) != TR_OK)
    goto done;
  for (uint32_t t = 0; t < in.ntris; t++) {
    if (!in.live[t])
      continue;
    size_t n0 = nraw;
    if (start[t] == start[t + 1]) { /* uncut: the triangle is its own piece */
      if ((st = rs_grow((void **)&raw, 3 * sizeof *raw, nraw + 1, &craw)) != TR_OK)
        goto done;
      memcpy(raw + 3 * nraw++, in.tris + 3 * (size_t)t, 3 * sizeof *raw);
    } else if ((st = rs_subdivide(sub, &in, &ps, t, sorted + start[t], start[t + 1] - start[t],
                                  &raw, &nraw, &craw, &arr->ncrossings)) != TR_OK) {
      goto done;
    }
    if ((st = rs_grow((void **)&rt, sizeof *rt, nraw, &crt)) != TR_OK)
      goto done;
    for (size_t i = n0; i < nraw; i++)
      rt[i] = t;
  }
  if ((st = merge(arr, plc, raw, rt, nraw)) != TR_OK)
    goto done;
  arr->verts = ps.v;
  arr->nverts = ps.n;
  ps.v = NULL;
  ps.n = 0;
done:
  rs_sub_destroy(sub);
  rs_points_free(&ps);
  rs_input_free(&in);
  free(cuts);
  free(sorted);
  free(start);
  free(raw);
  free(rt);
  return st;
}
