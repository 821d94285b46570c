/* Flat sub-faces (src/refine/flat.c) on a hand-made state: the tetrahedron A B C D whose
 * face ABC has a 3.6-degree corner at B, with a point x already on BC, so
 * that the sub-face (A, B, x) has a 174-degree angle at x opposite the sub-segment AB,
 * which the small-angle rules protect from x. Refinement with no bound (so that only the
 * flat sub-face can act) and tr_refine_params.flat_splits splits AB once, at x's foot,
 * exactly on AB; it leaves the state as it is without flat_splits, and also when ABC has
 * an angle over 120 degrees itself. Every mesh goes through the mesh validator (with its
 * exact volume; it also requires canonical Steiner coordinates: the foot's 26/64 of AB was
 * kept as such, and mpq_equal, which compares limbs, then took equal areas for different
 * ones) and the exact conformity validator. */
#include <gmp.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "pipeline/pipeline.h"
#include "refine/refine.h"
#include "../pipeline/tmesh.h"

enum { A, B, C, D, XM };

static double angle_at(const tr_mesh *m, uint32_t o, uint32_t p, uint32_t q)
{
  const double *O = m->xyz + 3 * (size_t)o, *P = m->xyz + 3 * (size_t)p, *Q = m->xyz + 3 * (size_t)q;
  double a[3], b[3];
  for (int i = 0; i < 3; i++) {
    a[i] = P[i] - O[i];
    b[i] = Q[i] - O[i];
  }
  double c = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) /
             sqrt((a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) * (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
  return acos(c < -1 ? -1 : c > 1 ? 1 : c) * (180 / 3.14159265358979323846);
}

/* The sub-faces of the state: the input triangles, the one with edge BC split at x. */
static void subfaces_with_x(const tr_plc *plc, tr_subfaces *sub)
{
  sub->n = 0;
  sub->v = malloc(3 * sizeof *sub->v * (plc->ntris + 2));
  sub->tri = malloc(sizeof *sub->tri * (plc->ntris + 2));
  for (uint32_t i = 0; i < plc->ntris; i++) {
    const uint32_t *T = plc->tris + 3 * i;
    int k = -1;
    for (int e = 0; e < 3; e++)
      if ((T[e] == B && T[(e + 1) % 3] == C) || (T[e] == C && T[(e + 1) % 3] == B))
        k = e;
    if (k < 0) {
      memcpy(sub->v + 3 * sub->n, T, 3 * sizeof *T);
      sub->tri[sub->n++] = i;
      continue;
    }
    /* (p, q, r) with p q the split edge: (p, x, r) and (x, q, r), same orientation */
    uint32_t p = T[k], q = T[(k + 1) % 3], r = T[(k + 2) % 3];
    uint32_t f1[3] = {p, XM, r}, f2[3] = {XM, q, r};
    memcpy(sub->v + 3 * sub->n, f1, sizeof f1);
    sub->tri[sub->n++] = i;
    memcpy(sub->v + 3 * sub->n, f2, sizeof f2);
    sub->tri[sub->n++] = i;
  }
}

/* ABC: right-angled at A (ABC's angles 90, 3.6, 86.4 degrees; 6V = 75/4; x at 0.4 of BC)
 * or, with cap, with C at (8, 0.5, 0) (angles 14, 3.6, 162.4; 6V = 15; x its midpoint):
 * x = (4, 0.25, 0) exactly on BC either way. */
static void flat_case(const char *name, int cap, int on, uint64_t want)
{
  double X[15] = {10, 0, 0, 0, 0, 0, 10, 0.625, 0, 5, 0.25, 3, 4, 0.25, 0};
  if (cap) {
    X[6] = 8;
    X[7] = 0.5;
  }
  tr_plc *plc = tm_plc(X, 4, (const uint32_t[]){0, 1, 2, 0, 3, 1, 1, 3, 2, 0, 2, 3}, 4);
  tr_mesh *m = NULL;
  if (!plc || tr_delaunay_build(X, 5, &m) != TR_OK) {
    EXPECT(0, "%s: set-up failed: %s", name, tr_last_error());
    tr_plc_destroy(plc);
    return;
  }
  tr_subfaces sub;
  subfaces_with_x(plc, &sub);
  EXPECT(angle_at(m, XM, A, B) > 170, "%s: the state has no flat sub-face (%g degrees)", name,
         angle_at(m, XM, A, B));
  tr_refine_params par;
  memset(&par, 0, sizeof par); /* no bound: no tet is bad, only the flat sub-face acts */
  par.flat_splits = on;
  tr_refine_stats st;
  tr_status s = tr_refine(m, plc, &sub, &par, &st);
  EXPECT(s == TR_OK, "%s: %s", name, tr_last_error());
  EXPECT(st.points == want && st.on_segments == want, "%s: %llu points, %llu on edges (want %llu)",
         name, (unsigned long long)st.points, (unsigned long long)st.on_segments,
         (unsigned long long)want);
  /* the new point: on AB exactly, at x's foot (x = 4) within a sixty-fourth of AB */
  for (uint32_t v = 5; v < m->nv; v++) {
    tr_point p = tr_mesh_point(m, v);
    mpq_t c;
    mpq_init(c);
    tr_point_get_q(&p, 1, c);
    int on_ab = mpq_sgn(c) == 0;
    tr_point_get_q(&p, 2, c);
    on_ab &= mpq_sgn(c) == 0;
    tr_point_get_q(&p, 0, c);
    double x = mpq_get_d(c);
    mpq_clear(c);
    EXPECT(on_ab && fabs(x - 4) <= 10.0 / 64, "%s: vertex %u at (%g, %g, %g): not x's foot "
           "on AB", name, v, p.d[0], p.d[1], p.d[2]);
  }
  /* with the split, no sub-face has a flat angle at x any more */
  for (uint32_t i = 0; want && i < sub.n; i++)
    for (int k = 0; k < 3; k++)
      if (sub.v[3 * i + k] == XM) {
        double a = angle_at(m, XM, sub.v[3 * i + (k + 1) % 3], sub.v[3 * i + (k + 2) % 3]);
        EXPECT(a < 120, "%s: sub-face %u still %g degrees at x", name, i, a);
      }
  mpq_t six_v; /* 6 V = |(A - B) . ((C - B) x (D - B))| = 10 * C_y * 3 */
  mpq_init(six_v);
  mpq_set_ui(six_v, cap ? 15 : 75, cap ? 1 : 4);
  s = tr_check_mesh(m, TR_CHK_TOPOLOGY, six_v);
  EXPECT(s == TR_OK, "%s: mesh validator: %s", name, tr_last_error());
  s = tr_check_conformity(m, plc, NULL, TR_CONF_KEEP_EDGES);
  EXPECT(s == TR_OK, "%s: exact conformity: %s", name, tr_last_error());
  mpq_clear(six_v);
  tr_subfaces_free(&sub);
  tr_mesh_destroy(m);
  tr_plc_destroy(plc);
}

static void foot(void)
{
  flat_case("foot", 0, 1, 1);
}

static void off(void)
{
  flat_case("off", 0, 0, 0);
}

static void input_cap(void)
{
  flat_case("input_cap", 1, 1, 0);
}

/* tests/data/flat_split_star.off, a star-shaped polyhedron of 26 points the pipeline fuzz
 * target made: under R = 1.414, -O 3, spacing radii, sub-face ratio 1.414 and kept input
 * edges, flat splits put points at 32/64 of sub-segments. The in-memory mesh must pass the
 * mesh validator (canonical coordinates) and exact conformity against the meshed surface
 * (it failed on input triangle 26, "covered / own projected area = 1", while the written
 * --exact file passed `tetrec check`). */
static void star(const char *path)
{
  tr_plc *p = tm_read(path);
  tr_options opt;
  tr_options_default(&opt);
  opt.quality_ratio = 1.414;
  opt.optimize = 3;
  opt.refine_spacing_radii = 1;
  opt.quality_subface_ratio = 1.414;
  opt.keep_edges = 1;
  opt.refine_budget = 500;
  tr_mesh *m = NULL;
  tr_plc *used = NULL;
  tr_stats st = {.size = sizeof st};
  tr_status s = p ? tr_mesh_plc_flags(p, &opt, &m, &st, &used, TR_PIPE_KEEP_EXACT)
                  : tr_error(TR_ERR_IO, "cannot read %s", path);
  EXPECT(s == TR_OK, "%s: %s", path, tr_last_error());
  if (m) {
    EXPECT(tr_check_mesh(m, TR_CHK_TOPOLOGY, NULL) == TR_OK, "%s: mesh validator: %s", path,
           tr_last_error());
    EXPECT(tr_check_conformity(m, used, NULL, 0) == TR_OK, "%s: exact conformity: %s", path,
           tr_last_error());
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
  tr_plc_destroy(p);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"foot", foot, NULL},
      {"off", off, NULL},
      {"input_cap", input_cap, NULL},
      {"star", NULL, star},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
