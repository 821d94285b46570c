/* Delaunay tests: every result goes through the validator (links, exact orientation,
 * vertex->tet map, Euler characteristic of a ball, perturbed Delaunay property, convex
 * hull), and where the hull is known, its exact volume. Usage: test_delaunay <case>. */
#include <gmp.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "core/hugepage.h"
#include "delaunay/det2.h"
#include "mesh/check.h"
#include "mesh/mesh.h"
#include "../mesh/tcommon.h"

/* Triangulates, validates, and compares the hull volume (6*volume) when vol6 >= 0. */
static int run(const char *what, const double *xyz, uint32_t n, double vol6, struct tr_mesh **keep)
{
  struct tr_mesh *m;
  EXPECT_OK(tr_delaunay_build(xyz, n, &m), what);
  mpq_t v;
  mpq_init(v);
  if (vol6 >= 0)
    mpq_set_d(v, vol6);
  tr_status s = tr_check_mesh(m, TR_CHK_ALL_DELAUNAY, vol6 >= 0 ? v : NULL);
  mpq_clear(v);
  EXPECT(s == TR_OK, "%s: the mesh must be a valid Delaunay ball: %s", what, tr_last_error());
  EXPECT(tr_mesh_num_tets(m) > 0, "%s: some tets", what);
  if (keep)
    *keep = m;
  else
    tr_mesh_destroy(m);
  return 0;
}

static double *alloc_pts(uint32_t n) { return malloc(3 * (size_t)n * sizeof(double)); }

static int random_points(uint32_t n)
{
  double *p = alloc_pts(n);
  for (uint32_t i = 0; i < 3 * n; i++)
    p[i] = t_unif();
  char what[64];
  snprintf(what, sizeof what, "%u uniform random points", n);
  int r = run(what, p, n, -1, NULL);
  free(p);
  return r;
}

/* The unit cube's corners plus random interior points: hull volume exactly 1. */
static int cube_with_interior(uint32_t n)
{
  double *p = alloc_pts(n + 8);
  for (int i = 0; i < 8; i++) {
    p[3 * i] = i & 1;
    p[3 * i + 1] = (i >> 1) & 1;
    p[3 * i + 2] = (i >> 2) & 1;
  }
  for (uint32_t i = 24; i < 3 * (n + 8); i++)
    p[i] = t_unif();
  int r = run("cube corners + interior points", p, n + 8, 6, NULL);
  free(p);
  return r;
}

static int grid(int g)
{
  uint32_t n = (uint32_t)(g * g * g);
  double *p = alloc_pts(n);
  uint32_t k = 0;
  for (int z = 0; z < g; z++)
    for (int y = 0; y < g; y++)
      for (int x = 0; x < g; x++) {
        p[3 * k] = x;
        p[3 * k + 1] = y;
        p[3 * k + 2] = z;
        k++;
      }
  struct tr_mesh *m = NULL;
  double side = g - 1;
  int r = run("integer grid (massively cospherical)", p, n, 6 * side * side * side, &m);
  if (r == 0) {
    /* every grid point is a vertex and no tet is larger than a unit cube: the perturbed
     * Delaunay tets of a grid all lie in one cell, so 6*volume is 1 or 2 */
    for (uint32_t t = 0; t < m->nt; t++) {
      if (!tr_tet_is_real(m, t))
        continue;
      const uint32_t *v = m->tv + 4 * t;
      for (int a = 0; a < 4; a++)
        for (int b = 0; b < 4; b++)
          for (int c = 0; c < 3; c++) {
            double d = m->xyz[3 * v[a] + c] - m->xyz[3 * v[b] + c];
            EXPECT(d >= -1 && d <= 1, "grid tet %u spans more than one cell", t);
          }
    }
    tr_mesh_destroy(m);
  }
  free(p);
  return r;
}

static int cube_corners(void)
{
  double p[24];
  for (int i = 0; i < 8; i++) {
    p[3 * i] = i & 1;
    p[3 * i + 1] = (i >> 1) & 1;
    p[3 * i + 2] = (i >> 2) & 1;
  }
  struct tr_mesh *m;
  int r = run("cube corners", p, 8, 6, &m);
  if (r)
    return r;
  uint32_t nt = tr_mesh_num_tets(m);
  EXPECT(nt == 5 || nt == 6, "a cube is split into 5 or 6 tets, got %u", nt);
  tr_mesh_destroy(m);
  return 0;
}

/* Random points on 4 planes z = 0..3 with coordinates on a 1/8 lattice (many coplanar
 * and cospherical subsets) plus the corners of the box. */
static int planes(void)
{
  uint32_t n = 4 * 200 + 8;
  double *p = alloc_pts(n);
  uint32_t k = 0;
  for (int i = 0; i < 8; i++, k++) {
    p[3 * k] = 8 * (i & 1);
    p[3 * k + 1] = 8 * ((i >> 1) & 1);
    p[3 * k + 2] = 3 * ((i >> 2) & 1);
  }
  for (int z = 0; z < 4; z++)
    for (int i = 0; i < 200; i++, k++) {
      p[3 * k] = (double)(t_next() % 65) / 8;
      p[3 * k + 1] = (double)(t_next() % 65) / 8;
      p[3 * k + 2] = z;
    }
  int r = run("points on 4 planes", p, n, 6 * 8 * 8 * 3, NULL);
  free(p);
  return r;
}

/* Long collinear runs along the 3 axes and a diagonal, plus 4 points off them. */
static int collinear_runs(void)
{
  uint32_t n = 4 * 50 + 4, k = 0;
  double *p = alloc_pts(n);
  for (int i = 0; i < 50; i++) {
    double t = i;
    double run4[4][3] = {{t, 0, 0}, {0, t, 0}, {0, 0, t}, {t, t, t}};
    for (int j = 0; j < 4; j++, k++)
      memcpy(p + 3 * k, run4[j], sizeof run4[j]);
  }
  double extra[4][3] = {{60, 1, 1}, {1, 60, 1}, {1, 1, 60}, {-5, -5, -5}};
  for (int j = 0; j < 4; j++, k++)
    memcpy(p + 3 * k, extra[j], sizeof extra[j]);
  /* (0,0,0) appears in 4 runs: 3 duplicates */
  struct tr_mesh *m;
  int r = run("collinear runs", p, n, -1, &m);
  if (r == 0) {
    EXPECT(m->ndup == 3, "the origin is listed 4 times: 3 duplicates, got %u", m->ndup);
    tr_mesh_destroy(m);
  }
  free(p);
  return r;
}

static int duplicates(void)
{
  uint32_t n0 = 1000, n = 3 * n0;
  double *p = alloc_pts(n);
  for (uint32_t i = 0; i < 3 * n0; i++)
    p[i] = t_unif();
  /* point n0 + i copies point i, point 2 n0 + i copies point (i * 7) % n0 */
  p[0] = 0.0;
  memcpy(p + 3 * n0, p, 3 * n0 * sizeof *p);
  for (uint32_t i = 0; i < n0; i++)
    memcpy(p + 3 * (2 * n0 + i), p + 3 * ((i * 7) % n0), 3 * sizeof *p);
  p[3 * n0] = -0.0; /* -0.0 equals 0.0: point n0 is still a copy of point 0 */
  struct tr_mesh *m;
  int r = run("random points, each listed 3 times", p, n, -1, &m);
  if (r == 0) {
    EXPECT(m->ndup == 2 * n0, "ndup = %u, expected %u", m->ndup, 2 * n0);
    for (uint32_t i = 0; i < n0; i++) {
      EXPECT(m->dup_map[i] == i, "the first copy is kept (dup_map[%u] = %u)", i, m->dup_map[i]);
      EXPECT(m->dup_map[n0 + i] == i, "dup_map[%u] = %u, expected %u", n0 + i, m->dup_map[n0 + i],
             i);
      EXPECT(m->dup_map[2 * n0 + i] == (i * 7) % n0, "dup_map of the third copies");
    }
    tr_mesh_destroy(m);
  }
  free(p);
  return r;
}

/* A 10x10 grid in z = 0 and one apex: every tet has the apex, one per base triangle. */
static int one_off_plane(void)
{
  double p[101 * 3];
  uint32_t k = 0;
  for (int x = 0; x < 10; x++)
    for (int y = 0; y < 10; y++, k++) {
      p[3 * k] = x;
      p[3 * k + 1] = y;
      p[3 * k + 2] = 0;
    }
  p[3 * k] = 3;
  p[3 * k + 1] = 4;
  p[3 * k + 2] = 1;
  struct tr_mesh *m;
  /* pyramid: 6 * (81 * 1 / 3) = 162 */
  int r = run("10x10 grid plus one point off its plane", p, 101, 162, &m);
  if (r)
    return r;
  /* triangles of a triangulation of 100 points with 36 on the hull: 2n - h - 2 = 162 */
  EXPECT(tr_mesh_num_tets(m) == 162, "one tet per base triangle: %u, expected 162",
         tr_mesh_num_tets(m));
  tr_mesh_destroy(m);
  return 0;
}

static int expect_degenerate(const char *what, const double *p, uint32_t n, tr_status want,
                             const char *msg)
{
  struct tr_mesh *m = NULL;
  tr_status s = tr_delaunay_build(p, n, &m);
  EXPECT(s == want && m == NULL, "%s: expected %s, got %s (%s)", what, tr_status_name(want),
         tr_status_name(s), tr_last_error());
  EXPECT(strstr(tr_last_error(), msg), "%s: message \"%s\" must mention \"%s\"", what,
         tr_last_error(), msg);
  return 0;
}

static int degenerate_inputs(void)
{
  double p[300];
  /* 100 points in the plane x + 2y - z = 3 (exact small integers) */
  for (int i = 0; i < 100; i++) {
    double x = i % 10, y = (i * 7) % 13;
    p[3 * i] = x;
    p[3 * i + 1] = y;
    p[3 * i + 2] = x + 2 * y - 3;
  }
  if (expect_degenerate("coplanar set", p, 100, TR_ERR_DEGENERATE, "all 100 points are coplanar"))
    return 1;
  for (int i = 0; i < 100; i++) {
    p[3 * i] = i;
    p[3 * i + 1] = 2 * i;
    p[3 * i + 2] = -i;
  }
  if (expect_degenerate("collinear set", p, 100, TR_ERR_DEGENERATE, "collinear"))
    return 1;
  if (expect_degenerate("3 points", p, 3, TR_ERR_DEGENERATE, "at least 4"))
    return 1;
  if (expect_degenerate("0 points", p, 0, TR_ERR_DEGENERATE, "at least 4"))
    return 1;
  for (int i = 0; i < 12; i++)
    p[i] = 1.5;
  if (expect_degenerate("4 equal points", p, 4, TR_ERR_DEGENERATE, "same point"))
    return 1;
  double q[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  q[7] = 0.0 / 0.0;
  if (expect_degenerate("NaN", q, 4, TR_ERR_INPUT, "point 2"))
    return 1;
  q[7] = 1;
  return run("4 points", q, 4, 1, NULL);
}

/* All integer points on the sphere x^2 + y^2 + z^2 = 45^2 (exactly cospherical) and the
 * centre: the centre's cavity is every tet inserted before it, far more than the small
 * cavity matcher takes, so this also covers the general cavity gluing. */
static int sphere_and_centre(void)
{
  enum { R = 45 };
  double *p = alloc_pts(20000);
  uint32_t n = 0;
  for (int x = -R; x <= R; x++)
    for (int y = -R; y <= R; y++)
      for (int z = -R; z <= R; z++)
        if (x * x + y * y + z * z == R * R && n < 19999) {
          p[3 * n] = x;
          p[3 * n + 1] = y;
          p[3 * n + 2] = z;
          n++;
        }
  EXPECT(n > 500, "enough sphere points (%u)", n);
  p[3 * n] = p[3 * n + 1] = p[3 * n + 2] = 0;
  n++;
  int r = run("cospherical points and the centre", p, n, -1, NULL);
  free(p);
  return r;
}

/* n points on each of two skew lines: the only tets are (a_i, a_i+1, b_j, b_j+1), so
 * (n-1)^2 tets from 2n points, far past the store's per-point estimate: the tet arrays
 * grow inside an insertion (regression: a stale pointer to the neighbour array after
 * that reallocation corrupted the mesh; ASan saw it on CGAL's cheese.off). */
static int skew_lines(uint32_t n)
{
  double *p = alloc_pts(2 * n);
  for (uint32_t i = 0; i < n; i++) {
    p[6 * i] = i, p[6 * i + 1] = 0, p[6 * i + 2] = 0;
    p[6 * i + 3] = 0, p[6 * i + 4] = i, p[6 * i + 5] = 1;
  }
  struct tr_mesh *m = NULL;
  int r = run("points on two skew lines", p, 2 * n, (double)(n - 1) * (n - 1), &m);
  if (r == 0) {
    EXPECT(tr_mesh_num_tets(m) == (uint64_t)(n - 1) * (n - 1),
           "two skew lines of %u points: %llu tets, want %u", n,
           (unsigned long long)tr_mesh_num_tets(m), (n - 1) * (n - 1));
    tr_mesh_destroy(m);
  }
  free(p);
  return r;
}

static int deterministic(void)
{
  uint32_t n = 20000;
  double *p = alloc_pts(n);
  for (uint32_t i = 0; i < 3 * n; i++)
    p[i] = (double)(t_next() % 50); /* many duplicates and degeneracies */
  struct tr_mesh *a, *b;
  EXPECT_OK(tr_delaunay_build(p, n, &a), "first run");
  EXPECT_OK(tr_delaunay_build(p, n, &b), "second run");
  EXPECT(a->nt == b->nt && memcmp(a->tv, b->tv, 4 * (size_t)a->nt * 4) == 0 &&
             memcmp(a->tn, b->tn, 4 * (size_t)a->nt * 4) == 0,
         "two runs on the same input give the same arrays byte for byte");
  tr_status s = tr_check_mesh(a, TR_CHK_ALL_DELAUNAY, NULL);
  EXPECT(s == TR_OK, "lattice points with duplicates: %s", tr_last_error());
  tr_mesh_destroy(a);
  tr_mesh_destroy(b);
  free(p);
  return 0;
}

/* The kernel's two-lane insphere determinant (delaunay/det2.h) must round exactly like
 * tr_insphere_det_, whose evaluation order the static filter bound is derived for: same
 * bits on random points in boxes of many scales and offsets, on lattice points (many
 * exact zeros and cospherical cases), and on nearly cospherical points. */
static int det2_same_bits(void)
{
  double q[5][3];
  uint32_t nzero = 0;
  for (int it = 0; it < 300000; it++) {
    const int kind = it % 3;
    const double scale = ldexp(1.0, (int)(t_next() % 80) - 40);
    const double off = scale * (double)(t_next() % 7);
    for (int i = 0; i < 5; i++)
      for (int c = 0; c < 3; c++) {
        if (kind == 0)
          q[i][c] = off + scale * t_unif();
        else if (kind == 1)
          q[i][c] = (double)(t_next() % 5);
        else /* on the unit sphere up to rounding, around a random centre */
          q[i][c] = 0;
      }
    if (kind == 2)
      for (int i = 0; i < 5; i++) {
        const double th = 6.283185307179586 * t_unif(), z = 2 * t_unif() - 1;
        const double r = sqrt(1 - z * z);
        q[i][0] = off + scale * r * cos(th);
        q[i][1] = off + scale * r * sin(th);
        q[i][2] = off + scale * z;
      }
    const double a = tr_dt_insphere_det(q[0], q[1], q[2], q[3], q[4]);
    const double b = tr_insphere_det_(q[0], q[1], q[2], q[3], q[4]);
    EXPECT(memcmp(&a, &b, sizeof a) == 0, "case %d: two-lane determinant %a, scalar %a", it, a,
           b);
    nzero += b == 0;
  }
  EXPECT(nzero > 1000, "the lattice cases include exact zeros (%u)", nzero);
  return 0;
}

/* The huge-page hint of the builder's arrays (core/hugepage.h) is a hint only: on memory
 * already written, on ranges whose ends are not page aligned, below its size threshold and
 * on NULL it neither fails nor changes a byte, and memory advised before its first
 * write reads back what was written. */
static int hugepage_hint_keeps_contents(void)
{
  const size_t n = (9u << 20) / sizeof(uint32_t) + 3; /* 9 MB and a bit: 4 huge pages */
  uint32_t *a = malloc(n * sizeof *a), *b = malloc(n * sizeof *b);
  EXPECT(a && b, "allocations");
  for (size_t i = 0; i < n; i++)
    a[i] = (uint32_t)(i * 2654435761u);
  tr_advise_hugepages(a, n * sizeof *a);                /* touched */
  tr_advise_hugepages((char *)a + 7, n * sizeof *a - 9); /* unaligned ends */
  tr_advise_hugepages(b, n * sizeof *b);                /* untouched */
  tr_advise_hugepages(b, 100);                          /* below the threshold */
  tr_advise_hugepages(NULL, 1u << 30);
  for (size_t i = 0; i < n; i++)
    b[i] = a[i] ^ 0x5bd1e995u;
  for (size_t i = 0; i < n; i++)
    EXPECT(a[i] == (uint32_t)(i * 2654435761u) && (b[i] ^ 0x5bd1e995u) == a[i],
           "entry %zu kept its value after the hint", i);
  free(a);
  free(b);
  return 0;
}

int main(int argc, char **argv)
{
  if (argc < 2)
    return 2;
  const char *c = argv[1];
  if (!strncmp(c, "random", 6))
    return random_points((uint32_t)atoi(c + 6));
  if (!strcmp(c, "cube_interior"))
    return cube_with_interior(2000);
  if (!strncmp(c, "grid", 4))
    return grid(atoi(c + 4));
  if (!strcmp(c, "cube_corners"))
    return cube_corners();
  if (!strcmp(c, "planes"))
    return planes();
  if (!strcmp(c, "collinear"))
    return collinear_runs();
  if (!strcmp(c, "duplicates"))
    return duplicates();
  if (!strcmp(c, "one_off_plane"))
    return one_off_plane();
  if (!strcmp(c, "degenerate"))
    return degenerate_inputs();
  if (!strcmp(c, "sphere"))
    return sphere_and_centre();
  if (!strcmp(c, "skew_lines"))
    return skew_lines(150);
  if (!strcmp(c, "deterministic"))
    return deterministic();
  if (!strcmp(c, "det2"))
    return det2_same_bits();
  if (!strcmp(c, "hugepage"))
    return hugepage_hint_keeps_contents();
  fprintf(stderr, "unknown case %s\n", c);
  return 2;
}
