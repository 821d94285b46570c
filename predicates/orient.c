/* orient2d, orient3d, orient2d_proj and incircle: a floating filter, Shewchuk's
 * adaptive stages, and an exact fallback, with tetrec's sign conventions.
 *
 * ---- Error model (used by every bound in this file and insphere.c) ----
 * eps = 2^-53. For normal results, fl(x op y) = (x op y)(1 + d) with |d| <= eps.
 * A term that went through k roundings is off by at most gamma_k = k eps/(1 - k eps)
 * relative. A value evaluated from rounded coordinate differences by a sum of
 * monomials therefore has |computed - exact| <= gamma_k * P, where P is the sum of the
 * absolute values of the monomials with exact differences (the "permanent") and k the
 * largest number of roundings on any monomial's path (its difference factors count:
 * fl(b - a) = (b - a)(1 + d)). Every constant below is k*(coefficient of P) rounded up
 * with slack for the O(eps^2) terms and for the roundings of the bound itself (a
 * computed bound can be up to (1-eps)^r too small after r roundings).
 *
 * ---- Stages ----
 * A (filter): semi-static bound in terms of the largest difference per coordinate.
 * B: the determinant of the *rounded* differences computed exactly as an expansion
 *    (D~). Writing each exact difference as rounded + tail with |tail| <= eps|rounded|,
 *    a degree-n monomial changes by at most ((1+eps)^n - 1)|monomial|, so
 *    |D - D~| <= (n eps + C(n,2) eps^2 + ...) P~ with P~ the permanent of the rounded
 *    differences. If all tails are 0, D~ is D.
 * C: D = D~ + L + Q with L the first-order tail terms (bounded by n eps P~) and Q the
 *    higher-order ones (<= (C(n,2) eps^2 + ...) P~). L is evaluated in floating point
 *    (Lf, error <= gamma_k * n eps P~) and added exactly: X = D~ + Lf, so
 *    |D - X| <= (k n + C(n,2)) eps^2 P~ (1 + O(eps)).
 * D: the exact determinant of the raw coordinates (no differences) as an expansion.
 * Stages B and C compare |expansion| with the bound exactly (tr_exp_sign_beyond), so
 * no estimate error enters.
 *
 * ---- Exact range ----
 * Expansion arithmetic is exact only when no product underflows and nothing
 * overflows. Let every nonzero input coordinate satisfy 2^-LO <= |x| <= 2^HI. Then
 * every coordinate, difference, tail and Veltkamp half is an integer multiple of
 * q = 2^-(LO+52), so every product of degree n the stages form is a multiple of q^n;
 * we choose LO with q^n >= 2^-902, so that nonzero products are normal doubles (the
 * relative model above holds and the exact transformations have representable
 * errors) with 2^120 to spare for the eps^2 bounds of stage C. HI keeps the degree-n
 * permanent, the sums of up to a few hundred such terms, and the Veltkamp split
 * (operand < 2^995) finite: n (HI + 1) + 10 <= 990. Inputs outside the range go to
 * tr_gmp_lifted_det_sign (expansion.c), which is exact for every finite double.
 *   degree 2 (orient2d):  LO = 390, HI = 480
 *   degree 3 (orient3d):  LO = 240, HI = 320
 *   degree 4 (incircle):  LO = 170, HI = 240
 *   degree 5 (insphere):  LO = 120, HI = 190   (insphere.c)
 * The filters use a separate, wider window (they only need the relative model up to
 * underflow errors of 2^-1075 per product, which the windows make smaller than the
 * eps*P slack of the constants).
 */
#include "expansion.h"
#include "predicates.h"

#include <math.h>

#define EPS TR_EPS

/* ---------------------------------------------------------------- orient2d ----
 * det[u; v] with u = b - a, v = c - a: ux vy - uy vx.
 * A: each monomial sees 2 difference roundings, 1 product and 1 subtraction: k = 4.
 *    P <= 2 mx my / (1-eps)^2 with mx, my the largest rounded |difference| per axis,
 *    so the bound is 8 eps (1 + O(eps)) mx my; two more roundings computing it: 9 eps.
 * B: n = 2: (2 eps + eps^2) P~; P~ computed with 2 roundings: (2 + 256 eps) eps.
 * C: L = (tux vy - tuy vx) + (ux tvy - uy tvx): k = 3, |L| <= 2 eps P~,
 *    Q <= eps^2 P~: 7 eps^2 (1 + O(eps)) -> 8 eps^2. */
#define O2_FILTER (9.0 * EPS)
#define O2_FLO 0x1p-480
#define O2_FHI 0x1p480
#define O2_B ((2.0 + 256.0 * EPS) * EPS)
#define O2_C (8.0 * EPS * EPS)
#define O2_LO 0x1p-390
#define O2_HI 0x1p480

/* Exact orient2d of raw coordinates: det[[ax ay 1];[bx by 1];[cx cy 1]]
 * = m(a,b) + m(b,c) + m(c,a) with m(p,q) = px qy - qx py. Returns the length of h
 * (at most 12). */
static int orient2d_raw(const double *a, const double *b, const double *c, double *h)
{
  double ab[4], bc[4], ca[4], t[8];
  int nab = tr_exp_two_two_diff_prod(a[0], b[1], b[0], a[1], ab);
  int nbc = tr_exp_two_two_diff_prod(b[0], c[1], c[0], b[1], bc);
  int nca = tr_exp_two_two_diff_prod(c[0], a[1], a[0], c[1], ca);
  int nt = tr_exp_sum(nab, ab, nbc, bc, t);
  return tr_exp_sum(nt, t, nca, ca, h);
}

static double orient2d_adapt(const double *a, const double *b, const double *c)
{
  /* Three points on one axis-parallel line are collinear: exactly 0 without the
   * expansions. Projections of CAD faces in axis planes (the self-intersection test,
   * facet recovery) ask this often, and the filter cannot answer it (mx or my is 0). */
  if ((a[0] == b[0] && a[0] == c[0]) || (a[1] == b[1] && a[1] == c[1]))
    return 0;
  const double *p[3] = {a, b, c};
  if (!tr_exp_in_range(3, p, 2, O2_LO, O2_HI))
    return tr_gmp_lifted_det_sign(2, 0, p);
  const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
  const double perm = fabs(ux * vy) + fabs(uy * vx);
  double B[4];
  int nb = tr_exp_two_two_diff_prod(ux, vy, uy, vx, B);
  const double tux = tr_two_diff_tail(b[0], a[0], ux), tuy = tr_two_diff_tail(b[1], a[1], uy);
  const double tvx = tr_two_diff_tail(c[0], a[0], vx), tvy = tr_two_diff_tail(c[1], a[1], vy);
  if (tux == 0 && tuy == 0 && tvx == 0 && tvy == 0)
    return tr_exp_value(nb, B);
  if (tr_exp_sign_beyond(nb, B, O2_B * perm))
    return tr_exp_value(nb, B);
  const double L = (tux * vy - tuy * vx) + (ux * tvy - uy * tvx);
  double X[5];
  int nx = tr_exp_grow(nb, B, L, X);
  if (tr_exp_sign_beyond(nx, X, O2_C * perm))
    return tr_exp_value(nx, X);
  double E[12];
  int ne = orient2d_raw(a, b, c, E);
  return tr_exp_value(ne, E);
}

double tr_orient2d(const double a[2], const double b[2], const double c[2])
{
  const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - a[0], vy = c[1] - a[1];
  const double det = ux * vy - uy * vx;
  const double mx = tr_absmax3_(ux, vx, 0), my = tr_absmax3_(uy, vy, 0);
  if (mx >= O2_FLO && my >= O2_FLO && mx <= O2_FHI && my <= O2_FHI) {
    const double eb = O2_FILTER * mx * my;
    if (det > eb || -det > eb)
      return det;
  }
  return orient2d_adapt(a, b, c);
}

double tr_orient2d_proj(const double a[3], const double b[3], const double c[3], int drop)
{
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const double pa[2] = {a[u], a[v]}, pb[2] = {b[u], b[v]}, pc[2] = {c[u], c[v]};
  return tr_orient2d(pa, pb, pc);
}

/* ---------------------------------------------------------------- orient3d ----
 * det[u; v; w] with u = b - a, v = c - a, w = d - a, evaluated as
 * (ux (vy wz - vz wy) + uy (vz wx - vx wz)) + uz (vx wy - vy wx).
 * A (TR_O3_FILTER in predicates.h): 3 difference roundings + product + subtraction +
 *    product + 2 additions: k = 8. P <= 6 mx my mz / (1-eps)^3 (each of the six
 *    monomials is a product of one |difference| per axis), so the bound is
 *    48 eps (1 + O(eps)) mx my mz; three roundings computing it: 49 eps.
 * B: n = 3: (3 eps + 3 eps^2 + eps^3) P~; P~ computed with 5 roundings:
 *    (3 + 256 eps) eps.
 * C: L = tu.(v x w) + tv.(w x u) + tw.(u x v) (the gradient of the triple product):
 *    cross products 2 roundings, dot products 3, the final sum 2: k = 7; |L| <= 3 eps P~,
 *    Q <= (3 eps^2 + eps^3) P~: 24 eps^2 (1 + O(eps)) -> 25 eps^2. */
#define O3_B ((3.0 + 256.0 * EPS) * EPS)
#define O3_C (25.0 * EPS * EPS)
#define O3_LO 0x1p-240
#define O3_HI 0x1p320

/* h = e * b + f * c (exact); returns the length. Buffers: at most 2(ne + nf). */
static int scale2_sum(int ne, const double *e, double b, int nf, const double *f, double c,
                      double *h)
{
  double s1[64], s2[64];
  int n1 = tr_exp_scale(ne, e, b, s1);
  int n2 = tr_exp_scale(nf, f, c, s2);
  return tr_exp_sum(n1, s1, n2, s2, h);
}

/* Exact orient3d of raw coordinates: D = -det[[p 1]] expanded along z,
 * D = -az T(bcd) + bz T(acd) - cz T(abd) + dz T(abc), T the raw orient2d of the xy
 * projections. Returns the length of h (at most 96). */
static int orient3d_raw(const double *a, const double *b, const double *c, const double *d,
                        double *h)
{
  double ab[4], ac[4], ad[4], bc[4], bd[4], cd[4], t1[8];
  double Tbcd[12], Tacd[12], Tabd[12], Tabc[12], s1[48], s2[48];
  int nab = tr_exp_two_two_diff_prod(a[0], b[1], b[0], a[1], ab);
  int nac = tr_exp_two_two_diff_prod(a[0], c[1], c[0], a[1], ac);
  int nad = tr_exp_two_two_diff_prod(a[0], d[1], d[0], a[1], ad);
  int nbc = tr_exp_two_two_diff_prod(b[0], c[1], c[0], b[1], bc);
  int nbd = tr_exp_two_two_diff_prod(b[0], d[1], d[0], b[1], bd);
  int ncd = tr_exp_two_two_diff_prod(c[0], d[1], d[0], c[1], cd);
  int n, nbcd, nacd, nabd, nabc, n1, n2;
  n = tr_exp_sum(nbc, bc, ncd, cd, t1); /* T(bcd) = bc + cd - bd */
  nbcd = tr_exp_diff(n, t1, nbd, bd, Tbcd);
  n = tr_exp_sum(nac, ac, ncd, cd, t1); /* T(acd) = ac + cd - ad */
  nacd = tr_exp_diff(n, t1, nad, ad, Tacd);
  n = tr_exp_sum(nab, ab, nbd, bd, t1); /* T(abd) = ab + bd - ad */
  nabd = tr_exp_diff(n, t1, nad, ad, Tabd);
  n = tr_exp_sum(nab, ab, nbc, bc, t1); /* T(abc) = ab + bc - ac */
  nabc = tr_exp_diff(n, t1, nac, ac, Tabc);
  n1 = scale2_sum(nbcd, Tbcd, -a[2], nacd, Tacd, b[2], s1);
  n2 = scale2_sum(nabd, Tabd, -c[2], nabc, Tabc, d[2], s2);
  return tr_exp_sum(n1, s1, n2, s2, h);
}

double tr_orient3d_adapt(const double a[3], const double b[3], const double c[3],
                         const double d[3])
{
  const double *p[4] = {a, b, c, d};
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = d[0] - a[0], wy = d[1] - a[1], wz = d[2] - a[2];
  const double tux = tr_two_diff_tail(b[0], a[0], ux), tuy = tr_two_diff_tail(b[1], a[1], uy),
               tuz = tr_two_diff_tail(b[2], a[2], uz);
  const double tvx = tr_two_diff_tail(c[0], a[0], vx), tvy = tr_two_diff_tail(c[1], a[1], vy),
               tvz = tr_two_diff_tail(c[2], a[2], vz);
  const double twx = tr_two_diff_tail(d[0], a[0], wx), twy = tr_two_diff_tail(d[1], a[1], wy),
               twz = tr_two_diff_tail(d[2], a[2], wz);
  const int exact_diffs = tux == 0 && tuy == 0 && tuz == 0 && tvx == 0 && tvy == 0 &&
                          tvz == 0 && twx == 0 && twy == 0 && twz == 0;
  /* Exactly representable evaluation: differences within 2^16 quanta make every
   * intermediate of the filter's expression a multiple of q^3 below 2^51 q^3 (products
   * < 2^32 q^2, minors < 2^33 q^2, terms < 2^49 q^3, sum of three < 2^51 q^3): the
   * floating determinant is exact. Integer-grid inputs (exact zeros) end here. */
  if (exact_diffs) {
    const double dv[9] = {ux, uy, uz, vx, vy, vz, wx, wy, wz};
    if (tr_exp_exact_in_float(9, dv, 16, 3))
      return (ux * (vy * wz - vz * wy) + uy * (vz * wx - vx * wz)) + uz * (vx * wy - vy * wx);
  }
  if (!tr_exp_in_range(4, p, 3, O3_LO, O3_HI))
    return -tr_gmp_lifted_det_sign(3, 0, p);
  const double perm = (fabs(ux) * (fabs(vy * wz) + fabs(vz * wy)) +
                       fabs(uy) * (fabs(vz * wx) + fabs(vx * wz))) +
                      fabs(uz) * (fabs(vx * wy) + fabs(vy * wx));
  /* Stage B: D~ = ux m_vw_yz + uy m_vw_zx + uz m_vw_xy exactly. */
  double cx[4], cy[4], cz[4], s1[16], s2[8], B[24];
  int ncx = tr_exp_two_two_diff_prod(vy, wz, vz, wy, cx);
  int ncy = tr_exp_two_two_diff_prod(vz, wx, vx, wz, cy);
  int ncz = tr_exp_two_two_diff_prod(vx, wy, vy, wx, cz);
  int n1 = scale2_sum(ncx, cx, ux, ncy, cy, uy, s1);
  int n2 = tr_exp_scale(ncz, cz, uz, s2);
  int nb = tr_exp_sum(n1, s1, n2, s2, B);
  if (exact_diffs)
    return tr_exp_value(nb, B);
  if (tr_exp_sign_beyond(nb, B, O3_B * perm))
    return tr_exp_value(nb, B);
  /* Stage C. */
  const double vw_x = vy * wz - vz * wy, vw_y = vz * wx - vx * wz, vw_z = vx * wy - vy * wx;
  const double wu_x = wy * uz - wz * uy, wu_y = wz * ux - wx * uz, wu_z = wx * uy - wy * ux;
  const double uv_x = uy * vz - uz * vy, uv_y = uz * vx - ux * vz, uv_z = ux * vy - uy * vx;
  const double L = ((tux * vw_x + tuy * vw_y) + tuz * vw_z) +
                   ((tvx * wu_x + tvy * wu_y) + tvz * wu_z) +
                   ((twx * uv_x + twy * uv_y) + twz * uv_z);
  double X[25];
  int nx = tr_exp_grow(nb, B, L, X);
  if (tr_exp_sign_beyond(nx, X, O3_C * perm))
    return tr_exp_value(nx, X);
  /* Stage D. */
  double E[96];
  int ne = orient3d_raw(a, b, c, d, E);
  return tr_exp_value(ne, E);
}

/* ---------------------------------------------------------------- incircle ----
 * Relative to d (p' = p - d, l_p = |p'|^2, m(p,q) = p'x q'y - q'x p'y):
 *   tr_incircle = l_a m(b,c) + l_b m(c,a) + l_c m(a,b)   (= det[[x y x^2+y^2 1]]).
 * A: monomials x_a^2 x_b y_c: 4 difference roundings, lift 2 (square, addition),
 *    minor 2, product 1, sum of three terms 2: k = 11. P <= 3 * 2 mx my S / (1-eps)^4
 *    with S = mx^2 + my^2: 66 eps (1 + O(eps)) mx my S; five roundings computing it:
 *    67 eps.
 * B: n = 4: (4 eps + 6 eps^2 + ...) P~; P~ computed with 7 roundings: (4 + 256 eps) eps.
 * C: L = sum over rows of 2 (p.t) m + l dm, dm(p,q) = (tpx qy - tpy qx) + (px tqy - py tqx).
 *    Paths: dm 3 roundings, times l (itself 2) 1: 6; 2 (p.t) m: dot 2, m 2, product 1: 5;
 *    row sum 1, total over rows 2: k = 9. |L| <= 4 eps P~, Q <= (6 eps^2 + ...) P~:
 *    42 eps^2 (1 + O(eps)) -> 44 eps^2. */
#define IC_FILTER (67.0 * EPS)
#define IC_FLO 0x1p-230
#define IC_FHI 0x1p230
#define IC_B ((4.0 + 256.0 * EPS) * EPS)
#define IC_C (44.0 * EPS * EPS)
#define IC_LO 0x1p-170
#define IC_HI 0x1p240

/* h = m * (x^2 + y^2) exactly (x, y single doubles); at most 8 nm components. */
static int lift2_times(int nm, const double *m, double x, double y, double *h)
{
  double t1[96], t2[192], t3[96], t4[192];
  int n1 = tr_exp_scale(nm, m, x, t1);
  int n2 = tr_exp_scale(n1, t1, x, t2);
  int n3 = tr_exp_scale(nm, m, y, t3);
  int n4 = tr_exp_scale(n3, t3, y, t4);
  return tr_exp_sum(n2, t2, n4, t4, h);
}

/* Exact incircle of raw coordinates: l_a T(bcd) - l_b T(acd) + l_c T(abd) - l_d T(abc)
 * (det[[x y l 1]] expanded along the lift column). At most 384 components. */
static int incircle_raw(const double *a, const double *b, const double *c, const double *d,
                        double *h)
{
  double T[4][12], P[4][96], s1[192], s2[192];
  const double *q[4] = {a, b, c, d};
  int nT[4], nP[4];
  nT[0] = orient2d_raw(b, c, d, T[0]);
  nT[1] = orient2d_raw(a, c, d, T[1]);
  nT[2] = orient2d_raw(a, b, d, T[2]);
  nT[3] = orient2d_raw(a, b, c, T[3]);
  for (int i = 0; i < 4; i++)
    nP[i] = lift2_times(nT[i], T[i], q[i][0], q[i][1], P[i]);
  int n1 = tr_exp_diff(nP[0], P[0], nP[1], P[1], s1);
  int n2 = tr_exp_diff(nP[2], P[2], nP[3], P[3], s2);
  return tr_exp_sum(n1, s1, n2, s2, h);
}

static double incircle_adapt(const double *a, const double *b, const double *c,
                             const double *d)
{
  const double *p[4] = {a, b, c, d};
  if (!tr_exp_in_range(4, p, 2, IC_LO, IC_HI))
    return tr_gmp_lifted_det_sign(2, 1, p);
  const double ax = a[0] - d[0], ay = a[1] - d[1], bx = b[0] - d[0], by = b[1] - d[1];
  const double cx = c[0] - d[0], cy = c[1] - d[1];
  const double la = ax * ax + ay * ay, lb = bx * bx + by * by, lc = cx * cx + cy * cy;
  const double perm = (la * (fabs(bx * cy) + fabs(cx * by)) +
                       lb * (fabs(cx * ay) + fabs(ax * cy))) +
                      lc * (fabs(ax * by) + fabs(bx * ay));
  double mbc[4], mca[4], mab[4], Pa[32], Pb[32], Pc[32], s1[64], B[96];
  int nbc = tr_exp_two_two_diff_prod(bx, cy, cx, by, mbc);
  int nca = tr_exp_two_two_diff_prod(cx, ay, ax, cy, mca);
  int nab = tr_exp_two_two_diff_prod(ax, by, bx, ay, mab);
  int na = lift2_times(nbc, mbc, ax, ay, Pa);
  int nbb = lift2_times(nca, mca, bx, by, Pb);
  int nc = lift2_times(nab, mab, cx, cy, Pc);
  int n1 = tr_exp_sum(na, Pa, nbb, Pb, s1);
  int nb = tr_exp_sum(n1, s1, nc, Pc, B);
  const double tax = tr_two_diff_tail(a[0], d[0], ax), tay = tr_two_diff_tail(a[1], d[1], ay);
  const double tbx = tr_two_diff_tail(b[0], d[0], bx), tby = tr_two_diff_tail(b[1], d[1], by);
  const double tcx = tr_two_diff_tail(c[0], d[0], cx), tcy = tr_two_diff_tail(c[1], d[1], cy);
  if (tax == 0 && tay == 0 && tbx == 0 && tby == 0 && tcx == 0 && tcy == 0)
    return tr_exp_value(nb, B);
  if (tr_exp_sign_beyond(nb, B, IC_B * perm))
    return tr_exp_value(nb, B);
  /* Stage C. */
  const double fbc = bx * cy - cx * by, fca = cx * ay - ax * cy, fab = ax * by - bx * ay;
  const double dbc = (tbx * cy - tby * cx) + (bx * tcy - by * tcx);
  const double dca = (tcx * ay - tcy * ax) + (cx * tay - cy * tax);
  const double dab = (tax * by - tay * bx) + (ax * tby - ay * tbx);
  const double ra = 2 * (ax * tax + ay * tay) * fbc + la * dbc;
  const double rb = 2 * (bx * tbx + by * tby) * fca + lb * dca;
  const double rc = 2 * (cx * tcx + cy * tcy) * fab + lc * dab;
  const double L = (ra + rb) + rc;
  double X[97];
  int nx = tr_exp_grow(nb, B, L, X);
  if (tr_exp_sign_beyond(nx, X, IC_C * perm))
    return tr_exp_value(nx, X);
  double E[384];
  int ne = incircle_raw(a, b, c, d, E);
  return tr_exp_value(ne, E);
}

double tr_incircle(const double a[2], const double b[2], const double c[2], const double d[2])
{
  const double ax = a[0] - d[0], ay = a[1] - d[1], bx = b[0] - d[0], by = b[1] - d[1];
  const double cx = c[0] - d[0], cy = c[1] - d[1];
  const double la = ax * ax + ay * ay, lb = bx * bx + by * by, lc = cx * cx + cy * cy;
  const double det = (la * (bx * cy - cx * by) + lb * (cx * ay - ax * cy)) +
                     lc * (ax * by - bx * ay);
  const double mx = tr_absmax3_(ax, bx, cx), my = tr_absmax3_(ay, by, cy);
  if (mx >= IC_FLO && my >= IC_FLO && mx <= IC_FHI && my <= IC_FHI) {
    const double eb = IC_FILTER * mx * my * (mx * mx + my * my);
    if (det > eb || -det > eb)
      return det;
  }
  return incircle_adapt(a, b, c, d);
}

/* ---- the exact stages alone (tests) ---- */
double tr_orient2d_exact(const double a[2], const double b[2], const double c[2])
{
  const double *p[3] = {a, b, c};
  if (!tr_exp_in_range(3, p, 2, O2_LO, O2_HI))
    return tr_gmp_lifted_det_sign(2, 0, p);
  double E[12];
  return tr_exp_value(orient2d_raw(a, b, c, E), E);
}

double tr_orient3d_exact(const double a[3], const double b[3], const double c[3],
                         const double d[3])
{
  const double *p[4] = {a, b, c, d};
  if (!tr_exp_in_range(4, p, 3, O3_LO, O3_HI))
    return -tr_gmp_lifted_det_sign(3, 0, p);
  double E[96];
  return tr_exp_value(orient3d_raw(a, b, c, d, E), E);
}

double tr_incircle_exact(const double a[2], const double b[2], const double c[2],
                         const double d[2])
{
  const double *p[4] = {a, b, c, d};
  if (!tr_exp_in_range(4, p, 2, IC_LO, IC_HI))
    return tr_gmp_lifted_det_sign(2, 1, p);
  double E[384];
  return tr_exp_value(incircle_raw(a, b, c, d, E), E);
}
