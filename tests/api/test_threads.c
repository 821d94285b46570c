/* Thread safety as include/tetrec.h states it: several inputs meshed on 4 threads at
 * once give byte-identical meshes to the serial runs, while every thread also reads one
 * shared mesh through the const accessors. Public header only. Also run under
 * ThreadSanitizer (scripts/tsan.sh). Usage: test_threads SOURCE_ROOT */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tetrec.h"

#define NTHREADS 4

static const char *const files[] = {
    "examples/data/cube.off", "tests/data/schoenhardt.off", "tests/data/two_cubes.off",
    "tests/data/cavity.off", "tests/data/cube_facets.poly",
    "tests/data/regressions/star_steiner_cluster_s2_1315.off"};
#define NFILES (sizeof files / sizeof *files)

static tr_plc *plc[NFILES];
static tr_mesh *serial[NFILES];
static const tr_mesh *shared; /* read by every thread at once */

/* 0 iff a and b are the same mesh: points, tets, regions, faces, markers, origins. */
static int differ(const tr_mesh *a, const tr_mesh *b)
{
  uint32_t nv = tr_mesh_num_vertices(a), nt = tr_mesh_num_tets(a),
           nf = tr_mesh_num_boundary_faces(a);
  if (nv != tr_mesh_num_vertices(b) || nt != tr_mesh_num_tets(b) ||
      nf != tr_mesh_num_boundary_faces(b))
    return 1;
  if (memcmp(tr_mesh_points(a), tr_mesh_points(b), 3 * sizeof(double) * nv) ||
      memcmp(tr_mesh_tets(a), tr_mesh_tets(b), 4 * sizeof(uint32_t) * nt) ||
      memcmp(tr_mesh_tet_regions(a), tr_mesh_tet_regions(b), sizeof(int32_t) * nt) ||
      memcmp(tr_mesh_boundary_faces(a), tr_mesh_boundary_faces(b), 3 * sizeof(uint32_t) * nf) ||
      memcmp(tr_mesh_boundary_markers(a), tr_mesh_boundary_markers(b), sizeof(int32_t) * nf))
    return 1;
  for (uint32_t v = 0; v < nv; v++) {
    int ka, kb;
    uint32_t ia, ib;
    if (tr_mesh_vertex_origin(a, v, &ka, &ia) != TR_OK ||
        tr_mesh_vertex_origin(b, v, &kb, &ib) != TR_OK || ka != kb || ia != ib)
      return 1;
  }
  return 0;
}

/* Reads every exact point of the shared mesh; the text must be the same every time. */
static int read_shared(char **first)
{
  int bad = 0;
  for (uint32_t v = 0; v < tr_mesh_num_vertices(shared); v++) {
    char *s = NULL;
    if (tr_mesh_point_exact(shared, v, &s) != TR_OK)
      return 1;
    if (!first[v])
      first[v] = s;
    else {
      bad |= strcmp(first[v], s) != 0;
      tr_free(s);
    }
  }
  return bad;
}

typedef struct {
  int id, failures;
  char msg[256];
} job;

static void *worker(void *arg)
{
  job *j = arg;
  char **texts = calloc(tr_mesh_num_vertices(shared), sizeof *texts);
  tr_options o;
  tr_options_default(&o);
  o.verbose = 0;
  for (size_t r = 0; r < 2 * NFILES; r++) {
    size_t i = (r + (size_t)j->id) % NFILES; /* threads start on different inputs */
    tr_mesh *m = NULL;
    tr_status s = tr_mesh_plc(plc[i], &o, &m, NULL);
    if (s != TR_OK || differ(m, serial[i])) {
      j->failures++;
      snprintf(j->msg, sizeof j->msg, "%s: %s %s", files[i], tr_status_name(s),
               s != TR_OK ? tr_last_error() : "differs from the serial mesh");
    }
    tr_mesh_destroy(m);
    if (texts && read_shared(texts)) {
      j->failures++;
      snprintf(j->msg, sizeof j->msg, "shared mesh read differently");
    }
  }
  /* an error message is per thread: this thread's failure is not another's */
  tr_plc *bad = NULL;
  char name[64];
  snprintf(name, sizeof name, "no-such-file-%d.off", j->id);
  if (tr_plc_read(name, &bad) == TR_OK || !strstr(tr_last_error(), name)) {
    j->failures++;
    snprintf(j->msg, sizeof j->msg, "error message not the thread's own: %s", tr_last_error());
  }
  for (uint32_t v = 0; texts && v < tr_mesh_num_vertices(shared); v++)
    tr_free(texts[v]);
  free(texts);
  tr_thread_cleanup();
  return NULL;
}

int main(int argc, char **argv)
{
  if (argc != 2) {
    fprintf(stderr, "usage: test_threads SOURCE_ROOT\n");
    return 2;
  }
  int failures = 0;
  tr_options o;
  tr_options_default(&o);
  o.verbose = 0;
  for (size_t i = 0; i < NFILES; i++) {
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", argv[1], files[i]);
    if (tr_plc_read(path, &plc[i]) != TR_OK || tr_mesh_plc(plc[i], &o, &serial[i], NULL) != TR_OK) {
      fprintf(stderr, "FAIL serial %s: %s\n", files[i], tr_last_error());
      return 1;
    }
  }
  shared = serial[1]; /* schoenhardt: has a Steiner point */
  pthread_t th[NTHREADS];
  job jobs[NTHREADS];
  for (int t = 0; t < NTHREADS; t++) {
    memset(&jobs[t], 0, sizeof jobs[t]);
    jobs[t].id = t;
    if (pthread_create(&th[t], NULL, worker, &jobs[t]) != 0) {
      fprintf(stderr, "FAIL pthread_create\n");
      return 1;
    }
  }
  for (int t = 0; t < NTHREADS; t++) {
    pthread_join(th[t], NULL);
    if (jobs[t].failures) {
      fprintf(stderr, "FAIL thread %d: %d failures, last: %s\n", t, jobs[t].failures,
              jobs[t].msg);
      failures++;
    }
  }
  for (size_t i = 0; i < NFILES; i++) {
    tr_mesh_destroy(serial[i]);
    tr_plc_destroy(plc[i]);
  }
  tr_thread_cleanup();
  printf("%d threads x %zu meshes each: %s\n", NTHREADS, 2 * NFILES,
         failures ? "FAILED" : "identical to the serial meshes");
  return failures != 0;
}
