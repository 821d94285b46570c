/* The ring of an edge's shell and its best triangulation (flips.c), shared by the edge
 * removals there and the facet flips (facetflip.c). */
#ifndef TETREC_SLIVER_RING_H
#define TETREC_SLIVER_RING_H

#include "sliver/sliver.h"

/* The polygon r[0..n) around edge A B, in the shell's turning order (the tet with r[i],
 * r[i+1] is {A, B, r[i], r[i+1]} up to an even permutation), and the best triangulation of
 * each sub-polygon r[i..j] coned to A and B. */
typedef struct tr_sliver_ring {
  const tr_sliver_ctx *c;
  const struct tr_mesh *m;
  uint32_t region;
  double was; /* the largest ratio of the tets replaced */
  double floor; /* what the triangulation must beat: no sub-polygon at or under it helps */
  uint32_t A, B, r[SL_MAX_RING];
  int n;
  double val[SL_MAX_RING][SL_MAX_RING]; /* best smallest angle of r[i..j], -1: none */
  int8_t cut[SL_MAX_RING][SL_MAX_RING];
} tr_sliver_ring;

/* Fills val and cut: every tet of a triangulation counted is exactly positive and keeps
 * the bounds (tr_sliver_keeps_bounds with R->region and R->was). */
void tr_sliver_ring_dp(tr_sliver_ring *R);
/* Appends the tets of r[i..j]'s best triangulation (2 per triangle) to newv, *nnew of
 * them already there. */
void tr_sliver_ring_emit(const tr_sliver_ring *R, int i, int j, uint32_t *newv, uint32_t *nnew);

#endif
