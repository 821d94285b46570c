/* Parallel output and input (issue 48): the block writer (src/io/blocks.c), the writers
 * that format on several threads, and the parallel reading of a .node file's points
 * (src/io/read_tetgen.c). Every case compares bytes: the files of 1, 2 and 3 threads,
 * a printf reference, or the serial reading. Usage: test_blocks CASE TMPDIR */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "delaunay/delaunay.h"
#include "io/blocks.h"
#include "io/io.h"
#include "mesh/mesh.h"
#include "tetrec.h"
#include "tpath.h"
#include "../pipeline/texpect.h"

static const char *tmp;

static char *slurp(const char *path, size_t *len)
{
  char *b = NULL;
  *len = 0;
  if (tr_io_load(path, &b, len) != TR_OK)
    return NULL;
  return b;
}

/* 1 iff files a and b hold the same bytes (both readable). */
static int same_file(const char *a, const char *b)
{
  size_t na, nb;
  char *x = slurp(a, &na), *y = slurp(b, &nb);
  int same = x && y && na == nb && memcmp(x, y, na) == 0;
  free(x);
  free(y);
  return same;
}

static uint64_t lcg_state = 0x2545f4914f6cdd1dull;
static uint64_t lcg(void)
{
  lcg_state = lcg_state * 6364136223846793005ull + 1442695040888963407ull;
  return lcg_state >> 11;
}
static double unit(void) { return (double)lcg() / 9007199254740992.0; }

/* ---- the block writer ---- */

/* record i: its number, a colon, i * 7919 % 13 letters, a newline: lengths vary */
static char *letters(const void *ctx, uint64_t i0, uint64_t i1, char *p)
{
  (void)ctx;
  for (uint64_t i = i0; i < i1; i++) {
    p += sprintf(p, "%llu:", (unsigned long long)i);
    for (uint64_t k = 0; k < i * 7919 % 13; k++)
      *p++ = (char)('a' + k);
    *p++ = '\n';
  }
  return p;
}

static void t_blocks_order(void)
{
  static const uint64_t counts[] = {0, 1, 4095, 4096, 4097, 3 * 4096 + 5, 50000};
  static const int threads[] = {1, 2, 3, 5, 64};
  const char *path = tpath(tmp, "blocks_order.txt");
  for (size_t c = 0; c < sizeof counts / sizeof *counts; c++) {
    uint64_t n = counts[c];
    char *want = malloc((size_t)n * 40 + 64), *end = letters(NULL, 0, n, want);
    for (size_t t = 0; t < sizeof threads / sizeof *threads; t++) {
      FILE *f = fopen(path, "wb");
      tr_status s = tr_io_write_blocks(f, n, 40, letters, NULL, threads[t]);
      fclose(f);
      size_t len;
      char *got = slurp(path, &len);
      EXPECT(s == TR_OK && got && len == (size_t)(end - want) && !memcmp(got, want, len),
             "%llu records on %d threads: %zu bytes, %td expected, or different",
             (unsigned long long)n, threads[t], len, end - want);
      free(got);
    }
    free(want);
  }
  remove(path);
}

/* ---- the formatters ---- */

static void t_fmt_lines(void)
{
  static const int64_t edge[] = {0, 1, -1, 9, 10, 99, 100, 101, 4294967295ll, 4294967296ll,
                                 -4294967296ll, INT64_MAX, INT64_MIN, INT64_MIN + 1};
  char got[TR_IO_INT_MAX * 9 + 8], want[512];
  for (size_t i = 0; i < sizeof edge / sizeof *edge; i++) {
    char *e = tr_io_fmt_ints(got, edge + i, 1);
    snprintf(want, sizeof want, "%lld\n", (long long)edge[i]);
    EXPECT((size_t)(e - got) == strlen(want) && !memcmp(got, want, strlen(want)),
           "%lld written as '%.*s'", (long long)edge[i], (int)(e - got), got);
  }
  for (int r = 0; r < 100000; r++) {
    int64_t x[9];
    int n = 1 + (int)(lcg() % 9), len = 0;
    for (int k = 0; k < n; k++) {
      int bits = (int)(lcg() % 64);
      x[k] = (int64_t)(lcg() << 11 ^ lcg()) >> bits;
      len += snprintf(want + len, sizeof want - (size_t)len, "%s%lld", k ? " " : "",
                      (long long)x[k]);
    }
    want[len++] = '\n';
    char *e = tr_io_fmt_ints(got, x, n);
    EXPECT(e - got == len && !memcmp(got, want, (size_t)len), "ints line '%.*s' for '%.*s'",
           (int)(e - got), got, len, want);
  }
  char line[TR_IO_XYZ_MAX + 32];
  for (int r = 0; r < 100000; r++) {
    double x[3];
    for (int k = 0; k < 3; k++) {
      uint64_t u = lcg() << 11 ^ lcg();
      memcpy(&x[k], &u, 8);
      if (!isfinite(x[k]) || r % 3 == 0)
        x[k] = (unit() - 0.5) * pow(10, (double)(lcg() % 40) - 20);
    }
    int64_t lead = r % 2 ? (int64_t)(lcg() % 100000000) : -1;
    const char *tail = r % 4 == 1 ? " 0\n" : "\n";
    char *e = tr_io_fmt_xyz(line, lead, x, tail);
    int len = lead >= 0 ? snprintf(want, sizeof want, "%lld ", (long long)lead) : 0;
    len += snprintf(want + len, sizeof want - (size_t)len, "%.17g %.17g %.17g%s", x[0], x[1],
                    x[2], tail);
    EXPECT(e - line == len && !memcmp(line, want, (size_t)len), "xyz line '%.*s' for '%s'",
           (int)(e - line), line, want);
    EXPECT(e - line <= TR_IO_XYZ_MAX, "xyz line of %td bytes, over TR_IO_XYZ_MAX",
           e - line);
  }
}

/* ---- the writers on several threads ---- */

/* The Delaunay mesh of 20,000 points: about 130k tets, 32 blocks of tets and 5 of
 * vertices, so every thread count splits them differently. */
static tr_mesh *big_mesh(void)
{
  enum { N = 20000 };
  double *xyz = malloc(sizeof *xyz * 3 * N);
  for (int i = 0; i < 3 * N; i++)
    xyz[i] = unit();
  tr_mesh *m = NULL;
  tr_status s = tr_delaunay_build_threads(xyz, N, 1, &m);
  EXPECT(s == TR_OK, "Delaunay of %d points: %s", N, tr_last_error());
  free(xyz);
  if (m)
    EXPECT(tr_mesh_num_tets(m) > 5 * TR_IO_BLOCK && m->nv > 4 * TR_IO_BLOCK,
           "%u tets, %u vertices: too few to split into blocks", tr_mesh_num_tets(m), m->nv);
  return m;
}

static const struct {
  const char *name, *ext;
  int flags;
} formats[] = {{"medit", "mesh", 41},     {"vtu", "vtu", 41},
               {"vtu_binary", "vtu", 41 | TR_WRITE_BINARY},
               {"vtk", "vtk", 41},        {"vtk_binary", "vtk", 41 | TR_WRITE_BINARY},
               {"msh41", "msh", 41},      {"msh41_binary", "msh", 41 | TR_WRITE_BINARY},
               {"msh22", "msh", 22},      {"msh22_binary", "msh", 22 | TR_WRITE_BINARY},
               {"meshb", "meshb", 41},    {"tetgen", "node", 41}};

/* The files of one write: one, or TetGen's three. */
static int files_of(const char *ext, const char *base, char out[3][1100])
{
  if (strcmp(ext, "node")) {
    snprintf(out[0], 1100, "%.1000s.%s", base, ext);
    return 1;
  }
  static const char *tg[3] = {"node", "ele", "face"};
  for (int i = 0; i < 3; i++)
    snprintf(out[i], 1100, "%.1000s.%s", base, tg[i]);
  return 3;
}

/* Writes with 1, 2 and 3 threads (write(path, threads)) and compares every file. */
static void same_for_threads(const char *what, const char *ext,
                             tr_status (*write)(const void *, const char *, int, int),
                             const void *obj, int flags)
{
  char f[3][3][1100];
  int nf = 0;
  for (int th = 1; th <= 3; th++) {
    char base[1024];
    snprintf(base, sizeof base, "%.900s/blocks_%.60s_%d", tmp, what, th);
    nf = files_of(ext, base, f[th - 1]);
    char path[1100];
    snprintf(path, sizeof path, "%.1000s.%s", base, ext);
    tr_status s = write(obj, path, flags, th);
    EXPECT(s == TR_OK, "%s on %d threads: %s", what, th, tr_last_error());
  }
  for (int i = 0; i < nf; i++) {
    EXPECT(same_file(f[0][i], f[1][i]), "%s: %s and %s differ", what, f[0][i], f[1][i]);
    EXPECT(same_file(f[0][i], f[2][i]), "%s: %s and %s differ", what, f[0][i], f[2][i]);
    for (int th = 0; th < 3; th++)
      remove(f[th][i]);
  }
}

static tr_status write_mesh(const void *m, const char *path, int flags, int threads)
{
  return tr_mesh_write_threads(m, path, 0, flags, threads);
}

static void t_writer(const char *fmt)
{
  for (size_t i = 0; i < sizeof formats / sizeof *formats; i++)
    if (!strcmp(fmt, formats[i].name)) {
      tr_mesh *m = big_mesh();
      if (m)
        same_for_threads(fmt, formats[i].ext, write_mesh, m, formats[i].flags);
      tr_mesh_destroy(m);
      return;
    }
  EXPECT(0, "no format %s", fmt);
}

/* ---- .msh elements grouped by value, against printf ---- */

static tr_status write_view(const void *v, const char *path, int flags, int threads)
{
  struct tr_mesh_view w = *(const struct tr_mesh_view *)v;
  w.threads = threads;
  return tr_write_mesh_view_as(&w, path, 0, flags);
}

static int cmp_i32(const void *a, const void *b)
{
  int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
  return (x > y) - (x < y);
}

/* The .msh 2.2 text of v as the writer wrote it before the block writers: printf, the
 * elements of each dimension grouped by increasing value (tets without regions: 1), in
 * index order within a value. */
static void msh22_reference(const struct tr_mesh_view *v, const char *path)
{
  FILE *f = fopen(path, "w");
  fprintf(f, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%u\n", v->nverts);
  for (uint32_t i = 0; i < v->nverts; i++)
    fprintf(f, "%u %.17g %.17g %.17g\n", i + 1, v->xyz[3 * i], v->xyz[3 * i + 1],
            v->xyz[3 * i + 2]);
  fprintf(f, "$EndNodes\n$Elements\n%llu\n", (unsigned long long)v->ntris + v->ntets);
  unsigned long long tag = 1;
  for (int dim = 2; dim <= 3; dim++) {
    uint32_t n = dim == 2 ? v->ntris : v->ntets, per = (uint32_t)dim + 1;
    const int32_t *val = dim == 2 ? v->tri_marker : v->region;
    const uint32_t *cv = dim == 2 ? v->tris : v->tets;
    int32_t *vals = malloc(sizeof *vals * (n ? n : 1));
    uint32_t nval = 0;
    for (uint32_t i = 0; i < n; i++)
      vals[i] = val ? val[i] : dim == 3;
    qsort(vals, n, sizeof *vals, cmp_i32);
    for (uint32_t i = 0; i < n; i++)
      if (i == 0 || vals[i] != vals[nval - 1])
        vals[nval++] = vals[i];
    for (uint32_t e = 0; e < nval; e++)
      for (uint32_t i = 0; i < n; i++) {
        if ((val ? val[i] : dim == 3) != vals[e])
          continue;
        fprintf(f, "%llu %d 2 %d %u", tag++, dim == 2 ? 2 : 4, (int)vals[e], e + 1);
        for (uint32_t k = 0; k < per; k++)
          fprintf(f, " %u", cv[per * i + k] + 1);
        fprintf(f, "\n");
      }
    free(vals);
  }
  fprintf(f, "$EndElements\n");
  fclose(f);
}

static void t_msh_groups(void)
{
  tr_mesh *m = big_mesh();
  if (!m)
    return;
  uint32_t nt = tr_mesh_num_tets(m), nf = 3000;
  int32_t *reg = malloc(sizeof *reg * nt), *mark = malloc(sizeof *mark * nf);
  uint32_t *tris = malloc(sizeof *tris * 3 * nf);
  for (uint32_t f = 0; f < nf; f++) {
    mark[f] = (int32_t)(lcg() % 7) - 2; /* 0 (no marker) and negative ones too */
    for (int k = 0; k < 3; k++)
      tris[3 * f + k] = (uint32_t)(lcg() % m->nv);
  }
  /* unsorted regions (an order array), then regions in tet order (none), then none */
  for (int layout = 0; layout < 3; layout++) {
    for (uint32_t t = 0; t < nt; t++)
      reg[t] = layout == 0 ? (int32_t)(lcg() % 5) + 1 : (int32_t)(t / 9000) + 1;
    struct tr_mesh_view v = {m->nv, m->xyz, NULL, nt, tr_mesh_tets(m),
                             layout == 2 ? NULL : reg, nf, tris, mark, 1};
    char what[64];
    snprintf(what, sizeof what, "groups%d_msh22", layout);
    const char *ref = tpath(tmp, "blocks_groups_reference.msh");
    msh22_reference(&v, ref);
    for (int th = 1; th <= 3; th++) {
      const char *path = tpath(tmp, "blocks_groups.msh");
      tr_status s = write_view(&v, path, 22, th);
      EXPECT(s == TR_OK && same_file(path, ref), "layout %d, %d threads: .msh 2.2 differs "
             "from the printf reference (%s)", layout, th, tr_last_error());
      remove(path);
    }
    remove(ref);
    static const int variants[3] = {41, 41 | TR_WRITE_BINARY, 22 | TR_WRITE_BINARY};
    for (int k = 0; k < 3; k++) {
      snprintf(what, sizeof what, "groups%d_%d", layout, variants[k]);
      same_for_threads(what, "msh", write_view, &v, variants[k]);
    }
  }
  free(reg);
  free(mark);
  free(tris);
  tr_mesh_destroy(m);
}

/* ---- parallel reading of a .node file ---- */

/* A .node text of n points (over the 4 MB from which the reading goes parallel) in one of
 * the layouts of the cases below. */
static char *node_text(const char *kind, int n, size_t *len)
{
  size_t cap = (size_t)n * 128 + 4096;
  char *b = malloc(cap), *p = b;
  int zero = !strcmp(kind, "zero_based_attributes_markers");
  int declared = !strcmp(kind, "more_declared_than_given") ? n + 1
                 : !strcmp(kind, "fewer_declared_than_given") ? n - 1 : n;
  p += sprintf(p, "# a .node file\n%d 3 %d %d\n", declared, zero ? 2 : 0, zero);
  for (int i = 0; i < n; i++) {
    double x[3] = {unit(), unit() * 1e-7, (unit() - 0.5) * 3e5};
    int id = i + (zero ? 0 : 1);
    if (!strcmp(kind, "id_out_of_sequence") && i == n * 3 / 5)
      id += 2;
    if (!strcmp(kind, "comments_blank_lines_crlf") && i % 9000 == 4500)
      p += sprintf(p, "\n  # a comment line\r\n\t\n");
    if (!strcmp(kind, "point_split_over_lines") && i == n / 2) {
      p += sprintf(p, "%d %.17g\n%.17g %.17g\n", id, x[0], x[1], x[2]);
      continue;
    }
    if (!strcmp(kind, "bad_number") && i == n * 4 / 5) {
      p += sprintf(p, "%d %.17g 0.5x %.17g\n", id, x[0], x[2]);
      continue;
    }
    if (!strcmp(kind, "rationals") && i % 1000 == 7) {
      p += sprintf(p, "%d 1/3 -22/7 %d/1024\n", id, i);
      continue;
    }
    p += sprintf(p, "%d %.17g %.17g %.17g", id, x[0], x[1], x[2]);
    if (zero)
      p += sprintf(p, " %d 0.25 %d", i % 3, i % 2);
    if (!strcmp(kind, "comments_blank_lines_crlf"))
      p += sprintf(p, i % 2 ? "\r" : "  # why not");
    *p++ = '\n';
  }
  if (!strcmp(kind, "comments_blank_lines_crlf"))
    p += sprintf(p, "# Generated by tetgen -p\n");
  if (!strcmp(kind, "trailing_text"))
    p += sprintf(p, "end of the points\n");
  *len = (size_t)(p - b);
  return b;
}

static void t_node_parallel(const char *kind)
{
  enum { N = 70000 };
  size_t len;
  lcg_state = 7;
  char *text = node_text(kind, N, &len);
  EXPECT(len > ((size_t)4 << 20), "%s: %zu bytes: below the parallel reading's threshold",
         kind, len);
  struct tr_plc serial = {0};
  tr_status s1 = tr_read_tetgen_buf_threads(TR_TETGEN_NODE, text, len, "p.node", NULL, 0, NULL,
                                            &serial, 1);
  char msg1[1024];
  snprintf(msg1, sizeof msg1, "%s", tr_last_error());
  for (int th = 2; th <= 8; th *= 2) {
    struct tr_plc par = {0};
    tr_status s = tr_read_tetgen_buf_threads(TR_TETGEN_NODE, text, len, "p.node", NULL, 0, NULL,
                                             &par, th);
    EXPECT(s == s1 && !strcmp(tr_last_error(), msg1),
           "%s, %d threads: %s '%s', serially %s '%s'", kind, th, tr_status_name(s),
           tr_last_error(), tr_status_name(s1), msg1);
    EXPECT(par.npoints == serial.npoints &&
               (!par.npoints ||
                !memcmp(par.xyz, serial.xyz, sizeof *par.xyz * 3 * par.npoints)),
           "%s, %d threads: %u points, serially %u, or other doubles", kind, th, par.npoints,
           serial.npoints);
    tr_plc_clear(&par);
  }
  int ok = !strcmp(kind, "plain") || !strcmp(kind, "zero_based_attributes_markers") ||
           !strcmp(kind, "comments_blank_lines_crlf") || !strcmp(kind, "point_split_over_lines") ||
           !strcmp(kind, "rationals") || !strcmp(kind, "fewer_declared_than_given") ||
           !strcmp(kind, "trailing_text");
  EXPECT((s1 == TR_OK) == ok, "%s: the serial reading gives %s (%s)", kind, tr_status_name(s1),
         msg1);
  tr_plc_clear(&serial);
  free(text);
}

/* ---- .msh node tags found by offset ---- */

/* A .msh 2.2 of the unit tet's four corners under the given tags (file order), its tet
 * and one triangle given by tags: the read tet and triangle must name the corners those
 * tags were given to, whether the tags are in order from 1, in order from another first
 * tag (found by offset), contiguous but shuffled, or sparse (found by search). */
static void t_msh_node_tags(void)
{
  static const uint64_t tags[4][4] = {{1, 2, 3, 4}, {7, 8, 9, 10}, {3, 1, 4, 2}, {5, 90, 6, 13}};
  static const double corner[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int c = 0; c < 4; c++) {
    char text[1024];
    int n = sprintf(text, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n");
    for (int i = 0; i < 4; i++)
      n += sprintf(text + n, "%llu %g %g %g\n", (unsigned long long)tags[c][i], corner[i][0],
                   corner[i][1], corner[i][2]);
    /* the tet lists corners 0 1 2 3 by their tags; the triangle corners 0 2 1 */
    n += sprintf(text + n, "$EndNodes\n$Elements\n2\n1 2 2 5 1 %llu %llu %llu\n"
                 "2 4 2 1 1 %llu %llu %llu %llu\n$EndElements\n",
                 (unsigned long long)tags[c][0], (unsigned long long)tags[c][2],
                 (unsigned long long)tags[c][1], (unsigned long long)tags[c][0],
                 (unsigned long long)tags[c][1], (unsigned long long)tags[c][2],
                 (unsigned long long)tags[c][3]);
    struct tr_plc p = {0};
    tr_status s = tr_read_msh_buf(text, (size_t)n, "tags.msh", &p);
    EXPECT(s == TR_OK && p.npoints == 4 && p.ntets == 1 && p.ntris == 1,
           "case %d: %s, %u points %u tets %u triangles", c, tr_last_error(), p.npoints,
           p.ntets, p.ntris);
    if (s == TR_OK && p.ntets == 1 && p.ntris == 1) {
      const uint32_t want_tet[4] = {0, 1, 2, 3}, want_tri[3] = {0, 2, 1};
      for (int k = 0; k < 4; k++)
        EXPECT(!memcmp(p.xyz + 3 * p.tets[k], corner[want_tet[k]], sizeof corner[0]),
               "case %d: tet corner %d is point %u", c, k, p.tets[k]);
      for (int k = 0; k < 3; k++)
        EXPECT(!memcmp(p.xyz + 3 * p.tris[k], corner[want_tri[k]], sizeof corner[0]),
               "case %d: triangle corner %d is point %u", c, k, p.tris[k]);
      EXPECT(p.tri_marker && p.tri_marker[0] == 5, "case %d: marker lost", c);
    }
    tr_plc_clear(&p);
  }
  /* a tag one past the last of tags in order is no node */
  char text[1024];
  int n = sprintf(text, "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n");
  for (int i = 0; i < 4; i++)
    n += sprintf(text + n, "%d %g %g %g\n", 7 + i, corner[i][0], corner[i][1], corner[i][2]);
  n += sprintf(text + n, "$EndNodes\n$Elements\n1\n1 4 2 1 1 7 8 9 11\n$EndElements\n");
  struct tr_plc p = {0};
  tr_status s = tr_read_msh_buf(text, (size_t)n, "tags.msh", &p);
  EXPECT(s == TR_ERR_INPUT && strstr(tr_last_error(), "node tag 11 is not defined"),
         "tag past the last: %s '%s'", tr_status_name(s), tr_last_error());
  tr_plc_clear(&p);
}

int main(int argc, char **argv)
{
  if (argc < 3) {
    fprintf(stderr, "usage: test_blocks CASE TMPDIR\n");
    return 2;
  }
  tmp = argv[2];
  const char *c = argv[1];
  if (!strcmp(c, "blocks_order"))
    t_blocks_order();
  else if (!strcmp(c, "fmt_lines"))
    t_fmt_lines();
  else if (!strcmp(c, "msh_groups"))
    t_msh_groups();
  else if (!strcmp(c, "msh_node_tags"))
    t_msh_node_tags();
  else if (!strncmp(c, "writer_", 7))
    t_writer(c + 7);
  else if (!strncmp(c, "node_", 5))
    t_node_parallel(c + 5);
  else {
    fprintf(stderr, "unknown case %s\n", c);
    return 2;
  }
  if (failures)
    fprintf(stderr, "%s: %d check(s) failed\n", c, failures);
  else
    printf("%s: ok\n", c);
  return failures ? 1 : 0;
}
