/* --surface-tolerance (src/simplify, docs/simplify.md): the two-sided bound decided
 * exactly on surfaces at known distances, and the stage on a box whose faces are fans of
 * thin triangles: every mesh through the mesh validator and the exact conformity
 * validator against the simplified surface (tmesh.h), and every simplified output's
 * boundary checked against the input by the bound (tr_simplify_bound, on the mesh's own
 * boundary faces and written doubles). */
#define _DEFAULT_SOURCE
#include <math.h>

#include "refine/quality.h"
#include "simplify/edit.h"
#include "simplify/simplify.h"
#include "../pipeline/tmesh.h"

/* An n x n grid of squares on [0,1]^2 at height z, two triangles each; flip: the other
 * diagonal. */
static void grid(int n, double z, int flip, double *x, uint32_t *t)
{
  for (int j = 0; j <= n; j++)
    for (int i = 0; i <= n; i++) {
      double *p = x + 3 * (size_t)(j * (n + 1) + i);
      p[0] = (double)i / n, p[1] = (double)j / n, p[2] = z;
    }
  for (int j = 0; j < n; j++)
    for (int i = 0; i < n; i++) {
      uint32_t a = (uint32_t)(j * (n + 1) + i), b = a + 1, c = a + (uint32_t)n + 1, d = c + 1;
      uint32_t q[6] = {a, b, d, a, d, c}, r[6] = {a, b, c, b, d, c};
      memcpy(t + 6 * (size_t)(j * n + i), flip ? r : q, sizeof q);
    }
}

static int bound_holds(const double *x, const uint32_t *t, uint32_t nt, const double *y,
                       const uint32_t *u, uint32_t nu, double d, double *measured)
{
  tr_simp_bound_result r;
  tr_status s = tr_simplify_bound(x, t, nt, y, u, nu, d, &r);
  EXPECT(s == TR_OK, "tr_simplify_bound: %s", tr_last_error());
  *measured = r.measured;
  return s == TR_OK && r.ok;
}

/* A plane and its copy offset by exactly d: within d, not within the double below d;
 * with the diagonals of the copy flipped the pieces need subdividing: within 1.01 d, not
 * below d. d down to 2^-30 of the plane's size, and above it. */
static void offset_plane(void)
{
  enum { N = 4 };
  double x[3 * (N + 1) * (N + 1)], y[3 * (N + 1) * (N + 1)];
  uint32_t t[6 * N * N], u[6 * N * N];
  const double ds[] = {0.25, 1e-3, 0x1p-30, 3.0};
  for (size_t k = 0; k < sizeof ds / sizeof *ds; k++) {
    double d = ds[k], m;
    grid(N, 0, 0, x, t);
    grid(N, d, 0, y, u);
    EXPECT(bound_holds(x, t, 2 * N * N, y, u, 2 * N * N, d, &m),
           "a copy offset by exactly %g is within %g", d, d);
    EXPECT(m <= d, "measured bound %.17g above %g", m, d);
    EXPECT(!bound_holds(x, t, 2 * N * N, y, u, 2 * N * N, nextafter(d, 0), &m),
           "a copy offset by exactly %g is not within the double below it", d);
    /* the flipped copy is covered by two triangles near each diagonal, and pieces there
     * must shrink to about d to be within 1.01 d of one of them: 2^-30 below the
     * triangles' size that is more pieces than the budget (docs/simplify.md) */
    if (d < 1e-6)
      continue;
    grid(N, d, 1, y, u);
    EXPECT(bound_holds(x, t, 2 * N * N, y, u, 2 * N * N, 1.01 * d, &m),
           "the flipped copy offset by %g is within 1.01 times that", d);
    EXPECT(!bound_holds(x, t, 2 * N * N, y, u, 2 * N * N, nextafter(d, 0), &m),
           "the flipped copy offset by %g is not within the double below it", d);
  }
  /* one way only: the copy covers a square half as wide */
  grid(N, 0, 0, x, t);
  grid(N, 1e-3, 0, y, u);
  for (int i = 0; i < (N + 1) * (N + 1); i++)
    y[3 * i] *= 0.5;
  double m;
  EXPECT(!bound_holds(x, t, 2 * N * N, y, u, 2 * N * N, 0.4, &m),
         "half of the plane is farther than 0.4 from a copy half as wide");
  EXPECT(bound_holds(y, u, 2 * N * N, x, t, 2 * N * N, 0.01, &m) == 0,
         "the two-sided bound fails when only one side holds");
}

/* The box [0,1]^3 whose faces are fans of 4 n thin triangles around their centres, the
 * centres raised by bump (out of the box), n points on each edge. */
static tr_plc *fan_box(int n, double bump)
{
  /* points: 8 corners, then 12 edges x (n - 1) inner points, then 6 centres */
  uint32_t np = 8 + 12 * (uint32_t)(n - 1) + 6;
  double *x = malloc(sizeof *x * 3 * np);
  uint32_t *t = malloc(sizeof *t * 3 * 6 * 4 * (size_t)n);
  for (int i = 0; i < 8; i++)
    for (int k = 0; k < 3; k++)
      x[3 * i + k] = (i >> k) & 1;
  /* edge e joins corners a < b differing in one bit */
  int ea[12], eb[12], ne = 0;
  for (int a = 0; a < 8; a++)
    for (int k = 0; k < 3; k++)
      if (!((a >> k) & 1))
        ea[ne] = a, eb[ne++] = a | 1 << k;
  for (int e = 0; e < 12; e++)
    for (int i = 1; i < n; i++)
      for (int k = 0; k < 3; k++)
        x[3 * (8 + e * (n - 1) + i - 1) + k] =
            x[3 * ea[e] + k] + (x[3 * eb[e] + k] - x[3 * ea[e] + k]) * i / n;
  /* the point i (0..n) along edge a -> b */
  uint32_t nt = 0;
  for (int k = 0; k < 3; k++)
    for (int s = 0; s < 2; s++) {
      uint32_t c = 8 + 12 * (uint32_t)(n - 1) + (uint32_t)(2 * k + s);
      int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      for (int q = 0; q < 3; q++)
        x[3 * c + q] = q == k ? s + (s ? bump : -bump) : 0.5;
      /* the face's corners in cyclic order */
      int cor[4] = {s << k, (s << k) | 1 << k1, (s << k) | 1 << k1 | 1 << k2,
                    (s << k) | 1 << k2};
      for (int side = 0; side < 4; side++) {
        int a = cor[side], b = cor[(side + 1) % 4];
        int e = 0;
        while (!((ea[e] == a && eb[e] == b) || (ea[e] == b && eb[e] == a)))
          e++;
        for (int i = 0; i < n; i++) {
          int i0 = ea[e] == a ? i : n - i, i1 = ea[e] == a ? i + 1 : n - i - 1;
          uint32_t p0 = i0 == 0 ? (uint32_t)ea[e] : i0 == n ? (uint32_t)eb[e]
                                                           : 8 + (uint32_t)(e * (n - 1) + i0 - 1);
          uint32_t p1 = i1 == 0 ? (uint32_t)ea[e] : i1 == n ? (uint32_t)eb[e]
                                                           : 8 + (uint32_t)(e * (n - 1) + i1 - 1);
          t[3 * nt] = c, t[3 * nt + 1] = p0, t[3 * nt + 2] = p1;
          nt++;
        }
      }
    }
  tr_plc *p = tm_plc(x, np, t, nt);
  free(x), free(t);
  return p;
}

/* The boundary faces of m against the input plc, both ways, within eps of the diagonal. */
static void check_output_bound(const char *name, const tr_plc *plc, const tr_mesh *m,
                               double eps)
{
  double diag = tr_simplify_diagonal(plc), meas;
  EXPECT(bound_holds(plc->xyz, plc->tris, plc->ntris, tr_mesh_points(m),
                     tr_mesh_boundary_faces(m), tr_mesh_num_boundary_faces(m), eps * diag,
                     &meas),
         "%s: the mesh's boundary is not proven within %g of the diagonal of the input", name,
         eps);
}

static void fan_box_case(const char *name, int n, double bump, double eps, int quality)
{
  tr_plc *in = fan_box(n, bump);
  tr_options opt = quality ? tm_refinement(1.414, 0) : tm_options();
  tm_run plain, tol, again;
  tr_mesh *m0 = tm_mesh(&plain, name, in, &opt, TR_CHK_TOPOLOGY);
  opt.surface_tolerance = eps;
  tr_mesh *m1 = tm_mesh(&tol, name, in, &opt, TR_CHK_TOPOLOGY);
  tr_mesh *m2 = tm_mesh(&again, name, in, &opt, TR_CHK_TOPOLOGY);
  if (m0 && m1 && m2) {
    EXPECT(tol.st.surface_collapses > 0, "%s: no collapse", name);
    EXPECT(tol.used->ntris < in->ntris, "%s: %u triangles, as many as the input's %u", name,
           tol.used->ntris, in->ntris);
    EXPECT(tol.st.surface_tolerance_bound > 0 && tol.st.surface_tolerance_bound <= eps,
           "%s: reported bound %g, tolerance %g", name, tol.st.surface_tolerance_bound, eps);
    check_output_bound(name, in, m1, eps);
    EXPECT(tol.st.min_dihedral > plain.st.min_dihedral, "%s: smallest dihedral %g with the "
           "tolerance, %g without", name, tol.st.min_dihedral, plain.st.min_dihedral);
    /* the same input, the same mesh */
    EXPECT(tr_mesh_num_vertices(m1) == tr_mesh_num_vertices(m2) &&
               tr_mesh_num_tets(m1) == tr_mesh_num_tets(m2) &&
               !memcmp(tr_mesh_tets(m1), tr_mesh_tets(m2),
                       sizeof(uint32_t) * 4 * tr_mesh_num_tets(m1)) &&
               !memcmp(tr_mesh_points(m1), tr_mesh_points(m2),
                       sizeof(double) * 3 * tr_mesh_num_vertices(m1)),
           "%s: two runs differ", name);
    if (bump > 0) {
      /* the bump went: the bound is not met at a tenth of it */
      double meas;
      EXPECT(!bound_holds(in->xyz, in->tris, in->ntris, tr_mesh_points(m1),
                          tr_mesh_boundary_faces(m1), tr_mesh_num_boundary_faces(m1),
                          bump / 10, &meas),
             "%s: the surface moved by less than a tenth of the bump", name);
    }
  }
  tm_free(&plain), tm_free(&tol), tm_free(&again);
  tr_plc_destroy(in);
}

static void fan_box_flat(void) { fan_box_case("fan box", 16, 0, 1e-3, 1); }
static void fan_box_bump(void) { fan_box_case("fan box, bumps", 16, 1e-4, 1e-3, 1); }
static void fan_box_plain(void) { fan_box_case("fan box, no refinement", 8, 0, 1e-3, 0); }

/* The unit cube sheared by x += 2 y: its faces z = 0 and z = 1 are parallelograms, each
 * cut along its long diagonal into a cap (corners 153.4, 18.4 and 8.1 degrees) and its
 * twin. Every corner is on three sharp edges, so nothing collapses; flipping each long
 * diagonal into the short one is the only move (the other faces' triangles, 26.6 degrees
 * at worst, are right triangles, no caps), and it raises the smallest angle to 18.4
 * degrees without moving the surface at all (the proof of the bound, by pieces, needs
 * the tolerance: the pieces across the new diagonal shrink to its size). */
static void sheared_box_flips(void)
{
  double x[24];
  for (int i = 0; i < 8; i++) {
    x[3 * i] = (i & 1) + 2 * ((i >> 1) & 1);
    x[3 * i + 1] = (i >> 1) & 1;
    x[3 * i + 2] = (i >> 2) & 1;
  }
  const uint32_t t[36] = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
                          2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  tr_plc *in = tm_plc(x, 8, t, 12);
  tr_options opt = tm_options();
  opt.surface_tolerance = 1e-3;
  tm_run a, b;
  tr_mesh *m1 = tm_mesh(&a, "sheared box", in, &opt, TR_CHK_TOPOLOGY);
  tr_mesh *m2 = tm_mesh(&b, "sheared box", in, &opt, TR_CHK_TOPOLOGY);
  if (m1 && m2) {
    EXPECT(a.st.surface_flips == 2 && a.st.surface_collapses == 0,
           "sheared box: %llu flips and %llu collapses, not 2 and 0",
           (unsigned long long)a.st.surface_flips, (unsigned long long)a.st.surface_collapses);
    double worst = 180;
    for (uint32_t i = 0; i < a.used->ntris; i++) {
      const uint32_t *v = a.used->tris + 3 * (size_t)i;
      worst = fmin(worst, tr_simp_min_angle(a.used->xyz + 3 * (size_t)v[0],
                                            a.used->xyz + 3 * (size_t)v[1],
                                            a.used->xyz + 3 * (size_t)v[2]));
    }
    EXPECT(fabs(worst - atan(1.0 / 3) * 180 / M_PI) < 1e-9,
           "sheared box: smallest angle %.12g after the flips, not atan(1/3)", worst);
    check_output_bound("sheared box", in, m1, 1e-3);
    EXPECT(a.st.surface_tolerance_bound <= 1e-3, "sheared box: reported bound %g",
           a.st.surface_tolerance_bound);
    EXPECT(tr_mesh_num_tets(m1) == tr_mesh_num_tets(m2) &&
               !memcmp(tr_mesh_tets(m1), tr_mesh_tets(m2),
                       sizeof(uint32_t) * 4 * tr_mesh_num_tets(m1)),
           "sheared box: two runs differ");
  }
  tm_free(&a), tm_free(&b);
  tr_plc_destroy(in);
}

/* Too small to move anything: the mesh is the input's (the bumps are 1e-4, the
 * tolerance 1e-9). */
static void tiny_tolerance(void)
{
  tr_plc *in = fan_box(8, 1e-4);
  tr_options opt = tm_options();
  tm_run a, b;
  tr_mesh *m0 = tm_mesh(&a, "tiny", in, &opt, TR_CHK_TOPOLOGY);
  opt.surface_tolerance = 1e-9;
  tr_mesh *m1 = tm_mesh(&b, "tiny", in, &opt, TR_CHK_TOPOLOGY);
  if (m0 && m1) {
    EXPECT(b.st.surface_collapses == 0, "tiny: %llu collapses",
           (unsigned long long)b.st.surface_collapses);
    EXPECT(tr_mesh_num_tets(m0) == tr_mesh_num_tets(m1) &&
               !memcmp(tr_mesh_tets(m0), tr_mesh_tets(m1),
                       sizeof(uint32_t) * 4 * tr_mesh_num_tets(m0)),
           "tiny: the mesh differs from the exact mode's");
  }
  tm_free(&a), tm_free(&b);
  tr_plc_destroy(in);
}

static void bad_values(void)
{
  tr_plc *in = fan_box(2, 0);
  const double bad[] = {-1e-3, NAN, INFINITY, -INFINITY};
  for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
    tr_options opt = tm_options();
    opt.surface_tolerance = bad[i];
    tr_mesh *m = NULL;
    tr_status s = tr_mesh_plc(in, &opt, &m, NULL);
    EXPECT(s == TR_ERR_USAGE && !m, "surface_tolerance %g: %s, not TR_ERR_USAGE", bad[i],
           tr_status_name(s));
    tr_mesh_destroy(m);
  }
  tr_plc_destroy(in);
}

/* `write N BUMP FILE`: the fan box as OFF, for the command-line test. */
static int write_off(int n, double bump, const char *path)
{
  tr_plc *p = fan_box(n, bump);
  tr_status s = tr_plc_write(p, path);
  tr_plc_destroy(p);
  return s != TR_OK;
}

int main(int argc, char **argv)
{
  if (argc == 5 && !strcmp(argv[1], "write"))
    return write_off(atoi(argv[2]), atof(argv[3]), argv[4]);
  static const texpect_case cases[] = {
      {"offset_plane", offset_plane, NULL},
      {"fan_box_flat", fan_box_flat, NULL},
      {"fan_box_bump", fan_box_bump, NULL},
      {"fan_box_plain", fan_box_plain, NULL},
      {"sheared_box_flips", sheared_box_flips, NULL},
      {"tiny_tolerance", tiny_tolerance, NULL},
      {"bad_values", bad_values, NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
