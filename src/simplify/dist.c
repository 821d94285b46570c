/* Is an exact point p within distance d of a triangle: a filter in doubles whose error
 * term is proven below, and exact rationals (GMP) when the filter cannot tell.
 *
 * The filter's error terms. u = 2^-53 is the unit roundoff; M = the largest |coordinate|
 * of the six points. p~ (p in doubles: A + s (B - A) + t (C - A) with |s|, |t| <= 1) lies
 * within 10 u M of p; q~, the nearest point the filter finds, a + v (b - a) + w (c - a)
 * with v, w >= 0, v + w <= 1 + 2u, within 10 u M of a point of the triangle; |p~ - q~| is
 * computed with a relative error under 4u on a value under 4 M. So the exact distance is
 * at most |p~ - q~| (1 + 2^-50) + E with E = 2^-43 M, far above the 40 u M these add up
 * to. Lower bounds: the gap between p~ and the triangle's box (exact corners), and to
 * its slabs (tr_simp_prepare). Both are at most the distance of p~ to the triangle, which
 * is within E of p's. */
#include <gmp.h>
#include <math.h>

#include "simplify_impl.h"

void tr_simp_point(const double *A, const double *B, const double *C, tr_simp_pt p,
                   double out[3])
{
  /* i / 2^k and j / 2^k exactly (k <= 62, i, j < 2^32: no rounding, no underflow) */
  double sc = 1.0 / (double)((uint64_t)1 << p.k);
  double s = (double)p.i * sc, t = (double)p.j * sc;
  for (int k = 0; k < 3; k++)
    out[k] = A[k] + s * (B[k] - A[k]) + t * (C[k] - A[k]);
}

/* comparisons rather than fmin/fmax: coordinates are finite (tr_plc_set) and these are
 * library calls in a hot loop */
void tr_simp_tri_box(const double *a, const double *b, const double *c, double lo[3],
                     double hi[3])
{
  for (int k = 0; k < 3; k++) {
    double l = a[k] < b[k] ? a[k] : b[k], h = a[k] < b[k] ? b[k] : a[k];
    lo[k] = c[k] < l ? c[k] : l;
    hi[k] = c[k] > h ? c[k] : h;
  }
}

static double dot(const double *x, const double *y)
{
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

static double norm1(const double *x) { return fabs(x[0]) + fabs(x[1]) + fabs(x[2]); }

/* The nearest point of (a, b, c) to p by regions (Ericson, Real-Time Collision
 * Detection, 5.1.5), in doubles, as weights (v, w) on b - a and c - a kept in the
 * triangle; the distance |p - q|. NaN when the weights are not finite. */
static double near_double(const double *p, const double *a, const double *b, const double *c)
{
  double ab[3], ac[3], ap[3], bp[3], cp[3];
  for (int k = 0; k < 3; k++) {
    ab[k] = b[k] - a[k], ac[k] = c[k] - a[k], ap[k] = p[k] - a[k];
    bp[k] = p[k] - b[k], cp[k] = p[k] - c[k];
  }
  double d1 = dot(ab, ap), d2 = dot(ac, ap), d3 = dot(ab, bp), d4 = dot(ac, bp);
  double d5 = dot(ab, cp), d6 = dot(ac, cp), v = 0, w = 0;
  double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
  if (d1 <= 0 && d2 <= 0)
    v = w = 0;
  else if (d3 >= 0 && d4 <= d3)
    v = 1, w = 0;
  else if (vc <= 0 && d1 >= 0 && d3 <= 0)
    v = d1 / (d1 - d3), w = 0;
  else if (d6 >= 0 && d5 <= d6)
    v = 0, w = 1;
  else if (vb <= 0 && d2 >= 0 && d6 <= 0)
    v = 0, w = d2 / (d2 - d6);
  else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    v = 1 - w; /* b + w (c - b) */
  } else {
    double den = va + vb + vc;
    v = vb / den, w = vc / den;
  }
  if (!isfinite(v) || !isfinite(w))
    return NAN;
  v = v < 0 ? 0 : v > 1 ? 1 : v;
  w = w < 0 ? 0 : w > 1 ? 1 : w;
  if (v + w > 1) {
    double s = v + w;
    v /= s, w /= s;
  }
  double r2 = 0;
  for (int k = 0; k < 3; k++) {
    double q = a[k] + v * ab[k] + w * ac[k];
    r2 += (p[k] - q) * (p[k] - q);
  }
  return sqrt(r2);
}

/* The slabs of the triangle: across direction w it lies between the planes through its
 * lowest and highest vertex along w, whatever w is, so no accuracy of w is needed, only
 * the rounding of the dot products: each is a sum of three products of differences of
 * doubles, within 8 u |x|_1 |w|_1 of its value (the bounds below use 2^-48 = 32 u). The
 * directions: (roughly) the normal and the in-plane normals of the edges. */
void tr_simp_prepare(const double *a, const double *b, const double *c, tr_simp_tprep *t)
{
  t->a = a, t->b = b, t->c = c;
  tr_simp_tri_box(a, b, c, t->lo, t->hi);
  t->m = 0;
  for (int k = 0; k < 3; k++)
    t->m = fmax(t->m, fmax(fabs(t->lo[k]), fabs(t->hi[k])));
  double u[3], v[3], *n = t->w[0];
  for (int k = 0; k < 3; k++)
    u[k] = b[k] - a[k], v[k] = c[k] - a[k];
  n[0] = u[1] * v[2] - u[2] * v[1];
  n[1] = u[2] * v[0] - u[0] * v[2];
  n[2] = u[0] * v[1] - u[1] * v[0];
  const double *q[3] = {a, b, c};
  for (int i = 0; i < 3; i++) {
    double ed[3], *e = t->w[i + 1];
    for (int k = 0; k < 3; k++)
      ed[k] = q[(i + 1) % 3][k] - q[i][k];
    e[0] = n[1] * ed[2] - n[2] * ed[1];
    e[1] = n[2] * ed[0] - n[0] * ed[2];
    e[2] = n[0] * ed[1] - n[1] * ed[0];
  }
  for (int s = 0; s < 4; s++) {
    const double *w = t->w[s];
    t->wn1[s] = norm1(w);
    t->wlen[s] = sqrt(dot(w, w)) * (1 + 0x1p-50);
    double tb = dot(u, w), tc = dot(v, w);
    double eb = 0x1p-48 * norm1(u) * t->wn1[s], ec = 0x1p-48 * norm1(v) * t->wn1[s];
    t->hi_t[s] = fmax(0, fmax(tb + eb, tc + ec)) * (1 + 0x1p-50);
    t->lo_t[s] = fmin(0, fmin(tb - eb, tc - ec)) * (1 + 0x1p-50);
  }
  /* |w0 . ws| / (|w0| |ws|), rounded up: the dot product within 2^-48 of the 1-norms'
   * product, the lengths (wlen, rounded up by 2^-50) taken 2^-48 smaller. Near 0: the
   * in-plane normals are normal to w0 but for rounding. */
  t->cos0[0] = 1;
  for (int s = 1; s < 4; s++) {
    double num = fabs(dot(t->w[0], t->w[s])) + 0x1p-48 * t->wn1[0] * t->wn1[s];
    double den = t->wlen[0] * t->wlen[s] * (1 - 0x1p-47);
    t->cos0[s] = den > 0 ? fmin(1, num / den * (1 + 0x1p-50)) : 1;
  }
}

/* A lower bound of |x| for every x with x . u >= a and x . v >= b (a, b >= 0; u, v unit
 * vectors, |u . v| <= c < 1/2): the smallest such x lies in the plane of u and v, on
 * both lines when neither bound alone implies the other, where the Gram matrix gives
 * |x|^2 = (a^2 + b^2 - 2 a b c') / (1 - c'^2) with c' = u . v, smallest at c' = c. */
static double pythagoras(double a, double b, double c)
{
  if (!(c < 0.5))
    return fmax(a, b);
  if (b <= a * c)
    return a;
  if (a <= b * c)
    return b;
  return sqrt((a * a + b * b - 2 * a * b * c) / (1 - c * c)) * (1 - 0x1p-48);
}

/* A lower bound of the distance of p~ to the triangle: the gap to its box, then to its
 * slabs (stopping once one is over d), then the normal slab's gap with each edge's: the
 * two directions are orthogonal but for rounding, and a point beyond both is farther
 * than either gap alone (a point near the plane but past an edge, at a distance just
 * over d, would otherwise take the exact test: 39,624 times, all "farther", when
 * 1452677.stl was simplified). */
static double lower_double(const double *p, const tr_simp_tprep *t, double d)
{
  double g2 = 0;
  for (int k = 0; k < 3; k++) {
    double g = t->lo[k] - p[k] > 0 ? t->lo[k] - p[k] : p[k] - t->hi[k] > 0 ? p[k] - t->hi[k] : 0;
    g2 += g * g;
  }
  double best = sqrt(g2) * (1 - 0x1p-50);
  double x[3];
  for (int k = 0; k < 3; k++)
    x[k] = p[k] - t->a[k];
  double xn = norm1(x);
  double gap[4] = {0, 0, 0, 0};
  for (int s = 0; s < 4 && best <= d; s++) {
    double v = dot(x, t->w[s]), e = 0x1p-48 * xn * t->wn1[s];
    double g = v - e > t->hi_t[s] ? (v - e - t->hi_t[s]) * (1 - 0x1p-50)
               : v + e < t->lo_t[s] ? (t->lo_t[s] - v - e) * (1 - 0x1p-50) : 0;
    if (g > 0 && t->wlen[s] > 0)
      best = fmax(best, gap[s] = g / t->wlen[s] * (1 - 0x1p-50));
  }
  for (int s = 1; s < 4 && best <= d; s++)
    if (gap[0] > 0 && gap[s] > 0)
      best = fmax(best, pythagoras(gap[0], gap[s], t->cos0[s]));
  return best;
}

/* The exact test: p's exact rational position, Ericson's regions in rationals, then
 * |p - q|^2 <= d^2. */
static int within_exact(const double *A, const double *B, const double *C, tr_simp_pt pt,
                        const double *a, const double *b, const double *c, double d)
{
  mpq_t p[3], ab[3], ac[3], ap[3], bp[3], cp[3], dd[7], x, y, v, w, t;
  mpq_t *all[] = {p, ab, ac, ap, bp, cp};
  for (int s = 0; s < 6; s++)
    for (int k = 0; k < 3; k++)
      mpq_init(all[s][k]);
  for (int k = 0; k < 7; k++)
    mpq_init(dd[k]);
  mpq_init(x), mpq_init(y), mpq_init(v), mpq_init(w), mpq_init(t);
  mpq_t si, ti;
  mpq_init(si), mpq_init(ti);
  mpz_set_ui(mpq_numref(si), pt.i);
  mpz_set_ui(mpq_numref(ti), pt.j);
  mpz_set_ui(mpq_denref(si), 1);
  mpz_set_ui(mpq_denref(ti), 1);
  mpz_mul_2exp(mpq_denref(si), mpq_denref(si), (mp_bitcnt_t)pt.k);
  mpz_mul_2exp(mpq_denref(ti), mpq_denref(ti), (mp_bitcnt_t)pt.k);
  mpq_canonicalize(si), mpq_canonicalize(ti);
  for (int k = 0; k < 3; k++) {
    mpq_set_d(p[k], A[k]);
    mpq_set_d(x, B[k]);
    mpq_sub(x, x, p[k]);
    mpq_mul(x, x, si);
    mpq_set_d(y, C[k]);
    mpq_sub(y, y, p[k]);
    mpq_mul(y, y, ti);
    mpq_add(p[k], p[k], x);
    mpq_add(p[k], p[k], y);
    mpq_set_d(x, a[k]);
    mpq_set_d(ab[k], b[k]);
    mpq_sub(ab[k], ab[k], x);
    mpq_set_d(ac[k], c[k]);
    mpq_sub(ac[k], ac[k], x);
    mpq_sub(ap[k], p[k], x);
    mpq_set_d(y, b[k]);
    mpq_sub(bp[k], p[k], y);
    mpq_set_d(y, c[k]);
    mpq_sub(cp[k], p[k], y);
  }
  /* dd[0..5] = d1..d6 */
  const mpq_t *l[6] = {&ab[0], &ac[0], &ab[0], &ac[0], &ab[0], &ac[0]};
  const mpq_t *r[6] = {&ap[0], &ap[0], &bp[0], &bp[0], &cp[0], &cp[0]};
  for (int s = 0; s < 6; s++) {
    mpq_set_ui(dd[s], 0, 1);
    for (int k = 0; k < 3; k++) {
      mpq_mul(x, l[s][k], r[s][k]);
      mpq_add(dd[s], dd[s], x);
    }
  }
  mpq_t va, vb, vc;
  mpq_init(va), mpq_init(vb), mpq_init(vc);
  mpq_mul(vc, dd[0], dd[3]), mpq_mul(x, dd[2], dd[1]), mpq_sub(vc, vc, x);
  mpq_mul(vb, dd[4], dd[1]), mpq_mul(x, dd[0], dd[5]), mpq_sub(vb, vb, x);
  mpq_mul(va, dd[2], dd[5]), mpq_mul(x, dd[4], dd[3]), mpq_sub(va, va, x);
  int s1 = mpq_sgn(dd[0]), s2 = mpq_sgn(dd[1]), s3 = mpq_sgn(dd[2]), s4, s6 = mpq_sgn(dd[5]);
  mpq_sub(x, dd[3], dd[2]); /* d4 - d3 */
  s4 = mpq_sgn(x);
  mpq_sub(y, dd[4], dd[5]); /* d5 - d6 */
  int s56 = mpq_sgn(y);
  mpq_set_ui(v, 0, 1), mpq_set_ui(w, 0, 1);
  if (s1 <= 0 && s2 <= 0) {
  } else if (s3 >= 0 && s4 <= 0) {
    mpq_set_ui(v, 1, 1);
  } else if (mpq_sgn(vc) <= 0 && s1 >= 0 && s3 <= 0) {
    mpq_sub(t, dd[0], dd[2]);
    mpq_div(v, dd[0], t);
  } else if (s6 >= 0 && s56 <= 0) {
    mpq_set_ui(w, 1, 1);
  } else if (mpq_sgn(vb) <= 0 && s2 >= 0 && s6 <= 0) {
    mpq_sub(t, dd[1], dd[5]);
    mpq_div(w, dd[1], t);
  } else if (mpq_sgn(va) <= 0 && s4 >= 0 && s56 >= 0) {
    mpq_add(t, x, y);
    mpq_div(w, x, t);
    mpq_set_ui(v, 1, 1);
    mpq_sub(v, v, w);
  } else {
    mpq_add(t, va, vb);
    mpq_add(t, t, vc);
    mpq_div(v, vb, t);
    mpq_div(w, vc, t);
  }
  /* |p - q|^2 = |ap - v ab - w ac|^2 */
  mpq_set_ui(dd[6], 0, 1);
  for (int k = 0; k < 3; k++) {
    mpq_mul(x, v, ab[k]);
    mpq_sub(t, ap[k], x);
    mpq_mul(x, w, ac[k]);
    mpq_sub(t, t, x);
    mpq_mul(t, t, t);
    mpq_add(dd[6], dd[6], t);
  }
  mpq_set_d(x, d);
  mpq_mul(x, x, x);
  int in = mpq_cmp(dd[6], x) <= 0;
  for (int s = 0; s < 6; s++)
    for (int k = 0; k < 3; k++)
      mpq_clear(all[s][k]);
  for (int k = 0; k < 7; k++)
    mpq_clear(dd[k]);
  mpq_clear(x), mpq_clear(y), mpq_clear(v), mpq_clear(w), mpq_clear(t);
  mpq_clear(si), mpq_clear(ti), mpq_clear(va), mpq_clear(vb), mpq_clear(vc);
  return in;
}

int tr_simp_within(const double *A, const double *B, const double *C, tr_simp_pt pt,
                   const double p[3], double m, const tr_simp_tprep *t, double d, double *ub)
{
  double mt = t->m;
  double E = 0x1p-44 * (m > mt ? m : mt) * 2;
  if (ub)
    *ub = INFINITY;
  if (lower_double(p, t, d + E) - E > d * (1 + 0x1p-50))
    return 0;
  double r = near_double(p, t->a, t->b, t->c);
  if (!isnan(r)) {
    double up = (r * (1 + 0x1p-50) + E) * (1 + 0x1p-50);
    if (ub)
      *ub = up;
    if (up <= d)
      return 1;
  }
  return within_exact(A, B, C, pt, t->a, t->b, t->c, d);
}
