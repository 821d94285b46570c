/* Refinement's points against the doubles they are written as (src/refine/insert.c,
 * rounding_allows): no point goes in closer to a vertex than the rounding repair can
 * separate, nor with new tets that are flat on their doubles beyond a one-ulp move, and a
 * point let in with that move keeps it, so a valid input under --quality never ends in
 * exit 9 at the rounding stage (issue 50, item 4). Every mesh through the mesh and exact
 * conformity validators (tmesh.h). */
#include <stdlib.h>
#include <string.h>

#include "../pipeline/tmesh.h"
#include "output/round.h"

/* One run under ratio 1.414: it succeeds (validated), adds quality points, every point
 * refinement counts is an output vertex and no other is (refused points included: they
 * leave the mesh uncounted; recovery's points that suppression removed before refinement
 * are not output vertices either), and the rounding stage moves at most max_repairs
 * Steiner points off their nearest doubles. */
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
                    r.st.points_added_for_sliver - r.st.steiner_removed;
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

/* Refinement alone under ratio 1.414 with no rounding repair (TR_PIPE_KEEP_EXACT, as for
 * --exact): every tet is strictly positive (exact orient3d) on the doubles refinement left
 * its points at, each Steiner point at its nearest double or at the one next to it that it
 * was admitted at; and the exact mesh validates and conforms. */
static void positive_unrepaired(const char *name, const char *path)
{
  tr_plc *p = tm_read(path);
  if (!p)
    return;
  tr_options opt = tm_refinement(1.414, 0);
  tr_mesh *m = NULL;
  tr_plc *used = NULL;
  tr_stats st = {.size = sizeof st};
  tr_status s = tr_mesh_plc_flags(p, &opt, &m, &st, &used, TR_PIPE_KEEP_EXACT);
  EXPECT(s == TR_OK, "%s: tr_mesh_plc: %s", name, tr_last_error());
  if (s == TR_OK) {
    EXPECT(st.points_added_for_quality > 0, "%s: no quality point", name);
    s = tr_check_mesh(m, TR_CHK_TOPOLOGY, NULL);
    EXPECT(s == TR_OK, "%s: mesh validator: %s", name, tr_last_error());
    s = tr_check_conformity(m, used, NULL, 0);
    EXPECT(s == TR_OK, "%s: exact conformity: %s", name, tr_last_error());
    uint32_t first;
    uint64_t flat = tr_round_count_nonpositive(m, &first);
    EXPECT(flat == 0, "%s: %llu tets flat or inverted on the unrepaired doubles (the first: "
           "tet %u)", name, (unsigned long long)flat, first);
    EXPECT(st.rounding_flips == 0, "%s: %llu flips of tets flat in doubles", name,
           (unsigned long long)st.rounding_flips);
    uint64_t off = 0;
    for (uint32_t v = 0; v < m->nv; v++)
      off += m->vq && m->vq[v] &&
             memcmp(m->xyz + 3 * (size_t)v, m->vq[v]->near, 3 * sizeof(double)) != 0;
    fprintf(stderr, "%s: %llu quality points, %u tets, %llu Steiner points admitted off "
            "their nearest double\n", name, (unsigned long long)st.points_added_for_quality,
            tr_mesh_num_tets(m), (unsigned long long)off);
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
  tr_plc_destroy(p);
}

/* tests/data/chamfer_ribbon_rounding.off: a box whose edge is chamfered by a ribbon 1e-9
 * wide, printed with 15 digits (see the file). Points whose new tets are positive only
 * one ulp off their nearest double went in there, each checked against its neighbours'
 * nearest doubles although they had been let in for another one; the moves all of them
 * needed at the end conflicted, and 1 tet stayed flat after the repair's budget (exit 9),
 * with and without sliver removal. Each point now keeps the double it was admitted at:
 * refinement leaves no tet flat on the doubles, and the whole run (sliver removal on)
 * ends valid. */
static void chamfer_ribbon(const char *path)
{
  positive_unrepaired("chamfer ribbon, refinement alone", path);
  /* any number of points off their nearest double: sliver removal's flips and points
   * there make tets that need the repair */
  refine_rounds("chamfer ribbon", path, UINT64_MAX);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"tilted_prism", NULL, tilted_prism},
      {"bumpy_prism", NULL, bumpy_prism},
      {"chamfer_ribbon", NULL, chamfer_ribbon},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
