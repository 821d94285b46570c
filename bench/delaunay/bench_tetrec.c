/* Delaunay benchmark driver for tetrec, and the point generator shared with the CGAL
 * and tetgen runs (bench/delaunay/run.sh).
 *   bench_tetrec gen random|sphere|grid N out.bin out.node   (grid: N points per axis)
 * random: N points uniform in the unit cube; sphere: N points on the unit sphere (Gaussian
 * samples normalised, so every insphere test among close points is nearly degenerate:
 * the case that exercises the exact stages of the predicates); grid: the N^3 integer
 * grid (exactly cospherical: the symbolic perturbation decides). Fixed seeds.
 *   bench_tetrec run in.bin [check] [hash] [-jN]   (N threads, 0 every core; default 1)
 * .bin: uint32 n, then 3n doubles (native endianness). run prints one line
 * "tetrec n=.. tets=.. dt_seconds=.. dt_cpu=.." (triangulation only, reading excluded;
 * wall and CPU time) and with
 * `check` validates the mesh (links, orientation, Euler, Delaunay) and says so; `hash`
 * prints an FNV-1a hash of the store (nt, tv, tn, v2t), to compare two builds of the
 * kernel byte for byte. */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "delaunay/delaunay.h"
#include "mesh/check.h"

static double now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* CPU time of the process: on a loaded machine this is the comparable figure (tetgen
 * reports clock() time too). */
static double cpu(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* xorshift64: a fixed sequence on every machine */
static double uniform01(unsigned long long *s)
{
  *s ^= *s << 13;
  *s ^= *s >> 7;
  *s ^= *s << 17;
  return (double)(*s >> 11) * 0x1p-53;
}

/* Standard normal by Box-Muller from two uniforms in (0, 1]. */
static double gauss(unsigned long long *s)
{
  const double u = 1.0 - uniform01(s), v = uniform01(s);
  return sqrt(-2.0 * log(u)) * cos(6.283185307179586 * v);
}

static int gen(const char *kind, unsigned long n, const char *bin, const char *node)
{
  size_t np;
  double *p;
  if (!strcmp(kind, "grid")) {
    np = n * n * n;
    p = malloc(3 * np * sizeof *p);
    size_t k = 0;
    for (unsigned long z = 0; z < n; z++)
      for (unsigned long y = 0; y < n; y++)
        for (unsigned long x = 0; x < n; x++, k++) {
          p[3 * k] = (double)x;
          p[3 * k + 1] = (double)y;
          p[3 * k + 2] = (double)z;
        }
  } else if (!strcmp(kind, "sphere")) {
    np = n;
    p = malloc(3 * np * sizeof *p);
    unsigned long long s = 0x9e3779b97f4a7c15ull;
    for (size_t i = 0; i < np; i++) {
      double x, y, z, r;
      do {
        x = gauss(&s);
        y = gauss(&s);
        z = gauss(&s);
        r = sqrt(x * x + y * y + z * z);
      } while (!(r > 1e-3)); /* keep the direction well defined */
      p[3 * i] = x / r;
      p[3 * i + 1] = y / r;
      p[3 * i + 2] = z / r;
    }
  } else if (!strcmp(kind, "random")) {
    np = n;
    p = malloc(3 * np * sizeof *p);
    unsigned long long s = 88172645463325252ull;
    for (size_t i = 0; i < 3 * np; i++)
      p[i] = uniform01(&s);
  } else {
    fprintf(stderr, "unknown point set %s (random, sphere, grid)\n", kind);
    return 2;
  }
  if (!p) {
    fprintf(stderr, "out of memory\n");
    return 1;
  }
  FILE *f = fopen(bin, "wb");
  uint32_t n32 = (uint32_t)np;
  if (!f || fwrite(&n32, 4, 1, f) != 1 || fwrite(p, sizeof *p, 3 * np, f) != 3 * np) {
    fprintf(stderr, "cannot write %s\n", bin);
    return 1;
  }
  fclose(f);
  f = fopen(node, "w");
  if (!f) {
    fprintf(stderr, "cannot write %s\n", node);
    return 1;
  }
  fprintf(f, "%zu 3 0 0\n", np);
  for (size_t i = 0; i < np; i++)
    fprintf(f, "%zu %.17g %.17g %.17g\n", i + 1, p[3 * i], p[3 * i + 1], p[3 * i + 2]);
  fclose(f);
  free(p);
  return 0;
}

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
  const unsigned char *c = p;
  for (size_t i = 0; i < n; i++)
    h = (h ^ c[i]) * 0x100000001b3ull;
  return h;
}

static int run(const char *bin, int check, int hash, int threads)
{
  FILE *f = fopen(bin, "rb");
  uint32_t n;
  if (!f || fread(&n, 4, 1, f) != 1) {
    fprintf(stderr, "cannot read %s\n", bin);
    return 1;
  }
  double *p = malloc(3 * (size_t)n * sizeof *p);
  if (!p || fread(p, sizeof *p, 3 * (size_t)n, f) != 3 * (size_t)n) {
    fprintf(stderr, "short file %s\n", bin);
    return 1;
  }
  fclose(f);
  double t0 = now(), c0 = cpu();
  struct tr_mesh *m;
  tr_status s = threads == 1 ? tr_delaunay_build(p, n, &m)
                             : tr_delaunay_build_threads(p, n, threads, &m);
  double t1 = now(), c1 = cpu();
  if (s != TR_OK) {
    fprintf(stderr, "tetrec: %s: %s\n", tr_status_name(s), tr_last_error());
    return 1;
  }
  printf("tetrec n=%u threads=%d tets=%u dt_seconds=%.3f dt_cpu=%.3f\n", n,
         tr_delaunay_thread_count(threads), tr_mesh_num_tets(m), t1 - t0, c1 - c0);
  if (hash) {
    uint64_t h = fnv(0xcbf29ce484222325ull, &m->nt, sizeof m->nt);
    h = fnv(h, m->tv, 4 * (size_t)m->nt * sizeof *m->tv);
    h = fnv(h, m->tn, 4 * (size_t)m->nt * sizeof *m->tn);
    h = fnv(h, m->v2t, (size_t)m->nv * sizeof *m->v2t);
    printf("tetrec store hash %016llx\n", (unsigned long long)h);
  }
  if (check) {
    s = tr_check_mesh(m, TR_CHK_ALL_DELAUNAY, NULL);
    printf("tetrec validator: %s%s%s (%.2f s)\n", s == TR_OK ? "valid Delaunay mesh" : "INVALID",
           s == TR_OK ? "" : ": ", s == TR_OK ? "" : tr_last_error(), now() - t1);
    if (s != TR_OK)
      return 1;
  }
  tr_mesh_destroy(m);
  free(p);
  return 0;
}

int main(int argc, char **argv)
{
  if (argc >= 6 && !strcmp(argv[1], "gen"))
    return gen(argv[2], strtoul(argv[3], NULL, 10), argv[4], argv[5]);
  if (argc >= 3 && !strcmp(argv[1], "run")) {
    int check = 0, hash = 0, threads = 1;
    for (int i = 3; i < argc; i++) {
      if (!strcmp(argv[i], "check"))
        check = 1;
      else if (!strcmp(argv[i], "hash"))
        hash = 1;
      else if (!strncmp(argv[i], "-j", 2) && argv[i][2] >= '0' && argv[i][2] <= '9')
        threads = atoi(argv[i] + 2);
      else
        break;
    }
    return run(argv[2], check, hash, threads);
  }
  fprintf(stderr, "usage: bench_tetrec gen random|sphere|grid N out.bin out.node\n"
                  "       bench_tetrec run in.bin [check] [hash] [-jN]   (N threads, 0: all "
                  "cores; default 1)\n");
  return 2;
}
