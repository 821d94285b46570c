/* Shape of polygon triangulations (src/io/polyflip.c after ear clipping). Each subcommand
 * checks one property named by its meson test. Usage: test_polytri SUBTEST */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/polyflip.h"
#include "io/soup.h"
#include "predicates.h"
#include "../pipeline/texpect.h"

/* Triangulates one loop (and holes after it) of points xyz[3 * i], indices 0..n-1 in
 * order, or fails the test. */
static tr_u32vec tri_loops(const double *xyz, const uint32_t *idx, const uint32_t *first,
                           uint32_t nloops, uint32_t n)
{
  tr_u32vec out = {0};
  tr_status st = tr_triangulate_facet(xyz, idx, first, nloops, n, NULL, 0, &out, "polygon");
  EXPECT(st == TR_OK, "triangulation failed: %s", tr_last_error());
  return out;
}

static tr_u32vec tri_loop(const double *xyz, uint32_t n)
{
  uint32_t idx[64], first = 0;
  for (uint32_t i = 0; i < n; i++)
    idx[i] = i;
  return tri_loops(xyz, idx, &first, 1, n);
}

static double shape(const double *xyz, uint32_t a, uint32_t b, uint32_t c)
{
  return tr_polyflip_shape(xyz + 3 * a, xyz + 3 * b, xyz + 3 * c);
}

/* The smallest angle of a triangulation in degrees, measured independently (acos). */
static double min_angle(const double *xyz, const uint32_t *t, uint32_t ntri)
{
  double m = 180;
  for (uint32_t i = 0; i < ntri; i++)
    for (int k = 0; k < 3; k++) {
      const double *o = xyz + 3 * t[3 * i + k], *p = xyz + 3 * t[3 * i + (k + 1) % 3],
                   *q = xyz + 3 * t[3 * i + (k + 2) % 3];
      double u[3], v[3], uu = 0, vv = 0, uv = 0;
      for (int j = 0; j < 3; j++) {
        u[j] = p[j] - o[j];
        v[j] = q[j] - o[j];
        uu += u[j] * u[j];
        vv += v[j] * v[j];
        uv += u[j] * v[j];
      }
      double a = acos(uv / sqrt(uu * vv)) * 180 / acos(-1.0);
      m = a < m ? a : m;
    }
  return m;
}

/* Twice the signed area in the xy plane, exact for small integers. */
static int64_t area2(const double *xyz, uint32_t a, uint32_t b, uint32_t c)
{
  const double *p = xyz + 3 * a, *q = xyz + 3 * b, *r = xyz + 3 * c;
  return ((int64_t)q[0] - (int64_t)p[0]) * ((int64_t)r[1] - (int64_t)p[1]) -
         ((int64_t)q[1] - (int64_t)p[1]) * ((int64_t)r[0] - (int64_t)p[0]);
}

static int has_edge(const tr_u32vec *t, uint32_t a, uint32_t b)
{
  for (uint32_t i = 0; i < t->n; i += 3)
    for (int k = 0; k < 3; k++) {
      uint32_t x = t->a[i + k], y = t->a[i + (k + 1) % 3];
      if ((x == a && y == b) || (x == b && y == a))
        return 1;
    }
  return 0;
}

/* Every diagonal of the result whose quadrilateral is convex is locally Delaunay (exact
 * incircle in the xy plane, where the polygon lies): the constrained Delaunay one. */
static void expect_locally_delaunay(const double *xyz, const tr_u32vec *t, const char *what)
{
  for (uint32_t i = 0; i < t->n; i += 3)
    for (uint32_t j = 0; j < t->n; j += 3)
      for (int k = 0; k < 3; k++)
        for (int l = 0; l < 3; l++) {
          uint32_t a = t->a[i + k], b = t->a[i + (k + 1) % 3], c = t->a[i + (k + 2) % 3];
          if (t->a[j + l] != b || t->a[j + (l + 1) % 3] != a)
            continue;
          uint32_t d = t->a[j + (l + 2) % 3];
          double pa[2] = {xyz[3 * a], xyz[3 * a + 1]}, pb[2] = {xyz[3 * b], xyz[3 * b + 1]};
          double pc[2] = {xyz[3 * c], xyz[3 * c + 1]}, pd[2] = {xyz[3 * d], xyz[3 * d + 1]};
          EXPECT(tr_incircle(pa, pb, pc, pd) <= 0,
                 "%s: diagonal %u-%u is not Delaunay (%u inside the circle of %u %u %u)", what,
                 a, b, d, a, b, c);
        }
}

/* A convex hexagon in z = 0 whose ear clip is a fan with a 2.3 degree angle: the flips
 * give the Delaunay triangulation, the best smallest angle (39.5 degrees) of all 14. */
static void t_convex_hexagon(void)
{
  const double xyz[] = {-4, 0, 0, 3, -10, 0, 14, -13, 0, 15, 1, 0, 2, 19, 0, -12, 14, 0};
  tr_u32vec t = tri_loop(xyz, 6);
  EXPECT(t.n == 12, "%u triangles (4 expected)", t.n / 3);
  int64_t sum = 0;
  for (uint32_t i = 0; i + 2 < t.n; i += 3) {
    int64_t s = area2(xyz, t.a[i], t.a[i + 1], t.a[i + 2]);
    EXPECT(s > 0, "triangle %u is not counterclockwise (%lld)", i / 3, (long long)s);
    sum += s;
  }
  int64_t poly = 0;
  for (uint32_t i = 0; i < 6; i++)
    poly += (int64_t)xyz[3 * i] * (int64_t)xyz[3 * ((i + 1) % 6) + 1] -
            (int64_t)xyz[3 * ((i + 1) % 6)] * (int64_t)xyz[3 * i + 1];
  EXPECT(sum == poly, "triangles cover %lld, the hexagon %lld", (long long)sum, (long long)poly);
  expect_locally_delaunay(xyz, &t, "hexagon");
  /* All triangulations of a convex hexagon: a triangle on side 0-1 with apex k, then the
   * (convex) rest on each side; enumerated as the 14 sets of 3 non-crossing diagonals. */
  uint32_t diag[9][2], nd = 0;
  for (uint32_t a = 0; a < 6; a++)
    for (uint32_t b = a + 2; b < 6; b++)
      if (!(a == 0 && b == 5))
        diag[nd][0] = a, diag[nd][1] = b, nd++;
  double best = 0;
  int count = 0;
  for (uint32_t x = 0; x < nd; x++)
    for (uint32_t y = x + 1; y < nd; y++)
      for (uint32_t z = y + 1; z < nd; z++) {
        uint32_t s[3] = {x, y, z};
        int ok = 1;
        for (int i = 0; i < 3; i++)
          for (int j = i + 1; j < 3; j++) {
            uint32_t a = diag[s[i]][0], b = diag[s[i]][1], c = diag[s[j]][0], d = diag[s[j]][1];
            if ((a < c && c < b && b < d) || (c < a && a < d && d < b))
              ok = 0; /* they cross */
          }
        if (!ok)
          continue;
        count++;
        /* the triangles: every triple of corners all of whose sides are sides or chosen */
        uint32_t tri[12], nt = 0;
        for (uint32_t a = 0; a < 6; a++)
          for (uint32_t b = a + 1; b < 6; b++)
            for (uint32_t c = b + 1; c < 6; c++) {
              uint32_t e[3][2] = {{a, b}, {b, c}, {a, c}};
              int all = 1;
              for (int i = 0; i < 3; i++) {
                uint32_t p = e[i][0], q = e[i][1];
                int side = q == p + 1 || (p == 0 && q == 5);
                int chosen = 0;
                for (int j = 0; j < 3; j++)
                  chosen |= diag[s[j]][0] == p && diag[s[j]][1] == q;
                all &= side || chosen;
              }
              if (all && nt < 4)
                tri[3 * nt] = a, tri[3 * nt + 1] = b, tri[3 * nt + 2] = c, nt++;
            }
        double m = min_angle(xyz, tri, nt);
        best = m > best ? m : best;
      }
  EXPECT(count == 14, "%d triangulations of the hexagon (14 expected)", count);
  double got = min_angle(xyz, t.a, t.n / 3);
  EXPECT(got == best, "smallest angle %.17g, the best triangulation has %.17g", got, best);
  /* Ear clipping alone (first ear at corner 0, then its neighbours) gives the fan from
   * corner 1. */
  const uint32_t fan1[12] = {5, 0, 1, 4, 5, 1, 3, 4, 1, 2, 3, 1};
  double fan = min_angle(xyz, fan1, 4);
  EXPECT(fan < 3 && got > 39, "the fan reaches %g degrees, the result %g", fan, got);
  tr_u32vec_free(&t);
}

/* A dart (reflex corner 2): the diagonal 1-3 would raise the smallest angle from about
 * 6 to about 39 degrees but lies outside the polygon, so it must be refused. */
static void t_reflex_flip_refused(void)
{
  const double xyz[] = {0, 0, 0, 10, 0, 0, 1, 1, 0, 0, 10, 0};
  double in = shape(xyz, 0, 1, 2) < shape(xyz, 0, 2, 3) ? shape(xyz, 0, 1, 2) : shape(xyz, 0, 2, 3);
  double out = shape(xyz, 0, 1, 3) < shape(xyz, 1, 2, 3) ? shape(xyz, 0, 1, 3) : shape(xyz, 1, 2, 3);
  EXPECT(out > in, "the outside diagonal must look better (%g vs %g) for this test to bite",
         out, in);
  tr_u32vec t = tri_loop(xyz, 4);
  EXPECT(t.n == 6 && has_edge(&t, 0, 2) && !has_edge(&t, 1, 3),
         "the dart must keep its only inner diagonal 0-2");
  for (uint32_t i = 0; i + 2 < t.n; i += 3)
    EXPECT(area2(xyz, t.a[i], t.a[i + 1], t.a[i + 2]) > 0, "triangle %u not counterclockwise",
           i / 3);
  tr_u32vec_free(&t);
  /* The same through tr_polyflip directly, given the dart's triangulation. */
  double p[4][2] = {{0, 0}, {10, 0}, {1, 1}, {0, 10}};
  uint32_t id[4] = {0, 1, 2, 3}, next[4] = {1, 2, 3, 0}, tri[6] = {0, 1, 2, 0, 2, 3}, nf = 9;
  tr_polyflip_in fin = {(const double(*)[2])p, id, xyz, next, tri, 2};
  EXPECT(tr_polyflip(&fin, &nf) == TR_OK && nf == 0, "tr_polyflip flipped %u times", nf);
  /* and a convex quadrilateral with the same bad diagonal is flipped */
  double p2[4][2] = {{0, 0}, {10, 0}, {6, 6}, {0, 10}};
  const double xyz2[] = {0, 0, 0, 10, 0, 0, 6, 6, 0, 0, 10, 0};
  uint32_t tri2[6] = {0, 1, 3, 1, 2, 3}; /* 1-3 is the worse diagonal of this kite */
  tr_polyflip_in fin2 = {(const double(*)[2])p2, id, xyz2, next, tri2, 2};
  EXPECT(tr_polyflip(&fin2, &nf) == TR_OK && nf == 1, "kite: %u flips (1 expected)", nf);
  tr_u32vec t2 = {tri2, 6, 6};
  EXPECT(has_edge(&t2, 0, 2) && !has_edge(&t2, 1, 3), "kite: diagonal 0-2 expected");
}

/* A square with a square hole, both given in either orientation, on the tilted plane
 * z = x + 2y: hole sides stay edges, every triangle has the outer loop's orientation and
 * the triangles cover exactly the ring. */
static void t_hole_and_orientation(void)
{
  const int64_t P[8][2] = {{0, 0}, {30, 0}, {30, 30}, {0, 30}, {10, 10}, {10, 20}, {20, 20}, {20, 10}};
  for (int rev = 0; rev < 2; rev++) {
    double xyz[24];
    for (int i = 0; i < 8; i++) {
      int k = rev ? (i < 4 ? 3 - i : 11 - i) : i;
      xyz[3 * i] = (double)P[k][0];
      xyz[3 * i + 1] = (double)P[k][1];
      xyz[3 * i + 2] = (double)(P[k][0] + 2 * P[k][1]);
    }
    uint32_t idx[8] = {0, 1, 2, 3, 4, 5, 6, 7}, first[2] = {0, 4};
    tr_u32vec t = tri_loops(xyz, idx, first, 2, 8);
    EXPECT(t.n == 3 * 8, "ring: %u triangles (8 expected)", t.n / 3);
    int64_t sum = 0;
    for (uint32_t i = 0; i + 2 < t.n; i += 3) {
      int64_t s = area2(xyz, t.a[i], t.a[i + 1], t.a[i + 2]);
      EXPECT(rev ? s < 0 : s > 0, "ring %d: triangle %u has the wrong orientation (%lld)", rev,
             i / 3, (long long)s);
      sum += s;
    }
    EXPECT(sum == (rev ? -2 : 2) * (900 - 100), "ring %d: twice-area %lld", rev, (long long)sum);
    for (uint32_t i = 0; i < 4; i++) {
      EXPECT(has_edge(&t, i, (i + 1) % 4), "ring %d: outer side %u missing", rev, i);
      EXPECT(has_edge(&t, 4 + i, 4 + (i + 1) % 4), "ring %d: hole side %u missing", rev, i);
    }
    tr_u32vec_free(&t);
  }
}

/* Random star polygons, planar (z = 0) and lifted onto a paraboloid (non-planar): valid,
 * the same twice, and no convex diagonal is left whose flip would raise the smaller
 * smallest angle; the planar ones are the constrained Delaunay triangulation. */
static void t_random_locally_optimal_and_deterministic(void)
{
  uint64_t seed = 977;
  int tested = 0;
  for (int iter = 0; iter < 300; iter++) {
    int n = 4 + iter % 30, lifted = iter % 3 == 2;
    double xyz[3 * 40], ang[40];
    int64_t P[40][2];
    for (int i = 0; i < n; i++) {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      ang[i] = (double)(seed >> 11) / 9007199254740992.0 * 6.283185307179586;
    }
    for (int i = 1; i < n; i++)
      for (int j = i; j > 0 && ang[j] < ang[j - 1]; j--) {
        double x = ang[j];
        ang[j] = ang[j - 1];
        ang[j - 1] = x;
      }
    for (int i = 0; i < n; i++) {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      double r = 1 + (double)((seed >> 33) % 1000);
      P[i][0] = (int64_t)llround(r * cos(ang[i]));
      P[i][1] = (int64_t)llround(r * sin(ang[i]));
    }
    int ok = 1;
    for (int i = 0; i < n; i++)
      if (P[i][0] * P[(i + 1) % n][1] - P[i][1] * P[(i + 1) % n][0] <= 0)
        ok = 0;
    if (!ok)
      continue;
    for (int i = 0; i < n; i++) {
      xyz[3 * i] = (double)P[i][0];
      xyz[3 * i + 1] = (double)P[i][1];
      /* a gentle lift keeps the projection onto xy (the first corners decide it) */
      xyz[3 * i + 2] = lifted ? (double)((P[i][0] * P[i][0] + P[i][1] * P[i][1]) / 65536) : 0;
    }
    tr_u32vec t = tri_loop(xyz, (uint32_t)n), t2 = tri_loop(xyz, (uint32_t)n);
    EXPECT(t.n == 3 * (uint32_t)(n - 2), "star %d: %u triangles", iter, t.n / 3);
    EXPECT(t.n == t2.n && memcmp(t.a, t2.a, sizeof *t.a * t.n) == 0,
           "star %d: two runs differ", iter);
    int64_t sum = 0, poly = 0;
    for (int i = 0; i < n; i++)
      poly += P[i][0] * P[(i + 1) % n][1] - P[i][1] * P[(i + 1) % n][0];
    for (uint32_t i = 0; i + 2 < t.n; i += 3) {
      int64_t s = area2(xyz, t.a[i], t.a[i + 1], t.a[i + 2]);
      EXPECT(s > 0, "star %d: triangle %u has twice-area %lld", iter, i / 3, (long long)s);
      sum += s;
    }
    EXPECT(sum == poly, "star %d: cover %lld of %lld", iter, (long long)sum, (long long)poly);
    for (uint32_t i = 0; i < t.n; i += 3)
      for (uint32_t j = 0; j < t.n; j += 3)
        for (int k = 0; k < 3; k++)
          for (int l = 0; l < 3; l++) {
            uint32_t a = t.a[i + k], b = t.a[i + (k + 1) % 3], c = t.a[i + (k + 2) % 3];
            if (t.a[j + l] != b || t.a[j + (l + 1) % 3] != a)
              continue;
            uint32_t d = t.a[j + (l + 2) % 3];
            if (area2(xyz, a, b, d) <= 0 || area2(xyz, a, d, c) <= 0)
              continue; /* not convex: no flip possible */
            double now = fmin(shape(xyz, a, b, c), shape(xyz, b, a, d));
            double flip = fmin(shape(xyz, a, b, d), shape(xyz, a, d, c));
            EXPECT(!(flip > now * (1 + 1e-9)),
                   "star %d: diagonal %u-%u would gain by a flip (%.17g -> %.17g)", iter, a, b,
                   now, flip);
          }
    if (!lifted)
      expect_locally_delaunay(xyz, &t, "planar star");
    tr_u32vec_free(&t);
    tr_u32vec_free(&t2);
    tested++;
  }
  EXPECT(tested > 80, "only %d star polygons survived rounding", tested);
}

int main(int argc, char **argv)
{
  if (argc < 2) {
    fprintf(stderr, "usage: test_polytri SUBTEST\n");
    return 2;
  }
  static const struct {
    const char *name;
    void (*fn)(void);
  } tests[] = {{"convex_hexagon", t_convex_hexagon},
               {"reflex_flip_refused", t_reflex_flip_refused},
               {"hole_and_orientation", t_hole_and_orientation},
               {"random", t_random_locally_optimal_and_deterministic}};
  for (size_t i = 0; i < sizeof tests / sizeof tests[0]; i++)
    if (!strcmp(argv[1], tests[i].name)) {
      tests[i].fn();
      if (failures)
        fprintf(stderr, "%s: %d check(s) failed\n", argv[1], failures);
      return failures ? 1 : 0;
    }
  fprintf(stderr, "unknown subtest %s\n", argv[1]);
  return 2;
}
