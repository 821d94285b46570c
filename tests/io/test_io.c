/* I/O and validation tests. Each subcommand checks one property named by its meson test;
 * a failure prints what differed. Usage: test_io SUBTEST DATADIR TMPDIR */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/edgesort.h"
#include "core/plc.h"
#include "input/validate.h"
#include "io/io.h"
#include "io/lex.h"
#include "io/soup.h"
#include "qpoint.h"
#include "tetrec.h"
#include "tpath.h"
#include "../pipeline/texpect.h"

static const char *data, *tmp;

static struct tr_plc *read_ok(const char *file)
{
  struct tr_plc *p = calloc(1, sizeof *p);
  tr_status s = tr_io_read_file(file, p);
  EXPECT(s == TR_OK, "reading %s: %s (%s)", file, tr_status_name(s), tr_last_error());
  return p;
}

static void destroy(struct tr_plc *p) { tr_plc_destroy(p); }

static const double tet_xyz[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
static const uint32_t tet_tris[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

static void expect_tet(const struct tr_plc *p, const char *what)
{
  EXPECT(p->npoints == 4 && p->ntris == 4, "%s: %u points %u triangles (4, 4 expected)", what,
         p->npoints, p->ntris);
  if (p->npoints == 4)
    EXPECT(memcmp(p->xyz, tet_xyz, sizeof tet_xyz) == 0, "%s: coordinates differ", what);
  if (p->ntris == 4)
    EXPECT(memcmp(p->tris, tet_tris, sizeof tet_tris) == 0, "%s: triangles differ", what);
}

/* Twice the signed area of triangle t projected on z (exact for small integers). */
static double area2z(const struct tr_plc *p, uint32_t t)
{
  const double *a = p->xyz + 3 * p->tris[3 * t], *b = p->xyz + 3 * p->tris[3 * t + 1],
               *c = p->xyz + 3 * p->tris[3 * t + 2];
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

static void t_off_variants(void)
{
  const char *f[] = {"tet.off", "variant_coff.off", "variant_noff.off"};
  for (int i = 0; i < 3; i++) {
    struct tr_plc *p = read_ok(tpath(data, f[i]));
    expect_tet(p, f[i]);
    destroy(p);
  }
}

static void t_off_polygons(void)
{
  struct tr_plc *p = read_ok(tpath(data, "lshape.off"));
  EXPECT(p->ntris == 5, "L-shaped 7-gon gives %u triangles (5 expected)", p->ntris);
  double sum = 0;
  for (uint32_t t = 0; t < p->ntris; t++) {
    double a = area2z(p, t);
    EXPECT(a > 0, "triangle %u has area2 %g: not positive (orientation lost or degenerate)", t, a);
    sum += a;
    EXPECT(p->tri_source[t] == 0, "triangle %u comes from face %u", t, p->tri_source[t]);
  }
  EXPECT(sum == 12, "triangles cover twice-area %g (12 expected)", sum);
  destroy(p);
  p = calloc(1, sizeof *p);
  tr_status s = tr_io_read_file(tpath(data, "../../examples/data/cube.off"), p);
  EXPECT(s == TR_OK && p->ntris == 12, "cube of 6 quads: %s, %u triangles", tr_last_error(),
         p->ntris);
  if (s == TR_OK) {
    s = tr_plc_validate(p, NULL);
    EXPECT(s == TR_OK && strcmp(tr_plc_report(p), "") == 0,
           "triangulated cube must be valid without repair: %s / %s", tr_last_error(),
           tr_plc_report(p));
  }
  destroy(p);
}

static void t_stl(void)
{
  struct tr_plc *p = read_ok(tpath(data, "tet_ascii.stl"));
  /* First-occurrence order: (0,0,0) (0,1,0) (1,0,0) (0,0,1); -0 merged with 0. */
  static const double xyz[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1};
  static const uint32_t tris[12] = {0, 1, 2, 0, 2, 3, 0, 3, 1, 2, 1, 3};
  EXPECT(p->npoints == 4 && p->ntris == 4, "ascii STL: %u points %u triangles", p->npoints,
         p->ntris);
  if (p->npoints == 4 && p->ntris == 4) {
    EXPECT(memcmp(p->xyz, xyz, sizeof xyz) == 0, "ascii STL: merged points differ");
    EXPECT(memcmp(p->tris, tris, sizeof tris) == 0, "ascii STL: triangles differ");
    EXPECT(!signbit(p->xyz[0]), "-0.0 must be stored as the merged +0.0");
  }
  destroy(p);
  /* Binary, header starting with "solid": decided by the size 84 + 50 n. */
  unsigned char b[84 + 2 * 50];
  memset(b, 0, sizeof b);
  memcpy(b, "solid but binary", 16);
  b[80] = 2;
  float v[2][9] = {{0, 0, 0, 0, 1, 0, 1, 0, 0}, {-0.0f, 0, 0, 1, 0, 0, 0.1f, 0, 1}};
  for (int t = 0; t < 2; t++)
    memcpy(b + 84 + 50 * t + 12, v[t], 36); /* little-endian host assumed by the test */
  p = calloc(1, sizeof *p);
  tr_status s = tr_read_stl_buf((const char *)b, sizeof b, "mem.stl", p);
  EXPECT(s == TR_OK, "binary STL: %s", tr_last_error());
  EXPECT(p->npoints == 4 && p->ntris == 2, "binary STL: %u points %u triangles (4, 2)",
         p->npoints, p->ntris);
  if (p->npoints == 4) {
    EXPECT(p->tris[3] == 0 && p->tris[4] == 2, "binary STL: -0.0 and 1,0,0 must merge");
    EXPECT(p->xyz[9] == (double)0.1f, "float 0.1f must widen exactly: %.17g", p->xyz[9]);
  }
  destroy(p);
}

/* STL vertex merging groups equal points by a hash and resolves a group exactly; a
 * group of more than 32 occurrences (a vertex of many triangles) is sorted instead. Both
 * ways must give the first-occurrence numbering: a closed fan of 48 triangles around a
 * centre written as (0,0,0) and (-0,0,-0) on alternate triangles, rim points shared by
 * neighbours, and an apex above closing nothing (a soup is all the reader sees). */
static void t_stl_fan(void)
{
  enum { N = 48 };
  unsigned char b[84 + N * 50];
  memset(b, 0, sizeof b);
  b[80] = N;
  for (int t = 0; t < N; t++) {
    float c0 = t % 2 ? -0.0f : 0.0f;
    float v[9] = {c0, 0, c0, (float)(t + 1), 1, 0, (float)(t + 2), 1, 0};
    memcpy(b + 84 + 50 * t + 12, v, 36); /* little-endian host assumed by the test */
  }
  struct tr_plc *p = calloc(1, sizeof *p);
  tr_status s = tr_read_stl_buf((const char *)b, sizeof b, "fan.stl", p);
  EXPECT(s == TR_OK, "fan STL: %s", tr_last_error());
  /* the centre, then rim points 1 .. N+1 in order of first occurrence */
  EXPECT(p->npoints == N + 2 && p->ntris == N, "fan STL: %u points %u triangles (%d, %d)",
         p->npoints, p->ntris, N + 2, N);
  if (p->npoints == N + 2 && p->ntris == N) {
    int ok = 1;
    for (int t = 0; t < N; t++)
      ok &= p->tris[3 * t] == 0 && p->tris[3 * t + 1] == (uint32_t)t + 1 &&
            p->tris[3 * t + 2] == (uint32_t)t + 2;
    EXPECT(ok, "fan STL: every triangle must be (centre, rim t+1, rim t+2)");
    for (int i = 1; i <= N + 1; i++)
      ok &= p->xyz[3 * i] == i && p->xyz[3 * i + 1] == 1;
    EXPECT(ok, "fan STL: rim points in order of first occurrence");
    EXPECT(!signbit(p->xyz[0]) && !signbit(p->xyz[2]), "fan STL: centre stored as +0.0");
  }
  destroy(p);
}

static void t_obj(void)
{
  struct tr_plc *p = read_ok(tpath(data, "forms.obj"));
  EXPECT(p->npoints == 8 && p->ntris == 12, "OBJ: %u points %u triangles (8, 12)", p->npoints,
         p->ntris);
  for (uint32_t t = 0; t < p->ntris; t++)
    if (p->tri_source[t] == 4)
      for (int k = 0; k < 3; k++) {
        uint32_t v = p->tris[3 * t + k];
        EXPECT(v == 2 || v == 3 || v == 6 || v == 7,
               "negative indices -5 -1 -2 -6 must be vertices 3 7 6 2, got %u", v);
      }
  tr_status s = tr_plc_validate(p, NULL);
  EXPECT(s == TR_OK && !*tr_plc_report(p), "OBJ cube valid without repair: %s %s",
         tr_last_error(), tr_plc_report(p));
  destroy(p);
}

static size_t put(unsigned char *b, size_t at, const void *x, int n, int big)
{
  for (int i = 0; i < n; i++)
    b[at + i] = ((const unsigned char *)x)[big ? n - 1 - i : i];
  return at + n;
}

static void t_ply(void)
{
  struct tr_plc *p = read_ok(tpath(data, "tet_ascii.ply"));
  expect_tet(p, "ascii PLY");
  destroy(p);
  for (int big = 0; big < 2; big++) {
    unsigned char b[1024];
    int h = snprintf((char *)b, sizeof b,
                     "ply\nformat %s 1.0\ncomment binary test\nelement vertex 4\n"
                     "property double x\nproperty float y\nproperty int z\nproperty uchar c\n"
                     "element face 4\nproperty list uchar uint vertex_indices\n"
                     "property short s\nend_header\n",
                     big ? "binary_big_endian" : "binary_little_endian");
    size_t at = (size_t)h;
    for (int i = 0; i < 4; i++) {
      double x = tet_xyz[3 * i];
      float y = (float)tet_xyz[3 * i + 1];
      int32_t z = (int32_t)tet_xyz[3 * i + 2];
      unsigned char c = 200;
      at = put(b, at, &x, 8, big);
      at = put(b, at, &y, 4, big);
      at = put(b, at, &z, 4, big);
      at = put(b, at, &c, 1, big);
    }
    for (int f = 0; f < 4; f++) {
      unsigned char n = 3;
      int16_t s = -1;
      at = put(b, at, &n, 1, big);
      for (int k = 0; k < 3; k++)
        at = put(b, at, &tet_tris[3 * f + k], 4, big);
      at = put(b, at, &s, 2, big);
    }
    p = calloc(1, sizeof *p);
    tr_status s = tr_read_ply_buf((const char *)b, at, big ? "be.ply" : "le.ply", p);
    EXPECT(s == TR_OK, "binary PLY (%s): %s", big ? "big" : "little", tr_last_error());
    expect_tet(p, big ? "binary big-endian PLY" : "binary little-endian PLY");
    destroy(p);
    /* Truncated: one byte short. */
    p = calloc(1, sizeof *p);
    s = tr_read_ply_buf((const char *)b, at - 1, "short.ply", p);
    EXPECT(s == TR_ERR_PARSE && strstr(tr_last_error(), "unexpected end of file"),
           "truncated binary PLY: %s %s", tr_status_name(s), tr_last_error());
    destroy(p);
  }
}

static void t_medit(void)
{
  struct tr_plc *p = read_ok(tpath(data, "tet.mesh"));
  EXPECT(p->npoints == 4 && p->ntris == 4 && p->ntets == 1, "Medit: %u %u %u", p->npoints,
         p->ntris, p->ntets);
  if (p->ntris == 4) {
    EXPECT(memcmp(p->tris, tet_tris, sizeof tet_tris) == 0, "Medit triangles (1-based) differ");
    for (int t = 0; t < 4; t++)
      EXPECT(p->tri_marker[t] == 10 + t, "marker %d of triangle %d", p->tri_marker[t], t);
  }
  if (p->ntets == 1)
    EXPECT(p->tets[0] == 0 && p->tets[3] == 3, "tet vertices %u..%u", p->tets[0], p->tets[3]);
  destroy(p);
}

static void t_tetgen(void)
{
  struct tr_plc *p = read_ok(tpath(data, "tet.node"));
  EXPECT(p->npoints == 4 && p->ntris == 0, ".node: %u points", p->npoints);
  if (p->npoints == 4)
    EXPECT(p->xyz[11] == 1.0 / 3.0, "1/3 must read as the nearest double, got %.17g",
           p->xyz[11]);
  destroy(p);
  p = read_ok(tpath(data, "tet.smesh"));
  expect_tet(p, ".smesh");
  for (uint32_t t = 0; t < p->ntris; t++)
    EXPECT(p->tri_marker[t] == 5 + (int)t, ".smesh marker %d", p->tri_marker[t]);
  destroy(p);
  p = read_ok(tpath(data, "cube_facets.poly"));
  EXPECT(p->npoints == 8 && p->ntris == 12, ".poly with .node: %u points %u triangles",
         p->npoints, p->ntris);
  EXPECT(p->ntris == 12 && p->tri_marker[11] == 6, ".poly facet markers");
  destroy(p);
  p = read_ok(tpath(data, "frame.poly"));
  EXPECT(p->ntris == 8, "square with a square hole: %u triangles (8 expected)", p->ntris);
  double sum = 0;
  for (uint32_t t = 0; t < p->ntris; t++) {
    double a = area2z(p, t);
    EXPECT(a > 0, "frame triangle %u has area2 %g", t, a);
    sum += a;
    double cx = 0, cy = 0;
    for (int k = 0; k < 3; k++) {
      cx += p->xyz[3 * p->tris[3 * t + k]];
      cy += p->xyz[3 * p->tris[3 * t + k] + 1];
    }
    EXPECT(!(cx > 3 && cx < 9 && cy > 3 && cy < 9), "triangle %u lies in the hole", t);
    EXPECT(p->tri_marker[t] == 3, "frame marker %d", p->tri_marker[t]);
  }
  EXPECT(sum == 24, "frame twice-area %g (24 expected)", sum);
  destroy(p);
}

/* Awkward doubles survive every writer + reader exactly. */
static void t_roundtrip(void)
{
  double xyz[12] = {0.1, -0.0, 1e-300, 1.0 / 3, 2.5e300, -7.25, 0x1.fffffffffffffp-1, 5e-324,
                    123456789.123456789, -1.0 / 7, 3, 4};
  uint32_t tris[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  int32_t mark[4] = {1, -2, 3, 40};
  tr_plc *p;
  EXPECT(tr_plc_create(&p) == TR_OK, "create");
  EXPECT(tr_plc_set(p, xyz, 4, tris, 4, mark) == TR_OK, "set: %s", tr_last_error());
  const char *outs[] = {"rt.mesh", "rt.off", "rt.node"};
  for (int i = 0; i < 3; i++) {
    tr_status s = tr_plc_write(p, tpath(tmp, outs[i]));
    EXPECT(s == TR_OK, "writing %s: %s", outs[i], tr_last_error());
    struct tr_plc *q = read_ok(tpath(tmp, outs[i]));
    EXPECT(q->npoints == 4 && memcmp(q->xyz, xyz, sizeof xyz) == 0,
           "%s: coordinates not bitwise equal after the round trip", outs[i]);
    if (i < 2)
      EXPECT(q->ntris == 4 && memcmp(q->tris, tris, sizeof tris) == 0, "%s: triangles differ",
             outs[i]);
    if (i == 0)
      EXPECT(q->ntris == 4 && memcmp(q->tri_marker, mark, sizeof mark) == 0,
             "%s: markers differ", outs[i]);
    destroy(q);
  }
  EXPECT(tr_plc_write(p, tpath(tmp, "rt.vtu")) == TR_OK, "vtu: %s", tr_last_error());
  char *buf;
  size_t len;
  if (tr_io_load(tpath(tmp, "rt.vtu"), &buf, &len) == TR_OK) {
    EXPECT(strstr(buf, "NumberOfPoints=\"4\" NumberOfCells=\"4\"") != NULL, "vtu counts");
    EXPECT(strstr(buf, "Name=\"region\"") != NULL, "vtu region data");
    EXPECT(strstr(buf, "0.33333333333333331") != NULL, "vtu %%.17g coordinates");
    free(buf);
  } else
    EXPECT(0, "vtu not readable");
  tr_plc_destroy(p);
}

/* A Delaunay mesh written in every format reads back with the same tets; --exact
 * rationals read back as the nearest doubles. */
static void t_mesh_write(void)
{
  static const double cube[24] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                  0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  tr_mesh *m = NULL;
  tr_status s = tr_delaunay(cube, 8, &m);
  EXPECT(s == TR_OK, "delaunay: %s", tr_last_error());
  if (s != TR_OK)
    return;
  uint32_t nt = tr_mesh_num_tets(m);
  EXPECT(tr_mesh_write(m, tpath(tmp, "dm.mesh"), 0) == TR_OK, "%s", tr_last_error());
  EXPECT(tr_mesh_write(m, tpath(tmp, "dm.1"), 0) == TR_OK, "%s", tr_last_error());
  EXPECT(tr_mesh_write(m, tpath(tmp, "dm.vtu"), 0) == TR_OK, "%s", tr_last_error());
  struct tr_plc *q = read_ok(tpath(tmp, "dm.mesh"));
  EXPECT(q->ntets == nt && q->npoints == 8, ".mesh: %u tets (%u expected)", q->ntets, nt);
  EXPECT(q->ntris == 12, "hull of the cube: %u boundary triangles (12 expected)", q->ntris);
  destroy(q);
  q = read_ok(tpath(tmp, "dm.1.ele"));
  EXPECT(q->ntets == nt && q->npoints == 8, ".ele: %u tets (%u expected)", q->ntets, nt);
  destroy(q);
  tr_mesh_destroy(m);
  /* exact rationals */
  tr_qpoint qp;
  tr_qpoint_init(&qp);
  mpq_set_si(qp.c[0], 1, 3);
  mpq_set_si(qp.c[1], 2, 7);
  mpq_set_si(qp.c[2], -5, 11);
  tr_qpoint_update(&qp);
  const tr_qpoint *ex[4] = {NULL, &qp, NULL, NULL};
  double xyz[12] = {0, 0, 0, qp.near[0], qp.near[1], qp.near[2], 0, 1, 0, 0, 0, 1};
  uint32_t tet[4] = {0, 1, 2, 3};
  struct tr_mesh_view v = {4, xyz, ex, 1, tet, NULL, 0, NULL, NULL, 1};
  EXPECT(tr_write_tetgen(&v, tpath(tmp, "ex"), 1) == TR_OK, "%s", tr_last_error());
  char *buf;
  size_t len;
  if (tr_io_load(tpath(tmp, "ex.node"), &buf, &len) == TR_OK) {
    EXPECT(strstr(buf, "2 1/3 2/7 -5/11\n") != NULL, "exact .node line missing:\n%s", buf);
    free(buf);
  }
  q = read_ok(tpath(tmp, "ex.node"));
  EXPECT(q->npoints == 4 && q->xyz[3] == 1.0 / 3 && q->xyz[4] == 2.0 / 7 &&
             q->xyz[5] == -5.0 / 11,
         "rationals must read as the nearest doubles");
  destroy(q);
  tr_qpoint_clear(&qp);
}

static tr_status parse_status(const char *s)
{
  for (int i = 0; i <= 11; i++)
    if (!strcmp(s, tr_status_name((tr_status)i)))
      return (tr_status)i;
  return (tr_status)-1;
}

/* Every malformed input gives its status and its message (library side; the CLI side
 * is checked by cli_errors.py from the same table). */
static void t_malformed(void)
{
  char *tab;
  size_t len;
  if (tr_io_load(tpath(data, "../io/malformed.txt"), &tab, &len) != TR_OK) {
    EXPECT(0, "cannot read malformed.txt");
    return;
  }
  int n = 0;
  for (char *line = strtok(tab, "\n"); line; line = strtok(NULL, "\n")) {
    if (line[0] == '#')
      continue;
    char *f = line, *st = strchr(f, '|'), *code, *msg, *end;
    if (!st || !(code = strchr(st + 1, '|')) || !(msg = strchr(code + 1, '|')) ||
        !(end = strchr(msg + 1, '|'))) {
      EXPECT(0, "bad table line '%s'", line);
      continue;
    }
    *st++ = *code++ = *msg++ = *end = '\0';
    *strchr(st, '\0') = '\0';
    tr_status want = parse_status(st);
    tr_plc *p = NULL;
    char full[1024];
    snprintf(full, sizeof full, "%s/bad/%s", data, f);
    tr_status s = tr_plc_read(full, &p);
    if (s == TR_OK)
      s = tr_plc_validate(p, NULL);
    const char *text = want == TR_OK ? tr_plc_report(p) : tr_last_error();
    EXPECT(s == want, "%s: status %s, expected %s (%s)", f, tr_status_name(s), st,
           tr_last_error());
    EXPECT(text && strstr(text, msg), "%s: message '%s' lacks '%s'", f, text ? text : "", msg);
    tr_plc_destroy(p);
    n++;
  }
  EXPECT(n >= 20, "only %d malformed cases", n);
  free(tab);
}

/* Orientation repair gives exactly the outward tetrahedron; duplicate vertices merge. */
static void t_repairs(void)
{
  const char *f[] = {"bad/inconsistent.off", "bad/inverted.off", "bad/dup_vertex.off",
                     "bad/dup_tri.off"};
  for (int i = 0; i < 4; i++) {
    tr_plc *p = NULL;
    tr_status s = tr_plc_read(tpath(data, f[i]), &p);
    if (s == TR_OK)
      s = tr_plc_validate(p, NULL);
    EXPECT(s == TR_OK, "%s: %s", f[i], tr_last_error());
    if (s != TR_OK) {
      tr_plc_destroy(p);
      continue;
    }
    EXPECT(p->npoints == 4 && p->ntris == 4, "%s: %u points %u triangles", f[i], p->npoints,
           p->ntris);
    /* Each repaired triangle is a cyclic rotation of the outward one. */
    for (uint32_t t = 0; t < p->ntris && p->ntris == 4; t++) {
      int found = 0;
      for (int u = 0; u < 4; u++)
        for (int r = 0; r < 3; r++)
          found |= p->tris[3 * t] == tet_tris[3 * u + r] &&
                   p->tris[3 * t + 1] == tet_tris[3 * u + (r + 1) % 3] &&
                   p->tris[3 * t + 2] == tet_tris[3 * u + (r + 2) % 3];
      EXPECT(found, "%s: triangle %u (%u %u %u) is not an outward face", f[i], t,
             p->tris[3 * t], p->tris[3 * t + 1], p->tris[3 * t + 2]);
    }
    tr_plc_destroy(p);
  }
}

/* A cavity shell faces into the cavity (out of the domain); disjoint shells face out.
 * Checked through the exact enclosed volume: 6 * (64 - 8) for the cube with a cavity. */
static void t_cavity(void)
{
  const char *f[] = {"cavity.off", "two_cubes.off"};
  const long want6[] = {6 * (64 - 8), 6 * 2};
  /* 12 flips: 10 listed, then "... and 2 more flipped triangles" (the log is capped) */
  const int flips[] = {11, 0};
  for (int i = 0; i < 2; i++) {
    tr_plc *p = NULL;
    tr_status s = tr_plc_read(tpath(data, f[i]), &p);
    if (s == TR_OK)
      s = tr_plc_validate(p, NULL);
    EXPECT(s == TR_OK, "%s: %s", f[i], tr_last_error());
    if (s != TR_OK) {
      tr_plc_destroy(p);
      continue;
    }
    mpq_t v;
    mpq_init(v);
    tr_input_volume6(p, v);
    EXPECT(mpq_cmp_si(v, want6[i], 1) == 0, "%s: 6 * volume = %s, expected %ld", f[i],
           mpq_get_str(NULL, 10, v), want6[i]);
    mpq_clear(v);
    int n = 0;
    for (const char *r = tr_plc_report(p); (r = strstr(r, "flipped")) != NULL; r++)
      n++;
    EXPECT(n == flips[i], "%s: %d triangles reported flipped, expected %d", f[i], n, flips[i]);
    if (i == 0)
      EXPECT(strstr(tr_plc_report(p), "... and 2 more flipped triangles") != NULL,
             "cavity: the capped log must count the rest: %s", tr_plc_report(p));
    tr_plc_destroy(p);
  }
}

/* Random star-shaped polygons with integer corners, on the tilted plane z = x + 2y:
 * the triangulation has n - 2 triangles, each with the polygon's orientation, and they
 * cover exactly the polygon's area (all arithmetic exact in int64). */
static void t_polygon_random(void)
{
  uint64_t seed = 12345;
  int tested = 0;
  for (int iter = 0; iter < 400; iter++) {
    int n = 3 + iter % 38;
    double xyz[3 * 40];
    uint32_t idx[40], first = 0;
    int64_t P[40][2];
    double ang[40];
    for (int i = 0; i < n; i++) {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      ang[i] = (double)(seed >> 11) / 9007199254740992.0 * 6.283185307179586;
    }
    for (int i = 1; i < n; i++) /* insertion sort of the angles */
      for (int j = i; j > 0 && ang[j] < ang[j - 1]; j--) {
        double t = ang[j];
        ang[j] = ang[j - 1];
        ang[j - 1] = t;
      }
    for (int i = 0; i < n; i++) {
      seed = seed * 6364136223846793005ull + 1442695040888963407ull;
      double r = 1 + (double)((seed >> 33) % 1000);
      P[i][0] = (int64_t)llround(r * cos(ang[i]));
      P[i][1] = (int64_t)llround(r * sin(ang[i]));
    }
    int ok = 1; /* strictly increasing angles after rounding: a simple star polygon */
    for (int i = 0; i < n; i++) {
      int64_t *a = P[i], *b = P[(i + 1) % n];
      if (a[0] * b[1] - a[1] * b[0] <= 0)
        ok = 0;
    }
    if (!ok)
      continue;
    int rev = iter & 1; /* both orientations */
    int64_t area2 = 0;
    for (int i = 0; i < n; i++) {
      int k = rev ? n - 1 - i : i;
      xyz[3 * i] = (double)P[k][0];
      xyz[3 * i + 1] = (double)P[k][1];
      xyz[3 * i + 2] = (double)(P[k][0] + 2 * P[k][1]);
      idx[i] = (uint32_t)i;
    }
    for (int i = 0; i < n; i++) {
      const double *a = xyz + 3 * i, *b = xyz + 3 * ((i + 1) % n);
      area2 += (int64_t)a[0] * (int64_t)b[1] - (int64_t)a[1] * (int64_t)b[0];
    }
    tr_u32vec out = {0};
    tr_status st = tr_triangulate_facet(xyz, idx, &first, 1, (uint32_t)n, NULL, 0, &out, "star");
    EXPECT(st == TR_OK, "star polygon %d (n=%d): %s", iter, n, tr_last_error());
    EXPECT(out.n == 3 * (uint32_t)(n - 2), "star polygon %d: %u triangles for n=%d", iter,
           out.n / 3, n);
    int64_t sum = 0;
    for (uint32_t t = 0; t + 2 < out.n; t += 3) {
      const double *a = xyz + 3 * out.a[t], *b = xyz + 3 * out.a[t + 1], *c = xyz + 3 * out.a[t + 2];
      int64_t s2 = ((int64_t)b[0] - (int64_t)a[0]) * ((int64_t)c[1] - (int64_t)a[1]) -
                   ((int64_t)b[1] - (int64_t)a[1]) * ((int64_t)c[0] - (int64_t)a[0]);
      EXPECT(s2 != 0 && (s2 > 0) == (area2 > 0), "star %d: triangle with area2 %lld", iter,
             (long long)s2);
      sum += s2;
    }
    EXPECT(sum == area2, "star %d: triangles cover %lld, polygon %lld", iter, (long long)sum,
           (long long)area2);
    tr_u32vec_free(&out);
    tested++;
  }
  EXPECT(tested > 100, "only %d star polygons survived rounding", tested);
}

/* xorshift64: the same random triangles on every machine */
static uint64_t es_rng = 0x243f6a8885a308d3ull;
static double es_unif(void)
{
  es_rng ^= es_rng << 13;
  es_rng ^= es_rng >> 7;
  es_rng ^= es_rng << 17;
  return (double)(es_rng >> 11) * 0x1p-53;
}

/* tr_edge_slots_sorted against a comparison sort of (min, max, slot). */
static int sb_cmp(const void *a, const void *b)
{
  const uint32_t *x = a, *y = b;
  for (int i = 0; i < 3; i++)
    if (x[i] != y[i])
      return x[i] < y[i] ? -1 : 1;
  return 0;
}

static void t_edge_sort(void)
{
  for (uint32_t nv = 1; nv < 40; nv += 7) {
    uint32_t nt = 3 * nv + 5, ne = 3 * nt, *T = malloc(sizeof *T * ne), *S = malloc(sizeof *S * ne),
             *R = malloc(sizeof *R * 3 * ne);
    for (uint32_t i = 0; i < ne; i++)
      T[i] = (uint32_t)(es_unif() * nv);
    EXPECT(tr_edge_slots_sorted(T, nt, nv, S) == TR_OK, "sorted");
    for (uint32_t i = 0; i < ne; i++) {
      uint32_t a = T[i], b = T[3 * (i / 3) + (i % 3 + 1) % 3];
      R[3 * i] = a < b ? a : b;
      R[3 * i + 1] = a < b ? b : a;
      R[3 * i + 2] = i;
    }
    qsort(R, ne, 3 * sizeof *R, sb_cmp);
    for (uint32_t i = 0; i < ne; i++)
      EXPECT(S[i] == R[3 * i + 2], "nv %u: position %u holds slot %u, the sort says %u", nv, i,
             S[i], R[3 * i + 2]);
    free(T);
    free(S);
    free(R);
  }
}

/* tr_io_fmt_double against the C library's %.17g, byte for byte, and strtod of its text
 * against the double: random bit patterns, random magnitudes, short decimals as models
 * have them, neighbours of powers of ten (where rounding carries into a new digit), and
 * the exponent ends of the 128-bit path and beyond. */
static uint64_t fd_rng = 0x9e3779b97f4a7c15ull;
static uint64_t fd_next(void)
{
  fd_rng ^= fd_rng << 13;
  fd_rng ^= fd_rng >> 7;
  fd_rng ^= fd_rng << 17;
  return fd_rng;
}

static void fd_check(double x)
{
  char a[40], b[40];
  int n = tr_io_fmt_double(a, x);
  snprintf(b, sizeof b, "%.17g", x);
  EXPECT(strcmp(a, b) == 0 && n == (int)strlen(b), "%a: wrote %s, %%.17g is %s", x, a, b);
  EXPECT(strtod(a, NULL) == x && signbit(strtod(a, NULL)) == signbit(x),
         "%a: %s reads back as %a", x, a, strtod(a, NULL));
}

static void t_fmt_double(void)
{
  const double fixed[] = {0.0, -0.0, 1, -1, 0.1, 0.5, 1e-5, 1e-6, 1e-7, 9.9999999999999995e-7,
                          1e16, 1e17, 123456789012345678.0, 0x1p52, 0x1p53, 0x1p-1074,
                          1.7976931348623157e308, 2.2250738585072014e-308, 100, 1234.5};
  for (size_t i = 0; i < sizeof fixed / sizeof fixed[0]; i++) {
    fd_check(fixed[i]);
    fd_check(-fixed[i]);
  }
  for (int i = 0; i < 400000; i++) {
    uint64_t r = fd_next();
    double x;
    switch (i % 4) {
    case 0:
      memcpy(&x, &r, sizeof x);
      if (!isfinite(x))
        continue;
      break;
    case 1:
      x = ldexp((double)(r >> 11), (int)(fd_next() % 90) - 113);
      break;
    case 2:
      x = (double)(int64_t)(r % 2000001 - 1000000) / pow(10, (double)(fd_next() % 12));
      break;
    default:
      x = nextafter(pow(10, (double)((int)(fd_next() % 44) - 14)), (r & 1) ? 0 : INFINITY);
      if (r & 2)
        x = -x;
    }
    fd_check(x);
  }
}

/* tr_parse_double against strtod on one token: the same verdict, the same double bit for
 * bit (sign of zero included). */
static int pd_check(const char *tok)
{
  double got = 0, want;
  char *end;
  int r = tr_parse_double(tok, strlen(tok), &got);
  want = strtod(tok, &end);
  int ok_want = *tok && *end == '\0' && isfinite(want);
  if (!ok_want) {
    EXPECT(r != 0, "'%s': strtod refuses it, tr_parse_double gives %a", tok, got);
    return r != 0;
  }
  EXPECT(r == 0 && !memcmp(&got, &want, sizeof got), "'%s': %a (status %d), strtod %a", tok,
         got, r, want);
  return r == 0 && !memcmp(&got, &want, sizeof got);
}

/* The decimal reader's fast path (an exact product or quotient by a power of ten) and its
 * hand-over to strtod: random tokens of every shape (signs, no integer or no fraction part,
 * leading zeros, 1 to 22 digits, exponents to +-40, the limits 2^53 and 10^22), and
 * malformed ones, each read as strtod reads it. */
static void t_parse_double(void)
{
  const char *fixed[] = {"0", "-0", "+0", "-0.0", "0.", ".5", "-.5", "5.", "1e22", "1e23",
                         "1e-22", "1e-23", "9007199254740992", "9007199254740993",
                         "-9007199254740993e-5", "1234567890123456789", "12345678901234567890",
                         "0.1", "0.3", "2.5e-3", "7E+2", "1e0001", "1e", "1e+", "e5", ".", "-",
                         "+", "1.2.3", "0x1p3", "inf", "nan", "1e400", "1e-400", "4.9e-324",
                         "00000000000000000001", "1,5", "1 ", "1e5x"};
  for (size_t i = 0; i < sizeof fixed / sizeof fixed[0]; i++)
    pd_check(fixed[i]);
  int bad = 0;
  for (int i = 0; i < 300000 && bad < 10; i++) {
    char tok[80];
    size_t n = 0;
    uint64_t r = fd_next();
    if (r & 1)
      tok[n++] = r & 2 ? '-' : '+';
    int id = (int)(fd_next() % 12), fd = (int)(fd_next() % 12);
    if (r & 4)
      id = (int)(fd_next() % 23);
    for (int k = 0; k < id; k++)
      tok[n++] = (char)('0' + fd_next() % 10);
    if ((r & 8) || !id)
      tok[n++] = '.';
    for (int k = 0; k < fd; k++)
      tok[n++] = (char)('0' + fd_next() % 10);
    if (r & 16)
      n += (size_t)snprintf(tok + n, sizeof tok - n, "%c%d", r & 32 ? 'e' : 'E',
                            (int)(fd_next() % 81) - 40);
    if ((r & 0x3c0) == 0x3c0) /* now and then a stray character */
      tok[fd_next() % (n + 1)] = "x.e-+ "[fd_next() % 6];
    tok[n] = '\0';
    bad += !pd_check(tok);
  }
  /* what writers print: %.17g (and 15, 16, 18 digits) of random doubles, and 19 digits
   * of the midpoints between neighbouring doubles, which round to 64 bits onto the
   * midpoint itself about one time in ten (the x87 path must hand those over) */
  for (int i = 0; i < 200000 && bad < 10; i++) {
    char tok[80];
    double x = ldexp(1 + (double)(fd_next() >> 12) * 0x1p-52, (int)(fd_next() % 100) - 50);
    if (i % 2) {
      snprintf(tok, sizeof tok, "%.*g", 15 + (int)(fd_next() % 4), x);
    } else {
      long double mid = (long double)x + (long double)(nextafter(x, INFINITY) - x) / 2;
      snprintf(tok, sizeof tok, "%.18Le", mid);
    }
    bad += !pd_check(tok);
  }
}

int main(int argc, char **argv)
{
  if (argc < 4) {
    fprintf(stderr, "usage: test_io SUBTEST DATADIR TMPDIR\n");
    return 2;
  }
  data = argv[2];
  tmp = argv[3];
  static const struct {
    const char *name;
    void (*fn)(void);
  } tests[] = {{"off_variants", t_off_variants}, {"off_polygons", t_off_polygons},
               {"stl", t_stl},                   {"stl_fan", t_stl_fan},                   {"obj", t_obj},
               {"ply", t_ply},                   {"medit", t_medit},
               {"tetgen", t_tetgen},             {"roundtrip", t_roundtrip},
               {"mesh_write", t_mesh_write},     {"malformed", t_malformed},
               {"repairs", t_repairs},           {"edge_sort", t_edge_sort},
               {"cavity", t_cavity},             {"polygon_random", t_polygon_random},
               {"fmt_double", t_fmt_double},     {"parse_double", t_parse_double}};
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
