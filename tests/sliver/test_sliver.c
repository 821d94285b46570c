/* Sliver removal (src/sliver/sliver.h): on hand-made meshes (the Delaunay mesh of a box
 * with a sliver inside) and through the whole pipeline on refined surfaces from
 * tests/data. Every mesh goes through the mesh validator (links, exact orientation, v2t)
 * and, the pipeline's, through the exact conformity validator (every input edge a chain
 * of mesh edges, every input triangle exactly covered, exact volume). */
#include <gmp.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "mesh/conform.h"
#include "pipeline/pipeline.h"
#include "refine/quality.h"
#include "refine/refine.h"
#include "sliver/sliver.h"
#include "../pipeline/texpect.h"

/* The box [0,1]^3 (vertices 0..7) and a sliver: a square at z = 1/2 folded by e, its
 * corners alternately up and down (vertices 8..11). Its circumsphere is centred in the
 * square, so the four points form a Delaunay tet with dihedral angles near 0 and 180. */
static tr_mesh *sliver_box(double e)
{
  double x[36];
  for (int i = 0; i < 8; i++)
    for (int k = 0; k < 3; k++)
      x[3 * i + k] = (i >> k) & 1 ? 1.0 : 0.0;
  const double sq[4][3] = {{0.375, 0.375, 0.5 + e}, {0.625, 0.375, 0.5 - e},
                           {0.625, 0.625, 0.5 + e}, {0.375, 0.625, 0.5 - e}};
  memcpy(x + 24, sq, sizeof sq);
  tr_mesh *m = NULL;
  if (tr_delaunay_build(x, 12, &m) != TR_OK) {
    fprintf(stderr, "Delaunay failed: %s\n", tr_last_error());
    exit(1);
  }
  return m;
}

/* 1 iff some live tet has exactly the vertices v (any order). */
static int has_tet(const tr_mesh *m, const uint32_t v[4])
{
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    int n = 0;
    for (int i = 0; i < 4; i++)
      n += tr_ncode(m, t, v[i]) >= 0;
    if (n == 4)
      return 1;
  }
  return 0;
}

static double min_dihedral(const tr_mesh *m)
{
  tr_quality q;
  tr_quality_measure(m, &q);
  return q.min_dihedral;
}

/* The validator, and the exact volume of the box (6 * 1). */
static void valid_box(const char *name, const tr_mesh *m)
{
  mpq_t six;
  mpq_init(six);
  mpq_set_ui(six, 6, 1);
  tr_status s = tr_check_mesh(m, TR_CHK_TOPOLOGY, six);
  EXPECT(s == TR_OK, "%s: mesh validator: %s", name, tr_last_error());
  mpq_clear(six);
}

static void a_sliver_is_removed_by_a_flip(void)
{
  tr_mesh *m = sliver_box(0.01);
  const uint32_t sl[4] = {8, 9, 10, 11};
  EXPECT(has_tet(m, sl), "the folded square is not a tet of the Delaunay mesh");
  double before = min_dihedral(m);
  EXPECT(before < 5, "the sliver's smallest angle %g is not small", before);
  tr_subfaces none = {0, NULL, NULL};
  tr_sliver_params par = {TR_SLIVER_FLIPS, TR_SLIVER_BOUND, TR_SLIVER_ROUNDS, 0, {0, 0, NULL, 0}};
  tr_sliver_stats st;
  tr_status s = tr_sliver_remove(m, &none, NULL, 8, &par, &st);
  EXPECT(s == TR_OK, "sliver stage: %s", tr_last_error());
  EXPECT(!has_tet(m, sl), "the sliver is still there");
  EXPECT(st.flips23 + st.flips32 + st.flips44 + st.flipsn > 0 && st.smoothed == 0 &&
             st.points == 0, "flips only were asked for");
  double after = min_dihedral(m);
  EXPECT(after > before, "smallest dihedral angle %g -> %g: not raised", before, after);
  valid_box("flip", m);
  tr_mesh_destroy(m);
}

/* A sub-face through the sliver's diagonal 8-10 and a vertex (9) given as lying on an input
 * triangle: neither the face nor the edge is flipped away, 8, 9, 10 do not move, and the
 * free vertex 11 may. */
static void constraints_are_kept_and_their_vertices_stay(void)
{
  tr_mesh *m = sliver_box(0.01);
  uint32_t f[3] = {8, 10, 9}, t = TR_NONE;
  tr_ball_find(m, 8, 10, 9, &t);
  EXPECT(t != TR_NONE, "8 10 9 is not a face");
  uint32_t tri = 0;
  tr_subfaces sub = {1, f, &tri};
  uint8_t vkind[12];
  for (int v = 0; v < 12; v++)
    vkind[v] = v < 8 ? TR_VERTEX_INPUT : TR_VERTEX_INTERIOR;
  vkind[9] = TR_VERTEX_ON_TRIANGLE;
  double x0[36];
  memcpy(x0, m->xyz, sizeof x0);
  double before = min_dihedral(m);
  tr_sliver_params par = {TR_SLIVER_SMOOTH, TR_SLIVER_BOUND, TR_SLIVER_ROUNDS, 0, {0, 0, NULL, 0}};
  tr_sliver_stats st;
  tr_status s = tr_sliver_remove(m, &sub, vkind, 8, &par, &st);
  EXPECT(s == TR_OK, "sliver stage: %s", tr_last_error());
  for (uint32_t v = 0; v < 11; v++)
    EXPECT(!memcmp(x0 + 3 * v, m->xyz + 3 * (size_t)v, 24), "vertex %u moved", v);
  t = TR_NONE;
  tr_ball_find(m, 8, 10, 9, &t);
  EXPECT(t != TR_NONE, "the sub-face 8 10 9 was flipped away");
  double after = min_dihedral(m);
  EXPECT(after >= before, "smallest dihedral angle %g -> %g: lowered", before, after);
  valid_box("constraints", m);
  tr_mesh_destroy(m);
}

/* The insertion pass alone on the folded square with the sub-face 8 10 9 (no vertex may
 * move): the sliver is replaced by the cone from a new double point, which lies strictly
 * inside the box and off the sub-face's plane (exact), the sub-face stays, every input
 * vertex stays, the smallest angle rises, the mesh validates. */
static void a_sliver_is_removed_by_a_new_interior_point(void)
{
  tr_mesh *m = sliver_box(0.01);
  const uint32_t sl[4] = {8, 9, 10, 11};
  uint32_t f[3] = {8, 10, 9}, tri = 0, t = TR_NONE;
  tr_subfaces sub = {1, f, &tri};
  double before = min_dihedral(m), x0[36];
  memcpy(x0, m->xyz, sizeof x0);
  tr_sliver_ctx c;
  tr_sliver_stats st;
  memset(&st, 0, sizeof st);
  tr_status s = tr_sliver_ctx_init(&c, m, &sub, NULL, 12, TR_SLIVER_BOUND);
  if (s == TR_OK)
    s = tr_sliver_insert_pass(&c, &st);
  EXPECT(s == TR_OK, "insertion: %s", tr_last_error());
  tr_sliver_ctx_free(&c);
  EXPECT(st.points >= 1 && m->nv == 12 + st.points, "%llu points added, %u vertices",
         (unsigned long long)st.points, m->nv);
  EXPECT(!has_tet(m, sl), "the sliver is still there");
  tr_ball_find(m, 8, 10, 9, &t);
  EXPECT(t != TR_NONE, "the sub-face 8 10 9 is gone");
  for (uint32_t v = 0; v < 12; v++)
    EXPECT(!memcmp(x0 + 3 * v, m->xyz + 3 * (size_t)v, 24), "vertex %u moved", v);
  tr_point a = tr_mesh_point(m, 8), b = tr_mesh_point(m, 10), d = tr_mesh_point(m, 9);
  for (uint32_t v = 12; v < m->nv; v++) {
    const double *x = m->xyz + 3 * (size_t)v;
    EXPECT(!(m->vq && m->vq[v]), "new vertex %u is not a double", v);
    for (int k = 0; k < 3; k++)
      EXPECT(x[k] > 0 && x[k] < 1, "new vertex %u not strictly inside the box", v);
    tr_point p = tr_pt_d(x);
    EXPECT(tr_orient3d_p(&a, &b, &d, &p) != 0, "new vertex %u on the sub-face's plane", v);
    EXPECT(m->v2t[v] != TR_NONE, "new vertex %u in no tet", v);
  }
  double after = min_dihedral(m);
  EXPECT(after > before, "smallest dihedral angle %g -> %g: not raised", before, after);
  valid_box("insertion", m);
  tr_mesh_destroy(m);
}

/* The smallest dihedral angle of the tets at vertex v. */
static double star_min(const tr_mesh *m, uint32_t v)
{
  double q = 180;
  for (uint32_t t = 0; t < m->nt; t++)
    if (tr_tet_is_real(m, t) && tr_ncode(m, t, v) >= 0) {
      const uint32_t *w = m->tv + 4 * (size_t)t;
      q = fmin(q, tr_sliver_min_dihedral(m, w[0], w[1], w[2], w[3]));
    }
  return q;
}

/* One smoothing pass with 11 the only vertex that may move (npoints 11, no sub-faces):
 * it moves, the smallest angle of its star rises, the mesh's does not drop, every tet
 * stays exactly positive. */
static void smoothing_moves_a_free_vertex_and_raises_the_angle(void)
{
  tr_mesh *m = sliver_box(0.01);
  double before = min_dihedral(m), star0 = star_min(m, 11), x0[36];
  memcpy(x0, m->xyz, sizeof x0);
  tr_subfaces none = {0, NULL, NULL};
  tr_sliver_ctx c;
  tr_sliver_stats st;
  memset(&st, 0, sizeof st);
  tr_status s = tr_sliver_ctx_init(&c, m, &none, NULL, 11, TR_SLIVER_BOUND);
  if (s == TR_OK)
    s = tr_sliver_smooth_pass(&c, &st);
  EXPECT(s == TR_OK, "smoothing: %s", tr_last_error());
  tr_sliver_ctx_free(&c);
  EXPECT(st.smoothed == 1, "%llu vertices moved, 11 only may", (unsigned long long)st.smoothed);
  for (uint32_t v = 0; v < 11; v++)
    EXPECT(!memcmp(x0 + 3 * v, m->xyz + 3 * (size_t)v, 24), "vertex %u moved", v);
  double after = min_dihedral(m), star1 = star_min(m, 11);
  EXPECT(star1 > star0, "smallest dihedral angle at 11 %g -> %g: not raised", star0, star1);
  EXPECT(after >= before, "smallest dihedral angle %g -> %g: lowered", before, after);
  valid_box("smoothing", m);
  tr_mesh_destroy(m);
}

/* Every flip pass and smoothing pass on a box with several slivers leaves the smallest
 * dihedral angle where it was or higher, and a valid mesh. */
static void no_pass_lowers_the_smallest_angle(void)
{
  for (int i = 1; i <= 4; i++) {
    tr_mesh *m = sliver_box(0.002 * i);
    tr_subfaces none = {0, NULL, NULL};
    tr_sliver_ctx c;
    tr_sliver_stats st;
    memset(&st, 0, sizeof st);
    tr_status s = tr_sliver_ctx_init(&c, m, &none, NULL, 8, TR_SLIVER_BOUND);
    double q = min_dihedral(m);
    for (int pass = 0; pass < 6 && s == TR_OK; pass++) {
      s = pass % 2 ? tr_sliver_smooth_pass(&c, &st) : tr_sliver_flip_pass(&c, &st);
      double r = min_dihedral(m);
      EXPECT(r >= q, "fold %d pass %d: smallest dihedral angle %g -> %g", i, pass, q, r);
      q = r;
    }
    EXPECT(s == TR_OK, "passes: %s", tr_last_error());
    tr_sliver_ctx_free(&c);
    valid_box("passes", m);
    tr_mesh_destroy(m);
  }
}

/* Meshes plc with --quality R and the given level; validators; NULL on failure. */
static tr_mesh *mesh(const char *name, const tr_plc *plc, int level, unsigned chk,
                     tr_plc **used, tr_stats *st)
{
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = 0;
  opt.quality_ratio = 1.414;
  opt.optimize = level;
  tr_mesh *m = NULL;
  memset(st, 0, sizeof *st);
  st->size = sizeof *st;
  tr_status s = tr_mesh_plc_ex(plc, &opt, &m, st, used);
  if (s != TR_OK) {
    EXPECT(0, "%s -O %d: tr_mesh_plc failed: %s: %s", name, level, tr_status_name(s),
           tr_last_error());
    return NULL;
  }
  s = tr_check_mesh(m, chk, NULL);
  EXPECT(s == TR_OK, "%s -O %d: mesh validator: %s", name, level, tr_last_error());
  s = tr_check_conformity(m, *used, NULL, 0);
  EXPECT(s == TR_OK, "%s -O %d: exact conformity: %s", name, level, tr_last_error());
  return m;
}

/* Refined surfaces of tests/data with and without the stage: all validate, level 2 adds no
 * point, keeps every input vertex where it was, never lowers the smallest dihedral angle,
 * leaves no more tets under 10 degrees, and keeps the ratio bound on the tets with an angle
 * under its bound; level 3 (new points) keeps the input vertices, the smallest angle and
 * the ratio bound too. */
static void refined_surfaces(const char *dir)
{
  const char *files[] = {"schoenhardt.off", "cavity.off", "cube_facets.poly", "two_cubes.off",
                         "star_rounding_budget.off"};
  for (size_t i = 0; i < sizeof files / sizeof *files; i++) {
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, files[i]);
    tr_plc *p = NULL;
    if (tr_plc_read(path, &p) != TR_OK) {
      EXPECT(0, "%s: %s", path, tr_last_error());
      continue;
    }
    /* a cavity or two cubes are not a ball: no Euler check (the volume is checked exactly) */
    unsigned chk = TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T;
    tr_plc *u0 = NULL, *u2 = NULL, *u3 = NULL;
    tr_stats s0, s2, s3;
    tr_mesh *m0 = mesh(files[i], p, 0, chk, &u0, &s0);
    tr_mesh *m2 = mesh(files[i], p, 2, chk, &u2, &s2);
    tr_mesh *m3 = mesh(files[i], p, 3, chk, &u3, &s3);
    if (m0 && m3) {
      EXPECT(s3.min_dihedral >= s0.min_dihedral, "%s -O 3: smallest dihedral %g -> %g",
             files[i], s0.min_dihedral, s3.min_dihedral);
      EXPECT(s3.volume_nodes == s0.volume_nodes + s3.points_added_for_sliver,
             "%s -O 3: %llu vertices, %llu without the stage and %llu points added", files[i],
             (unsigned long long)s3.volume_nodes, (unsigned long long)s0.volume_nodes,
             (unsigned long long)s3.points_added_for_sliver);
      double worst0 = 0, worst3 = 0;
      for (int k = 0; k < 2; k++) {
        const tr_mesh *m = k ? m3 : m0;
        for (uint32_t t = 0; t < m->nt; t++) {
          double r = 0, q;
          if (!tr_tet_is_real(m, t))
            continue;
          q = tr_sliver_min_dihedral_at(m, m->tv + 4 * (size_t)t, TR_NONE, NULL, &r);
          if (!k)
            worst0 = fmax(worst0, r);
          else if (q < TR_SLIVER_BOUND)
            worst3 = fmax(worst3, r);
        }
      }
      EXPECT(worst3 <= fmax(1.414, worst0) * (1 + 1e-9),
             "%s -O 3: a tet under %g degrees has ratio %g above max(1.414, %g)", files[i],
             TR_SLIVER_BOUND, worst3, worst0);
      for (uint32_t v = 0; v < m3->nv && v < m0->nv; v++) {
        int k0, k3;
        uint32_t x0, x3;
        if (tr_mesh_vertex_origin(m0, v, &k0, &x0) != TR_OK ||
            tr_mesh_vertex_origin(m3, v, &k3, &x3) != TR_OK) {
          EXPECT(0, "%s: vertex origin %u: %s", files[i], v, tr_last_error());
          break;
        }
        if (k0 == TR_VERTEX_INPUT || k3 == TR_VERTEX_INPUT)
          EXPECT(k0 == k3 && !memcmp(m0->xyz + 3 * (size_t)v, m3->xyz + 3 * (size_t)v, 24),
                 "%s -O 3: input vertex %u moved", files[i], v);
      }
      fprintf(stderr, "%s -O 3: min dihedral %.3f -> %.3f, under 10 deg %llu -> %llu, "
              "%llu points added\n", files[i], s0.min_dihedral, s3.min_dihedral,
              (unsigned long long)s0.tets_dihedral_below_10,
              (unsigned long long)s3.tets_dihedral_below_10,
              (unsigned long long)s3.points_added_for_sliver);
    }
    tr_mesh_destroy(m3);
    tr_plc_destroy(u3);
    if (m0 && m2) {
      EXPECT(s2.points_added_for_sliver == 0 && s0.volume_nodes == s2.volume_nodes,
             "%s: the stage added points (%llu -> %llu vertices)", files[i],
             (unsigned long long)s0.volume_nodes, (unsigned long long)s2.volume_nodes);
      EXPECT(s0.sliver_flips == 0 && s0.sliver_points_smoothed == 0,
             "%s: -O 0 flipped or moved", files[i]);
      EXPECT(s2.min_dihedral >= s0.min_dihedral, "%s: smallest dihedral %g -> %g", files[i],
             s0.min_dihedral, s2.min_dihedral);
      EXPECT(s2.tets_dihedral_below_10 <= s0.tets_dihedral_below_10,
             "%s: tets under 10 degrees %llu -> %llu", files[i],
             (unsigned long long)s0.tets_dihedral_below_10,
             (unsigned long long)s2.tets_dihedral_below_10);
      /* the ratio bound holds for every tet with an angle under the stage's bound, up to
       * the worst ratio refinement left (exempt tets); the written doubles of Steiner
       * points may differ from the ones the stage measured by a few ulps */
      double worst0 = 0, worst2 = 0;
      for (int k = 0; k < 2; k++) {
        const tr_mesh *m = k ? m2 : m0;
        for (uint32_t t = 0; t < m->nt; t++) {
          double r = 0, q;
          if (!tr_tet_is_real(m, t))
            continue;
          q = tr_sliver_min_dihedral_at(m, m->tv + 4 * (size_t)t, TR_NONE, NULL, &r);
          if (!k)
            worst0 = fmax(worst0, r);
          else if (q < TR_SLIVER_BOUND)
            worst2 = fmax(worst2, r);
        }
      }
      EXPECT(worst2 <= fmax(1.414, worst0) * (1 + 1e-9),
             "%s: a tet under %g degrees has ratio %g above max(1.414, %g)", files[i],
             TR_SLIVER_BOUND, worst2, worst0);
      for (uint32_t v = 0; v < m2->nv && v < m0->nv; v++) {
        int k0, k2;
        uint32_t x0, x2;
        if (tr_mesh_vertex_origin(m0, v, &k0, &x0) != TR_OK ||
            tr_mesh_vertex_origin(m2, v, &k2, &x2) != TR_OK) {
          EXPECT(0, "%s: vertex origin %u: %s", files[i], v, tr_last_error());
          break;
        }
        if (k0 == TR_VERTEX_INPUT || k2 == TR_VERTEX_INPUT)
          EXPECT(k0 == k2 && !memcmp(m0->xyz + 3 * (size_t)v, m2->xyz + 3 * (size_t)v, 24),
                 "%s: input vertex %u moved", files[i], v);
      }
      fprintf(stderr, "%s: min dihedral %.3f -> %.3f, under 10 deg %llu -> %llu, %llu flips, "
              "%llu moved\n", files[i], s0.min_dihedral, s2.min_dihedral,
              (unsigned long long)s0.tets_dihedral_below_10,
              (unsigned long long)s2.tets_dihedral_below_10,
              (unsigned long long)s2.sliver_flips,
              (unsigned long long)s2.sliver_points_smoothed);
    }
    tr_mesh_destroy(m0);
    tr_mesh_destroy(m2);
    tr_plc_destroy(u0);
    tr_plc_destroy(u2);
    tr_plc_destroy(p);
  }
}

/* The regular icosahedron (0, +-1, +-phi) and its cyclic permutations, its 20 faces
 * oriented outward, into plc. */
static tr_status icosahedron(tr_plc **plc)
{
  const double f = (1 + sqrt(5.0)) / 2;
  double x[36];
  for (int i = 0; i < 12; i++) {
    double a[3] = {0, i & 1 ? -1 : 1, i & 2 ? -f : f};
    for (int k = 0; k < 3; k++)
      x[3 * i + k] = a[(k + 3 - i / 4) % 3];
  }
  uint32_t tris[60], n = 0;
  for (uint32_t a = 0; a < 12; a++)
    for (uint32_t b = a + 1; b < 12; b++)
      for (uint32_t c = b + 1; c < 12; c++) {
        const double *p[3] = {x + 3 * a, x + 3 * b, x + 3 * c};
        int edges = 0; /* the 30 edges have length 2, every other pair is longer */
        for (int i = 0; i < 3; i++) {
          double d = 0;
          for (int k = 0; k < 3; k++)
            d += (p[i][k] - p[(i + 1) % 3][k]) * (p[i][k] - p[(i + 1) % 3][k]);
          edges += d < 4.5;
        }
        if (edges < 3 || n >= 60)
          continue;
        double u[3], v[3], nn = 0;
        for (int k = 0; k < 3; k++)
          u[k] = p[1][k] - p[0][k], v[k] = p[2][k] - p[0][k];
        for (int k = 0; k < 3; k++) /* outward: the normal points away from the origin */
          nn += (u[(k + 1) % 3] * v[(k + 2) % 3] - u[(k + 2) % 3] * v[(k + 1) % 3]) * p[0][k];
        tris[n++] = a, tris[n++] = nn > 0 ? b : c, tris[n++] = nn > 0 ? c : b;
      }
  if (n != 60)
    return tr_error(TR_ERR_INTERNAL, "icosahedron: %u faces", n / 3);
  TR_CHECK(tr_plc_create(plc));
  return tr_plc_set(*plc, x, 12, tris, 20, NULL);
}

/* A small convex polyhedron whose worst tet after refinement is above the rounds' bound
 * (20 degrees): the final polish (polish.c) works on the worst tets whatever their angle.
 * The icosahedron's 12 vertices alone give tets of about 21 degrees (CGAL's
 * icosahedron.off: 20.9); a point at its centre gives 20 tets of 69.1. With flips only
 * (level 1, no point) the worst rises over 30 degrees. Every mesh through the validators
 * (mesh and exact conformity); the polish never lowers the smallest angle (level 1 against
 * level 0). */
static void the_polish_raises_the_minimum_of_an_icosahedron(void)
{
  tr_plc *p = NULL;
  if (icosahedron(&p) != TR_OK) {
    EXPECT(0, "icosahedron: %s", tr_last_error());
    tr_plc_destroy(p);
    return;
  }
  tr_plc *u0 = NULL, *u1 = NULL, *u3 = NULL;
  tr_stats s0, s1, s3;
  tr_mesh *m0 = mesh("icosahedron", p, 0, TR_CHK_TOPOLOGY, &u0, &s0);
  tr_mesh *m1 = mesh("icosahedron", p, 1, TR_CHK_TOPOLOGY, &u1, &s1);
  tr_mesh *m3 = mesh("icosahedron", p, 3, TR_CHK_TOPOLOGY, &u3, &s3);
  if (m0 && m1 && m3) {
    EXPECT(s3.min_dihedral >= 60, "icosahedron -O 3: smallest dihedral %.3f, under 60",
           s3.min_dihedral);
    EXPECT(s1.min_dihedral >= s0.min_dihedral && s1.min_dihedral >= 30 &&
               s1.points_added_for_sliver == 0,
           "icosahedron -O 1: smallest dihedral %.3f -> %.3f (under 30?), %llu points",
           s0.min_dihedral, s1.min_dihedral, (unsigned long long)s1.points_added_for_sliver);
    fprintf(stderr, "icosahedron: min dihedral -O 0 %.3f, -O 1 %.3f, -O 3 %.3f (%llu tets)\n",
            s0.min_dihedral, s1.min_dihedral, s3.min_dihedral,
            (unsigned long long)s3.volume_elements);
  }
  tr_mesh_destroy(m0);
  tr_mesh_destroy(m1);
  tr_mesh_destroy(m3);
  tr_plc_destroy(u0);
  tr_plc_destroy(u1);
  tr_plc_destroy(u3);
  tr_plc_destroy(p);
}

/* A beam (CGAL's beam.off, scaled to dyadic coordinates): the box [0,1]^2 x [0,9], each
 * side two triangles, so the long sides stand on triangles of 6.3 degrees. Refinement
 * splits the long edges once and stops (its circumcentres lie too close to those
 * points); the worst tets, 8.93 degrees, have all four vertices on the surface, and no
 * flip, move or interior point opens them (level 1 keeps 8.93; so did level 3 before the
 * polish split constraint pieces). With points exactly on the long input edges the
 * smallest angle rises over TetGen 1.6's 17.4 (-pq1.414 on beam.off), every mesh through
 * the validators (mesh, exact conformity and volume). */
static void a_beam_pinned_between_its_sides_rises_only_with_points_on_its_edges(void)
{
  static const double x[24] = {1, 1, 9, 1, 0, 9, 0, 1, 9, 0, 0, 9,
                               1, 1, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0};
  static const uint32_t quads[6][4] = {{0, 1, 3, 2}, {5, 4, 6, 7}, {0, 2, 6, 4},
                                       {3, 1, 5, 7}, {0, 4, 5, 1}, {6, 2, 3, 7}};
  uint32_t tris[36];
  for (int q = 0; q < 6; q++) { /* the diagonal from each quad's second to fourth vertex */
    const uint32_t *v = quads[q];
    uint32_t t[6] = {v[0], v[1], v[3], v[1], v[2], v[3]};
    memcpy(tris + 6 * q, t, sizeof t);
  }
  tr_plc *p = NULL;
  tr_status s = tr_plc_create(&p);
  if (s == TR_OK)
    s = tr_plc_set(p, x, 8, tris, 12, NULL);
  if (s != TR_OK) {
    EXPECT(0, "beam: %s", tr_last_error());
    tr_plc_destroy(p);
    return;
  }
  tr_plc *u1 = NULL, *u3 = NULL;
  tr_stats s1, s3;
  tr_mesh *m1 = mesh("beam", p, 1, TR_CHK_TOPOLOGY, &u1, &s1);
  tr_mesh *m3 = mesh("beam", p, 3, TR_CHK_TOPOLOGY, &u3, &s3);
  if (m1 && m3) {
    EXPECT(s1.min_dihedral < 10, "beam -O 1: smallest dihedral %.3f: no longer pinned?",
           s1.min_dihedral);
    EXPECT(s3.min_dihedral > 17.446, "beam -O 3: smallest dihedral %.3f, TetGen's 17.446",
           s3.min_dihedral);
    EXPECT(s3.points_added_for_sliver > 0, "beam -O 3: no point added");
    fprintf(stderr, "beam: min dihedral -O 1 %.3f (%llu tets), -O 3 %.3f (%llu tets)\n",
            s1.min_dihedral, (unsigned long long)s1.volume_elements, s3.min_dihedral,
            (unsigned long long)s3.volume_elements);
  }
  tr_mesh_destroy(m1);
  tr_mesh_destroy(m3);
  tr_plc_destroy(u1);
  tr_plc_destroy(u3);
  tr_plc_destroy(p);
}

/* Two runs, the same bytes; an unknown level is a usage error before any work. */
static void deterministic_and_levels_checked(const char *dir)
{
  char path[1024];
  snprintf(path, sizeof path, "%s/star_rounding_budget.off", dir);
  tr_plc *p = NULL;
  if (tr_plc_read(path, &p) != TR_OK) {
    EXPECT(0, "%s: %s", path, tr_last_error());
    return;
  }
  tr_plc *u0 = NULL, *u1 = NULL;
  tr_stats st;
  tr_mesh *m0 = mesh("determinism", p, TR_SLIVER_INSERT, TR_CHK_TOPOLOGY, &u0, &st);
  tr_mesh *m1 = mesh("determinism", p, TR_SLIVER_INSERT, TR_CHK_TOPOLOGY, &u1, &st);
  if (m0 && m1) {
    EXPECT(m0->nv == m1->nv && m0->nt == m1->nt, "determinism: sizes differ");
    if (m0->nv == m1->nv && m0->nt == m1->nt)
      EXPECT(!memcmp(m0->xyz, m1->xyz, 24 * (size_t)m0->nv) &&
                 !memcmp(m0->tv, m1->tv, 16 * (size_t)m0->nt),
             "determinism: two runs differ");
  }
  tr_options opt;
  tr_options_default(&opt);
  EXPECT(opt.optimize == TR_SLIVER_INSERT, "default level %d", opt.optimize);
  opt.verbose = 0;
  opt.quality_ratio = 1.414;
  opt.optimize = TR_SLIVER_INSERT + 1;
  tr_mesh *bad = NULL;
  EXPECT(tr_mesh_plc(p, &opt, &bad, NULL) == TR_ERR_USAGE && !bad, "level 4 accepted");
  tr_mesh_destroy(m0);
  tr_mesh_destroy(m1);
  tr_plc_destroy(u0);
  tr_plc_destroy(u1);
  tr_plc_destroy(p);
}

/* The flat tet of the tet surface A B C D (D a quarter above the base ABC, over its
 * circumcircle): four input vertices, four sub-faces, so no flip, move or interior point
 * opens it. With the plc given, the stage puts points on the constraints under it
 * (sliver.c, pinned tets): it is gone, every new vertex lies exactly on an input
 * triangle, the mesh validates with the exact volume (6 V = 14). */
static void a_tet_pinned_between_sub_faces_gets_points_on_them(void)
{
  const double x[12] = {0, 0, 0, 8, 0, 0, 4, 7, 0, 4, 3, 0.25};
  static const uint32_t tris[12] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
  tr_plc *plc = NULL;
  tr_mesh *m = NULL;
  if (tr_plc_create(&plc) != TR_OK || tr_plc_set(plc, x, 4, tris, 4, NULL) != TR_OK ||
      tr_delaunay_build(x, 4, &m) != TR_OK) {
    EXPECT(0, "pinned: setup: %s", tr_last_error());
    tr_plc_destroy(plc);
    return;
  }
  uint32_t sv[12], tri[4] = {0, 1, 2, 3};
  memcpy(sv, tris, sizeof sv);
  tr_subfaces sub = {4, NULL, NULL};
  sub.v = malloc(sizeof sv);
  sub.tri = malloc(sizeof tri);
  memcpy(sub.v, sv, sizeof sv);
  memcpy(sub.tri, tri, sizeof tri);
  /* the stage takes refinement's output, inner tets only: an empty list discards the
   * ghosts and adds nothing */
  tr_refine_params none;
  memset(&none, 0, sizeof none);
  tr_refine_stats rs;
  tr_status s = tr_refine_open_pinned(m, plc, &sub, &none, NULL, 0, &rs);
  EXPECT(s == TR_OK && rs.points == 0, "pinned: an empty list added points or failed");
  const uint32_t flat[4] = {0, 1, 2, 3};
  EXPECT(has_tet(m, flat), "pinned: the flat tet is not there to begin with");
  tr_sliver_params par = {TR_SLIVER_INSERT, TR_SLIVER_BOUND, TR_SLIVER_ROUNDS, 0, {0, 0, plc, 0}};
  tr_sliver_stats st;
  s = tr_sliver_remove(m, &sub, NULL, 4, &par, &st);
  EXPECT(s == TR_OK, "pinned: sliver stage: %s", tr_last_error());
  EXPECT(st.on_constraints >= 1 && m->nv > 4, "pinned: no point on a constraint");
  EXPECT(!has_tet(m, flat), "pinned: the flat tet is still there");
  tr_point P[4];
  for (uint32_t i = 0; i < 4; i++)
    P[i] = tr_mesh_point(m, i);
  uint64_t on = 0; /* the interior points lie strictly inside, the others exactly on */
  for (uint32_t v = 4; v < m->nv; v++) {
    tr_point q = tr_mesh_point(m, v);
    int at = 0;
    for (int f = 0; f < 4; f++)
      at |= tr_orient3d_p(&P[tris[3 * f]], &P[tris[3 * f + 1]], &P[tris[3 * f + 2]], &q) == 0;
    on += (uint64_t)at;
  }
  EXPECT(on == st.on_constraints, "pinned: %llu vertices on the input's faces, %llu counted",
         (unsigned long long)on, (unsigned long long)st.on_constraints);
  mpq_t six_v;
  mpq_init(six_v);
  mpq_set_ui(six_v, 14, 1);
  s = tr_check_mesh(m, TR_CHK_TOPOLOGY, six_v);
  EXPECT(s == TR_OK, "pinned: mesh validator: %s", tr_last_error());
  mpq_clear(six_v);
  tr_subfaces_free(&sub);
  tr_mesh_destroy(m);
  tr_plc_destroy(plc);
}

/* A cap over a nearly flat ridge: the hull's bottom is folded along p q (0 1) by 1/64 up
 * to r and s (2 3), its top is the apex u (4). The Delaunay mesh is the cap p q r s and
 * the two tets from u over p r s and q r s; the cap's four points are not cocircular, so
 * its circumcentre lies far below the hull (no candidate between it and the centroid is
 * inside). Every vertex is an input point (none moves) and no face is a sub-face: the
 * insertion pass opens the cap by a point off its plane on the domain's side (insert.c,
 * off_plane), strictly inside the hull, and the smallest angle rises. */
static void a_pinned_cap_is_opened_by_a_point_off_its_plane(void)
{
  const double e = 1.0 / 64, x[15] = {0, 0, 0, 1, 0, 0, 0.5, 0.25, e, 0.5, -0.25, e, 0.5, 0, 1};
  tr_mesh *m = NULL;
  if (tr_delaunay_build(x, 5, &m) != TR_OK) {
    EXPECT(0, "cap: Delaunay failed: %s", tr_last_error());
    return;
  }
  const uint32_t cap[4] = {0, 1, 2, 3};
  EXPECT(has_tet(m, cap), "cap: the cap is not a tet of the Delaunay mesh");
  double before = min_dihedral(m);
  EXPECT(before < 5, "cap: its smallest angle %g is not small", before);
  mpq_t six_v; /* the hull is u over p q r and p q s: 6 V = 1/4 + 1/4 */
  mpq_init(six_v);
  mpq_set_ui(six_v, 1, 2);
  EXPECT(tr_check_mesh(m, TR_CHK_TOPOLOGY, six_v) == TR_OK, "cap: setup: %s", tr_last_error());
  tr_subfaces none = {0, NULL, NULL};
  tr_sliver_ctx c;
  tr_sliver_stats st;
  memset(&st, 0, sizeof st);
  tr_status s = tr_sliver_ctx_init(&c, m, &none, NULL, 5, TR_SLIVER_BOUND);
  if (s == TR_OK)
    s = tr_sliver_insert_pass(&c, &st);
  EXPECT(s == TR_OK, "cap: insertion: %s", tr_last_error());
  tr_sliver_ctx_free(&c);
  EXPECT(st.points >= 1 && m->nv == 5 + st.points, "cap: %llu points added, %u vertices",
         (unsigned long long)st.points, m->nv);
  EXPECT(!has_tet(m, cap), "cap: the cap is still there");
  for (uint32_t v = 0; v < 5; v++)
    EXPECT(!memcmp(x + 3 * v, m->xyz + 3 * (size_t)v, 24), "cap: vertex %u moved", v);
  for (uint32_t v = 5; v < m->nv; v++) {
    const double *p = m->xyz + 3 * (size_t)v;
    EXPECT(p[2] > e && p[2] < 1 && !(m->vq && m->vq[v]) && m->v2t[v] != TR_NONE,
           "cap: new vertex %u is not a double above the ridge inside the hull", v);
  }
  double after = min_dihedral(m);
  EXPECT(after > before, "cap: smallest dihedral angle %g -> %g: not raised", before, after);
  s = tr_check_mesh(m, TR_CHK_TOPOLOGY, six_v);
  EXPECT(s == TR_OK, "cap: mesh validator: %s", tr_last_error());
  mpq_clear(six_v);
  tr_mesh_destroy(m);
}

int main(int argc, char **argv)
{
  const char *c = argc > 1 ? argv[1] : "";
  if (!strcmp(c, "flip"))
    a_sliver_is_removed_by_a_flip();
  else if (!strcmp(c, "constraints"))
    constraints_are_kept_and_their_vertices_stay();
  else if (!strcmp(c, "smoothing"))
    smoothing_moves_a_free_vertex_and_raises_the_angle();
  else if (!strcmp(c, "insertion"))
    a_sliver_is_removed_by_a_new_interior_point();
  else if (!strcmp(c, "passes"))
    no_pass_lowers_the_smallest_angle();
  else if (!strcmp(c, "cap"))
    a_pinned_cap_is_opened_by_a_point_off_its_plane();
  else if (!strcmp(c, "pinned"))
    a_tet_pinned_between_sub_faces_gets_points_on_them();
  else if (!strcmp(c, "beam"))
    a_beam_pinned_between_its_sides_rises_only_with_points_on_its_edges();
  else if (!strcmp(c, "polish"))
    the_polish_raises_the_minimum_of_an_icosahedron();
  else if (!strcmp(c, "surfaces") && argc > 2)
    refined_surfaces(argv[2]);
  else if (!strcmp(c, "determinism") && argc > 2)
    deterministic_and_levels_checked(argv[2]);
  else {
    fprintf(stderr, "unknown case '%s'\n", c);
    return 2;
  }
  return failures != 0;
}
