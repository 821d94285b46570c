/* Whole inputs through tr_mesh_plc in the default mode and under keep_surface
 * (--keep-surface): `test_keep_surface (CASE|FILE.off) (default|keep|refused)`. CASE is a
 * case of tests/hard/hard_cases.h, FILE an OFF surface.
 *   default: the mesh passes the mesh validator and the exact conformity validator, and
 *            the Steiner counts by location add up to the Steiner points in the mesh;
 *   keep:    the same, and its boundary faces are exactly the input triangles with no
 *            Steiner point on them (tests/suppress/keepcheck.h);
 *   steps:   the stages run one by one up to outer removal, then the suppression with
 *            the validators after every removal or relocation (TR_SUP_CHECK), in the
 *            --keep-surface mode;
 *   refused: keep_surface fails with TR_ERR_UNSUPPORTED and a message naming the point
 *            and the input edge or facet, and writes no mesh;
 *   quality: keep_surface with quality refinement (R = 1.414, and a volume bound of half
 *            the mean volume of the keep mode's tets, so that refinement must add points):
 *            everything keep checks, points added, every one inside (the boundary faces
 *            are still the input triangles), and every tet's exact volume within the
 *            bound (issue 17: refinement adds interior points only under it). */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "input/validate.h"
#include "mesh/check.h"
#include "mesh/conform.h"
#include "delaunay/delaunay.h"
#include "outer/color.h"
#include "pipeline/pipeline.h"
#include "suppress/suppress.h"

#include "../hard/hard_cases.h"
#include "../pipeline/texpect.h"
#include "../pipeline/trecover.h"
#include "keepcheck.h"
#include "../refine/tvolume.h"

/* 6 x the domain's volume: the hard case's own figure (vol6 != 0), else the meshed PLC's */
static void domain_vol6(const tr_plc *used, double vol6, mpq_t v)
{
  if (vol6 != 0)
    mpq_set_d(v, vol6);
  else
    tr_input_domain_volume6(used, v);
}

static void run(const char *name, tr_plc *plc, double vol6, int ball, const char *mode)
{
  int keep = strcmp(mode, "default") != 0, refused = !strcmp(mode, "refused");
  int quality = !strcmp(mode, "quality");
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = 0;
  opt.keep_surface = keep;
  double bound = 0;
  if (quality) { /* the keep mode's mesh first: its tets' mean volume */
    tr_mesh *m0 = NULL;
    tr_plc *used0 = NULL;
    tr_status s0 = tr_mesh_plc_ex(plc, &opt, &m0, NULL, &used0);
    EXPECT(s0 == TR_OK, "%s: keep mode: %s", name, tr_last_error());
    if (s0 == TR_OK) {
      mpq_t v;
      mpq_init(v);
      domain_vol6(used0, vol6, v);
      bound = mpq_get_d(v) / 6 / (2.0 * tr_mesh_num_tets(m0));
      mpq_clear(v);
    }
    tr_mesh_destroy(m0);
    tr_plc_destroy(used0);
    if (!(bound > 0))
      return;
    opt.quality_ratio = 1.414;
    opt.max_volume = bound;
  }
  tr_mesh *m = NULL;
  tr_plc *used = NULL;
  tr_stats st;
  memset(&st, 0, sizeof st);
  st.size = sizeof st;
  tr_status s = tr_mesh_plc_ex(plc, &opt, &m, &st, &used);
  if (refused) {
    const char *msg = tr_last_error();
    EXPECT(s == TR_ERR_UNSUPPORTED && !m, "%s: expected a refusal, got %s", name,
           tr_status_name(s));
    EXPECT(strstr(msg, "--keep-surface: Steiner point") &&
               (strstr(msg, "input edge (") || strstr(msg, "input facet ")),
           "%s: the message does not name the point and the edge or facet: %s", name, msg);
    fprintf(stderr, "%s: refused as expected: %s\n", name, msg);
    tr_mesh_destroy(m);
    tr_plc_destroy(used);
    return;
  }
  EXPECT(s == TR_OK, "%s: %s: %s", name, tr_status_name(s), tr_last_error());
  if (s != TR_OK)
    return;
  s = tr_check_mesh(m, ball ? TR_CHK_TOPOLOGY : TR_CHK_TOPOLOGY & ~TR_CHK_EULER, NULL);
  EXPECT(s == TR_OK, "%s: mesh validator: %s", name, tr_last_error());
  mpq_t v;
  mpq_init(v);
  domain_vol6(used, vol6, v);
  s = tr_check_conformity(m, used, v, 0);
  EXPECT(s == TR_OK, "%s: conformity: %s", name, tr_last_error());
  mpq_clear(v);
  uint64_t nsteiner = 0;
  for (uint32_t i = 0; i < m->nv; i++)
    nsteiner += m->vq && m->vq[i];
  EXPECT(nsteiner == st.steiner_on_edges + st.steiner_on_facets + st.steiner_interior,
         "%s: %llu Steiner points in the mesh, counted %llu/%llu/%llu", name,
         (unsigned long long)nsteiner, (unsigned long long)st.steiner_on_edges,
         (unsigned long long)st.steiner_on_facets, (unsigned long long)st.steiner_interior);
  if (quality) {
    uint32_t n, over = tv_count_over(m, bound, UINT32_MAX, &n);
    EXPECT(over == 0, "%s: %u of %u tets over the volume bound %g", name, over, n, bound);
    EXPECT(st.points_added_for_quality > 0, "%s: refinement added no point: a test of nothing",
           name);
    fprintf(stderr, "%s (quality): %llu interior points from refinement, %llu from sliver "
            "removal, %u tets within %g\n", name,
            (unsigned long long)st.points_added_for_quality,
            (unsigned long long)st.points_added_for_sliver, n, bound);
  }
  if (keep) {
    char why[256];
    EXPECT(keep_surface_holds(m, used, why, sizeof why) == 0, "%s: surface: %s", name, why);
    EXPECT(st.steiner_on_edges == 0 && st.steiner_on_facets == 0,
           "%s: %llu + %llu Steiner points left on the surface", name,
           (unsigned long long)st.steiner_on_edges, (unsigned long long)st.steiner_on_facets);
  }
  fprintf(stderr,
          "%s (%s): %llu Steiner points added by recovery; left %llu on edges, %llu on "
          "facets, %llu inside; %llu removed, %llu relocated; %u tets\n",
          name, mode, (unsigned long long)(st.points_added_for_edges + st.points_added_for_facets),
          (unsigned long long)st.steiner_on_edges, (unsigned long long)st.steiner_on_facets,
          (unsigned long long)st.steiner_interior, (unsigned long long)st.steiner_removed,
          (unsigned long long)st.steiner_relocated, tr_mesh_num_tets(m));
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
}

/* Delaunay, recovery and outer removal as tr_mesh_plc runs them (no smoothing), then the
 * suppression with every change validated. */
static void steps(const char *name, tr_plc *plc)
{
  trec_run r;
  tr_status s = trec_to_recovery(plc, &r);
  EXPECT(s != TR_OK || (r.nopen == 0 && r.nmulti == 0), "%s: not a closed manifold", name);
  struct tr_mesh *m = r.m;
  uint32_t nreg = 0;
  if (s == TR_OK)
    s = tr_outer_color(m, &r.sub, 0, NULL, &nreg);
  EXPECT(s == TR_OK, "%s: stages: %s", name, tr_last_error());
  tr_suppress_stats ss;
  memset(&ss, 0, sizeof ss);
  if (s == TR_OK) {
    unsigned flags = TR_SUP_REMOVE | TR_SUP_RELOCATE | TR_SUP_INTERIOR | TR_SUP_REQUIRE |
                     TR_SUP_CHECK;
    s = tr_suppress_steiner(m, &r.sub, plc, flags, &ss);
    EXPECT(s == TR_OK, "%s: suppression: %s", name, tr_last_error());
  }
  EXPECT(ss.removed + ss.relocated > 0, "%s: nothing to suppress: a test of nothing", name);
  fprintf(stderr, "%s (steps): %llu removed, %llu relocated, each change validated\n", name,
          (unsigned long long)ss.removed, (unsigned long long)ss.relocated);
  trec_free(&r);
}

int main(int argc, char **argv)
{
  if (argc != 3) {
    fprintf(stderr, "usage: %s CASE|FILE.off default|keep|refused|steps|quality\n", argv[0]);
    return 2;
  }
  const char *name = argv[1], *mode = argv[2];
  if (strcmp(mode, "default") && strcmp(mode, "keep") && strcmp(mode, "refused") &&
      strcmp(mode, "steps") && strcmp(mode, "quality")) {
    fprintf(stderr, "unknown mode '%s'\n", mode);
    return 2;
  }
  size_t l = strlen(name);
  if (l > 4 && !strcmp(name + l - 4, ".off")) {
    tr_plc *p = NULL;
    tr_status s = tr_plc_read(name, &p);
    EXPECT(s == TR_OK, "%s: %s", name, tr_last_error());
    if (s == TR_OK && !strcmp(mode, "steps"))
      steps(name, p);
    else if (s == TR_OK)
      run(name, p, 0, 1, mode);
    tr_plc_destroy(p);
    return failures != 0;
  }
  for (int i = 0; i < hard_case_count(); i++) {
    if (strcmp(hard_case_name(i), name))
      continue;
    hard_case c;
    if (hard_case_build(i, &c) != 0)
      return 1;
    tr_plc *p = NULL;
    tr_status s = tr_plc_create(&p);
    if (s == TR_OK)
      s = tr_plc_set(p, c.xyz, c.np, c.tris, c.nt, NULL);
    EXPECT(s == TR_OK && c.status == TR_OK && !c.allow_open,
           "%s: not a valid closed case for this test", name);
    if (s == TR_OK && c.status == TR_OK && !c.allow_open && !strcmp(mode, "steps"))
      steps(name, p);
    else if (s == TR_OK && c.status == TR_OK && !c.allow_open)
      run(name, p, c.vol6, c.ball, mode);
    tr_plc_destroy(p);
    hard_case_free(&c);
    return failures != 0;
  }
  fprintf(stderr, "unknown case '%s'\n", name);
  return 2;
}
