/* Stage 3 driver: every input triangle in input order, with its sub-faces. */
#include "recover_facets/recover_facets.h"

#include <stdlib.h>
#include <string.h>

#include "recover_edges/edgeset.h"
#include "recover_facets/facet.h"

/* The sub-faces listed so far (sorted triples, open addressing, fixed hash: no seed) and
 * the constraint edges: what the flips of later facets must keep. */
typedef struct keep {
  tr_edgeset cons;
  uint32_t *f; /* 3 per slot, f[3i] == TR_NONE: empty */
  uint32_t n, cap;
} keep;

static uint32_t face_slot(const keep *k, const uint32_t o[3])
{
  uint32_t i = (uint32_t)(tr_hash3(o) >> 32) & (k->cap - 1);
  while (k->f[3 * (size_t)i] != TR_NONE &&
         (k->f[3 * (size_t)i] != o[0] || k->f[3 * (size_t)i + 1] != o[1] ||
          k->f[3 * (size_t)i + 2] != o[2]))
    i = (i + 1) & (k->cap - 1);
  return i;
}

static tr_status keep_face(keep *k, const uint32_t *v)
{
  if (2 * (k->n + 1) > k->cap) {
    uint32_t nc = k->cap ? 2 * k->cap : 1024, *old = k->f, oc = k->cap;
    k->f = malloc(3 * (size_t)nc * sizeof *k->f);
    if (!k->f) {
      k->f = old;
      return tr_error(TR_ERR_NOMEM, "out of memory for the sub-face set");
    }
    memset(k->f, 0xff, 3 * (size_t)nc * sizeof *k->f);
    k->cap = nc;
    for (uint32_t i = 0; i < oc; i++)
      if (old[3 * (size_t)i] != TR_NONE) {
        uint32_t j = face_slot(k, old + 3 * (size_t)i);
        memcpy(k->f + 3 * (size_t)j, old + 3 * (size_t)i, 3 * sizeof *old);
      }
    free(old);
  }
  uint32_t o[3];
  memcpy(o, v, 3 * sizeof *o);
  tr_sort3(o);
  uint32_t j = face_slot(k, o);
  if (k->f[3 * (size_t)j] == TR_NONE) {
    memcpy(k->f + 3 * (size_t)j, o, sizeof o);
    k->n++;
  }
  return TR_OK;
}

static int keep_guard(void *ud, const uint32_t *v, int nv)
{
  const keep *k = ud;
  if (nv == 2)
    return tr_edgeset_get(&k->cons, v[0], v[1]) != TR_EDGESET_NONE;
  if (k->cap == 0)
    return 0;
  uint32_t o[3];
  memcpy(o, v, 3 * sizeof *o);
  tr_sort3(o);
  return k->f[3 * (size_t)face_slot(k, o)] != TR_NONE;
}

void tr_subfaces_free(tr_subfaces *s)
{
  if (!s)
    return;
  free(s->v);
  free(s->tri);
  s->v = NULL;
  s->tri = NULL;
  s->n = 0;
}

/* `chains` only feeds the set of constraint edges the flips must keep (the pieces of the
 * input edges): the cluster of a facet is found from its corners, and its boundary
 * vertices (the chains' Steiner points) show up as on-plane clusterel nodes. */
tr_status tr_recover_facets(struct tr_mesh *m, const uint32_t *tris, uint32_t n,
                            const tr_edge_chains *chains, tr_subfaces *sub,
                            tr_facet_recovery_stats *st)
{
  return tr_recover_facets_ex(m, tris, n, chains, NULL, sub, st);
}

tr_status tr_recover_facets_ex(struct tr_mesh *m, const uint32_t *tris, uint32_t n,
                               const tr_edge_chains *chains, const tr_facet_recovery_opts *fo,
                               tr_subfaces *sub, tr_facet_recovery_stats *st)
{
  tr_facet_detail d = {0};
  tr_facet_opts opt = {0};
  opt.no_flips = opt.no_cavity = fo && fo->paper;
  opt.no_flips |= fo && fo->no_flips;
  keep kp;
  memset(&kp, 0, sizeof kp);
  for (uint32_t c = 0; chains && c < chains->n; c++)
    for (uint32_t k = chains->start[c]; k + 1 < chains->start[c + 1]; k++) {
      tr_status e2 = tr_edgeset_put(&kp.cons, chains->v[k], chains->v[k + 1], c);
      if (e2 != TR_OK) {
        tr_edgeset_free(&kp.cons);
        return e2;
      }
    }
  /* Without chains the triangles' edges are mesh edges (the caller recovered them
   * without Steiner points): they are the constraint edges. Unprotected, the flips for
   * one facet could take away an edge of another, whose cluster is then ill-formed. */
  for (uint32_t i = 0; !chains && i < n; i++)
    for (int q = 0; q < 3; q++) {
      tr_status e2 = tr_edgeset_put(&kp.cons, tris[3 * i + q], tris[3 * i + (q + 1) % 3], i);
      if (e2 != TR_OK) {
        tr_edgeset_free(&kp.cons);
        return e2;
      }
    }
  opt.guard = keep_guard;
  opt.guard_ud = &kp;
  /* Which facets are faces already, in one pass over the tets instead of a ball search
   * per facet (most facets of a fine surface are). */
  uint32_t *hint = malloc(sizeof *hint * (n ? n : 1));
  if (!hint) {
    tr_edgeset_free(&kp.cons);
    return tr_error(TR_ERR_NOMEM, "out of memory for %u facet hints", n);
  }
  tr_status hs = tr_mesh_find_faces(m, tris, n, hint);
  if (hs != TR_OK) {
    free(hint);
    tr_edgeset_free(&kp.cons);
    return hs;
  }
  opt.hint = hint;
  tr_facet_recovery_stats s = {0};
  if (sub) {
    sub->n = 0;
    sub->v = NULL;
    sub->tri = NULL;
  }
  /* Each facet's faces are listed right after its recovery: a later facet never splits
   * them (its Steiner points lie in its own open interior, which meets no other input
   * triangle), and the tests check the final listing against the final mesh. */
  tr_u32buf v = {0}, tri = {0};
  tr_status r = TR_OK;
  for (uint32_t i = 0; i < n && r == TR_OK; i++) {
    int outcome;
    size_t before = v.n;
    r = tr_recover_facet(m, i, tris[3 * i], tris[3 * i + 1], tris[3 * i + 2], &opt, &d,
                         &outcome, &v);
    if (r != TR_OK)
      break;
    if (outcome != TR_FACET_PRESENT)
      s.missing_facets++;
    if (outcome == TR_FACET_BY_SWAP32 || outcome == TR_FACET_BY_FLIPS)
      s.recovered_by_swap++;
    else if (outcome == TR_FACET_BY_CAVITY)
      s.recovered_by_cavity++;
    for (size_t k = before; k < v.n && r == TR_OK; k += 3) {
      r = tr_u32buf_push(&tri, i);
      if (r == TR_OK)
        r = keep_face(&kp, v.a + k);
    }
  }
  tr_edgeset_free(&kp.cons);
  free(kp.f);
  free(hint);
  s.points_added = d.steiner + d.h_points;
  s.by_flips = d.by_flips;
  s.flip23 = d.flips.flip23;
  s.flip32 = d.flips.flip32;
  s.flip44 = d.flips.flip44;
  s.flipn = d.flips.flipn;
  s.flips_undone = d.flips.undone;
  s.cavity_tried = d.cavity.tried;
  s.cavity_expanded = d.cavity.expanded;
  if (st)
    *st = s;
  if (r != TR_OK || !sub) {
    tr_u32buf_free(&v);
    tr_u32buf_free(&tri);
    return r;
  }
  sub->n = (uint32_t)tri.n;
  sub->v = v.a;
  sub->tri = tri.a;
  return TR_OK;
}
