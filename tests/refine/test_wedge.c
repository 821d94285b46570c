/* Wedge grading (src/refine/angles.c, rf_wedge_split; tr_refine_params.wedge_grading) on a
 * double cone: N thin triangles meet at the top apex, each with an angle of 360/N degrees
 * there, every other rim vertex raised so that no two of them are coplanar (each is a
 * facet of its own, its edges at the apex input edges). Refinement alone (tr_refine after
 * the recovery and outer colouring, no sliver stage) under R = 1.414, once with wedge
 * grading and once without: with 7.5-degree corners (N = 48), grading splits pieces across
 * the wedges (counted) and leaves fewer tets under 10 degrees (129 against 153). The
 * rule's 3-degree floor has no test here: on a cone every pair of rim edges counts
 * (2.4-degree corners still have 4.8-degree pairs), and on a needle or a fin whose edges
 * all meet under 3 degrees the rule found nothing to split even without the floor. Every mesh goes through the mesh validator and the exact conformity validator, with the
 * domain's exact volume from the input's cells. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "outer/color.h"
#include "refine/quality.h"
#include "refine/refine.h"
#include "../pipeline/tmesh.h"
#include "../pipeline/trecover.h"

/* The double cone: apex (0, 0, 1), bottom apex (0, 0, -4), rim of n points at radius 10
 * (rounded to 1/64, exact doubles), z = 0 and 1/4 alternating (n even). */
static tr_plc *double_cone(uint32_t n)
{
  double *x = malloc(sizeof *x * 3 * (n + 2));
  uint32_t *t = malloc(sizeof *t * 6 * n);
  if (!x || !t) {
    fprintf(stderr, "out of memory\n");
    exit(1);
  }
  const double top[6] = {0, 0, 1, 0, 0, -4};
  memcpy(x, top, sizeof top);
  for (uint32_t i = 0; i < n; i++) {
    double a = 2 * 3.14159265358979323846 * i / n;
    x[3 * (i + 2)] = round(640 * cos(a)) / 64;
    x[3 * (i + 2) + 1] = round(640 * sin(a)) / 64;
    x[3 * (i + 2) + 2] = i % 2 ? 0.25 : 0;
  }
  for (uint32_t i = 0; i < n; i++) {
    uint32_t u = 2 + i, v = 2 + (i + 1) % n;
    const uint32_t tri[6] = {0, u, v, 1, v, u};
    memcpy(t + 6 * i, tri, sizeof tri);
  }
  tr_plc *p = tm_plc(x, n + 2, t, 2 * n);
  free(x);
  free(t);
  return p;
}

typedef struct {
  uint32_t nv, nt, under10;
  uint64_t wedge_splits;
} outcome;

/* Recovery, colouring and refinement of plc under R = 1.414, wedge grading on or off. */
static void refine_cone(const char *name, tr_plc *plc, int grading, outcome *o)
{
  memset(o, 0, sizeof *o);
  trec_run r;
  tr_status s = trec_to_recovery(plc, &r);
  uint32_t nreg = 0;
  if (s == TR_OK)
    s = tr_outer_color(r.m, &r.sub, 0, NULL, &nreg);
  tr_refine_params par;
  memset(&par, 0, sizeof par);
  par.ratio = 1.414;
  par.budget = 100000;
  par.wedge_grading = grading;
  tr_refine_stats st;
  if (s == TR_OK)
    s = tr_refine(r.m, plc, &r.sub, &par, &st);
  EXPECT(s == TR_OK, "%s: %s", name, tr_last_error());
  if (s != TR_OK) {
    trec_free(&r);
    return;
  }
  tr_mesh *m = r.m;
  s = tr_check_mesh(m, TR_CHK_TOPOLOGY, NULL);
  EXPECT(s == TR_OK, "%s: mesh validator: %s", name, tr_last_error());
  s = tr_check_conformity(m, plc, NULL, 0);
  EXPECT(s == TR_OK, "%s: exact conformity: %s", name, tr_last_error());
  o->nv = m->nv;
  o->wedge_splits = st.wedge_splits;
  for (uint32_t t = 0; t < m->nt; t++)
    if (tr_tet_is_real(m, t)) {
      const uint32_t *v = m->tv + 4 * (size_t)t;
      double ratio, vol;
      o->nt++;
      o->under10 += tr_tet_min_dihedral(m->xyz + 3 * (size_t)v[0], m->xyz + 3 * (size_t)v[1],
                                        m->xyz + 3 * (size_t)v[2], m->xyz + 3 * (size_t)v[3],
                                        &ratio, &vol) < 10;
    }
  fprintf(stderr, "%s: %u vertices, %u tets, %u under 10 degrees, %llu pieces queued by "
          "wedge grading\n", name, o->nv, o->nt, o->under10,
          (unsigned long long)o->wedge_splits);
  trec_free(&r);
}

static void graded(void)
{
  tr_plc *plc = double_cone(48);
  outcome on, off;
  refine_cone("7.5 degrees, graded", plc, 1, &on);
  refine_cone("7.5 degrees, not graded", plc, 0, &off);
  EXPECT(on.wedge_splits > 0, "graded: no piece split across a wedge");
  EXPECT(off.wedge_splits == 0, "not graded: %llu pieces split across a wedge",
         (unsigned long long)off.wedge_splits);
  EXPECT(on.under10 < off.under10, "graded: %u tets under 10 degrees, not fewer than the %u "
         "without grading", on.under10, off.under10);
  tr_plc_destroy(plc);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"graded", graded, NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
