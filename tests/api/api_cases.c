/* The public API beyond the accessors: the writers' faces and markers in every format,
 * progress and cancellation, the ABI size rule of tr_options/tr_stats, the per-stage
 * times, the version. Cases of test_api (main in test_api.c). */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api.h"
#include "io/io.h"
#include "mesh/check.h"
#include "mesh/conform.h"
#include "pipeline/pipeline.h"

/* ---- writers: the faces and markers in every format ---- */
/* The whole file as a string (stdio: through tr_io_load's out-parameter, gcc -O3 took
 * every pointer into the text for one to a local of this function). */
static char *slurp(const char *path)
{
  FILE *f = fopen(path, "rb");
  char *buf = NULL;
  long n = -1;
  if (f && fseek(f, 0, SEEK_END) == 0 && (n = ftell(f)) >= 0 && fseek(f, 0, SEEK_SET) == 0 &&
      (buf = malloc((size_t)n + 1)) != NULL) {
    if (fread(buf, 1, (size_t)n, f) == (size_t)n)
      buf[n] = '\0';
    else {
      free(buf);
      buf = NULL;
    }
  }
  if (f)
    fclose(f);
  return buf;
}

void t_writers(const char *tmp)
{
  tr_plc *p = two_region_box(), *used = NULL;
  tr_mesh *m = mesh_checked(p, "two_region_box", &used);
  tr_plc_destroy(p);
  tr_plc_destroy(used);
  if (!m)
    return;
  uint32_t nf = tr_mesh_num_boundary_faces(m), nt = tr_mesh_num_tets(m);
  const uint32_t *bf = tr_mesh_boundary_faces(m);
  const int32_t *bm = tr_mesh_boundary_markers(m);
  char path[4200];
  /* Medit: read back through tetrec's reader (triangle refs become markers) */
  snprintf(path, sizeof path, "%s/w.mesh", tmp);
  EXPECT(tr_mesh_write(m, path, 0) == TR_OK, "write .mesh: %s", tr_last_error());
  tr_plc *q = NULL;
  EXPECT(tr_plc_read(path, &q) == TR_OK, "read .mesh: %s", tr_last_error());
  if (q) {
    EXPECT(q->ntris == nf && q->ntets == nt, ".mesh: %u triangles %u tets (%u, %u)", q->ntris,
           q->ntets, nf, nt);
    EXPECT(q->ntris == nf && memcmp(q->tris, bf, sizeof *bf * 3 * nf) == 0 &&
               memcmp(q->tri_marker, bm, sizeof *bm * nf) == 0,
           ".mesh: triangles or refs differ from the boundary faces");
    EXPECT(q->ntets == nt && memcmp(q->tets, tr_mesh_tets(m), 16 * (size_t)nt) == 0,
           ".mesh: tets differ");
    EXPECT(memcmp(q->xyz, tr_mesh_points(m), 24 * (size_t)tr_mesh_num_vertices(m)) == 0,
           ".mesh: points differ");
  }
  tr_plc_destroy(q);
  /* TetGen .face: index, three 1-based vertices, marker */
  snprintf(path, sizeof path, "%s/w.1", tmp);
  EXPECT(tr_mesh_write(m, path, 0) == TR_OK, "write .node: %s", tr_last_error());
  snprintf(path, sizeof path, "%s/w.1.face", tmp);
  char *buf = slurp(path);
  EXPECT(buf != NULL, "no .face");
  if (buf) {
    char *s = buf;
    unsigned long n = strtoul(s, &s, 10), flag = strtoul(s, &s, 10);
    EXPECT(n == nf && flag == 1, ".face header: %lu faces, marker flag %lu", n, flag);
    for (uint32_t f = 0; f < nf && n == nf; f++) {
      unsigned long i = strtoul(s, &s, 10);
      long v[3], mk;
      for (int j = 0; j < 3; j++)
        v[j] = strtol(s, &s, 10);
      mk = strtol(s, &s, 10);
      EXPECT(i == f + 1 && v[0] == bf[3 * f] + 1 && v[1] == bf[3 * f + 1] + 1 &&
                 v[2] == bf[3 * f + 2] + 1 && mk == bm[f],
             ".face line %u differs", f);
    }
    free(buf);
  }
  /* VTU: tets then triangles, "marker" cell data */
  snprintf(path, sizeof path, "%s/w.vtu", tmp);
  EXPECT(tr_mesh_write(m, path, 0) == TR_OK, "write .vtu: %s", tr_last_error());
  buf = slurp(path);
  if (buf) {
    char want[128];
    snprintf(want, sizeof want, "NumberOfCells=\"%u\"", nt + nf);
    EXPECT(strstr(buf, want) != NULL, ".vtu: %s expected", want);
    char *mk = strstr(buf, "Name=\"marker\"");
    EXPECT(mk != NULL, ".vtu: no marker data");
    if (mk) {
      char *s = strchr(mk, '\n') + 1;
      for (uint32_t c = 0; c < nt + nf; c++) {
        long x = strtol(s, &s, 10);
        EXPECT(x == (c < nt ? 0 : bm[c - nt]), ".vtu: marker of cell %u is %ld", c, x);
      }
    }
    free(buf);
  } else
    EXPECT(0, "no .vtu");
  tr_mesh_destroy(m);
}

/* An open surface meshed within its convex hull (allow_open): the .mesh triangles are
 * the faces on input triangles with their markers, then every other hull face with
 * reference 0, so together they bound the mesh. */
void t_writers_open(const char *tmp)
{
  tr_plc *p = hard_plc("open_box");
  if (!p)
    return;
  tr_options o = quiet();
  o.allow_open = 1;
  tr_mesh *m = NULL;
  EXPECT(tr_mesh_plc(p, &o, &m, NULL) == TR_OK, "open box: %s", tr_last_error());
  tr_plc_destroy(p);
  if (!m)
    return;
  EXPECT(tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT, NULL) == TR_OK, "open box: %s",
         tr_last_error());
  char path[4200];
  snprintf(path, sizeof path, "%s/open.mesh", tmp);
  EXPECT(tr_mesh_write(m, path, 0) == TR_OK, "write: %s", tr_last_error());
  tr_plc *q = NULL;
  EXPECT(tr_plc_read(path, &q) == TR_OK, "read back: %s", tr_last_error());
  uint32_t nf = tr_mesh_num_boundary_faces(m), nt = tr_mesh_num_tets(m);
  if (q) {
    EXPECT(q->ntris > nf && memcmp(q->tris, tr_mesh_boundary_faces(m), 12 * (size_t)nf) == 0 &&
               memcmp(q->tri_marker, tr_mesh_boundary_markers(m), 4 * (size_t)nf) == 0,
           "open: the input faces come first (%u triangles, %u faces)", q->ntris, nf);
    for (uint32_t i = nf; i < q->ntris; i++)
      EXPECT(q->tri_marker[i] == 0, "open: hull face %u has marker %d", i, q->tri_marker[i]);
    /* every face of exactly one tet (the hull) is among the triangles written */
    const uint32_t *tv = tr_mesh_tets(m);
    uint32_t *keys = malloc(sizeof *keys * 12 * (size_t)nt), *tk = malloc(12 * (size_t)q->ntris);
    for (uint32_t t = 0; t < nt; t++)
      for (int k = 0; k < 4; k++) {
        uint32_t *f = keys + 12 * (size_t)t + 3 * k;
        for (int j = 0; j < 3; j++)
          f[j] = tv[4 * t + tr_face_vtx[k][j]];
        tr_sort3(f);
      }
    qsort(keys, 4 * (size_t)nt, 12, cmp_key);
    memcpy(tk, q->tris, 12 * (size_t)q->ntris);
    for (uint32_t i = 0; i < q->ntris; i++)
      tr_sort3(tk + 3 * (size_t)i);
    qsort(tk, q->ntris, 12, cmp_key);
    uint32_t hull = 0;
    for (size_t i = 0; i < 4 * (size_t)nt;) {
      size_t j = i + 1;
      while (j < 4 * (size_t)nt && cmp_key(keys + 3 * i, keys + 3 * j) == 0)
        j++;
      if (j == i + 1) {
        hull++;
        EXPECT(bsearch(keys + 3 * i, tk, q->ntris, 12, cmp_key) != NULL,
               "open: hull face not written");
      }
      i = j;
    }
    EXPECT(hull > 0, "open: no hull face");
    free(keys);
    free(tk);
  }
  tr_plc_destroy(q);
  tr_mesh_destroy(m);
}

/* ---- progress and cancellation ---- */
typedef struct {
  int calls, cancel_at;
  char stages[64][24];
  double fraction[64];
} prog;

static int on_progress(void *user, const char *stage, double fraction)
{
  prog *p = user;
  if (p->calls < 64) {
    snprintf(p->stages[p->calls], sizeof p->stages[0], "%s", stage ? stage : "(null)");
    p->fraction[p->calls] = fraction;
  }
  return ++p->calls == p->cancel_at;
}

void t_progress(void)
{
  tr_plc *p = read_plc("tests/data/schoenhardt.off");
  if (!p)
    return;
  tr_options o = quiet();
  prog rec;
  memset(&rec, 0, sizeof rec);
  o.progress = on_progress;
  o.progress_user = &rec;
  tr_mesh *m = NULL;
  EXPECT(tr_mesh_plc(p, &o, &m, NULL) == TR_OK && m, "progress run: %s", tr_last_error());
  tr_mesh_destroy(m);
  /* every stage the pipeline runs, in order, each opened (0) and closed (1) */
  static const int order[] = {TR_STAGE_VALIDATE, TR_STAGE_SMOOTH, TR_STAGE_DELAUNAY,
                              TR_STAGE_EDGES, TR_STAGE_FACETS, TR_STAGE_COLOR,
                              TR_STAGE_SUPPRESS, TR_STAGE_ROUND};
  int n = (int)(sizeof order / sizeof *order);
  EXPECT(rec.calls == 2 * n, "progress: %d calls (%d expected)", rec.calls, 2 * n);
  for (int i = 0; i < rec.calls && i < 2 * n; i++)
    EXPECT(strcmp(rec.stages[i], tr_stage_name(order[i / 2])) == 0 &&
               rec.fraction[i] == (i % 2 ? 1.0 : 0.0),
           "progress call %d: %s %g", i, rec.stages[i], rec.fraction[i]);
  /* cancel at each call in turn: TR_ERR_CANCELLED, no mesh, nothing leaked (the suite
   * runs under ASan's leak checker too) */
  int total = rec.calls;
  for (int c = 1; c <= total; c++) {
    memset(&rec, 0, sizeof rec);
    rec.cancel_at = c;
    m = (tr_mesh *)&rec; /* must be reset to NULL */
    tr_plc *used = (tr_plc *)&rec;
    tr_stats st = {.size = sizeof st};
    tr_status s = tr_mesh_plc_ex(p, &o, &m, &st, &used);
    EXPECT(s == TR_ERR_CANCELLED && m == NULL && used == NULL && rec.calls == c,
           "cancel at call %d: %s (%s), %d calls", c, tr_status_name(s), tr_last_error(),
           rec.calls);
    EXPECT(strstr(tr_last_error(), "cancelled") != NULL, "cancel message: %s", tr_last_error());
  }
  EXPECT(strcmp(tr_status_name(TR_ERR_CANCELLED), "TR_ERR_CANCELLED") == 0, "status name");
  tr_plc_destroy(p);
}

/* With a quality bound, refinement is a stage of its own between coloring and rounding:
 * its progress calls come in that place and its time is in its own row, not coloring's. */
void t_progress_refinement(void)
{
  tr_plc *p = read_plc("examples/data/cube.off");
  if (!p)
    return;
  tr_options o = quiet();
  o.quality_ratio = 1.414;
  prog rec;
  memset(&rec, 0, sizeof rec);
  o.progress = on_progress;
  o.progress_user = &rec;
  tr_mesh *m = NULL;
  tr_plc *used = NULL;
  tr_stats st = {.size = sizeof st};
  EXPECT(tr_mesh_plc_ex(p, &o, &m, &st, &used) == TR_OK && m, "quality run: %s",
         tr_last_error());
  if (!m) {
    tr_plc_destroy(p);
    return;
  }
  static const int order[] = {TR_STAGE_VALIDATE, TR_STAGE_SMOOTH, TR_STAGE_DELAUNAY,
                              TR_STAGE_EDGES, TR_STAGE_FACETS, TR_STAGE_COLOR,
                              TR_STAGE_SUPPRESS, TR_STAGE_REFINE, TR_STAGE_ROUND};
  int n = (int)(sizeof order / sizeof *order);
  EXPECT(rec.calls == 2 * n, "progress: %d calls (%d expected)", rec.calls, 2 * n);
  for (int i = 0; i < rec.calls && i < 2 * n; i++)
    EXPECT(strcmp(rec.stages[i], tr_stage_name(order[i / 2])) == 0 &&
               rec.fraction[i] == (i % 2 ? 1.0 : 0.0),
           "progress call %d: %s %g", i, rec.stages[i], rec.fraction[i]);
  EXPECT(strcmp(tr_stage_name(TR_STAGE_REFINE), "refinement") == 0, "stage name %s",
         tr_stage_name(TR_STAGE_REFINE));
  EXPECT(st.stage_seconds[TR_STAGE_REFINE] > 0, "refinement not timed");
  double sum = 0;
  for (int k = 0; k < TR_STAGE_COUNT; k++)
    sum += st.stage_seconds[k];
  EXPECT(sum <= st.total_seconds, "stages %g > total %g", sum, st.total_seconds);
  EXPECT(tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, NULL) == TR_OK,
         "refined mesh: %s", tr_last_error());
  EXPECT(tr_check_conformity(m, used, NULL, 0) == TR_OK, "refined conformity: %s",
         tr_last_error());
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
  tr_plc_destroy(p);
}

static int must_not_be_called(void *user, const char *stage, double fraction)
{
  (void)stage;
  (void)fraction;
  ++*(int *)user;
  return 1;
}

/* A caller built against a smaller tr_options/tr_stats: fields past its size are neither
 * read nor written. */
void t_abi_size(void)
{
  tr_options d;
  tr_options_default(&d);
  EXPECT(d.size == sizeof d && d.progress == NULL && d.smooth == 1, "defaults");
  tr_plc *p = read_plc("examples/data/cube.off");
  if (!p)
    return;
  tr_options o = quiet();
  int called = 0;
  o.progress = must_not_be_called;
  o.progress_user = &called;
  o.size = offsetof(tr_options, progress);
  tr_stats st;
  memset(&st, 0, sizeof st);
  for (int k = 0; k < TR_STAGE_COUNT; k++)
    st.stage_seconds[k] = -1;
  st.size = offsetof(tr_stats, stage_seconds);
  tr_mesh *m = NULL;
  EXPECT(tr_mesh_plc(p, &o, &m, &st) == TR_OK, "small structs: %s", tr_last_error());
  EXPECT(called == 0, "progress read past options size");
  EXPECT(st.size == offsetof(tr_stats, stage_seconds) && st.volume_elements > 0,
         "stats size %zu", st.size);
  for (int k = 0; k < TR_STAGE_COUNT; k++)
    EXPECT(st.stage_seconds[k] == -1, "stage %d written past the stats size", k);
  tr_mesh_destroy(m);
  /* size 0: this header's size, the whole struct */
  o.size = 0;
  memset(&st, 0, sizeof st);
  EXPECT(tr_mesh_plc(p, &o, &m, &st) == TR_ERR_CANCELLED && called == 1 && !m,
         "size 0 reads the whole options");
  tr_plc_destroy(p);
}

/* Every stage's time is recorded, non-negative, within the total. */
void t_stage_times(void)
{
  tr_plc *p = read_plc("tests/data/schoenhardt.off");
  if (!p)
    return;
  tr_options o = quiet();
  tr_stats st = {.size = 0};
  tr_mesh *m = NULL;
  EXPECT(tr_mesh_plc(p, &o, &m, &st) == TR_OK, "%s", tr_last_error());
  EXPECT(st.size == sizeof st, "stats size out %zu", st.size);
  double sum = 0;
  for (int k = 0; k < TR_STAGE_COUNT; k++) {
    EXPECT(st.stage_seconds[k] >= 0, "stage %d negative", k);
    sum += st.stage_seconds[k];
  }
  EXPECT(st.stage_seconds[TR_STAGE_READ] == 0 && st.stage_seconds[TR_STAGE_WRITE] == 0,
         "the library neither reads nor writes");
  EXPECT(sum <= st.total_seconds, "stages %g > total %g", sum, st.total_seconds);
  EXPECT(st.stage_seconds[TR_STAGE_DELAUNAY] > 0 && st.stage_seconds[TR_STAGE_EDGES] > 0,
         "stages not timed");
  const char *seen[TR_STAGE_COUNT];
  for (int k = 0; k < TR_STAGE_COUNT; k++) {
    seen[k] = tr_stage_name(k);
    EXPECT(seen[k] && *seen[k], "stage %d unnamed", k);
    for (int j = 0; j < k; j++)
      EXPECT(seen[j] && seen[k] && strcmp(seen[j], seen[k]) != 0, "stage names repeat");
  }
  EXPECT(tr_stage_name(-1) == NULL && tr_stage_name(TR_STAGE_COUNT) == NULL, "out of range");
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
}

void t_version(const char *want)
{
  int a = -1, b = -1, c = -1;
  tr_version(&a, &b, &c);
  char got[64];
  snprintf(got, sizeof got, "%d.%d.%d", a, b, c);
  EXPECT(want && strcmp(got, want) == 0, "tr_version %s, meson %s", got, want ? want : "?");
  EXPECT(a == TETREC_VERSION_MAJOR && b == TETREC_VERSION_MINOR && c == TETREC_VERSION_PATCH,
         "header macros differ from tr_version");
  EXPECT(strcmp(TETREC_VERSION_STRING, got) == 0, "TETREC_VERSION_STRING %s",
         TETREC_VERSION_STRING);
  tr_version(NULL, NULL, NULL);
}

