/* In-process timing of tetrec's readers and writers (bench/io/run.sh), apart from the
 * Delaunay build that the whole-process figures include.
 *   bench_io read FILE [REPEAT [THREADS]]
 *       -> "read threads=.. points=.. triangles=.. seconds=.. cpu=.. hash=.." (best of
 *       REPEAT; hash: FNV-1a of the points' and triangles' bytes, to compare readings)
 *   bench_io write POINTS OUT_PREFIX THREADS_LIST FORMAT...
 *       builds the Delaunay mesh of POINTS once (every core), then writes it in each
 *       FORMAT (node, mesh, vtu, vtk, msh, msh22, meshb; a trailing "b" for the binary
 *       form: vtub, vtkb, mshb, msh22b) with each thread count of THREADS_LIST (e.g.
 *       1,2): "write format=.. threads=.. seconds=.. cpu=.. MB=.. MB/s=..". Every file
 *       is removed after it is timed (its dirty pages with it).
 * seconds: wall time; cpu: the process's CPU time (user + sys, every thread). Writing
 * goes to the page cache as the command's does; nothing is synced. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "delaunay/delaunay.h"
#include "io/io.h"
#include "tetrec.h"

static double clock_of(clockid_t id)
{
  struct timespec ts;
  clock_gettime(id, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
static double now(void) { return clock_of(CLOCK_MONOTONIC); }
static double cpu(void) { return clock_of(CLOCK_PROCESS_CPUTIME_ID); }

static int fail(const char *what)
{
  fprintf(stderr, "bench_io: %s: %s\n", what, tr_last_error());
  return 1;
}

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
  const unsigned char *c = p;
  for (size_t i = 0; i < n; i++)
    h = (h ^ c[i]) * 0x100000001b3ull;
  return h;
}

static int cmd_read(const char *path, int repeat, int threads)
{
  double best = -1, best_cpu = 0;
  uint32_t np = 0, nt = 0;
  uint64_t h = 0;
  for (int r = 0; r < repeat; r++) {
    tr_plc *plc = NULL;
    double t0 = now(), c0 = cpu();
    if (tr_plc_read_threads(path, &plc, threads) != TR_OK)
      return fail(path);
    double t = now() - t0, c = cpu() - c0;
    np = tr_plc_num_points(plc);
    nt = tr_plc_num_triangles(plc);
    h = fnv(0xcbf29ce484222325ull, tr_plc_points(plc), sizeof(double) * 3 * (size_t)np);
    h = fnv(h, tr_plc_triangles(plc), sizeof(uint32_t) * 3 * (size_t)nt);
    tr_plc_destroy(plc);
    if (best < 0 || t < best) {
      best = t;
      best_cpu = c;
    }
  }
  printf("read threads=%d points=%u triangles=%u seconds=%.3f cpu=%.3f hash=%016llx\n",
         threads, np, nt, best, best_cpu, (unsigned long long)h);
  return 0;
}

/* The output name and flags of a format name. */
static int format(const char *fmt, const char *prefix, char *path, size_t size, int *flags)
{
  static const struct {
    const char *name, *ext;
    int flags;
  } F[] = {{"node", "node", 0},   {"mesh", "mesh", 0},   {"vtu", "vtu", 0},
           {"vtub", "vtu", 41 | TR_WRITE_BINARY}, {"vtk", "vtk", 0},
           {"vtkb", "vtk", 41 | TR_WRITE_BINARY}, {"msh", "msh", 41},
           {"mshb", "msh", 41 | TR_WRITE_BINARY}, {"msh22", "msh", 22},
           {"msh22b", "msh", 22 | TR_WRITE_BINARY}, {"meshb", "meshb", 41}};
  for (size_t i = 0; i < sizeof F / sizeof *F; i++)
    if (!strcmp(fmt, F[i].name)) {
      snprintf(path, size, "%s.%s", prefix, F[i].ext);
      *flags = F[i].flags ? F[i].flags : 41;
      return 1;
    }
  return 0;
}

static long long file_bytes(const char *path)
{
  struct stat st;
  return stat(path, &st) == 0 ? (long long)st.st_size : 0;
}

static void remove_outputs(const char *path, const char *prefix)
{
  char p[4096];
  remove(path);
  static const char *tg[3] = {"node", "ele", "face"};
  for (int i = 0; i < 3; i++) {
    snprintf(p, sizeof p, "%s.%s", prefix, tg[i]);
    remove(p);
  }
}

static int cmd_write(const char *points, const char *prefix, const char *threads, char **fmts,
                     int nfmt)
{
  tr_plc *plc = NULL;
  if (tr_plc_read(points, &plc) != TR_OK)
    return fail(points);
  tr_mesh *m = NULL;
  if (tr_delaunay_build_threads(tr_plc_points(plc), tr_plc_num_points(plc), 0, &m) != TR_OK)
    return fail("delaunay");
  tr_plc_destroy(plc);
  printf("mesh vertices=%u tets=%u\n", tr_mesh_num_vertices(m), tr_mesh_num_tets(m));
  for (int i = 0; i < nfmt; i++) {
    char path[4096];
    int flags;
    if (!format(fmts[i], prefix, path, sizeof path, &flags)) {
      fprintf(stderr, "bench_io: unknown format %s\n", fmts[i]);
      return 2;
    }
    for (const char *t = threads; *t;) {
      int nth = atoi(t);
      double t0 = now(), c0 = cpu();
      if (tr_mesh_write_threads(m, path, 0, flags, nth) != TR_OK)
        return fail(path);
      double w = now() - t0, c = cpu() - c0;
      long long bytes = file_bytes(path);
      if (!strcmp(fmts[i], "node")) {
        char p[4096];
        snprintf(p, sizeof p, "%s.ele", prefix);
        bytes += file_bytes(p);
      }
      printf("write format=%s threads=%d seconds=%.3f cpu=%.3f MB=%.1f MB/s=%.0f\n", fmts[i],
             nth, w, c, bytes / 1e6, w > 0 ? bytes / 1e6 / w : 0);
      fflush(stdout);
      remove_outputs(path, prefix);
      t = strchr(t, ',');
      t = t ? t + 1 : "";
    }
  }
  tr_mesh_destroy(m);
  return 0;
}

int main(int argc, char **argv)
{
  if (argc >= 3 && !strcmp(argv[1], "read"))
    return cmd_read(argv[2], argc > 3 ? atoi(argv[3]) : 1, argc > 4 ? atoi(argv[4]) : 1);
  if (argc >= 6 && !strcmp(argv[1], "write"))
    return cmd_write(argv[2], argv[3], argv[4], argv + 5, argc - 5);
  fprintf(stderr, "usage: bench_io read FILE [REPEAT [THREADS]]\n"
                  "       bench_io write POINTS OUT_PREFIX THREADS_LIST FORMAT...\n");
  return 2;
}
