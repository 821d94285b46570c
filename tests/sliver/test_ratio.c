/* The sliver stage's ratio pass (src/sliver/ratio.c): interior vertices of tets over the
 * radius-edge bound move to where their star's largest ratio is smaller, without taking
 * any angle of the star under min(its smallest angle, the stage's bound) and without
 * lowering the mesh's smallest angle. A hand-made box, then refined surfaces through the
 * whole pipeline; every mesh through the mesh validator (the pipeline's also through the
 * exact conformity validator, tmesh.h). */
#include <gmp.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "refine/quality.h"
#include "sliver/sliver.h"
#include "../pipeline/tmesh.h"
#include "tico.h"

/* The star of v: its largest radius-edge ratio and smallest dihedral angle. */
static void star_shape(const tr_mesh *m, uint32_t v, double *top, double *low)
{
  *top = 0;
  *low = 180;
  for (uint32_t t = 0; t < m->nt; t++)
    if (tr_tet_is_real(m, t) && tr_ncode(m, t, v) >= 0) {
      double r, q = tr_sliver_min_dihedral_at(m, m->tv + 4 * (size_t)t, TR_NONE, NULL, &r);
      *top = fmax(*top, r);
      *low = fmin(*low, q);
    }
}

static double mesh_min(const tr_mesh *m)
{
  tr_quality q;
  tr_quality_measure(m, &q);
  return q.min_dihedral;
}

/* The unit box's corners (0..7) and an interior point near its face x = 1 (8), in x; their
 * Delaunay mesh, NULL (counted) if it fails. */
static tr_mesh *off_centre_box(double x[27])
{
  for (int i = 0; i < 8; i++)
    for (int k = 0; k < 3; k++)
      x[3 * i + k] = (i >> k) & 1 ? 1.0 : 0.0;
  x[24] = 0.9375, x[25] = 0.5, x[26] = 0.4375;
  tr_mesh *m = NULL;
  if (tr_delaunay_build(x, 9, &m) != TR_OK) {
    EXPECT(0, "Delaunay: %s", tr_last_error());
    return NULL;
  }
  return m;
}

/* The off-centre box (off_centre_box): the tets
 * on that face are flat and long, their ratios far over 1.414. With 8 the only vertex that
 * may move, the pass moves it, its star's largest ratio falls under 1.414, its smallest
 * angle does not drop, no other vertex moves, and the mesh stays valid with the box's exact
 * volume. A second pass finds nothing to do. */
static void an_off_centre_point_moves_and_its_star_comes_under_the_bound(void)
{
  double x[27];
  tr_mesh *m = off_centre_box(x);
  if (!m)
    return;
  double top0, low0, top1, low1, min0 = mesh_min(m);
  star_shape(m, 8, &top0, &low0);
  EXPECT(top0 > 1.414, "the star's largest ratio %g is not over the bound", top0);
  tr_subfaces none = {0, NULL, NULL};
  tr_sliver_ctx c;
  tr_sliver_stats st;
  memset(&st, 0, sizeof st);
  tr_status s = tr_sliver_ctx_init(&c, m, &none, NULL, 8, TR_SLIVER_BOUND);
  c.keep.ratio = 1.414;
  if (s == TR_OK)
    s = tr_sliver_ratio_pass(&c, &st);
  EXPECT(s == TR_OK, "ratio pass: %s", tr_last_error());
  EXPECT(st.smoothed >= 1, "vertex 8 did not move");
  for (uint32_t v = 0; v < 8; v++)
    EXPECT(!memcmp(x + 3 * v, m->xyz + 3 * (size_t)v, 24), "box corner %u moved", v);
  star_shape(m, 8, &top1, &low1);
  EXPECT(top1 <= 1.414, "the star's largest ratio %g -> %g: not under 1.414", top0, top1);
  EXPECT(low1 >= fmin(low0, TR_SLIVER_BOUND), "the star's smallest angle %g -> %g", low0, low1);
  EXPECT(mesh_min(m) >= min0, "the mesh's smallest angle %g -> %g", min0, mesh_min(m));
  uint64_t moved = st.smoothed;
  if (s == TR_OK)
    s = tr_sliver_ratio_pass(&c, &st);
  EXPECT(s == TR_OK && st.smoothed == moved, "a second pass moved %llu more",
         (unsigned long long)(st.smoothed - moved));
  tr_sliver_ctx_free(&c);
  mpq_t six;
  mpq_init(six);
  mpq_set_ui(six, 6, 1);
  s = tr_check_mesh(m, TR_CHK_TOPOLOGY, six);
  EXPECT(s == TR_OK, "mesh validator: %s", tr_last_error());
  mpq_clear(six);
  fprintf(stderr, "box: star ratio %.3f -> %.3f, star angle %.3f -> %.3f\n", top0, top1, low0, low1);
  tr_mesh_destroy(m);
}

/* Without a ratio bound (sliver removal under -a alone) the pass does nothing. */
static void no_ratio_bound_no_move(void)
{
  double x[27];
  tr_mesh *m = off_centre_box(x);
  if (!m)
    return;
  tr_subfaces none = {0, NULL, NULL};
  tr_sliver_ctx c;
  tr_sliver_stats st;
  memset(&st, 0, sizeof st);
  tr_status s = tr_sliver_ctx_init(&c, m, &none, NULL, 8, TR_SLIVER_BOUND);
  if (s == TR_OK)
    s = tr_sliver_ratio_pass(&c, &st);
  EXPECT(s == TR_OK && st.smoothed == 0, "moved %llu vertices without a ratio bound",
         (unsigned long long)st.smoothed);
  EXPECT(!memcmp(x + 24, m->xyz + 24, 24), "vertex 8 moved");
  tr_sliver_ctx_free(&c);
  tr_mesh_destroy(m);
}

/* The regular icosahedron subdivided twice onto its circumsphere (320 triangles, an
 * exact-double surface: each new vertex is the rounded projection, fixed once), into plc. */
static tr_status icosphere(tr_plc **plc)
{
  double x[3 * 162];
  uint32_t t[3 * 320], nv = 12, nt = 60;
  TR_CHECK(tico_icosahedron(x, t));
  const double f = (1 + sqrt(5.0)) / 2;
  double rad = sqrt(1 + f * f);
  for (int level = 0; level < 2; level++) {
    uint32_t n = nt / 3, mid[3];
    uint32_t out[3 * 320], no = 0;
    for (uint32_t i = 0; i < n; i++) {
      for (int e = 0; e < 3; e++) { /* the edge's midpoint, shared by its two triangles */
        uint32_t p = t[3 * i + e], q = t[3 * i + (e + 1) % 3];
        double y[3], l = 0;
        for (int k = 0; k < 3; k++) {
          y[k] = 0.5 * (x[3 * p + k] + x[3 * q + k]);
          l += y[k] * y[k];
        }
        for (int k = 0; k < 3; k++)
          y[k] *= rad / sqrt(l);
        uint32_t j = 0;
        while (j < nv && memcmp(x + 3 * j, y, sizeof y))
          j++;
        if (j == nv)
          memcpy(x + 3 * nv++, y, sizeof y);
        mid[e] = j;
      }
      const uint32_t *v = t + 3 * i;
      const uint32_t sub[12] = {v[0], mid[0], mid[2], mid[0], v[1], mid[1],
                                mid[2], mid[1], v[2], mid[0], mid[1], mid[2]};
      memcpy(out + no, sub, sizeof sub);
      no += 12;
    }
    memcpy(t, out, sizeof *t * no);
    nt = no;
  }
  if (nv != 162 || nt != 3 * 320)
    return tr_error(TR_ERR_INTERNAL, "icosphere: %u vertices, %u triangles", nv, nt / 3);
  TR_CHECK(tr_plc_create(plc));
  return tr_plc_set(*plc, x, nv, t, nt / 3, NULL);
}

static uint64_t over(const tr_mesh *m, double bound)
{
  uint64_t n = 0;
  for (uint32_t t = 0; t < m->nt; t++)
    if (tr_tet_is_real(m, t)) {
      double r;
      tr_sliver_min_dihedral_at(m, m->tv + 4 * (size_t)t, TR_NONE, NULL, &r);
      n += r > bound;
    }
  return n;
}

/* A sphere refined under --quality 1.414: refinement alone leaves no tet over the bound;
 * the sliver stage without its ratio pass left 4.7% of CGAL's sphere.off over it. With the
 * pass, at most 1% of the tets are over, the smallest angle is at least the rounds' bound
 * and at least that of refinement alone, and both meshes validate exactly. */
static void a_refined_sphere_keeps_nearly_every_tet_under_the_bound(void)
{
  tr_plc *p = NULL;
  if (icosphere(&p) != TR_OK) {
    EXPECT(0, "icosphere: %s", tr_last_error());
    tr_plc_destroy(p);
    return;
  }
  tr_options o0 = tm_refinement(1.414, 0), o3 = tm_options();
  o3.quality_ratio = 1.414;
  tm_run r0, r3;
  tr_mesh *m0 = tm_mesh(&r0, "icosphere -O 0", p, &o0, TR_CHK_TOPOLOGY);
  tr_mesh *m3 = tm_mesh(&r3, "icosphere", p, &o3, TR_CHK_TOPOLOGY);
  if (m0 && m3) {
    uint64_t n0 = over(m0, 1.414), n3 = over(m3, 1.414), t3 = r3.st.volume_elements;
    EXPECT(n3 * 100 <= t3, "icosphere: %llu of %llu tets over 1.414",
           (unsigned long long)n3, (unsigned long long)t3);
    EXPECT(r3.st.min_dihedral >= TR_SLIVER_BOUND && r3.st.min_dihedral >= r0.st.min_dihedral,
           "icosphere: smallest dihedral %.3f (refinement alone %.3f)", r3.st.min_dihedral,
           r0.st.min_dihedral);
    fprintf(stderr, "icosphere: over 1.414: -O 0 %llu of %llu, default %llu of %llu; "
            "min dihedral %.3f -> %.3f\n", (unsigned long long)n0,
            (unsigned long long)r0.st.volume_elements, (unsigned long long)n3,
            (unsigned long long)t3, r0.st.min_dihedral, r3.st.min_dihedral);
  }
  tm_free(&r0);
  tm_free(&r3);
  tr_plc_destroy(p);
}

/* The per-slot measures (tr_sliver_tet_min) name their vertex ids: a trial undone gives its
 * ids back, and tr_sliver_forget_from(c, nv) must forget every measure naming an id from nv
 * on, and no other. Vertex 8 of the off-centre box stands for a given-back id: moved
 * without tr_sliver_forget, its tets keep their old measure until it is forgotten, and
 * forgetting from 9 on leaves them. */
static void forgetting_given_back_ids_measures_their_tets_again(void)
{
  double x[27];
  tr_mesh *m = off_centre_box(x);
  if (!m)
    return;
  tr_subfaces none = {0, NULL, NULL};
  tr_sliver_ctx c;
  tr_status s = tr_sliver_ctx_init(&c, m, &none, NULL, 8, TR_SLIVER_BOUND);
  EXPECT(s == TR_OK, "sliver context: %s", tr_last_error());
  uint32_t with8 = TR_NONE; /* every tet of the box has 8: the corners are cospherical */
  for (uint32_t t = 0; s == TR_OK && t < m->nt && with8 == TR_NONE; t++)
    if (tr_tet_is_real(m, t) && tr_ncode(m, t, 8) >= 0)
      with8 = t;
  EXPECT(with8 != TR_NONE, "the box has no tet at 8");
  if (s == TR_OK && with8 != TR_NONE) {
    double r, a8 = tr_sliver_tet_min(&c, with8, &r);
    m->xyz[24] = 0.5; /* another point under id 8: the box's centre */
    EXPECT(tr_sliver_tet_min(&c, with8, &r) == a8, "the measure was not remembered");
    tr_sliver_forget_from(&c, 9);
    EXPECT(tr_sliver_tet_min(&c, with8, &r) == a8, "forget_from(9) forgot a tet of 8");
    tr_sliver_forget_from(&c, 8);
    double now = tr_sliver_min_dihedral_at(m, m->tv + 4 * (size_t)with8, TR_NONE, NULL, &r);
    EXPECT(tr_sliver_tet_min(&c, with8, &r) == now && now != a8,
           "after forget_from(8) the tet of 8 measures %g, not its new %g (old %g)",
           tr_sliver_tet_min(&c, with8, &r), now, a8);
  }
  tr_sliver_ctx_free(&c);
  tr_mesh_destroy(m);
}

/* The ratio a new tet under the stage's bound may have (tr_sliver_ratio_allowed, through
 * tr_sliver_keeps_bounds, which every flip, move and point asks): the ratio bound or the
 * largest ratio of the tets it replaces, but never over the largest ratio the stage
 * started from. The replaced tets' ratio alone is a moving reference: a tet with no angle
 * under the bound may have any ratio, so one step may make a tet of 25 degrees and ratio
 * 97.5 and a later step replacing it a tet of 12.5 degrees and ratio 97.25, over the 52.98
 * the stage started from (the figures of star_rounding_budget.off at -O 3, where the cap
 * trials compared with the mesh's largest ratio under the bound, which the pinned tets'
 * refinement had raised to 97.25). Without a known start (0) the old rule holds. */
static void a_replaced_tets_ratio_allows_no_more_than_the_ratio_the_stage_started_from(void)
{
  double x[27];
  tr_mesh *m = off_centre_box(x);
  if (!m)
    return;
  tr_subfaces none = {0, NULL, NULL};
  tr_sliver_ctx c;
  tr_status s = tr_sliver_ctx_init(&c, m, &none, NULL, 8, TR_SLIVER_BOUND);
  EXPECT(s == TR_OK, "sliver context: %s", tr_last_error());
  uint32_t t = 0;
  while (t < m->nt && !tr_tet_is_real(m, t))
    t++;
  if (s == TR_OK && t < m->nt) {
    const uint32_t *p = m->tv + 4 * (size_t)t; /* no volume bound: only the figures count */
    c.keep.ratio = 1.414;
    EXPECT(tr_sliver_ratio_allowed(&c, 97.5) == 97.5 &&
               tr_sliver_keeps_bounds(&c, p, TR_NONE, NULL, 0, 97.25, 12.5, 97.5),
           "no start known: the replaced tets' 97.5 should allow 97.25");
    c.ratio_start = 52.98;
    EXPECT(tr_sliver_ratio_allowed(&c, 97.5) == 52.98, "allowed %g over the start 52.98",
           tr_sliver_ratio_allowed(&c, 97.5));
    EXPECT(tr_sliver_ratio_allowed(&c, 30) == 30, "replaced 30: allowed %g",
           tr_sliver_ratio_allowed(&c, 30));
    EXPECT(tr_sliver_ratio_allowed(&c, 1) == 1.414, "replaced 1: allowed %g, not the bound",
           tr_sliver_ratio_allowed(&c, 1));
    EXPECT(!tr_sliver_keeps_bounds(&c, p, TR_NONE, NULL, 0, 97.25, 12.5, 97.5),
           "a tet of 12.5 degrees and ratio 97.25 kept over the start's 52.98");
    EXPECT(tr_sliver_keeps_bounds(&c, p, TR_NONE, NULL, 0, 97.5, 25, 0),
           "a tet with no angle under the bound refused for its ratio");
    EXPECT(tr_sliver_keeps_bounds(&c, p, TR_NONE, NULL, 0, 52.98, 12.5, 97.5) &&
               tr_sliver_keeps_bounds(&c, p, TR_NONE, NULL, 0, 45, 12.5, 45) &&
               !tr_sliver_keeps_bounds(&c, p, TR_NONE, NULL, 0, 46, 12.5, 45),
           "up to the start, and up to the replaced tets' ratio under it");
    c.ratio_start = 1.2; /* a start under the bound: the bound */
    EXPECT(tr_sliver_ratio_allowed(&c, 97.5) == 1.414, "start 1.2: allowed %g",
           tr_sliver_ratio_allowed(&c, 97.5));
  }
  tr_sliver_ctx_free(&c);
  tr_mesh_destroy(m);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"box", an_off_centre_point_moves_and_its_star_comes_under_the_bound, NULL},
      {"no_bound", no_ratio_bound_no_move, NULL},
      {"sphere", a_refined_sphere_keeps_nearly_every_tet_under_the_bound, NULL},
      {"forget_from", forgetting_given_back_ids_measures_their_tets_again, NULL},
      {"allowance", a_replaced_tets_ratio_allows_no_more_than_the_ratio_the_stage_started_from,
       NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
