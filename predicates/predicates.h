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

#include <math.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

double tr_orient2d(const double a[2], const double b[2], const double c[2]);
double tr_incircle(const double a[2], const double b[2], const double c[2], const double d[2]);
/* tr_orient3d and tr_insphere are the static inline filters at the end of this file. */

/* The adaptive and exact stages behind the inline filters (orient.c, insphere.c);
 * callers use tr_orient3d / tr_insphere. Exact for every finite input. */
double tr_orient3d_adapt(const double a[3], const double b[3], const double c[3],
                         const double d[3]);
double tr_insphere_adapt(const double a[3], const double b[3], const double c[3],
                         const double d[3], const double e[3]);

/* The exact last stage alone (raw-coordinate expansions, or GMP outside their exact
 * range), for the tests: same sign conventions. */
double tr_orient2d_exact(const double a[2], const double b[2], const double c[2]);
double tr_orient3d_exact(const double a[3], const double b[3], const double c[3],
                         const double d[3]);
double tr_incircle_exact(const double a[2], const double b[2], const double c[2],
                         const double d[2]);
double tr_insphere_exact(const double a[3], const double b[3], const double c[3],
                         const double d[3], const double e[3]);

/* orient2d of the projections of 3D points onto the coordinate plane that drops axis
 * `drop` (0 = x, 1 = y, 2 = z), with the kept axes in cyclic order
 * u = (drop+1)%3, v = (drop+2)%3, so the 2D sign is the sign of component `drop` of
 * the triangle normal (b-a)x(c-a). Exact. */
double tr_orient2d_proj(const double a[3], const double b[3], const double c[3], int drop);

/* Symbolically perturbed predicates (never 0 for distinct points in general enough
 * position; see perturb.c for the exact scheme and its proof of consistency).
 * ia..ie are the global indices of the points: the perturbation is index-ordered, so
 * equal inputs give equal answers in every call, on every machine.
 * Return -1 or +1 (0 only where documented in perturb.c): tr_insphere_sos is nonzero
 * whenever a,b,c,d are not coplanar, tr_orient3d_sos whenever the four indices are
 * distinct (even for coincident points). */
int tr_insphere_sos(const double a[3], const double b[3], const double c[3], const double d[3],
                    const double e[3], uint32_t ia, uint32_t ib, uint32_t ic, uint32_t id,
                    uint32_t ie);
int tr_orient3d_sos(const double a[3], const double b[3], const double c[3], const double d[3],
                    uint32_t ia, uint32_t ib, uint32_t ic, uint32_t id);

static inline int tr_sign(double x) { return (x > 0) - (x < 0); }

/* ---- inline semi-static filters ----
 * The hot path of every Delaunay insertion: differences, the floating determinant and
 * a bound built from the largest difference in each coordinate; only when the sign is
 * not certified does the out-of-line adaptive code run. The constants are derived in
 * orient.c (TR_O3_FILTER) and insphere.c (TR_IS_FILTER). The range test keeps every
 * product away from overflow and makes underflow errors negligible against the slack
 * in the constants; outside it, or when the bound is not met, the adaptive code
 * decides. Contraction into FMA would not invalidate the bounds (it only removes
 * roundings), so C++ callers compiled without -ffp-contract=off stay correct. */
#define TR_O3_FILTER (49.0 * 0x1p-53)
#define TR_O3_FLO 0x1p-300
#define TR_O3_FHI 0x1p300
#define TR_IS_FILTER (385.0 * 0x1p-53)
#define TR_IS_FLO 0x1p-180
#define TR_IS_FHI 0x1p180

/* fabs, not a sign test: random signs would make a branch mispredict. */
static inline double tr_absmax3_(double a, double b, double c)
{
  a = fabs(a);
  b = fabs(b);
  c = fabs(c);
  a = b > a ? b : a;
  return c > a ? c : a;
}

/* The floating-point determinants of the filters, in one place: the filter bounds in
 * orient.c / insphere.c are derived for exactly this evaluation order, and the Delaunay
 * kernel's static filters (delaunay/bw.c) reuse those bounds, so they must evaluate the
 * very same expression. */
static inline double tr_orient3d_det_(const double a[3], const double b[3], const double c[3],
                                      const double d[3])
{
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  return (ux * (vy * wz - vz * wy) + uy * (vz * wx - vx * wz)) + uz * (vx * wy - vy * wx);
}

static inline double tr_insphere_det_(const double a[3], const double b[3], const double c[3],
                                      const double d[3], const double e[3])
{
  const double ax = a[0] - e[0], ay = a[1] - e[1], az = a[2] - e[2];
  const double bx = b[0] - e[0], by = b[1] - e[1], bz = b[2] - e[2];
  const double cx = c[0] - e[0], cy = c[1] - e[1], cz = c[2] - e[2];
  const double dx = d[0] - e[0], dy = d[1] - e[1], dz = d[2] - e[2];
  const double ab = ax * by - bx * ay, ac = ax * cy - cx * ay, ad = ax * dy - dx * ay;
  const double bc = bx * cy - cx * by, bd = bx * dy - dx * by, cd = cx * dy - dx * cy;
  const double ma = (bz * cd - cz * bd) + dz * bc;
  const double mb = (az * cd - cz * ad) + dz * ac;
  const double mc = (az * bd - bz * ad) + dz * ab;
  const double md = (az * bc - bz * ac) + cz * ab;
  const double la = (ax * ax + ay * ay) + az * az, lb = (bx * bx + by * by) + bz * bz;
  const double lc = (cx * cx + cy * cy) + cz * cz, ld = (dx * dx + dy * dy) + dz * dz;
  return (la * ma - lb * mb) + (lc * mc - ld * md);
}

/* The orient3d filter's verdict on the floating determinant det, given the largest
 * |difference| per axis: 1 iff the bound (orient.c, TR_O3_FILTER) fixes its sign. */
static inline int tr_orient3d_certain_(double det, double mx, double my, double mz)
{
  if (mx >= TR_O3_FLO && my >= TR_O3_FLO && mz >= TR_O3_FLO && mx <= TR_O3_FHI &&
      my <= TR_O3_FHI && mz <= TR_O3_FHI) {
    const double eb = TR_O3_FILTER * mx * my * mz;
    if (det > eb || -det > eb)
      return 1;
  }
  return 0;
}

/* The static filter of tr_orient3d alone: 1 with *det of the right sign, or 0 when only
 * the adaptive stages can decide (callers that remember the hard cases, such as the
 * flips' orientation memo, ask this first). */
static inline int tr_orient3d_filter(const double a[3], const double b[3], const double c[3],
                                     const double d[3], double *det)
{
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  *det = tr_orient3d_det_(a, b, c, d);
  return tr_orient3d_certain_(*det, tr_absmax3_(ux, vx, wx), tr_absmax3_(uy, vy, wy),
                              tr_absmax3_(uz, vz, wz));
}

/* A triangle (a, b, c) prepared for many orient3d(a, b, c, d) with d varying (the side of
 * points against a plane): the cross product n of u = b - a and v = c - a and the axis
 * maxima of |u| and |v|. tr_o3plane_filter(P, a, d) evaluates, operation for operation,
 * tr_orient3d_filter(a, d, b, c): w (uy vz - uz vy) + ... with w = d - a (an even
 * permutation: the value of orient3d(a, b, c, d)), so that filter's bound decides it, and
 * it returns 1 with *det of the right sign, or 0 (then tr_orient3d_adapt(a, b, c, d)). */
typedef struct tr_o3plane {
  double n[3], m[3];
} tr_o3plane;

static inline void tr_o3plane_init(tr_o3plane *P, const double a[3], const double b[3],
                                   const double c[3])
{
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  P->n[0] = uy * vz - uz * vy;
  P->n[1] = uz * vx - ux * vz;
  P->n[2] = ux * vy - uy * vx;
  P->m[0] = tr_absmax3_(ux, vx, 0);
  P->m[1] = tr_absmax3_(uy, vy, 0);
  P->m[2] = tr_absmax3_(uz, vz, 0);
}

static inline int tr_o3plane_filter(const tr_o3plane *P, const double a[3], const double d[3],
                                    double *det)
{
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  *det = (wx * P->n[0] + wy * P->n[1]) + wz * P->n[2];
  return tr_orient3d_certain_(*det, tr_absmax3_(wx, P->m[0], 0), tr_absmax3_(wy, P->m[1], 0),
                              tr_absmax3_(wz, P->m[2], 0));
}

static inline double tr_orient3d(const double a[3], const double b[3], const double c[3],
                                 const double d[3])
{
  double det;
  if (tr_orient3d_filter(a, b, c, d, &det))
    return det;
  return tr_orient3d_adapt(a, b, c, d);
}

static inline double tr_insphere(const double a[3], const double b[3], const double c[3],
                                 const double d[3], const double e[3])
{
  const double ax = a[0] - e[0], ay = a[1] - e[1], az = a[2] - e[2];
  const double bx = b[0] - e[0], by = b[1] - e[1], bz = b[2] - e[2];
  const double cx = c[0] - e[0], cy = c[1] - e[1], cz = c[2] - e[2];
  const double dx = d[0] - e[0], dy = d[1] - e[1], dz = d[2] - e[2];
  const double det = tr_insphere_det_(a, b, c, d, e);
  const double mx = tr_absmax3_(ax, bx, tr_absmax3_(cx, dx, 0));
  const double my = tr_absmax3_(ay, by, tr_absmax3_(cy, dy, 0));
  const double mz = tr_absmax3_(az, bz, tr_absmax3_(cz, dz, 0));
  if (mx >= TR_IS_FLO && my >= TR_IS_FLO && mz >= TR_IS_FLO && mx <= TR_IS_FHI &&
      my <= TR_IS_FHI && mz <= TR_IS_FHI) {
    const double eb = TR_IS_FILTER * mx * my * mz * ((mx * mx + my * my) + mz * mz);
    if (det > eb || -det > eb)
      return det;
  }
  return tr_insphere_adapt(a, b, c, d, e);
}

#ifdef __cplusplus
}
#endif

#endif
