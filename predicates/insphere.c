/* insphere: the adaptive and exact stages behind the inline filter tr_insphere
 * (predicates.h). Error model, stage structure and exact range: see orient.c.
 *
 * Relative to e (p' = p - e, l_p = |p'|^2), with the xyz determinants of three rows
 *   M_a = det[b'; c'; d'], M_b = det[a'; c'; d'], M_c = det[a'; b'; d'], M_d = det[a'; b'; c']
 * expanded along z through the xy minors m(p,q) = p'x q'y - q'x p'y:
 *   tr_insphere = (l_a M_a - l_b M_b) + (l_c M_c - l_d M_d)
 * which is -det[[x y z x^2+y^2+z^2 1]] of the raw rows a..e: positive iff e is inside
 * the sphere abcd when tr_orient3d(a,b,c,d) > 0 (checked on an example by the tests).
 *
 * Order in tr_insphere_adapt: differences short enough for a plain floating evaluation
 * to be exact; then differences that are short integers times one power of two, exact
 * in fixed-width integers (intdet.c: near-cospherical points close together, the common
 * hard case of a Delaunay build); then the range check (GMP outside), stage A against
 * the permanent, and the expansion stages B, C, D.
 *
 * A (TR_IS_FILTER in predicates.h): a monomial is x_a^2 times a monomial of M_a: five
 *    difference roundings, lift 3 (square, two additions), M 5 (product, subtraction,
 *    product, two additions), l*M 1, the final two-level sum 2: k = 16. With mx, my, mz
 *    the largest rounded |difference| per axis and S = mx^2 + my^2 + mz^2,
 *    P <= 4 rows * 6 mx my mz * S / (1-eps)^5, so the bound is
 *    384 eps (1 + O(eps)) mx my mz S; seven roundings computing it: 385 eps.
 * A (again, in tr_insphere_adapt, inside the exact range below): the same k = 16
 *    against the permanent perm of the rounded differences, computed with at most 11
 *    roundings on any monomial (|product| 1, minor sum 1, times |z| 1, two sums 2,
 *    lift 3, l*f 1, final sums 2); the exact-difference permanent P <= perm /
 *    (1-eps)^16, so |error| <= 16 eps (1 + O(eps)) perm; 17 eps covers the O(eps^2)
 *    terms and the rounding of the bound. The range (no product underflows, nothing
 *    overflows) makes every rounding relative, as for stages B and C.
 * B: n = 5: (5 eps + 10 eps^2 + ...) P~; P~ computed with 11 roundings: (5 + 256 eps) eps.
 * C: the first-order term is the directional derivative along the tails t:
 *      L = sum_rows +-( 2 (p.t_p) M_p + l_p dM_p ),
 *    with dM for det[p;q;r] = t_p.(q x r) + t_q.(r x p) + t_r.(p x q).
 *    Paths: dM 7 (cross 2, dot 3, sum 2), times l (3) 1: 11; 2 (p.t) M: 3 + 5 + 1 = 9;
 *    the row term 1 and the final sum 2: k = 14. |L| <= 5 eps P~, Q <= (10 eps^2 + ...)
 *    P~: 80 eps^2 (1 + O(eps)) -> 82 eps^2.
 * D: -det of the raw 5x5 lifted matrix: sum_i (-1)^(i+1) l_i D(the other four), with
 *    D the raw orient3d expansion of orient.c's stage D and l_i = x^2 + y^2 + z^2
 *    multiplied in by scaling twice per axis. */
#include "expansion.h"
#include "intdet.h"
#include "predicates.h"

#include <math.h>
#include <stdlib.h>

#define EPS TR_EPS
#define IS_A (17.0 * EPS)
#define IS_B ((5.0 + 256.0 * EPS) * EPS)
#define IS_C (82.0 * EPS * EPS)
#define IS_LO 0x1p-120
#define IS_HI 0x1p190

/* h = x^2 + y^2 + z^2 exactly, compressed (at most 6 components). */
static int lift3(double x, double y, double z, double *h)
{
  double a[2], b[2], c[2], t[4], u[6];
  int na = 0, nb = 0, nc = 0;
  double hi, lo;
  tr_two_product(x, x, &hi, &lo);
  if (lo != 0)
    a[na++] = lo;
  a[na++] = hi;
  tr_two_product(y, y, &hi, &lo);
  if (lo != 0)
    b[nb++] = lo;
  b[nb++] = hi;
  tr_two_product(z, z, &hi, &lo);
  if (lo != 0)
    c[nc++] = lo;
  c[nc++] = hi;
  int nt = tr_exp_sum(na, a, nb, b, t);
  int nu = tr_exp_sum(nt, t, nc, c, u);
  return tr_exp_compress(nu, u, h);
}

/* h = m * (x^2 + y^2 + z^2) exactly, compressed: at most 12 nm components (nm <= 96).
 * The operands of near-cospherical points carry 50 to 300 significant bits; compressed,
 * m and the lift are a few components each, so the product costs a few scalings of
 * short expansions instead of six scalings of m and two long sums. */
static int lift3_times(int nm, const double *m, double x, double y, double z, double *h)
{
  double l[6], scratch[4 * 6 * 96];
  int nl = lift3(x, y, z, l);
  return tr_exp_mul(nl, l, nm, m, h, scratch);
}

/* h = e*b + f*c + g*d exactly for 4-component minors (at most 24 components). */
static int det3_from_minors(int ne, const double *e, double b, int nf, const double *f,
                            double c, int ng, const double *g, double d, double *h)
{
  double s1[8], s2[8], s3[8], t[16];
  int n1 = tr_exp_scale(ne, e, b, s1);
  int n2 = tr_exp_scale(nf, f, c, s2);
  int n3 = tr_exp_scale(ng, g, d, s3);
  int nt = tr_exp_sum(n1, s1, n2, s2, t);
  int nh = tr_exp_sum(nt, t, n3, s3, h);
  return tr_exp_compress(nh, h, h);
}

/* ---- stage D: raw coordinates ---- */

/* Raw orient3d of p[q[0..3]] given raw xy minors mm[i][j] (i < j) of the five points:
 * D = -pz T(qrs) + qz T(prs) - rz T(pqs) + sz T(pqr), T(ijk) = m_ij + m_jk - m_ik. */
static int raw_T(double mm[5][5][4], int nm[5][5], int i, int j, int k, double *h)
{
  double t[8];
  int n = tr_exp_sum(nm[i][j], mm[i][j], nm[j][k], mm[j][k], t);
  n = tr_exp_diff(n, t, nm[i][k], mm[i][k], h);
  return tr_exp_compress(n, h, h);
}

static int raw_orient3d(const double *const *p, double mm[5][5][4], int nm[5][5],
                        const int q[4], double *h)
{
  double T[4][12], s[4][24], u1[48], u2[48];
  int nT[4], ns[4];
  nT[0] = raw_T(mm, nm, q[1], q[2], q[3], T[0]);
  nT[1] = raw_T(mm, nm, q[0], q[2], q[3], T[1]);
  nT[2] = raw_T(mm, nm, q[0], q[1], q[3], T[2]);
  nT[3] = raw_T(mm, nm, q[0], q[1], q[2], T[3]);
  for (int i = 0; i < 4; i++) {
    double z = p[q[i]][2];
    ns[i] = tr_exp_scale(nT[i], T[i], (i % 2 == 0) ? -z : z, s[i]);
  }
  int n1 = tr_exp_sum(ns[0], s[0], ns[1], s[1], u1);
  int n2 = tr_exp_sum(ns[2], s[2], ns[3], s[3], u2);
  int n = tr_exp_sum(n1, u1, n2, u2, h);
  return tr_exp_compress(n, h, h);
}

enum { IS_RAW_MAX = 5 * 1152 };

/* The exact value of tr_insphere as an expansion in h (IS_RAW_MAX doubles) plus a
 * scratch of the same size; inputs in the exact range. Returns the length. */
static int insphere_raw(const double *const *p, double *h, double *scratch)
{
  double mm[5][5][4], D[96], P[1152];
  int nm[5][5];
  for (int i = 0; i < 5; i++)
    for (int j = i + 1; j < 5; j++)
      nm[i][j] = tr_exp_two_two_diff_prod(p[i][0], p[j][1], p[j][0], p[i][1], mm[i][j]);
  int n = 0;
  double *acc = h, *tmp = scratch;
  for (int i = 0; i < 5; i++) {
    int q[4], k = 0;
    for (int j = 0; j < 5; j++)
      if (j != i)
        q[k++] = j;
    int nd = raw_orient3d(p, mm, nm, q, D);
    int np = lift3_times(nd, D, p[i][0], p[i][1], p[i][2], P);
    /* term sign (-1)^(i+1): the cofactor sign of the lift column */
    if (i == 0) {
      for (int j = 0; j < np; j++)
        acc[j] = -P[j];
      n = np;
    } else {
      n = (i % 2 == 1) ? tr_exp_sum(n, acc, np, P, tmp) : tr_exp_diff(n, acc, np, P, tmp);
      double *sw = acc;
      acc = tmp;
      tmp = sw;
    }
  }
  if (acc != h)
    for (int j = 0; j < n; j++)
      h[j] = acc[j];
  return n;
}

double tr_insphere_exact(const double a[3], const double b[3], const double c[3],
                         const double d[3], const double e[3])
{
  const double *p[5] = {a, b, c, d, e};
  if (!tr_exp_in_range(5, p, 3, IS_LO, IS_HI))
    return -tr_gmp_lifted_det_sign(3, 1, p);
  double *buf = malloc(2 * IS_RAW_MAX * sizeof *buf);
  if (!buf) /* the GMP path needs far less memory */
    return -tr_gmp_lifted_det_sign(3, 1, p);
  int n = insphere_raw(p, buf, buf + IS_RAW_MAX);
  double v = tr_exp_value(n, buf);
  free(buf);
  return v;
}

double tr_insphere_adapt(const double a[3], const double b[3], const double c[3],
                         const double d[3], const double e[3])
{
  const double *p[5] = {a, b, c, d, e};
  const double ax = a[0] - e[0], ay = a[1] - e[1], az = a[2] - e[2];
  const double bx = b[0] - e[0], by = b[1] - e[1], bz = b[2] - e[2];
  const double cx = c[0] - e[0], cy = c[1] - e[1], cz = c[2] - e[2];
  const double dx = d[0] - e[0], dy = d[1] - e[1], dz = d[2] - e[2];
  const double la = (ax * ax + ay * ay) + az * az, lb = (bx * bx + by * by) + bz * bz;
  const double lc = (cx * cx + cy * cy) + cz * cz, ld = (dx * dx + dy * dy) + dz * dz;
  const double tax = tr_two_diff_tail(a[0], e[0], ax), tay = tr_two_diff_tail(a[1], e[1], ay),
               taz = tr_two_diff_tail(a[2], e[2], az);
  const double tbx = tr_two_diff_tail(b[0], e[0], bx), tby = tr_two_diff_tail(b[1], e[1], by),
               tbz = tr_two_diff_tail(b[2], e[2], bz);
  const double tcx = tr_two_diff_tail(c[0], e[0], cx), tcy = tr_two_diff_tail(c[1], e[1], cy),
               tcz = tr_two_diff_tail(c[2], e[2], cz);
  const double tdx = tr_two_diff_tail(d[0], e[0], dx), tdy = tr_two_diff_tail(d[1], e[1], dy),
               tdz = tr_two_diff_tail(d[2], e[2], dz);
  const int exact_diffs = tax == 0 && tay == 0 && taz == 0 && tbx == 0 && tby == 0 &&
                          tbz == 0 && tcx == 0 && tcy == 0 && tcz == 0 && tdx == 0 &&
                          tdy == 0 && tdz == 0;
  /* Exactly representable evaluation: differences within 2^9 quanta keep every
   * intermediate of the filter's expression (predicates.h) a multiple of q^n below
   * 2^53 q^n: minors < 2^19 q^2, M < 2^30 q^3, lifts < 2^20 q^2, l M < 2^50 q^5, the
   * two-level sum < 2^52 q^5. The floating determinant is then exact. */
  const double dv[12] = {ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz};
  if (exact_diffs) {
    if (tr_exp_exact_in_float(12, dv, 9, 5)) {
      const double ab = ax * by - bx * ay, ac = ax * cy - cx * ay, ad = ax * dy - dx * ay;
      const double bc = bx * cy - cx * by, bd = bx * dy - dx * by, cd = cx * dy - dx * cy;
      const double ma = (bz * cd - cz * bd) + dz * bc, mb = (az * cd - cz * ad) + dz * ac;
      const double mc = (az * bd - bz * ad) + dz * ab, md = (az * bc - bz * ac) + cz * ab;
      return (la * ma - lb * mb) + (lc * mc - ld * md);
    }
  }
  /* Differences that are short integers times one power of two (near-cospherical
   * points close together, the common hard case): exact in fixed-width integers. */
  double v;
  if (tr_insphere_int(p, dv, exact_diffs, &v))
    return v;
  if (!tr_exp_in_range(5, p, 3, IS_LO, IS_HI))
    return -tr_gmp_lifted_det_sign(3, 1, p);
  {
    const double pab = fabs(ax * by) + fabs(bx * ay), pac = fabs(ax * cy) + fabs(cx * ay);
    const double pad = fabs(ax * dy) + fabs(dx * ay), pbc = fabs(bx * cy) + fabs(cx * by);
    const double pbd = fabs(bx * dy) + fabs(dx * by), pcd = fabs(cx * dy) + fabs(dx * cy);
    const double fa = (fabs(bz) * pcd + fabs(cz) * pbd) + fabs(dz) * pbc;
    const double fb = (fabs(az) * pcd + fabs(cz) * pad) + fabs(dz) * pac;
    const double fc = (fabs(az) * pbd + fabs(bz) * pad) + fabs(dz) * pab;
    const double fd = (fabs(az) * pbc + fabs(bz) * pac) + fabs(cz) * pab;
    const double perm = (la * fa + lb * fb) + (lc * fc + ld * fd);

    /* Stage A with the permanent: the filter's determinant against its error bound in
     * terms of the computed permanent, far tighter than the inline filter's
     * mx my mz S on near-cospherical points (there |det| is some 10^3 eps P~ while
     * mx my mz S exceeds P~ many times), and decisive for most of them. */
    const double det = tr_insphere_det_(a, b, c, d, e);
    if (det > IS_A * perm || -det > IS_A * perm)
      return det;

    /* Stage B. */
    double ab[4], ac[4], ad[4], bc[4], bd[4], cd[4];
    int nab = tr_exp_two_two_diff_prod(ax, by, bx, ay, ab);
    int nac = tr_exp_two_two_diff_prod(ax, cy, cx, ay, ac);
    int nad = tr_exp_two_two_diff_prod(ax, dy, dx, ay, ad);
    int nbc = tr_exp_two_two_diff_prod(bx, cy, cx, by, bc);
    int nbd = tr_exp_two_two_diff_prod(bx, dy, dx, by, bd);
    int ncd = tr_exp_two_two_diff_prod(cx, dy, dx, cy, cd);
    double M[4][24], P[4][288], s1[576], s2[576], B[1152];
    int nM[4], nP[4];
    nM[0] = det3_from_minors(ncd, cd, bz, nbd, bd, -cz, nbc, bc, dz, M[0]);
    nM[1] = det3_from_minors(ncd, cd, az, nad, ad, -cz, nac, ac, dz, M[1]);
    nM[2] = det3_from_minors(nbd, bd, az, nad, ad, -bz, nab, ab, dz, M[2]);
    nM[3] = det3_from_minors(nbc, bc, az, nac, ac, -bz, nab, ab, cz, M[3]);
    nP[0] = lift3_times(nM[0], M[0], ax, ay, az, P[0]);
    nP[1] = lift3_times(nM[1], M[1], bx, by, bz, P[1]);
    nP[2] = lift3_times(nM[2], M[2], cx, cy, cz, P[2]);
    nP[3] = lift3_times(nM[3], M[3], dx, dy, dz, P[3]);
    int n1 = tr_exp_diff(nP[0], P[0], nP[1], P[1], s1);
    int n2 = tr_exp_diff(nP[2], P[2], nP[3], P[3], s2);
    int nb = tr_exp_sum(n1, s1, n2, s2, B);

    if (exact_diffs)
      return tr_exp_value(nb, B);
    if (tr_exp_sign_beyond(nb, B, IS_B * perm))
      return tr_exp_value(nb, B);

    /* Stage C: cross products X_pq = p x q of the rounded differences. */
    const double Xab[3] = {ay * bz - az * by, az * bx - ax * bz, ax * by - ay * bx};
    const double Xac[3] = {ay * cz - az * cy, az * cx - ax * cz, ax * cy - ay * cx};
    const double Xad[3] = {ay * dz - az * dy, az * dx - ax * dz, ax * dy - ay * dx};
    const double Xbc[3] = {by * cz - bz * cy, bz * cx - bx * cz, bx * cy - by * cx};
    const double Xbd[3] = {by * dz - bz * dy, bz * dx - bx * dz, bx * dy - by * dx};
    const double Xcd[3] = {cy * dz - cz * dy, cz * dx - cx * dz, cx * dy - cy * dx};
#define DOT(t, X) (((t##x) * (X)[0] + (t##y) * (X)[1]) + (t##z) * (X)[2])
    const double dMa = (DOT(tb, Xcd) - DOT(tc, Xbd)) + DOT(td, Xbc);
    const double dMb = (DOT(ta, Xcd) - DOT(tc, Xad)) + DOT(td, Xac);
    const double dMc = (DOT(ta, Xbd) - DOT(tb, Xad)) + DOT(td, Xab);
    const double dMd = (DOT(ta, Xbc) - DOT(tb, Xac)) + DOT(tc, Xab);
#undef DOT
    const double fMa = (bz * Xcd[2] - cz * Xbd[2]) + dz * Xbc[2];
    const double fMb = (az * Xcd[2] - cz * Xad[2]) + dz * Xac[2];
    const double fMc = (az * Xbd[2] - bz * Xad[2]) + dz * Xab[2];
    const double fMd = (az * Xbc[2] - bz * Xac[2]) + cz * Xab[2];
    const double ra = 2 * ((ax * tax + ay * tay) + az * taz) * fMa + la * dMa;
    const double rb = 2 * ((bx * tbx + by * tby) + bz * tbz) * fMb + lb * dMb;
    const double rc = 2 * ((cx * tcx + cy * tcy) + cz * tcz) * fMc + lc * dMc;
    const double rd = 2 * ((dx * tdx + dy * tdy) + dz * tdz) * fMd + ld * dMd;
    const double L = (ra - rb) + (rc - rd);
    double X[1153];
    int nx = tr_exp_grow(nb, B, L, X);
    if (tr_exp_sign_beyond(nx, X, IS_C * perm))
      return tr_exp_value(nx, X);
  }
  /* Stage D. */
  return tr_insphere_exact(a, b, c, d, e);
}
