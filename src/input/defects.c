/* Every defect of a surface at once (defects.h): the analysis `tetrec check-surface`
 * prints and `tetrec resolve` counts on its rounded surface. */
#include <stdlib.h>
#include <string.h>

#include "core/edgesort.h"
#include "core/vtmap.h"
#include "input/defects.h"
#include "input/validate.h"
#include "predicates.h"

void tr_surface_defects_free(tr_surface_defects *d)
{
  free(d->zero);
  free(d->dup);
  free(d->edge);
  free(d->edge_start);
  free(d->edge_tri);
  free(d->pairs);
  memset(d, 0, sizeof *d);
}

static int zero_area(const double *x, const uint32_t *t)
{
  const double *a = x + 3 * (size_t)t[0], *b = x + 3 * (size_t)t[1], *c = x + 3 * (size_t)t[2];
  for (int k = 0; k < 3; k++)
    if (tr_orient2d_proj(a, b, c, k) != 0)
      return 0;
  return 1;
}

/* Duplicates (copy, first), compact numbers, in the order of their vertex set. */
typedef struct {
  const uint32_t *tris, *dup;
} dup_order;

static int cmp_dup(const void *ctx, uint32_t a, uint32_t b)
{
  const dup_order *o = ctx;
  const uint32_t *s = o->tris + 3 * (size_t)o->dup[2 * (size_t)a + 1],
                 *t = o->tris + 3 * (size_t)o->dup[2 * (size_t)b + 1];
  uint32_t p[3], q[3];
  tr_vtkey_face(s[0], s[1], s[2], p);
  tr_vtkey_face(t[0], t[1], t[2], q);
  for (int i = 0; i < 3; i++)
    if (p[i] != q[i])
      return p[i] < q[i] ? -1 : 1;
  return 0;
}

/* The duplicates among w's nt triangles into d (compact numbers for now) and drop[]. A
 * hash of vertex sets finds them in one pass; only the few found are sorted, into the
 * order a sort of every triangle by its set would list them. */
static tr_status duplicates(const uint32_t *tris, uint32_t nt, uint8_t *drop,
                            tr_surface_defects *d)
{
  tr_vtmap map = {0};
  uint32_t *dup = NULL, *ord = NULL, cap = 0;
  tr_status st = tr_vtmap_reserve(&map, 3, nt);
  for (uint32_t t = 0; st == TR_OK && t < nt; t++) {
    uint32_t k[3], first;
    const uint32_t *v = tris + 3 * (size_t)t;
    tr_vtkey_face(v[0], v[1], v[2], k);
    if ((st = tr_vtmap_put(&map, 3, k, t, &first)) != TR_OK || first == t)
      continue;
    if (d->ndup == cap) {
      cap = cap ? 2 * cap : 16;
      uint32_t *x = realloc(dup, sizeof *x * 2 * (size_t)cap);
      if (!x) {
        st = tr_error(TR_ERR_NOMEM, "out of memory listing duplicate triangles");
        break;
      }
      dup = x;
    }
    dup[2 * (size_t)d->ndup] = t;
    dup[2 * (size_t)d->ndup + 1] = first;
    d->ndup++;
    drop[t] = 1;
  }
  tr_vtmap_free(&map);
  uint32_t n = d->ndup;
  if (st == TR_OK && n) {
    ord = malloc(sizeof *ord * n);
    d->dup = malloc(sizeof *d->dup * 2 * (size_t)n);
    if (!ord || !d->dup)
      st = tr_error(TR_ERR_NOMEM, "out of memory sorting %u duplicate triangles", n);
  }
  for (uint32_t i = 0; st == TR_OK && i < n; i++)
    ord[i] = i;
  dup_order o = {tris, dup};
  if (st == TR_OK && n)
    st = tr_sort_ids(ord, n, cmp_dup, &o); /* stable: copies stay increasing */
  for (uint32_t i = 0; st == TR_OK && i < n; i++)
    memcpy(d->dup + 2 * (size_t)i, dup + 2 * (size_t)ord[i], 2 * sizeof *dup);
  free(dup);
  free(ord);
  return st;
}

/* The open and non-manifold edges of w's nt triangles into d; keep maps w to the PLC. */
static tr_status census(const uint32_t *tris, uint32_t nt, uint32_t nv, const uint32_t *keep,
                        tr_surface_defects *d)
{
  uint32_t *slots = malloc(sizeof *slots * 3 * (size_t)(nt ? nt : 1));
  d->edge_start = malloc(sizeof *d->edge_start);
  if (!slots || !d->edge_start) {
    free(slots);
    return tr_error(TR_ERR_NOMEM, "out of memory for the edges of %u triangles", nt);
  }
  d->edge_start[0] = 0;
  tr_status st = tr_edge_slots_sorted(tris, nt, nv, slots);
  uint32_t cap = 0, tcap = 0, ntri = 0;
  for (uint32_t i = 0, j; st == TR_OK && i < 3 * nt; i = j) {
    uint32_t s = slots[i], a = tris[s], b = tris[s / 3 * 3 + (s % 3 + 1) % 3];
    for (j = i + 1; j < 3 * nt; j++) {
      uint32_t s2 = slots[j], a2 = tris[s2], b2 = tris[s2 / 3 * 3 + (s2 % 3 + 1) % 3];
      if ((a2 < b2 ? a2 : b2) != (a < b ? a : b) || (a2 < b2 ? b2 : a2) != (a < b ? b : a))
        break;
    }
    if (j - i == 2)
      continue;
    if (d->nedges == cap || ntri + (j - i) > tcap) {
      cap = d->nedges == cap ? (cap ? 2 * cap : 16) : cap;
      while (ntri + (j - i) > tcap)
        tcap = tcap ? 2 * tcap : 32;
      uint32_t *e = realloc(d->edge, sizeof *e * 2 * (size_t)cap);
      if (e)
        d->edge = e;
      uint32_t *es = e ? realloc(d->edge_start, sizeof *es * ((size_t)cap + 1)) : NULL;
      if (es)
        d->edge_start = es;
      uint32_t *et = es ? realloc(d->edge_tri, sizeof *et * (size_t)tcap) : NULL;
      if (!et) {
        st = tr_error(TR_ERR_NOMEM, "out of memory listing open and non-manifold edges");
        break;
      }
      d->edge_tri = et;
    }
    d->edge[2 * (size_t)d->nedges] = a < b ? a : b;
    d->edge[2 * (size_t)d->nedges + 1] = a < b ? b : a;
    for (uint32_t k = i; k < j; k++)
      d->edge_tri[ntri++] = keep[slots[k] / 3];
    d->edge_start[++d->nedges] = ntri;
    if (j - i == 1)
      d->nopen++;
    else
      d->nnonmanifold++;
  }
  free(slots);
  return st;
}

tr_status tr_surface_defects_find(const struct tr_plc *plc, tr_surface_defects *d)
{
  memset(d, 0, sizeof *d);
  uint32_t nv = plc->npoints, nt = plc->ntris;
  uint32_t *ord = malloc(sizeof *ord * (nv ? nv : 1)), *rep = malloc(sizeof *rep * (nv ? nv : 1));
  uint32_t *keep = malloc(sizeof *keep * (nt ? nt : 1));
  uint8_t *drop = calloc(nt ? nt : 1, 1);
  struct tr_plc w;
  memset(&w, 0, sizeof w);
  w.tris = malloc(sizeof *w.tris * 3 * (size_t)(nt ? nt : 1));
  d->zero = malloc(sizeof *d->zero * (nt ? nt : 1));
  tr_status st = ord && rep && keep && drop && w.tris && d->zero
                     ? TR_OK
                     : tr_error(TR_ERR_NOMEM, "out of memory checking %u triangles", nt);
  /* exact duplicates -> the first of their copies in coordinate order: the least index */
  for (uint32_t i = 0; st == TR_OK && i < nv; i++)
    ord[i] = i;
  if (st == TR_OK)
    st = tr_sort_ids(ord, nv, tr_cmp_point, plc->xyz);
  for (uint32_t i = 0; st == TR_OK && i < nv; i++)
    rep[ord[i]] = i && tr_cmp_point(plc->xyz, ord[i - 1], ord[i]) == 0 ? rep[ord[i - 1]] : ord[i];
  w.npoints = nv;
  w.xyz = plc->xyz;
  for (uint32_t t = 0; st == TR_OK && t < nt; t++) {
    uint32_t v[3];
    for (int k = 0; k < 3; k++)
      v[k] = rep[plc->tris[3 * (size_t)t + k]];
    if (zero_area(plc->xyz, v)) {
      d->zero[d->nzero++] = t;
      continue;
    }
    memcpy(w.tris + 3 * (size_t)w.ntris, v, sizeof v);
    keep[w.ntris++] = t;
  }
  if (st == TR_OK)
    st = duplicates(w.tris, w.ntris, drop, d);
  for (uint32_t i = 0; st == TR_OK && i < 2 * d->ndup; i++)
    d->dup[i] = keep[d->dup[i]];
  if (st == TR_OK) {
    uint32_t n = 0;
    for (uint32_t t = 0; t < w.ntris; t++)
      if (!drop[t]) {
        memmove(w.tris + 3 * (size_t)n, w.tris + 3 * (size_t)t, 3 * sizeof *w.tris);
        keep[n++] = keep[t];
      }
    w.ntris = n;
    st = census(w.tris, w.ntris, nv, keep, d);
  }
  if (st == TR_OK)
    st = tr_input_self_intersection_pairs(&w, TR_SELFINT_AUTO, &d->pairs, &d->npairs);
  for (size_t i = 0; st == TR_OK && i < 2 * d->npairs; i++)
    d->pairs[i] = keep[d->pairs[i]];
  free(ord);
  free(rep);
  free(keep);
  free(drop);
  free(w.tris);
  return st;
}
