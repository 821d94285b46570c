/* The set-up the whole-pipeline tests share (tests/refine, tests/sliver): small surfaces
 * built from arrays (tplc.h), and meshing one under given options with every output through the
 * mesh validator and the exact conformity validator. One helper, so that each test states
 * its configuration and its property, and no test can mesh without validating. Uses the
 * counting check of texpect.h: a failed run or validation is counted and the case goes on. */
#ifndef TR_TESTS_PIPELINE_TMESH_H
#define TR_TESTS_PIPELINE_TMESH_H

#include <stdlib.h>
#include <string.h>

#include "mesh/check.h"
#include "mesh/conform.h"
#include "pipeline/pipeline.h"
#include "texpect.h"
#include "tplc.h"

/* The library's defaults, quiet. */
static inline tr_options tm_options(void)
{
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = 0;
  return opt;
}

/* Refinement under the radius-edge bound ratio and the volume bound maxvol (0: none),
 * sliver removal off: sliver removal may trade a tet's radius-edge ratio above the bound
 * for larger dihedral angles, which the refinement tests' properties do not allow (the
 * cases that test it turn it on). */
static inline tr_options tm_refinement(double ratio, double maxvol)
{
  tr_options opt = tm_options();
  opt.quality_ratio = ratio;
  opt.max_volume = maxvol;
  opt.optimize = 0;
  return opt;
}

/* The surface at path (a test's data file), or exit 1 with the reader's message. */
static inline tr_plc *tm_read(const char *path)
{
  tr_plc *p = NULL;
  if (tr_plc_read(path, &p) != TR_OK) {
    fprintf(stderr, "%s: %s\n", path, tr_last_error());
    exit(1);
  }
  return p;
}

/* One meshing: the mesh (NULL when it failed), the PLC as meshed, the whole stats. */
typedef struct {
  tr_mesh *m;
  tr_plc *used;
  tr_stats st;
} tm_run;

/* Meshes plc under opt into *r and runs the mesh validator (checks chk) and the exact
 * conformity validator (every input edge a chain of mesh edges too when opt->keep_edges);
 * name starts every message. Returns r->m: NULL when meshing failed (counted); a failed
 * validation is counted and the mesh returned. tm_free releases *r either way. */
static inline tr_mesh *tm_mesh(tm_run *r, const char *name, const tr_plc *plc,
                               const tr_options *opt, unsigned chk)
{
  memset(r, 0, sizeof *r);
  r->st.size = sizeof r->st; /* the whole struct is filled (ABI growth, tetrec.h) */
  tr_status s = tr_mesh_plc_ex(plc, opt, &r->m, &r->st, &r->used);
  if (s != TR_OK) {
    EXPECT(0, "%s: tr_mesh_plc failed: %s: %s", name, tr_status_name(s), tr_last_error());
    tr_mesh_destroy(r->m);
    r->m = NULL;
    return NULL;
  }
  s = tr_check_mesh(r->m, chk, NULL);
  EXPECT(s == TR_OK, "%s: mesh validator: %s", name, tr_last_error());
  s = tr_check_conformity(r->m, r->used, NULL, opt->keep_edges ? TR_CONF_KEEP_EDGES : 0);
  EXPECT(s == TR_OK, "%s: exact conformity: %s", name, tr_last_error());
  return r->m;
}

static inline void tm_free(tm_run *r)
{
  tr_mesh_destroy(r->m);
  tr_plc_destroy(r->used);
  memset(r, 0, sizeof *r);
}

/* The live tet with exactly the vertices v (any order), TR_NONE if none. */
static inline uint32_t tm_find_tet(const tr_mesh *m, const uint32_t v[4])
{
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    int n = 0;
    for (int i = 0; i < 4; i++)
      n += tr_ncode(m, t, v[i]) >= 0;
    if (n == 4)
      return t;
  }
  return TR_NONE;
}

#endif
