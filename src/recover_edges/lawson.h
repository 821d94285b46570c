/* Lawson flips around a new vertex (Joe 1991): restores the local Delaunay property of
 * the faces opposite a point that was just inserted (a midpoint split of edge recovery),
 * so that later sub-segments meet a better mesh and more of them appear by themselves.
 *
 * The faces examined are the link faces of p (the faces of tets incident to p that do not
 * contain p). A link face of tet t = (p, a, b, c) whose opposite apex d is strictly inside
 * the circumsphere of t (exact tr_insphere_p, no perturbation: a cospherical apex is left
 * alone) is flipped by a 2-3 flip when pd crosses the open face, by a 3-2 flip of an
 * edge of the face whose shell is exactly {t, neighbour, (p, d, edge)}, or, when p, d
 * and an edge of the face are coplanar with pd crossing that edge, by the 4-4 flip of
 * that edge (common on CAD models: axis-aligned facets put midpoints on shared planes;
 * without it half of the non-Delaunay faces stayed); otherwise it is left (a later flip
 * may remove it). Faces on the hull (a ghost on either side) are never flipped, and the
 * guard (the constraint edges of the caller) is passed to every flip.
 *
 * Every flip replaces the upper by the lower lifted triangulation of five points, so the
 * lifted height strictly drops and the loop ends even when the mesh around p is not
 * Delaunay; the flip budget (TR_LAWSON_BUDGET times the first number of link faces) only
 * caps the work, and it is deterministic (the order is the stack order from Ball(p)).
 */
#ifndef TR_RECOVER_EDGES_LAWSON_H
#define TR_RECOVER_EDGES_LAWSON_H

#include "recover_edges/flip.h"

#define TR_LAWSON_BUDGET 64

typedef struct tr_lawson_stats {
  uint64_t tested;    /* link faces tested with insphere */
  uint64_t flip23, flip32, flip44;  /* flips made */
  uint64_t blocked;   /* non-Delaunay faces left: not flippable, or refused by the guard */
  uint64_t capped;    /* calls stopped by the budget */
} tr_lawson_stats;

/* Scratch memory kept between calls. Zero-initialise; free with tr_lawson_free. */
typedef struct tr_lawson {
  uint32_t *st; /* stack entries: tet hint + the three link-face vertices */
  size_t n, cap;
  tr_u32buf ball;
} tr_lawson;
void tr_lawson_free(tr_lawson *L);

/* Lawson flips around vertex p (see above). st (may be NULL) accumulates counters. */
tr_status tr_lawson_vertex(struct tr_mesh *m, uint32_t p, tr_flip_guard guard, void *ud,
                           tr_lawson *L, tr_lawson_stats *st);

/* 1 iff link face k of real tet t (k: the face opposite a vertex) is locally Delaunay in
 * the strict sense used above: a hull face, or the apex across it is not strictly inside
 * the circumsphere of t. For tests. */
int tr_lawson_face_ok(const struct tr_mesh *m, uint32_t t, int k);

#endif
