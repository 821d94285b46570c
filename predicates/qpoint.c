/* Exact rational points: life cycle, and correct rounding of rationals to binary64.
 *
 * Rounding is done with integer arithmetic only (mpz shifts and one division), so it
 * does not depend on the FPU rounding mode or on MPFR:
 *   |x| = n/d. Scale by 2^K so that the integer quotient m = floor(|n| 2^K / d) has at
 *   least 54 bits; the remainder tells whether anything nonzero was cut (sticky bit).
 *   The exact binary exponent of |x| is then e = bits(m) - 1 - K. The last kept bit of
 *   a binary64 has weight 2^u with u = max(e - 52, -1074) (the max is what makes
 *   subnormal results come out right: below 2^-1022 the ulp stays 2^-1074). Dropping
 *   s = u + K >= 1 low bits of m gives the truncated significand; the first dropped bit
 *   is the "half" bit and the remaining dropped bits plus the sticky bit decide ties.
 *   The kept significand is <= 2^53, so ldexp(kept, u) is exact; when it reaches 2^1024
 *   ldexp returns inf, which is exactly IEEE round-to-nearest overflow (every
 *   x >= DBL_MAX + ulp/2 rounds to inf, ties there going "to even" = up).
 */
#include "qpoint.h"

#include <float.h>
#include <math.h>

/* Rounding of |x| (x != 0): *down = largest double <= |x| (may be DBL_MAX when |x|
 * overflows), *up = smallest double >= |x| (inf when |x| > DBL_MAX), *nearest = |x|
 * rounded to nearest, ties to even (inf on overflow). */
static void round_abs(const mpq_t x, double *down, double *nearest, double *up)
{
  mpz_t n, m, r;
  mpz_init(n);
  mpz_init(m);
  mpz_init(r);
  mpz_abs(n, mpq_numref(x));
  const mpz_srcptr d = mpq_denref(x);
  long ln = (long)mpz_sizeinbase(n, 2), ld = (long)mpz_sizeinbase(d, 2);
  /* |x| < 2^(ln-ld+1) and >= 2^(ln-ld-1): quick exits far outside the double range.
   * They only save work: the general path below would give the same answers. */
  if (ln - ld - 1 > 1024) {
    *down = DBL_MAX;
    *nearest = *up = INFINITY;
    goto done;
  }
  if (ln - ld + 1 < -1080) {
    *down = *nearest = 0.0;
    *up = 0x1p-1074;
    goto done;
  }
  /* m = floor(|n| 2^K / d) has 54 or 55 bits: |x| 2^K lies in (2^53, 2^55). */
  long K = 54 - (ln - ld);
  if (K >= 0)
    mpz_mul_2exp(n, n, (mp_bitcnt_t)K);
  else {
    mpz_t dd;
    mpz_init(dd);
    mpz_mul_2exp(dd, d, (mp_bitcnt_t)(-K));
    mpz_tdiv_qr(m, r, n, dd);
    mpz_clear(dd);
    goto have_quotient;
  }
  mpz_tdiv_qr(m, r, n, d);
have_quotient:;
  int sticky = mpz_sgn(r) != 0;
  long e = (long)mpz_sizeinbase(m, 2) - 1 - K;
  long u = e - 52 < -1074 ? -1074 : e - 52;
  long s = u + K; /* >= 1 because bits(m) >= 54 */
  int half = mpz_tstbit(m, (mp_bitcnt_t)(s - 1));
  /* any dropped bit below the half bit? */
  int rest = sticky || (mpz_scan1(m, 0) < (mp_bitcnt_t)(s - 1));
  mpz_tdiv_q_2exp(m, m, (mp_bitcnt_t)s);
  /* m < 2^53 fits a double exactly */
  double t = mpz_get_d(m);
  int inexact = half || rest;
  *down = ldexp(t, (int)u);
  *up = inexact ? ldexp(t + 1.0, (int)u) : *down;
  int odd = mpz_odd_p(m);
  int round_up = half && (rest || odd);
  *nearest = round_up ? *up : *down;
  if (isinf(*down)) /* cannot happen for e <= 1023, kept for safety of the contract */
    *down = DBL_MAX;
done:
  mpz_clear(n);
  mpz_clear(m);
  mpz_clear(r);
}

/* Rounds x three ways at once: lo = largest double <= x, hi = smallest double >= x,
 * near = nearest (ties to even). Beyond the double range lo/hi saturate to +-DBL_MAX
 * on the finite side and +-inf on the other; near is +-inf (IEEE overflow). */
static void round3(const mpq_t x, double *lo, double *near, double *hi)
{
  int sg = mpq_sgn(x);
  if (sg == 0) {
    *lo = *near = *hi = 0.0;
    return;
  }
  double dn, nr, up;
  round_abs(x, &dn, &nr, &up);
  if (sg > 0) {
    *lo = dn;
    *near = nr;
    *hi = up;
  } else {
    *lo = -up;
    *near = -nr;
    *hi = -dn;
  }
}

double tr_q_round_nearest(const mpq_t x)
{
  double lo, near, hi;
  round3(x, &lo, &near, &hi);
  return near;
}

void tr_q_round_bounds(const mpq_t x, double *lo, double *hi)
{
  double near;
  round3(x, lo, &near, hi);
}

void tr_qpoint_init(tr_qpoint *q)
{
  for (int i = 0; i < 3; i++) {
    mpq_init(q->c[i]);
    mpz_init(q->hx[i]);
    q->lo[i] = q->hi[i] = q->near[i] = q->err[i] = 0.0;
  }
  mpz_init_set_ui(q->hw, 1);
}

void tr_qpoint_clear(tr_qpoint *q)
{
  for (int i = 0; i < 3; i++) {
    mpq_clear(q->c[i]);
    mpz_clear(q->hx[i]);
  }
  mpz_clear(q->hw);
}

/* hx, hw from c: hw = lcm of the denominators (usually one shared denominator for a
 * Steiner point), hx[i] = num[i] * (hw / den[i]). */
static void hom_cache(tr_qpoint *q)
{
  mpz_set(q->hw, mpq_denref(q->c[0]));
  for (int i = 1; i < 3; i++)
    if (mpz_cmp(q->hw, mpq_denref(q->c[i])) != 0)
      mpz_lcm(q->hw, q->hw, mpq_denref(q->c[i]));
  for (int i = 0; i < 3; i++) {
    if (mpz_cmp(q->hw, mpq_denref(q->c[i])) == 0)
      mpz_set(q->hx[i], mpq_numref(q->c[i]));
    else {
      mpz_divexact(q->hx[i], q->hw, mpq_denref(q->c[i]));
      mpz_mul(q->hx[i], q->hx[i], mpq_numref(q->c[i]));
    }
  }
}

/* near - lo and hi - near are each 0 or the gap between neighbouring doubles (a power
 * of two, so the subtraction is exact); inf - x = inf beyond the range. */
static void err_cache(tr_qpoint *q)
{
  for (int i = 0; i < 3; i++) {
    double a = q->near[i] - q->lo[i], b = q->hi[i] - q->near[i];
    q->err[i] = a > b ? a : b;
    if (q->err[i] != q->err[i]) /* inf - inf */
      q->err[i] = INFINITY;
  }
}

void tr_qpoint_set_d(tr_qpoint *q, const double d[3])
{
  for (int i = 0; i < 3; i++) {
    mpq_set_d(q->c[i], d[i]);
    /* -0.0 becomes +0.0: the exact value is what counts */
    q->lo[i] = q->hi[i] = q->near[i] = d[i] + 0.0;
    q->err[i] = 0.0;
  }
  hom_cache(q);
}

void tr_qpoint_update(tr_qpoint *q)
{
  for (int i = 0; i < 3; i++)
    round3(q->c[i], &q->lo[i], &q->near[i], &q->hi[i]);
  err_cache(q);
  hom_cache(q);
}

void tr_qpoint_set_point(tr_qpoint *q, const tr_point *p)
{
  if (p->q) {
    if (q == p->q)
      return;
    for (int i = 0; i < 3; i++) {
      mpq_set(q->c[i], p->q->c[i]);
      mpz_set(q->hx[i], p->q->hx[i]);
      q->lo[i] = p->q->lo[i];
      q->hi[i] = p->q->hi[i];
      q->near[i] = p->q->near[i];
      q->err[i] = p->q->err[i];
    }
    mpz_set(q->hw, p->q->hw);
  } else
    tr_qpoint_set_d(q, p->d);
}

/* Doubles: x = m 2^e with an integer m (|m| < 2^53); with E = the smallest e over the
 * nonzero coordinates, X_i = m_i 2^(e_i - E) and W = 2^-E (or W = 1 and everything
 * shifted up when E >= 0). No gcd and no rational is involved. Rationals: the form
 * cached by hom_cache. */
void tr_point_get_hom(const tr_point *p, mpz_t X[3], mpz_t W)
{
  if (!p->q) {
    int e[3], E = 0, any = 0;
    double m[3];
    for (int i = 0; i < 3; i++) {
      m[i] = frexp(p->d[i], &e[i]) * 0x1p53; /* exact: an integer below 2^53 */
      e[i] -= 53;
      if (m[i] != 0 && (!any || e[i] < E))
        E = e[i], any = 1;
    }
    for (int i = 0; i < 3; i++) {
      mpz_set_d(X[i], m[i]);
      if (m[i] != 0)
        mpz_mul_2exp(X[i], X[i], (mp_bitcnt_t)(e[i] - E + (E > 0 ? E : 0)));
    }
    mpz_set_ui(W, 1);
    if (E < 0)
      mpz_mul_2exp(W, W, (mp_bitcnt_t)(-E));
    return;
  }
  for (int i = 0; i < 3; i++)
    mpz_set(X[i], p->q->hx[i]);
  mpz_set(W, p->q->hw);
}

void tr_point_get_q(const tr_point *p, int i, mpq_t out)
{
  if (p->q)
    mpq_set(out, p->q->c[i]);
  else
    mpq_set_d(out, p->d[i]);
}
