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
 * Flat edges (tr_flat_edges): the edges inside a flat region (an inner edge of a planar
 * facet of core/facets.h), which edge recovery takes after the feature edges
 * (recover_edges.c). */
#include <stdlib.h>
#include <string.h>

#include "core/facets.h"
#include "core/vtmap.h"
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
                                   const uint32_t *edges, uint32_t ne, uint64_t *nswaps)
{
  *nswaps = 0;
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
  if (st == TR_OK && nmiss && plc->ntris >= 2)
    st = tr_smooth_surface_rule(plc, toward_mesh, &c, nswaps);
  tr_vtmap_free(&c.missing);
  return st;
}

tr_status tr_flat_edges(const struct tr_plc *plc, const uint32_t *edges, uint32_t n,
                        uint8_t *flat)
{
  /* the inner edges of refinement's planar facets: one definition of a flat region */
  tr_facets F;
  TR_CHECK(tr_facets_build(plc, 0, &F));
  memset(flat, 0, n);
  for (uint32_t t = 0; t < plc->ntris; t++)
    for (int k = 0; k < 3; k++)
      if (F.inner[t] >> k & 1) {
        uint32_t i = tr_edge_index(edges, n, plc->tris[3 * t + k],
                                   plc->tris[3 * t + (k + 1) % 3]);
        if (i != TR_NONE)
          flat[i] = 1;
      }
  tr_facets_free(&F);
  /* a segment along a flat edge keeps it a feature */
  for (uint32_t s = 0; s < plc->nsegs; s++) {
    uint32_t i = tr_edge_index(edges, n, plc->segs[2 * (size_t)s], plc->segs[2 * (size_t)s + 1]);
    if (i != TR_NONE)
      flat[i] = 0;
  }
  return TR_OK;
}
