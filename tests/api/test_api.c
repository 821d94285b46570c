/* The output mesh accessors of include/tetrec.h checked exactly against the geometry:
 * every boundary face is a tet face inside its input triangle, oriented like it, with its
 * marker, and the faces of a triangle add up to its exact area; every vertex origin holds
 * exactly; the exact point text reads back as the exact point. Every mesh goes through
 * the validators (tr_check_mesh, tr_check_conformity). main() dispatches every case of
 * tests/api (the others are in api_cases.c).
 * Usage: test_api CASE SOURCE_ROOT [PROJECT_VERSION|TMPDIR] */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../hard/hard_cases.h"
#include "api.h"
#include "mesh/check.h"
#include "mesh/conform.h"
#include "pipeline/pipeline.h"

const char *api_root;
int failures;
static char pathbuf[4096];

const char *api_src(const char *rel)
{
  snprintf(pathbuf, sizeof pathbuf, "%s/%s", api_root, rel);
  return pathbuf;
}

tr_plc *read_plc(const char *rel)
{
  tr_plc *p = NULL;
  tr_status s = tr_plc_read(api_src(rel), &p);
  EXPECT(s == TR_OK, "%s: %s", rel, tr_last_error());
  return p;
}

/* A 2x1x1 box cut by the internal square x = 1 into two regions: 22 triangles, each
 * with its own marker 100 + index, so every face's marker names its triangle. */
tr_plc *two_region_box(void)
{
  double x[36];
  for (int i = 0; i < 12; i++) {
    x[3 * i] = i / 4;
    x[3 * i + 1] = (i / 2) % 2;
    x[3 * i + 2] = i % 2;
  }
  /* point (a, b, c) with a in 0..2, b, c in 0..1 is 4a + 2b + c */
#define P(a, b, c) (4 * (a) + 2 * (b) + (c))
  uint32_t t[66];
  int n = 0;
  uint32_t q[11][4] = {
      {P(0, 0, 0), P(0, 1, 0), P(0, 1, 1), P(0, 0, 1)}, /* x = 0 */
      {P(2, 0, 0), P(2, 0, 1), P(2, 1, 1), P(2, 1, 0)}, /* x = 2 */
      {P(1, 0, 0), P(1, 0, 1), P(1, 1, 1), P(1, 1, 0)}, /* x = 1, internal */
  };
  int nq = 3;
  for (int a = 0; a < 2; a++) {
    uint32_t y0[4] = {P(a, 0, 0), P(a, 0, 1), P(a + 1, 0, 1), P(a + 1, 0, 0)};
    uint32_t y1[4] = {P(a, 1, 0), P(a + 1, 1, 0), P(a + 1, 1, 1), P(a, 1, 1)};
    uint32_t z0[4] = {P(a, 0, 0), P(a + 1, 0, 0), P(a + 1, 1, 0), P(a, 1, 0)};
    uint32_t z1[4] = {P(a, 0, 1), P(a, 1, 1), P(a + 1, 1, 1), P(a + 1, 0, 1)};
    memcpy(q[nq++], y0, sizeof y0);
    memcpy(q[nq++], y1, sizeof y1);
    memcpy(q[nq++], z0, sizeof z0);
    memcpy(q[nq++], z1, sizeof z1);
  }
#undef P
  for (int i = 0; i < nq; i++) {
    uint32_t a[6] = {q[i][0], q[i][1], q[i][2], q[i][0], q[i][2], q[i][3]};
    memcpy(t + 3 * n, a, sizeof a);
    n += 2;
  }
  int32_t mk[22];
  for (int i = 0; i < n; i++)
    mk[i] = 100 + i;
  tr_plc *p = NULL;
  EXPECT(tr_plc_create(&p) == TR_OK, "create");
  EXPECT(tr_plc_set(p, x, 12, t, (uint32_t)n, mk) == TR_OK, "set: %s", tr_last_error());
  return p;
}

/* A case of tests/hard/hard_cases.c as a PLC (NULL if it does not exist). */
tr_plc *hard_plc(const char *name)
{
  tr_plc *p = NULL;
  for (int i = 0; i < hard_case_count(); i++) {
    if (strcmp(hard_case_name(i), name) != 0)
      continue;
    hard_case c;
    EXPECT(hard_case_build(i, &c) == 0, "build %s", name);
    EXPECT(tr_plc_create(&p) == TR_OK && tr_plc_set(p, c.xyz, c.np, c.tris, c.nt, NULL) == TR_OK,
           "%s: %s", name, tr_last_error());
    hard_case_free(&c);
  }
  EXPECT(p != NULL, "no hard case %s", name);
  return p;
}

tr_options quiet(void)
{
  tr_options o;
  tr_options_default(&o);
  o.verbose = 0;
  return o;
}

/* Pipeline flags of mesh_checked: t_accessors runs its inputs once as they come (the
 * suppression stage removes or relocates boundary Steiner points) and once with
 * TR_PIPE_KEEP_STEINER, so that points on input edges and triangles stay to be checked. */
static unsigned pipe_flags;
static int pipe_recovery; /* tr_options.recovery of mesh_checked */

/* tr_mesh_plc_flags plus both validators; *used = the PLC as meshed. */
tr_mesh *mesh_checked(const tr_plc *p, const char *name, tr_plc **used)
{
  tr_options o = quiet();
  o.recovery = pipe_recovery;
  tr_mesh *m = NULL;
  tr_status s = tr_mesh_plc_flags(p, &o, &m, NULL, used, pipe_flags);
  EXPECT(s == TR_OK, "%s: %s", name, tr_last_error());
  if (s != TR_OK)
    return NULL;
  s = tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, NULL);
  EXPECT(s == TR_OK, "%s: mesh check: %s", name, tr_last_error());
  s = tr_check_conformity(m, *used, NULL, 0);
  EXPECT(s == TR_OK, "%s: conformity: %s", name, tr_last_error());
  return m;
}

static tr_point vpt(const tr_mesh *m, uint32_t v) { return tr_mesh_point(m, v); }
static tr_point ppt(const tr_plc *p, uint32_t i) { return tr_pt_d(p->xyz + 3 * (size_t)i); }

/* The axis to drop for the triangle (a,b,c): one where its projection is not flat. */
static int drop_axis(const tr_point *a, const tr_point *b, const tr_point *c, int *sign)
{
  for (int d = 0; d < 3; d++)
    if ((*sign = tr_orient2d_proj_p(a, b, c, d)) != 0)
      return d;
  return -1;
}

/* 1 strictly inside, 0 on its boundary, -1 outside or off its plane. */
static int in_triangle(const tr_point *a, const tr_point *b, const tr_point *c,
                       const tr_point *p)
{
  if (tr_orient3d_p(a, b, c, p) != 0)
    return -1;
  int sg, d = drop_axis(a, b, c, &sg);
  int s1 = tr_orient2d_proj_p(a, b, p, d) * sg, s2 = tr_orient2d_proj_p(b, c, p, d) * sg,
      s3 = tr_orient2d_proj_p(c, a, p, d) * sg;
  if (s1 < 0 || s2 < 0 || s3 < 0)
    return -1;
  return s1 > 0 && s2 > 0 && s3 > 0;
}

/* p strictly between a and b on segment ab. */
static int in_segment(const tr_point *a, const tr_point *b, const tr_point *p)
{
  for (int d = 0; d < 3; d++)
    if (tr_orient2d_proj_p(a, b, p, d) != 0)
      return 0;
  for (int i = 0; i < 3; i++) {
    int ab = tr_cmp_coord_p(a, b, i);
    if (ab != 0)
      return tr_cmp_coord_p(a, p, i) == ab && tr_cmp_coord_p(p, b, i) == ab;
  }
  return 0;
}

/* Twice the signed area of (a,b,c) projected along axis d, exactly. */
static void area2(const tr_point *a, const tr_point *b, const tr_point *c, int d, mpq_t out)
{
  mpq_t ax, ay, bx, by, cx, cy, t;
  mpq_inits(ax, ay, bx, by, cx, cy, t, NULL);
  int i = (d + 1) % 3, j = (d + 2) % 3;
  tr_point_get_q(a, i, ax);
  tr_point_get_q(a, j, ay);
  tr_point_get_q(b, i, bx);
  tr_point_get_q(b, j, by);
  tr_point_get_q(c, i, cx);
  tr_point_get_q(c, j, cy);
  mpq_sub(bx, bx, ax);
  mpq_sub(by, by, ay);
  mpq_sub(cx, cx, ax);
  mpq_sub(cy, cy, ay);
  mpq_mul(out, bx, cy);
  mpq_mul(t, by, cx);
  mpq_sub(out, out, t);
  mpq_clears(ax, ay, bx, by, cx, cy, t, NULL);
}

int cmp_key(const void *a, const void *b) { return tr_cmp_face_key(a, b); }

static unsigned triangles_without_faces; /* facets between two cavities seen */

/* The accessors agree with the store, and the boundary faces tile every input triangle
 * exactly, each oriented like it, each a face of a tet, with its triangle's marker. */
static void check_accessors(const tr_mesh *m, const tr_plc *used, const char *name)
{
  uint32_t nv = tr_mesh_num_vertices(m), nt = tr_mesh_num_tets(m);
  const double *x = tr_mesh_points(m);
  const uint32_t *tv = tr_mesh_tets(m);
  const int32_t *reg = tr_mesh_tet_regions(m);
  EXPECT(x && tv && reg, "%s: NULL array", name);
  if (!x || !tv || !reg)
    return;
  EXPECT(memcmp(x, m->xyz, sizeof *x * 3 * nv) == 0, "%s: points differ from the store", name);
  uint32_t *keys = malloc(sizeof *keys * 12 * (size_t)nt);
  for (uint32_t t = 0; t < nt; t++) {
    tr_point p[4];
    for (int k = 0; k < 4; k++) {
      EXPECT(tv[4 * t + k] < nv, "%s: tet %u vertex out of range", name, t);
      p[k] = vpt(m, tv[4 * t + k]);
    }
    EXPECT(tr_orient3d_p(&p[0], &p[1], &p[2], &p[3]) > 0, "%s: tet %u not positive", name, t);
    EXPECT(reg[t] == (int32_t)m->region[t], "%s: region of tet %u", name, t);
    for (int k = 0; k < 4; k++) {
      uint32_t *f = keys + 12 * (size_t)t + 3 * k;
      for (int j = 0; j < 3; j++)
        f[j] = tv[4 * t + tr_face_vtx[k][j]];
      tr_sort3(f);
    }
  }
  qsort(keys, 4 * (size_t)nt, 3 * sizeof *keys, cmp_key);
  uint32_t nf = tr_mesh_num_boundary_faces(m);
  const uint32_t *bf = tr_mesh_boundary_faces(m), *btri = tr_mesh_boundary_triangles(m);
  const int32_t *bm = tr_mesh_boundary_markers(m);
  /* fewer faces than triangles is right where a facet lies between two cavities: each
   * triangle's faces are checked below to tile it, or to be absent from every tet */
  EXPECT(bf && bm && btri, "%s: %u boundary faces for %u triangles", name, nf, used->ntris);
  if (!bf || !bm || !btri) {
    free(keys);
    return;
  }
  mpq_t sum, a;
  mpq_inits(sum, a, NULL);
  uint32_t f = 0;
  for (uint32_t k = 0; k < used->ntris; k++) {
    const uint32_t *T = used->tris + 3 * (size_t)k;
    tr_point A = ppt(used, T[0]), B = ppt(used, T[1]), C = ppt(used, T[2]);
    int sg, d = drop_axis(&A, &B, &C, &sg);
    /* an apex off the triangle's plane: the mesh vertex of smallest index */
    uint32_t apex = 0;
    tr_point X = vpt(m, 0);
    int side = 0;
    while (apex < nv && (X = vpt(m, apex), side = tr_orient3d_p(&A, &B, &C, &X)) == 0)
      apex++;
    mpq_set_ui(sum, 0, 1);
    uint32_t first = f;
    if (f >= nf || btri[f] != k) {
      /* no face listed (faces are sorted by triangle): then no tet has a face inside the
       * triangle, as for a facet between two cavities */
      triangles_without_faces++;
      for (uint32_t t = 0; t < nt; t++)
        for (int j = 0; j < 4; j++) {
          int inside = 1;
          for (int i = 0; i < 3; i++) {
            tr_point q = vpt(m, tv[4 * t + tr_face_vtx[j][i]]);
            inside &= in_triangle(&A, &B, &C, &q) >= 0;
          }
          EXPECT(!inside, "%s: triangle %u has no face listed but tet %u has one in it", name,
                 k, t);
        }
      continue;
    }
    for (; f < nf && btri[f] == k; f++) {
      const uint32_t *F = bf + 3 * (size_t)f;
      tr_point p[3] = {vpt(m, F[0]), vpt(m, F[1]), vpt(m, F[2])};
      for (int j = 0; j < 3; j++)
        EXPECT(in_triangle(&A, &B, &C, &p[j]) >= 0, "%s: face %u vertex %u not in triangle %u",
               name, f, F[j], k);
      EXPECT(tr_orient3d_p(&p[0], &p[1], &p[2], &X) == side,
             "%s: face %u not oriented like triangle %u", name, f, k);
      EXPECT(bm[f] == (used->tri_marker ? used->tri_marker[k] : 0),
             "%s: face %u marker %d, triangle %u has %d", name, f, bm[f], k,
             used->tri_marker ? used->tri_marker[k] : 0);
      uint32_t key[3] = {F[0], F[1], F[2]};
      tr_sort3(key);
      EXPECT(bsearch(key, keys, 4 * (size_t)nt, 3 * sizeof *keys, cmp_key) != NULL,
             "%s: face %u is no tet's face", name, f);
      for (uint32_t g = first; g < f; g++) {
        uint32_t o[3] = {bf[3 * g], bf[3 * g + 1], bf[3 * g + 2]};
        tr_sort3(o);
        EXPECT(memcmp(o, key, sizeof o) != 0, "%s: face %u listed twice", name, f);
      }
      area2(&p[0], &p[1], &p[2], d, a);
      mpq_add(sum, sum, a);
    }
    /* distinct faces inside the triangle whose areas add up to its area tile it */
    area2(&A, &B, &C, d, a);
    EXPECT(mpq_equal(sum, a), "%s: the faces of triangle %u do not cover it", name, k);
  }
  EXPECT(f == nf, "%s: %u faces after the last triangle", name, nf - f);
  mpq_clears(sum, a, NULL);
  free(keys);
}

/* Every vertex's origin, checked exactly: an input vertex is that input point, a Steiner
 * point on edge k lies strictly inside it, one on triangle k strictly inside it, and an
 * interior one on no input triangle. counts[kind] is incremented. */
static void check_origins(const tr_mesh *m, const tr_plc *used, const char *name,
                          unsigned counts[4])
{
  uint32_t ne = tr_mesh_num_input_edges(m);
  for (uint32_t k = 0; k + 1 < ne; k++) {
    uint32_t a, b, c, d;
    tr_mesh_input_edge(m, k, &a, &b);
    tr_mesh_input_edge(m, k + 1, &c, &d);
    EXPECT(a < b && b < used->npoints && (a < c || (a == c && b < d)),
           "%s: input edges not unique and sorted at %u", name, k);
  }
  uint32_t a, b;
  EXPECT(tr_mesh_input_edge(m, ne, &a, &b) == TR_ERR_USAGE, "%s: edge out of range", name);
  for (uint32_t v = 0; v < tr_mesh_num_vertices(m); v++) {
    int kind = -1;
    uint32_t idx = 0;
    EXPECT(tr_mesh_vertex_origin(m, v, &kind, &idx) == TR_OK, "%s: origin %u", name, v);
    tr_point p = vpt(m, v);
    if (kind < 0 || kind > 3) {
      EXPECT(0, "%s: vertex %u has kind %d", name, v, kind);
      continue;
    }
    counts[kind]++;
    if (kind == TR_VERTEX_INPUT) {
      EXPECT(idx < used->npoints && !(m->vq && m->vq[v]) &&
                 memcmp(m->xyz + 3 * (size_t)v, used->xyz + 3 * (size_t)idx, 24) == 0,
             "%s: vertex %u is not input point %u", name, v, idx);
    } else if (kind == TR_VERTEX_ON_EDGE) {
      EXPECT(idx < ne && tr_mesh_input_edge(m, idx, &a, &b) == TR_OK, "%s: edge %u", name, idx);
      tr_point A = ppt(used, a), B = ppt(used, b);
      EXPECT(in_segment(&A, &B, &p), "%s: vertex %u not strictly inside edge %u", name, v, idx);
    } else {
      for (uint32_t k = 0; k < used->ntris; k++) {
        const uint32_t *T = used->tris + 3 * (size_t)k;
        tr_point A = ppt(used, T[0]), B = ppt(used, T[1]), C = ppt(used, T[2]);
        int in = in_triangle(&A, &B, &C, &p);
        if (kind == TR_VERTEX_ON_TRIANGLE && k == idx)
          EXPECT(in == 1, "%s: vertex %u not strictly inside triangle %u", name, v, k);
        if (kind == TR_VERTEX_INTERIOR)
          EXPECT(in < 0, "%s: interior vertex %u lies on triangle %u", name, v, k);
      }
      EXPECT(kind != TR_VERTEX_ON_TRIANGLE || idx < used->ntris, "%s: triangle %u", name, idx);
      EXPECT(kind != TR_VERTEX_INTERIOR || idx == v, "%s: interior index", name);
    }
  }
  int kind;
  uint32_t idx;
  EXPECT(tr_mesh_vertex_origin(m, tr_mesh_num_vertices(m), &kind, &idx) == TR_ERR_USAGE,
         "%s: vertex out of range accepted", name);
}

/* The text of every vertex reads back as its exact point. */
static void check_exact_text(const tr_mesh *m, const char *name)
{
  mpq_t q[3], c;
  mpq_inits(q[0], q[1], q[2], c, NULL);
  for (uint32_t v = 0; v < tr_mesh_num_vertices(m); v++) {
    char *s = NULL;
    EXPECT(tr_mesh_point_exact(m, v, &s) == TR_OK && s, "%s: exact %u", name, v);
    if (!s)
      continue;
    char *tok = s, *sp;
    tr_point p = vpt(m, v);
    for (int k = 0; k < 3; k++) {
      sp = strchr(tok, ' ');
      if (sp)
        *sp = '\0';
      EXPECT((k < 2) == (sp != NULL), "%s: vertex %u: not three fields", name, v);
      EXPECT(mpq_set_str(q[k], tok, 10) == 0, "%s: vertex %u: bad rational '%s'", name, v, tok);
      mpq_canonicalize(q[k]);
      tr_point_get_q(&p, k, c);
      EXPECT(mpq_equal(q[k], c), "%s: vertex %u coordinate %d differs", name, v, k);
      if (sp)
        tok = sp + 1;
      else
        break;
    }
    tr_free(s);
  }
  char *s = NULL;
  EXPECT(tr_mesh_point_exact(m, tr_mesh_num_vertices(m), &s) == TR_ERR_USAGE && !s,
         "%s: out of range accepted", name);
  mpq_clears(q[0], q[1], q[2], c, NULL);
}

static void run_all_checks(tr_plc *p, const char *name, unsigned counts[4])
{
  tr_plc *used = NULL;
  tr_mesh *m = mesh_checked(p, name, &used);
  if (m) {
    check_accessors(m, used, name);
    check_origins(m, used, name, counts);
    check_exact_text(m, name);
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
}

static const char *const inputs[] = {
    "examples/data/cube.off", "tests/data/schoenhardt.off", "tests/data/two_cubes.off",
    "tests/data/cavity.off", "tests/data/cube_facets.poly",
    "tests/data/regressions/star_steiner_cluster_s2_1315.off",
    "tests/data/regressions/star_steiner_cluster_s3_1477.off",
    "tests/data/regressions/star_flips_undone_stale_cluster.off"};

/* Every check on every input and hard case, counting origins. */
static void accessor_inputs(unsigned counts[4])
{
  for (size_t i = 0; i < sizeof inputs / sizeof *inputs; i++) {
    tr_plc *p = read_plc(inputs[i]);
    if (p)
      run_all_checks(p, inputs[i], counts);
    tr_plc_destroy(p);
  }
  tr_plc *p = two_region_box();
  run_all_checks(p, "two_region_box", counts);
  tr_plc_destroy(p);
  /* generated hard cases with Steiner points on facets, cracks and fins */
  static const char *const hard[] = {"chazelle_g4", "crack_inside_box", "fin_attached_inside",
                                     "nested_cavity", "two_regions_inverted",
                                     "two_cavities_sharing_a_face", "cavity_and_crack"};
  for (size_t h = 0; h < sizeof hard / sizeof *hard; h++) {
    p = hard_plc(hard[h]);
    if (p)
      run_all_checks(p, hard[h], counts);
    tr_plc_destroy(p);
  }
}

static void t_accessors(void)
{
  unsigned counts[4] = {0, 0, 0, 0};
  pipe_flags = 0;
  accessor_inputs(counts);
  pipe_flags = TR_PIPE_KEEP_STEINER;
  accessor_inputs(counts);
  /* Whether the default recovery needs a point on a triangle depends on the order the
   * mesh stores its tets in; the paper's clusterels put points on triangles of this
   * input whatever that order */
  pipe_recovery = 1;
  tr_plc *p = read_plc("tests/data/regressions/star_steiner_cluster_s2_1315.off");
  if (p)
    run_all_checks(p, "star_steiner_cluster_s2_1315.off, paper recovery", counts);
  tr_plc_destroy(p);
  pipe_recovery = 0;
  pipe_flags = 0;
  printf("vertex origins: %u input, %u on edges, %u on triangles, %u interior; %u input "
         "triangles between two cavities\n",
         counts[0], counts[1], counts[2], counts[3], triangles_without_faces);
  /* the inputs exercise Steiner points on edges and on triangles */
  EXPECT(counts[1] > 0 && counts[2] > 0, "inputs gave no Steiner point on an edge/triangle");
  EXPECT(triangles_without_faces > 0, "no input triangle between two cavities was tried");
}

/* Internal facet: both regions touch it, its faces are listed once each with markers. */
static void t_internal_facet(void)
{
  tr_plc *p = two_region_box(), *used = NULL;
  tr_mesh *m = mesh_checked(p, "two_region_box", &used);
  if (m) {
    const int32_t *reg = tr_mesh_tet_regions(m);
    int32_t r0 = reg[0], other = 0;
    for (uint32_t t = 0; t < tr_mesh_num_tets(m); t++)
      other |= reg[t] != r0;
    EXPECT(other, "two regions expected");
    uint32_t on_internal = 0;
    for (uint32_t f = 0; f < tr_mesh_num_boundary_faces(m); f++)
      if (tr_mesh_boundary_markers(m)[f] == 104 || tr_mesh_boundary_markers(m)[f] == 105)
        on_internal++;
    EXPECT(on_internal >= 2, "internal facet: %u faces", on_internal);
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
  tr_plc_destroy(p);
}

/* A tr_delaunay mesh: dense positive tets, no regions, no boundary faces, input vertices. */
static void t_delaunay_accessors(void)
{
  tr_plc *p = read_plc("examples/data/cube.off");
  tr_mesh *m = NULL;
  if (!p || tr_delaunay(tr_plc_points(p), tr_plc_num_points(p), &m) != TR_OK) {
    EXPECT(0, "delaunay: %s", tr_last_error());
    tr_plc_destroy(p);
    return;
  }
  uint32_t nt = tr_mesh_num_tets(m);
  const uint32_t *tv = tr_mesh_tets(m);
  EXPECT(nt > 0 && tv, "delaunay: no tets");
  for (uint32_t t = 0; tv && t < nt; t++) {
    tr_point q[4];
    for (int k = 0; k < 4; k++) {
      EXPECT(tv[4 * t + k] < tr_mesh_num_vertices(m), "delaunay: tet %u vertex", t);
      q[k] = tr_pt_d(tr_mesh_points(m) + 3 * (size_t)(tv[4 * t + k] % tr_mesh_num_vertices(m)));
    }
    EXPECT(tr_orient3d_p(&q[0], &q[1], &q[2], &q[3]) > 0, "delaunay: tet %u not positive", t);
  }
  EXPECT(tr_mesh_tet_regions(m) == NULL && tr_mesh_num_boundary_faces(m) == 0 &&
             tr_mesh_boundary_faces(m) == NULL && tr_mesh_boundary_markers(m) == NULL,
         "delaunay: regions or faces");
  int kind;
  uint32_t idx;
  EXPECT(tr_mesh_vertex_origin(m, 3, &kind, &idx) == TR_OK && kind == TR_VERTEX_INPUT &&
             idx == 3,
         "delaunay: origin");
  check_exact_text(m, "delaunay");
  tr_mesh_destroy(m);
  tr_plc_destroy(p);
}

int main(int argc, char **argv)
{
  if (argc < 3) {
    fprintf(stderr, "usage: test_api CASE SOURCE_ROOT [VERSION|TMPDIR]\n");
    return 2;
  }
  api_root = argv[2];
  const char *c = argv[1];
  if (!strcmp(c, "accessors"))
    t_accessors();
  else if (!strcmp(c, "internal_facet"))
    t_internal_facet();
  else if (!strcmp(c, "delaunay"))
    t_delaunay_accessors();
  else if (!strcmp(c, "writers"))
    t_writers(argc > 3 ? argv[3] : ".");
  else if (!strcmp(c, "writers_open"))
    t_writers_open(argc > 3 ? argv[3] : ".");
  else if (!strcmp(c, "progress"))
    t_progress();
  else if (!strcmp(c, "progress_refinement"))
    t_progress_refinement();
  else if (!strcmp(c, "abi_size"))
    t_abi_size();
  else if (!strcmp(c, "stage_times"))
    t_stage_times();
  else if (!strcmp(c, "strict_doubles"))
    t_strict_doubles();
  else if (!strcmp(c, "version"))
    t_version(argc > 3 ? argv[3] : NULL);
  else {
    fprintf(stderr, "unknown case %s\n", c);
    return 2;
  }
  tr_exact_scratch_free();
  return failures != 0;
}
