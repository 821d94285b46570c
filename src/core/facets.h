/* Planar facets for refinement: edge-adjacent input triangles that are EXACTLY coplanar
 * (exact orient3d of the fourth vertex = 0 on the input doubles), share a manifold edge
 * (exactly two triangles on it), have the same boundary marker, use the edge in opposite
 * directions (consistent orientation) and lie on opposite sides of it are one facet, a
 * planar polygon (possibly with holes). The edges inside a facet ("inner" edges) are no
 * constraints for refinement: its sub-faces may cross them. Used by refinement, the
 * conformity validator and `tetrec check`, so that all three agree. */
#ifndef TR_CORE_FACETS_H
#define TR_CORE_FACETS_H

#include <stdint.h>

#include "core/plc.h"

typedef struct tr_facets {
  uint32_t ntris;
  uint32_t *group;   /* per triangle: its facet's id = the smallest triangle index in it */
  uint8_t *inner;    /* per triangle, bit k: edge (tris[3t+k], tris[3t+(k+1)%3]) is inner */
  uint32_t *start;   /* CSR by group id: members of group g (g a group id) are
                        member[start[g] .. start[g+1]), increasing; empty for non-ids */
  uint32_t *member;
  uint32_t ninner;   /* inner edges (each counted once): input edges merged away */
  uint32_t nmerged;  /* facets of two or more triangles */
} tr_facets;

/* Groups plc's triangles (union-find, deterministic). keep_edges: every triangle alone. */
tr_status tr_facets_build(const struct tr_plc *plc, int keep_edges, tr_facets *out);
void tr_facets_free(tr_facets *f);
/* dst = a copy of src (dst is overwritten, not freed). */
tr_status tr_facets_copy(tr_facets *dst, const tr_facets *src);

/* An axis along which input triangle t's projection is not degenerate (its normal's
 * component there is non-zero, exact), -1 if none: the projection facets and the
 * validator compute 2D orientations and areas in. */
int tr_plc_tri_axis(const struct tr_plc *plc, uint32_t t);

struct tr_point;
/* p, a point in input triangle t's plane, in the closed triangle, tested in the projection
 * along axis k (non-degenerate for t). Exact. */
int tr_plc_tri_holds(const struct tr_plc *plc, uint32_t t, int k, const struct tr_point *p);
/* The smallest triangle of facet g (a group id) whose closed triangle holds p, a point in
 * g's plane, tested in the projection along axis k (non-degenerate for g, so for every
 * member); UINT32_MAX (TR_NONE) if none. hint, if not UINT32_MAX, is a member known or guessed to hold p:
 * it is checked once and ends the scan early. Exact. The one rule that labels a facet's
 * sub-faces, shared by refinement and the sliver stage's facet flips. */
uint32_t tr_facets_triangle_of(const tr_facets *F, const struct tr_plc *plc, uint32_t g, int k,
                               const struct tr_point *p, uint32_t hint);

static inline uint32_t tr_facets_size(const tr_facets *f, uint32_t g)
{
  return f->start[g + 1] - f->start[g];
}

#endif
