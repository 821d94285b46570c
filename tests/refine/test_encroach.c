/* The exact encroachment tests of refinement (src/refine/encroach.c): strictly inside the
 * diametral sphere of a segment, strictly inside the equatorial sphere of a triangle.
 * Each answer is compared with an oracle that computes the sphere's centre and squared
 * radius in rationals (GMP) and compares squared distances, on points exactly on the
 * sphere (where the double filter cannot decide and the exact stage answers), one ulp off
 * it, rational points (thirds), and random points at very different scales. The volume
 * bound (rf_volume_above) against the rational determinant, with bounds one ulp and
 * 0.1% around the tet's volume. Rational points a few dozen ulps from double points, as refinement's
 * points on constraints are, in small tets far from the origin: the filters decide most
 * of those (their error bound grows with the points' rounding over the differences) and
 * must agree with the oracles. */
#include <gmp.h>
#include <math.h>
#include <stdlib.h>

#include "predicates.h"
#include "qpoint.h"
#include "refine/refine_impl.h"
#include "../pipeline/texpect.h"

static void get(const tr_point *p, mpq_t x[3])
{
  for (int i = 0; i < 3; i++)
    tr_point_get_q(p, i, x[i]);
}

/* sign of |p - o|^2 - |a - o|^2 */
static int cmp_dist(mpq_t p[3], mpq_t a[3], mpq_t o[3])
{
  mpq_t s, t, d;
  mpq_inits(s, t, d, NULL);
  for (int i = 0; i < 3; i++) {
    mpq_sub(d, p[i], o[i]);
    mpq_mul(d, d, d);
    mpq_add(s, s, d);
    mpq_sub(d, a[i], o[i]);
    mpq_mul(d, d, d);
    mpq_sub(s, s, d);
  }
  int r = mpq_sgn(s);
  mpq_clears(s, t, d, NULL);
  return r;
}

static int oracle_diametral(const tr_point *a, const tr_point *b, const tr_point *p)
{
  mpq_t A[3], B[3], P[3], O[3];
  for (int i = 0; i < 3; i++)
    mpq_inits(A[i], B[i], P[i], O[i], NULL);
  get(a, A);
  get(b, B);
  get(p, P);
  for (int i = 0; i < 3; i++) {
    mpq_add(O[i], A[i], B[i]);
    mpq_div_2exp(O[i], O[i], 1);
  }
  int r = cmp_dist(P, A, O) < 0;
  for (int i = 0; i < 3; i++)
    mpq_clears(A[i], B[i], P[i], O[i], NULL);
  return r;
}

static void cross(mpq_t out[3], mpq_t x[3], mpq_t y[3], mpq_t t)
{
  for (int i = 0; i < 3; i++) {
    int j = (i + 1) % 3, k = (i + 2) % 3;
    mpq_mul(out[i], x[j], y[k]);
    mpq_mul(t, x[k], y[j]);
    mpq_sub(out[i], out[i], t);
  }
}
static void dot(mpq_t out, mpq_t x[3], mpq_t y[3], mpq_t t)
{
  mpq_set_ui(out, 0, 1);
  for (int i = 0; i < 3; i++) {
    mpq_mul(t, x[i], y[i]);
    mpq_add(out, out, t);
  }
}

/* centre o = a + ((|u|^2 v - |v|^2 u) x n) / (2 |n|^2), n = u x v: the circumcentre of
 * abc, in its plane */
static int oracle_equatorial(const tr_point *a, const tr_point *b, const tr_point *c,
                             const tr_point *p)
{
  mpq_t A[3], B[3], C[3], P[3], U[3], V[3], N[3], W[3], O[3], uu, vv, nn, t;
  for (int i = 0; i < 3; i++)
    mpq_inits(A[i], B[i], C[i], P[i], U[i], V[i], N[i], W[i], O[i], NULL);
  mpq_inits(uu, vv, nn, t, NULL);
  get(a, A);
  get(b, B);
  get(c, C);
  get(p, P);
  for (int i = 0; i < 3; i++) {
    mpq_sub(U[i], B[i], A[i]);
    mpq_sub(V[i], C[i], A[i]);
  }
  cross(N, U, V, t);
  dot(uu, U, U, t);
  dot(vv, V, V, t);
  dot(nn, N, N, t);
  for (int i = 0; i < 3; i++) {
    mpq_mul(W[i], uu, V[i]);
    mpq_mul(t, vv, U[i]);
    mpq_sub(W[i], W[i], t);
  }
  cross(O, W, N, t);
  mpq_mul_2exp(nn, nn, 1);
  for (int i = 0; i < 3; i++) {
    mpq_div(O[i], O[i], nn);
    mpq_add(O[i], O[i], A[i]);
  }
  int r = cmp_dist(P, A, O) < 0;
  for (int i = 0; i < 3; i++)
    mpq_clears(A[i], B[i], C[i], P[i], U[i], V[i], N[i], W[i], O[i], NULL);
  mpq_clears(uu, vv, nn, t, NULL);
  return r;
}

/* out = 6 x the exact volume of abcd (the rational determinant) */
static void six_volume(const tr_point *a, const tr_point *b, const tr_point *c,
                       const tr_point *d, mpq_t out)
{
  mpq_t A[3], B[3], C[3], D[3], N[3], t;
  for (int i = 0; i < 3; i++)
    mpq_inits(A[i], B[i], C[i], D[i], N[i], NULL);
  mpq_init(t);
  get(a, A);
  get(b, B);
  get(c, C);
  get(d, D);
  for (int i = 0; i < 3; i++) {
    mpq_sub(B[i], B[i], A[i]);
    mpq_sub(C[i], C[i], A[i]);
    mpq_sub(D[i], D[i], A[i]);
  }
  cross(N, C, D, t);
  dot(out, B, N, t);
  for (int i = 0; i < 3; i++)
    mpq_clears(A[i], B[i], C[i], D[i], N[i], NULL);
  mpq_clear(t);
}

/* 6 V < the exact 6 x volume of abcd */
static int oracle_volume_above(const tr_point *a, const tr_point *b, const tr_point *c,
                               const tr_point *d, double V)
{
  mpq_t s, t, six;
  mpq_inits(s, t, six, NULL);
  six_volume(a, b, c, d, s);
  mpq_set_d(t, V);
  mpq_set_ui(six, 6, 1);
  mpq_mul(t, t, six);
  int r = mpq_cmp(s, t) > 0;
  mpq_clears(s, t, six, NULL);
  return r;
}

/* The exact volume of abcd rounded to a double. */
static double volume_d(const tr_point *a, const tr_point *b, const tr_point *c,
                       const tr_point *d)
{
  mpq_t s, t;
  mpq_inits(s, t, NULL);
  six_volume(a, b, c, d, s);
  mpq_set_ui(t, 1, 6);
  mpq_mul(s, s, t);
  double v = mpq_get_d(s);
  mpq_clears(s, t, NULL);
  return v;
}

static int checks;
static void both(const char *what, const tr_point *a, const tr_point *b, const tr_point *c,
                 const tr_point *p)
{
  int d = rf_in_diametral(a, b, p), od = oracle_diametral(a, b, p);
  EXPECT(d == od, "%s: in diametral sphere %d, oracle %d", what, d, od);
  int e = rf_in_equatorial(a, b, c, p), oe = oracle_equatorial(a, b, c, p);
  EXPECT(e == oe, "%s: in equatorial sphere %d, oracle %d", what, e, oe);
  checks++;
}

/* exact: a, b, c on one line (the projections on the three coordinate planes are) */
static int collinear(const double a[3], const double b[3], const double c[3])
{
  for (int i = 0; i < 3; i++) {
    int j = (i + 1) % 3;
    double pa[2] = {a[i], a[j]}, pb[2] = {b[i], b[j]}, pc[2] = {c[i], c[j]};
    if (tr_orient2d(pa, pb, pc) != 0)
      return 0;
  }
  return 1;
}

static double frand(void)
{
  return (double)rand() / RAND_MAX - 0.5;
}

int main(void)
{
  /* a right triangle: its equatorial sphere has centre (0.5, 0.5, 0), radius^2 0.5; the
   * diametral sphere of ab has centre (0.5, 0, 0), radius^2 0.25 */
  double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0};
  tr_point A = tr_pt_d(a), B = tr_pt_d(b), C = tr_pt_d(c);
  double on_eq[][3] = {{1, 1, 0}, {1, 0.5, 0.5}, {0.5, 0.5, -0x1.6a09e667f3bcdp-1}};
  for (int k = 0; k < 2; k++) {
    tr_point P = tr_pt_d(on_eq[k]);
    EXPECT(!rf_in_equatorial(&A, &B, &C, &P), "a point on the equatorial sphere is inside");
    both("on the sphere", &A, &B, &C, &P);
    for (int dir = -1; dir <= 1; dir += 2) {
      double q[3] = {on_eq[k][0], on_eq[k][1], on_eq[k][2]};
      q[0] = nextafter(q[0], dir * INFINITY);
      tr_point Q = tr_pt_d(q);
      EXPECT(rf_in_equatorial(&A, &B, &C, &Q) == (dir < 0),
             "one ulp %s the equatorial sphere", dir < 0 ? "inside" : "outside");
      both("one ulp off the sphere", &A, &B, &C, &Q);
    }
  }
  double on_dia[3] = {0.5, 0.5, 0};
  tr_point D = tr_pt_d(on_dia);
  EXPECT(!rf_in_diametral(&A, &B, &D), "a point on the diametral sphere is inside");
  both("on the diametral sphere", &A, &B, &C, &D);
  /* rational points: thirds, on and near the sphere of the right triangle scaled by 3 */
  tr_qpoint q[4];
  for (int k = 0; k < 4; k++)
    tr_qpoint_init(&q[k]);
  long num[4][3] = {{0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
  for (int k = 0; k < 4; k++) {
    for (int i = 0; i < 3; i++)
      mpq_set_si(q[k].c[i], num[k][i], 3);
    tr_qpoint_update(&q[k]);
  }
  tr_point QA = tr_pt_q(&q[0]), QB = tr_pt_q(&q[1]), QC = tr_pt_q(&q[2]), QP = tr_pt_q(&q[3]);
  EXPECT(!rf_in_equatorial(&QA, &QB, &QC, &QP), "thirds: a point on the sphere is inside");
  both("thirds", &QA, &QB, &QC, &QP);
  mpq_set_si(q[3].c[0], 299, 900);
  tr_qpoint_update(&q[3]);
  EXPECT(rf_in_equatorial(&QA, &QB, &QC, &QP), "thirds: a point just inside is outside");
  both("thirds, just inside", &QA, &QB, &QC, &QP);
  /* random triangles and points at scales from 2^-60 to 2^60, and random cocircular
   * points: the fourth point a reflection of a vertex through the centre's plane axis */
  srand(7);
  for (int n = 0; n < 3000; n++) {
    double s = ldexp(1, (n % 121) - 60), o = frand() * ldexp(s, n % 7);
    double x[4][3];
    for (int k = 0; k < 4; k++)
      for (int i = 0; i < 3; i++)
        x[k][i] = o + s * frand();
    if (n % 3 == 0) /* p mirrors a across the perpendicular bisector of bc's z */
      for (int i = 0; i < 3; i++)
        x[3][i] = x[0][i];
    if (n % 3 == 1) { /* a right angle at a in the z = const plane: p opposite a */
      x[1][2] = x[2][2] = x[3][2] = x[0][2];
      x[1][1] = x[0][1];
      x[2][0] = x[0][0];
      x[3][0] = x[1][0];
      x[3][1] = x[2][1];
    }
    tr_point P[4];
    for (int k = 0; k < 4; k++)
      P[k] = tr_pt_d(x[k]);
    if (collinear(x[0], x[1], x[2]))
      continue; /* no equatorial sphere */
    both("random", &P[0], &P[1], &P[2], &P[3]);
  }
  /* rational points: each a double point moved by a rational offset of 1..64 ulps with a
   * denominator that is no power of two (so it is no double), the fourth point at times
   * on the equatorial sphere of the three others moved the same way; volume bounds one
   * ulp around the exact volume */
  for (int n = 0; n < 3000; n++) {
    /* a small tet far from the origin (o up to 2^14 of its size): its differences are
     * 2^-38 to 2^-52 of its coordinates, the range the filters are for */
    double s = ldexp(1, (n % 41) - 20), o = s * ldexp(1, n % 15), x[4][3];
    for (int k = 0; k < 4; k++)
      for (int i = 0; i < 3; i++)
        x[k][i] = o + s * frand();
    if (n % 2 == 0) { /* a right angle at 0 in a z = const plane, p opposite it */
      x[1][2] = x[2][2] = x[3][2] = x[0][2];
      x[1][1] = x[0][1];
      x[2][0] = x[0][0];
      x[3][0] = x[1][0];
      x[3][1] = x[2][1];
    }
    if (collinear(x[0], x[1], x[2]))
      continue;
    tr_point P[4];
    for (int k = 0; k < 4; k++) {
      for (int i = 0; i < 3; i++) {
        double ulp = nextafter(fabs(x[k][i]), INFINITY) - fabs(x[k][i]);
        if (x[k][i] == 0)
          ulp = ldexp(1, -60) * s;
        mpq_t off, f;
        mpq_inits(off, f, NULL);
        mpq_set_d(q[k].c[i], x[k][i]);
        mpq_set_d(off, ulp * (double)(1 + rand() % 64));
        /* times +-1/odd: no double */
        mpq_set_si(f, rand() % 2 ? 1 : -1, (unsigned long)(3 + rand() % 97) | 1u);
        mpq_canonicalize(f);
        if (!(n % 5 == 0 && k == 3)) { /* else p stays on the sphere in this coordinate */
          mpq_mul(off, off, f);
          mpq_add(q[k].c[i], q[k].c[i], off);
        }
        mpq_clears(off, f, NULL);
      }
      tr_qpoint_update(&q[k]);
      P[k] = tr_pt_q(&q[k]);
    }
    both("rational, ulps off", &P[0], &P[1], &P[2], &P[3]);
    double v = volume_d(&P[0], &P[1], &P[2], &P[3]);
    if (v < 0) { /* the bound is on positive tets */
      tr_point t = P[1];
      P[1] = P[2];
      P[2] = t;
      v = -v;
    }
    double bounds[5] = {0.999 * v, nextafter(v, 0), v, nextafter(v, INFINITY), 1.001 * v};
    for (int j = 0; j < 5; j++) {
      if (!(bounds[j] > 0))
        continue;
      int r = rf_volume_above(&P[0], &P[1], &P[2], &P[3], bounds[j]);
      int o = oracle_volume_above(&P[0], &P[1], &P[2], &P[3], bounds[j]);
      EXPECT(r == o, "rational tet: volume above %.17g: %d, oracle %d", bounds[j], r, o);
      checks++;
    }
  }
  for (int k = 0; k < 4; k++)
    tr_qpoint_clear(&q[k]);
  fprintf(stderr, "%d cases checked against the rational oracle\n", checks);
  return failures != 0;
}
