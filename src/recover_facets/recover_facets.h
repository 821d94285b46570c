/* Stage 3 of the pipeline: recovery of every missing input triangle (the paper's
 * "RECOVERY OF MISSING FACETS"): Swap32 first, then the general flips (flipfacet.h), then
 * cavity retriangulation (cavity.h, no Steiner point), then clusterel decomposition with
 * exact Steiner points on the facet.
 *
 * Precondition: tr_recover_edges succeeded, so every edge of every input triangle is a
 * chain of mesh edges. On success every input triangle is exactly the union of the mesh
 * faces listed for it in `sub`.
 */
#ifndef TR_RECOVER_FACETS_H
#define TR_RECOVER_FACETS_H

#include "mesh/mesh.h"
#include "recover_edges/recover_edges.h"

/* Sub-faces of the input triangles: face j = (v[3j], v[3j+1], v[3j+2]) ordered so that its
 * right-hand normal has the direction of its input triangle's, tri[j] = the input
 * triangle's index. Sorted by tri, then by vertex ids (deterministic). */
typedef struct tr_subfaces {
  uint32_t n;
  uint32_t *v;   /* 3 * n */
  uint32_t *tri; /* n */
} tr_subfaces;
void tr_subfaces_free(tr_subfaces *s);

typedef struct tr_facet_recovery_stats {
  uint64_t missing_facets;     /* input triangles not unions of mesh faces after edges */
  uint64_t recovered_by_swap;  /* by Swap32 or general flips alone */
  uint64_t points_added;       /* Steiner points on facets (and the extra points H) */
  /* details: facets recovered by general flips (part of recovered_by_swap), the flips
   * kept by kind (Swap23, edge removal with a shell of 3, 4, >= 5 tets), flips undone */
  uint64_t by_flips, flip23, flip32, flip44, flipn, flips_undone;
  /* cavity retriangulation (cavity.h): facets recovered by it (no Steiner point; not in
   * recovered_by_swap), facets it was tried on, tets added by cavity expansion */
  uint64_t recovered_by_cavity, cavity_tried, cavity_expanded;
} tr_facet_recovery_stats;

/* paper = 1: the published algorithm only, Swap32 then clusterels (no general flips, no
 * cavity retriangulation). no_flips = 1: no general flips, so the cavity retriangulation
 * runs right after Swap32 (for comparisons). Zero-initialised: the default. */
typedef struct tr_facet_recovery_opts {
  int paper, no_flips;
} tr_facet_recovery_opts;

/* tris: 3*n mesh vertex ids (outward oriented), chains from edge recovery. */
tr_status tr_recover_facets(struct tr_mesh *m, const uint32_t *tris, uint32_t n,
                            const tr_edge_chains *chains, tr_subfaces *sub,
                            tr_facet_recovery_stats *st);
/* The same with options (opt may be NULL: the default). hint_out (may be NULL; needs
 * sub): *hint_out[j] (sub->n entries, freed by the caller) = a tet that had sub-face j
 * as a face when it was listed, TR_NONE: none; later flips may have taken it away (the
 * outer removal checks it: tr_outer_color_ex). */
tr_status tr_recover_facets_ex(struct tr_mesh *m, const uint32_t *tris, uint32_t n,
                               const tr_edge_chains *chains, const tr_facet_recovery_opts *fo,
                               tr_subfaces *sub, tr_facet_recovery_stats *st,
                               uint32_t **hint_out);

#endif
