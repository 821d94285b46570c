/* Stage 3 driver: every input triangle in input order, then the sub-faces of all of them
 * (collected at the end: recovering a later facet never splits an earlier one's faces,
 * since its Steiner points lie in its own open interior, but reading them last makes the
 * listing independent of that argument). */
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
  for (uint32_t i = 0; i < n; i++) {
    int outcome;
    TR_CHECK(tr_recover_facet(m, i, tris[3 * i], tris[3 * i + 1], tris[3 * i + 2], NULL, &d,
                              &outcome));
    if (outcome != TR_FACET_PRESENT)
      s.missing_facets++;
    if (outcome == TR_FACET_BY_SWAP32)
      s.recovered_by_swap++;
  }
  s.points_added = d.steiner + d.h_points;
  if (st)
    *st = s;
  if (!sub)
    return TR_OK;
  tr_u32buf v = {0}, tri = {0};
  tr_status r = TR_OK;
  for (uint32_t i = 0; i < n && r == TR_OK; i++) {
    size_t before = v.n;
    int present;
    r = tr_facet_faces(m, i, tris[3 * i], tris[3 * i + 1], tris[3 * i + 2], &present, &v);
    if (r == TR_OK && !present)
      r = tr_error(TR_ERR_INTERNAL, "facet %u missing after recovery", i);
    for (size_t k = before; k < v.n && r == TR_OK; k += 3)
      r = tr_u32buf_push(&tri, i);
  }
  if (r != TR_OK) {
    tr_u32buf_free(&v);
    tr_u32buf_free(&tri);
    return r;
  }
  sub->n = (uint32_t)tri.n;
  sub->v = v.a;
  sub->tri = tri.a;
  return TR_OK;
}
