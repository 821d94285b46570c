/* Adaptive-precision geometric predicates on double coordinates (Shewchuk's method:
 * a floating-point stage with a proven error bound, adaptive expansion stages, and an
 * exact sign at the end). Written for tetrec from the published algorithm.
 *
 * Sign conventions (the library's, see include/tetrec.h):
 *   tr_orient2d(a,b,c)   > 0  iff a,b,c turn counterclockwise: det[b-a; c-a] > 0.
 *   tr_orient3d(a,b,c,d) > 0  iff det[b-a; c-a; d-a] > 0, i.e. d lies on the side of
 *                              plane abc its right-hand normal points to. This is the
 *                              NEGATION of Shewchuk's orient3d and equals CGAL's
 *                              orientation(a,b,c,d).
 *   tr_insphere(a,b,c,d,e) > 0 iff e lies strictly inside the sphere through a,b,c,d,
 *                              given tr_orient3d(a,b,c,d) > 0 (CGAL's
 *                              side_of_oriented_sphere); the sign flips with the
 *                              orientation of abcd.
 *   tr_incircle(a,b,c,d) > 0  iff d lies inside the circle abc, given orient2d(a,b,c) > 0.
 * The returned doubles have the exact sign; their magnitude is an approximation.
 * Inputs must be finite; no tolerance is used anywhere.
 */
#ifndef TR_PREDICATES_H
#define TR_PREDICATES_H

#include <stdint.h>

double tr_orient2d(const double a[2], const double b[2], const double c[2]);
double tr_orient3d(const double a[3], const double b[3], const double c[3], const double d[3]);
double tr_incircle(const double a[2], const double b[2], const double c[2], const double d[2]);
double tr_insphere(const double a[3], const double b[3], const double c[3], const double d[3],
                   const double e[3]);

/* orient2d of the projections of 3D points onto the coordinate plane that drops axis
 * `drop` (0 = x, 1 = y, 2 = z). Exact. */
double tr_orient2d_proj(const double a[3], const double b[3], const double c[3], int drop);

/* Symbolically perturbed predicates (never 0 for distinct points in general enough
 * position; see perturb.c for the exact scheme and its proof of consistency).
 * ia..ie are the global indices of the points: the perturbation is index-ordered, so
 * equal inputs give equal answers in every call, on every machine.
 * Return -1 or +1 (0 only where documented in perturb.c). */
int tr_insphere_sos(const double a[3], const double b[3], const double c[3], const double d[3],
                    const double e[3], uint32_t ia, uint32_t ib, uint32_t ic, uint32_t id,
                    uint32_t ie);
int tr_orient3d_sos(const double a[3], const double b[3], const double c[3], const double d[3],
                    uint32_t ia, uint32_t ib, uint32_t ic, uint32_t id);

static inline int tr_sign(double x) { return (x > 0) - (x < 0); }

#endif
