/* Surface smoothing by diagonal swap before recovery (the seed paper's "Smoothing
 * operations of the surface", Fig.7).
 *
 * Two input triangles ABC and ACD sharing the edge AC (which has exactly these two
 * triangles) are replaced by ABD and BCD when (1) they are exactly coplanar, (2) they
 * carry the same marker, (3) the quadrilateral ABCD is strictly convex, (4) D lies
 * strictly inside the circumcircle of ABC, and (5) BD is not already an input edge.
 * This is a Lawson flip in the plane, so it only removes input edges interior to a
 * coplanar region of one marker: the surface (as a point set) and its marker map are
 * unchanged, but the constraint edges are not those of the input.
 *
 * Exact coplanar incircle: for coplanar A, B, C, D and any X off their plane, the sphere
 * through A, B, C, X meets the plane exactly in the circumcircle of ABC, so D is inside
 * that circle iff D is inside the sphere: sign(insphere(A,B,C,X,D)) * sign(orient3d(A,B,C,X)).
 * X is A moved along the axis of a non-zero component of the normal, hence off the plane.
 *
 * Passes run in sorted edge order; within a pass no two swaps share a vertex (so a pass
 * never creates the same edge twice); at most TR_SMOOTH_MAX_PASSES passes. A pass after
 * the first examines only the edges near the previous pass's swaps (smooth.c says why
 * that makes the same swaps). */
#ifndef TR_SMOOTH_H
#define TR_SMOOTH_H

#include <stdint.h>

#include "core/plc.h"
#include "core/status.h"

#define TR_SMOOTH_MAX_PASSES 1000

/* Swaps diagonals of plc's triangles in place (consistently oriented input, as after
 * tr_plc_validate); *nswaps = number of swaps done. */
tr_status tr_smooth_surface(struct tr_plc *plc, uint64_t *nswaps);

/* The swap condition (4) of tr_smooth_surface made a parameter: called on a quad that
 * meets (1)-(3), with q = the points of A, B, C, D (AC the shared diagonal); 1 to swap AC
 * for BD. It must depend on the four vertices only: a refusal is remembered while
 * neither triangle changes. Each swap must make progress towards a fixed point (the
 * passes stop at TR_SMOOTH_MAX_PASSES otherwise). */
typedef int (*tr_swap_rule)(void *user, const double *const q[4], uint32_t A, uint32_t B,
                            uint32_t C, uint32_t D);
tr_status tr_smooth_surface_rule(struct tr_plc *plc, tr_swap_rule rule, void *user,
                                 uint64_t *nswaps);

/* The same swaps in the same order as tr_smooth_surface_rule, by passes that sort and scan
 * every edge: the reference the tests hold the worklist to. */
tr_status tr_smooth_surface_rule_passes(struct tr_plc *plc, tr_swap_rule rule, void *user,
                                        uint64_t *nswaps);

/* 1 iff D is strictly inside the circumcircle of the non-degenerate triangle ABC, the four
 * points being coplanar (exact). */
int tr_coplanar_incircle(const double a[3], const double b[3], const double c[3],
                         const double d[3]);

#endif
