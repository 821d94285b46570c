/* Exact constructions: the result lies exactly on the line and the plane (both lines). */
#include <math.h>

#include "check.h"
#include "construct.h"
#include "oracle.h"
#include "qpoint.h"

static int collinear3(const tr_point *a, const tr_point *b, const tr_point *x)
{
  for (int k = 0; k < 3; k++)
    if (tr_orient2d_proj_p(a, b, x, k) != 0)
      return 0;
  return 1;
}

/* box and nearest are consistent with the exact coordinates */
static int box_ok(const tr_qpoint *q)
{
  mpq_t t;
  mpq_init(t);
  int ok = 1;
  for (int i = 0; i < 3; i++) {
    mpq_set_d(t, q->lo[i]);
    ok &= mpq_cmp(t, q->c[i]) <= 0;
    mpq_set_d(t, q->hi[i]);
    ok &= mpq_cmp(q->c[i], t) <= 0;
    ok &= q->near[i] == tr_q_round_nearest(q->c[i]);
  }
  mpq_clear(t);
  return ok;
}

static double grid(double scale) { return (double)check_irand(-50, 50) * scale; }

static void set_grid(tr_qpoint *q, double scale, int rational)
{
  for (int i = 0; i < 3; i++) {
    mpq_set_d(q->c[i], grid(scale));
    if (rational) { /* divide by a small odd number: not a double any more */
      mpq_t d;
      mpq_init(d);
      mpq_set_ui(d, (unsigned long)check_irand(1, 4) * 2 + 1, 1);
      mpq_div(q->c[i], q->c[i], d);
      mpq_clear(d);
    }
  }
  tr_qpoint_update(q);
}

static void line_plane_case(double scale, int rational, int iters)
{
  tr_qpoint q[5], x;
  for (int i = 0; i < 5; i++)
    tr_qpoint_init(&q[i]);
  tr_qpoint_init(&x);
  int built = 0;
  for (int it = 0; it < iters; it++) {
    tr_point p[5];
    for (int i = 0; i < 5; i++) {
      set_grid(&q[i], scale, rational && (it + i) % 2);
      p[i] = tr_pt_q(&q[i]);
      if (!rational)
        p[i] = tr_pt_d(q[i].near);
    }
    int r = tr_construct_line_plane(&p[0], &p[1], &p[2], &p[3], &p[4], &x);
    int oa = tr_orient3d_p(&p[2], &p[3], &p[4], &p[0]), ob = tr_orient3d_p(&p[2], &p[3], &p[4], &p[1]);
    if (r != 0) {
      CHECK(oa == ob, "failure only when ab is parallel to the plane (iteration %d)", it);
      continue;
    }
    built++;
    tr_point X = tr_pt_q(&x);
    const tr_point *pl[4] = {&p[2], &p[3], &p[4], &X};
    CHECK(tr_orient3d_p(&p[2], &p[3], &p[4], &X) == 0, "X on plane pqr (iteration %d)", it);
    CHECK(oracle_orient3d(pl) == 0, "X on plane pqr by the oracle (iteration %d)", it);
    CHECK(collinear3(&p[0], &p[1], &X), "X on line ab (iteration %d)", it);
    CHECK(box_ok(&x), "box and nearest of X (iteration %d)", it);
  }
  CHECK(built > iters / 2, "most random cases are constructible (%d of %d)", built, iters);
  for (int i = 0; i < 5; i++)
    tr_qpoint_clear(&q[i]);
  tr_qpoint_clear(&x);
}

static void line_plane_doubles(void) { line_plane_case(1.0, 0, 3000); }
static void line_plane_rationals(void) { line_plane_case(1.0, 1, 3000); }
static void line_plane_tiny(void) { line_plane_case(1e-150, 1, 1000); }
static void line_plane_huge(void) { line_plane_case(1e150, 1, 1000); }

static void line_plane_known_value(void)
{
  static const double a[3] = {0, 0, 0}, b[3] = {3, 3, 3};
  static const double p[3] = {1, 0, 0}, q[3] = {0, 1, 0}, r[3] = {0, 0, 1};
  tr_point A = tr_pt_d(a), B = tr_pt_d(b), P = tr_pt_d(p), Q = tr_pt_d(q), R = tr_pt_d(r);
  tr_qpoint x;
  tr_qpoint_init(&x);
  CHECK(tr_construct_line_plane(&A, &B, &P, &Q, &R, &x) == 0, "constructible");
  mpq_t third;
  mpq_init(third);
  mpq_set_ui(third, 1, 3);
  for (int i = 0; i < 3; i++) {
    CHECK(mpq_equal(x.c[i], third), "coordinate %d is exactly 1/3", i);
    CHECK(x.near[i] == 1.0 / 3.0 && x.lo[i] < x.hi[i], "rounding of 1/3");
  }
  /* segment in the plane: undefined */
  static const double c[3] = {1, 0, 0}, d[3] = {0, 0, 1};
  tr_point C = tr_pt_d(c), D = tr_pt_d(d);
  CHECK(tr_construct_line_plane(&C, &D, &P, &Q, &R, &x) == -1, "line in the plane fails");
  static const double e[3] = {2, 0, 0}, f[3] = {0, 2, 0};
  tr_point E = tr_pt_d(e), F = tr_pt_d(f);
  CHECK(tr_construct_line_plane(&E, &F, &P, &Q, &R, &x) == -1, "parallel line fails");
  mpq_clear(third);
  tr_qpoint_clear(&x);
}

/* random coplanar lines: d = a + s (b - a) + t (c - a) */
static void line_line_case(double scale, int iters)
{
  tr_qpoint q[4], x, tmp;
  for (int i = 0; i < 4; i++)
    tr_qpoint_init(&q[i]);
  tr_qpoint_init(&x);
  tr_qpoint_init(&tmp);
  int built = 0;
  for (int it = 0; it < iters; it++) {
    tr_point p[4];
    for (int i = 0; i < 3; i++) {
      set_grid(&q[i], scale, it % 2);
      p[i] = tr_pt_q(&q[i]);
    }
    oracle_lerp(&tmp, &p[0], &p[1], check_irand(-7, 7), 5);
    tr_point T = tr_pt_q(&tmp);
    oracle_lerp(&q[3], &T, &p[2], check_irand(-7, 7), 3);
    p[3] = tr_pt_q(&q[3]);
    int r = tr_construct_line_line(&p[0], &p[1], &p[2], &p[3], &x);
    if (r != 0)
      continue;
    built++;
    tr_point X = tr_pt_q(&x);
    CHECK(collinear3(&p[0], &p[1], &X), "X on line ab (iteration %d)", it);
    CHECK(collinear3(&p[2], &p[3], &X), "X on line cd (iteration %d)", it);
    CHECK(box_ok(&x), "box of X");
  }
  CHECK(built > iters / 2, "most random cases are constructible (%d of %d)", built, iters);
  for (int i = 0; i < 4; i++)
    tr_qpoint_clear(&q[i]);
  tr_qpoint_clear(&x);
  tr_qpoint_clear(&tmp);
}

static void line_line_random(void) { line_line_case(1.0, 3000); }
static void line_line_magnitudes(void)
{
  line_line_case(1e-150, 1000);
  line_line_case(1e150, 1000);
}

/* a = 0, b = (1,0,0); c = (0,1,z), d = (1, 1-2^-50, z) tilted in 3D: meets at 2^50 */
static void line_line_near_parallel(void)
{
  const double eps = 0x1p-50; /* 1 - 2^-50 is a double; 1 - 2^-60 is not */
  static const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0};
  const double c[3] = {0, 1, 0}, d[3] = {1, 1 - eps, 0};
  tr_point A = tr_pt_d(a), B = tr_pt_d(b), C = tr_pt_d(c), D = tr_pt_d(d);
  tr_qpoint x;
  tr_qpoint_init(&x);
  CHECK(tr_construct_line_line(&A, &B, &C, &D, &x) == 0, "near-parallel lines meet");
  CHECK(x.near[0] == 0x1p50 && x.lo[0] == x.hi[0] && mpq_sgn(x.c[1]) == 0 &&
            mpq_sgn(x.c[2]) == 0,
        "meeting point is exactly (2^50, 0, 0), got %a", x.near[0]);
  /* the same lines rotated out of the xy plane: (x, y, 0) -> (x, y, y) */
  const double c2[3] = {0, 1, 1}, d2[3] = {1, 1 - eps, 1 - eps};
  tr_point C2 = tr_pt_d(c2), D2 = tr_pt_d(d2);
  CHECK(tr_construct_line_line(&A, &B, &C2, &D2, &x) == 0, "tilted near-parallel lines meet");
  CHECK(x.near[0] == 0x1p50 && mpq_sgn(x.c[1]) == 0 && mpq_sgn(x.c[2]) == 0,
        "tilted meeting point is exactly (2^50, 0, 0)");
  /* exactly parallel and skew lines fail */
  const double c3[3] = {0, 1, 0}, d3[3] = {1, 1, 0}, d4[3] = {1, 1, 1e-300};
  tr_point C3 = tr_pt_d(c3), D3 = tr_pt_d(d3), D4 = tr_pt_d(d4);
  CHECK(tr_construct_line_line(&A, &B, &C3, &D3, &x) == -1, "parallel lines fail");
  CHECK(tr_construct_line_line(&A, &B, &C3, &D4, &x) == -1, "skew lines (1e-300 off) fail");
  tr_qpoint_clear(&x);
}

int main(int argc, char **argv)
{
  static const check_case cases[] = {
      {"line_plane_doubles", line_plane_doubles},
      {"line_plane_rationals", line_plane_rationals},
      {"line_plane_tiny_1e-150", line_plane_tiny},
      {"line_plane_huge_1e150", line_plane_huge},
      {"line_plane_known_value", line_plane_known_value},
      {"line_line_random", line_line_random},
      {"line_line_magnitudes", line_line_magnitudes},
      {"line_line_near_parallel", line_line_near_parallel},
  };
  int r = check_main(argc, argv, cases, (int)(sizeof cases / sizeof cases[0]));
  tr_exact_scratch_free();
  return r;
}
