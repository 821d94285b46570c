/* Meshing at extreme scales (issue 50): `test_scale CASE [FILE.off]`.
 *   surface FILE.off: the surface times 1, 2^600, 2^-600, 1e200 and 1e-200, meshed without
 *            smoothing (so that recovery adds Steiner points and suppression removes or
 *            relocates them): every mesh passes the mesh validator and the exact
 *            conformity validator, and its statistics (smallest and largest dihedral
 *            angle, largest radius-edge ratio) are those at scale 1: the very same doubles
 *            at a power of two (exact scaling, the same mesh), within 1e-12 relatively at
 *            a power of ten (rounded input). Suppression once computed normals in doubles
 *            that overflowed into a NaN point at 1e200 (GMP aborted on it), and every
 *            statistic came out 180 degrees and 1e308 at 1e200 and 1e-200.
 *   shape:   tr_tet_shape and tr_tet_min_cos of one tet at 2^k, k = -1000..1000: the
 *            same angles and ratio, the volume times 2^3k and the circumcentre times 2^k
 *            wherever those are doubles. */
#include <gmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "input/validate.h"
#include "mesh/check.h"
#include "mesh/conform.h"
#include "pipeline/pipeline.h"
#include "refine/quality.h"
#include "tetrec.h"

#include "../pipeline/texpect.h"

typedef struct {
  double min_dih, max_dih, max_re;
  uint64_t removed, relocated, tets;
} figures;

/* Meshes plc's points times 2^e (pow2) or times f, validates, and returns the figures. */
static int mesh_scaled(const char *name, const tr_plc *plc, int pow2, int e, double f,
                       figures *out)
{
  uint32_t np = tr_plc_num_points(plc), nt = tr_plc_num_triangles(plc);
  const double *x0 = tr_plc_points(plc);
  double *x = malloc(sizeof *x * 3 * (size_t)np);
  if (!x)
    return 0;
  for (size_t i = 0; i < 3 * (size_t)np; i++)
    x[i] = pow2 ? ldexp(x0[i], e) : x0[i] * f;
  tr_plc *p = NULL;
  tr_status s = tr_plc_create(&p);
  if (s == TR_OK)
    s = tr_plc_set(p, x, np, tr_plc_triangles(plc), nt, NULL);
  free(x);
  EXPECT(s == TR_OK, "%s: %s", name, tr_last_error());
  tr_options opt;
  tr_options_default(&opt);
  opt.verbose = 0;
  opt.smooth = 0;
  tr_mesh *m = NULL;
  tr_plc *used = NULL;
  tr_stats st;
  memset(&st, 0, sizeof st);
  st.size = sizeof st;
  if (s == TR_OK)
    s = tr_mesh_plc_ex(p, &opt, &m, &st, &used);
  EXPECT(s == TR_OK, "%s: %s: %s", name, tr_status_name(s), tr_last_error());
  int ok = s == TR_OK;
  if (ok) {
    s = tr_check_mesh(m, TR_CHK_TOPOLOGY & ~TR_CHK_EULER, NULL);
    EXPECT(s == TR_OK, "%s: mesh validator: %s", name, tr_last_error());
    mpq_t v;
    mpq_init(v);
    tr_status sv = tr_input_domain_volume6(used, v);
    EXPECT(sv == TR_OK, "%s: domain volume: %s", name, tr_last_error());
    s = tr_check_conformity(m, used, sv == TR_OK ? v : NULL, 0);
    EXPECT(s == TR_OK, "%s: conformity: %s", name, tr_last_error());
    mpq_clear(v);
    out->min_dih = st.min_dihedral;
    out->max_dih = st.max_dihedral;
    out->max_re = st.max_radius_edge;
    out->removed = st.steiner_removed;
    out->relocated = st.steiner_relocated;
    out->tets = st.volume_elements;
    fprintf(stderr, "%s: %llu tets, %llu Steiner points removed, %llu relocated; dihedral "
            "%.17g .. %.17g, radius-edge up to %.17g\n", name, (unsigned long long)out->tets,
            (unsigned long long)out->removed, (unsigned long long)out->relocated,
            out->min_dih, out->max_dih, out->max_re);
  }
  tr_mesh_destroy(m);
  tr_plc_destroy(used);
  tr_plc_destroy(p);
  return ok;
}

static int near_rel(double a, double b, double rel)
{
  return fabs(a - b) <= rel * fabs(b);
}

static void surface(const char *path)
{
  tr_plc *plc = NULL;
  tr_status s = tr_plc_read(path, &plc);
  EXPECT(s == TR_OK, "%s: %s", path, tr_last_error());
  if (s != TR_OK)
    return;
  figures f1;
  if (mesh_scaled("scale 1", plc, 1, 0, 1, &f1)) {
    EXPECT(f1.removed + f1.relocated > 0,
           "%s: suppression had nothing to do at scale 1: a test of nothing", path);
    static const int ex[2] = {600, -600};
    for (int i = 0; i < 2; i++) {
      char name[32];
      snprintf(name, sizeof name, "scale 2^%d", ex[i]);
      figures f;
      if (!mesh_scaled(name, plc, 1, ex[i], 0, &f))
        continue;
      /* exact scaling: the same decisions, the same mesh, the same doubles */
      EXPECT(f.min_dih == f1.min_dih && f.max_dih == f1.max_dih && f.max_re == f1.max_re,
             "%s: %s: figures %.17g %.17g %.17g, at scale 1 %.17g %.17g %.17g", path, name,
             f.min_dih, f.max_dih, f.max_re, f1.min_dih, f1.max_dih, f1.max_re);
      EXPECT(f.removed == f1.removed && f.relocated == f1.relocated && f.tets == f1.tets,
             "%s: %s: another mesh than at scale 1", path, name);
    }
    static const double fs[2] = {1e200, 1e-200};
    for (int i = 0; i < 2; i++) {
      char name[32];
      snprintf(name, sizeof name, "scale %g", fs[i]);
      figures f;
      if (!mesh_scaled(name, plc, 0, 0, fs[i], &f))
        continue;
      /* the input rounded after scaling: measures of nearly the same tets */
      EXPECT(near_rel(f.min_dih, f1.min_dih, 1e-12) && near_rel(f.max_dih, f1.max_dih, 1e-12) &&
                 near_rel(f.max_re, f1.max_re, 1e-12),
             "%s: %s: figures %.17g %.17g %.17g, at scale 1 %.17g %.17g %.17g", path, name,
             f.min_dih, f.max_dih, f.max_re, f1.min_dih, f1.max_dih, f1.max_re);
    }
  }
  tr_plc_destroy(plc);
}

static void shape(void)
{
  /* an irregular tet, its coordinates of a few bits so that every power of two scales
   * them exactly */
  static const double t[4][3] = {{0.5, -0.25, 1}, {3, 0.75, -0.5}, {-1, 2.5, 0.25},
                                 {0.75, 1, 3.5}};
  double r1, v1, d1[6], c1[3], w1;
  EXPECT(tr_tet_shape(t[0], t[1], t[2], t[3], &r1, &v1, d1, c1), "no circumcentre at 2^0");
  double lo1 = tr_tet_min_cos(t[0], t[1], t[2], t[3], &w1);
  for (int k = -1000; k <= 1000; k += 50) {
    double s[4][3], r, v, d[6], c[3], w;
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 3; j++)
        s[i][j] = ldexp(t[i][j], k);
    int has_cc = tr_tet_shape(s[0], s[1], s[2], s[3], &r, &v, d, c);
    double lo = tr_tet_min_cos(s[0], s[1], s[2], s[3], &w);
    EXPECT(r == r1 && lo == lo1, "2^%d: ratio %.17g min cosine %.17g, at 2^0 %.17g %.17g",
           k, r, lo, r1, lo1);
    for (int e = 0; e < 6; e++)
      EXPECT(d[e] == d1[e], "2^%d: angle %d %.17g, at 2^0 %.17g", k, e, d[e], d1[e]);
    /* the volume and the circumcentre wherever they are normal doubles */
    if (abs(3 * k) < 1000) {
      EXPECT(v == ldexp(v1, 3 * k) && w == v, "2^%d: volume %.17g, expected %.17g", k, v,
             ldexp(v1, 3 * k));
    }
    if (abs(k) < 1000) {
      EXPECT(has_cc, "2^%d: no circumcentre", k);
      for (int j = 0; j < 3; j++)
        EXPECT(c[j] == ldexp(c1[j], k), "2^%d: circumcentre %.17g, expected %.17g", k, c[j],
               ldexp(c1[j], k));
    }
  }
}

int main(int argc, char **argv)
{
  if (argc > 2 && !strcmp(argv[1], "surface"))
    surface(argv[2]);
  else if (argc > 1 && !strcmp(argv[1], "shape"))
    shape();
  else {
    fprintf(stderr, "usage: test_scale surface FILE.off | shape\n");
    return 2;
  }
  return failures != 0;
}
