/* Cap clusters (src/refine/capcluster.c, rf_caps; the rule in angles.c) on a tetrahedron
 * whose bottom face is cut along a crack: A = (0,0,0) to D = (1,0,0) is an edge, and B, C
 * lie 1e-5 beside it (and a few 1e-6 off the face's plane, so that nothing is coplanar),
 * at x = 0.3 and 0.6. The caps D-A-C (apex C) and B-C-A (apex B) share edge A-C, so
 * edges A-D and B-C lie 1e-5 apart along 0.3 with no input vertex in common: the shape of
 * 32770.stl's two costly spots (tests/data/cap_strip.off holds the same surface).
 * Refinement used to split A-D for the points on B-C and back down to pieces about 1e-5
 * long, a cascade that had run 8 minutes on these 8 triangles when it was stopped. Every
 * mesh goes through the mesh validator and the exact conformity validator (with the
 * enclosed volume). */
#include <stdlib.h>
#include <string.h>

#include "outer/color.h"
#include "refine/refine.h"
#include "refine/refine_impl.h"
#include "../pipeline/tmesh.h"
#include "../pipeline/tplc.h"
#include "../pipeline/trecover.h"

enum { A, D, Z, U, B, C };

static tr_plc *cap_strip(void)
{
  static const double x[18] = {0, 0, 0,   1, 0, 0,       0.5, 1, 0,
                               0.5, 0.3, 1, 0.3, 1e-5, 2e-6, 0.6, 1e-5, -3e-6};
  static const uint32_t t[24] = {A, Z, B, B, Z, C, C, Z, D, D, A, C,
                                 B, C, A, A, D, U, D, Z, U, Z, A, U};
  return tm_plc(x, 6, t, 8);
}

/* A tetrahedron A-Z-D-U whose bottom face is cut at C, 1e-15 beside A-D at x = 0.6 (and
 * 3e-16 off the plane): the cap D-A-C, alone, flat but for the last bits of the doubles
 * (the two caps of 93703.stl are 2e-15 and 1e-14 of their edge's length off it), coordinates
 * times `scale`. */
static tr_plc *flat_cap(double scale)
{
  double x[15] = {0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, 0.3, 1, 0.6, 1e-15, -3e-16};
  for (int i = 0; i < 15; i++)
    x[i] *= scale;
  static const uint32_t t[18] = {A, Z, 4, 4, Z, D, D, A, 4, A, D, U, D, Z, U, Z, A, U};
  return tm_plc(x, 5, t, 6);
}

/* The two caps make one cluster named by the smaller (triangle 3); its five edges map to
 * it, the fan's edges at Z and the side faces' to none; the copy made for the set-up
 * memo answers the same. A lone cap and a tetrahedron make none. */
static void clusters(void)
{
  tr_plc *p = cap_strip();
  rf_caps k = {0}, k2 = {0};
  tr_status s = rf_caps_build(&k, p);
  EXPECT(s == TR_OK, "build: %s", tr_last_error());
  EXPECT(k.n == 2, "%u caps found, not 2", k.n);
  s = rf_caps_copy(&k2, &k, p);
  EXPECT(s == TR_OK, "copy: %s", tr_last_error());
  const rf_caps *both[2] = {&k, &k2};
  for (int i = 0; i < 2 && s == TR_OK && k.n == 2; i++) {
    const rf_caps *q = both[i];
    EXPECT(q->tri[3] == 3 && q->tri[4] == 3, "the caps' clusters: %u %u, not 3 3", q->tri[3],
           q->tri[4]);
    for (uint32_t j = 0; j < 8; j++)
      EXPECT(j == 3 || j == 4 || q->tri[j] == TR_NONE, "triangle %u in cluster %u", j, q->tri[j]);
    const uint32_t in[5][2] = {{A, D}, {B, C}, {A, C}, {A, B}, {C, D}};
    for (int e = 0; e < 5; e++)
      EXPECT(rf_caps_edge(q, in[e][1], in[e][0]) == 3, "edge %u-%u: cluster %u, not 3",
             in[e][0], in[e][1], rf_caps_edge(q, in[e][1], in[e][0]));
    const uint32_t out[4][2] = {{A, Z}, {B, Z}, {A, U}, {Z, U}};
    for (int e = 0; e < 4; e++)
      EXPECT(rf_caps_edge(q, out[e][0], out[e][1]) == TR_NONE, "edge %u-%u in a cluster",
             out[e][0], out[e][1]);
    EXPECT(q->vert[Z] == TR_NONE && q->vert[U] == TR_NONE && q->vert[B] == 3,
           "vertex clusters: Z %u, U %u, B %u", q->vert[Z], q->vert[U], q->vert[B]);
  }
  rf_caps_free(&k);
  rf_caps_free(&k2);
  /* one cap alone (C beside A-D, no B) is no cluster: its sharp corners are wedges the
   * other rules know */
  static const double x1[15] = {0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, 0.3, 1, 0.6, 1e-5, -3e-6};
  static const uint32_t t1[18] = {A, Z, 4, 4, Z, D, D, A, 4, A, D, U, D, Z, U, Z, A, U};
  tr_plc *one = tm_plc(x1, 5, t1, 6);
  s = rf_caps_build(&k, one);
  EXPECT(s == TR_OK && k.n == 0 && !k.tri && !k.vert, "a lone cap makes a cluster (%u)", k.n);
  rf_caps_free(&k);
  tr_plc_destroy(one);
  /* a flat lone cap (its apex 1e-15 of its edge's length off it) is a cluster of its own,
   * at any scale */
  static const double sc[3] = {1, 1e200, 1e-200};
  for (int i = 0; i < 3; i++) {
    tr_plc *flat = flat_cap(sc[i]);
    s = rf_caps_build(&k, flat);
    EXPECT(s == TR_OK && k.n == 1 && k.tri && k.tri[2] == 2 && rf_caps_edge(&k, A, D) == 2,
           "scale %g: a flat lone cap makes no cluster of its own (%u)", sc[i], k.n);
    rf_caps_free(&k);
    tr_plc_destroy(flat);
  }
  /* a regular tetrahedron: no cap, nothing allocated */
  static const double x[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  static const uint32_t t[12] = {0, 2, 1, 0, 1, 3, 1, 2, 3, 2, 0, 3};
  tr_plc *q = tm_plc(x, 4, t, 4);
  s = rf_caps_build(&k, q);
  EXPECT(s == TR_OK && k.n == 0 && !k.tri && !k.vert, "a tetrahedron has caps (%u)", k.n);
  EXPECT(rf_caps_edge(&k, 0, 1) == TR_NONE, "an edge of no cap has a cluster");
  rf_caps_free(&k);
  tr_plc_destroy(q);
  tr_plc_destroy(p);
}

/* Refinement alone under R = 1.414 ends within a few points (the tets along the crack are
 * left as forced), far below a budget the cascade ran into. */
static void strip_refines(void)
{
  tr_plc *plc = cap_strip();
  trec_run r;
  tr_status s = trec_to_recovery(plc, &r);
  uint32_t nreg = 0;
  if (s == TR_OK)
    s = tr_outer_color(r.m, &r.sub, 0, NULL, &nreg);
  tr_refine_params par;
  memset(&par, 0, sizeof par);
  par.ratio = 1.414;
  par.budget = 3000;
  par.wedge_grading = 1;
  tr_refine_stats st;
  if (s == TR_OK)
    s = tr_refine(r.m, plc, &r.sub, &par, &st);
  EXPECT(s == TR_OK, "refinement: %s", tr_last_error());
  if (s == TR_OK) {
    EXPECT(st.points <= 100, "%llu points (%llu on edges) for 8 triangles",
           (unsigned long long)st.points, (unsigned long long)st.on_segments);
    EXPECT(st.skipped_small_angle > 0, "no tet left as forced by the crack");
    s = tr_check_mesh(r.m, TR_CHK_TOPOLOGY, NULL);
    EXPECT(s == TR_OK, "mesh validator: %s", tr_last_error());
    s = tr_check_conformity(r.m, plc, NULL, 0);
    EXPECT(s == TR_OK, "exact conformity: %s", tr_last_error());
    fprintf(stderr, "cap strip, refinement alone: %llu points, %llu tets left as forced\n",
            (unsigned long long)st.points, (unsigned long long)st.skipped_small_angle);
  }
  trec_free(&r);
  tr_plc_destroy(plc);
}

/* The flat lone cap under R = 1.414, the whole pipeline: its long edge is not split down
 * toward the apex's height (before the rule, 415 refinement and 318 sliver points and
 * 3,614 tets for these 6 triangles; with it 0 and 3, 11 tets). */
static void flat_cap_pipeline(void)
{
  tr_plc *p = flat_cap(1);
  tr_options opt = tm_options();
  opt.quality_ratio = 1.414;
  tm_run r;
  if (tm_mesh(&r, "flat lone cap", p, &opt, TR_CHK_TOPOLOGY)) {
    uint64_t added = r.st.points_added_for_quality + r.st.points_added_for_sliver;
    EXPECT(added <= 50, "%llu points added for 6 triangles",
           (unsigned long long)added);
    fprintf(stderr, "flat lone cap: %llu quality and %llu sliver points, %u tets\n",
            (unsigned long long)r.st.points_added_for_quality,
            (unsigned long long)r.st.points_added_for_sliver, tr_mesh_num_tets(r.m));
  }
  tm_free(&r);
  tr_plc_destroy(p);
}

/* The whole pipeline on the data file, sliver removal included. */
static void strip_pipeline(const char *path)
{
  tr_plc *p = tm_read(path);
  tr_options opt = tm_options();
  opt.quality_ratio = 1.414;
  tm_run r;
  if (tm_mesh(&r, "cap strip", p, &opt, TR_CHK_TOPOLOGY)) {
    uint64_t added = r.st.points_added_for_quality + r.st.points_added_for_sliver;
    EXPECT(added <= 200, "%llu points added for 8 triangles", (unsigned long long)added);
    fprintf(stderr, "cap strip: %llu quality and %llu sliver points, %u tets\n",
            (unsigned long long)r.st.points_added_for_quality,
            (unsigned long long)r.st.points_added_for_sliver, tr_mesh_num_tets(r.m));
  }
  tm_free(&r);
  tr_plc_destroy(p);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"clusters", clusters, NULL},
      {"strip_refines", strip_refines, NULL},
      {"strip_pipeline", NULL, strip_pipeline},
      {"flat_cap_pipeline", flat_cap_pipeline, NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
