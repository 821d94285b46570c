/* Formats and CLI support of issue 18: Gmsh .msh in and out, legacy VTK out, PLY triangle
 * strips, output names, the collect-all self-intersection check, non-planar polygons and
 * the deviation of written Steiner doubles. Usage: test_formats SUBTEST DATADIR TMPDIR */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "input/validate.h"
#include "io/io.h"
#include "mesh/mesh.h"
#include "qpoint.h"
#include "tetrec.h"
#include "tpath.h"
#include "../pipeline/texpect.h"
#include "../pipeline/tplc.h"

static const char *data, *tmp;

static struct tr_plc *read_buf(tr_status (*rd)(const char *, size_t, const char *, struct tr_plc *),
                               const char *text, size_t len, tr_status *st)
{
  struct tr_plc *p = calloc(1, sizeof *p);
  *st = rd(text, len, "t", p);
  return p;
}

static void put_file(const char *file, const char *text, size_t len)
{
  FILE *f = fopen(file, "wb");
  fwrite(text, 1, len, f);
  fclose(f);
}

/* Awkward doubles and markers (0, negative, large) survive .msh 4.1 and 2.2 bitwise. */
static void t_msh_roundtrip(void)
{
  double xyz[15] = {0.1, -0.0, 1e-300, 1.0 / 3, 2.5e300, -7.25, 0x1.fffffffffffffp-1, 5e-324,
                    123456789.123456789, -1.0 / 7, 3, 4, 1e10, -2e-5, 0.5};
  uint32_t tris[15] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 4, 1, 2};
  int32_t mark[5] = {1, -2, 0, 40, 1};
  tr_plc *p;
  EXPECT(tr_plc_create(&p) == TR_OK, "create");
  EXPECT(tr_plc_set(p, xyz, 5, tris, 5, mark) == TR_OK, "set: %s", tr_last_error());
  for (int ver = 0; ver < 2; ver++) {
    const char *file = tpath(tmp, ver ? "rt22.msh" : "rt41.msh");
    EXPECT(tr_plc_write_ex(p, file, ver ? 22 : 41) == TR_OK, "write: %s", tr_last_error());
    struct tr_plc q;
    memset(&q, 0, sizeof q);
    tr_status s = tr_io_read_file(file, &q);
    EXPECT(s == TR_OK, "%s: %s", file, tr_last_error());
    EXPECT(q.npoints == 5 && memcmp(q.xyz, xyz, sizeof xyz) == 0, "%s: coordinates differ", file);
    /* triangles are grouped by marker: compare as sets of (triangle, marker) */
    EXPECT(q.ntris == 5, "%s: %u triangles", file, q.ntris);
    for (uint32_t t = 0; t < 5 && q.ntris == 5; t++) {
      int found = 0;
      for (uint32_t u = 0; u < 5; u++)
        found |= !memcmp(q.tris + 3 * u, tris + 3 * t, sizeof(uint32_t) * 3) &&
                 q.tri_marker[u] == mark[t];
      EXPECT(found, "%s: triangle %u with marker %d not read back", file, t, mark[t]);
    }
    tr_plc_clear(&q);
  }
  tr_plc_destroy(p);
}

/* A Delaunay mesh written as .msh (both versions) and .vtk: the .msh reads back with the
 * same tets, the boundary triangles carry their marker as physical tag. */
static void t_msh_mesh(void)
{
  static const double cube[24] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                  0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  tr_mesh *m = NULL;
  EXPECT(tr_delaunay(cube, 8, &m) == TR_OK, "delaunay: %s", tr_last_error());
  if (!m)
    return;
  uint32_t nt = tr_mesh_num_tets(m);
  EXPECT(tr_mesh_write(m, tpath(tmp, "dm.mesh"), 0) == TR_OK, "%s", tr_last_error());
  struct tr_plc ref;
  memset(&ref, 0, sizeof ref);
  EXPECT(tr_io_read_file(tpath(tmp, "dm.mesh"), &ref) == TR_OK, "%s", tr_last_error());
  for (int ver = 0; ver < 2; ver++) {
    const char *file = tpath(tmp, ver ? "dm22.msh" : "dm41.msh");
    EXPECT(tr_mesh_write_ex(m, file, 0, ver ? 22 : 41) == TR_OK, "%s", tr_last_error());
    struct tr_plc q;
    memset(&q, 0, sizeof q);
    EXPECT(tr_io_read_file(file, &q) == TR_OK, "%s: %s", file, tr_last_error());
    EXPECT(q.ntets == nt && q.npoints == 8, "%s: %u tets (%u expected)", file, q.ntets, nt);
    EXPECT(q.ntets == ref.ntets && !memcmp(q.tets, ref.tets, sizeof(uint32_t) * 4 * nt),
           "%s: tets differ from the .mesh output", file);
    EXPECT(q.ntris == 12, "%s: %u boundary triangles (12)", file, q.ntris);
    for (uint32_t t = 0; t < q.ntris; t++)
      EXPECT(q.tri_marker[t] == 1, "%s: triangle %u has marker %d", file, t, q.tri_marker[t]);
    tr_plc_clear(&q);
  }
  EXPECT(tr_mesh_write(m, tpath(tmp, "dm.vtk"), 0) == TR_OK, "%s", tr_last_error());
  char *buf;
  size_t len;
  if (tr_io_load(tpath(tmp, "dm.vtk"), &buf, &len) == TR_OK) {
    char want[64];
    /* the tets, then the 12 hull faces with their marker (1 for a tr_delaunay mesh) */
    snprintf(want, sizeof want, "CELLS %u %u\n", nt + 12, 5 * nt + 4 * 12);
    EXPECT(strstr(buf, want) != NULL, "vtk: no '%s'", want);
    snprintf(want, sizeof want, "CELL_TYPES %u\n10\n", nt + 12);
    EXPECT(strstr(buf, want) != NULL, "vtk: no '%s'", want);
    EXPECT(strstr(buf, "SCALARS region int 1") != NULL, "vtk: region cell data");
    const char *mk = strstr(buf, "SCALARS marker int 1\nLOOKUP_TABLE default\n");
    EXPECT(mk != NULL, "vtk: marker cell data");
    if (mk) {
      mk = strchr(strchr(mk, '\n') + 1, '\n') + 1;
      uint32_t ones = 0, zeros = 0;
      for (uint32_t c = 0; c < nt + 12; c++, mk = strchr(mk, '\n') + 1) {
        if (c < nt)
          zeros += mk[0] == '0';
        else
          ones += mk[0] == '1';
      }
      EXPECT(zeros == nt && ones == 12, "vtk: markers %u zeros (tets), %u ones (faces)", zeros,
             ones);
    }
    free(buf);
  }
  tr_plc_clear(&ref);
  tr_mesh_destroy(m);
}

/* The reader: sparse node tags, physical tags from entities (4.1) or the first tag (2.2),
 * quads as polygons, points and lines skipped; and every malformed file refused with its
 * status and line, without allocating by a declared count. */
static void t_msh_reader(void)
{
  static const char v41[] =
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
      "$PhysicalNames\n1\n2 7 \"wall\"\n$EndPhysicalNames\n"
      "$Entities\n1 0 2 0\n5 0 0 0 0\n"
      "3 0 0 0 1 1 1 1 7 0\n4 0 0 0 1 1 1 0 0\n$EndEntities\n"
      "$Nodes\n2 5 10 1000000000000\n"
      "2 3 0 3\n10\n20\n1000000000000\n0 0 0\n1 0 0\n1 1 0\n"
      "2 4 0 2\n30\n40\n0 1 0\n0.5 0.5 1\n$EndNodes\n"
      "$Elements\n3 4 1 4\n0 5 15 1\n1 10\n2 3 3 1\n2 10 20 1000000000000 30\n"
      "2 4 2 2\n3 10 20 40\n4 20 1000000000000 40\n$EndElements\n";
  tr_status s;
  struct tr_plc *p = read_buf(tr_read_msh_buf, v41, sizeof v41 - 1, &s);
  EXPECT(s == TR_OK, "4.1: %s", tr_last_error());
  EXPECT(p->npoints == 5 && p->ntris == 4, "4.1: %u points, %u triangles (5, 4)", p->npoints,
         p->ntris);
  if (p->ntris == 4) {
    EXPECT(p->tri_marker[0] == 7 && p->tri_marker[1] == 7, "quad triangles: markers %d %d (7)",
           p->tri_marker[0], p->tri_marker[1]);
    EXPECT(p->tri_marker[2] == 0 && p->tri_marker[3] == 0, "no physical tag: marker 0");
    EXPECT(p->tris[6] == 0 && p->tris[7] == 1 && p->tris[8] == 4, "node tags 10 20 40 -> 0 1 4");
    EXPECT(p->xyz[3 * 2] == 1 && p->xyz[3 * 2 + 1] == 1, "tag 10^12 is the third node");
  }
  tr_plc_destroy(p);
  /* as meshio writes it: an element block of an entity $Entities does not declare */
  static const char undeclared[] =
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 0 1\n1 0 0 0 1 1 1 1 3 0\n"
      "$EndEntities\n$Nodes\n1 3 1 3\n3 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n"
      "$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 3\n$EndElements\n";
  p = read_buf(tr_read_msh_buf, undeclared, sizeof undeclared - 1, &s);
  EXPECT(s == TR_OK && p->ntris == 1 && p->tri_marker[0] == 0,
         "undeclared entity: no physical tag (%s)", tr_last_error());
  tr_plc_destroy(p);
  static const char v22[] = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n"
                            "1 0 0 0\n2 1 0 0\n3 0 1 0\n7 0 0 1\n$EndNodes\n"
                            "$Elements\n3\n1 2 2 5 1 1 3 2\n2 1 2 5 1 1 2\n"
                            "3 4 2 9 1 1 2 3 7\n$EndElements\n";
  p = read_buf(tr_read_msh_buf, v22, sizeof v22 - 1, &s);
  EXPECT(s == TR_OK, "2.2: %s", tr_last_error());
  EXPECT(p->ntris == 1 && p->ntets == 1 && p->tri_marker[0] == 5, "2.2: %u tris %u tets",
         p->ntris, p->ntets);
  if (p->ntets == 1)
    EXPECT(p->tets[3] == 3, "node tag 7 -> index 3");
  tr_plc_destroy(p);
  static const struct {
    const char *text, *msg;
    tr_status status;
  } bad[] = {
      {"$MeshFormat\n4.1 1 4\n$EndMeshFormat\n",
       "t:2: binary .msh with data size 4 not supported", TR_ERR_UNSUPPORTED},
      {"$MeshFormat\n4.1 1 8\n$EndMeshFormat\n", "t:3: binary .msh: the int after the header",
       TR_ERR_PARSE},
      {"$MeshFormat\n4 0 8\n$EndMeshFormat\n", "t:2: .msh format 4 not supported",
       TR_ERR_UNSUPPORTED},
      {"$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n99999999999\n1 0 0 0\n$EndNodes\n",
       "t:5: header declares 99999999999 nodes", TR_ERR_PARSE},
      {"$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n$Elements\n1\n"
       "1 2 0 1 1 2\n$EndElements\n",
       "t:10: node tag 2 is not defined", TR_ERR_INPUT},
      {"$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n$Elements\n1\n"
       "1 9 0 1 1 1 1 1 1\n$EndElements\n",
       "t:10: element type 9 not supported", TR_ERR_UNSUPPORTED},
      {"$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n2\n1 0 0 0\n1 1 0 0\n$EndNodes\n",
       "node tag 1 defined twice", TR_ERR_INPUT},
      {"$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Elements\n0\n$EndElements\n",
       "t:4: $Elements before $Nodes", TR_ERR_PARSE},
      {"$Nodes\n", "t:1: no $MeshFormat section first", TR_ERR_PARSE},
      {"$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Foo\n1 2 3\n", "t:4: section $Foo has no $EndFoo",
       TR_ERR_PARSE},
      {"$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0\n", "end of file",
       TR_ERR_PARSE},
      {"$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1 1 1\n2 1 1 1\n1\n0 0 0 0 0\n"
       "$EndNodes\n", "t:6: parametric nodes not supported", TR_ERR_UNSUPPORTED},
      {"$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 1 1 1\n2 1 0 1\n1\n0 0 0\n"
       "$EndNodes\n$Elements\n1 1 1 1\n2 1 2 1\n1 1 1 1\n", "end of file while reading $EndElements",
       TR_ERR_PARSE},
  };
  for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
    p = read_buf(tr_read_msh_buf, bad[i].text, strlen(bad[i].text), &s);
    EXPECT(s == bad[i].status && strstr(tr_last_error(), bad[i].msg),
           "case %zu: %s (%s), expected %s (%s)", i, tr_status_name(s), tr_last_error(),
           tr_status_name(bad[i].status), bad[i].msg);
    EXPECT(p->npoints == 0 && p->ntris == 0, "case %zu: plc left filled", i);
    tr_plc_destroy(p);
  }
}

/* Triangle strips: the unit cube as one strip around its sides and two caps after -1
 * restarts, with a repeated vertex (a join) in between; ascii and binary read the same 12
 * triangles, a closed surface oriented outward (validation repairs nothing and the
 * enclosed volume is exactly 1). */
static void t_ply_strips(void)
{
  static const double cube[24] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                  0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  static const int strip[] = {4, 0, 5, 1, 6, 2, 7, 3, 4, 0, 0, -1,
                              4, 5, 7, 6, -1, 0, 3, 1, 2};
  int ns = (int)(sizeof strip / sizeof strip[0]);
  char text[2048];
  int n = snprintf(text, sizeof text,
                   "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
                   "property float z\nelement tristrips 1\nproperty list int int vertex_indices\n"
                   "end_header\n");
  for (int i = 0; i < 8; i++)
    n += snprintf(text + n, sizeof text - (size_t)n, "%g %g %g\n", cube[3 * i], cube[3 * i + 1],
                  cube[3 * i + 2]);
  n += snprintf(text + n, sizeof text - (size_t)n, "%d", ns);
  for (int i = 0; i < ns; i++)
    n += snprintf(text + n, sizeof text - (size_t)n, " %d", strip[i]);
  n += snprintf(text + n, sizeof text - (size_t)n, "\n");
  unsigned char bin[1024];
  size_t b = (size_t)snprintf((char *)bin, sizeof bin,
                              "ply\nformat binary_little_endian 1.0\nelement vertex 8\n"
                              "property double x\nproperty double y\nproperty double z\n"
                              "element tristrips 1\nproperty list uchar int vertex_indices\n"
                              "end_header\n");
  for (int i = 0; i < 24; i++) {
    memcpy(bin + b, &cube[i], 8); /* the test machines are little endian, as is the format */
    b += 8;
  }
  bin[b++] = (unsigned char)ns;
  for (int i = 0; i < ns; i++) {
    int32_t v = strip[i];
    memcpy(bin + b, &v, 4);
    b += 4;
  }
  for (int form = 0; form < 2; form++) {
    tr_status s;
    struct tr_plc *p = form ? read_buf(tr_read_ply_buf, (const char *)bin, b, &s)
                            : read_buf(tr_read_ply_buf, text, (size_t)n, &s);
    EXPECT(s == TR_OK, "%s: %s", form ? "binary" : "ascii", tr_last_error());
    EXPECT(p->ntris == 12, "%s: %u triangles (12)", form ? "binary" : "ascii", p->ntris);
    tr_options o;
    tr_options_default(&o);
    o.verbose = 0;
    s = tr_plc_validate(p, &o);
    EXPECT(s == TR_OK, "strip cube valid: %s", tr_last_error());
    EXPECT(*tr_plc_report(p) == 0, "nothing repaired: %s", tr_plc_report(p));
    mpq_t vol;
    mpq_init(vol);
    EXPECT(tr_input_volume6(p, vol) == TR_OK && mpq_cmp_si(vol, 6, 1) == 0,
           "6 x volume = 6, outward");
    mpq_clear(vol);
    tr_plc_destroy(p);
  }
  /* a face marker property (after the index list) reaches both triangles of each quad */
  n = snprintf(text, sizeof text,
               "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
               "property float z\nelement face 6\nproperty list uchar int vertex_indices\n"
               "property int marker\nend_header\n");
  for (int i = 0; i < 8; i++)
    n += snprintf(text + n, sizeof text - (size_t)n, "%g %g %g\n", cube[3 * i], cube[3 * i + 1],
                  cube[3 * i + 2]);
  static const int quad[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                 {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  for (int q = 0; q < 6; q++)
    n += snprintf(text + n, sizeof text - (size_t)n, "4 %d %d %d %d %d\n", quad[q][0], quad[q][1],
                  quad[q][2], quad[q][3], 10 + q);
  {
    tr_status sm;
    struct tr_plc *pm = read_buf(tr_read_ply_buf, text, (size_t)n, &sm);
    EXPECT(sm == TR_OK && pm && pm->ntris == 12, "ply markers: %s", tr_last_error());
    for (uint32_t t = 0; sm == TR_OK && t < pm->ntris; t++)
      EXPECT(pm->tri_marker && pm->tri_marker[t] == 10 + (int32_t)(t / 2),
             "ply markers: triangle %u has marker %d", t, pm->tri_marker ? pm->tri_marker[t] : -1);
    tr_plc_destroy(pm);
  }
  static const char badidx[] = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                               "property float y\nproperty float z\nelement tristrips 1\n"
                               "property list int int vertex_indices\nend_header\n"
                               "0 0 0\n1 0 0\n0 1 0\n4 0 1 2 -2\n";
  tr_status s;
  struct tr_plc *p = read_buf(tr_read_ply_buf, badidx, sizeof badidx - 1, &s);
  EXPECT(s == TR_ERR_INPUT && strstr(tr_last_error(), "vertex index -2 out of range"),
         "-2 in a strip: %s", tr_last_error());
  tr_plc_destroy(p);
}

/* Output names: extension with a letter = a format (or an error), none = TetGen base. */
static void t_out_names(void)
{
  static const struct {
    const char *name;
    enum tr_out_format f;
  } cs[] = {{"a.mesh", TR_OUT_MEDIT}, {"A.VTK", TR_OUT_VTK},     {"x/y.msh", TR_OUT_MSH},
            {"b.vtu", TR_OUT_VTU},    {"c.1", TR_OUT_TETGEN},    {"out", TR_OUT_TETGEN},
            {"d.node", TR_OUT_TETGEN}, {"e.face", TR_OUT_TETGEN}, {"dir.v2/out", TR_OUT_TETGEN},
            {"f.stl", TR_OUT_STL},    {"g.vtk.bak", TR_OUT_UNKNOWN}, {"h.off", TR_OUT_OFF},
            {"i.meshb", TR_OUT_MESHB}, {"j.MESHB", TR_OUT_MESHB}, {"k.xyz", TR_OUT_UNKNOWN}};
  for (size_t i = 0; i < sizeof cs / sizeof cs[0]; i++)
    EXPECT(tr_io_out_format(cs[i].name) == cs[i].f, "%s: format %d, expected %d", cs[i].name,
           tr_io_out_format(cs[i].name), cs[i].f);
  EXPECT(tr_io_check_out_name("x.xyz", 1) == TR_ERR_USAGE &&
             strstr(tr_last_error(), "does not write '.xyz'") &&
             strstr(tr_last_error(), ".meshb") && strstr(tr_last_error(), ".stl"),
         "x.xyz: %s", tr_last_error());
  EXPECT(tr_io_check_out_name("x.off", 0) == TR_ERR_USAGE, "a mesh is not written as .off");
  EXPECT(tr_io_check_out_name("x.stl", 0) == TR_ERR_USAGE &&
             strstr(tr_last_error(), "of a tetrahedral mesh"),
         "a mesh is not written as .stl: %s", tr_last_error());
  EXPECT(tr_io_check_out_name("x.off", 1) == TR_OK, "a surface is");
  EXPECT(tr_io_check_out_name("x.stl", 1) == TR_OK, "a surface is, as .stl too");
  EXPECT(tr_io_check_writable(tpath(tmp, "nodir/x.mesh")) == TR_ERR_IO, "missing directory");
  EXPECT(tr_io_check_writable(tpath(tmp, "probe")) == TR_OK, "TetGen base in tmp: %s", tr_last_error());
  FILE *f = fopen(tpath(tmp, "probe.node"), "r");
  EXPECT(f == NULL, "the probe left probe.node behind");
  if (f)
    fclose(f);
  /* the library refuses an unknown extension instead of writing TetGen files */
  tr_plc *p;
  tr_plc_create(&p);
  static const double x[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  static const uint32_t t[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  tr_plc_set(p, x, 4, t, 4, NULL);
  EXPECT(tr_plc_write(p, tpath(tmp, "w.xyz")) == TR_ERR_USAGE, "tr_plc_write .xyz");
  f = fopen(tpath(tmp, "w.xyz.node"), "r");
  EXPECT(f == NULL, "w.xyz.node written");
  if (f)
    fclose(f);
  tr_plc_destroy(p);
}

/* Pairs of triangles decided one pair at a time (a two-triangle PLC through the failing
 * check) against the collect-all list, on soups with many intersections, for every broad
 * phase: the same pairs, sorted. */
static uint64_t rng = 0x9e3779b97f4a7c15ull;
static double unif(void)
{
  rng ^= rng << 13;
  rng ^= rng >> 7;
  rng ^= rng << 17;
  return (double)(rng >> 11) * 0x1p-53;
}

static void t_selfint_all(void)
{
  for (int round = 0; round < 6; round++) {
    uint32_t nt = 20 + 10 * (uint32_t)round, nv = 3 * nt;
    double *x = malloc(sizeof *x * 3 * nv);
    uint32_t *t = malloc(sizeof *t * 3 * nt);
    for (uint32_t v = 0; v < nv; v++)
      for (int k = 0; k < 3; k++) /* coarse grid coordinates: touching and coplanar cases */
        x[3 * v + k] = round % 2 ? floor(8 * unif()) : unif();
    for (uint32_t i = 0; i < 3 * nt; i++)
      t[i] = i;
    /* some triangles share vertices with the previous one */
    for (uint32_t i = 1; i < nt; i += 3)
      t[3 * i] = t[3 * (i - 1) + 1];
    struct tr_plc p = tm_plc_view(x, nv, t, nt, NULL);
    /* the oracle, pair by pair */
    uint32_t *want = malloc(sizeof *want * nt * nt), nw = 0;
    for (uint32_t i = 0; i < nt; i++)
      for (uint32_t j = i + 1; j < nt; j++) {
        uint32_t u[6];
        memcpy(u, t + 3 * i, 3 * sizeof *u);
        memcpy(u + 3, t + 3 * j, 3 * sizeof *u);
        struct tr_plc q = p;
        q.ntris = 2;
        q.tris = u;
        int zero = 0;
        for (int a = 0; a < 2; a++) { /* zero-area triangles are not the check's input */
          double d[3] = {0, 0, 0};
          const double *A = x + 3 * u[3 * a], *B = x + 3 * u[3 * a + 1], *C = x + 3 * u[3 * a + 2];
          d[0] = (B[1] - A[1]) * (C[2] - A[2]) - (B[2] - A[2]) * (C[1] - A[1]);
          d[1] = (B[2] - A[2]) * (C[0] - A[0]) - (B[0] - A[0]) * (C[2] - A[2]);
          d[2] = (B[0] - A[0]) * (C[1] - A[1]) - (B[1] - A[1]) * (C[0] - A[0]);
          zero |= d[0] == 0 && d[1] == 0 && d[2] == 0;
        }
        if (!zero && tr_input_self_intersections(&q, NULL) == TR_ERR_SELF_INTERSECT) {
          want[2 * nw] = i;
          want[2 * nw++ + 1] = j;
        }
      }
    EXPECT(nw > 3, "round %d: only %u intersecting pairs, the test needs more", round, nw);
    for (int method = TR_SELFINT_AUTO; method <= TR_SELFINT_ALL_PAIRS; method++) {
      uint32_t *got = NULL;
      size_t ng = 0;
      EXPECT(tr_input_self_intersection_pairs(&p, method, &got, &ng) == TR_OK, "%s",
             tr_last_error());
      /* pairs with a zero-area triangle (the oracle skips them) are dropped here too */
      size_t k = 0;
      for (size_t i = 0; i < ng; i++) {
        int skip = 0;
        for (int e = 0; e < 2; e++) {
          const uint32_t *u = t + 3 * got[2 * i + e];
          const double *A = x + 3 * u[0], *B = x + 3 * u[1], *C = x + 3 * u[2];
          double c0 = (B[1] - A[1]) * (C[2] - A[2]) - (B[2] - A[2]) * (C[1] - A[1]);
          double c1 = (B[2] - A[2]) * (C[0] - A[0]) - (B[0] - A[0]) * (C[2] - A[2]);
          double c2 = (B[0] - A[0]) * (C[1] - A[1]) - (B[1] - A[1]) * (C[0] - A[0]);
          skip |= c0 == 0 && c1 == 0 && c2 == 0;
        }
        if (!skip) {
          got[2 * k] = got[2 * i];
          got[2 * k++ + 1] = got[2 * i + 1];
        }
      }
      EXPECT(k == nw && !memcmp(got, want, sizeof *got * 2 * nw),
             "round %d method %d: %zu pairs, the pair-by-pair oracle %u", round, method, k, nw);
      free(got);
    }
    /* the failing check names the least of them */
    if (nw) {
      EXPECT(tr_input_self_intersections(&p, NULL) == TR_ERR_SELF_INTERSECT, "fails");
      char want_msg[64];
      snprintf(want_msg, sizeof want_msg, "triangles %u and %u intersect", want[0], want[1]);
      EXPECT(strstr(tr_last_error(), want_msg), "%s: %s", want_msg, tr_last_error());
    }
    free(want);
    free(x);
    free(t);
  }
}

/* A planar quad and hexagon give nothing; a quad with one corner lifted by h gives one
 * entry whose deviation is the lift's distance from the largest triangle's plane. */
static void t_nonplanar(void)
{
  static const char off[] = "OFF\n10 3 0\n0 0 0\n2 0 0\n2 1 0\n0 1 0\n"
                            "0 0 5\n4 0 5\n4 4 5.5\n0 4 5\n"
                            "9 9 9\n9 9 10\n"
                            "4 0 1 2 3\n4 4 5 6 7\n3 8 9 0\n";
  tr_status s;
  struct tr_plc *p = read_buf(tr_read_off_buf, off, sizeof off - 1, &s);
  EXPECT(s == TR_OK, "%s", tr_last_error());
  tr_nonplanar *np = NULL;
  uint32_t n = 0;
  EXPECT(tr_plc_nonplanar(p, &np, &n) == TR_OK, "%s", tr_last_error());
  EXPECT(n == 1, "%u non-planar polygons (1)", n);
  if (n == 1) {
    EXPECT(np[0].facet == 1 && np[0].first_tri == 2 && np[0].ntris == 2,
           "facet %u triangles %u+%u", np[0].facet, np[0].first_tri, np[0].ntris);
    /* ear clipping cuts the lifted quad along 5-7: the larger triangle is (5, 6, 7), normal
     * (-2, -2, 16), and vertex 4 lies 8 / |n| from its plane */
    double want = 8 / sqrt(264.0);
    EXPECT(fabs(np[0].deviation - want) < 1e-12, "deviation %.17g, expected %.17g",
           np[0].deviation, want);
  }
  free(np);
  tr_plc_destroy(p);
}

/* Steiner points whose written double is moved off their facet / edge by a known amount:
 * the deviation is that distance over the bounding box diagonal, at the right vertex; a
 * Steiner point written exactly counts 0. */
static void t_deviation(void)
{
  static const double x[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  static const uint32_t t[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  tr_plc *p;
  tr_plc_create(&p);
  tr_plc_set(p, x, 4, t, 4, NULL);
  tr_mesh *m = NULL;
  EXPECT(tr_delaunay(x, 4, &m) == TR_OK, "%s", tr_last_error());
  if (!m)
    return;
  double dev;
  uint32_t v;
  EXPECT(tr_mesh_double_deviation(m, p, &dev, &v) == TR_OK && dev == 0 && v == UINT32_MAX,
         "no Steiner point: 0");
  /* on facet z = 0 at (1/3, 1/4, 0), written 2^-30 above it */
  tr_qpoint *q = malloc(sizeof *q);
  tr_qpoint_init(q);
  mpq_set_si(q->c[0], 1, 3);
  mpq_set_si(q->c[1], 1, 4);
  mpq_set_si(q->c[2], 0, 1);
  tr_qpoint_update(q);
  uint32_t a, b;
  tr_mesh_add_steiner(m, q, &a);
  m->xyz[3 * a + 2] = 0x1p-30;
  double diag = sqrt(3.0);
  EXPECT(tr_mesh_double_deviation(m, p, &dev, &v) == TR_OK && dev == 0x1p-30 / diag && v == a,
         "facet point: %.17g at %u, expected %.17g at %u", dev, v, 0x1p-30 / diag, a);
  /* on edge (1,0,0)-(0,1,0) at (1/2, 1/2, 0), a double: written 2^-25 off along z */
  q = malloc(sizeof *q);
  tr_qpoint_init(q);
  mpq_set_si(q->c[0], 1, 2);
  mpq_set_si(q->c[1], 1, 2);
  mpq_set_si(q->c[2], 0, 1);
  tr_qpoint_update(q);
  tr_mesh_add_steiner(m, q, &b);
  EXPECT(tr_mesh_double_deviation(m, p, &dev, &v) == TR_OK && v == a, "exact double point 0");
  m->xyz[3 * b + 2] = -0x1p-25;
  EXPECT(tr_mesh_double_deviation(m, p, &dev, &v) == TR_OK && dev == 0x1p-25 / diag && v == b,
         "edge point: %.17g at %u, expected %.17g at %u", dev, v, 0x1p-25 / diag, b);
  /* along the edge does not count: only the distance from the line */
  m->xyz[3 * b + 2] = 0;
  m->xyz[3 * b] = 0.75;
  m->xyz[3 * b + 1] = 0.25;
  EXPECT(tr_mesh_double_deviation(m, p, &dev, &v) == TR_OK && v == a,
         "a move along the edge: %.17g at %u", dev, v);
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
}

int main(int argc, char **argv)
{
  if (argc < 4) {
    fprintf(stderr, "usage: test_formats SUBTEST DATADIR TMPDIR\n");
    return 2;
  }
  data = argv[2];
  tmp = argv[3];
  (void)data;
  (void)put_file;
  static const struct {
    const char *name;
    void (*fn)(void);
  } tests[] = {{"msh_roundtrip", t_msh_roundtrip}, {"msh_mesh", t_msh_mesh},
               {"msh_reader", t_msh_reader},       {"ply_strips", t_ply_strips},
               {"out_names", t_out_names},         {"selfint_all", t_selfint_all},
               {"nonplanar", t_nonplanar},         {"deviation", t_deviation}};
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
