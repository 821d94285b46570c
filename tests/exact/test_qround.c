/* Correct rounding of rationals to doubles (tr_q_round_nearest, tr_q_round_bounds). */
#include <float.h>
#include <math.h>

#include "check.h"
#include "qpoint.h"

/* x = m * 2^e (+ sgn * 2^f if f is not 0) */
static void set_pow(mpq_t x, long m, long e)
{
  mpq_set_si(x, m, 1);
  if (e >= 0)
    mpq_mul_2exp(x, x, (mp_bitcnt_t)e);
  else
    mpq_div_2exp(x, x, (mp_bitcnt_t)(-e));
}
static void add_pow(mpq_t x, long m, long e)
{
  mpq_t t;
  mpq_init(t);
  set_pow(t, m, e);
  mpq_add(x, x, t);
  mpq_clear(t);
}

static void expect(const mpq_t x, double want, const char *what)
{
  double got = tr_q_round_nearest(x);
  CHECK(got == want && signbit(got) == signbit(want), "%s: got %a want %a", what, got, want);
  mpq_t y;
  mpq_init(y);
  mpq_neg(y, x);
  got = tr_q_round_nearest(y);
  CHECK(got == -want, "-(%s): got %a want %a", what, got, -want);
  mpq_clear(y);
}

static void halfway_ties_to_even(void)
{
  mpq_t x;
  mpq_init(x);
  set_pow(x, 1, 0);
  add_pow(x, 1, -53); /* halfway 1 .. 1+2^-52: even is 1 */
  expect(x, 1.0, "1+2^-53");
  set_pow(x, 1, 0);
  add_pow(x, 3, -53); /* halfway 1+2^-52 (odd) .. 1+2^-51 (even) */
  expect(x, 1.0 + 0x1p-51, "1+3*2^-53");
  set_pow(x, 1, 0);
  add_pow(x, 1, -53);
  add_pow(x, 1, -300); /* just above halfway */
  expect(x, 1.0 + 0x1p-52, "1+2^-53+2^-300");
  set_pow(x, 1, 0);
  add_pow(x, 1, -53);
  add_pow(x, -1, -300); /* just below halfway */
  expect(x, 1.0, "1+2^-53-2^-300");
  /* a halfway point with a large exponent */
  set_pow(x, (1L << 53) - 1, 900);
  add_pow(x, 1, 899);
  expect(x, 0x1p953, "(2^53-1+1/2)*2^900");
  mpq_clear(x);
}

/* IEEE division of two doubles is correctly rounded: an independent oracle. */
static void matches_ieee_division(void)
{
  mpq_t x;
  mpq_init(x);
  mpq_set_ui(x, 1, 3);
  expect(x, 1.0 / 3.0, "1/3");
  for (int it = 0; it < 20000; it++) {
    long p = check_irand(1, (1L << 53) - 1), q = check_irand(1, (1L << 53) - 1);
    int sp = (int)check_irand(-1000, 960), sq = (int)check_irand(-20, 20);
    double dp = ldexp((double)p, sp), dq = ldexp((double)q, sq);
    mpq_t a;
    mpq_init(a);
    mpq_set_d(a, dp);
    mpq_set_d(x, dq);
    mpq_div(x, a, x);
    double want = dp / dq;
    double got = tr_q_round_nearest(x);
    CHECK(got == want, "%a / %a: got %a want %a", dp, dq, got, want);
    mpq_clear(a);
  }
  mpq_clear(x);
}

static void subnormals(void)
{
  mpq_t x;
  mpq_init(x);
  set_pow(x, 1, -1074);
  expect(x, 0x1p-1074, "2^-1074");
  set_pow(x, 1, -1075); /* halfway 0 .. 2^-1074: even is 0 */
  expect(x, 0.0, "2^-1075");
  set_pow(x, 1, -1075);
  add_pow(x, 1, -2000);
  expect(x, 0x1p-1074, "2^-1075+2^-2000");
  set_pow(x, 3, -1075); /* halfway 2^-1074 (odd) .. 2^-1073 (even) */
  expect(x, 0x1p-1073, "3*2^-1075");
  set_pow(x, 3, -1076); /* 0.75 ulp */
  expect(x, 0x1p-1074, "3*2^-1076");
  set_pow(x, (1L << 52) - 1, -1074);
  add_pow(x, 1, -1075); /* largest subnormal + half ulp: tie to even = 2^-1022 */
  expect(x, 0x1p-1022, "max subnormal + half ulp");
  set_pow(x, 1, -5000);
  expect(x, 0.0, "2^-5000");
  /* oracle: a single IEEE division with a subnormal result */
  for (int it = 0; it < 20000; it++) {
    long p = check_irand(1, (1L << 53) - 1), q = check_irand(1, (1L << 53) - 1);
    double dp = ldexp((double)p, -1000 - (int)check_irand(0, 40)), dq = ldexp((double)q, 60);
    mpq_t a;
    mpq_init(a);
    mpq_set_d(a, dp);
    mpq_set_d(x, dq);
    mpq_div(x, a, x);
    double want = dp / dq, got = tr_q_round_nearest(x);
    CHECK(got == want, "%a / %a: got %a want %a", dp, dq, got, want);
    mpq_clear(a);
  }
  mpq_clear(x);
}

static void overflow(void)
{
  mpq_t x;
  mpq_init(x);
  mpq_set_d(x, DBL_MAX);
  expect(x, DBL_MAX, "DBL_MAX");
  add_pow(x, 1, 970); /* DBL_MAX + ulp/2: ties to even -> 2^1024 -> inf */
  expect(x, INFINITY, "DBL_MAX + ulp/2");
  add_pow(x, -1, 600);
  expect(x, DBL_MAX, "DBL_MAX + ulp/2 - 2^600");
  set_pow(x, 1, 1100);
  expect(x, INFINITY, "2^1100");
  double lo, hi;
  tr_q_round_bounds(x, &lo, &hi);
  CHECK(lo == DBL_MAX && hi == INFINITY, "bounds of 2^1100: [%a, %a]", lo, hi);
  mpq_neg(x, x);
  tr_q_round_bounds(x, &lo, &hi);
  CHECK(lo == -INFINITY && hi == -DBL_MAX, "bounds of -2^1100: [%a, %a]", lo, hi);
  mpq_clear(x);
}

/* lo <= x <= hi exactly, lo == hi iff x is a double, else hi == nextafter(lo), and the
 * nearest is the closer one (ties to even mantissa). */
static void bounds_bracket(void)
{
  mpq_t x, t, dlo, dhi;
  mpq_init(x), mpq_init(t), mpq_init(dlo), mpq_init(dhi);
  for (int it = 0; it < 20000; it++) {
    mpz_set_ui(mpq_numref(x), (unsigned long)check_rand());
    mpz_mul_ui(mpq_numref(x), mpq_numref(x), (unsigned long)check_rand());
    mpz_set_ui(mpq_denref(x), (unsigned long)(check_rand() | 1));
    mpq_canonicalize(x);
    long sh = check_irand(-1150, 1000);
    if (sh >= 0)
      mpq_mul_2exp(x, x, (mp_bitcnt_t)sh);
    else
      mpq_div_2exp(x, x, (mp_bitcnt_t)(-sh));
    if (it & 1)
      mpq_neg(x, x);
    if (it % 7 == 0) /* exact doubles too */
      mpq_set_d(x, ldexp((double)check_irand(-1000000, 1000000), (int)check_irand(-1100, 900)));
    double lo, hi, near = tr_q_round_nearest(x);
    tr_q_round_bounds(x, &lo, &hi);
    if (isinf(lo) || isinf(hi))
      continue;
    mpq_set_d(dlo, lo);
    mpq_set_d(dhi, hi);
    CHECK(mpq_cmp(dlo, x) <= 0 && mpq_cmp(x, dhi) <= 0, "bracket %a %a", lo, hi);
    CHECK((lo == hi) == (mpq_equal(dlo, x) != 0), "exactness %a", lo);
    CHECK(lo == hi || hi == nextafter(lo, INFINITY), "adjacent %a %a", lo, hi);
    CHECK(near == lo || near == hi, "nearest in bounds %a", near);
    /* distance test */
    mpq_sub(dlo, x, dlo);
    mpq_sub(dhi, dhi, x);
    int c = mpq_cmp(dlo, dhi);
    if (lo != hi) {
      if (c < 0)
        CHECK(near == lo, "closer to lo %a", lo);
      else if (c > 0)
        CHECK(near == hi, "closer to hi %a", hi);
      else {
        /* hi - lo is the spacing (exact); near / spacing is the integer significand */
        CHECK(fmod(fabs(near) / (hi - lo), 2.0) == 0.0, "tie not to even %a", near);
      }
    }
  }
  mpq_clear(x), mpq_clear(t), mpq_clear(dlo), mpq_clear(dhi);
}

static void huge_and_tiny(void)
{
  mpq_t x;
  mpq_init(x);
  mpq_set_d(x, 1e300);
  expect(x, 1e300, "1e300");
  mpq_set_d(x, 1e-300);
  expect(x, 1e-300, "1e-300");
  mpz_ui_pow_ui(mpq_numref(x), 10, 400);
  mpz_set_ui(mpq_denref(x), 1);
  expect(x, INFINITY, "1e400");
  mpq_inv(x, x);
  expect(x, 0.0, "1e-400");
  double lo, hi;
  tr_q_round_bounds(x, &lo, &hi);
  CHECK(lo == 0.0 && hi == 0x1p-1074, "bounds of 1e-400: [%a, %a]", lo, hi);
  /* 10^k / 10^(k-1) with huge numbers: exactly 10 */
  mpz_ui_pow_ui(mpq_numref(x), 10, 5000);
  mpz_ui_pow_ui(mpq_denref(x), 10, 4999);
  expect(x, 10.0, "10^5000/10^4999");
  mpq_set_ui(x, 0, 1);
  expect(x, 0.0, "0");
  mpq_clear(x);
}

int main(int argc, char **argv)
{
  static const check_case cases[] = {
      {"halfway_ties_to_even", halfway_ties_to_even},
      {"matches_ieee_division", matches_ieee_division},
      {"subnormals", subnormals},
      {"overflow_to_inf", overflow},
      {"bounds_bracket_and_nearest", bounds_bracket},
      {"huge_and_tiny", huge_and_tiny},
  };
  return check_main(argc, argv, cases, (int)(sizeof cases / sizeof cases[0]));
}
