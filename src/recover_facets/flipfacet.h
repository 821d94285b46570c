/* Facet recovery by flips, before any Steiner point: a missing facet EFG whose edges are
 * mesh edges is crossed by mesh edges only; remove them by edge removal (Swap32 is its
 * n = 3 case, recover_edges/flip.h, with the bounded flipnm recursion) or Swap23 on the
 * faces EFG cuts. An attempt (one candidate, possibly several flips) is kept only if it
 * lowers the number of crossing clusterels (counted on the flipped regions only, exact
 * tests); otherwise it is undone exactly. That number drops with every kept attempt, so
 * the loop ends.
 *
 * What is protected: edges the guard names (the driver passes the constraint edges of
 * edge recovery). Faces need no guard: edge removal deletes only faces containing the
 * crossed edge, and Swap23 only a face EFG cuts through; neither can be a sub-face of
 * another input facet unless the input self-intersects, which validation excludes.
 */
#ifndef TR_RECOVER_FACETS_FLIPFACET_H
#define TR_RECOVER_FACETS_FLIPFACET_H

#include "recover_edges/flip.h"

typedef struct tr_facet_flip_stats {
  uint64_t flip23, flip32, flip44, flipn; /* kept flips by kind (edge removal by shell) */
  uint64_t undone;                        /* tried and undone */
} tr_facet_flip_stats;

/* Runs the flips on facet efg. *changed = 1 if the mesh changed or a flip was made and
 * undone (an undo may put tets in other slots): the caller's cluster is then stale.
 * *clear = 1 if no clusterel crosses efg any more (the facet is present by the closure
 * argument of facet.h). st may be NULL. */
tr_status tr_facet_try_flips(struct tr_mesh *m, uint32_t e, uint32_t f, uint32_t g,
                             tr_flip_guard guard, void *ud, tr_facet_flip_stats *st,
                             int *changed, int *clear);

#endif
