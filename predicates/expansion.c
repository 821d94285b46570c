/* Expansion arithmetic (see expansion.h for the model) and the GMP fallback used when
 * an input is outside the range where expansions are exact. */
#include "expansion.h"

#include <math.h>
#include <stdlib.h>

int tr_exp_two_two_diff_prod(double a, double b, double c, double d, double *h)
{
  double x1, y1, x2, y2;
  tr_two_product(a, b, &x1, &y1);
  tr_two_product(c, d, &x2, &y2);
  /* Grow (y1, x1) by -y2 then by -x2: two Grow-Expansion passes unrolled. */
  double i, e0, j, e1, e2, e3;
  tr_two_diff(y1, y2, &i, &e0);
  tr_two_sum(x1, i, &j, &e1);
  double k;
  tr_two_diff(e1, x2, &k, &e1);
  tr_two_sum(j, k, &e3, &e2);
  int n = 0;
  if (e0 != 0)
    h[n++] = e0;
  if (e1 != 0)
    h[n++] = e1;
  if (e2 != 0)
    h[n++] = e2;
  if (e3 != 0 || n == 0)
    h[n++] = e3;
  return n;
}

int tr_exp_grow(int elen, const double *e, double b, double *h)
{
  double q = b, t;
  int n = 0;
  for (int i = 0; i < elen; i++) {
    tr_two_sum(q, e[i], &q, &t);
    if (t != 0)
      h[n++] = t;
  }
  if (q != 0 || n == 0)
    h[n++] = q;
  return n;
}

/* Fast-Expansion-Sum of e and sf*f (sf = +1 or -1, negation is exact). The two inputs
 * are merged by increasing magnitude; the running sum q then absorbs them in that
 * order, the first step with Fast-Two-Sum (the second merged component is at least as
 * large as the first) and the others with Two-Sum. */
static int exp_sum_signed(int elen, const double *e, int flen, const double *f, double sf,
                          double *h)
{
  int ei = 0, fi = 0, n = 0;
  double q, t, g;
#define TR_NEXT_(g)                                             \
  do {                                                          \
    if (fi >= flen || (ei < elen && fabs(e[ei]) < fabs(f[fi]))) \
      (g) = e[ei++];                                            \
    else                                                        \
      (g) = sf * f[fi++];                                       \
  } while (0)
  if (elen + flen == 0) {
    h[0] = 0;
    return 1;
  }
  TR_NEXT_(q);
  if (ei + fi < elen + flen) {
    TR_NEXT_(g);
    tr_fast_two_sum(g, q, &q, &t);
    if (t != 0)
      h[n++] = t;
    while (ei + fi < elen + flen) {
      TR_NEXT_(g);
      tr_two_sum(q, g, &q, &t);
      if (t != 0)
        h[n++] = t;
    }
  }
#undef TR_NEXT_
  if (q != 0 || n == 0)
    h[n++] = q;
  return n;
}

int tr_exp_sum(int elen, const double *e, int flen, const double *f, double *h)
{
  return exp_sum_signed(elen, e, flen, f, 1.0, h);
}

int tr_exp_diff(int elen, const double *e, int flen, const double *f, double *h)
{
  return exp_sum_signed(elen, e, flen, f, -1.0, h);
}

int tr_exp_scale(int elen, const double *e, double b, double *h)
{
  double bh, bl, q, t, hi, lo, s;
  int n = 0;
  if (elen == 0) {
    h[0] = 0;
    return 1;
  }
  tr_split(b, &bh, &bl);
  tr_two_product_presplit(e[0], b, bh, bl, &q, &t);
  if (t != 0)
    h[n++] = t;
  for (int i = 1; i < elen; i++) {
    /* q holds the carried high part; add this component's exact product to it and
     * emit the two low parts that are final. */
    tr_two_product_presplit(e[i], b, bh, bl, &hi, &lo);
    tr_two_sum(q, lo, &s, &t);
    if (t != 0)
      h[n++] = t;
    tr_fast_two_sum(hi, s, &q, &t);
    if (t != 0)
      h[n++] = t;
  }
  if (q != 0 || n == 0)
    h[n++] = q;
  return n;
}

int tr_exp_compress(int elen, const double *e, double *h)
{
  if (elen <= 0) {
    h[0] = 0;
    return 1;
  }
  /* Downward pass: accumulate from the top; whenever Fast-Two-Sum leaves a nonzero
   * remainder, the sum so far is final and the remainder starts a new group. */
  int bottom = elen - 1;
  double q = e[bottom], qn, r;
  for (int i = elen - 2; i >= 0; i--) {
    tr_fast_two_sum(q, e[i], &qn, &r);
    if (r != 0) {
      h[bottom--] = qn;
      q = r;
    } else {
      q = qn;
    }
  }
  h[bottom] = q;
  /* Upward pass: re-add from the bottom so adjacent groups merge. */
  int top = 0;
  for (int i = bottom + 1; i < elen; i++) {
    tr_fast_two_sum(h[i], q, &qn, &r);
    if (r != 0)
      h[top++] = r;
    q = qn;
  }
  h[top++] = q;
  return top;
}

int tr_exp_mul(int ne, const double *e, int nf, const double *f, double *h, double *scratch)
{
  if (ne > nf) { /* loop over the shorter one: fewer (longer) scalings and sums */
    const double *t = e;
    e = f;
    f = t;
    int k = ne;
    ne = nf;
    nf = k;
  }
  double *acc = scratch, *tmp = scratch + 2 * ne * nf, *sc = h;
  int n = tr_exp_scale(nf, f, e[0], acc);
  for (int i = 1; i < ne; i++) {
    int ns = tr_exp_scale(nf, f, e[i], sc);
    n = tr_exp_sum(n, acc, ns, sc, tmp);
    double *sw = acc;
    acc = tmp;
    tmp = sw;
  }
  return tr_exp_compress(n, acc, h);
}

double tr_exp_estimate(int elen, const double *e)
{
  double s = 0;
  for (int i = 0; i < elen; i++)
    s += e[i];
  return s;
}

int tr_exp_sign_beyond(int elen, const double *e, double bound)
{
  int s = tr_exp_sign(elen, e);
  if (s == 0 || bound == 0)
    return s;
  /* Grow e by -s*bound, keeping only the largest nonzero output component: the sign of
   * e - s*bound is the sign of that component. */
  double q = -s * bound, t, top = 0;
  for (int i = 0; i < elen; i++) {
    tr_two_sum(q, e[i], &q, &t);
    if (t != 0)
      top = t;
  }
  if (q != 0)
    top = q;
  return ((top > 0) - (top < 0)) == s ? s : 0;
}

double tr_exp_value(int elen, const double *e)
{
  int s = tr_exp_sign(elen, e);
  double est = tr_exp_estimate(elen, e);
  if (((est > 0) - (est < 0)) == s)
    return est;
  for (int i = elen - 1; i >= 0; i--)
    if (e[i] != 0)
      return e[i];
  return 0;
}

/* ---- GMP fallback ----
 * Every finite double is m * 2^k with an integer |m| < 2^53. Multiplying all
 * coordinates by the same 2^-kmin makes them integers; a uniform positive scale does
 * not change the sign of an orientation or lifted determinant (the lifted column is
 * scaled by the square of the factor, the column of ones not at all). The determinant
 * is then evaluated with fraction-free Gaussian elimination (Bareiss), whose divisions
 * are exact. Orientations (no lifted column) take a cheaper path, gmp_orient_sign. */
/* The exponent of the last mantissa bit of the smallest nonzero pts[i][j], i < rows,
 * j0 <= j < j1 (0 if all are 0): scaling by 2^-that makes every such value an integer. */
static int min_exp(const double *const *pts, int rows, int j0, int j1)
{
  int kmin = 0, have = 0;
  for (int i = 0; i < rows; i++)
    for (int j = j0; j < j1; j++)
      if (pts[i][j] != 0) {
        int k;
        (void)frexp(pts[i][j], &k);
        if (!have || k - 53 < kmin)
          kmin = k - 53;
        have = 1;
      }
  return kmin;
}

/* x * 2^-kmin as an integer (kmin at most the exponent of x's last mantissa bit). */
static void scaled(mpz_t out, double x, int kmin)
{
  if (x == 0) {
    mpz_set_ui(out, 0);
    return;
  }
  int k;
  double f = frexp(x, &k);
  mpz_set_d(out, ldexp(f, 53)); /* an integer below 2^53: exact */
  mpz_mul_2exp(out, out, (mp_bitcnt_t)(k - 53 - kmin));
}

/* The orientation case (no lifted column): det[[p_i 1]] = (-1)^dim det[p_i - p_0], and
 * that is linear in each coordinate column, so every column gets its own power of two.
 * With one scale for all, a column of subnormals (a face of a model at 0 moved by
 * ulps) next to one of ordinary coordinates made 1,100-bit integers of every entry,
 * and Bareiss on the 4x4 matrix with its column of ones multiplied those up to 4,000
 * bits; the rounding repair of such a model spent 65% of its time there. */
static int gmp_orient_sign(int dim, const double *const *pts)
{
  mpz_t d[3][3], a, t, u;
  mpz_inits(a, t, u, NULL);
  for (int j = 0; j < dim; j++) {
    int kmin = min_exp(pts, dim + 1, j, j + 1);
    scaled(a, pts[0][j], kmin);
    for (int i = 1; i <= dim; i++) {
      mpz_init(d[i - 1][j]);
      scaled(d[i - 1][j], pts[i][j], kmin);
      mpz_sub(d[i - 1][j], d[i - 1][j], a);
    }
  }
  int sign;
  if (dim == 2) {
    mpz_mul(t, d[0][0], d[1][1]);
    mpz_submul(t, d[0][1], d[1][0]);
    sign = mpz_sgn(t);
  } else {
    mpz_set_ui(a, 0);
    for (int j = 0; j < 3; j++) {
      /* cofactor of d[0][j]: the 2x2 minor of rows 1, 2 without column j, signed */
      int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
      mpz_mul(t, d[1][j1], d[2][j2]);
      mpz_submul(t, d[1][j2], d[2][j1]);
      mpz_mul(u, d[0][j], t);
      mpz_add(a, a, u);
    }
    sign = -mpz_sgn(a);
  }
  for (int i = 0; i < dim; i++)
    for (int j = 0; j < dim; j++)
      mpz_clear(d[i][j]);
  mpz_clears(a, t, u, NULL);
  return sign;
}

int tr_gmp_lifted_det_sign(int dim, int lifted, const double *const *pts)
{
  if (!lifted && (dim == 2 || dim == 3))
    return gmp_orient_sign(dim, pts);
  enum { NMAX = 5 };
  const int n = dim + lifted + 1;
  mpz_t m[NMAX][NMAX];
  int kmin = min_exp(pts, n, 0, dim);
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++)
      mpz_init(m[i][j]);
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < dim; j++)
      scaled(m[i][j], pts[i][j], kmin);
    if (lifted) {
      for (int j = 0; j < dim; j++)
        mpz_addmul(m[i][dim], m[i][j], m[i][j]);
    }
    mpz_set_ui(m[i][n - 1], 1);
  }
  int sign = 1, result;
  mpz_t t;
  mpz_init(t);
  for (int k = 0; k < n - 1; k++) {
    if (mpz_sgn(m[k][k]) == 0) {
      int r = k + 1;
      while (r < n && mpz_sgn(m[r][k]) == 0)
        r++;
      if (r == n) {
        sign = 0;
        break;
      }
      for (int j = 0; j < n; j++)
        mpz_swap(m[k][j], m[r][j]);
      sign = -sign;
    }
    for (int i = k + 1; i < n; i++) {
      for (int j = k + 1; j < n; j++) {
        mpz_mul(t, m[i][j], m[k][k]);
        mpz_submul(t, m[i][k], m[k][j]);
        if (k > 0)
          mpz_divexact(m[i][j], t, m[k - 1][k - 1]);
        else
          mpz_swap(m[i][j], t);
      }
    }
  }
  result = sign * mpz_sgn(m[n - 1][n - 1]);
  mpz_clear(t);
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++)
      mpz_clear(m[i][j]);
  return result;
}
