/* Flips of an edge inside an input triangle (src/sliver/facetflip.c), on hand-made
 * meshes: a quadrilateral a c b d in z = 0, cut by its diagonal a b into the sub-faces
 * a b c and a b d of one input triangle, with c 1/16 off a b (an angle of 166 degrees at
 * c), coned to x above it and, in the two-sided case, to y below it. The flip pass swaps
 * the diagonal for c d: the tets and the sub-faces follow, the smallest angle rises, and
 * the mesh validates with its exact volume. One-sided, the quadrilateral is on the
 * mesh's boundary (tr_mesh_replace_open). With a fan of three tets over a b (c x1 x2 d,
 * all in the plane x = 1/2), the flip takes the longer fan, unless the triangle is thin. */
#include <gmp.h>
#include <stdlib.h>
#include <string.h>

#include "refine/quality.h"
#include "sliver/sliver.h"
#include "../pipeline/tmesh.h"

enum { A, B, C, D, X, Y };
static const double pts[6][3] = {{0, 0, 0},      {1, 0, 0},         {0.5, 0.0625, 0},
                                 {0.5, -0.5, 0}, {0.5, -0.125, 0.5}, {0.5, -0.125, -0.5}};

/* A new tet on a, b, c, d, reordered to be positive. */
static void tet(tr_mesh *m, uint32_t a, uint32_t b, uint32_t c, uint32_t d, uint32_t *out)
{
  tr_point p[4] = {tr_mesh_point(m, a), tr_mesh_point(m, b), tr_mesh_point(m, c),
                   tr_mesh_point(m, d)};
  int s = tr_orient3d_p(&p[0], &p[1], &p[2], &p[3]);
  EXPECT(s != 0, "tet %u %u %u %u is flat", a, b, c, d);
  uint32_t v[4] = {a, b, c, d};
  if (s < 0)
    v[0] = b, v[1] = a;
  memcpy(out, v, sizeof v);
}

static int has_face(const tr_mesh *m, uint32_t a, uint32_t b, uint32_t c)
{
  for (uint32_t t = 0; t < m->nt; t++)
    if (tr_tet_is_real(m, t) && tr_fcode(m, t, a, b, c) >= 0)
      return 1;
  return 0;
}

static int has_edge(const tr_mesh *m, uint32_t a, uint32_t b)
{
  for (uint32_t t = 0; t < m->nt; t++)
    if (tr_tet_is_real(m, t) && tr_ncode(m, t, a) >= 0 && tr_ncode(m, t, b) >= 0)
      return 1;
  return 0;
}

static void flip_case(const char *name, int two_sided)
{
  tr_mesh *m = NULL;
  if (tr_mesh_create(6, 8, &m) != TR_OK) {
    EXPECT(0, "%s: no mesh", name);
    return;
  }
  uint32_t id;
  for (int i = 0; i < (two_sided ? 6 : 5); i++)
    EXPECT(tr_mesh_add_vertex(m, pts[i], &id) == TR_OK && id == (uint32_t)i, "%s: vertex %d",
           name, i);
  uint32_t newv[16], n = 0;
  tet(m, A, B, C, X, newv + 4 * n++);
  tet(m, A, B, D, X, newv + 4 * n++);
  if (two_sided) {
    tet(m, A, B, C, Y, newv + 4 * n++);
    tet(m, A, B, D, Y, newv + 4 * n++);
  }
  /* from nothing: every face matched by none is on the boundary */
  EXPECT(tr_mesh_replace_open(m, NULL, 0, newv, n, NULL) == TR_OK, "%s: build: %s", name,
         tr_last_error());
  uint32_t sv[6] = {A, B, C, B, A, D}, stri[2] = {7, 7};
  tr_subfaces sub = {2, sv, stri};
  mpq_t six;
  mpq_init(six);
  mpq_set_ui(six, 9, two_sided ? 16 : 32); /* 2 area(acbd) height, per side */
  EXPECT(tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, six) == TR_OK,
         "%s: setup: %s", name, tr_last_error());
  tr_quality q;
  tr_quality_measure(m, &q);
  const double before = q.min_dihedral;
  tr_sliver_ctx c;
  tr_sliver_stats st;
  memset(&st, 0, sizeof st);
  tr_status s = tr_sliver_ctx_init(&c, m, &sub, NULL, 6, TR_SLIVER_BOUND);
  c.sub = &sub;
  if (s == TR_OK)
    s = tr_sliver_flip_pass(&c, &st);
  EXPECT(s == TR_OK, "%s: flip pass: %s", name, tr_last_error());
  EXPECT(st.facet_flips == 1, "%s: %llu facet flips", name, (unsigned long long)st.facet_flips);
  EXPECT(!has_edge(m, A, B) && has_edge(m, C, D), "%s: the diagonal is still a b", name);
  /* the sub-faces keep their slots and orientation (normal +z for all four) */
  const uint32_t f0[3] = {A, D, C}, f1[3] = {B, C, D};
  EXPECT(!memcmp(sv, f0, sizeof f0) && !memcmp(sv + 3, f1, sizeof f1),
         "%s: sub-faces (%u %u %u) (%u %u %u)", name, sv[0], sv[1], sv[2], sv[3], sv[4], sv[5]);
  EXPECT(has_face(m, A, D, C) && has_face(m, B, C, D), "%s: a new sub-face is no mesh face",
         name);
  uint32_t fa[3] = {A, C, D}, fb[3] = {A, B, C}, ea[2] = {C, D}, eb[2] = {A, B};
  EXPECT(tr_sliver_protected(&c, fa, 3) && !tr_sliver_protected(&c, fb, 3) &&
             tr_sliver_protected(&c, ea, 2) && !tr_sliver_protected(&c, eb, 2),
         "%s: the constraint sets do not follow the flip", name);
  tr_sliver_ctx_free(&c);
  tr_quality_measure(m, &q);
  EXPECT(q.min_dihedral > before + 5, "%s: smallest dihedral angle %g -> %g", name, before,
         q.min_dihedral);
  EXPECT(tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, six) == TR_OK,
         "%s: after the flip: %s", name, tr_last_error());
  mpq_clear(six);
  tr_mesh_destroy(m);
}

/* The fan a b c x1, a b x1 x2, a b x2 d over the quadrilateral, boundary below: no flip
 * with two tets a side exists, the one with three replaces the fan (3 tets -> 4). thin:
 * the input triangle is flagged thin, and nothing changes. */
static void fan_of_three(const char *name, int thin)
{
  enum { X1 = 4, X2 = 5 };
  static const double fp[6][3] = {{0, 0, 0},      {1, 0, 0},        {0.5, 0.0625, 0},
                                  {0.5, -0.5, 0}, {0.5, 0.25, 0.5}, {0.5, -0.5, 0.5}};
  tr_mesh *m = NULL;
  if (tr_mesh_create(6, 8, &m) != TR_OK) {
    EXPECT(0, "%s: no mesh", name);
    return;
  }
  uint32_t id;
  for (int i = 0; i < 6; i++)
    EXPECT(tr_mesh_add_vertex(m, fp[i], &id) == TR_OK && id == (uint32_t)i, "%s: vertex %d",
           name, i);
  uint32_t newv[12];
  tet(m, A, B, C, X1, newv);
  tet(m, A, B, X1, X2, newv + 4);
  tet(m, A, B, X2, D, newv + 8);
  EXPECT(tr_mesh_replace_open(m, NULL, 0, newv, 3, NULL) == TR_OK, "%s: build: %s", name,
         tr_last_error());
  uint32_t sv[6] = {A, B, C, B, A, D}, stri[2] = {0, 0};
  tr_subfaces sub = {2, sv, stri};
  mpq_t six;
  mpq_init(six);
  /* a b is the unit x axis and the ring lies in x = 1/2: 6 vol(a b p q) = |p_y q_z - p_z q_y|,
   * 1/32 + 3/8 + 1/4 */
  mpq_set_ui(six, 21, 32);
  EXPECT(tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, six) == TR_OK,
         "%s: setup: %s", name, tr_last_error());
  tr_quality q;
  tr_quality_measure(m, &q);
  const double before = q.min_dihedral;
  const uint32_t bad[4] = {A, B, C, X1};
  const uint32_t t = tm_find_tet(m, bad);
  EXPECT(t != TR_NONE, "%s: no tet a b c x1", name);
  tr_sliver_ctx c;
  tr_sliver_stats st;
  memset(&st, 0, sizeof st);
  const uint8_t flags[1] = {1};
  tr_status s = tr_sliver_ctx_init(&c, m, &sub, NULL, 6, TR_SLIVER_BOUND);
  c.sub = &sub;
  c.thin = thin ? flags : NULL;
  int done = 0;
  if (s == TR_OK)
    s = tr_sliver_facet_flip_tet(&c, t, &st, &done);
  EXPECT(s == TR_OK, "%s: facet flip: %s", name, tr_last_error());
  tr_sliver_ctx_free(&c);
  tr_quality_measure(m, &q);
  if (thin) {
    EXPECT(!done && st.facet_flips == 0 && has_edge(m, A, B) && m->nt - m->nfree == 3,
           "%s: a fan of three in a thin triangle was flipped", name);
    EXPECT(q.min_dihedral == before, "%s: smallest angle %g -> %g", name, before,
           q.min_dihedral);
  } else {
    EXPECT(done && st.facet_flips == 1, "%s: %llu facet flips", name,
           (unsigned long long)st.facet_flips);
    EXPECT(!has_edge(m, A, B) && has_edge(m, C, D) && m->nt - m->nfree == 4,
           "%s: the diagonal is still a b, or not 4 tets", name);
    const uint32_t f0[3] = {A, D, C}, f1[3] = {B, C, D};
    EXPECT(!memcmp(sv, f0, sizeof f0) && !memcmp(sv + 3, f1, sizeof f1),
           "%s: sub-faces (%u %u %u) (%u %u %u)", name, sv[0], sv[1], sv[2], sv[3], sv[4],
           sv[5]);
    /* 8.97 degrees (a b c x1) -> 41.85 (the ring split by c x2), by hand */
    EXPECT(before < 9 && q.min_dihedral > 41, "%s: smallest dihedral angle %g -> %g", name,
           before, q.min_dihedral);
  }
  EXPECT(tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, six) == TR_OK,
         "%s: after: %s", name, tr_last_error());
  mpq_clear(six);
  tr_mesh_destroy(m);
}

static void a_fan_of_three_tets_is_flipped_when_none_of_two_is(void)
{
  fan_of_three("fan of three", 0);
}

static void a_fan_of_three_tets_in_a_thin_triangle_is_left(void)
{
  fan_of_three("thin fan of three", 1);
}

static void an_edge_inside_a_facet_is_flipped_on_both_sides(void)
{
  flip_case("two-sided", 1);
}

static void an_edge_inside_a_boundary_facet_is_flipped(void)
{
  flip_case("one-sided", 0);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"two_sided", an_edge_inside_a_facet_is_flipped_on_both_sides, NULL},
      {"one_sided", an_edge_inside_a_boundary_facet_is_flipped, NULL},
      {"fan_of_three", a_fan_of_three_tets_is_flipped_when_none_of_two_is, NULL},
      {"thin_fan_of_three", a_fan_of_three_tets_in_a_thin_triangle_is_left, NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
