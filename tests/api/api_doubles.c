/* tr_options.strict_doubles through the library (the CLI's --strict-doubles is tested in
 * tests/io/cli_formats.py): a mesh whose written doubles lie more than 2^-40 of the
 * bounding box diagonal off their constraints fails with it and is returned without it.
 * Case of test_api (main in test_api.c). */
#include <stdlib.h>
#include <string.h>

#include "api.h"
#include "mesh/check.h"
#include "mesh/conform.h"
#include "pipeline/pipeline.h"

/* schoenhardt_rotated.off (Schoenhardt's prism, which has no tetrahedralization without a
 * Steiner point, rotated so that no edge is along an axis; star_far.off, a star-shaped
 * polyhedron, needs no point since flipnm undoes its failed nested removals) moved by 2^40
 * along every axis: the recovery's Steiner points on its surface are rationals whose nearest
 * doubles, 2^-12 apart out there, lie far off it relative to the model's size. */
static tr_plc *far_star(double shift)
{
  tr_plc *p = read_plc("tests/data/schoenhardt_rotated.off"), *q = NULL;
  if (!p)
    return NULL;
  double *x = malloc(sizeof *x * 3 * (size_t)p->npoints);
  EXPECT(x != NULL, "out of memory");
  if (x) {
    for (size_t i = 0; i < 3 * (size_t)p->npoints; i++)
      x[i] = p->xyz[i] + shift;
    EXPECT(tr_plc_create(&q) == TR_OK &&
               tr_plc_set(q, x, p->npoints, p->tris, p->ntris, NULL) == TR_OK,
           "far star: %s", tr_last_error());
  }
  free(x);
  tr_plc_destroy(p);
  return q;
}

/* Meshes p keeping the recovery's Steiner points (the suppression stage would move
 * those on facets inside, where every double is exact); returns the status, *dev the
 * deviation the stats report, and checks a returned mesh with both validators and
 * tr_mesh_double_deviation. */
static tr_status mesh_far(const tr_plc *p, int strict, const char *what, double *dev)
{
  tr_options o = quiet();
  o.keep_steiner = 1;
  o.strict_doubles = strict;
  tr_stats st = {.size = sizeof st};
  tr_mesh *m = NULL;
  tr_plc *used = NULL;
  tr_status s = tr_mesh_plc_flags(p, &o, &m, &st, &used, 0);
  *dev = st.double_deviation;
  if (s != TR_OK) {
    EXPECT(m == NULL, "%s: a failed call returned a mesh", what);
  } else {
    EXPECT(m != NULL && tr_mesh_num_tets(m) > 0, "%s: no mesh", what);
    EXPECT(tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, NULL) == TR_OK,
           "%s: mesh check: %s", what, tr_last_error());
    EXPECT(tr_check_conformity(m, used, NULL, 0) == TR_OK, "%s: conformity: %s", what,
           tr_last_error());
    double d = -1;
    uint32_t v;
    EXPECT(tr_mesh_double_deviation(m, used, &d, &v) == TR_OK && d == st.double_deviation,
           "%s: tr_mesh_double_deviation %g, stats %g", what, d, st.double_deviation);
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
  return s;
}

void t_strict_doubles(void)
{
  tr_plc *far = far_star(0x1p40), *near = far_star(0);
  if (!far || !near) {
    EXPECT(0, "inputs");
    tr_plc_destroy(far);
    tr_plc_destroy(near);
    return;
  }
  double dev;
  EXPECT(mesh_far(far, 0, "far, lenient", &dev) == TR_OK, "far, lenient: %s", tr_last_error());
  EXPECT(dev > 0x1p-40, "far star: written doubles %g of the diagonal off: not above 2^-40",
         dev);
  tr_status s = mesh_far(far, 1, "far, strict", &dev);
  EXPECT(s == TR_ERR_INVALID_MESH && strstr(tr_last_error(), "strict_doubles") != NULL,
         "far, strict: %s (%s), TR_ERR_INVALID_MESH naming strict_doubles expected",
         tr_status_name(s), tr_last_error());
  /* the same surface at the origin: its doubles are within 2^-40, strict passes */
  s = mesh_far(near, 1, "near, strict", &dev);
  EXPECT(s == TR_OK && dev <= 0x1p-40, "near, strict: %s, deviation %g", tr_last_error(), dev);
  tr_plc_destroy(far);
  tr_plc_destroy(near);
}
