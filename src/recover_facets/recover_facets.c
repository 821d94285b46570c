/* Stage 3 driver: every input triangle in input order, with its sub-faces. */
#include "recover_facets/recover_facets.h"

#include <stdlib.h>

#include "recover_facets/facet.h"

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

/* `chains` is not needed: the cluster of a facet is found from its corners, and its
 * boundary vertices (the chains' Steiner points) show up as on-plane clusterel nodes. */
tr_status tr_recover_facets(struct tr_mesh *m, const uint32_t *tris, uint32_t n,
                            const tr_edge_chains *chains, tr_subfaces *sub,
                            tr_facet_recovery_stats *st)
{
  (void)chains;
  tr_facet_detail d = {0};
  tr_facet_recovery_stats s = {0, 0, 0};
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
    r = tr_recover_facet(m, i, tris[3 * i], tris[3 * i + 1], tris[3 * i + 2], NULL, &d,
                         &outcome, sub ? &v : NULL);
    if (r != TR_OK)
      break;
    if (outcome != TR_FACET_PRESENT)
      s.missing_facets++;
    if (outcome == TR_FACET_BY_SWAP32)
      s.recovered_by_swap++;
    for (size_t k = before; k < v.n && r == TR_OK; k += 3)
      r = tr_u32buf_push(&tri, i);
  }
  s.points_added = d.steiner + d.h_points;
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
