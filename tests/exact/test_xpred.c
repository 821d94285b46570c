/* Filtered exact predicates on tr_point against an independent mpq oracle. */
#include <float.h>
#include <math.h>

#include "check.h"
#include "construct.h"
#include "oracle.h"
#include "predicates.h"
#include "qpoint.h"

enum { NP = 8 };

/* A random point: small integer grid doubles, or a rational with a small denominator,
 * scaled by 2^scale. */
static void random_qpoint(tr_qpoint *q, int scale)
{
  for (int i = 0; i < 3; i++) {
    long n = check_irand(-20, 20), d = check_irand(1, 7);
    mpq_set_si(q->c[i], n, (unsigned long)d);
    mpq_canonicalize(q->c[i]);
    if (scale >= 0)
      mpq_mul_2exp(q->c[i], q->c[i], (mp_bitcnt_t)scale);
    else
      mpq_div_2exp(q->c[i], q->c[i], (mp_bitcnt_t)(-scale));
  }
  tr_qpoint_update(q);
}

static void orient3d_matches_oracle(void)
{
  tr_qpoint q[NP];
  for (int i = 0; i < NP; i++)
    tr_qpoint_init(&q[i]);
  static const int scales[] = {0, -490, 490, 30};
  int zeros = 0;
  for (int it = 0; it < 6000; it++) {
    int sc = scales[it % 4];
    for (int i = 0; i < 4; i++)
      random_qpoint(&q[i], sc);
    /* make some cases degenerate: d on the plane abc, a rational combination */
    if (it % 3 == 0) {
      tr_point a = tr_pt_q(&q[0]), b = tr_pt_q(&q[1]), c = tr_pt_q(&q[2]);
      oracle_lerp(&q[4], &a, &b, check_irand(-5, 5), 7);
      tr_point e = tr_pt_q(&q[4]);
      oracle_lerp(&q[3], &e, &c, check_irand(-5, 5), 3);
    }
    tr_point p[4];
    const tr_point *pp[4];
    for (int i = 0; i < 4; i++) {
      p[i] = tr_pt_q(&q[i]);
      pp[i] = &p[i];
      /* some points as plain doubles when they are doubles */
      if ((it >> i) & 1 && q[i].lo[0] == q[i].hi[0] && q[i].lo[1] == q[i].hi[1] &&
          q[i].lo[2] == q[i].hi[2])
        p[i] = tr_pt_d(q[i].lo);
    }
    int want = oracle_orient3d(pp);
    int got = tr_orient3d_p(pp[0], pp[1], pp[2], pp[3]);
    zeros += want == 0;
    CHECK(got == want, "iteration %d: got %d want %d", it, got, want);
  }
  CHECK(zeros >= 1000, "too few degenerate cases (%d)", zeros);
  for (int i = 0; i < NP; i++)
    tr_qpoint_clear(&q[i]);
}

/* tr_insphere_p on the five rational points q[0..4]; *want: the GMP oracle's sign. */
static int insphere_and_oracle(const tr_qpoint *q, int *want)
{
  tr_point p[5];
  const tr_point *pp[5];
  for (int i = 0; i < 5; i++) {
    p[i] = tr_pt_q(&q[i]);
    pp[i] = &p[i];
  }
  *want = oracle_insphere(pp);
  return tr_insphere_p(pp[0], pp[1], pp[2], pp[3], pp[4]);
}

static void insphere_matches_oracle(void)
{
  tr_qpoint q[NP];
  for (int i = 0; i < NP; i++)
    tr_qpoint_init(&q[i]);
  static const int scales[] = {0, -300, 300, 20};
  for (int it = 0; it < 3000; it++) {
    int sc = scales[it % 4];
    for (int i = 0; i < 5; i++)
      random_qpoint(&q[i], sc);
    int want, got = insphere_and_oracle(q, &want);
    CHECK(got == want, "iteration %d: got %d want %d", it, got, want);
  }
  for (int i = 0; i < NP; i++)
    tr_qpoint_clear(&q[i]);
}

/* q = centre + rad * the point of the unit sphere that stereographic projection maps to
 * (s, t): ((2s, 2t, s^2 + t^2 - 1) / (s^2 + t^2 + 1)), exactly on that sphere. */
static void on_sphere(tr_qpoint *q, const mpq_t centre[3], const mpq_t rad, long s, long t)
{
  mpq_t den, x;
  mpq_init(den), mpq_init(x);
  mpq_set_si(den, s * s + t * t + 1, 1);
  long num[3] = {2 * s, 2 * t, s * s + t * t - 1};
  for (int i = 0; i < 3; i++) {
    mpq_set_si(x, num[i], 1);
    mpq_div(x, x, den);
    mpq_mul(x, x, rad);
    mpq_add(q->c[i], x, centre[i]);
  }
  tr_qpoint_update(q);
  mpq_clear(den), mpq_clear(x);
}

/* Rational points on a sphere and a fifth point on it or 2^-j off it (j from 30 to 140
 * bits below the radius): the cases where the nearest doubles' static filter must leave
 * the decision to the later stages when its bound is not met, at scales from 2^-170 to
 * 2^170. */
static void insphere_near_cospherical_matches_oracle(void)
{
  tr_qpoint q[5];
  for (int i = 0; i < 5; i++)
    tr_qpoint_init(&q[i]);
  mpq_t centre[3], rad, off;
  for (int i = 0; i < 3; i++)
    mpq_init(centre[i]);
  mpq_init(rad), mpq_init(off);
  static const int scales[] = {0, -170, 170, 40, -20};
  int zeros = 0, inside = 0, outside = 0;
  for (int it = 0; it < 4000; it++) {
    int sc = scales[it % 5];
    for (int i = 0; i < 3; i++)
      mpq_set_si(centre[i], check_irand(-50, 50), (unsigned long)check_irand(1, 9));
    mpq_set_si(rad, check_irand(1, 40), (unsigned long)check_irand(1, 7));
    for (int i = 0; i < 3; i++)
      mpq_canonicalize(centre[i]);
    mpq_canonicalize(rad);
    if (sc >= 0)
      mpq_mul_2exp(rad, rad, (mp_bitcnt_t)sc);
    else
      mpq_div_2exp(rad, rad, (mp_bitcnt_t)(-sc));
    for (int i = 0; i < 3; i++)
      if (sc >= 0)
        mpq_mul_2exp(centre[i], centre[i], (mp_bitcnt_t)sc);
      else
        mpq_div_2exp(centre[i], centre[i], (mp_bitcnt_t)(-sc));
    for (int k = 0; k < 5; k++)
      on_sphere(&q[k], (const mpq_t *)centre, rad, check_irand(-9, 9), check_irand(-9, 9));
    if (it % 4) { /* the fifth point off the sphere by rad * 2^-j along one axis */
      int j = (int)check_irand(30, 140), ax = (int)check_irand(0, 2);
      mpq_div_2exp(off, rad, (mp_bitcnt_t)j);
      if (check_irand(0, 1))
        mpq_neg(off, off);
      mpq_add(q[4].c[ax], q[4].c[ax], off);
      tr_qpoint_update(&q[4]);
    }
    int want, got = insphere_and_oracle(q, &want);
    zeros += want == 0;
    inside += want > 0;
    outside += want < 0;
    CHECK(got == want, "iteration %d (scale 2^%d): got %d want %d", it, sc, got, want);
  }
  CHECK(zeros >= 500 && inside >= 500 && outside >= 500,
        "too few cases of a kind: %d on, %d inside, %d outside", zeros, inside, outside);
  for (int i = 0; i < 3; i++)
    mpq_clear(centre[i]);
  mpq_clear(rad), mpq_clear(off);
  for (int i = 0; i < 5; i++)
    tr_qpoint_clear(&q[i]);
}

/* tr_insphere_p > 0 iff e inside the sphere of a positively oriented abcd. */
static void insphere_sign_convention(void)
{
  static const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0}, d[3] = {0, 0, 1};
  tr_point A = tr_pt_d(a), B = tr_pt_d(b), C = tr_pt_d(c), D = tr_pt_d(d);
  CHECK(tr_orient3d_p(&A, &B, &C, &D) == 1, "unit tet is positive");
  tr_qpoint e;
  tr_qpoint_init(&e);
  /* (1/3, 1/3, 1/3): inside, not a double -> exact or filtered path */
  for (int i = 0; i < 3; i++)
    mpq_set_ui(e.c[i], 1, 3);
  tr_qpoint_update(&e);
  tr_point E = tr_pt_q(&e);
  CHECK(tr_insphere_p(&A, &B, &C, &D, &E) == 1, "inside point");
  CHECK(tr_insphere_p(&B, &A, &C, &D, &E) == -1, "inside point, negative tet flips");
  /* (1, 1, 0) lies on the sphere (centre (1/2,1/2,1/2), r^2 = 3/4); as a rational */
  mpq_set_ui(e.c[0], 1, 1), mpq_set_ui(e.c[1], 1, 1), mpq_set_ui(e.c[2], 0, 1);
  tr_qpoint_update(&e);
  CHECK(tr_insphere_p(&A, &B, &C, &D, &E) == 0, "cospherical point");
  /* just outside along (1,1,0) + 2^-80 (1,1,0) */
  mpq_set_ui(e.c[0], 1, 1);
  mpz_ui_pow_ui(mpq_denref(e.c[0]), 2, 80);
  mpz_add(mpq_numref(e.c[0]), mpq_denref(e.c[0]), mpq_numref(e.c[0]));
  mpq_canonicalize(e.c[0]);
  mpq_set(e.c[1], e.c[0]);
  tr_qpoint_update(&e);
  CHECK(tr_insphere_p(&A, &B, &C, &D, &E) == -1, "just outside");
  tr_qpoint_clear(&e);
}

/* sign of orient2d_proj(drop k) = sign of component k of (b-a)x(c-a) */
static void orient2d_proj_convention(void)
{
  tr_qpoint q[3];
  for (int i = 0; i < 3; i++)
    tr_qpoint_init(&q[i]);
  for (int it = 0; it < 3000; it++) {
    for (int i = 0; i < 3; i++)
      random_qpoint(&q[i], it % 2 ? 0 : -600);
    tr_point p[3];
    for (int i = 0; i < 3; i++)
      p[i] = tr_pt_q(&q[i]);
    if (it % 5 == 0) /* collinear in some projection: c = a + t (b - a) */
      oracle_lerp(&q[2], &p[0], &p[1], check_irand(-9, 9), 4);
    mpq_t u[3], v[3], n, t;
    mpq_init(n), mpq_init(t);
    for (int i = 0; i < 3; i++) {
      mpq_init(u[i]), mpq_init(v[i]);
      mpq_sub(u[i], q[1].c[i], q[0].c[i]);
      mpq_sub(v[i], q[2].c[i], q[0].c[i]);
    }
    for (int k = 0; k < 3; k++) {
      int x = (k + 1) % 3, y = (k + 2) % 3;
      mpq_mul(n, u[x], v[y]);
      mpq_mul(t, u[y], v[x]);
      mpq_sub(n, n, t);
      int got = tr_orient2d_proj_p(&p[0], &p[1], &p[2], k);
      CHECK(got == mpq_sgn(n), "drop %d: got %d want %d", k, got, mpq_sgn(n));
      /* and the double path for double inputs */
      tr_point d[3] = {tr_pt_d(q[0].near), tr_pt_d(q[1].near), tr_pt_d(q[2].near)};
      tr_qpoint r[3];
      for (int i = 0; i < 3; i++) {
        tr_qpoint_init(&r[i]);
        tr_qpoint_set_d(&r[i], q[i].near);
      }
      tr_point rq[3] = {tr_pt_q(&r[0]), tr_pt_q(&r[1]), tr_pt_q(&r[2])};
      CHECK(tr_orient2d_proj_p(&d[0], &d[1], &d[2], k) ==
                tr_orient2d_proj_p(&rq[0], &rq[1], &rq[2], k),
            "double and rational paths agree, drop %d", k);
      for (int i = 0; i < 3; i++)
        tr_qpoint_clear(&r[i]);
    }
    for (int i = 0; i < 3; i++)
      mpq_clear(u[i]), mpq_clear(v[i]);
    mpq_clear(n), mpq_clear(t);
  }
  for (int i = 0; i < 3; i++)
    tr_qpoint_clear(&q[i]);
}

/* a double point and the same value held as a rational give the same answers */
static void double_and_rational_agree(void)
{
  tr_qpoint q[5];
  for (int i = 0; i < 5; i++)
    tr_qpoint_init(&q[i]);
  double x[5][3];
  for (int it = 0; it < 3000; it++) {
    for (int k = 0; k < 5; k++)
      for (int i = 0; i < 3; i++)
        x[k][i] = ldexp((double)check_irand(-3, 3), (int)check_irand(-2, 2)) *
                  (it % 3 == 0 ? 1e-150 : it % 3 == 1 ? 1e150 : 1.0);
    tr_point d[5], r[5];
    for (int k = 0; k < 5; k++) {
      tr_qpoint_set_d(&q[k], x[k]);
      d[k] = tr_pt_d(x[k]);
      r[k] = tr_pt_q(&q[k]);
    }
    CHECK(tr_orient3d_p(&d[0], &d[1], &d[2], &d[3]) == tr_orient3d_p(&r[0], &d[1], &r[2], &d[3]),
          "orient3d %d", it);
    CHECK(tr_insphere_p(&d[0], &d[1], &d[2], &d[3], &d[4]) ==
              tr_insphere_p(&d[0], &r[1], &d[2], &r[3], &r[4]),
          "insphere %d", it);
    const tr_point *pp[4] = {&r[0], &r[1], &r[2], &r[3]};
    CHECK(tr_orient3d_p(&d[0], &d[1], &d[2], &d[3]) == oracle_orient3d(pp), "oracle %d", it);
  }
  for (int i = 0; i < 5; i++)
    tr_qpoint_clear(&q[i]);
}

static void cmp_and_equal(void)
{
  tr_qpoint a, b;
  tr_qpoint_init(&a), tr_qpoint_init(&b);
  static const double one[3] = {1, 1, 1};
  tr_qpoint_set_d(&a, one);
  tr_qpoint_set_d(&b, one);
  /* b.x = 1 + 2^-200: same box as 1's neighbours, different value */
  mpq_set_ui(b.c[0], 1, 1);
  mpz_mul_2exp(mpq_denref(b.c[0]), mpq_denref(b.c[0]), 200);
  mpz_add(mpq_numref(b.c[0]), mpq_numref(b.c[0]), mpq_denref(b.c[0]));
  mpq_canonicalize(b.c[0]);
  tr_qpoint_update(&b);
  tr_point A = tr_pt_q(&a), B = tr_pt_q(&b), D = tr_pt_d(one);
  CHECK(b.near[0] == 1.0 && b.lo[0] == 1.0 && b.hi[0] > 1.0, "box of 1+2^-200");
  CHECK(tr_cmp_coord_p(&A, &B, 0) == -1, "1 < 1+2^-200");
  CHECK(tr_cmp_coord_p(&B, &D, 0) == 1, "1+2^-200 > double 1");
  CHECK(tr_cmp_coord_p(&B, &D, 1) == 0, "y equal");
  CHECK(tr_equal_p(&A, &D), "rational 1,1,1 equals double 1,1,1");
  CHECK(!tr_equal_p(&B, &D), "differs in x by 2^-200");
  tr_qpoint_clear(&a), tr_qpoint_clear(&b);
}

int main(int argc, char **argv)
{
  static const check_case cases[] = {
      {"orient3d_matches_oracle", orient3d_matches_oracle},
      {"insphere_matches_oracle", insphere_matches_oracle},
      {"insphere_near_cospherical_matches_oracle", insphere_near_cospherical_matches_oracle},
      {"insphere_sign_convention", insphere_sign_convention},
      {"orient2d_proj_convention", orient2d_proj_convention},
      {"double_and_rational_agree", double_and_rational_agree},
      {"cmp_and_equal", cmp_and_equal},
  };
  int r = check_main(argc, argv, cases, (int)(sizeof cases / sizeof cases[0]));
  tr_exact_scratch_free();
  return r;
}
