/* Refinement on merged planar facets (src/core/facets.h): a thin box whose sides are two
 * exactly coplanar triangles each, with skinny diagonals. Every output goes through the
 * mesh validator and the exact conformity validator. */
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "mesh/check.h"
#include "mesh/conform.h"
#include "pipeline/pipeline.h"
#include "refine/quality.h"
#include "../pipeline/texpect.h"

/* The box [0,1] x [0,0.05] x [0,0.05] (12 triangles, six diagonals). */
static tr_plc *thin_box(void)
{
  double x[24], hi[3] = {1, 0.05, 0.05};
  for (int i = 0; i < 8; i++)
    for (int k = 0; k < 3; k++)
      x[3 * i + k] = (i >> k) & 1 ? hi[k] : 0;
  static const uint32_t t[36] = {0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3, 0, 4, 5, 0, 5, 1,
                                 2, 3, 7, 2, 7, 6, 0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5};
  tr_plc *p = NULL;
  if (tr_plc_create(&p) != TR_OK || tr_plc_set(p, x, 8, t, 12, NULL) != TR_OK) {
    fprintf(stderr, "cannot build PLC: %s\n", tr_last_error());
    exit(1);
  }
  return p;
}

static tr_mesh *refine(const tr_plc *plc, int keep_edges, tr_stats *st, tr_plc **used)
{
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = 0;
  opt.quality_ratio = 1.414;
  opt.keep_edges = keep_edges;
  tr_mesh *m = NULL;
  memset(st, 0, sizeof *st);
  st->size = sizeof *st;
  tr_status s = tr_mesh_plc_ex(plc, &opt, &m, st, used);
  if (s != TR_OK) {
    EXPECT(0, "keep_edges %d: tr_mesh_plc failed: %s: %s", keep_edges, tr_status_name(s),
           tr_last_error());
    return NULL;
  }
  s = tr_check_mesh(m, TR_CHK_TOPOLOGY, NULL);
  EXPECT(s == TR_OK, "keep_edges %d: mesh validator: %s", keep_edges, tr_last_error());
  s = tr_check_conformity(m, *used, NULL, keep_edges ? TR_CONF_KEEP_EDGES : 0);
  EXPECT(s == TR_OK, "keep_edges %d: exact conformity: %s", keep_edges, tr_last_error());
  return m;
}

/* Merged: valid, the six diagonals are no chains of mesh edges (the per-triangle check
 * names one), the smallest dihedral angle above the one with --keep-edges; kept: every
 * edge a chain. */
static void thin_box_diagonals_merge(void)
{
  tr_plc *p = thin_box();
  tr_plc *u1 = NULL, *u2 = NULL;
  tr_stats s1, s2;
  tr_mesh *m1 = refine(p, 0, &s1, &u1), *m2 = refine(p, 1, &s2, &u2);
  if (m1 && m2) {
    EXPECT(s1.input_edges_merged == 6, "merged %llu input edges, not the 6 diagonals",
           (unsigned long long)s1.input_edges_merged);
    EXPECT(s2.input_edges_merged == 0, "--keep-edges merged %llu edges",
           (unsigned long long)s2.input_edges_merged);
    tr_status s = tr_check_conformity(m1, u1, NULL, TR_CONF_KEEP_EDGES);
    EXPECT(s == TR_ERR_INVALID_MESH && strstr(tr_last_error(), "input edge"),
           "a diagonal is still a chain of mesh edges (%s)", tr_last_error());
    tr_quality q1, q2;
    tr_quality_measure(m1, &q1);
    tr_quality_measure(m2, &q2);
    EXPECT(q1.min_dihedral > q2.min_dihedral,
           "min dihedral merged %.3f not above kept %.3f", q1.min_dihedral, q2.min_dihedral);
    fprintf(stderr, "thin box: merged %llu tets, min dihedral %.3f; kept %llu tets, %.3f\n",
            (unsigned long long)q1.ntets, q1.min_dihedral, (unsigned long long)q2.ntets,
            q2.min_dihedral);
  }
  tr_mesh_destroy(m1);
  tr_mesh_destroy(m2);
  tr_plc_destroy(u1);
  tr_plc_destroy(u2);
  tr_plc_destroy(p);
}

/* The slab 8 x 8 x 0.25 under R = 3 with its sides merged: valid, and its worst
 * radius-edge ratio drops. (Its share of tets with ratio >= 4 does not, unlike with
 * --keep-edges: the merged sides' triangles are skinny, and their corners protect the
 * long edges from the sides' split points; a known limit of angles.c's triangle corners.) */
static void merged_slab(void)
{
  double x[24], hi[3] = {8, 8, 0.25};
  for (int i = 0; i < 8; i++)
    for (int k = 0; k < 3; k++)
      x[3 * i + k] = (i >> k) & 1 ? hi[k] : 0;
  static const uint32_t t[36] = {0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3, 0, 4, 5, 0, 5, 1,
                                 2, 3, 7, 2, 7, 6, 0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5};
  tr_plc *p = NULL, *u = NULL;
  if (tr_plc_create(&p) != TR_OK || tr_plc_set(p, x, 8, t, 12, NULL) != TR_OK) {
    fprintf(stderr, "cannot build PLC: %s\n", tr_last_error());
    exit(1);
  }
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = 0;
  opt.optimize = 0;
  tr_mesh *m0 = NULL, *m1 = NULL;
  tr_plc *u0 = NULL;
  EXPECT(tr_mesh_plc_ex(p, &opt, &m0, NULL, &u0) == TR_OK, "slab: %s", tr_last_error());
  opt.quality_ratio = 3;
  tr_stats st;
  memset(&st, 0, sizeof st);
  st.size = sizeof st;
  EXPECT(tr_mesh_plc_ex(p, &opt, &m1, &st, &u) == TR_OK, "slab -q 3: %s", tr_last_error());
  if (m0 && m1) {
    EXPECT(tr_check_mesh(m1, TR_CHK_TOPOLOGY, NULL) == TR_OK, "slab: %s", tr_last_error());
    EXPECT(tr_check_conformity(m1, u, NULL, 0) == TR_OK, "slab: %s", tr_last_error());
    EXPECT(st.input_edges_merged == 6, "slab: %llu edges merged",
           (unsigned long long)st.input_edges_merged);
    tr_quality q0, q1;
    tr_quality_measure(m0, &q0);
    tr_quality_measure(m1, &q1);
    EXPECT(q1.max_radius_edge < q0.max_radius_edge, "slab: worst ratio %g -> %g",
           q0.max_radius_edge, q1.max_radius_edge);
  }
  tr_mesh_destroy(m0);
  tr_mesh_destroy(m1);
  tr_plc_destroy(u0);
  tr_plc_destroy(u);
  tr_plc_destroy(p);
}

/* tests/data/merged_facet_notch.off (found by fuzz_pipeline_quality): a union of voxels
 * whose top at z = 16 is one merged facet of two thin strips joined at one end, with a
 * notch between them that lies inside the domain. A refinement cavity from a point on one
 * side of the notch held a sub-face of the other strip; coning it from the point made a
 * sub-face across the notch, outside the facet, and the refinement stopped with
 * TR_ERR_INTERNAL. Now such an insertion is refused (insert.c, fans_into): the mesh is
 * made, valid and exactly conforming, with the sliver stage's pinned refinement too. */
static void notch(const char *path)
{
  tr_plc *p = NULL, *u = NULL;
  if (tr_plc_read(path, &p) != TR_OK) {
    fprintf(stderr, "%s: %s\n", path, tr_last_error());
    exit(1);
  }
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = 0;
  opt.quality_ratio = 1.414;
  tr_mesh *m = NULL;
  tr_stats st;
  memset(&st, 0, sizeof st);
  st.size = sizeof st;
  tr_status s = tr_mesh_plc_ex(p, &opt, &m, &st, &u);
  EXPECT(s == TR_OK, "notch: %s: %s", tr_status_name(s), tr_last_error());
  if (m) {
    EXPECT(st.input_edges_merged > 0, "notch: no facet merged, the case is not exercised");
    EXPECT(tr_check_mesh(m, TR_CHK_TOPOLOGY, NULL) == TR_OK, "notch: %s", tr_last_error());
    EXPECT(tr_check_conformity(m, u, NULL, 0) == TR_OK, "notch: %s", tr_last_error());
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(u);
  tr_plc_destroy(p);
}

int main(int argc, char **argv)
{
  const char *c = argc > 1 ? argv[1] : "";
  if (!strcmp(c, "thin_box"))
    thin_box_diagonals_merge();
  else if (!strcmp(c, "slab"))
    merged_slab();
  else if (!strcmp(c, "notch") && argc > 2)
    notch(argv[2]);
  else {
    fprintf(stderr, "unknown case '%s'\n", c);
    return 2;
  }
  return failures != 0;
}
