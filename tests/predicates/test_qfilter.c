/* The rational-point side of the predicates: the static filter of tr_orient3d_p on the
 * nearest doubles (xpredicates.c) and the cached homogeneous form and error bound of a
 * tr_qpoint (qpoint.c), against an in-test mpq evaluation.
 *
 * The filter's risky inputs are Steiner-like points (rationals with large denominators,
 * so near != exact) that are exactly coplanar or off the plane by a few ulps or less:
 * those must come out exactly, never decided by a bound that is too small.
 * Usage: test_qfilter <property>. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "qpoint.h"

static int fails, checks;
#define CHECK(c, ...)                                                                    \
  do {                                                                                   \
    checks++;                                                                            \
    if (!(c) && ++fails <= 20) {                                                         \
      fprintf(stderr, "FAIL %s:%d: %s: ", __FILE__, __LINE__, #c);                       \
      fprintf(stderr, __VA_ARGS__);                                                      \
      fputc('\n', stderr);                                                               \
    }                                                                                    \
  } while (0)

static unsigned long long rng = 0x2545F4914F6CDD1Dull;
static unsigned long long rnd(void)
{
  rng ^= rng >> 12;
  rng ^= rng << 25;
  rng ^= rng >> 27;
  return rng * 2685821657736338717ull;
}
static long irand(long lo, long hi) { return lo + (long)(rnd() % (unsigned long long)(hi - lo + 1)); }

/* sign of det[b-a; c-a; d-a] over mpq, by cofactors on the exact coordinates */
static int ref_orient3d(const tr_qpoint *p[4])
{
  mpq_t r[3][3], t, u, acc;
  mpq_init(t);
  mpq_init(u);
  mpq_init(acc);
  for (int k = 0; k < 3; k++)
    for (int i = 0; i < 3; i++) {
      mpq_init(r[k][i]);
      mpq_sub(r[k][i], p[k + 1]->c[i], p[0]->c[i]);
    }
  for (int i = 0; i < 3; i++) {
    int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
    mpq_mul(t, r[1][i1], r[2][i2]);
    mpq_mul(u, r[1][i2], r[2][i1]);
    mpq_sub(t, t, u);
    mpq_mul(t, t, r[0][i]);
    mpq_add(acc, acc, t);
  }
  int s = mpq_sgn(acc);
  for (int k = 0; k < 3; k++)
    for (int i = 0; i < 3; i++)
      mpq_clear(r[k][i]);
  mpq_clear(t);
  mpq_clear(u);
  mpq_clear(acc);
  return s;
}

/* A Steiner-like point: (1 - w) x + w y for double points x, y and w = num / den with a
 * large odd den, all scaled by 2^scale. */
static void steiner_like(tr_qpoint *q, int scale)
{
  mpq_t w, t;
  mpq_init(w);
  mpq_init(t);
  mpq_set_si(w, irand(1, 1000000), (unsigned long)(2 * irand(500000, 1000000) + 1));
  mpq_canonicalize(w);
  for (int i = 0; i < 3; i++) {
    double x = ldexp((double)irand(-1000000, 1000000), scale - 20);
    double y = ldexp((double)irand(-1000000, 1000000), scale - 20);
    mpq_set_d(t, y - x); /* exact: both are small integers times one power of two */
    mpq_mul(t, t, w);
    mpq_set_d(q->c[i], x);
    mpq_add(q->c[i], q->c[i], t);
  }
  tr_qpoint_update(q);
  mpq_clear(w);
  mpq_clear(t);
}

/* d = a + s (b - a) + t (c - a) exactly (coplanar with a, b, c), then moved by
 * off * 2^-shift * (unit vector i) so that it is just off the plane (or not). */
static void near_plane(tr_qpoint *d, const tr_qpoint *a, const tr_qpoint *b, const tr_qpoint *c,
                       long off, int shift)
{
  mpq_t s, t, x;
  mpq_init(s);
  mpq_init(t);
  mpq_init(x);
  mpq_set_si(s, irand(-7, 7), 3);
  mpq_canonicalize(s);
  mpq_set_si(t, irand(-7, 7), 5);
  mpq_canonicalize(t);
  int axis = (int)irand(0, 2);
  for (int i = 0; i < 3; i++) {
    mpq_sub(x, b->c[i], a->c[i]);
    mpq_mul(x, x, s);
    mpq_add(d->c[i], a->c[i], x);
    mpq_sub(x, c->c[i], a->c[i]);
    mpq_mul(x, x, t);
    mpq_add(d->c[i], d->c[i], x);
    if (i == axis && off != 0) {
      mpq_set_si(x, off, 1);
      if (shift >= 0)
        mpq_div_2exp(x, x, (mp_bitcnt_t)shift);
      else
        mpq_mul_2exp(x, x, (mp_bitcnt_t)(-shift));
      mpq_add(d->c[i], d->c[i], x);
    }
  }
  tr_qpoint_update(d);
  mpq_clear(s);
  mpq_clear(t);
  mpq_clear(x);
}

static void orient3d_rational_near_degenerate(void)
{
  enum { N = 5 };
  tr_qpoint q[N];
  for (int i = 0; i < N; i++)
    tr_qpoint_init(&q[i]);
  static const int scales[] = {0, 40, -40, 200, -200};
  int zeros = 0, tiny = 0;
  for (int it = 0; it < 40000; it++) {
    int sc = scales[it % 5];
    for (int i = 0; i < 3; i++)
      steiner_like(&q[i], sc);
    /* offsets from 0 to far below and around the coordinates' ulp */
    long off = (it % 4 == 0) ? 0 : irand(-3, 3);
    int shift = (int)irand(30, 120) - sc;
    near_plane(&q[3], &q[0], &q[1], &q[2], off, shift);
    const tr_qpoint *pp[4] = {&q[0], &q[1], &q[2], &q[3]};
    int want = ref_orient3d(pp);
    zeros += want == 0;
    tiny += want != 0;
    /* every argument order (the filter sees different differences) */
    static const int perm[6][4] = {{0, 1, 2, 3}, {1, 0, 2, 3}, {3, 1, 2, 0},
                                   {2, 3, 0, 1}, {0, 3, 1, 2}, {1, 2, 3, 0}};
    static const int par[6] = {1, -1, -1, 1, 1, -1};
    for (int k = 0; k < 6; k++) {
      tr_point p[4];
      for (int i = 0; i < 4; i++)
        p[i] = tr_pt_q(pp[perm[k][i]]);
      int got = tr_orient3d_p(&p[0], &p[1], &p[2], &p[3]);
      CHECK(got == par[k] * want, "it %d perm %d: got %d want %d", it, k, got, par[k] * want);
    }
  }
  CHECK(zeros > 5000 && tiny > 20000, "too few cases of a kind (%d zero, %d nonzero)", zeros,
        tiny);
  for (int i = 0; i < N; i++)
    tr_qpoint_clear(&q[i]);
}

/* Double points (as tr_pt_d) mixed with rational ones, coordinates spanning the filter's
 * range guard (2^+-300) and beyond the double range. */
static void orient3d_mixed_and_extreme(void)
{
  tr_qpoint q[4], e;
  for (int i = 0; i < 4; i++)
    tr_qpoint_init(&q[i]);
  tr_qpoint_init(&e);
  static const int scales[] = {0, 290, 310, -290, -310, 600, -600, 1000, -1060};
  for (int it = 0; it < 20000; it++) {
    int sc = scales[it % 9];
    for (int i = 0; i < 3; i++) {
      for (int c = 0; c < 3; c++) {
        mpq_set_si(q[i].c[c], irand(-50, 50), (unsigned long)(i == 0 ? 1 : irand(1, 9)));
        mpq_canonicalize(q[i].c[c]);
        if (sc >= 0)
          mpq_mul_2exp(q[i].c[c], q[i].c[c], (mp_bitcnt_t)sc);
        else
          mpq_div_2exp(q[i].c[c], q[i].c[c], (mp_bitcnt_t)(-sc));
      }
      tr_qpoint_update(&q[i]);
    }
    near_plane(&q[3], &q[0], &q[1], &q[2], (it % 3) ? irand(-2, 2) : 0, 60 - sc);
    const tr_qpoint *pp[4] = {&q[0], &q[1], &q[2], &q[3]};
    int want = ref_orient3d(pp);
    tr_point p[4];
    for (int i = 0; i < 4; i++) {
      p[i] = tr_pt_q(&q[i]);
      /* a point that is exactly a double goes in as a plain double point half the time */
      if ((it >> i) & 1 && q[i].err[0] == 0 && q[i].err[1] == 0 && q[i].err[2] == 0)
        p[i] = tr_pt_d(q[i].near);
    }
    int got = tr_orient3d_p(&p[0], &p[1], &p[2], &p[3]);
    CHECK(got == want, "it %d scale %d: got %d want %d", it, sc, got, want);
  }
  for (int i = 0; i < 4; i++)
    tr_qpoint_clear(&q[i]);
  tr_qpoint_clear(&e);
}

/* tr_point_get_hom is X / W = c with W > 0 after every way of setting a point, and err
 * bounds |c - near| exactly (0 iff the coordinate is a double). */
static void cached_hom_form_and_error_bound(void)
{
  tr_qpoint q, r;
  tr_qpoint_init(&q);
  tr_qpoint_init(&r);
  mpz_t X[3], W;
  mpq_t x, d;
  for (int i = 0; i < 3; i++)
    mpz_init(X[i]);
  mpz_init(W);
  mpq_init(x);
  mpq_init(d);
  for (int it = 0; it < 3000; it++) {
    int how = it % 3;
    if (how == 0)
      steiner_like(&q, (int)irand(-300, 300));
    else if (how == 1) {
      double v[3] = {ldexp((double)irand(-99999, 99999), (int)irand(-1070, 1000)),
                     (double)irand(-5, 5), ldexp(1.0, (int)irand(-1074, 1023))};
      tr_qpoint_set_d(&q, v);
    } else {
      steiner_like(&r, (int)irand(-50, 50));
      tr_point pr = tr_pt_q(&r);
      tr_qpoint_set_point(&q, &pr);
    }
    tr_point p = tr_pt_q(&q);
    tr_point_get_hom(&p, X, W);
    CHECK(mpz_sgn(W) > 0, "it %d: W <= 0", it);
    for (int i = 0; i < 3; i++) {
      mpq_set_num(x, X[i]);
      mpq_set_den(x, W);
      mpq_canonicalize(x);
      CHECK(mpq_equal(x, q.c[i]), "it %d coord %d: X/W != c", it, i);
      mpq_set_d(d, q.near[i]);
      mpq_sub(d, q.c[i], d);
      mpq_abs(d, d);
      mpq_set_d(x, q.err[i]);
      CHECK(mpq_cmp(d, x) <= 0, "it %d coord %d: |c - near| > err", it, i);
      CHECK((q.err[i] == 0) == (q.lo[i] == q.hi[i]), "it %d coord %d: err 0 iff a double", it,
            i);
    }
  }
  for (int i = 0; i < 3; i++)
    mpz_clear(X[i]);
  mpz_clear(W);
  mpq_clear(x);
  mpq_clear(d);
  tr_qpoint_clear(&q);
  tr_qpoint_clear(&r);
}

int main(int argc, char **argv)
{
  static const struct {
    const char *name;
    void (*fn)(void);
  } cases[] = {
      {"orient3d_rational_near_degenerate", orient3d_rational_near_degenerate},
      {"orient3d_mixed_and_extreme", orient3d_mixed_and_extreme},
      {"cached_hom_form_and_error_bound", cached_hom_form_and_error_bound},
  };
  int ran = 0;
  for (size_t i = 0; i < sizeof cases / sizeof *cases; i++)
    if (argc < 2 || !strcmp(argv[1], cases[i].name)) {
      int before = checks;
      cases[i].fn();
      ran++;
      if (checks == before) {
        fprintf(stderr, "FAIL %s: asserted nothing\n", cases[i].name);
        fails++;
      }
    }
  if (!ran) {
    fprintf(stderr, "unknown property\n");
    return 2;
  }
  tr_exact_scratch_free();
  printf("%d checks, %d failed\n", checks, fails);
  return fails != 0;
}
