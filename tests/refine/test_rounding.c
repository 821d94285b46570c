/* Refinement's points against the doubles they are written as (src/refine/insert.c,
 * rounding_allows): no point goes in closer to a vertex than the rounding repair can
 * separate, nor with new tets that are flat on their doubles beyond a one-ulp move, so a
 * valid input under --quality never ends in exit 9 at the rounding stage (issue 50, item
 * 4). Every mesh through the mesh and exact conformity validators (tmesh.h). */
#include <stdlib.h>
#include <string.h>

#include "../pipeline/tmesh.h"

/* One run under ratio 1.414: it succeeds (validated), adds quality points, every point
 * refinement counts is an output vertex and no other is (refused points included: they
 * leave the mesh uncounted), and the rounding stage moves at most max_repairs Steiner
 * points off their nearest doubles. */
static void refine_rounds(const char *name, const char *path, uint64_t max_repairs)
{
  tr_plc *p = tm_read(path);
  if (!p)
    return;
  tr_options opt = tm_options();
  opt.quality_ratio = 1.414;
  tm_run r;
  if (tm_mesh(&r, name, p, &opt, TR_CHK_TOPOLOGY)) {
    EXPECT(r.st.points_added_for_quality > 0, "%s: no quality point, the case is not "
           "exercised", name);
    uint64_t want = r.st.surface_nodes + r.st.points_added_for_edges +
                    r.st.points_added_for_facets + r.st.points_added_for_quality +
                    r.st.points_added_for_sliver;
    EXPECT(r.st.volume_nodes == want, "%s: %llu vertices, %llu input and counted points",
           name, (unsigned long long)r.st.volume_nodes, (unsigned long long)want);
    EXPECT(r.st.rounding_repairs <= max_repairs, "%s: %llu Steiner points repaired after "
           "rounding, more than %llu", name, (unsigned long long)r.st.rounding_repairs,
           (unsigned long long)max_repairs);
    fprintf(stderr, "%s: %llu quality points, %u tets, %llu repaired\n", name,
            (unsigned long long)r.st.points_added_for_quality, tr_mesh_num_tets(r.m),
            (unsigned long long)r.st.rounding_repairs);
  }
  tm_free(&r);
  tr_plc_destroy(p);
}

/* tests/data/tilted_prism_rounding.off: a prism over a 24-gon whose caps lie on tilted
 * planes, its vertices rounded to doubles, so each cap is planar only to a few ulps (the
 * levels of stlcutters 93703.stl are so). Before the rule its split points landed within
 * ulps of each other on the caps and 110 tets stayed flat after the repair's budget
 * (TR_ERR_INVALID_MESH); now the run ends valid and nothing needs a repair. */
static void tilted_prism(const char *path)
{
  refine_rounds("tilted prism", path, 0);
}

/* tests/data/bumpy_prism_rounding.off: a prism over a 16-gon near (-27, 62), its caps
 * in long thin triangles whose vertices lie up to 1e-14 (a few ulps of x and y) off
 * z = 0 and z = 10, like the bottom of stlcutters 77343.stl. Some of its split points
 * are refused for their doubles; a refused point must not stay behind as a vertex of no
 * tet (a first version of the rule left it, and the stages after refinement failed on
 * its Ball). */
static void bumpy_prism(const char *path)
{
  refine_rounds("bumpy prism", path, 0);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"tilted_prism", NULL, tilted_prism},
      {"bumpy_prism", NULL, bumpy_prism},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
