/* Refinement on merged planar facets (src/core/facets.h): a thin box whose sides are two
 * exactly coplanar triangles each, with skinny diagonals. Every output goes through the
 * mesh validator and the exact conformity validator. */
#include <string.h>

#include "refine/quality.h"
#include "../pipeline/tmesh.h"

/* Quality refinement under R with or without keep_edges, sliver removal at its default. */
static tr_options quality(double R, int keep_edges)
{
  tr_options opt = tm_options();
  opt.quality_ratio = R;
  opt.keep_edges = keep_edges;
  return opt;
}

/* The box [0,1] x [0,0.05] x [0,0.05] (12 triangles, six diagonals). Merged: valid, the
 * six diagonals are no chains of mesh edges (the per-triangle check names one), the
 * smallest dihedral angle above the one with --keep-edges; kept: every edge a chain. */
static void thin_box_diagonals_merge(void)
{
  const double lo[3] = {0, 0, 0}, hi[3] = {1, 0.05, 0.05};
  tr_plc *p = tm_box(lo, hi);
  const tr_options merge = quality(1.414, 0), keep = quality(1.414, 1);
  tm_run a, b;
  tm_mesh(&a, "keep_edges 0", p, &merge, TR_CHK_TOPOLOGY);
  tm_mesh(&b, "keep_edges 1", p, &keep, TR_CHK_TOPOLOGY);
  if (a.m && b.m) {
    EXPECT(a.st.input_edges_merged == 6, "merged %llu input edges, not the 6 diagonals",
           (unsigned long long)a.st.input_edges_merged);
    EXPECT(b.st.input_edges_merged == 0, "--keep-edges merged %llu edges",
           (unsigned long long)b.st.input_edges_merged);
    tr_status s = tr_check_conformity(a.m, a.used, NULL, TR_CONF_KEEP_EDGES);
    EXPECT(s == TR_ERR_INVALID_MESH && strstr(tr_last_error(), "input edge"),
           "a diagonal is still a chain of mesh edges (%s)", tr_last_error());
    tr_quality q1, q2;
    tr_quality_measure(a.m, &q1);
    tr_quality_measure(b.m, &q2);
    EXPECT(q1.min_dihedral > q2.min_dihedral,
           "min dihedral merged %.3f not above kept %.3f", q1.min_dihedral, q2.min_dihedral);
    fprintf(stderr, "thin box: merged %llu tets, min dihedral %.3f; kept %llu tets, %.3f\n",
            (unsigned long long)q1.ntets, q1.min_dihedral, (unsigned long long)q2.ntets,
            q2.min_dihedral);
  }
  tm_free(&a);
  tm_free(&b);
  tr_plc_destroy(p);
}

/* The slab 8 x 8 x 0.25 under R = 3 with its sides merged: valid, and its worst
 * radius-edge ratio drops. (Its share of tets with ratio >= 4 does not, unlike with
 * --keep-edges: the merged sides' triangles are skinny, and their corners protect the
 * long edges from the sides' split points; a known limit of angles.c's triangle corners.) */
static void merged_slab(void)
{
  const double lo[3] = {0, 0, 0}, hi[3] = {8, 8, 0.25};
  tr_plc *p = tm_box(lo, hi);
  tr_options plain = tm_options(), refined = quality(3, 0);
  plain.optimize = refined.optimize = 0;
  tm_run a, b;
  tm_mesh(&a, "slab", p, &plain, TR_CHK_TOPOLOGY);
  tm_mesh(&b, "slab -q 3", p, &refined, TR_CHK_TOPOLOGY);
  if (a.m && b.m) {
    EXPECT(b.st.input_edges_merged == 6, "slab: %llu edges merged",
           (unsigned long long)b.st.input_edges_merged);
    tr_quality q0, q1;
    tr_quality_measure(a.m, &q0);
    tr_quality_measure(b.m, &q1);
    EXPECT(q1.max_radius_edge < q0.max_radius_edge, "slab: worst ratio %g -> %g",
           q0.max_radius_edge, q1.max_radius_edge);
  }
  tm_free(&a);
  tm_free(&b);
  tr_plc_destroy(p);
}

/* The box [0,1] x [0,0.1] x [0,0.1] under R = 1.414, refinement alone: its four long
 * edges are split at their midpoints first, each point with an insertion radius of 0.5,
 * and once points came 0.1 away on the neighbouring edges every circumcentre within 0.5
 * of them is too close. Such a circumcentre used to be refused outright, leaving 12 tets
 * with a worst ratio of 2.598; now the long sub-segments it encroaches are split first
 * (close splits, refine.c), and the box ends with 24 tets of ratio 1.436, just over the
 * bound. With refine_spacing_radii, which takes the spacing at those points instead
 * (refine.c, after_insert), every tet meets the bound. Both meshes validate exactly. */
static void long_box_spacing_radii(void)
{
  const double lo[3] = {0, 0, 0}, hi[3] = {1, 0.1, 0.1};
  tr_plc *p = tm_box(lo, hi);
  tr_options radii = quality(1.414, 0);
  radii.optimize = 0;
  tr_options spacing = radii;
  spacing.refine_spacing_radii = 1;
  tm_run a, b;
  tm_mesh(&a, "long box, insertion radii", p, &radii, TR_CHK_TOPOLOGY);
  tm_mesh(&b, "long box, spacings", p, &spacing, TR_CHK_TOPOLOGY);
  if (a.m && b.m) {
    tr_quality qa, qb;
    tr_quality_measure(a.m, &qa);
    tr_quality_measure(b.m, &qb);
    EXPECT(qa.max_radius_edge < 2, "long box: worst radius-edge %g with insertion radii",
           qa.max_radius_edge);
    EXPECT(qb.max_radius_edge <= 1.414, "long box: worst radius-edge %g over the bound with "
           "spacings", qb.max_radius_edge);
    fprintf(stderr, "long box: radii %llu tets, worst ratio %.3f; spacings %llu tets, %.3f\n",
            (unsigned long long)qa.ntets, qa.max_radius_edge, (unsigned long long)qb.ntets,
            qb.max_radius_edge);
  }
  tm_free(&a);
  tm_free(&b);
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
  tr_plc *p = tm_read(path);
  tr_options opt = tm_options();
  opt.quality_ratio = 1.414;
  tm_run r;
  if (tm_mesh(&r, "notch", p, &opt, TR_CHK_TOPOLOGY))
    EXPECT(r.st.input_edges_merged > 0, "notch: no facet merged, the case is not exercised");
  tm_free(&r);
  tr_plc_destroy(p);
}

/* The same input with refine_spacing_radii: its facet splits run to any budget once the
 * radii no longer hold them back, so the stage ends at its point cap (20 per input point
 * + 10,000) without error, and the mesh is made and conforms exactly. */
static void notch_spacing(const char *path)
{
  tr_plc *p = tm_read(path);
  tr_options opt = tm_options();
  opt.quality_ratio = 1.414;
  opt.refine_spacing_radii = 1;
  opt.optimize = 0;
  tm_run r;
  if (tm_mesh(&r, "notch, spacings", p, &opt, TR_CHK_TOPOLOGY)) {
    EXPECT(r.st.points_added_for_quality <= 20 * (uint64_t)p->npoints + 10000,
           "notch, spacings: %llu points, over the cap",
           (unsigned long long)r.st.points_added_for_quality);
    fprintf(stderr, "notch, spacings: %llu points, %u tets\n",
            (unsigned long long)r.st.points_added_for_quality, tr_mesh_num_tets(r.m));
  }
  tm_free(&r);
  tr_plc_destroy(p);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"thin_box", thin_box_diagonals_merge, NULL},
      {"slab", merged_slab, NULL},
      {"notch", NULL, notch},
      {"long_box", long_box_spacing_radii, NULL},
      {"notch_spacing", NULL, notch_spacing},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
