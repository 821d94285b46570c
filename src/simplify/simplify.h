/* --surface-tolerance EPS (tr_options.surface_tolerance, docs/simplify.md): before the
 * Delaunay stage the surface may be re-triangulated so that, with d = EPS times the
 * diagonal of the input's bounding box,
 *   every point of the new surface lies within d of the input surface, and
 *   every point of the input surface lies within d of the new one,
 * both proven (exact tests at the vertices of an adaptive subdivision). */
#ifndef TR_SIMPLIFY_H
#define TR_SIMPLIFY_H

#include <stdint.h>

#include "core/plc.h"

/* The two-sided bound between surfaces X (xyz_x, tri_x) and Y: *ok = 1 iff each is
 * within d of the other, proven. *measured = an upper bound of the larger of the two
 * one-sided distances (valid when *ok), or +inf. On failure *side = 0 when a triangle of
 * X (index *tri) is not within d of Y, 1 the other way round, and *undecided = 1 when
 * that was not proven either way (a piece budget ran out): the bound is then not
 * established, which `tetrec check` reports as a failure too. */
typedef struct tr_simp_bound_result {
  int ok, side, undecided;
  uint32_t tri;
  double measured;
} tr_simp_bound_result;
tr_status tr_simplify_bound(const double *xyz_x, const uint32_t *tri_x, uint32_t nx,
                            const double *xyz_y, const uint32_t *tri_y, uint32_t ny, double d,
                            tr_simp_bound_result *res);

/* What the stage did. */
typedef struct tr_simp_stats {
  uint64_t collapses, flips, vertices_frozen, rounds;
  double bound; /* the measured two-sided bound divided by the diagonal */
} tr_simp_stats;

/* The diagonal of the bounding box of the points of plc's triangles and segments. */
double tr_simplify_diagonal(const struct tr_plc *plc);

/* Replaces *plc (validated) by a simplified copy within eps times its diagonal (eps > 0
 * finite, else TR_ERR_USAGE), validated again; the old PLC is destroyed. Input segments,
 * marker boundaries, sharp edges (normals more than TR_SIMP_SHARP_DEG degrees apart,
 * i.e. dihedral angles under 180 minus that) and open or non-manifold edges stay chains
 * of edges; corners (vertices on one, or three or more, such edges) stay; the topology
 * stays. */
#define TR_SIMP_SHARP_DEG 30.0
tr_status tr_simplify_surface(struct tr_plc **plc, double eps, const tr_options *opt,
                              tr_simp_stats *stats);

#endif
