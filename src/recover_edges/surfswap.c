/* What edge recovery needs to know of the surface's flat regions.
 *
 * Surface diagonal swaps towards the Delaunay mesh (tr_surface_swaps_to_mesh): CAD and
 * 3D-printing surfaces cut their planar faces into fans and grids of cocircular points,
 * where the smoothing before Delaunay (src/smooth) cannot tell one diagonal from the other
 * and the mesh's symbolic perturbation picks its own; each such input edge is missing for
 * no reason but that choice. A diagonal AC of two exactly coplanar input triangles with
 * one marker is swapped for BD when the mesh lacks AC and has BD, the quad being strictly
 * convex (src/smooth's conditions: the surface as a point set and its marker map stay as
 * they are). Every swap trades an input edge the mesh lacks for one it has, so the passes
 * end. 65395.stl of Thingi10K: 733 missing edges -> 640.
 *
 * Flat edges (tr_flat_edges): the edges inside a flat region, which edge recovery takes
 * after the feature edges (recover_edges.c). */
#include <stdlib.h>

#include "core/vtmap.h"
#include "predicates.h"
#include "recover_edges.h"
#include "smooth/smooth.h"

typedef struct swap_ctx {
  struct tr_mesh *m;
  tr_vtmap missing; /* the input edges the mesh lacks (swaps only ever remove some) */
} swap_ctx;

static int toward_mesh(void *user, const double *const q[4], uint32_t A, uint32_t B,
                       uint32_t C, uint32_t D)
{
  (void)q;
  swap_ctx *c = user;
  uint32_t k[2], t = TR_NONE;
  tr_vtkey_edge(A, C, k);
  if (tr_vtmap_get(&c->missing, 2, k) == TR_VTMAP_NONE)
    return 0;
  /* rare (quads around a missing edge): a ball look-up each, no map of the mesh's edges */
  return tr_ball_find(c->m, B, D, TR_NONE, &t) == TR_OK && t != TR_NONE;
}

tr_status tr_surface_swaps_to_mesh(struct tr_plc *plc, struct tr_mesh *m,
                                   const uint32_t *edges, uint32_t ne, uint64_t *nswaps,
                                   uint32_t *nmissing)
{
  *nswaps = 0;
  *nmissing = 0;
  if (ne == 0)
    return TR_OK;
  uint8_t *there = malloc(ne);
  if (!there)
    return tr_error(TR_ERR_NOMEM, "out of memory for %u input edges", ne);
  swap_ctx c = {m, {0}};
  tr_status st = tr_mesh_find_edges(m, edges, ne, there);
  uint32_t nmiss = 0;
  for (uint32_t i = 0; st == TR_OK && i < ne; i++)
    if (!there[i]) {
      st = tr_vtmap_put(&c.missing, 2, edges + 2 * (size_t)i, 1, NULL);
      nmiss++;
    }
  free(there);
  *nmissing = nmiss;
  if (st == TR_OK && nmiss && plc->ntris >= 2)
    st = tr_smooth_surface_rule(plc, toward_mesh, &c, nswaps);
  tr_vtmap_free(&c.missing);
  return st;
}

tr_status tr_flat_edges(const struct tr_plc *plc, const uint32_t *edges, uint32_t n,
                        uint8_t *flat)
{
  /* edge -> the triangle that lists it first, and in a second map the one that lists
   * it second (TR_NONE once a third does: non-manifold) */
  tr_vtmap first = {0}, second = {0};
  tr_status st = tr_vtmap_reserve(&first, 2, 3 * plc->ntris / 2 + 8);
  for (uint32_t t = 0; st == TR_OK && t < plc->ntris; t++)
    for (int j = 0; j < 3 && st == TR_OK; j++) {
      uint32_t k[2], got;
      tr_vtkey_edge(plc->tris[3 * t + j], plc->tris[3 * t + (j + 1) % 3], k);
      if ((st = tr_vtmap_put(&first, 2, k, t, &got)) != TR_OK || got == t)
        continue;
      uint32_t r[2] = {k[1], k[0]};
      st = tr_vtmap_put(&second, 2, r, t, &got);
      if (st == TR_OK && got != t)
        st = tr_vtmap_set(&second, 2, r, TR_NONE);
    }
  for (uint32_t i = 0; st == TR_OK && i < n; i++) {
    flat[i] = 0;
    uint32_t k[2] = {edges[2 * (size_t)i], edges[2 * (size_t)i + 1]}, r[2] = {k[1], k[0]};
    uint32_t t1 = tr_vtmap_get(&first, 2, k), t2 = tr_vtmap_get(&second, 2, r);
    if (t1 == TR_VTMAP_NONE || t2 == TR_VTMAP_NONE)
      continue; /* a segment, an open edge or a non-manifold one */
    if (plc->tri_marker && plc->tri_marker[t1] != plc->tri_marker[t2])
      continue;
    uint32_t d = TR_NONE;
    for (int j = 0; j < 3; j++)
      if (plc->tris[3 * t2 + j] != k[0] && plc->tris[3 * t2 + j] != k[1])
        d = plc->tris[3 * t2 + j];
    const double *X = plc->xyz;
    const uint32_t *v = plc->tris + 3 * (size_t)t1;
    flat[i] = tr_orient3d(X + 3 * (size_t)v[0], X + 3 * (size_t)v[1], X + 3 * (size_t)v[2],
                          X + 3 * (size_t)d) == 0;
  }
  /* a segment along a flat edge keeps it a feature */
  for (uint32_t s = 0; st == TR_OK && s < plc->nsegs; s++) {
    uint32_t a = plc->segs[2 * (size_t)s], b = plc->segs[2 * (size_t)s + 1];
    if (a > b) {
      uint32_t x = a;
      a = b;
      b = x;
    }
    uint32_t lo = 0, hi = n;
    while (lo < hi) {
      uint32_t mid = lo + (hi - lo) / 2;
      if (edges[2 * (size_t)mid] < a ||
          (edges[2 * (size_t)mid] == a && edges[2 * (size_t)mid + 1] < b))
        lo = mid + 1;
      else
        hi = mid;
    }
    if (lo < n && edges[2 * (size_t)lo] == a && edges[2 * (size_t)lo + 1] == b)
      flat[lo] = 0;
  }
  tr_vtmap_free(&first);
  tr_vtmap_free(&second);
  return st;
}
