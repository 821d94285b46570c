/* The insphere determinant of the Delaunay kernel's static filter, two lanes at a time.
 *
 * tr_dt_insphere_det(a, b, c, d, e) returns exactly tr_insphere_det_(a, b, c, d, e)
 * (predicates.h): every intermediate value is the same IEEE operation on the same two
 * operands in the same order (a*b and b*a round alike), only two of them are computed
 * by one SSE2 instruction. So the rounding error bound that bw.c's static filter uses,
 * derived for tr_insphere_det_'s evaluation order, holds unchanged. Lanes:
 *   X1 = (ax, bx), X2 = (cx, dx), likewise Y, Z (differences to e);
 *   L1 = (la, lb), L2 = (lc, ld): the lifts (x*x + y*y) + z*z;
 *   M1 = (ab, cd), M2 = (ac, bd), M3 = (ad, bc): the 2x2 minors, uv = ux*vy - vx*uy;
 *   (ma, mc), (mb, md): the 3x3 minors, paired so that the final sum
 *   (la*ma - lb*mb) + (lc*mc - ld*md) is one product pair per lane and one addition.
 * A compiler that contracts a*b - c*d into a fused multiply-add (not on the x86-64
 * baseline) may contract the two versions differently; that only removes roundings,
 * which the bound allows (see TR_IS_FILTER). tests/delaunay checks the equality on
 * random and cospherical inputs. Without GNU vector extensions it is tr_insphere_det_. */
#ifndef TR_DELAUNAY_DET2_H
#define TR_DELAUNAY_DET2_H

#include "predicates.h"

#if defined(__GNUC__) || defined(__clang__)
typedef double tr_v2d_ __attribute__((vector_size(16)));

static inline double tr_dt_insphere_det(const double a[3], const double b[3], const double c[3],
                                        const double d[3], const double e[3])
{
  const tr_v2d_ ex = {e[0], e[0]}, ey = {e[1], e[1]}, ez = {e[2], e[2]};
  const tr_v2d_ X1 = (tr_v2d_){a[0], b[0]} - ex, X2 = (tr_v2d_){c[0], d[0]} - ex;
  const tr_v2d_ Y1 = (tr_v2d_){a[1], b[1]} - ey, Y2 = (tr_v2d_){c[1], d[1]} - ey;
  const tr_v2d_ Z1 = (tr_v2d_){a[2], b[2]} - ez, Z2 = (tr_v2d_){c[2], d[2]} - ez;
  const tr_v2d_ L1 = (X1 * X1 + Y1 * Y1) + Z1 * Z1, L2 = (X2 * X2 + Y2 * Y2) + Z2 * Z2;
  /* ab = ax*by - bx*ay, cd = cx*dy - dx*cy */
  const tr_v2d_ M1 = (tr_v2d_){X1[0], X2[0]} * (tr_v2d_){Y1[1], Y2[1]} -
                     (tr_v2d_){X1[1], X2[1]} * (tr_v2d_){Y1[0], Y2[0]};
  /* ac = ax*cy - cx*ay, bd = bx*dy - dx*by */
  const tr_v2d_ M2 = X1 * Y2 - X2 * Y1;
  /* ad = ax*dy - dx*ay, bc = bx*cy - cx*by */
  const tr_v2d_ M3 = X1 * (tr_v2d_){Y2[1], Y2[0]} - (tr_v2d_){X2[1], X2[0]} * Y1;
  /* ma = (bz*cd - cz*bd) + dz*bc, mc = (az*bd - bz*ad) + dz*ab */
  const tr_v2d_ czbz = {Z2[0], Z1[1]};
  const tr_v2d_ MAC = ((tr_v2d_){Z1[1], Z1[0]} * (tr_v2d_){M1[1], M2[1]} -
                       czbz * (tr_v2d_){M2[1], M3[0]}) +
                      (tr_v2d_){Z2[1], Z2[1]} * (tr_v2d_){M3[1], M1[0]};
  /* mb = (az*cd - cz*ad) + dz*ac, md = (az*bc - bz*ac) + cz*ab */
  const tr_v2d_ MBD = ((tr_v2d_){Z1[0], Z1[0]} * (tr_v2d_){M1[1], M3[1]} -
                       czbz * (tr_v2d_){M3[0], M2[0]}) +
                      (tr_v2d_){Z2[1], Z2[0]} * (tr_v2d_){M2[0], M1[0]};
  const tr_v2d_ S = (tr_v2d_){L1[0], L2[0]} * MAC - (tr_v2d_){L1[1], L2[1]} * MBD;
  return S[0] + S[1];
}
#else
#define tr_dt_insphere_det tr_insphere_det_
#endif

#endif
