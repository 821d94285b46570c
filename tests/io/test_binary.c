/* Binary formats of issue 48: Gmsh .msh 4.1 and 2.2 binary, Medit .meshb, VTU with raw
 * appended data, legacy VTK binary, binary STL. Written files read back bit for bit;
 * every damaged binary input (truncated, counts past the end of the file, the other byte
 * order, indices out of range) is refused with a status and a message, never a crash, and
 * never an allocation sized by the damaged count. Usage: test_binary CASE TMPDIR */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "io/io.h"
#include "tetrec.h"
#include "tpath.h"
#include "../pipeline/texpect.h"

static const char *tmp;

/* Awkward doubles (signed zero, subnormal, huge, non-terminating) and markers (0,
 * negative, large): a closed tetrahedron is not needed by the readers, only indices. */
static const double xyz[15] = {0.1, -0.0, 1e-300, 1.0 / 3, 2.5e300, -7.25,
                               0x1.fffffffffffffp-1, 5e-324, 123456789.123456789, -1.0 / 7,
                               3, 4, 1e10, -2e-5, 0.5};
static const uint32_t tris[15] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 4, 1, 2};
static const int32_t mark[5] = {1, -2, 0, 40, 2147483647};

static tr_plc *surface(void)
{
  tr_plc *p = NULL;
  EXPECT(tr_plc_create(&p) == TR_OK, "create");
  EXPECT(tr_plc_set(p, xyz, 5, tris, 5, mark) == TR_OK, "set: %s", tr_last_error());
  return p;
}

static int same_file(const char *a, const char *b)
{
  char *x = NULL, *y = NULL;
  size_t nx = 0, ny = 0;
  int same = tr_io_load(a, &x, &nx) == TR_OK && tr_io_load(b, &y, &ny) == TR_OK && nx == ny &&
             !memcmp(x, y, nx);
  free(x);
  free(y);
  return same;
}

/* Triangles of q with their markers equal those of the surface as sets (.msh groups them
 * by marker). */
static void expect_tris_as_set(const struct tr_plc *q, const char *file)
{
  EXPECT(q->ntris == 5, "%s: %u triangles", file, q->ntris);
  for (uint32_t t = 0; t < 5 && q->ntris == 5; t++) {
    int found = 0;
    for (uint32_t u = 0; u < 5; u++)
      found |= !memcmp(q->tris + 3 * u, tris + 3 * t, sizeof(uint32_t) * 3) &&
               q->tri_marker[u] == mark[t];
    EXPECT(found, "%s: triangle %u with marker %d not read back", file, t, mark[t]);
  }
}

/* memcmp of n bytes, for arrays that are NULL when empty */
static int same(const void *a, const void *b, size_t n) { return !n || !memcmp(a, b, n); }

/* The same plc from two files: points bitwise, triangles, markers and tets in order. */
static void expect_same_plc(const struct tr_plc *a, const struct tr_plc *b, const char *what)
{
  EXPECT(a->npoints == b->npoints && same(a->xyz, b->xyz, sizeof(double) * 3 * a->npoints),
         "%s: points differ", what);
  EXPECT(a->ntris == b->ntris && same(a->tris, b->tris, sizeof(uint32_t) * 3 * a->ntris) &&
             same(a->tri_marker, b->tri_marker, sizeof(int32_t) * a->ntris),
         "%s: triangles or markers differ (%u, %u)", what, a->ntris, b->ntris);
  EXPECT(a->ntets == b->ntets && same(a->tets, b->tets, sizeof(uint32_t) * 4 * a->ntets),
         "%s: tets differ (%u, %u)", what, a->ntets, b->ntets);
}

static tr_mesh *cube_mesh(void)
{
  static const double cube[24] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                  0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  tr_mesh *m = NULL;
  EXPECT(tr_delaunay(cube, 8, &m) == TR_OK, "delaunay: %s", tr_last_error());
  return m;
}

/* Binary .msh 4.1 and 2.2: the surface reads back bitwise with its markers, the same as
 * from the text form; a tet mesh reads back with the tets of its .mesh; writing twice
 * gives the same bytes. */
static void t_msh_binary_roundtrip(void)
{
  tr_plc *p = surface();
  tr_mesh *m = cube_mesh();
  struct tr_plc ref;
  memset(&ref, 0, sizeof ref);
  if (m) {
    EXPECT(tr_mesh_write(m, tpath(tmp, "cube.mesh"), 0) == TR_OK, "%s", tr_last_error());
    EXPECT(tr_io_read_file(tpath(tmp, "cube.mesh"), &ref) == TR_OK, "%s", tr_last_error());
  }
  for (int ver = 0; ver < 2; ver++) {
    int v = ver ? 22 : 41;
    const char *bin = tpath(tmp, ver ? "s22b.msh" : "s41b.msh");
    const char *txt = tpath(tmp, ver ? "s22.msh" : "s41.msh");
    const char *again = tpath(tmp, ver ? "s22b_again.msh" : "s41b_again.msh");
    EXPECT(tr_plc_write_ex(p, bin, v | TR_WRITE_BINARY) == TR_OK, "%s", tr_last_error());
    EXPECT(tr_plc_write_ex(p, again, v | TR_WRITE_BINARY) == TR_OK, "%s", tr_last_error());
    EXPECT(tr_plc_write_ex(p, txt, v) == TR_OK, "%s", tr_last_error());
    EXPECT(same_file(bin, again), "%s: two writes differ", bin);
    EXPECT(!same_file(bin, txt), "%s: the binary file is the text one", bin);
    struct tr_plc q, t;
    memset(&q, 0, sizeof q);
    memset(&t, 0, sizeof t);
    EXPECT(tr_io_read_file(bin, &q) == TR_OK, "%s: %s", bin, tr_last_error());
    EXPECT(tr_io_read_file(txt, &t) == TR_OK, "%s: %s", txt, tr_last_error());
    EXPECT(q.npoints == 5 && !memcmp(q.xyz, xyz, sizeof xyz), "%s: coordinates differ", bin);
    expect_tris_as_set(&q, bin);
    expect_same_plc(&q, &t, bin);
    tr_plc_clear(&q);
    tr_plc_clear(&t);
    if (!m)
      continue;
    const char *mb = tpath(tmp, ver ? "cube22b.msh" : "cube41b.msh");
    EXPECT(tr_mesh_write_ex(m, mb, 0, v | TR_WRITE_BINARY) == TR_OK, "%s", tr_last_error());
    EXPECT(tr_io_read_file(mb, &q) == TR_OK, "%s: %s", mb, tr_last_error());
    EXPECT(q.ntets == ref.ntets && q.ntets == tr_mesh_num_tets(m) &&
               !memcmp(q.tets, ref.tets, sizeof(uint32_t) * 4 * q.ntets),
           "%s: tets differ from the .mesh output", mb);
    EXPECT(q.npoints == 8 && !memcmp(q.xyz, ref.xyz, sizeof(double) * 24), "%s: points", mb);
    EXPECT(q.ntris == 12, "%s: %u hull triangles (12)", mb, q.ntris);
    for (uint32_t i = 0; i < q.ntris; i++)
      EXPECT(q.tri_marker[i] == 1, "%s: triangle %u marker %d (1)", mb, i, q.tri_marker[i]);
    tr_plc_clear(&q);
  }
  tr_plc_clear(&ref);
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
}

/* .meshb: the surface reads back bitwise, triangles and markers in order; a tet mesh
 * reads back as its text .mesh does; two writes give the same bytes; the header is the
 * int 1 then version 2. */
static void t_meshb_roundtrip(void)
{
  tr_plc *p = surface();
  const char *f = tpath(tmp, "s.meshb"), *g = tpath(tmp, "s_again.meshb");
  EXPECT(tr_plc_write(p, f) == TR_OK, "%s", tr_last_error());
  EXPECT(tr_plc_write(p, g) == TR_OK, "%s", tr_last_error());
  EXPECT(same_file(f, g), "two writes of %s differ", f);
  struct tr_plc q;
  memset(&q, 0, sizeof q);
  EXPECT(tr_io_read_file(f, &q) == TR_OK, "%s: %s", f, tr_last_error());
  EXPECT(q.npoints == 5 && !memcmp(q.xyz, xyz, sizeof xyz), "%s: coordinates differ", f);
  EXPECT(q.ntris == 5 && !memcmp(q.tris, tris, sizeof tris) &&
             !memcmp(q.tri_marker, mark, sizeof mark),
         "%s: triangles or markers differ", f);
  tr_plc_clear(&q);
  char *b = NULL;
  size_t n = 0;
  if (tr_io_load(f, &b, &n) == TR_OK) {
    const unsigned char *u = (const unsigned char *)b;
    EXPECT(n > 8 && tr_get_le32(u) == 1 && tr_get_le32(u + 4) == 2, "%s: header", f);
    /* Dimension 3, then Vertices, Triangles, End with next offset 0 */
    EXPECT(tr_get_le32(u + 8) == 3 && tr_get_le32(u + 12) == 20 && tr_get_le32(u + 16) == 3,
           "%s: Dimension keyword", f);
    EXPECT(tr_get_le32(u + 20) == 4 && tr_get_le32(u + 24) == 32 + 28 * 5 &&
               tr_get_le32(u + 28) == 5,
           "%s: Vertices keyword", f);
    EXPECT(tr_get_le32(u + n - 8) == 54 && tr_get_le32(u + n - 4) == 0, "%s: End", f);
    free(b);
  }
  tr_mesh *m = cube_mesh();
  if (m) {
    struct tr_plc t;
    memset(&t, 0, sizeof t);
    EXPECT(tr_mesh_write(m, tpath(tmp, "cube.meshb"), 0) == TR_OK, "%s", tr_last_error());
    EXPECT(tr_mesh_write(m, tpath(tmp, "cubem.mesh"), 0) == TR_OK, "%s", tr_last_error());
    EXPECT(tr_io_read_file(tpath(tmp, "cube.meshb"), &q) == TR_OK, "%s", tr_last_error());
    EXPECT(tr_io_read_file(tpath(tmp, "cubem.mesh"), &t) == TR_OK, "%s", tr_last_error());
    EXPECT(q.ntets == tr_mesh_num_tets(m), "cube.meshb: %u tets", q.ntets);
    expect_same_plc(&q, &t, "cube.meshb against cube.mesh");
    EXPECT(tr_mesh_write_ex(m, tpath(tmp, "cube_b.mesh"), 0, 41 | TR_WRITE_BINARY) ==
                   TR_ERR_USAGE &&
               strstr(tr_last_error(), ".meshb"),
           "--binary to a text .mesh: %s", tr_last_error());
    tr_plc_clear(&q);
    tr_plc_clear(&t);
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
}

static const char *find(const char *b, size_t n, const char *s)
{
  size_t k = strlen(s);
  for (size_t i = 0; i + k <= n; i++)
    if (!memcmp(b + i, s, k))
      return b + i;
  return NULL;
}

/* VTU with raw appended data, decoded here from its documented layout: each array's
 * offset attribute points at a UInt64 byte count followed by the array, little-endian;
 * the arrays hold the points bitwise, the cells, offsets, types, regions and markers. */
static void t_vtu_binary(void)
{
  static const uint32_t tets[8] = {0, 1, 2, 3, 1, 2, 3, 4};
  static const int32_t reg[2] = {7, -3};
  struct tr_mesh_view v = {5, xyz, NULL, 2, tets, reg, 5, tris, mark, 1};
  const char *f = tpath(tmp, "b.vtu"), *g = tpath(tmp, "b_again.vtu");
  EXPECT(tr_write_mesh_view_as(&v, f, 0, 41 | TR_WRITE_BINARY) == TR_OK, "%s", tr_last_error());
  EXPECT(tr_write_mesh_view_as(&v, g, 0, 41 | TR_WRITE_BINARY) == TR_OK, "%s", tr_last_error());
  EXPECT(same_file(f, g), "two writes of %s differ", f);
  char *b = NULL;
  size_t n = 0;
  if (tr_io_load(f, &b, &n) != TR_OK)
    return;
  EXPECT(find(b, n, "header_type=\"UInt64\"") && find(b, n, "byte_order=\"LittleEndian\""),
         "header attributes");
  const char *app = find(b, n, "<AppendedData encoding=\"raw\">\n   _");
  EXPECT(app != NULL, "no raw AppendedData");
  static const char tail[] = "\n  </AppendedData>\n</VTKFile>\n";
  EXPECT(n > sizeof tail && !memcmp(b + n - (sizeof tail - 1), tail, sizeof tail - 1), "tail");
  if (!app) {
    free(b);
    return;
  }
  const unsigned char *data = (const unsigned char *)strchr(app, '_') + 1;
  uint64_t off[6];
  const char *q = b;
  for (int i = 0; i < 6; i++) {
    q = find(q, (size_t)(app - q), "offset=\"");
    EXPECT(q != NULL, "array %d has no offset", i);
    if (!q) {
      free(b);
      return;
    }
    q += 8;
    off[i] = strtoull(q, NULL, 10);
  }
  uint64_t nc = 7, want[6] = {24 * 5, 8 * (8 + 15), 8 * nc, nc, 4 * nc, 4 * nc};
  for (int i = 0; i < 6; i++) {
    EXPECT(tr_get_le64(data + off[i]) == want[i], "array %d: %llu bytes, %llu expected", i,
           (unsigned long long)tr_get_le64(data + off[i]), (unsigned long long)want[i]);
    if (i < 5)
      EXPECT(off[i + 1] == off[i] + 8 + want[i], "array %d is not right after array %d", i + 1,
             i);
  }
  EXPECT((size_t)(data - (const unsigned char *)b) + off[5] + 8 + want[5] + sizeof tail - 1 == n,
         "the data end where the file says");
  const unsigned char *d = data + off[0] + 8;
  for (int i = 0; i < 15; i++) {
    double x = tr_get_le_f64(d + 8 * i);
    EXPECT(!memcmp(&x, &xyz[i], 8), "point coordinate %d not bitwise", i);
  }
  d = data + off[1] + 8;
  for (int i = 0; i < 23; i++)
    EXPECT(tr_get_le64(d + 8 * i) == (i < 8 ? tets[i] : tris[i - 8]), "connectivity %d", i);
  for (uint64_t c = 0; c < nc; c++) {
    EXPECT(tr_get_le64(data + off[2] + 8 + 8 * c) == (c < 2 ? 4 * (c + 1) : 8 + 3 * (c - 1)),
           "offset of cell %llu", (unsigned long long)c);
    EXPECT(data[off[3] + 8 + c] == (c < 2 ? 10 : 5), "type of cell %llu", (unsigned long long)c);
    EXPECT((int32_t)tr_get_le32(data + off[4] + 8 + 4 * c) == (c < 2 ? reg[c] : 0),
           "region of cell %llu", (unsigned long long)c);
    EXPECT((int32_t)tr_get_le32(data + off[5] + 8 + 4 * c) == (c < 2 ? 0 : mark[c - 2]),
           "marker of cell %llu", (unsigned long long)c);
  }
  free(b);
}

static uint32_t be32(const unsigned char *p)
{
  return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* Legacy VTK binary: each block of numbers right after its text line, big-endian, then a
 * newline before the next line: points bitwise, cells, types, regions, markers. */
static void t_vtk_binary(void)
{
  static const uint32_t tets[8] = {0, 1, 2, 3, 1, 2, 3, 4};
  static const int32_t reg[2] = {7, -3};
  struct tr_mesh_view v = {5, xyz, NULL, 2, tets, reg, 5, tris, mark, 1};
  const char *f = tpath(tmp, "b.vtk");
  EXPECT(tr_write_mesh_view_as(&v, f, 0, 41 | TR_WRITE_BINARY) == TR_OK, "%s", tr_last_error());
  char *b = NULL;
  size_t n = 0;
  if (tr_io_load(f, &b, &n) != TR_OK)
    return;
  EXPECT(!strncmp(b, "# vtk DataFile Version 3.0\ntetrec mesh\nBINARY\n", 42), "header");
  const char *pt = find(b, n, "POINTS 5 double\n"), *ce = find(b, n, "\nCELLS 7 30\n");
  const char *ty = find(b, n, "\nCELL_TYPES 7\n");
  static const char rgl[] = "\nCELL_DATA 7\nSCALARS region int 1\nLOOKUP_TABLE default\n";
  static const char mkl[] = "\nSCALARS marker int 1\nLOOKUP_TABLE default\n";
  const char *rg = find(b, n, rgl), *mk = find(b, n, mkl);
  EXPECT(pt && ce && ty && rg && mk, "a section line is missing");
  if (!(pt && ce && ty && rg && mk)) {
    free(b);
    return;
  }
  const unsigned char *u = (const unsigned char *)pt + 16;
  for (int i = 0; i < 15; i++) {
    uint64_t w = (uint64_t)be32(u + 8 * i) << 32 | be32(u + 8 * i + 4), x;
    memcpy(&x, &xyz[i], 8);
    EXPECT(w == x, "point coordinate %d not bitwise", i);
  }
  EXPECT((const char *)u + 120 == ce, "CELLS right after the points and a newline");
  u = (const unsigned char *)ce + 12;
  int k = 0;
  for (int c = 0; c < 7; c++) {
    int per = c < 2 ? 4 : 3;
    EXPECT(be32(u + 4 * k++) == (uint32_t)per, "cell %d size", c);
    for (int j = 0; j < per; j++, k++)
      EXPECT(be32(u + 4 * k) == (c < 2 ? tets[4 * c + j] : tris[3 * (c - 2) + j]),
             "cell %d vertex %d", c, j);
  }
  EXPECT((const char *)u + 4 * 30 == ty, "CELL_TYPES right after the cells");
  u = (const unsigned char *)ty + 14; /* "\nCELL_TYPES 7\n" */
  for (int c = 0; c < 7; c++)
    EXPECT(be32(u + 4 * c) == (c < 2 ? 10u : 5u), "type of cell %d", c);
  u = (const unsigned char *)rg + sizeof rgl - 1;
  for (int c = 0; c < 7; c++)
    EXPECT((int32_t)be32(u + 4 * c) == (c < 2 ? reg[c] : 0), "region of cell %d", c);
  u = (const unsigned char *)mk + sizeof mkl - 1;
  for (int c = 0; c < 7; c++)
    EXPECT((int32_t)be32(u + 4 * c) == (c < 2 ? 0 : mark[c - 2]), "marker of cell %d", c);
  EXPECT((const char *)u + 28 + 1 == b + n && b[n - 1] == '\n', "the file ends after the markers");
  free(b);
}

/* Binary STL: 84 + 50 n bytes, a header that does not start with "solid", the float
 * corners of every triangle (the doubles rounded to float), a unit normal; read back by
 * tetrec's STL reader to the same triangles. */
static void t_stl_binary(void)
{
  /* floats exactly, but for 0.1 (rounded) */
  static const double p[12] = {0, 0, 0, 2, 0, 0, 0, 0.5, 0, 0.1, 0.25, -3};
  static const uint32_t t[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  tr_plc *s = NULL;
  EXPECT(tr_plc_create(&s) == TR_OK && tr_plc_set(s, p, 4, t, 4, NULL) == TR_OK, "set");
  const char *f = tpath(tmp, "s.stl");
  EXPECT(tr_plc_write(s, f) == TR_OK, "%s", tr_last_error());
  char *b = NULL;
  size_t n = 0;
  if (tr_io_load(f, &b, &n) == TR_OK) {
    const unsigned char *u = (const unsigned char *)b;
    EXPECT(n == 84 + 50 * 4 && tr_get_le32(u + 80) == 4, "%s: %zu bytes", f, n);
    EXPECT(strncmp(b, "solid", 5) != 0, "the header starts with 'solid'");
    for (int k = 0; k < 4 && n == 284; k++) {
      const unsigned char *r = u + 84 + 50 * k;
      double nx = tr_get_le_f32(r), ny = tr_get_le_f32(r + 4), nz = tr_get_le_f32(r + 8);
      EXPECT(fabs(sqrt(nx * nx + ny * ny + nz * nz) - 1) < 1e-6, "normal %d not unit", k);
      for (int c = 0; c < 9; c++) {
        float x = tr_get_le_f32(r + 12 + 4 * c);
        EXPECT(x == (float)p[3 * t[3 * k + c / 3] + c % 3], "triangle %d value %d", k, c);
      }
    }
    struct tr_plc q;
    memset(&q, 0, sizeof q);
    EXPECT(tr_read_stl_buf(b, n, f, &q) == TR_OK, "%s", tr_last_error());
    EXPECT(q.ntris == 4 && q.npoints == 4, "%u triangles, %u points", q.ntris, q.npoints);
    for (uint32_t k = 0; k < q.ntris && q.ntris == 4; k++)
      for (int c = 0; c < 9; c++)
        EXPECT(q.xyz[3 * q.tris[3 * k + c / 3] + c % 3] ==
                   (double)(float)p[3 * t[3 * k + c / 3] + c % 3],
               "read back: triangle %u value %d", k, c);
    tr_plc_clear(&q);
    free(b);
  }
  tr_plc_destroy(s);
}

/* ---- damaged inputs ---- */

typedef tr_status (*reader)(const char *, size_t, const char *, struct tr_plc *);

/* Reads buf with rd: the expected status and, when msg is not NULL, a message holding it. */
static void expect_refused(reader rd, const char *buf, size_t n, tr_status want,
                           const char *msg, const char *what)
{
  struct tr_plc q;
  memset(&q, 0, sizeof q);
  tr_status s = rd(buf, n, "t", &q);
  EXPECT(s == want && (!msg || strstr(tr_last_error(), msg)),
         "%s: status %d (%d expected), '%s' (expected '%s')", what, s, want, tr_last_error(),
         msg ? msg : "");
  EXPECT(q.npoints == 0 && q.xyz == NULL && q.tris == NULL, "%s: plc not left cleared", what);
  tr_plc_clear(&q);
}

/* 1 iff the first k bytes of b end with s. */
static int ends_with(const char *b, size_t k, const char *s)
{
  size_t m = strlen(s);
  return k >= m && !memcmp(b + k - m, s, m);
}

/* Every proper prefix of a file up to `ok_from` bytes is refused with a message, but for
 * one that ends at `whole` (a .msh may end after any section: one cut right after
 * $EndNodes is a file of points, valid as such). */
static void truncations(reader rd, const char *b, size_t ok_from, const char *whole,
                        const char *what)
{
  int bad = 0;
  for (size_t k = 0; k < ok_from; k++) {
    if (whole &&
        (ends_with(b, k, whole) || (k && b[k - 1] == '\n' && ends_with(b, k - 1, whole))))
      continue;
    struct tr_plc q;
    memset(&q, 0, sizeof q);
    char *c = malloc(k ? k : 1); /* exactly k bytes: ASan sees any read past them */
    memcpy(c, b, k);
    tr_status s = rd(c, k, "t", &q);
    if (s == TR_OK || tr_last_error()[0] == '\0') {
      if (!bad++)
        fprintf(stderr, "%s: the first %zu bytes read with status %d\n", what, k, s);
    }
    tr_plc_clear(&q);
    free(c);
  }
  EXPECT(bad == 0, "%s: %d truncations read without an error", what, bad);
}

static char *load(const char *file, size_t *n)
{
  char *b = NULL;
  EXPECT(tr_io_load(file, &b, n) == TR_OK, "%s: %s", file, tr_last_error());
  return b;
}

static void put64(char *p, uint64_t x) { tr_le64((unsigned char *)p, x); }
static void put32(char *p, uint32_t x) { tr_le32((unsigned char *)p, x); }

/* Damaged copies of the binary .msh 4.1 of the Delaunay cube (8 nodes, 12 triangles in
 * one block, then 6 tets in one block). */
static void msh41_damaged(const char *b, size_t n)
{
  /* the last '\n' is not needed */
  truncations(tr_read_msh_buf, b, n - 1, "$EndNodes", "4.1 binary");
  char *c = malloc(n);
  const char *nodes = find(b, n, "$Nodes\n"), *els = find(b, n, "$Elements\n");
  const char *one = find(b, n, "4.1 1 8\n");
  if (!c || !nodes || !els || !one) {
    EXPECT(0, "4.1 binary: sections not found");
    free(c);
    return;
  }
  size_t nd = (size_t)(nodes - b) + 7, el = (size_t)(els - b) + 10, on = (size_t)(one - b) + 8;
#define DAMAGE(at, put, val, st, msg, what)      \
  do {                                           \
    memcpy(c, b, n);                             \
    put(c + (at), val);                          \
    expect_refused(tr_read_msh_buf, c, n, st, msg, what); \
  } while (0)
  DAMAGE(on, put32, 0x01000000u, TR_ERR_UNSUPPORTED, "big-endian", "4.1: big-endian marker");
  DAMAGE(on, put32, 2, TR_ERR_PARSE, "not 1", "4.1: marker 2");
  DAMAGE(nd, put64, 1ull << 60, TR_ERR_PARSE, "node blocks declared but the file has room",
         "4.1: 2^60 node blocks");
  DAMAGE(nd + 8, put64, 1ull << 40, TR_ERR_PARSE, "nodes declared but the file has room",
         "4.1: 2^40 nodes");
  DAMAGE(nd + 32 + 12, put64, 1ull << 33, TR_ERR_PARSE, "nodes in the block declared",
         "4.1: 2^33 nodes in the block");
  DAMAGE(nd + 32 + 8, put32, 1, TR_ERR_UNSUPPORTED, "parametric", "4.1: parametric nodes");
  DAMAGE(nd + 32 + 20, put64, 0, TR_ERR_INPUT, "node tag 0", "4.1: node tag 0");
  DAMAGE(nd + 32 + 20 + 8 * 8, put64, 0x7ff8000000000000ull, TR_ERR_INPUT, "NaN",
         "4.1: NaN coordinate");
  DAMAGE(el + 32 + 12, put64, 1ull << 50, TR_ERR_PARSE, "elements in the block declared",
         "4.1: 2^50 elements in a block");
  DAMAGE(el + 32 + 8, put32, 5, TR_ERR_UNSUPPORTED, "element type 5", "4.1: hexahedra");
  DAMAGE(el + 32 + 20 + 8, put64, 9, TR_ERR_INPUT, "node tag 9 is not defined",
         "4.1: node index 9 of 8");
  DAMAGE(el + 32 + 20 + 8, put64, ~0ull, TR_ERR_INPUT, "is not defined",
         "4.1: node index 2^64-1");
  DAMAGE(el + 8, put64, 19, TR_ERR_PARSE, "18 elements in the blocks, 19 declared",
         "4.1: element count off by one");
  free(c);
}

/* The same for 2.2 binary: text counts, then int records. */
static void msh22_damaged(const char *b, size_t n)
{
  truncations(tr_read_msh_buf, b, n - 1, "$EndNodes", "2.2 binary");
  char *c = malloc(n);
  const char *nodes = find(b, n, "$Nodes\n8\n"), *els = find(b, n, "$Elements\n18\n");
  const char *one = find(b, n, "2.2 1 8\n");
  if (!c || !nodes || !els || !one) {
    EXPECT(0, "2.2 binary: sections not found");
    free(c);
    return;
  }
  size_t nd = (size_t)(nodes - b) + 9, el = (size_t)(els - b) + 13, on = (size_t)(one - b) + 8;
  DAMAGE(on, put32, 0x01000000u, TR_ERR_UNSUPPORTED, "big-endian", "2.2: big-endian marker");
  DAMAGE(nd, put32, (uint32_t)-5, TR_ERR_INPUT, "node tag -5", "2.2: node tag -5");
  DAMAGE(el + 4, put32, 0x7fffffff, TR_ERR_PARSE, "elements left of the 18 declared",
         "2.2: group of 2^31-1 elements");
  DAMAGE(el + 4, put32, 0, TR_ERR_PARSE, "element group of 0 elements", "2.2: empty group");
  DAMAGE(el + 8, put32, 0x10000000, TR_ERR_PARSE, "elements in the group declared",
         "2.2: 2^28 tags per element");
  DAMAGE(el + 12 + 12, put32, (uint32_t)-1, TR_ERR_INPUT, "is not defined",
         "2.2: node index -1");
  DAMAGE(el + 12 + 12, put32, 0x7fffffff, TR_ERR_INPUT, "node tag 2147483647 is not defined",
         "2.2: node index 2^31-1");
  DAMAGE(el, put32, 9, TR_ERR_UNSUPPORTED, "element type 9", "2.2: 6-node triangles");
  free(c);
  /* a count in the text that the bytes cannot hold */
  const char big[] = "$MeshFormat\n2.2 1 8\n\x01\0\0\0\n$EndMeshFormat\n$Nodes\n99999\n";
  expect_refused(tr_read_msh_buf, big, sizeof big - 1, TR_ERR_PARSE,
                 "header declares 99999 nodes", "2.2: 99999 nodes in a short file");
}

/* Damaged .meshb of the cube: Dimension at 8, Vertices at 20 (8 lines of 28 bytes),
 * Tetrahedra at 256, Triangles after, End last. */
static void meshb_damaged(const char *b, size_t n)
{
  truncations(tr_read_meshb_buf, b, n - 4, NULL, ".meshb"); /* End's code is enough */
  char *c = malloc(n + 64);
  if (!c)
    return;
#undef DAMAGE
#define DAMAGE(at, put, val, st, msg, what)      \
  do {                                           \
    memcpy(c, b, n);                             \
    put(c + (at), val);                          \
    expect_refused(tr_read_meshb_buf, c, n, st, msg, what); \
  } while (0)
  DAMAGE(0, put32, 0x01000000u, TR_ERR_UNSUPPORTED, "big-endian", ".meshb: big-endian");
  DAMAGE(0, put32, 7, TR_ERR_PARSE, "not a binary Medit file", ".meshb: first int 7");
  DAMAGE(4, put32, 5, TR_ERR_UNSUPPORTED, "version 5", ".meshb: version 5");
  DAMAGE(16, put32, 2, TR_ERR_UNSUPPORTED, "Dimension 2", ".meshb: dimension 2");
  DAMAGE(28, put32, 0x7fffffff, TR_ERR_PARSE, "vertices declared but the file has room",
         ".meshb: 2^31-1 vertices");
  DAMAGE(28, put32, (uint32_t)-3, TR_ERR_PARSE, "negative number of vertices",
         ".meshb: -3 vertices");
  DAMAGE(256 + 8, put32, 0x40000000, TR_ERR_PARSE, "tetrahedra declared",
         ".meshb: 2^30 tetrahedra");
  DAMAGE(256 + 12, put32, 0, TR_ERR_INPUT, "index 0 out of range (1..8)", ".meshb: index 0");
  DAMAGE(256 + 12, put32, 9, TR_ERR_INPUT, "index 9 out of range (1..8)", ".meshb: index 9");
  DAMAGE(256 + 12, put32, (uint32_t)-7, TR_ERR_INPUT, "index -7 out of range",
         ".meshb: index -7");
  DAMAGE(32 + 8, put64, 0xfff0000000000000ull, TR_ERR_INPUT, "NaN or infinite",
         ".meshb: -inf coordinate");
  /* an unknown keyword (Corners, 13) is stepped over by its offset; one whose offset
   * points backwards, or past the end, is refused */
  memcpy(c, b, 256);
  put32(c + 256, 13);
  put32(c + 260, 256 + 20);
  put32(c + 264, 2);
  put32(c + 268, 1);
  put32(c + 272, 2);
  memcpy(c + 276, b + 256, n - 256);
  /* the later keywords' offsets are now 20 bytes short: the reader does not use them */
  struct tr_plc q;
  memset(&q, 0, sizeof q);
  EXPECT(tr_read_meshb_buf(c, n + 20, "t", &q) == TR_OK && q.ntets == 6,
         ".meshb with Corners: %s", tr_last_error());
  tr_plc_clear(&q);
  put32(c + 260, 200);
  expect_refused(tr_read_meshb_buf, c, n + 20, TR_ERR_PARSE, "keyword 13 cannot be skipped",
                 ".meshb: backward offset");
  put32(c + 260, (uint32_t)(n + 21));
  expect_refused(tr_read_meshb_buf, c, n + 20, TR_ERR_PARSE, "keyword 13 cannot be skipped",
                 ".meshb: offset past the end");
  /* the End keyword replaced by garbage and the file cut after it */
  memcpy(c, b, n);
  expect_refused(tr_read_meshb_buf, c, n - 8, TR_ERR_PARSE, "without the End keyword",
                 ".meshb: no End");
  free(c);
#undef DAMAGE
}

static void t_binary_damaged(void)
{
  tr_mesh *m = cube_mesh();
  if (!m)
    return;
  size_t n;
  char *b;
  EXPECT(tr_mesh_write_ex(m, tpath(tmp, "d41.msh"), 0, 41 | TR_WRITE_BINARY) == TR_OK, "41b");
  EXPECT(tr_mesh_write_ex(m, tpath(tmp, "d22.msh"), 0, 22 | TR_WRITE_BINARY) == TR_OK, "22b");
  EXPECT(tr_mesh_write(m, tpath(tmp, "d.meshb"), 0) == TR_OK, "meshb");
  if ((b = load(tpath(tmp, "d41.msh"), &n))) {
    msh41_damaged(b, n);
    free(b);
  }
  if ((b = load(tpath(tmp, "d22.msh"), &n))) {
    msh22_damaged(b, n);
    free(b);
  }
  if ((b = load(tpath(tmp, "d.meshb"), &n))) {
    meshb_damaged(b, n);
    free(b);
  }
  tr_mesh_destroy(m);
}

int main(int argc, char **argv)
{
  if (argc < 3) {
    fprintf(stderr, "usage: test_binary CASE TMPDIR\n");
    return 2;
  }
  tmp = argv[2];
  static const texpect_case cases[] = {
      {"msh_binary_roundtrip", t_msh_binary_roundtrip, NULL},
      {"meshb_roundtrip", t_meshb_roundtrip, NULL},
      {"vtu_binary", t_vtu_binary, NULL},
      {"vtk_binary", t_vtk_binary, NULL},
      {"stl_binary", t_stl_binary, NULL},
      {"binary_damaged", t_binary_damaged, NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof cases[0]);
}
