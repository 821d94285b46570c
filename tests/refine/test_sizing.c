/* The size field (tr_options.sizing, src/refine/sizing.c) through the whole pipeline: a
 * target edge length per input point, interpolated linearly. On the unit cube with a
 * linear field (interpolated exactly on any background tetrahedralization) the refined
 * mesh is graded: every tet's longest edge within the mean size of its vertices, fine at
 * the small corner and coarse at the far one, more tets for a smaller size; it composes
 * with the volume and ratio bounds, keeps the surface under keep_surface, is the same for
 * any thread count, survives the merge of duplicate points, and bad arrays and fields
 * that ask for too many points are refused. Every mesh goes through the mesh validator
 * and the exact conformity validator (tmesh.h). */
#include <math.h>
#include <string.h>

#include "refine/refine.h"
#include "../pipeline/tmesh.h"
#include "tvolume.h"

static const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};

/* h = a + b (x + y + z) at the box's corners (tm_box's point order) */
static void linear_sizes(double a, double b, double h[8])
{
  for (int i = 0; i < 8; i++)
    h[i] = a + b * ((i & 1) + ((i >> 1) & 1) + ((i >> 2) & 1));
}

typedef struct {
  uint32_t tets, over;   /* tets; tets whose longest edge is over their vertices' mean h */
  double worst;          /* the largest longest edge / mean h */
  double near_max;       /* the longest edge of a tet with centroid x+y+z < 0.3 */
  double far_max;        /* the longest edge of a tet with centroid x+y+z > 2.5 */
} grading;

static grading measure(const tr_mesh *m, double a, double b)
{
  grading g = {0, 0, 0, 0, 0};
  const double *x = tr_mesh_points(m);
  const uint32_t *t = tr_mesh_tets(m);
  g.tets = tr_mesh_num_tets(m);
  for (uint32_t i = 0; i < g.tets; i++) {
    const uint32_t *v = t + 4 * (size_t)i;
    double h = 0, s = 0, l2 = 0;
    for (int j = 0; j < 4; j++) {
      const double *p = x + 3 * (size_t)v[j];
      h += (a + b * (p[0] + p[1] + p[2])) / 4;
      s += (p[0] + p[1] + p[2]) / 4;
      for (int k = j + 1; k < 4; k++) {
        const double *q = x + 3 * (size_t)v[k];
        double d = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                   (p[2] - q[2]) * (p[2] - q[2]);
        l2 = d > l2 ? d : l2;
      }
    }
    double l = sqrt(l2);
    /* the doubles of the field are not the test's to the last bit */
    g.over += l > h * (1 + 1e-9);
    g.worst = l / h > g.worst ? l / h : g.worst;
    if (s < 0.3)
      g.near_max = l > g.near_max ? l : g.near_max;
    if (s > 2.5)
      g.far_max = l > g.far_max ? l : g.far_max;
  }
  return g;
}

static tr_options sized(const double *h, uint32_t n)
{
  tr_options opt = tm_refinement(0, 0);
  opt.sizing = h;
  opt.nsizing = n;
  return opt;
}

/* h from 0.02 at the origin to 0.32 at (1,1,1), refinement only (sliver removal's flips
 * may lengthen an edge: that stage is measured below) */
static void graded_cube(void)
{
  double h[8];
  linear_sizes(0.02, 0.1, h);
  tr_plc *plc = tm_box(lo, hi);
  tr_options opt = sized(h, 8);
  tm_run r;
  tr_mesh *m = tm_mesh(&r, "graded_cube", plc, &opt, TR_CHK_TOPOLOGY);
  if (m) {
    grading g = measure(m, 0.02, 0.1);
    fprintf(stderr, "graded_cube: %u tets, %u over, worst %.3f, near %.4f, far %.4f\n", g.tets,
            g.over, g.worst, g.near_max, g.far_max);
    EXPECT(g.over == 0, "%u of %u tets have their longest edge over their vertices' mean size "
           "(worst %.3f times)", g.over, g.tets, g.worst);
    EXPECT(g.near_max < 0.06, "a tet near the fine corner has an edge of %g", g.near_max);
    EXPECT(g.far_max > 0.15, "the coarse corner is refined as finely as the fine one: "
           "longest edge %g", g.far_max);
    /* the estimate the budget check uses is of the right order */
    EXPECT(g.tets > 4000 && g.tets < 60000, "%u tets", g.tets);
  }
  tm_free(&r);
  /* with sliver removal's flips, moves and points an edge may grow a little */
  opt.optimize = 3;
  m = tm_mesh(&r, "graded_cube_optimized", plc, &opt, TR_CHK_TOPOLOGY);
  if (m) {
    grading g = measure(m, 0.02, 0.1);
    fprintf(stderr, "graded_cube with sliver removal: %u tets, %u over, worst %.3f\n", g.tets,
            g.over, g.worst);
    EXPECT(g.worst < 1.5, "sliver removal made an edge %.3f times its size", g.worst);
  }
  tm_free(&r);
  tr_plc_destroy(plc);
}

/* a uniform field: the smaller h, the more tets; each within its h */
static void monotone(void)
{
  static const double sizes[] = {0.25, 0.17, 0.12, 0.085};
  uint32_t last = 0;
  tr_plc *plc = tm_box(lo, hi);
  for (size_t i = 0; i < sizeof sizes / sizeof *sizes; i++) {
    double h[8];
    linear_sizes(sizes[i], 0, h);
    tr_options opt = sized(h, 8);
    tm_run r;
    tr_mesh *m = tm_mesh(&r, "uniform", plc, &opt, TR_CHK_TOPOLOGY);
    if (m) {
      grading g = measure(m, sizes[i], 0);
      fprintf(stderr, "uniform h %g: %u tets\n", sizes[i], g.tets);
      EXPECT(g.over == 0, "h %g: %u tets over it (worst %.3f)", sizes[i], g.over, g.worst);
      EXPECT(g.tets > last, "h %g: %u tets, no more than the %u of a larger h", sizes[i],
             g.tets, last);
      last = g.tets;
    }
    tm_free(&r);
  }
  tr_plc_destroy(plc);
}

/* with -a V and a radius-edge bound: every bound holds at once */
static void composes(void)
{
  double h[8];
  linear_sizes(0.03, 0.1, h);
  tr_plc *plc = tm_box(lo, hi);
  tr_options opt = sized(h, 8);
  opt.max_volume = 2e-4;
  opt.quality_ratio = 1.414;
  tm_run r;
  tr_mesh *m = tm_mesh(&r, "composes", plc, &opt, TR_CHK_TOPOLOGY);
  if (m) {
    grading g = measure(m, 0.03, 0.1);
    uint32_t n, over = tv_count_over(m, opt.max_volume, UINT32_MAX, &n);
    EXPECT(g.over == 0, "%u tets over the size (worst %.3f)", g.over, g.worst);
    EXPECT(over == 0, "%u of %u tets over the volume bound", over, n);
    /* the radius-edge bound is met as without a field: up to the tets whose circumcentre
     * a vertex's spacing refuses (refine.c, too_close), a few */
    EXPECT(r.st.tets_over_bounds * 200 < n, "%llu of %u tets over the radius-edge bound "
           "(worst %g)", (unsigned long long)r.st.tets_over_bounds, n, r.st.max_radius_edge);
    /* the coarse side is bounded by the volume, finer than h alone would make it */
    EXPECT(g.far_max < 0.2, "longest edge at the coarse corner %g", g.far_max);
  }
  tm_free(&r);
  tr_plc_destroy(plc);
}

/* under keep_surface: the input triangles stay the boundary, points go inside only, and
 * the interior tets meet the field. The surface is the boundary of a cube meshed under a
 * uniform size 0.2 (the 12 triangles of a bare cube have equatorial balls that cover the
 * whole cube: every circumcentre there encroaches a triangle that may not be split, and
 * is left, as under a ratio bound) */
static void keep_surface(void)
{
  double h[8];
  linear_sizes(0.2, 0, h);
  tr_plc *box = tm_box(lo, hi), *plc = NULL;
  tr_options opt = sized(h, 8);
  tm_run r;
  tr_mesh *m = tm_mesh(&r, "keep_surface_input", box, &opt, TR_CHK_TOPOLOGY);
  uint32_t nf = m ? tr_mesh_num_boundary_faces(m) : 0, nv = 0;
  uint32_t *map = m ? malloc(sizeof *map * tr_mesh_num_vertices(m)) : NULL;
  uint32_t *f = m ? malloc(sizeof *f * 3 * (size_t)nf) : NULL;
  double *x = m ? malloc(sizeof *x * 3 * (size_t)tr_mesh_num_vertices(m)) : NULL;
  if (m && map && f && x) {
    memset(map, 0xff, sizeof *map * tr_mesh_num_vertices(m));
    for (size_t i = 0; i < 3 * (size_t)nf; i++) {
      uint32_t v = tr_mesh_boundary_faces(m)[i];
      if (map[v] == UINT32_MAX) {
        memcpy(x + 3 * (size_t)nv, tr_mesh_points(m) + 3 * (size_t)v, 3 * sizeof *x);
        map[v] = nv++;
      }
      f[i] = map[v];
    }
    EXPECT(tr_plc_create(&plc) == TR_OK && tr_plc_set(plc, x, nv, f, nf, NULL) == TR_OK,
           "surface: %s", tr_last_error());
  }
  tm_free(&r);
  if (plc) {
    double *hs = malloc(sizeof *hs * nv);
    for (uint32_t i = 0; i < nv; i++)
      hs[i] = 0.1;
    opt = sized(hs, nv);
    opt.keep_surface = 1;
    m = tm_mesh(&r, "keep_surface", plc, &opt, TR_CHK_TOPOLOGY);
    if (m) {
      EXPECT(tr_mesh_num_boundary_faces(m) == nf, "%u boundary faces of %u triangles",
             tr_mesh_num_boundary_faces(m), nf);
      EXPECT(r.st.points_added_for_quality > 100, "%llu points",
             (unsigned long long)r.st.points_added_for_quality);
      /* the tets away from the surface meet the field (nearer, a circumcentre that
       * encroaches a boundary triangle, which may not be split, is left) */
      uint32_t inner = 0, over = 0;
      for (uint32_t t = 0; t < tr_mesh_num_tets(m); t++) {
        const uint32_t *v = tr_mesh_tets(m) + 4 * (size_t)t;
        int on = 0;
        double l2 = 0;
        for (int j = 0; j < 4; j++) {
          const double *p = tr_mesh_points(m) + 3 * (size_t)v[j];
          for (int k = 0; k < 3; k++)
            on |= p[k] < 0.25 || p[k] > 0.75;
          for (int k = j + 1; k < 4; k++) {
            const double *p = tr_mesh_points(m) + 3 * (size_t)v[j],
                         *q = tr_mesh_points(m) + 3 * (size_t)v[k];
            double d = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                       (p[2] - q[2]) * (p[2] - q[2]);
            l2 = d > l2 ? d : l2;
          }
        }
        inner += !on;
        over += !on && l2 > 0.1 * 0.1 * (1 + 1e-9);
      }
      fprintf(stderr, "keep_surface: %u boundary faces, %u tets, %u at least 0.25 from the "
              "surface, %u of them over the size\n", nf, tr_mesh_num_tets(m), inner, over);
      EXPECT(inner > 100 && over == 0, "%u of %u tets away from the surface over the size", over,
             inner);
    }
    tm_free(&r);
    free(hs);
  }
  free(map);
  free(f);
  free(x);
  tr_plc_destroy(plc);
  tr_plc_destroy(box);
}

/* the same mesh, point for point and tet for tet, on 1 and 2 threads */
static void threads(void)
{
  double h[8];
  linear_sizes(0.03, 0.08, h);
  tr_plc *plc = tm_box(lo, hi);
  tm_run r[2];
  for (int i = 0; i < 2; i++) {
    tr_options opt = sized(h, 8);
    opt.quality_ratio = 1.414;
    opt.optimize = 3;
    opt.threads = i + 1;
    tm_mesh(&r[i], i ? "threads_2" : "threads_1", plc, &opt, TR_CHK_TOPOLOGY);
  }
  if (r[0].m && r[1].m) {
    uint32_t nv = tr_mesh_num_vertices(r[0].m), nt = tr_mesh_num_tets(r[0].m);
    EXPECT(nv == tr_mesh_num_vertices(r[1].m) && nt == tr_mesh_num_tets(r[1].m) &&
               !memcmp(tr_mesh_points(r[0].m), tr_mesh_points(r[1].m), 3 * sizeof(double) * nv) &&
               !memcmp(tr_mesh_tets(r[0].m), tr_mesh_tets(r[1].m), 4 * sizeof(uint32_t) * nt),
           "1 and 2 threads differ (%u/%u vertices, %u/%u tets)", nv,
           tr_mesh_num_vertices(r[1].m), nt, tr_mesh_num_tets(r[1].m));
  }
  tm_free(&r[0]);
  tm_free(&r[1]);
  tr_plc_destroy(plc);
}

/* point 8 duplicates the fine corner 0 with the coarse size and takes its place in half
 * the triangles: the merge keeps the finer size */
static void duplicates(void)
{
  double x[27], h[9];
  for (int i = 0; i < 8; i++)
    for (int k = 0; k < 3; k++)
      x[3 * i + k] = (i >> k) & 1 ? 1 : 0;
  memcpy(x + 24, x, 3 * sizeof(double));
  uint32_t t[36] = {0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3, 0, 4, 5, 0, 5, 1,
                    2, 3, 7, 2, 7, 6, 0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5};
  for (int i = 0; i < 18; i++)
    t[i] = t[i] == 0 ? 8 : t[i];
  linear_sizes(0.02, 0.1, h);
  h[8] = 0.3;
  tr_plc *plc = NULL;
  EXPECT(tr_plc_create(&plc) == TR_OK && tr_plc_set(plc, x, 9, t, 12, NULL) == TR_OK,
         "plc: %s", tr_last_error());
  tr_options opt = sized(h, 9);
  tm_run r;
  tr_mesh *m = tm_mesh(&r, "duplicates", plc, &opt, TR_CHK_TOPOLOGY);
  if (m) {
    grading g = measure(m, 0.02, 0.1);
    EXPECT(g.over == 0 && g.near_max < 0.06, "%u tets over, near the corner %g", g.over,
           g.near_max);
  }
  tm_free(&r);
  tr_plc_destroy(plc);
}

/* a count that is not the points', a value not finite or negative: TR_ERR_USAGE naming it;
 * sizes of 0 only: no bound, no point; a field asking for too many points: refused up
 * front naming the field */
static void refused(void)
{
  tr_plc *plc = tm_box(lo, hi);
  double h[8];
  struct {
    uint32_t n, at;
    double v;
    const char *msg;
  } bad[] = {{7, 0, 0.1, "7 values for 8 points"}, {8, 3, -1, "sizing[3] is -1"},
             {8, 5, NAN, "sizing[5] is nan"}, {8, 2, INFINITY, "sizing[2] is inf"}};
  for (size_t i = 0; i < sizeof bad / sizeof *bad; i++) {
    linear_sizes(0.1, 0, h);
    h[bad[i].at] = bad[i].v;
    tr_options opt = sized(h, bad[i].n);
    tr_mesh *m = NULL;
    tr_status s = tr_mesh_plc(plc, &opt, &m, NULL);
    EXPECT(s == TR_ERR_USAGE && !m && strstr(tr_last_error(), bad[i].msg), "case %zu: %s: %s",
           i, tr_status_name(s), tr_last_error());
    tr_mesh_destroy(m);
  }
  tr_options opt = sized(NULL, 8);
  tr_mesh *m = NULL;
  EXPECT(tr_mesh_plc(plc, &opt, &m, NULL) == TR_ERR_USAGE && !m, "NULL sizing with a count");
  linear_sizes(0, 0, h);
  opt = sized(h, 8);
  tm_run r;
  if (tm_mesh(&r, "zero_sizes", plc, &opt, TR_CHK_TOPOLOGY))
    EXPECT(r.st.points_added_for_quality == 0, "sizes of 0 added %llu points",
           (unsigned long long)r.st.points_added_for_quality);
  tm_free(&r);
  linear_sizes(1e-4, 0, h);
  opt = sized(h, 8);
  tr_status s = tr_mesh_plc(plc, &opt, &m, NULL);
  EXPECT(s == TR_ERR_NOMEM && !m && strstr(tr_last_error(), "size field"), "h 1e-4: %s: %s",
         tr_status_name(s), tr_last_error());
  tr_plc_destroy(plc);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"graded_cube", graded_cube, NULL}, {"monotone", monotone, NULL},
      {"composes", composes, NULL},       {"keep_surface", keep_surface, NULL},
      {"threads", threads, NULL},         {"duplicates", duplicates, NULL},
      {"refused", refused, NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
