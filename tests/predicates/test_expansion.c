/* Expansion arithmetic: each error-free transformation and expansion operation checked
 * against exact GMP rationals on random operands over wide exponent ranges. */
#include "expansion.h"
#include "ref.h"

#include <stdlib.h>

static int fails;

/* A random double with a random sign, 53 random bits and exponent in [lo, hi]. */
static double rnd(rng_t *r, int lo, int hi)
{
  double m = 1.0 + rng_unit(r);
  double x = ldexp(m, rng_int(r, lo, hi));
  return (rng_u64(r) & 1) ? -x : x;
}

/* Value of the lowest set bit of x != 0. */
static double lowbit(double x)
{
  int k;
  double f = frexp(fabs(x), &k);
  int64_t m = (int64_t)ldexp(f, 53);
  int tz = 0;
  while (!(m & 1)) {
    m >>= 1;
    tz++;
  }
  return ldexp(1.0, k - 53 + tz);
}

static int sig_bits(double x)
{
  if (x == 0)
    return 0;
  int k;
  int64_t m = (int64_t)ldexp(frexp(fabs(x), &k), 53);
  while (!(m & 1))
    m >>= 1;
  int b = 0;
  while (m) {
    m >>= 1;
    b++;
  }
  return b;
}

static void q_of_exp(int n, const double *e, mpq_t out)
{
  mpq_t t;
  mpq_init(t);
  mpq_set_ui(out, 0, 1);
  for (int i = 0; i < n; i++) {
    mpq_set_d(t, e[i]);
    mpq_add(out, out, t);
  }
  mpq_clear(t);
}

/* Nonoverlapping, increasing magnitude, zero-eliminated (a lone 0 allowed). */
static int well_formed(int n, const double *e)
{
  if (n < 1)
    return 0;
  if (n == 1)
    return 1;
  for (int i = 0; i < n; i++)
    if (e[i] == 0)
      return 0;
  for (int i = 0; i + 1 < n; i++)
    if (!(fabs(e[i]) < lowbit(e[i + 1])))
      return 0;
  return 1;
}

static void test_two_sum(void)
{
  rng_t r = {1};
  mpq_t a, b, s;
  mpq_inits(a, b, s, NULL);
  for (int i = 0; i < 100000; i++) {
    double x = rnd(&r, -80, 80), y = rnd(&r, -80, 80), h, l;
    if (i % 7 == 0)
      y = -x * (1 + 0x1p-40);
    tr_two_sum(x, y, &h, &l);
    mpq_set_d(a, x);
    mpq_set_d(b, y);
    mpq_add(s, a, b);
    mpq_set_d(a, h);
    mpq_set_d(b, l);
    mpq_add(a, a, b);
    CHECK(h == x + y && mpq_equal(a, s) && h + l == h,
          "two_sum(%a, %a) = (%a, %a) is not error-free", x, y, h, l);
    tr_two_diff(x, y, &h, &l);
    mpq_set_d(a, x);
    mpq_set_d(b, y);
    mpq_sub(s, a, b);
    mpq_set_d(a, h);
    mpq_set_d(b, l);
    mpq_add(a, a, b);
    CHECK(h == x - y && mpq_equal(a, s) && l == tr_two_diff_tail(x, y, h),
          "two_diff(%a, %a) = (%a, %a) is not error-free", x, y, h, l);
    if (fabs(x) < fabs(y)) {
      double t = x;
      x = y;
      y = t;
    }
    tr_fast_two_sum(x, y, &h, &l);
    mpq_set_d(a, x);
    mpq_set_d(b, y);
    mpq_add(s, a, b);
    mpq_set_d(a, h);
    mpq_set_d(b, l);
    mpq_add(a, a, b);
    CHECK(h == x + y && mpq_equal(a, s), "fast_two_sum(%a, %a) is not error-free", x, y);
  }
  mpq_clears(a, b, s, NULL);
}

static void test_two_product(void)
{
  rng_t r = {2};
  mpq_t a, b, s;
  mpq_inits(a, b, s, NULL);
  for (int i = 0; i < 100000; i++) {
    double x = rnd(&r, -400, 400), y = rnd(&r, -400, 400), h, l, hi, lo;
    tr_split(x, &hi, &lo);
    CHECK(hi + lo == x && sig_bits(hi) <= 26 && sig_bits(lo) <= 26,
          "split(%a) = (%a, %a): halves must have <= 26 bits and sum to the input", x, hi, lo);
    tr_two_product(x, y, &h, &l);
    mpq_set_d(a, x);
    mpq_set_d(b, y);
    mpq_mul(s, a, b);
    mpq_set_d(a, h);
    mpq_set_d(b, l);
    mpq_add(a, a, b);
    CHECK(h == x * y && mpq_equal(a, s), "two_product(%a, %a) = (%a, %a) is not error-free",
          x, y, h, l);
  }
  mpq_clears(a, b, s, NULL);
}

/* A random well-formed expansion of up to 6 components built by Grow-Expansion. */
static int rnd_exp(rng_t *r, double *e)
{
  int n = 1, k = rng_int(r, 1, 6);
  e[0] = rnd(r, -100, 100);
  double t[16];
  for (int i = 1; i < k; i++) {
    n = tr_exp_grow(n, e, rnd(r, -100, 100), t);
    memcpy(e, t, sizeof(double) * (size_t)n);
  }
  return n;
}

static void test_expansion_ops(void)
{
  rng_t r = {3};
  mpq_t qe, qf, qh, t;
  mpq_inits(qe, qf, qh, t, NULL);
  double e[16], f[16], h[64], g[64];
  for (int i = 0; i < 30000; i++) {
    int ne = rnd_exp(&r, e), nf = rnd_exp(&r, f);
    if (i % 5 == 0) { /* cancellation: f = -e plus a little */
      for (int j = 0; j < ne; j++)
        f[j] = -e[j];
      nf = tr_exp_grow(ne, f, rnd(&r, -120, -90), h);
      memcpy(f, h, sizeof(double) * (size_t)nf);
    }
    CHECK(well_formed(ne, e) && well_formed(nf, f), "grow must give well-formed expansions");
    q_of_exp(ne, e, qe);
    q_of_exp(nf, f, qf);
    int nh = tr_exp_sum(ne, e, nf, f, h);
    q_of_exp(nh, h, qh);
    mpq_add(t, qe, qf);
    CHECK(mpq_equal(t, qh) && well_formed(nh, h), "expansion sum must be exact and well formed");
    nh = tr_exp_diff(ne, e, nf, f, h);
    q_of_exp(nh, h, qh);
    mpq_sub(t, qe, qf);
    CHECK(mpq_equal(t, qh) && well_formed(nh, h), "expansion diff must be exact and well formed");
    CHECK(tr_exp_sign(nh, h) == mpq_sgn(t), "expansion sign must be exact");
    int nd = nh;
    double b = rnd(&r, -200, 200);
    nh = tr_exp_scale(nd, h, b, g);
    q_of_exp(nh, g, qh);
    mpq_set_d(qf, b);
    mpq_mul(t, t, qf);
    CHECK(mpq_equal(t, qh) && well_formed(nh, g), "scale expansion must be exact and well formed");
    int nc = tr_exp_compress(nh, g, g);
    q_of_exp(nc, g, qf);
    CHECK(mpq_equal(t, qf) && nc <= nh && nc >= 1, "compress must preserve the value");
    double v = tr_exp_value(nc, g);
    CHECK(sgn(v) == mpq_sgn(t), "tr_exp_value must carry the exact sign");
    /* sign_beyond against an exact comparison */
    double bound = fabs(tr_exp_estimate(nc, g)) * (i % 3 == 0 ? 1.0 : (i % 3 == 1 ? 0.5 : 2.0));
    if (i % 11 == 0)
      bound = fabs(g[nc - 1]);
    mpq_abs(qf, t);
    mpq_set_d(qh, bound);
    int expect = mpq_cmp(qf, qh) > 0 ? mpq_sgn(t) : 0;
    CHECK(tr_exp_sign_beyond(nc, g, bound) == expect,
          "sign_beyond must compare |e| with the bound exactly");
    /* two_two_diff_prod */
    double x1 = rnd(&r, -100, 100), y1 = rnd(&r, -100, 100), x2 = rnd(&r, -100, 100), y2;
    y2 = (i % 4 == 0) ? x1 * y1 / x2 : rnd(&r, -100, 100);
    int n4 = tr_exp_two_two_diff_prod(x1, y1, x2, y2, h);
    mpq_set_d(qe, x1);
    mpq_set_d(qf, y1);
    mpq_mul(t, qe, qf);
    mpq_set_d(qe, x2);
    mpq_set_d(qf, y2);
    mpq_mul(qe, qe, qf);
    mpq_sub(t, t, qe);
    q_of_exp(n4, h, qh);
    CHECK(n4 <= 4 && mpq_equal(t, qh) && well_formed(n4, h), "a*b - c*d must be exact");
  }
  mpq_clears(qe, qf, qh, t, NULL);
}

int main(int argc, char **argv)
{
  if (argc < 2)
    return 2;
  if (!strcmp(argv[1], "two_sum"))
    test_two_sum();
  else if (!strcmp(argv[1], "two_product"))
    test_two_product();
  else if (!strcmp(argv[1], "ops"))
    test_expansion_ops();
  else
    return 2;
  if (fails)
    fprintf(stderr, "%s: %d failures\n", argv[1], fails);
  return fails ? 1 : 0;
}
