/* Constrained Delaunay refinement for mesh quality (Shewchuk 1998, "Tetrahedral mesh
 * generation by Delaunay refinement"; Si 2015, "TetGen"): runs on the recovered mesh
 * after outer removal and inserts points until every inner tet meets the radius-edge
 * bound and the volume bound, or is exempt (see below), or the point budget is spent.
 *
 * Points and where they lie:
 *  - a bad tet (radius-edge ratio > R, volume > V, or longest edge over the size field,
 *    sizing.c) gets its circumcentre, computed in
 *    doubles from the tet's nearest doubles and inserted as an exact double point;
 *  - a point that would lie in the diametral sphere of a sub-segment or the equatorial
 *    sphere of a sub-face (exact tests, encroach.c) is not inserted: the constraint is
 *    split instead, at a point exactly on it: on an input edge AB the dyadic point
 *    A + k/2^m (B - A) (near the sub-segment's midpoint, or at a power-of-two fraction of
 *    AB next to an input vertex: concentric shells), on an input triangle ABC a dyadic
 *    barycentric combination of A, B, C near the sub-face's circumcentre.
 * Insertion is constrained Bowyer-Watson (cavity.c): the cavity grows through faces
 * whose far tet has the point strictly inside its circumsphere (exact, perturbed where
 * every point is a double), never through a sub-face unless the point lies in that
 * sub-face's input triangle, never out of the domain; it is then shrunk until every face
 * it is coned from is strictly visible from the point, so every new tet is positive
 * whatever the mesh was (recovery leaves it constrained, not Delaunay).
 *
 * With subface_ratio S > 0, a sub-face whose own radius-edge ratio is over S is split too
 * (subshape.c), unless a small input angle forces its shape.
 *
 * Termination: sub-segments next to an input vertex are split on concentric shells; a
 * bad tet whose shortest edge joins points on two input edges that meet at an input
 * vertex under less than 60 degrees is left as it is (its quality is forced by that
 * angle), but for wedge grading (angles.c), which splits pieces of such edges only away
 * from that vertex and only while longer than a quarter of their distance from it; a
 * circumcentre closer to a vertex of its cavity than that vertex's insertion
 * radius (its distance to its nearest vertex when refinement added it; with spacing_radii,
 * that radius shrunk by the points put next to the vertex since, and the radius-edge
 * refinement ends at a point cap, after which only tets over a volume bound are refined,
 * with the insertion radii) is not inserted, unless its tet is over the volume bound; and
 * a point budget stops a runaway with TR_ERR_NOMEM ("a size limit was exceeded") and a
 * message. Outer and ghost tets are discarded first. */
#ifndef TR_REFINE_H
#define TR_REFINE_H

#include <stdint.h>

#include "core/plc.h"
#include "mesh/mesh.h"
#include "recover_facets/recover_facets.h"

/* What one refinement set-up found that the next may take as it is, for a caller that
 * runs many (the sliver stage's hooks below): per vertex id below n, the input edge
 * (two input ids) whose line it was found exactly on, TR_NONE twice for none known. The
 * owner lowers n when ids from n on may name other points (vertices dropped and their
 * ids reused: caps.c's undone trials). A zeroed struct is empty; tr_refine_memo_free. */
typedef struct tr_refine_memo {
  uint32_t *line;
  uint32_t n, cap;
  /* the constraint tables of the last set-up that built them, for the next set-up on the
   * same sub-faces (memo.c) */
  struct rf_subs_cache *subs;
  uint32_t copies; /* set-ups that copied those tables instead of building them */
} tr_refine_memo;
void tr_refine_memo_free(tr_refine_memo *memo);

typedef struct tr_refine_params {
  double ratio;        /* radius-edge bound R (> 0), 0: no ratio criterion */
  double max_volume;   /* volume bound, 0: none */
  /* per-region volume bounds: region ids (sorted, distinct) and their bounds (> 0); a
   * tet of such a region is bounded by the smaller of its region's and max_volume */
  const uint32_t *region_id;
  const double *region_max_volume;
  uint32_t nregion_bounds;
  uint64_t budget;     /* points the stage may add; 0: tr_refine_default_budget */
  double subface_ratio; /* sub-faces over this radius-edge ratio are split for their shape
                           (subshape.c); 0: off */
  int keep_edges;      /* every input edge stays a constraint: no merged facets (facets.h) */
  int keep_surface;    /* no point on a constraint (--keep-surface): every sub-segment and
                          sub-face is unsplittable, so only interior points are added and a
                          bad tet whose circumcentre encroaches a piece is left (tr_refine
                          only; the hooks below are not called under it) */
  int flat_splits;     /* 1: a sub-segment opposite an angle over 120 degrees of a sub-face
                          is split at that vertex's foot, once (flat.c); 0: off.
                          tr_refine_stage sets it */
  int wedge_grading;   /* 1: a bad tet exempt for a small input angle between two input
                          edges still has the pieces of one that the other's points
                          encroach split, out from the innermost (angles.c,
                          rf_wedge_split); 0: off. tr_refine_stage sets it */
  int spacing_radii;   /* the circumcentre rule takes a vertex's current spacing (refine.c,
                          after_insert) instead of its insertion radius; the radius-edge
                          refinement ends (no error, bad tets left) at 20 points per input
                          point + 10,000 or half the budget, the volume bounds' goes on */
  /* sub is rf_subs_export's output (of tr_refine or of the hooks below, or a copy of it):
   * the input triangle of each sub-face still there at the end is taken from sub->tri,
   * not located again by its exact centroid (the bulk of each of the sliver polish's
   * trials on a model with large planar facets: cheese.off) */
  int partial;         /* reaching the budget ends tr_refine with TR_OK and the mesh made so
                          far (st->budget_reached = 1): valid, the bounds not met everywhere;
                          0: TR_ERR_NOMEM */
  int sub_exported;
  tr_refine_memo *memo; /* NULL, or the caller's memo: read and extended by the set-up */
  int verbose;
  /* the size field (sizing.h; NULL: none) and the sizes of the mesh's first nvsize
   * vertices (the others are taken from the field): tets and pieces over it are refined
   * (tr_refine only; sizing.c) */
  const struct tr_sizing *sizing;
  const double *vsize;
  uint32_t nvsize;
  uint64_t size_points; /* the points the field is expected to ask for (raises the point
                           cap of spacing_radii; refine.c, spacing_cap) */
  int threads;          /* threads for the rounds of parallel insertion (rounds.c); 0 or 1:
                           one. The mesh does not depend on it */
  uint32_t round_min;   /* bad tets queued (dead entries included) before rounds run;
                           0: no rounds (tr_options.refine_rounds) */
} tr_refine_params;

typedef struct tr_refine_stats {
  uint64_t points;          /* points added, all kinds */
  uint64_t on_segments, on_facets, inside; /* by kind */
  uint64_t skipped_small_angle; /* bad tets exempt: quality forced by an input angle */
  uint64_t wedge_splits;    /* pieces queued by wedge grading (par.wedge_grading) */
  uint64_t skipped_close;   /* bad tets left: circumcentre within a new vertex's
                               insertion radius (refine.c, too_close) */
  uint64_t skipped_other;   /* bad tets left: circumcentre blocked / refused */
  uint32_t merged_edges;    /* input edges inside merged planar facets: no constraints */
  int spacing_stopped;      /* spacing_radii: the radius-edge refinement ended at its point
                               cap (refine.c); tets over a volume bound were still refined */
  int budget_reached;       /* par->partial: refinement stopped at par->budget points */
  uint64_t rounds;          /* rounds of parallel insertion (rounds.c) */
  uint64_t round_points;    /* points inserted by them */
  uint64_t round_serial;    /* their candidates left to the serial loop */
} tr_refine_stats;

/* Tet t's volume bound under par: the smaller of par->max_volume and its region's
 * (m->region[t] among par->region_id); 0: none. */
double tr_refine_tet_bound(const tr_refine_params *par, const struct tr_mesh *m, uint32_t t);
/* The volume bound of region `region`: the smaller of max_volume and the region's entry
 * in a sorted table of tr_refine_region_bounds (ids, bounds, n; binary search); 0: none. */
double tr_refine_region_bound_of(const uint32_t *ids, const double *bounds, uint32_t n,
                                 double max_volume, uint32_t region);

/* The default budget: 100 points per input point plus 100,000, plus, with a volume bound,
 * 20 per multiple of V in the domain's volume (a mesh of tets of volume about V/6 needs
 * about 6 times that many points), at most TR_REFINE_BUDGET_CEILING or 8 per input point,
 * whichever is larger. */
#define TR_REFINE_BUDGET_CEILING 16777216.0 /* 2^24 points: ~20 GB */
uint64_t tr_refine_default_budget(uint32_t npoints, double domain_volume, double max_volume);

/* m: the recovered mesh with outer tets flagged (tr_outer_color), vertex ids = plc's point
 * ids for the first plc->npoints; sub: its sub-faces, replaced on success by the refined
 * ones (same ordering rules). On return m holds only inner tets (outer and ghost slots
 * freed, their faces TR_NONE). */
tr_status tr_refine(struct tr_mesh *m, const struct tr_plc *plc, tr_subfaces *sub,
                    const tr_refine_params *par, tr_refine_stats *st);

/* The sliver stage's hook (issue 17): tets flips and moves cannot open because they are
 * pinned between constraints (three or four vertices on input edges and triangles, a face
 * on a sub-face) get points exactly on those constraints. For each listed tet (slots of m,
 * which holds only inner tets, tr_refine's output, with its sub-faces sub): the pieces its
 * own vertices encroach are split, or, when none is, the sub-faces it lies on, with the
 * encroachment and small-angle rules of tr_refine; the new tets over the bounds are
 * refined as there. par->budget caps the points (reaching it is no error: what was split
 * stays, the mesh valid); sub is replaced by the new sub-faces. */
tr_status tr_refine_open_pinned(struct tr_mesh *m, const struct tr_plc *plc, tr_subfaces *sub,
                                const tr_refine_params *par, const uint32_t *tets,
                                uint32_t ntets, tr_refine_stats *st);

/* The sliver polish's hook: the sub-segment v[0]-v[1] (nv = 2) or the sub-face v[0..2]
 * (nv = 3) is split as an encroached piece is, within par->budget points (no error when
 * reached); nothing when it is no constraint piece or may not be split. sub is replaced
 * by the new sub-faces when a point went in. */
tr_status tr_refine_split_piece(struct tr_mesh *m, const struct tr_plc *plc, tr_subfaces *sub,
                                const tr_refine_params *par, const uint32_t *v, int nv,
                                tr_refine_stats *st);

#endif
