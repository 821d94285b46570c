/* Filtered exact predicates on tr_point (plain doubles or exact rationals).
 *
 * Three stages, cheapest first (orient3d has a static filter on the nearest doubles in
 * place of stage 2, see orient3d_static):
 *  1. every point a plain double: the adaptive double predicate of predicates.h, which
 *     is exact for any finite doubles;
 *  2. an interval filter on the boxes [lo, hi] of the points. Interval arithmetic needs
 *     outward rounding; we do not touch the FPU mode (fesetround is slow, thread-global
 *     in practice and easy to leave in the wrong state). Instead each operation is done
 *     in the default round-to-nearest and its result r is widened to
 *     [next double below r, next double above r]. That interval contains the exact result:
 *     the exact value v is nearer to r than to any other double, so it cannot lie
 *     beyond r's neighbours. This holds for subnormal results too (gradual underflow is
 *     still round-to-nearest; we assume no flush-to-zero, i.e. no -ffast-math). Overflow
 *     is excluded up front: the filter only runs when every box coordinate has
 *     magnitude <= 2^160, so a degree-5 polynomial (insphere) stays below ~2^810 and no
 *     inf/NaN can appear. The sign is decided when the final interval excludes 0.
 *     When it does not and all points are in fact doubles (lo == hi), stage 1 decides;
 *  3. exact evaluation with GMP integers. Each point is put in homogeneous form
 *     c_i = X_i / W (W = lcm of its coordinates' denominators, > 0), and the determinant
 *     rows are built from scaled differences (X_p W_a - X_a W_p): each row is the exact
 *     row times a positive factor, so the sign is unchanged and no gcd is ever taken
 *     in the determinant itself (mpq would canonicalise after every operation, which
 *     measured ~4x slower). The temporaries are thread-local and kept between calls so
 *     the hot path does not allocate once they have grown.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "construct.h"
#include "predicates.h"
#include "qpoint.h"

/* ---- stage 3 scratch ---- */
enum { NSCRATCH_Q = 4, NSCRATCH_Z = 64 };
static _Thread_local mpq_t scratch_q[NSCRATCH_Q];
static _Thread_local mpz_t scratch_z[NSCRATCH_Z];
static _Thread_local int scratch_ready;

static void scratch_init(void)
{
  if (scratch_ready)
    return;
  for (int i = 0; i < NSCRATCH_Q; i++)
    mpq_init(scratch_q[i]);
  for (int i = 0; i < NSCRATCH_Z; i++)
    mpz_init(scratch_z[i]);
  scratch_ready = 1;
}

void tr_exact_scratch_free(void)
{
  tr_construct_scratch_free();
  if (!scratch_ready)
    return;
  for (int i = 0; i < NSCRATCH_Q; i++)
    mpq_clear(scratch_q[i]);
  for (int i = 0; i < NSCRATCH_Z; i++)
    mpz_clear(scratch_z[i]);
  scratch_ready = 0;
}

/* For n points (homogeneous: H[4k..4k+3] = X,Y,Z,W), rows k = 0..n-2 of
 * (p_{k+1} - p_0) times the positive factor V_k (= W_0 W_{k+1}, or W when equal):
 * R[3k+i] = X_{k+1,i} W_0 - X_{0,i} W_{k+1}; V[k] = the factor. t: 1 temporary. */
static void hom_rows(mpz_srcptr *H, int n, mpz_t *R, mpz_t *V, mpz_ptr t)
{
  mpz_srcptr *a = H;
  for (int k = 1; k < n; k++) {
    mpz_srcptr *p = H + 4 * k;
    mpz_t *r = R + 3 * (k - 1);
    if (mpz_cmp(p[3], a[3]) == 0) {
      for (int i = 0; i < 3; i++)
        mpz_sub(r[i], p[i], a[i]);
      if (V)
        mpz_set(V[k - 1], a[3]);
    } else {
      for (int i = 0; i < 3; i++) {
        mpz_mul(r[i], p[i], a[3]);
        mpz_mul(t, a[i], p[3]);
        mpz_sub(r[i], r[i], t);
      }
      if (V)
        mpz_mul(V[k - 1], a[3], p[3]);
    }
  }
}

/* out = det[r0; r1; r2] over mpz rows; t: 2 temporaries */
static void z_det3(mpz_ptr out, mpz_t *r0, mpz_t *r1, mpz_t *r2, mpz_t *t)
{
  mpz_mul(t[0], r1[1], r2[2]);
  mpz_submul(t[0], r1[2], r2[1]);
  mpz_mul(out, r0[0], t[0]);
  mpz_mul(t[0], r1[2], r2[0]);
  mpz_submul(t[0], r1[0], r2[2]);
  mpz_addmul(out, r0[1], t[0]);
  mpz_mul(t[0], r1[0], r2[1]);
  mpz_submul(t[0], r1[1], r2[0]);
  mpz_addmul(out, r0[2], t[0]);
  (void)t[1];
}

/* Scratch layout: z[0..19] the homogeneous form of the double points (a rational
 * point's is read in place from its cache), R = z[20..31] (4 rows), V = z[32..35],
 * temporaries from z[36]. */
static mpz_t *exact_rows(const tr_point *const *p, int n, int want_v)
{
  scratch_init();
  mpz_t *z = scratch_z;
  mpz_srcptr H[20];
  for (int k = 0; k < n; k++) {
    if (p[k]->q) {
      for (int i = 0; i < 3; i++)
        H[4 * k + i] = p[k]->q->hx[i];
      H[4 * k + 3] = p[k]->q->hw;
    } else {
      tr_point_get_hom(p[k], z + 4 * k, z[4 * k + 3]);
      for (int i = 0; i < 4; i++)
        H[4 * k + i] = z[4 * k + i];
    }
  }
  hom_rows(H, n, z + 20, want_v ? z + 32 : NULL, z[36]);
  return z;
}

/* ---- stage 2: intervals ---- */
typedef struct iv {
  double lo, hi;
} iv;

/* Beyond this magnitude the filter is skipped (see the header comment). */
#define FILTER_MAX 0x1p160

/* Neighbours of a finite double by stepping its bit pattern (what nextafter does, without
 * the libm call): for r > 0 the next larger double has the next larger pattern, for
 * r < 0 the sign-magnitude layout reverses the direction; 0 steps to +-2^-1074. */
static inline double dn(double r)
{
  if (r == 0)
    return -0x1p-1074;
  uint64_t u;
  memcpy(&u, &r, sizeof u);
  u = r > 0 ? u - 1 : u + 1;
  memcpy(&r, &u, sizeof r);
  return r;
}
static inline double up(double r)
{
  if (r == 0)
    return 0x1p-1074;
  uint64_t u;
  memcpy(&u, &r, sizeof u);
  u = r > 0 ? u + 1 : u - 1;
  memcpy(&r, &u, sizeof r);
  return r;
}

static inline iv iv_sub(iv x, iv y)
{
  iv r = {dn(x.lo - y.hi), up(x.hi - y.lo)};
  return r;
}
static inline iv iv_add(iv x, iv y)
{
  iv r = {dn(x.lo + y.lo), up(x.hi + y.hi)};
  return r;
}
static inline iv iv_mul(iv x, iv y)
{
  double p0 = x.lo * y.lo, p1 = x.lo * y.hi, p2 = x.hi * y.lo, p3 = x.hi * y.hi;
  double mn = p0, mx = p0;
  if (p1 < mn) mn = p1;
  if (p1 > mx) mx = p1;
  if (p2 < mn) mn = p2;
  if (p2 > mx) mx = p2;
  if (p3 < mn) mn = p3;
  if (p3 > mx) mx = p3;
  iv r = {dn(mn), up(mx)};
  return r;
}
static inline int iv_sign(iv x)
{
  if (x.lo > 0)
    return 1;
  if (x.hi < 0)
    return -1;
  return 2; /* undecided */
}

/* Box of coordinate i; returns 0 when too large for the filter. */
static inline int box(const tr_point *p, int i, iv *out)
{
  if (p->q) {
    out->lo = p->q->lo[i];
    out->hi = p->q->hi[i];
  } else
    out->lo = out->hi = p->d[i];
  return fabs(out->lo) <= FILTER_MAX && fabs(out->hi) <= FILTER_MAX;
}

/* 1 iff p is exactly a double point; then fills d. */
static int as_double(const tr_point *p, double d[3])
{
  if (!p->q) {
    d[0] = p->d[0], d[1] = p->d[1], d[2] = p->d[2];
    return 1;
  }
  for (int i = 0; i < 3; i++) {
    if (p->q->lo[i] != p->q->hi[i])
      return 0;
    d[i] = p->q->lo[i];
  }
  return 1;
}

static iv iv_det3(const iv r0[3], const iv r1[3], const iv r2[3])
{
  iv m0 = iv_sub(iv_mul(r1[1], r2[2]), iv_mul(r1[2], r2[1]));
  iv m1 = iv_sub(iv_mul(r1[0], r2[2]), iv_mul(r1[2], r2[0]));
  iv m2 = iv_sub(iv_mul(r1[0], r2[1]), iv_mul(r1[1], r2[0]));
  return iv_add(iv_sub(iv_mul(r0[0], m0), iv_mul(r0[1], m1)), iv_mul(r0[2], m2));
}

/* ---- stage 2a: a static filter on the nearest doubles ----
 * Cheaper than the intervals (one floating determinant, no outward rounding) and, for
 * Steiner points, about as sharp: their boxes are one ulp wide either way.
 * Notation: P_k the exact points (k = 0..3), N_k their nearest doubles (q->near),
 * |P_kj - N_kj| <= e_kj (q->err; 0 for a double point). U_kj = P_{k+1,j} - P_{0,j},
 * V_kj = N_{k+1,j} - N_{0,j} (exact reals), u_kj = fl(V_kj) the computed differences,
 * m_j = max_k |u_kj|, eps = 2^-53.
 *  (1) D~ = tr_orient3d_det_(N) satisfies |D~ - det V| <= 49 eps m_x m_y m_z when every
 *      m_j is in [2^-300, 2^300] (TR_O3_FILTER, derived in orient.c).
 *  (2) |U_kj - V_kj| <= e_{k+1,j} + e_{0,j} <= R_j := max_k (e_{k+1,j} + e_{0,j}), and
 *      |V_kj| <= m_j / (1 - eps) <= (1 + 2 eps) m_j (a difference of doubles is exact
 *      when subnormal), so |U_kj|, |V_kj| <= M_j := (1 + 2 eps) m_j + R_j.
 *  (3) det U - det V is a signed sum of 6 differences of products xyz - x'y'z' taking
 *      one entry from each column; xyz - x'y'z' = (x-x')yz + x'(y-y')z + x'y'(z-z'),
 *      so |det U - det V| <= 6 (R_x M_y M_z + M_x R_y M_z + M_x M_y R_z).
 * Hence |det U - D~| <= (1) + (3), and the sign of D~ is the sign of det U when |D~|
 * exceeds that. Computing the bound: all terms are positive and go through at most ~20
 * roundings, each losing at most a factor (1 - eps) (no underflow: a nonzero R_j is
 * first raised to >= 2^-400, which only enlarges the bound, so every product is
 * >= 2^-1000; no overflow: R_j <= 2^300 is required as well), so the final factor
 * (1 + 2^-40) more than makes up for them. Returns 2 when undecided. */
#define SF_LO 0x1p-300
#define SF_HI 0x1p300
static inline const double *near_of(const tr_point *p) { return p->q ? p->q->near : p->d; }

static int orient3d_static(const tr_point *const *p)
{
  const double *n0 = near_of(p[0]), *n1 = near_of(p[1]), *n2 = near_of(p[2]),
               *n3 = near_of(p[3]);
  double m[3], R[3];
  for (int j = 0; j < 3; j++) {
    m[j] = tr_absmax3_(n1[j] - n0[j], n2[j] - n0[j], n3[j] - n0[j]);
    double e0 = p[0]->q ? p[0]->q->err[j] : 0.0, r = 0.0;
    for (int k = 1; k < 4; k++) {
      double ek = (p[k]->q ? p[k]->q->err[j] : 0.0) + e0;
      r = ek > r ? ek : r;
    }
    if (r != 0.0 && r < 0x1p-400)
      r = 0x1p-400;
    R[j] = r;
    if (!(m[j] >= SF_LO && m[j] <= SF_HI && r <= SF_HI))
      return 2;
  }
  const double det = tr_orient3d_det_(n0, n1, n2, n3);
  const double Mx = (1.0 + 0x1p-52) * m[0] + R[0], My = (1.0 + 0x1p-52) * m[1] + R[1],
               Mz = (1.0 + 0x1p-52) * m[2] + R[2];
  const double eb = (TR_O3_FILTER * m[0] * m[1] * m[2] +
                     6.0 * ((R[0] * My * Mz + Mx * R[1] * Mz) + Mx * My * R[2])) *
                    (1.0 + 0x1p-40);
  if (det > eb)
    return 1;
  if (-det > eb)
    return -1;
  return 2;
}

/* ---- orient3d ---- */
int tr_orient3d_p(const tr_point *a, const tr_point *b, const tr_point *c, const tr_point *d)
{
  if (!a->q && !b->q && !c->q && !d->q)
    return tr_sign(tr_orient3d(a->d, b->d, c->d, d->d));
  const tr_point *p[4] = {a, b, c, d};
  /* No interval stage after this one: on cheese.off it decided 1.5k of the 2.9M calls
   * the static filter left undecided (those are nearly all exactly degenerate). */
  int s0 = orient3d_static(p);
  if (s0 != 2)
    return s0;
  double da[3], db[3], dc[3], dd[3];
  if (as_double(a, da) && as_double(b, db) && as_double(c, dc) && as_double(d, dd))
    return tr_sign(tr_orient3d_adapt(da, db, dc, dd)); /* its filter just failed */
  mpz_t *z = exact_rows(p, 4, 0);
  z_det3(z[37], z + 20, z + 23, z + 26, z + 38);
  return mpz_sgn(z[37]);
}

/* ---- orient2d on a coordinate projection ---- */
int tr_orient2d_proj_p(const tr_point *a, const tr_point *b, const tr_point *c, int drop)
{
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const tr_point *p[3] = {a, b, c};
  double da[3], db[3], dc[3];
  if (!a->q && !b->q && !c->q) {
    double pa[2] = {a->d[u], a->d[v]}, pb[2] = {b->d[u], b->d[v]}, pc[2] = {c->d[u], c->d[v]};
    return tr_sign(tr_orient2d(pa, pb, pc));
  }
  iv bx[3][2];
  int ok = 1;
  for (int k = 0; k < 3; k++) {
    ok &= box(p[k], u, &bx[k][0]);
    ok &= box(p[k], v, &bx[k][1]);
  }
  if (ok) {
    iv x1 = iv_sub(bx[1][0], bx[0][0]), y1 = iv_sub(bx[1][1], bx[0][1]);
    iv x2 = iv_sub(bx[2][0], bx[0][0]), y2 = iv_sub(bx[2][1], bx[0][1]);
    int s = iv_sign(iv_sub(iv_mul(x1, y2), iv_mul(y1, x2)));
    if (s != 2)
      return s;
  }
  if (as_double(a, da) && as_double(b, db) && as_double(c, dc)) {
    double pa[2] = {da[u], da[v]}, pb[2] = {db[u], db[v]}, pc[2] = {dc[u], dc[v]};
    return tr_sign(tr_orient2d(pa, pb, pc));
  }
  mpz_t *z = exact_rows(p, 3, 0); /* rows: z[20..22] = b-a, z[23..25] = c-a (scaled) */
  mpz_mul(z[37], z[20 + u], z[23 + v]);
  mpz_submul(z[37], z[20 + v], z[23 + u]);
  return mpz_sgn(z[37]);
}

/* incircle of the projections (the arrangement's triangulation in a triangle's plane,
 * src/resolve/cdt.c): doubles -> the adaptive predicate; else intervals on the boxes;
 * else exact on the homogeneous forms X_k / W_k. Row k of the determinant, taken from d,
 * is (D_k / S_k, |D_k|^2 / S_k^2) with D_k = X_k W_d - X_d W_k and S_k = W_k W_d > 0;
 * scaled by S_k^2 it is the integer row (D_k S_k, |D_k|^2), of the same sign. */
int tr_incircle_proj_p(const tr_point *a, const tr_point *b, const tr_point *c,
                       const tr_point *d, int drop)
{
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const tr_point *p[4] = {a, b, c, d};
  double dd[4][3];
  if (!a->q && !b->q && !c->q && !d->q) {
    double q[4][2];
    for (int k = 0; k < 4; k++)
      q[k][0] = p[k]->d[u], q[k][1] = p[k]->d[v];
    return tr_sign(tr_incircle(q[0], q[1], q[2], q[3]));
  }
  iv bx[4][2];
  int ok = 1;
  for (int k = 0; k < 4; k++) {
    ok &= box(p[k], u, &bx[k][0]);
    ok &= box(p[k], v, &bx[k][1]);
  }
  if (ok) {
    iv r[3][3];
    for (int k = 0; k < 3; k++) {
      r[k][0] = iv_sub(bx[k][0], bx[3][0]);
      r[k][1] = iv_sub(bx[k][1], bx[3][1]);
      r[k][2] = iv_add(iv_mul(r[k][0], r[k][0]), iv_mul(r[k][1], r[k][1]));
    }
    int s = iv_sign(iv_det3(r[0], r[1], r[2]));
    if (s != 2)
      return s;
  }
  if (as_double(a, dd[0]) && as_double(b, dd[1]) && as_double(c, dd[2]) && as_double(d, dd[3])) {
    double q[4][2];
    for (int k = 0; k < 4; k++)
      q[k][0] = dd[k][u], q[k][1] = dd[k][v];
    return tr_sign(tr_incircle(q[0], q[1], q[2], q[3]));
  }
  mpz_t X[4][3], W[4], m[3][3], s, t;
  for (int k = 0; k < 4; k++) {
    mpz_inits(X[k][0], X[k][1], X[k][2], W[k], NULL);
    tr_point_get_hom(p[k], X[k], W[k]);
  }
  mpz_inits(s, t, NULL);
  for (int k = 0; k < 3; k++) {
    mpz_inits(m[k][0], m[k][1], m[k][2], NULL);
    mpz_mul(s, W[k], W[3]); /* S_k */
    for (int j = 0; j < 2; j++) {
      int ax = j ? v : u;
      mpz_mul(m[k][j], X[k][ax], W[3]);
      mpz_submul(m[k][j], X[3][ax], W[k]); /* D_k */
    }
    mpz_mul(m[k][2], m[k][0], m[k][0]);
    mpz_addmul(m[k][2], m[k][1], m[k][1]);
    mpz_mul(m[k][0], m[k][0], s);
    mpz_mul(m[k][1], m[k][1], s);
  }
  mpz_set_ui(s, 0);
  for (int k = 0; k < 3; k++) {
    int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    mpz_mul(t, m[k1][1], m[k2][2]);
    mpz_submul(t, m[k1][2], m[k2][1]);
    mpz_addmul(s, t, m[k][0]);
  }
  int sg = mpz_sgn(s);
  for (int k = 0; k < 4; k++)
    mpz_clears(X[k][0], X[k][1], X[k][2], W[k], NULL);
  for (int k = 0; k < 3; k++)
    mpz_clears(m[k][0], m[k][1], m[k][2], NULL);
  mpz_clears(s, t, NULL);
  return sg;
}

/* ---- stage 2a for insphere: the same static filter ----
 * D~ = tr_insphere_det_(N) on the nearest doubles, differences taken from e (the fifth
 * point) as tr_insphere takes them; P_k the exact points, U_kj = P_kj - P_ej and
 * V_kj = N_kj - N_ej (exact reals), m_j = max_k |fl(V_kj)|, S = m_x^2 + m_y^2 + m_z^2.
 *  (1) |D~ - D(V)| <= TR_IS_FILTER m_x m_y m_z S when every m_j is in
 *      [TR_IS_FLO, TR_IS_FHI] (insphere.c, stage A).
 *  (2) |U_kj - V_kj| <= R_j := max_k (e_kj + e_ej), and |U_kj|, |V_kj| <= M_j :=
 *      (1 + 2 eps) m_j + R_j (as for orient3d_static); the lifted entries
 *      l = x^2 + y^2 + z^2 are at most SM = M_x^2 + M_y^2 + M_z^2 and differ by at most
 *      RL = 2 (R_x M_x + R_y M_y + R_z M_z) (|u^2 - v^2| = |u - v| |u + v|).
 *  (3) D is a signed sum of 24 products x y z l (one entry per column, one row each);
 *      xyzl - x'y'z'l' telescopes into four differences, so
 *      |D(U) - D(V)| <= 24 ((R_x M_y M_z + M_x R_y M_z + M_x M_y R_z) SM + M_x M_y M_z RL).
 * The sign of D~ is D(U)'s when |D~| exceeds (1) + (3). The bound is a sum of positive
 * terms through ~30 roundings, made up for by (1 + 2^-40); a nonzero R_j is first raised
 * to >= 2^-280, which only enlarges the bound and keeps every product of (3) at least
 * 2^-280 * (2^-180)^4 = 2^-1000 (no underflow); R_j <= 2^180 keeps it finite. Returns 2
 * when undecided. */
static int insphere_static(const tr_point *const *p)
{
  const double *n[5];
  for (int k = 0; k < 5; k++)
    n[k] = near_of(p[k]);
  double m[3], R[3];
  for (int j = 0; j < 3; j++) {
    m[j] = tr_absmax3_(n[0][j] - n[4][j], n[1][j] - n[4][j],
                       tr_absmax3_(n[2][j] - n[4][j], n[3][j] - n[4][j], 0));
    double e4 = p[4]->q ? p[4]->q->err[j] : 0.0, r = 0.0;
    for (int k = 0; k < 4; k++) {
      double ek = (p[k]->q ? p[k]->q->err[j] : 0.0) + e4;
      r = ek > r ? ek : r;
    }
    if (r != 0.0 && r < 0x1p-280)
      r = 0x1p-280;
    R[j] = r;
    if (!(m[j] >= TR_IS_FLO && m[j] <= TR_IS_FHI && r <= TR_IS_FHI))
      return 2;
  }
  const double det = tr_insphere_det_(n[0], n[1], n[2], n[3], n[4]);
  const double e1 = TR_IS_FILTER * m[0] * m[1] * m[2] * ((m[0] * m[0] + m[1] * m[1]) + m[2] * m[2]);
  const double Mx = (1.0 + 0x1p-52) * m[0] + R[0], My = (1.0 + 0x1p-52) * m[1] + R[1],
               Mz = (1.0 + 0x1p-52) * m[2] + R[2];
  const double SM = (Mx * Mx + My * My) + Mz * Mz;
  const double RL = 2.0 * ((R[0] * Mx + R[1] * My) + R[2] * Mz);
  const double e3 =
      24.0 * (((R[0] * My * Mz + Mx * R[1] * Mz) + Mx * My * R[2]) * SM + Mx * My * Mz * RL);
  const double eb = (e1 + e3) * (1.0 + 0x1p-40);
  if (det > eb)
    return 1;
  if (-det > eb)
    return -1;
  return 2;
}

/* ---- insphere ----
 * With rows r_k = (x_k - a, |x_k - a|^2) for x = b, c, d, e, the 5x5 lifted determinant
 * of (a..e) equals det4[r_k]. For a positively oriented abcd and e inside that det4 is
 * negative (check: a = 0, b,c,d = unit vectors, e = (1/4,1/4,1/4) gives -9/16), so
 * tr_insphere's sign is -sign(det4). det4 is expanded along the lifted column. */
int tr_insphere_p(const tr_point *a, const tr_point *b, const tr_point *c, const tr_point *d,
                  const tr_point *e)
{
  if (!a->q && !b->q && !c->q && !d->q && !e->q)
    return tr_sign(tr_insphere(a->d, b->d, c->d, d->d, e->d));
  const tr_point *p[5] = {a, b, c, d, e};
  /* the static filter first (the refinement's cavities: 9% of rotor_small in the
   * intervals below); the intervals for what it leaves */
  int s0 = insphere_static(p);
  if (s0 != 2)
    return s0;
  iv bx[5][3];
  int ok = 1;
  for (int k = 0; k < 5; k++)
    for (int i = 0; i < 3; i++)
      ok &= box(p[k], i, &bx[k][i]);
  if (ok) {
    iv r[4][3], w[4];
    for (int k = 0; k < 4; k++) {
      for (int i = 0; i < 3; i++)
        r[k][i] = iv_sub(bx[k + 1][i], bx[0][i]);
      /* squares: x*x with the interval product over-approximates when x spans 0, but
       * stays a valid enclosure */
      w[k] = iv_add(iv_add(iv_mul(r[k][0], r[k][0]), iv_mul(r[k][1], r[k][1])),
                    iv_mul(r[k][2], r[k][2]));
    }
    iv t = iv_mul(w[3], iv_det3(r[0], r[1], r[2]));
    t = iv_sub(t, iv_mul(w[2], iv_det3(r[0], r[1], r[3])));
    t = iv_add(t, iv_mul(w[1], iv_det3(r[0], r[2], r[3])));
    t = iv_sub(t, iv_mul(w[0], iv_det3(r[1], r[2], r[3])));
    int s = iv_sign(t);
    if (s != 2)
      return -s;
  }
  double da[3], db[3], dc[3], dd[3], de[3];
  if (as_double(a, da) && as_double(b, db) && as_double(c, dc) && as_double(d, dd) &&
      as_double(e, de))
    return tr_sign(tr_insphere(da, db, dc, dd, de));
  /* rows (U_k V_k, |U_k|^2): the exact lifted row times V_k^2 > 0 */
  mpz_t *z = exact_rows(p, 5, 1);
  mpz_t *R = z + 20, *V = z + 32, *w = z + 40, *acc = z + 44, *m = z + 45, *t = z + 46;
  for (int k = 0; k < 4; k++) {
    mpz_mul(w[k], R[3 * k], R[3 * k]);
    mpz_addmul(w[k], R[3 * k + 1], R[3 * k + 1]);
    mpz_addmul(w[k], R[3 * k + 2], R[3 * k + 2]);
    for (int i = 0; i < 3; i++)
      mpz_mul(R[3 * k + i], R[3 * k + i], V[k]);
  }
  /* det4 = -w0 D(1,2,3) + w1 D(0,2,3) - w2 D(0,1,3) + w3 D(0,1,2) */
  static const int rows[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
  mpz_set_ui(acc[0], 0);
  for (int k = 0; k < 4; k++) {
    z_det3(m[0], R + 3 * rows[k][0], R + 3 * rows[k][1], R + 3 * rows[k][2], t);
    if (k % 2 == 0)
      mpz_submul(acc[0], m[0], w[k]);
    else
      mpz_addmul(acc[0], m[0], w[k]);
  }
  return -mpz_sgn(acc[0]);
}

/* ---- coordinates ---- */
int tr_cmp_coord_p(const tr_point *a, const tr_point *b, int i)
{
  if (!a->q && !b->q)
    return (a->d[i] > b->d[i]) - (a->d[i] < b->d[i]);
  iv x, y;
  box(a, i, &x);
  box(b, i, &y);
  if (x.hi < y.lo)
    return -1;
  if (x.lo > y.hi)
    return 1;
  if (x.lo == x.hi && y.lo == y.hi)
    return (x.lo > y.lo) - (x.lo < y.lo);
  scratch_init();
  tr_point_get_q(a, i, scratch_q[0]);
  tr_point_get_q(b, i, scratch_q[1]);
  int r = mpq_cmp(scratch_q[0], scratch_q[1]);
  return (r > 0) - (r < 0);
}

int tr_equal_p(const tr_point *a, const tr_point *b)
{
  for (int i = 0; i < 3; i++)
    if (tr_cmp_coord_p(a, b, i) != 0)
      return 0;
  return 1;
}
