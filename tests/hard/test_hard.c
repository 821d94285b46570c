/* End-to-end tests on the hard cases of hard_cases.h: `test_hard CASE` meshes one case
 * with tr_mesh_plc and checks its expected outcome. A valid case must give a mesh that
 * passes the mesh validator (topology, exact orientation; Euler when the domain is a
 * ball), the exact conformity validator with the exact expected volume, and has the
 * expected number of regions; an invalid one must fail with the expected status and a
 * message that names the culprits. With --exact the mesh keeps its exact Steiner points
 * and the doubles are not repaired (tetrec mesh --exact to a .node file); the validators
 * are exact either way. --paper meshes with the paper's algorithm only
 * (tr_options.recovery = 1), --no-facet-flips without the facet flips (2: missing facets
 * go to the cavity retriangulation right after Swap32). --quality refines under R = 1.414
 * with refine_partial and a small budget: the mesh is checked the same way whether the
 * budget stopped it or not. `test_hard --files DIR` writes every case with the
 * generator's writer, reads it back and checks the doubles survive bit for bit. */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/plc.h"
#include "hard_cases.h"
#include "input/validate.h"
#include "mesh/check.h"
#include "mesh/conform.h"
#include "pipeline/pipeline.h"

#include "../pipeline/texpect.h"

/* How run_case meshes: flags (TR_PIPE_KEEP_EXACT for --exact: the exact mesh is checked
 * and doubles that cannot be repaired are no failure) and the rounding budget (0: the
 * default). */
static unsigned run_flags;
static uint64_t run_budget;
static int run_recovery; /* tr_options.recovery (--paper: 1, --no-facet-flips: 2) */
static int expect_cavity; /* --expect-cavity: some facet must be recovered by the cavity */
/* --quality: refinement under R = 1.414 with the CLI's refine_partial and a budget of
 * QUALITY_BUDGET points, so that the slabs, whose facets need points as close as they are
 * thin, reach it in a second or two */
static int run_quality;
#define QUALITY_BUDGET 20000

static void run_case(const hard_case *c)
{
  tr_plc *plc = NULL;
  tr_status s = tr_plc_create(&plc);
  if (s == TR_OK)
    s = tr_plc_set(plc, c->xyz, c->np, c->tris, c->nt, NULL);
  EXPECT(s == TR_OK, "%s: building the PLC: %s", c->name, tr_last_error());
  if (s != TR_OK) {
    tr_plc_destroy(plc);
    return;
  }
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = 0;
  opt.allow_open = c->allow_open;
  opt.round_budget = run_budget;
  opt.recovery = run_recovery;
  if (run_quality) {
    opt.quality_ratio = 1.414;
    opt.refine_partial = 1;
    opt.refine_budget = QUALITY_BUDGET;
  }
  tr_mesh *m = NULL;
  tr_plc *used = NULL;
  tr_stats st = {.size = sizeof st};
  s = tr_mesh_plc_flags(plc, &opt, &m, &st, &used, run_flags);
  if (c->status != TR_OK) {
    const char *msg = tr_last_error();
    EXPECT(s == c->status, "%s: expected %s, got %s: %s", c->name, tr_status_name(c->status),
           tr_status_name(s), msg);
    /* the message must say where: the triangles for an overlap, the edge for an open
     * surface, and how to mesh an open surface anyway */
    if (c->status == TR_ERR_SELF_INTERSECT)
      EXPECT(strstr(msg, "triangles ") && strstr(msg, "intersect"),
             "%s: the message does not name the triangles: %s", c->name, msg);
    if (c->status == TR_ERR_OPEN)
      EXPECT(strstr(msg, "edge (") && strstr(msg, "--allow-open"),
             "%s: the message does not name the edge and the option: %s", c->name, msg);
    fprintf(stderr, "%s: rejected as expected: %s\n", c->name, msg);
    tr_mesh_destroy(m);
    tr_plc_destroy(used);
    tr_plc_destroy(plc);
    return;
  }
  if (s != TR_OK) {
    EXPECT(0, "%s: tr_mesh_plc failed: %s: %s", c->name, tr_status_name(s), tr_last_error());
    tr_plc_destroy(plc);
    return;
  }
  unsigned what = c->ball ? TR_CHK_TOPOLOGY : TR_CHK_TOPOLOGY & ~TR_CHK_EULER;
  s = tr_check_mesh(m, what, NULL);
  EXPECT(s == TR_OK, "%s: mesh validator: %s", c->name, tr_last_error());
  mpq_t v;
  mpq_init(v);
  if (c->vol6 != 0)
    mpq_set_d(v, c->vol6); /* exact: the expected volumes are small integers */
  else
    tr_input_volume6(used, v); /* a closed manifold surface: the volume it encloses */
  EXPECT(mpq_sgn(v) > 0, "%s: the expected volume is not positive", c->name);
  {
    /* the validator's own idea of the domain (cells.c) agrees with the construction */
    mpq_t dv;
    mpq_init(dv);
    s = tr_input_domain_volume6(used, dv);
    EXPECT(s == TR_OK && mpq_equal(dv, v), "%s: domain volume of the surface %.17g, expected "
           "%.17g (%s)", c->name, mpq_get_d(dv), mpq_get_d(v), s == TR_OK ? "" : tr_last_error());
    mpq_clear(dv);
  }
  s = tr_check_conformity(m, used, v, c->allow_open ? TR_CONF_OPEN : 0);
  EXPECT(s == TR_OK, "%s: conformity: %s", c->name, tr_last_error());
  mpq_clear(v);
  uint32_t maxr = 0, nt = tr_mesh_num_tets(m);
  for (uint32_t t = 0; t < m->nt; t++)
    if (m->region && m->region[t] > maxr)
      maxr = m->region[t];
  EXPECT(m->region && (int)maxr == c->regions, "%s: expected %d regions, got %u", c->name,
         c->regions, maxr);
  uint64_t added = st.points_added_for_edges + st.points_added_for_facets;
  if (c->steiner)
    EXPECT(added > 0, "%s: no Steiner point, but the case has no tetrahedralization without",
           c->name);
  if (run_quality) {
    /* a stop at the budget hands back the mesh made so far (validated above), to which
     * sliver removal adds no point */
    uint64_t q = st.points_added_for_quality;
    EXPECT(q > 0 || st.tets_over_bounds == 0, "%s: no point added, %llu tets over the bound",
           c->name, (unsigned long long)st.tets_over_bounds);
    EXPECT(q <= QUALITY_BUDGET, "%s: %llu points, over the budget", c->name,
           (unsigned long long)q);
    if (st.refine_budget_reached)
      EXPECT(q == QUALITY_BUDGET && st.points_added_for_sliver == 0,
             "%s: stopped at the budget with %llu points, %llu more for slivers", c->name,
             (unsigned long long)q, (unsigned long long)st.points_added_for_sliver);
    fprintf(stderr, "%s (quality): %llu points (budget %s), %llu sliver points; %llu of %u "
            "tets over the bound, min dihedral %.3f\n", c->name, (unsigned long long)q,
            st.refine_budget_reached ? "reached" : "not reached",
            (unsigned long long)st.points_added_for_sliver,
            (unsigned long long)st.tets_over_bounds, nt, st.min_dihedral);
  }
  /* the paper's algorithm has no cavity retriangulation */
  if (expect_cavity)
    EXPECT(st.facets_recovered_by_cavity > 0, "%s: no facet recovered by cavity "
           "retriangulation", c->name);
  if (run_recovery == 1)
    EXPECT(st.facets_recovered_by_cavity == 0, "%s: %llu facets recovered by cavity "
           "retriangulation with --paper", c->name,
           (unsigned long long)st.facets_recovered_by_cavity);
  fprintf(stderr,
          "%s%s: %u points, %u triangles -> %u vertices, %u tets, %u regions; missing edges "
          "%llu, facets %llu (by swaps %llu, by cavity %llu); Steiner points %llu (on facets "
          "%llu); %.3f s\n",
          c->name, run_recovery == 1 ? " (paper)" : run_recovery == 2 ? " (no facet flips)" : "", c->np, c->nt, tr_mesh_num_vertices(m), nt,
          maxr, (unsigned long long)st.missing_edges, (unsigned long long)st.missing_facets,
          (unsigned long long)st.facets_recovered_by_swap,
          (unsigned long long)st.facets_recovered_by_cavity, (unsigned long long)added,
          (unsigned long long)st.points_added_for_facets, st.total_seconds);
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
  tr_plc_destroy(plc);
}

/* Every case written as OFF and read back: the same points bit for bit, the same
 * triangles (the generator's files are what the tests mesh). */
static void files(const char *dir)
{
  char path[4096];
  mkdir(dir, 0777); /* may exist */
  for (int i = 0; i < hard_case_count(); i++) {
    hard_case c;
    if (hard_case_build(i, &c) != 0) {
      EXPECT(0, "out of memory building %s", hard_case_name(i));
      continue;
    }
    snprintf(path, sizeof path, "%s/%s.off", dir, c.name);
    EXPECT(hard_case_write_off(&c, path) == 0, "cannot write %s", path);
    tr_plc *p = NULL;
    tr_status s = tr_plc_read(path, &p);
    EXPECT(s == TR_OK, "%s: %s", path, tr_last_error());
    if (s == TR_OK) {
      EXPECT(tr_plc_num_points(p) == c.np && tr_plc_num_triangles(p) == c.nt,
             "%s: %u points / %u triangles read, %u / %u written", path, tr_plc_num_points(p),
             tr_plc_num_triangles(p), c.np, c.nt);
      if (tr_plc_num_points(p) == c.np && tr_plc_num_triangles(p) == c.nt) {
        EXPECT(memcmp(tr_plc_points(p), c.xyz, sizeof(double) * 3 * c.np) == 0,
               "%s: coordinates changed through the file", path);
        EXPECT(memcmp(tr_plc_triangles(p), c.tris, sizeof(uint32_t) * 3 * c.nt) == 0,
               "%s: triangles changed through the file", path);
      }
    }
    tr_plc_destroy(p);
    hard_case_free(&c);
  }
}

int main(int argc, char **argv)
{
  if (argc == 3 && !strcmp(argv[1], "--files")) {
    files(argv[2]);
  } else if (argc >= 2) {
    int found = 0, a = 1;
    for (; a + 1 < argc; a++) {
      if (!strcmp(argv[a], "--exact"))
        run_flags |= TR_PIPE_KEEP_EXACT;
      else if (!strcmp(argv[a], "--paper"))
        run_recovery = 1;
      else if (!strcmp(argv[a], "--no-facet-flips"))
        run_recovery = 2;
      else if (!strcmp(argv[a], "--expect-cavity"))
        expect_cavity = 1;
      else if (!strcmp(argv[a], "--quality"))
        run_quality = 1;
      else if (!strcmp(argv[a], "--round-budget") && a + 2 < argc)
        run_budget = strtoull(argv[++a], NULL, 10);
      else
        break;
    }
    for (int i = 0; i < hard_case_count() && a + 1 == argc; i++) {
      if (strcmp(argv[a], "all") && strcmp(argv[a], hard_case_name(i)))
        continue;
      found = 1;
      hard_case c;
      if (hard_case_build(i, &c) != 0) {
        EXPECT(0, "out of memory building %s", hard_case_name(i));
        continue;
      }
      run_case(&c);
      hard_case_free(&c);
    }
    EXPECT(found, "no case named %s", argv[argc - 1]);
  } else {
    fprintf(stderr, "usage: test_hard [--exact] [--paper | --no-facet-flips] [--expect-cavity] [--quality] "
                    "[--round-budget N] "
                    "CASE|all | "
                    "test_hard --files DIR\n");
    return 1;
  }
  if (failures)
    fprintf(stderr, "%d failure(s)\n", failures);
  return failures ? 1 : 0;
}
