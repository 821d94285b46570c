/* The parallel Delaunay build (src/delaunay/par.c): for 1, 2, 3 and 4 threads, with a
 * short serial prefix so that the threads do nearly all of the work and meet often, the
 * store (tets, neighbours, vertex->tet map, duplicate map) is byte for byte the one of
 * the serial build, and valid (links, exact orientation, Euler, perturbed Delaunay
 * property). Point sets: uniform, on a sphere (nearly cospherical everywhere), an integer
 * grid (exactly cospherical: the perturbation decides), and uniform with duplicates; the
 * most threads the build takes (64); and the parallel insertion order alone on a set
 * large enough for its threads.
 * Usage: test_threads <case>. scripts/tsan.sh runs it under ThreadSanitizer. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "mesh/mesh.h"
#include "../mesh/tcommon.h"

static int same_store(const struct tr_mesh *a, const struct tr_mesh *b)
{
  if (a->nt != b->nt || a->nv != b->nv || a->ndup != b->ndup)
    return 0;
  return !memcmp(a->tv, b->tv, 4 * (size_t)a->nt * sizeof *a->tv) &&
         !memcmp(a->tn, b->tn, 4 * (size_t)a->nt * sizeof *a->tn) &&
         !memcmp(a->v2t, b->v2t, (size_t)a->nv * sizeof *a->v2t) &&
         !memcmp(a->dup_map, b->dup_map, (size_t)a->nv * sizeof *a->dup_map);
}

/* Serial build, then 1..4 threads after a serial prefix of `prefix` points: the same
 * store every time, and valid. */
static int compare(const char *what, const double *xyz, uint32_t n, uint32_t prefix)
{
  struct tr_mesh *ref;
  EXPECT_OK(tr_delaunay_build(xyz, n, &ref), what);
  EXPECT(tr_check_mesh(ref, TR_CHK_ALL_DELAUNAY, NULL) == TR_OK, "%s: serial mesh invalid: %s",
         what, tr_last_error());
  for (int th = 1; th <= 4; th++) {
    struct tr_mesh *m;
    EXPECT_OK(tr_delaunay_build_ex(xyz, n, th, prefix, &m), what);
    tr_status s = tr_check_mesh(m, TR_CHK_ALL_DELAUNAY, NULL);
    EXPECT(s == TR_OK, "%s, %d threads: invalid mesh: %s", what, th, tr_last_error());
    EXPECT(same_store(ref, m), "%s, %d threads: the store differs from the serial one", what,
           th);
    tr_mesh_destroy(m);
  }
  printf("%s: %u points, %u tets, the same store for 1-4 threads\n", what, n, ref->nt);
  tr_mesh_destroy(ref);
  return 0;
}

/* The most threads the build takes (64: the largest thread id, which must fit par.c's
 * owner byte), each with a few hundred points per pass: the serial store, and valid. */
static int max_threads(uint32_t n)
{
  double *p = malloc(3 * (size_t)n * sizeof *p);
  for (uint32_t i = 0; i < 3 * n; i++)
    p[i] = t_unif();
  struct tr_mesh *ref, *m;
  EXPECT_OK(tr_delaunay_build(p, n, &ref), "64 threads");
  EXPECT_OK(tr_delaunay_build_ex(p, n, 64, 64, &m), "64 threads");
  EXPECT(tr_check_mesh(m, TR_CHK_ALL_DELAUNAY, NULL) == TR_OK, "64 threads: invalid mesh: %s",
         tr_last_error());
  EXPECT(same_store(ref, m), "64 threads: the store differs from the serial one");
  printf("uniform: %u points, %u tets, the same store for 64 threads\n", n, ref->nt);
  tr_mesh_destroy(m);
  tr_mesh_destroy(ref);
  free(p);
  return 0;
}

static int uniform(uint32_t n)
{
  double *p = malloc(3 * (size_t)n * sizeof *p);
  for (uint32_t i = 0; i < 3 * n; i++)
    p[i] = t_unif();
  int r = compare("uniform", p, n, 64);
  free(p);
  return r;
}

/* Gaussian samples normalised: every point on the unit sphere (rounded). */
static int sphere(uint32_t n)
{
  double *p = malloc(3 * (size_t)n * sizeof *p);
  for (uint32_t i = 0; i < n; i++) {
    double x, y, z, r;
    do {
      x = 2 * t_unif() - 1;
      y = 2 * t_unif() - 1;
      z = 2 * t_unif() - 1;
      r = sqrt(x * x + y * y + z * z);
    } while (r > 1 || r < 1e-3);
    p[3 * i] = x / r;
    p[3 * i + 1] = y / r;
    p[3 * i + 2] = z / r;
  }
  int r = compare("sphere", p, n, 64);
  free(p);
  return r;
}

/* k^3 integer grid: every cube cospherical, the perturbation decides everywhere. */
static int grid(uint32_t k)
{
  const uint32_t n = k * k * k;
  double *p = malloc(3 * (size_t)n * sizeof *p);
  for (uint32_t i = 0; i < n; i++) {
    p[3 * i] = i % k;
    p[3 * i + 1] = (i / k) % k;
    p[3 * i + 2] = i / (k * k);
  }
  int r = compare("grid", p, n, 64);
  free(p);
  return r;
}

/* Uniform points, every fifth one a copy of an earlier one. */
static int duplicates(uint32_t n)
{
  double *p = malloc(3 * (size_t)n * sizeof *p);
  for (uint32_t i = 0; i < n; i++) {
    const uint32_t j = i % 5 == 4 ? (uint32_t)(t_unif() * i) : i;
    for (int c = 0; c < 3; c++)
      p[3 * i + c] = j == i ? t_unif() : p[3 * j + c];
  }
  int r = compare("duplicates", p, n, 64);
  free(p);
  return r;
}

/* The insertion order alone (tr_spatial_order_threads: the keys and radix passes cut
 * into one range per thread from 2^16 points per thread): for 1..4 threads the same
 * order, count and duplicate map as the serial sort. Uniform points, every seventh a
 * copy of an earlier one, and a run of equal keys (points closer than a Hilbert cell). */
static int sort_order(uint32_t n)
{
  double *p = malloc(3 * (size_t)n * sizeof *p);
  uint32_t *o1 = malloc(n * sizeof *o1), *d1 = malloc(n * sizeof *d1);
  uint32_t *o = malloc(n * sizeof *o), *d = malloc(n * sizeof *d);
  for (uint32_t i = 0; i < n; i++) {
    const uint32_t j = i % 7 == 6 ? (uint32_t)(t_unif() * i) : i;
    for (int c = 0; c < 3; c++)
      p[3 * i + c] = j != i ? p[3 * j + c] : i % 11 == 3 ? 0.5 + 1e-9 * t_unif() : t_unif();
  }
  uint32_t nu1, nu;
  EXPECT_OK(tr_spatial_order(p, n, o1, &nu1, d1), "sort: serial");
  for (int th = 1; th <= 4; th++) {
    EXPECT_OK(tr_spatial_order_threads(p, n, o, &nu, d, th), "sort: threads");
    EXPECT(nu == nu1 && !memcmp(o, o1, nu * sizeof *o) && !memcmp(d, d1, n * sizeof *d),
           "sort, %d threads: order or duplicate map differs from the serial sort", th);
  }
  printf("sort: %u points, %u distinct, the same order for 1-4 threads\n", n, nu1);
  free(p);
  free(o1);
  free(d1);
  free(o);
  free(d);
  return 0;
}

int main(int argc, char **argv)
{
  if (argc < 2)
    return 2;
  const char *c = argv[1];
  if (!strcmp(c, "uniform"))
    return uniform(30000);
  if (!strcmp(c, "sphere"))
    return sphere(20000);
  if (!strcmp(c, "grid"))
    return grid(22);
  if (!strcmp(c, "duplicates"))
    return duplicates(20000);
  if (!strcmp(c, "max_threads"))
    return max_threads(40000);
  if (!strcmp(c, "sort"))
    return sort_order(300000);
  /* scripts/tsan.sh: smaller sets, every kind; the uniform one large enough (> 2^17
   * tets) that the canonical order and the renumbering run on 2 threads */
  if (!strcmp(c, "all"))
    return uniform(20000) | sphere(6000) | grid(14) | duplicates(6000) | sort_order(140000) |
           max_threads(20000);
  fprintf(stderr, "unknown case %s\n", c);
  return 2;
}
