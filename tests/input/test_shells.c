/* Input semantics of hole points, region points and nested shells (include/tetrec.h
 * tr_plc_add_hole / tr_plc_add_region, src/input/nesting.c, src/outer/points.c). Every
 * mesh goes through the mesh validator and the exact conformity validator with the
 * exact volume expected from the construction (small integers, exact in doubles). */
#define _POSIX_C_SOURCE 200809L /* dup, dup2, fileno: the warnings are read back */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core/plc.h"
#include "input/validate.h"
#include "mesh/check.h"
#include "mesh/conform.h"
#include "pipeline/pipeline.h"

#include "../pipeline/texpect.h"

typedef struct {
  double x[3 * 4096];
  uint32_t np, t[3 * 8192], nt;
} builder;

static uint32_t pt(builder *b, double x, double y, double z)
{
  b->x[3 * b->np] = x, b->x[3 * b->np + 1] = y, b->x[3 * b->np + 2] = z;
  return b->np++;
}

/* The box [lo, lo + s]^3 as 12 triangles facing outward, or into itself if inward. */
static void cube(builder *b, double x, double y, double z, double s, int inward)
{
  uint32_t v[8];
  for (int i = 0; i < 8; i++)
    v[i] = pt(b, x + (i & 1 ? s : 0), y + (i & 2 ? s : 0), z + (i & 4 ? s : 0));
  static const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                              {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (int f = 0; f < 6; f++) {
    uint32_t a = v[q[f][0]], c1 = v[q[f][1]], c2 = v[q[f][2]], d = v[q[f][3]];
    uint32_t tr[2][3] = {{a, c1, c2}, {a, c2, d}};
    for (int k = 0; k < 2; k++) {
      b->t[3 * b->nt] = tr[k][0];
      b->t[3 * b->nt + 1] = inward ? tr[k][2] : tr[k][1];
      b->t[3 * b->nt + 2] = inward ? tr[k][1] : tr[k][2];
      b->nt++;
    }
  }
}

static tr_plc *make(const builder *b)
{
  tr_plc *p = NULL;
  if (tr_plc_create(&p) != TR_OK || tr_plc_set(p, b->x, b->np, b->t, b->nt, NULL) != TR_OK) {
    fprintf(stderr, "cannot build the PLC: %s\n", tr_last_error());
    exit(1);
  }
  return p;
}

/* The box [0,4]^3 with the box [1,3]^3 inside, the inner one given inward or outward. */
static tr_plc *nested(int inner_inward)
{
  static builder b;
  memset(&b, 0, sizeof b);
  cube(&b, 0, 0, 0, 4, 0);
  cube(&b, 1, 1, 1, 2, inner_inward);
  return make(&b);
}

static int verbosity; /* opt.verbose of mesh(); mesh_said() raises it */

/* Meshes p, runs both validators with the expected 6 * volume, and checks that the
 * cell analysis's domain volume of the meshed PLC agrees. NULL on failure. */
static tr_mesh *mesh(const char *name, const tr_plc *p, long vol6, tr_plc **used_out)
{
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = verbosity;
  tr_mesh *m = NULL;
  tr_plc *used = NULL;
  tr_status s = tr_mesh_plc_ex(p, &opt, &m, NULL, &used);
  EXPECT(s == TR_OK, "%s: tr_mesh_plc: %s: %s", name, tr_status_name(s), tr_last_error());
  if (s != TR_OK)
    return NULL;
  EXPECT(tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, NULL) == TR_OK,
         "%s: mesh validator: %s", name, tr_last_error());
  mpq_t v, d;
  mpq_inits(v, d, NULL);
  mpq_set_si(v, vol6, 1);
  EXPECT(tr_check_conformity(m, used, v, 0) == TR_OK, "%s: conformity: %s", name,
         tr_last_error());
  /* the cell analysis (hole points included) measures the same domain */
  EXPECT(tr_input_domain_volume6(used, d) == TR_OK && mpq_equal(d, v),
         "%s: domain volume of the surface %.17g, expected %ld", name, mpq_get_d(d), vol6);
  mpq_clears(v, d, NULL);
  if (used_out)
    *used_out = used;
  else
    tr_plc_destroy(used);
  return m;
}

/* mesh() at verbosity v, with what it wrote to stderr in said[0 .. n) (NUL-terminated);
 * a failure's own lines are passed on. */
static tr_mesh *mesh_said(const char *name, const tr_plc *p, long vol6, int v, char *said,
                          size_t n)
{
  said[0] = 0;
  fflush(stderr);
  FILE *tf = tmpfile();
  int saved = tf ? dup(2) : -1;
  if (saved < 0 || dup2(fileno(tf), 2) < 0) {
    EXPECT(0, "%s: cannot capture stderr", name);
    if (tf)
      fclose(tf);
    if (saved >= 0)
      close(saved);
    return NULL;
  }
  int before = failures;
  verbosity = v;
  tr_mesh *m = mesh(name, p, vol6, NULL);
  verbosity = 0;
  fflush(stderr);
  dup2(saved, 2);
  close(saved);
  rewind(tf);
  size_t k = fread(said, 1, n - 1, tf);
  said[k] = 0;
  fclose(tf);
  if (failures != before)
    fputs(said, stderr);
  return m;
}

static uint32_t max_region(const tr_mesh *m)
{
  uint32_t r = 0;
  for (uint32_t t = 0; t < m->nt; t++)
    r = m->region[t] > r ? m->region[t] : r;
  return r;
}

/* 1 iff the centroid of tet t lies in the open box (lo, hi)^3 (vertices are integers:
 * the centroid is exact in doubles). */
static int centroid_in(const tr_mesh *m, uint32_t t, double lo, double hi)
{
  for (int d = 0; d < 3; d++) {
    double c = 0;
    for (int k = 0; k < 4; k++)
      c += m->xyz[3 * (size_t)m->tv[4 * (size_t)t + k] + d];
    if (!(c / 4 > lo && c / 4 < hi))
      return 0;
  }
  return 1;
}

static void t_hole(void)
{
  tr_plc *p = nested(0); /* given outward: an inclusion, unless the hole point says */
  EXPECT(tr_plc_add_hole(p, 2, 2, 2) == TR_OK, "add_hole: %s", tr_last_error());
  tr_plc *used = NULL;
  tr_mesh *m = mesh("hole_point_in_inner_box", p, 6 * (64 - 8), &used);
  if (m) {
    EXPECT(max_region(m) == 1, "hole: %u regions, expected 1", max_region(m));
    EXPECT(used->ncavities == 1 && used->ninclusions == 0, "hole: %u cavities %u inclusions",
           used->ncavities, used->ninclusions);
    EXPECT(strstr(tr_plc_report(used), "hole point 0 lies in it") != NULL,
           "hole: not reported: %s", tr_plc_report(used));
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
  tr_plc_destroy(p);
  /* a hole point in one of two boxes: disjoint (closed shells, no nesting) or sharing a
   * face (an internal facet: the cell analysis decides the domain) */
  for (int shared = 0; shared < 2; shared++) {
    static builder b2;
    memset(&b2, 0, sizeof b2);
    cube(&b2, 0, 0, 0, 2, 0);
    cube(&b2, shared ? 2 : 3, 0, 0, 2, 0); /* the shared face is given twice: merged */
    if (shared) { /* one vertex per point, so that the shared face's triangles coincide */
      for (uint32_t t = 0; t < 3 * b2.nt; t++)
        for (uint32_t q = 0; q < b2.t[t]; q++)
          if (!memcmp(b2.x + 3 * q, b2.x + 3 * b2.t[t], sizeof(double) * 3)) {
            b2.t[t] = q;
            break;
          }
    }
    p = make(&b2);
    tr_plc_add_hole(p, shared ? 3 : 4, 1, 1);
    m = mesh(shared ? "hole_in_one_of_two_boxes_sharing_a_face" : "hole_in_one_of_two_boxes",
             p, 6 * 8, NULL);
    if (m) {
      uint32_t bad = 0;
      for (uint32_t t = 0; t < m->nt; t++)
        bad += !centroid_in(m, t, 0, 2);
      EXPECT(bad == 0 && max_region(m) == 1, "hole in one of two boxes (shared %d): %u tets "
             "outside the first box, %u regions", shared, bad, max_region(m));
    }
    tr_mesh_destroy(m);
    tr_plc_destroy(p);
  }
  /* a hole point in the only body empties it: nothing is left to mesh */
  static builder b;
  memset(&b, 0, sizeof b);
  cube(&b, 0, 0, 0, 4, 0);
  p = make(&b);
  tr_plc_add_hole(p, 1, 1, 1);
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = 0;
  tr_status s = tr_mesh_plc(p, &opt, &m, NULL);
  EXPECT(s == TR_ERR_INPUT, "hole in the only body: %s, expected TR_ERR_INPUT", tr_status_name(s));
  tr_plc_destroy(p);
}

static void t_regions(void)
{
  tr_plc *p = nested(0);
  tr_plc_add_region(p, 2, 2, 2, 7, 0);
  tr_plc_add_region(p, 0.5, 0.5, 0.5, 3, 0);
  tr_mesh *m = mesh("two_region_points", p, 6 * 64, NULL);
  if (m) {
    uint32_t in = 0, bad = 0;
    for (uint32_t t = 0; t < m->nt; t++) {
      int inside = centroid_in(m, t, 1, 3);
      in += inside;
      bad += m->region[t] != (inside ? 7u : 3u);
    }
    EXPECT(in > 0 && bad == 0, "regions: %u tets with the wrong attribute (%u inside)", bad, in);
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
  /* one region point: its cell takes the attribute, the other keeps the numbering */
  p = nested(0);
  tr_plc_add_region(p, 2, 2, 2, 42, 0);
  m = mesh("one_region_point", p, 6 * 64, NULL);
  if (m) {
    uint32_t bad = 0;
    for (uint32_t t = 0; t < m->nt; t++)
      bad += m->region[t] != (centroid_in(m, t, 1, 3) ? 42u : 1u);
    EXPECT(bad == 0, "one region point: %u tets with the wrong region", bad);
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
}

static void t_nested_kinds(void)
{
  tr_plc *used = NULL;
  tr_plc *p = nested(1);
  tr_mesh *m = mesh("nested_inward_cavity", p, 6 * (64 - 8), &used);
  if (m) {
    EXPECT(max_region(m) == 1, "inward: %u regions, expected 1 (a cavity)", max_region(m));
    EXPECT(used->ncavities == 1 && used->ninclusions == 0, "inward: %u cavities %u inclusions",
           used->ncavities, used->ninclusions);
    EXPECT(strstr(tr_plc_report(used), "faces into itself") != NULL, "inward: report: %s",
           tr_plc_report(used));
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
  tr_plc_destroy(p);
  p = nested(0);
  m = mesh("nested_outward_inclusion", p, 6 * 64, &used);
  if (m) {
    EXPECT(max_region(m) == 2, "outward: %u regions, expected 2 (an inclusion)", max_region(m));
    uint32_t mixed = 0;
    for (uint32_t t = 0; t < m->nt; t++)
      mixed += (m->region[t] == m->region[0]) != (centroid_in(m, t, 1, 3) == centroid_in(m, 0, 1, 3));
    EXPECT(mixed == 0, "outward: %u tets in the wrong region", mixed);
    EXPECT(used->ncavities == 0 && used->ninclusions == 1, "outward: %u cavities %u inclusions",
           used->ncavities, used->ninclusions);
    EXPECT(strstr(tr_plc_report(used), "is an inclusion") != NULL, "outward: report: %s",
           tr_plc_report(used));
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
  tr_plc_destroy(p);
}

static void t_errors(void)
{
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = 0;
  tr_mesh *m = NULL;
  tr_plc *p = nested(0);
  tr_plc_add_hole(p, 2, 2, 3); /* on the inner box's top face */
  tr_status s = tr_mesh_plc(p, &opt, &m, NULL);
  EXPECT(s == TR_ERR_INPUT && strstr(tr_last_error(), "hole point 0"),
         "hole on a facet: %s: %s", tr_status_name(s), tr_last_error());
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
  p = nested(0);
  tr_plc_add_region(p, 5, 5, 5, 1, 0);
  s = tr_mesh_plc(p, &opt, &m, NULL);
  EXPECT(s == TR_ERR_INPUT && strstr(tr_last_error(), "region point 0") &&
         strstr(tr_last_error(), "outside"), "region outside: %s: %s", tr_status_name(s),
         tr_last_error());
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
  p = nested(0);
  tr_plc_add_region(p, 0.5, 0.5, 0.5, 1, 0);
  tr_plc_add_region(p, 3.5, 3.5, 3.5, 2, 0);
  s = tr_mesh_plc(p, &opt, &m, NULL);
  EXPECT(s == TR_ERR_INPUT && strstr(tr_last_error(), "same cell"),
         "two attributes in one cell: %s: %s", tr_status_name(s), tr_last_error());
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
  /* a hole point outside removes nothing: a warning, and the mesh is the same */
  p = nested(1);
  tr_plc_add_hole(p, 9, 9, 9);
  m = mesh("hole_outside", p, 6 * 56, NULL);
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
  /* NaN coordinates are refused at once */
  p = nested(1);
  EXPECT(tr_plc_add_hole(p, 0.0 / 0.0, 1, 1) == TR_ERR_INPUT, "NaN hole point accepted");
  EXPECT(tr_plc_add_region(p, 1, 1, 1, 1, 0.0 / 0.0) == TR_ERR_INPUT, "NaN volume accepted");
  EXPECT(tr_plc_num_holes(p) == 0 && tr_plc_num_regions(p) == 0, "refused points were kept");
  tr_plc_destroy(p);
}

/* A box holding a 4 x 4 x 4 grid of unit boxes, each with a half box inside: the grid
 * boxes alternate inward (cavities) and outward (inclusions); the small boxes are given
 * outward, so in a cavity they are islands and in an inclusion inclusions too. The
 * grid puts a point of one shell in the boxes of several others. Counts, the exact
 * domain volume and the mesh are checked. */
static void t_many(void)
{
  static builder b;
  memset(&b, 0, sizeof b);
  cube(&b, 0, 0, 0, 13, 0);
  long vol6 = 13 * 13 * 13 * 8; /* in units of (1/2)^3: 6 * volume * 8 */
  uint32_t cav = 0, inc = 0;
  for (int i = 0; i < 4; i++)
    for (int j = 0; j < 4; j++)
      for (int k = 0; k < 4; k++) {
        int inward = (i + j + k) & 1;
        double x = 1 + 3 * i, y = 1 + 3 * j, z = 1 + 3 * k;
        cube(&b, x, y, z, 2, inward);
        cube(&b, x + 0.5, y + 0.5, z + 0.5, 1, 0);
        if (inward) {
          cav++;
          vol6 -= 8 * 8 - 1 * 8; /* the cavity minus its island */
        } else
          inc += 2;
      }
  tr_plc *p = make(&b);
  tr_plc *used = NULL;
  tr_mesh *m = mesh("many_nested_shells", p, 6 * vol6 / 8, &used);
  if (m) {
    EXPECT(used->ncavities == cav && used->ninclusions == inc,
           "many: %u cavities %u inclusions, expected %u %u", used->ncavities,
           used->ninclusions, cav, inc);
    /* regions: the outer box, each inclusion (grid box and its half box), each island */
    EXPECT(max_region(m) == 1 + inc + cav, "many: %u regions, expected %u", max_region(m),
           1 + inc + cav);
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
  tr_plc_destroy(p);
  /* all inward: every grid box a cavity, as the rule before inclusions gave */
  memset(&b, 0, sizeof b);
  cube(&b, 0, 0, 0, 13, 0);
  for (int i = 0; i < 64; i++)
    cube(&b, 1 + 3 * (i & 3), 1 + 3 * (i >> 2 & 3), 1 + 3 * (i >> 4), 2, 1);
  p = make(&b);
  m = mesh("many_cavities", p, 6 * (13 * 13 * 13 - 64 * 8), &used);
  if (m)
    EXPECT(used->ncavities == 64 && max_region(m) == 1, "many cavities: %u cavities, %u regions",
           used->ncavities, max_region(m));
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
  tr_plc_destroy(p);
}

/* Thousands of region points, located in one pass (src/outer/points.c, a grid of the
 * points): the box [0,13]^3 holding a 4 x 4 x 4 grid of boxes [1+3i, 3+3i]^3 given
 * outward (inclusions), 8 region points in each box with its own attribute and every
 * point of the half-integer lattice outside the boxes with attribute 7. Each tet's region
 * is checked against the box its centroid lies in. Then the errors name the first
 * offender in point order, and the first triangle in index order: a hole point on the
 * diagonal shared by the outer box's triangles 0 and 1 names triangle 0. */
static void t_many_points(void)
{
  static builder b;
  memset(&b, 0, sizeof b);
  cube(&b, 0, 0, 0, 13, 0);
  for (int i = 0; i < 64; i++)
    cube(&b, 1 + 3 * (i & 3), 1 + 3 * (i >> 2 & 3), 1 + 3 * (i >> 4), 2, 0);
  tr_plc *p = make(&b);
  uint32_t nbody = 0;
  for (int i = 0; i < 64; i++)
    for (int k = 0; k < 8; k++)
      tr_plc_add_region(p, 1.5 + 3 * (i & 3) + (k & 1), 1.5 + 3 * (i >> 2 & 3) + (k >> 1 & 1),
                        1.5 + 3 * (i >> 4) + (k >> 2), 100 + i, 0);
  for (int x = 1; x < 26; x++)
    for (int y = 1; y < 26; y++)
      for (int z = 1; z < 26; z++) {
        double c[3] = {0.5 * x, 0.5 * y, 0.5 * z};
        int in = 1; /* in or on a grid box: all three coordinates in one box's range */
        for (int d = 0; d < 3; d++) {
          double u = c[d] - 1 - 3 * (int)((c[d] - 1) / 3);
          in &= c[d] >= 1 && c[d] <= 12 && u <= 2;
        }
        if (!in) {
          tr_plc_add_region(p, c[0], c[1], c[2], 7, 0);
          nbody++;
        }
      }
  EXPECT(nbody == 25 * 25 * 25 - 64 * 125, "%u lattice points outside the boxes", nbody);
  tr_mesh *m = mesh("many_region_points", p, 6 * 13 * 13 * 13, NULL);
  if (m) {
    uint32_t bad = 0;
    for (uint32_t t = 0; t < m->nt; t++) {
      if (tr_tet_is_free(m, t) || !m->region[t])
        continue;
      uint32_t want = 7;
      for (int i = 0; i < 64; i++) {
        double lo[3] = {1 + 3 * (i & 3), 1 + 3 * (i >> 2 & 3), 1 + 3 * (i >> 4)}, c[3];
        int in = 1;
        for (int d = 0; d < 3; d++) {
          c[d] = 0;
          for (int k = 0; k < 4; k++)
            c[d] += m->xyz[3 * (size_t)m->tv[4 * (size_t)t + k] + d] / 4;
          in &= c[d] > lo[d] && c[d] < lo[d] + 2;
        }
        if (in)
          want = 100 + (uint32_t)i;
      }
      bad += m->region[t] != want;
    }
    EXPECT(bad == 0, "many region points: %u tets with the wrong attribute", bad);
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
  /* errors: the first offending point, and the first triangle it lies on */
  memset(&b, 0, sizeof b);
  cube(&b, 0, 0, 0, 4, 0);
  p = make(&b);
  for (int i = 0; i < 50; i++)
    tr_plc_add_hole(p, 9, 9, 9 + i); /* outside: warnings only */
  tr_plc_add_hole(p, 2, 2, 0); /* on the diagonal of triangles 0 and 1 */
  tr_plc_add_hole(p, 0, 2, 2); /* on another face: not the one reported */
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = 0;
  m = NULL;
  tr_status s = tr_mesh_plc(p, &opt, &m, NULL);
  EXPECT(s == TR_ERR_INPUT && strstr(tr_last_error(), "hole point 50 ") &&
         strstr(tr_last_error(), "triangle 0 "), "first hole point on a facet: %s: %s",
         tr_status_name(s), tr_last_error());
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
}

/* An input segment inside a box (tr_plc_add_segments) is a chain of mesh edges; bad
 * segments are refused. */
static void t_segments(void)
{
  static builder b;
  memset(&b, 0, sizeof b);
  cube(&b, 0, 0, 0, 4, 0);
  uint32_t s[2] = {pt(&b, 1, 1, 1), pt(&b, 3, 2.5, 2)};
  tr_plc *p = make(&b);
  uint32_t bad[2] = {0, 99}, same[2] = {3, 3};
  EXPECT(tr_plc_add_segments(p, bad, 1) == TR_ERR_INPUT, "segment out of range accepted");
  EXPECT(tr_plc_add_segments(p, same, 1) == TR_ERR_INPUT, "segment with one vertex accepted");
  EXPECT(tr_plc_add_segments(p, s, 1) == TR_OK && p->nsegs == 1, "segment refused: %s",
         tr_last_error());
  tr_mesh *m = mesh("segment_inside_a_box", p, 6 * 64, NULL);
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
}

/* The box [0,4]^3 cut by the internal facet x = 2 (so the cell analysis, not the
 * closed-shell nesting, decides the domain) holding the box B = [0.5,1.5]x[1,3]x[1,3],
 * as a .poly whose facets carry no orientation: B's first facet is listed facing into
 * B, its other five facing out (as TetGen's example.poly lists its inner box), and the
 * hole points are hx[0 .. nh). */
static int write_split_box(const char *path, const double (*hx)[3], int nh)
{
  FILE *f = fopen(path, "w");
  if (!f)
    return 0;
  fprintf(f, "20 3 0 0\n");
  for (int k = 0; k < 2; k++) /* 1..12: x in {0,2,4}, y in {0,4}, z in {0,4} */
    for (int j = 0; j < 2; j++)
      for (int i = 0; i < 3; i++)
        fprintf(f, "%d %d %d %d\n", 1 + i + 3 * j + 6 * k, 2 * i, 4 * j, 4 * k);
  for (int i = 0; i < 8; i++) /* 13..20: B, bit 0 x, bit 1 y, bit 2 z */
    fprintf(f, "%d %g %d %d\n", 13 + i, i & 1 ? 1.5 : 0.5, i & 2 ? 3 : 1, i & 4 ? 3 : 1);
  fprintf(f, "17 0\n");
  for (int i = 0; i < 3; i++) /* x = 0, the internal x = 2, x = 4 */
    fprintf(f, "1\n4 %d %d %d %d\n", 1 + i, 4 + i, 10 + i, 7 + i);
  for (int i = 0; i < 2; i++) /* y = 0, y = 4, z = 0, z = 4 over each half */
    fprintf(f, "1\n4 %d %d %d %d\n1\n4 %d %d %d %d\n1\n4 %d %d %d %d\n1\n4 %d %d %d %d\n",
            1 + i, 2 + i, 8 + i, 7 + i, 4 + i, 5 + i, 11 + i, 10 + i, 1 + i, 2 + i, 5 + i,
            4 + i, 7 + i, 8 + i, 11 + i, 10 + i);
  static const int q[6][4] = {{1, 3, 2, 0}, {4, 5, 7, 6}, {0, 1, 5, 4}, /* first: inward */
                              {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (int k = 0; k < 6; k++)
    fprintf(f, "1\n4 %d %d %d %d\n", 13 + q[k][0], 13 + q[k][1], 13 + q[k][2], 13 + q[k][3]);
  fprintf(f, "%d\n", nh);
  for (int h = 0; h < nh; h++)
    fprintf(f, "%d %g %g %g\n", h + 1, hx[h][0], hx[h][1], hx[h][2]);
  fprintf(f, "0\n");
  return fclose(f) == 0;
}

/* 1 iff the centroid of tet t lies in the open box B of write_split_box. */
static int centroid_in_b(const tr_mesh *m, uint32_t t)
{
  static const double lo[3] = {0.5, 1, 1}, hi[3] = {1.5, 3, 3};
  for (int d = 0; d < 3; d++) {
    double c = 0;
    for (int k = 0; k < 4; k++)
      c += m->xyz[3 * (size_t)m->tv[4 * (size_t)t + k] + d];
    if (!(c / 4 > lo[d] && c / 4 < hi[d]))
      return 0;
  }
  return 1;
}

/* Issue 50, 6b (TetGen's example.poly): a hole point in an inner box whose first facet
 * happens to be listed inward empties the box, and says nothing at -v: the box is an
 * inclusion by the majority of its facets as given (it was taken for a cavity by the
 * orientation of its first facet, and the hole point warned "outside the domain: it
 * removes nothing"). Without the hole point the box is meshed, as TetGen meshes it. */
static void t_hole_box_poly(const char *dir)
{
  char path[4096], said[1 << 16];
  static const double hx[2][3] = {{1, 2, 2}, {9, 9, 9}};
  for (int nh = 0; nh <= 2; nh++) {
    snprintf(path, sizeof path, "%s/split_box_holes%d.poly", dir, nh);
    EXPECT(write_split_box(path, hx, nh), "cannot write %s", path);
    tr_plc *p = NULL;
    tr_status s = tr_plc_read(path, &p);
    EXPECT(s == TR_OK, "read %s: %s", path, tr_last_error());
    if (s != TR_OK)
      continue;
    tr_mesh *m = mesh_said(path, p, 6 * (nh ? 64 - 4 : 64), 1, said, sizeof said);
    if (m) {
      uint32_t in_b = 0, mixed = 0;
      for (uint32_t t = 0; t < m->nt; t++) {
        int b = centroid_in_b(m, t);
        in_b += b;
        mixed += b && m->region[t] == m->region[0] && !centroid_in_b(m, 0);
      }
      EXPECT(nh ? in_b == 0 : in_b > 0 && mixed == 0,
             "holes %d: %u tets in the box, %u of them in a region outside it", nh, in_b, mixed);
    }
    EXPECT(!strstr(said, "hole point 0"), "holes %d: hole point 0 in the box reported: %s",
           nh, said);
    /* one outside both halves removes nothing: that warning stays */
    EXPECT((nh == 2) == (strstr(said, "warning: hole point 1") &&
                         strstr(said, "it removes nothing")),
           "holes %d: the warning for the hole point outside: %s", nh, said);
    tr_mesh_destroy(m);
    tr_plc_destroy(p);
  }
}

/* A hole point in a cavity the surface leaves empty anyway (a box given facing into
 * itself) did what it asked: no warning at -v, and at -v -v exactly that; a hole point
 * outside every shell is warned about. The closed-shell nesting decides here. */
static void t_hole_said(void)
{
  char said[1 << 16];
  tr_plc *p = nested(1);
  tr_plc_add_hole(p, 2, 2, 2);
  tr_plc_add_hole(p, 9, 9, 9);
  for (int v = 1; v <= 2; v++) {
    tr_mesh *m = mesh_said("hole_in_cavity_and_outside", p, 6 * (64 - 8), v, said, sizeof said);
    EXPECT(m && max_region(m) == 1, "hole in a cavity: not one region left");
    EXPECT((v == 2) == (strstr(said, "tetrec: hole point 0 lies in a cavity the surface "
                                     "already leaves empty") != NULL) &&
               !strstr(said, "warning: hole point 0"),
           "-v x%d: hole point 0 in the inward box: %s", v, said);
    EXPECT(strstr(said, "warning: hole point 1 (9, 9, 9) lies outside the domain: it "
                        "removes nothing") != NULL,
           "-v x%d: hole point 1 outside not warned about: %s", v, said);
    tr_mesh_destroy(m);
  }
  tr_plc_destroy(p);
}

/* The hole and region sections of a .poly file reach the PLC and the mesh. */
static void t_poly(const char *dir)
{
  char path[4096];
  snprintf(path, sizeof path, "%s/box_hole_regions.poly", dir);
  FILE *f = fopen(path, "w");
  if (!f) {
    EXPECT(0, "cannot write %s", path);
    return;
  }
  fprintf(f, "# a 4-box with two 1-boxes inside, both given outward\n24 3 0 0\n");
  const double c[3][2] = {{0, 4}, {0.5, 1.5}, {2.5, 3.5}};
  for (int bx = 0; bx < 3; bx++)
    for (int i = 0; i < 8; i++)
      fprintf(f, "%d %g %g %g\n", 8 * bx + i + 1, c[bx][i & 1], c[bx][i >> 1 & 1], c[bx][i >> 2]);
  static const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                              {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  fprintf(f, "18 0\n");
  for (int bx = 0; bx < 3; bx++)
    for (int k = 0; k < 6; k++)
      fprintf(f, "1\n4 %d %d %d %d\n", 8 * bx + q[k][0] + 1, 8 * bx + q[k][1] + 1,
              8 * bx + q[k][2] + 1, 8 * bx + q[k][3] + 1);
  fprintf(f, "1\n1 1 1 1\n2\n1 3 3 3 5 0\n2 2 2 2 9 0.25\n");
  fclose(f);
  tr_plc *p = NULL;
  tr_status s = tr_plc_read(path, &p);
  EXPECT(s == TR_OK, "read %s: %s", path, tr_last_error());
  if (s != TR_OK)
    return;
  EXPECT(tr_plc_num_holes(p) == 1 && tr_plc_num_regions(p) == 2 && p->region_attr[1] == 9 &&
         p->region_maxvol[1] == 0.25, "poly: %u holes, %u regions read", tr_plc_num_holes(p),
         tr_plc_num_regions(p));
  tr_mesh *m = mesh("poly_hole_and_regions", p, 6 * (64 - 1), NULL);
  if (m) {
    uint32_t bad = 0;
    for (uint32_t t = 0; t < m->nt; t++)
      bad += m->region[t] != (centroid_in(m, t, 2.5, 3.5) ? 5u : 9u);
    EXPECT(bad == 0, "poly: %u tets with the wrong region", bad);
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
  /* .smesh: the same sections after its facets */
  snprintf(path, sizeof path, "%s/tet_region.smesh", dir);
  if (!(f = fopen(path, "w"))) {
    EXPECT(0, "cannot write %s", path);
    return;
  }
  fprintf(f, "4 3 0 0\n0 0 0 0\n1 6 0 0\n2 0 6 0\n3 0 0 6\n4 0\n3 0 2 1\n3 0 1 3\n"
             "3 0 3 2\n3 1 2 3\n0\n1\n1 1 1 1 -3\n");
  fclose(f);
  if ((s = tr_plc_read(path, &p)) != TR_OK) {
    EXPECT(0, "read %s: %s", path, tr_last_error());
    return;
  }
  m = mesh("smesh_region", p, 216, NULL);
  if (m)
    for (uint32_t t = 0; t < m->nt; t++)
      EXPECT((int32_t)m->region[t] == -3, "smesh: tet %u has region %d", t, (int32_t)m->region[t]);
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
}

int main(int argc, char **argv)
{
  const char *w = argc > 1 ? argv[1] : "all";
  int all = !strcmp(w, "all");
  if (all || !strcmp(w, "hole"))
    t_hole();
  if (all || !strcmp(w, "regions"))
    t_regions();
  if (all || !strcmp(w, "nested"))
    t_nested_kinds();
  if (all || !strcmp(w, "errors"))
    t_errors();
  if (all || !strcmp(w, "many"))
    t_many();
  if (all || !strcmp(w, "many_points"))
    t_many_points();
  if (all || !strcmp(w, "segments"))
    t_segments();
  if (all || !strcmp(w, "poly"))
    t_poly(argc > 2 ? argv[2] : ".");
  if (all || !strcmp(w, "hole_box_poly"))
    t_hole_box_poly(argc > 2 ? argv[2] : ".");
  if (all || !strcmp(w, "hole_said"))
    t_hole_said();
  if (failures)
    fprintf(stderr, "%d failure(s)\n", failures);
  return failures ? 1 : 0;
}
