/* The self-intersection narrow phase for triangles whose planes meet in a line
 * (src/input/selfint_line.c: two orient3d from the side signs) against the general path
 * (TR_SELFINT_REFERENCE: six segment-triangle classifications), on hand-made pairs with
 * known answers and on many random pairs on integer grids, where corners on the other's
 * plane, shared corners, touching edges and coplanar pairs are frequent; and coplanar
 * pairs sharing no corner (the separating edge test of selfint.c) the same way.
 * Usage: test_selfint_line CASE */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "input/validate.h"
#include "predicates.h"
#include "tetrec.h"
#include "../pipeline/texpect.h"

/* The number of improper pairs of the two-triangle soup by `method` (-1: not built). */
static int npairs(const double *X, uint32_t nv, const uint32_t *T, int method)
{
  struct tr_plc *p = NULL;
  uint32_t *pr = NULL;
  size_t n = 0;
  int r = -1;
  if (tr_plc_create(&p) == TR_OK && tr_plc_set(p, X, nv, T, 2, NULL) == TR_OK &&
      tr_input_self_intersection_pairs(p, method, &pr, &n) == TR_OK)
    r = (int)n;
  free(pr);
  tr_plc_destroy(p);
  return r;
}

/* Both paths give `want` (1: improper) for the pair. */
static void expect_pair(const char *what, const double *X, uint32_t nv, const uint32_t *T,
                        int want)
{
  int fast = npairs(X, nv, T, TR_SELFINT_ALL_PAIRS);
  int ref = npairs(X, nv, T, TR_SELFINT_REFERENCE);
  EXPECT(fast == want && ref == want, "%s: shortcuts %d, general path %d, want %d", what, fast,
         ref, want);
}

/* T = (0,0,0) (4,0,0) (0,4,0) as vertices 0, 1, 2; U = vertices 3, 4, 5 given, or a
 * vertex of T where an index below 3 is given in u. */
static void case_t(const char *what, const double u[9], const uint32_t ui[3], int want)
{
  double X[18] = {0, 0, 0, 4, 0, 0, 0, 4, 0};
  memcpy(X + 9, u, 9 * sizeof *X);
  uint32_t T[6] = {0, 1, 2, ui[0], ui[1], ui[2]};
  expect_pair(what, X, 6, T, want);
  /* the same with U's orientation reversed and T's corners rotated: the answer is a
   * property of the sets */
  uint32_t R[6] = {1, 2, 0, ui[0], ui[2], ui[1]};
  expect_pair(what, X, 6, R, want);
}

/* Pairs with known answers, each non-coplanar and sharing at most one corner. */
static void t_known(void)
{
  static const uint32_t none[3] = {3, 4, 5}, v0[3] = {0, 4, 5};
  static const struct {
    const char *what;
    double u[9];
    const uint32_t *ui;
    int want;
  } cs[] = {
      {"a corner of U inside T, U above", {1, 1, 0, 1, 1, 2, 2, 1, 2}, none, 1},
      {"a corner of U on T's plane outside T", {3, 3, 0, 3, 3, 2, 4, 3, 2}, none, 0},
      {"a corner of U on an edge of T", {2, 0, 0, 2, -1, 2, 2, 1, 2}, none, 1},
      {"a corner of U at T's corner's place, another vertex", {4, 0, 0, 5, 1, 1, 5, -1, 1},
       none, 1},
      {"an edge of U in T's plane across T", {1, -1, 0, 1, 5, 0, 1, 2, 3}, none, 1},
      {"an edge of U in T's plane beside T", {6, -1, 0, -1, 6, 0, 2, 2, 3}, none, 0},
      {"an edge of U along T's long edge", {5, -1, 0, -1, 5, 0, 2, 2, 3}, none, 1},
      {"U through T's interior", {1, 1, -1, 2, 1, 1, 1, 2, 1}, none, 1},
      {"U through T's plane beside T", {3, 3, -1, 4, 3, 1, 3, 4, 1}, none, 0},
      {"U's edge touching T's edge at one point", {2, -1, -1, 2, 1, 1, 2, -1, 1}, none, 1},
      {"U's edge passing T's edge", {2, -1.5, -1, 2, 0.5, 1, 2, -1.5, 1}, none, 0},
      {"U across T's plane meeting it only on T's edge", {2, 0, -1, 2, 0, 1, 2, -1, 0}, none, 1},
      {"shared corner, U's edge into T in its plane", {0, 0, 0, 1, 1, 0, 0, 0, 3}, v0, 1},
      {"shared corner, U's edge away from T in its plane", {0, 0, 0, -1, -1, 0, 0, 0, 3}, v0, 0},
      {"shared corner, U's edge beside T in its plane", {0, 0, 0, 1, -1, 0, 0, 0, 3}, v0, 0},
      {"shared corner, U's edge along T's edge", {0, 0, 0, 1, 0, 0, 0, 0, 3}, v0, 1},
      {"shared corner, U's edge along T's edge, U below", {0, 0, 0, 2, 0, 0, 0, -1, -3}, v0, 1},
      {"shared corner, U across T's plane through T", {0, 0, 0, 1, 1, -1, 1, 1, 1}, v0, 1},
      {"shared corner, U across T's plane beside T", {0, 0, 0, -1, 1, -1, -1, 1, 1}, v0, 0},
      {"shared corner, U across T's plane on T's edge line", {0, 0, 0, 1, 0, -1, 1, 0, 1}, v0,
       1},
      {"shared corner, U across T's plane outside along -x", {0, 0, 0, -1, 0, -1, -1, 0, 1}, v0,
       0},
  };
  for (size_t c = 0; c < sizeof cs / sizeof *cs; c++)
    case_t(cs[c].what, cs[c].u, cs[c].ui, cs[c].want);
}

static uint64_t rng = 0x9e3779b97f4a7c15ull;
static uint32_t rnd(uint32_t n)
{
  rng ^= rng << 13;
  rng ^= rng >> 7;
  rng ^= rng << 17;
  return (uint32_t)((rng >> 11) % n);
}

/* The grid {0..m-1}^3 under one of four exact maps: as is (triangles in axis planes), a
 * shear (no axis planes), a tilt mixing every axis (small integers, exact), and a big
 * offset with a shift of 2^-20 (adaptive stages, exact doubles). */
static void grid_point(int map, int m, int v, double *x)
{
  double a = v % m, b = v / m % m, c = v / (m * m);
  switch (map) {
  case 0:
    x[0] = a, x[1] = b, x[2] = c;
    break;
  case 1:
    x[0] = a + 0.5 * b, x[1] = b + 0.25 * c, x[2] = c + 0.125 * a;
    break;
  case 2:
    x[0] = 3 * a - b + c, x[1] = a + 2 * b - 2 * c, x[2] = 2 * a + 5 * b + c;
    break;
  default:
    x[0] = 1048576 + a + b * 0x1p-20, x[1] = -524288 + b + c * 0x1p-20, x[2] = c;
    break;
  }
}

static int flat(const double *X, const uint32_t *t)
{
  const double *a = X + 3 * t[0], *b = X + 3 * t[1], *c = X + 3 * t[2];
  return !tr_orient2d_proj(a, b, c, 0) && !tr_orient2d_proj(a, b, c, 1) &&
         !tr_orient2d_proj(a, b, c, 2);
}

/* Random pairs on the grid: both paths must agree. The pairs the line test decides
 * (not coplanar, sharing 0 or 1 corner, no side of all-one-sign) are counted by shared
 * corners, by whether a non-shared corner lies on the other's plane, and by verdict:
 * every kind must occur with both verdicts. */
static void t_random(void)
{
  int seen[2][2][2] = {{{0}}}, other = 0, bad = 0;
  for (int round = 0; round < 200000 && bad < 10; round++) {
    int map = round % 4, m = round % 8 < 4 ? 3 : 4, nv = m * m * m;
    double X[64 * 3];
    for (int v = 0; v < nv; v++)
      grid_point(map, m, v, X + 3 * v);
    uint32_t T[6];
    do {
      for (int k = 0; k < 6; k++)
        T[k] = rnd((uint32_t)nv);
      /* one or two corners of U taken from T, often */
      int share = (int)rnd(4);
      for (int k = 0; k < share && k < 2; k++)
        T[3 + rnd(3)] = T[rnd(3)];
    } while (flat(X, T) || flat(X, T + 3));
    int shared = 0;
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++)
        shared += T[i] == T[3 + j];
    if (shared == 3)
      continue; /* one triangle twice */
    int fast = npairs(X, (uint32_t)nv, T, TR_SELFINT_ALL_PAIRS);
    int ref = npairs(X, (uint32_t)nv, T, TR_SELFINT_REFERENCE);
    if (fast != ref || fast < 0) {
      bad++;
      EXPECT(0, "round %d: shortcuts %d, general path %d for (%u %u %u) (%u %u %u) map %d",
             round, fast, ref, T[0], T[1], T[2], T[3], T[4], T[5], map);
      continue;
    }
    /* the kind of pair: the sides of each one's corners against the other's plane */
    int cnt[2][3] = {{0}}, zero = 0;
    for (int w = 0; w < 2; w++) {
      const uint32_t *t = T + 3 * w, *u = T + 3 * (1 - w);
      for (int k = 0; k < 3; k++) {
        if (u[k] == t[0] || u[k] == t[1] || u[k] == t[2])
          continue;
        int o = tr_sign(tr_orient3d(X + 3 * t[0], X + 3 * t[1], X + 3 * t[2], X + 3 * u[k]));
        cnt[w][o > 0 ? 0 : o < 0 ? 1 : 2]++;
        zero |= !o;
      }
    }
    int coplanar = !cnt[0][0] && !cnt[0][1];
    int apart = 0;
    for (int w = 0; w < 2; w++)
      apart |= !cnt[w][2] && (!cnt[w][0] || !cnt[w][1]);
    if (shared > 1 || coplanar || apart)
      other++;
    else
      seen[shared][zero][fast > 0]++;
  }
  EXPECT(!bad, "%d disagreements", bad);
  for (int s = 0; s < 2; s++)
    for (int z = 0; z < 2; z++)
      EXPECT(seen[s][z][0] > 200 && seen[s][z][1] > 200,
             "line pairs sharing %d corners, %s: %d proper, %d improper (want > 200 each)", s,
             z ? "a corner on the other plane" : "strict sides", seen[s][z][0], seen[s][z][1]);
  EXPECT(other > 1000, "pairs decided elsewhere also mixed in: %d", other);
}

/* Coplanar pairs sharing no corner (the separating edge test of selfint.c) against the
 * general path: random triangles on a 5x5 grid in the plane z = 0, in a tilted plane
 * (z = x/4 + y/2, exact) and in one far from the origin, touching at corners, along
 * edges and overlapping often. Both verdicts must occur many times. */
static void t_coplanar(void)
{
  int seen[2] = {0, 0}, bad = 0;
  for (int round = 0; round < 40000 && bad < 10; round++) {
    enum { NV = 25 };
    double X[NV * 3];
    int plane = round % 3;
    for (int v = 0; v < NV; v++) {
      double x = v % 5, y = v / 5;
      X[3 * v] = plane == 2 ? 1048576 + x : x;
      X[3 * v + 1] = plane == 2 ? 3 * x + y : y;
      X[3 * v + 2] = plane == 1 ? 0.25 * x + 0.5 * y : plane == 2 ? x - 2 * y : 0;
    }
    uint32_t T[6];
    int shared;
    do {
      for (int k = 0; k < 6; k++)
        T[k] = rnd(NV);
      shared = 0;
      for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
          shared += T[i] == T[3 + j];
    } while (shared || flat(X, T) || flat(X, T + 3));
    int fast = npairs(X, NV, T, TR_SELFINT_ALL_PAIRS);
    int ref = npairs(X, NV, T, TR_SELFINT_REFERENCE);
    if (fast != ref || fast < 0) {
      bad++;
      EXPECT(0, "round %d: shortcuts %d, general path %d for (%u %u %u) (%u %u %u)", round,
             fast, ref, T[0], T[1], T[2], T[3], T[4], T[5]);
      continue;
    }
    seen[fast > 0]++;
  }
  EXPECT(!bad, "%d disagreements", bad);
  EXPECT(seen[0] > 5000 && seen[1] > 5000, "coplanar pairs apart %d, meeting %d (want > 5000)",
         seen[0], seen[1]);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"known", t_known, NULL},
      {"random", t_random, NULL},
      {"coplanar", t_coplanar, NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
