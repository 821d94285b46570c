/* Stage 2 of the pipeline: recovery of every missing input edge (the paper's "RECOVERY OF
 * MISSING EDGES"): first the swaps (Swap23, Swap44) and the general flips of flip.h over
 * all missing edges, then Steiner points (midpoint splits, then pipel by pipel) for those
 * the flips could not recover (see recover_edges.c).
 *
 * Input edges are given as pairs of mesh vertex ids (the PLC's points are the first mesh
 * vertices, duplicates already merged). On success every input edge is a chain of
 * collinear mesh edges, recorded in `chains`.
 */
#ifndef TR_RECOVER_EDGES_H
#define TR_RECOVER_EDGES_H

#include "mesh/mesh.h"

/* The chains of recovered input edges: edge i is the vertex sequence
 * v[start[i] .. start[i+1]-1], from its first end to its second (2 vertices when the
 * edge is a mesh edge). */
typedef struct tr_edge_chains {
  uint32_t n;
  uint32_t *start; /* n + 1 */
  uint32_t *v;
} tr_edge_chains;
void tr_edge_chains_free(tr_edge_chains *c);
/* Index of the chain of input edge {a,b} (either order), TR_NONE if it is not an input
 * edge. Relies on the sorted order documented at tr_recover_edges. */
uint32_t tr_edge_chains_find(const tr_edge_chains *c, const uint32_t *edges, uint32_t a,
                             uint32_t b);

/* The paper's Table 14 rows for this stage. */
#define TR_EDGE_PIPEL_KINDS 7
typedef struct tr_edge_recovery_stats {
  uint64_t missing_edges;          /* input edges not mesh edges after Delaunay */
  uint64_t recovered_by_swap;      /* by Swap23 / Swap44 / general flips alone */
  uint64_t points_added;           /* Steiner points on edges */
  /* Details (added by the edge recovery work; the three rows above are the paper's). A
   * missing edge is counted in exactly one of recovered_by_swap (no Steiner point, at
   * least one swap), through_vertices (only split at existing vertices it passes
   * through, every piece already a mesh edge) and recovered_by_steiner. */
  uint64_t through_vertices;
  uint64_t recovered_by_steiner;
  uint64_t swap23, swap44;          /* swaps performed */
  uint64_t split_at_vertex;         /* sub-segment splits at existing vertices */
  uint64_t ghosts_split;            /* ghost tets replaced (a hull face was split) */
  /* decomposed pipels by table: Case 1 (Table 5), Case 2 I, Case 2 II S, Case 2 II Z
   * (Table 6), Case 3 (Table 7), Case 4 (Table 8), Case 5 (Table 9) */
  uint64_t pipels[TR_EDGE_PIPEL_KINDS];
  /* decomposed pipels by raw type (second << 2 | first, classify.h's TR_NOD..TR_FAC) */
  uint64_t pipels_raw[16];
  /* general flips kept (flip.h): Swap23 on a crossed face, edge removal with a shell of
   * 3, 4, >= 5 tets, 2-2 hull flips; flips tried and undone (the pipe did not shrink) */
  uint64_t flip23, flip32, flip44, flipn, flip_hull, flips_undone;
  /* pass 2: sub-segments split at their exact midpoint (one Steiner point each, counted
   * in points_added) before the halves are tried by flips again */
  uint64_t midpoints;
  /* Lawson flips (lawson.h) around the midpoints: 2-3, 3-2, 4-4 */
  uint64_t lawson_flip23, lawson_flip32, lawson_flip44;
} tr_edge_recovery_stats;

/* edges: 2*n mesh vertex ids, the unique undirected input edges with
 * edges[2i] < edges[2i+1], sorted lexicographically (the pipeline builds them so; it makes
 * the run deterministic and lets later stages find an edge's chain by binary search).
 * chains keeps that order and direction. */
tr_status tr_recover_edges(struct tr_mesh *m, const uint32_t *edges, uint32_t n,
                           tr_edge_chains *chains, tr_edge_recovery_stats *st);

/* Switches for tests and comparisons (zero = the default of tr_recover_edges):
 * no_flips: only the paper's Swap23 / Swap44 before Steiner points (no flip.h flips);
 * no_midpoints: pass 2 uses the paper's pipels right away (no midpoint splits);
 * no_lawson: no Lawson flips around the midpoints (the mesh is left as the split made it). */
struct tr_plc;
typedef struct tr_edge_recovery_opts {
  int no_flips, no_midpoints, no_lawson;
  /* NULL, or the surface the input edges are those of (with segments): when an edge is
   * missing, its flat edges (tr_flat_edges) are recovered after the others, the flips
   * of the others protecting only those (see recover_edges.c). */
  const struct tr_plc *surface;
  /* Flip attempts allowed per sub-segment and try of the flip searches (flipfirst.c);
   * 0: TR_EDGE_FLIP_BUDGET of recover_edges.c. */
  uint32_t flip_budget;
} tr_edge_recovery_opts;
tr_status tr_recover_edges_ex(struct tr_mesh *m, const uint32_t *edges, uint32_t n,
                              const tr_edge_recovery_opts *opt, tr_edge_chains *chains,
                              tr_edge_recovery_stats *st);

/* The index of edge {a,b} (either order) in n sorted unique pairs, TR_NONE if absent. */
uint32_t tr_edge_index(const uint32_t *edges, uint32_t n, uint32_t a, uint32_t b);

/* flat[i] = 1 iff input edge i (edges: sorted pairs, as tr_recover_edges takes them) is
 * an inner edge of a planar facet of plc (core/facets.h: two exactly coplanar triangles
 * of one marker) and no segment (surfswap.c). */
tr_status tr_flat_edges(const struct tr_plc *plc, const uint32_t *edges, uint32_t n,
                        uint8_t *flat);

/* Before recovery: swaps diagonals of exactly coplanar input triangle pairs (one marker,
 * strictly convex quad) whose shared edge the mesh lacks for the other diagonal when the
 * mesh has it (surfswap.c); edges: plc's input edges as tr_recover_edges takes them;
 * *nswaps = how many. After a swap the input edges must be listed again. */
tr_status tr_surface_swaps_to_mesh(struct tr_plc *plc, struct tr_mesh *m,
                                   const uint32_t *edges, uint32_t ne, uint64_t *nswaps);

#endif
