/* The refinement point budget (src/refine/refine.h, tr_options.refine_budget) through the
 * whole pipeline: a volume bound it cannot reach is refused before any work; reaching it
 * fails with TR_ERR_NOMEM and no mesh, or, under tr_options.refine_partial (the CLI's
 * way), hands back the mesh made so far. Every mesh goes through the mesh validator and
 * the exact conformity validator (tmesh.h). The thin slabs, which stop at the budget
 * under R = 1.414, are tests/hard's (test_hard --quality). */
#include <string.h>

#include "refine/refine.h"
#include "../pipeline/tmesh.h"
#include "tvolume.h"

/* A volume bound the point budget cannot reach is refused before refinement starts, with
 * TR_ERR_NOMEM and a message naming the tets it asks for (-a 1e-300 on a cube once ran
 * towards a default budget of 4e9 points: hours, and all the memory); also for a region's
 * bound alone. The default budget stops at its ceiling, or 8 points per input point. */
static void volume_bound_over_budget(void)
{
  const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  EXPECT(tr_refine_default_budget(8, 1, 1e-300) == (uint64_t)TR_REFINE_BUDGET_CEILING,
         "default budget under -a 1e-300: %llu",
         (unsigned long long)tr_refine_default_budget(8, 1, 1e-300));
  EXPECT(tr_refine_default_budget(10000000, 1, 1e-300) == 80000000u,
         "default budget of a large input: %llu",
         (unsigned long long)tr_refine_default_budget(10000000, 1, 1e-300));
  EXPECT(tr_refine_default_budget(8, 1, 0.01) == 102800u, "default budget under -a 0.01: %llu",
         (unsigned long long)tr_refine_default_budget(8, 1, 0.01));
  for (int region = 0; region <= 1; region++) {
    tr_plc *plc = tm_box(lo, hi);
    if (region)
      EXPECT(tr_plc_add_region(plc, 0.5, 0.5, 0.5, 2, 1e-300) == TR_OK, "region: %s",
             tr_last_error());
    tr_options opt = tm_refinement(1.414, region ? 0 : 1e-300);
    tr_mesh *m = NULL;
    tr_stats st;
    tr_status s = tr_mesh_plc(plc, &opt, &m, &st);
    EXPECT(s == TR_ERR_NOMEM && !m && strstr(tr_last_error(), "asks for at least 1e+300 tets"),
           "%s: %s (%d)", region ? "region bound" : "-a", tr_last_error(), s);
    /* a bound the budget reaches is not refused */
    opt = tm_refinement(1.414, region ? 0 : 0.01);
    opt.refine_budget = 2000;
    if (region) {
      tr_plc_destroy(plc);
      plc = tm_box(lo, hi);
      tr_plc_add_region(plc, 0.5, 0.5, 0.5, 2, 0.01);
    }
    tm_run r;
    m = tm_mesh(&r, region ? "region_bound_in_budget" : "bound_in_budget", plc, &opt,
                TR_CHK_TOPOLOGY);
    EXPECT(m != NULL, "a bound within the budget");
    tm_free(&r);
    tr_plc_destroy(plc);
  }
}

/* The unit cube under -a 1e-4 (about 5,000 points) with a budget of 1,500 points: within
 * what the up-front check allows (10,000 tets asked, 8 per point), beyond what
 * refinement can reach. */
#define CUBE_BOUND 1e-4
#define CUBE_BUDGET 1500

static tr_options cube_options(void)
{
  tr_options opt = tm_refinement(0, CUBE_BOUND);
  opt.refine_budget = CUBE_BUDGET;
  opt.optimize = 3; /* the default: sliver removal would add points if it could */
  return opt;
}

/* Without refine_partial, the library's default: TR_ERR_NOMEM, no mesh, and a message
 * that names the budget and what to do. */
static void fails_at_budget(void)
{
  const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  tr_plc *plc = tm_box(lo, hi);
  tr_options opt = cube_options();
  tr_mesh *m = NULL;
  tr_stats st = {.size = sizeof st};
  tr_status s = tr_mesh_plc(plc, &opt, &m, &st);
  const char *msg = tr_last_error();
  EXPECT(s == TR_ERR_NOMEM && !m, "expected TR_ERR_NOMEM and no mesh, got %s: %s",
         tr_status_name(s), msg);
  EXPECT(strstr(msg, "point budget of 1500 points") && strstr(msg, "--refine-budget"),
         "the message names neither the budget nor the option: %s", msg);
  tr_mesh_destroy(m);
  tr_plc_destroy(plc);
}

/* With refine_partial: TR_OK and a mesh that passes both validators, refinement's points
 * exactly the budget, none added by sliver removal (no budget is left for it), and
 * tets_over_bounds equal to the tets whose exact volume is over the bound. */
static void partial_at_budget(void)
{
  const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  tr_plc *plc = tm_box(lo, hi);
  tr_options opt = cube_options();
  opt.refine_partial = 1;
  tm_run r;
  tr_mesh *m = tm_mesh(&r, "cube_partial", plc, &opt, TR_CHK_TOPOLOGY);
  if (m) {
    uint32_t n, over = tv_count_over(m, CUBE_BOUND, UINT32_MAX, &n);
    EXPECT(r.st.refine_budget_reached == 1, "the budget was not reached");
    EXPECT(r.st.points_added_for_quality == CUBE_BUDGET && r.st.points_added_for_sliver == 0,
           "%llu refinement points, %llu sliver points",
           (unsigned long long)r.st.points_added_for_quality,
           (unsigned long long)r.st.points_added_for_sliver);
    EXPECT(over > 0 && r.st.tets_over_bounds == over, "tets over the bound: %llu counted, "
           "%u by exact volumes of %u", (unsigned long long)r.st.tets_over_bounds, over, n);
    fprintf(stderr, "cube_partial: %u tets, %u over the bound\n", n, over);
  }
  tm_free(&r);
  tr_plc_destroy(plc);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"volume_bound_over_budget", volume_bound_over_budget, NULL},
      {"fails_at_budget", fails_at_budget, NULL},
      {"partial_at_budget", partial_at_budget, NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
