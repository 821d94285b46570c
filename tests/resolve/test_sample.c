/* An independent check of --resolve's meshes (issue 49): what the mesh covers is the
 * solid by winding number, and its boundary lies on the input.
 *
 * Nothing here comes from src/resolve: the winding number of the input soup at a point
 * is counted along a segment to a point outside its box (each crossing of a triangle's
 * interior counts +1 or -1 by the side the point is on; a segment through an edge, a
 * corner or in a plane is drawn again to another far point), and a point is in the mesh
 * when some tet holds it (four exact orientations). The only shared code is the exact
 * predicates, which tests/predicates and tests/cgal check against CGAL's exact kernel.
 *
 * Samples: points spread over the soup's box, and points next to the soup's triangles
 * (a corner combination rounded to doubles, so on either side or exactly on it). A
 * sample exactly on an input triangle has no winding number and is skipped; every other
 * one must be in the mesh exactly when its winding number is at least 1.
 * Every boundary face of the mesh (a face of one tet) must lie in the union of the input
 * triangles in its plane, exactly (covered() below: split along their edge lines).
 *
 *   test_sample corpus DATA     the resolve corpus (tests/data/resolve_*.off): plain,
 *                               --keep-surface and (not on the turned or moved copies)
 *                               --quality 1.414, exact points kept
 *   test_sample files F...      the same for any files (the notes' runs on CGAL's models)
 *                               SAMPLES=N per kind (default 400)
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "construct.h"
#include "mesh/mesh.h"
#include "tetrec.h"

#include "../pipeline/texpect.h"
#include "../pipeline/tmesh.h"

static uint64_t rng = 0x9e3779b97f4a7c15u;
static double unit(void) /* in [0, 1) */
{
  rng = rng * 6364136223846793005u + 1442695040888963407u;
  return (double)(rng >> 11) * 0x1p-53;
}

typedef struct {
  double lo[3], hi[3];
} box3;

static box3 point_box(const tr_point *p, int n)
{
  box3 b;
  for (int k = 0; k < 3; k++) {
    b.lo[k] = INFINITY;
    b.hi[k] = -INFINITY;
  }
  for (int i = 0; i < n; i++)
    for (int k = 0; k < 3; k++) {
      /* an exact point lies within one ulp of its nearest double */
      double lo = p[i].q ? nextafter(p[i].d[k], -INFINITY) : p[i].d[k];
      double hi = p[i].q ? nextafter(p[i].d[k], INFINITY) : p[i].d[k];
      b.lo[k] = fmin(b.lo[k], lo);
      b.hi[k] = fmax(b.hi[k], hi);
    }
  return b;
}

static int boxes_meet(const box3 *a, const box3 *b)
{
  for (int k = 0; k < 3; k++)
    if (a->hi[k] < b->lo[k] || b->hi[k] < a->lo[k])
      return 0;
  return 1;
}

static tr_point soup_pt(const tr_plc *s, uint32_t v) { return tr_pt_d(s->xyz + 3 * (size_t)v); }

/* The winding number of the soup at p along the segment pq: *w, and 0; 1 when pq meets a
 * triangle other than in its interior at one point (draw another q); 2 when p lies on a
 * triangle (no winding number there). */
static int winding_along(const tr_plc *s, const box3 *tbox, const double *p, const double *q,
                         int *w)
{
  tr_point P = tr_pt_d(p), Q = tr_pt_d(q);
  box3 sb = point_box((tr_point[]){P, Q}, 2);
  int n = 0;
  for (uint32_t t = 0; t < s->ntris; t++) {
    if (!boxes_meet(&sb, tbox + t))
      continue;
    const uint32_t *v = s->tris + 3 * (size_t)t;
    tr_point a = soup_pt(s, v[0]), b = soup_pt(s, v[1]), c = soup_pt(s, v[2]);
    int sp = tr_orient3d_p(&a, &b, &c, &P), sq = tr_orient3d_p(&a, &b, &c, &Q);
    if (sp == 0) {
      if (tr_classify_point_triangle(&P, &a, &b, &c).type != TR_DEG)
        return 2;
      if (sq == 0)
        return 1;
      continue; /* pq leaves the plane at p, outside the triangle */
    }
    if (sq == 0)
      return 1;
    if (sp == sq)
      continue;
    int e1 = tr_orient3d_p(&P, &Q, &a, &b), e2 = tr_orient3d_p(&P, &Q, &b, &c),
        e3 = tr_orient3d_p(&P, &Q, &c, &a);
    int pos = (e1 > 0) + (e2 > 0) + (e3 > 0), neg = (e1 < 0) + (e2 < 0) + (e3 < 0);
    if (pos && neg)
      continue; /* the line passes beside the triangle */
    if (pos + neg < 3)
      return 1; /* through an edge or a corner */
    /* from behind an outward triangle (tr_orient3d_p < 0 there: the side opposite to
     * where tetrec's positive tets have their fourth corner) pq leaves the solid */
    n += sp < 0 ? 1 : -1;
  }
  *w = n;
  return 0;
}

/* The winding number of the soup at p (box: the soup's box), or INT32_MIN when p lies on
 * one of its triangles. */
static int winding(const tr_plc *s, const box3 *tbox, const box3 *box, const double *p)
{
  double span = 0;
  for (int k = 0; k < 3; k++)
    span = fmax(span, box->hi[k] - box->lo[k]);
  for (int tries = 0; tries < 64; tries++) {
    double q[3] = {box->hi[0] + span * (1 + unit()), p[1] + span * (unit() - 0.5),
                   p[2] + span * (unit() - 0.5)};
    int w = 0, r = winding_along(s, tbox, p, q, &w);
    if (r == 0)
      return w;
    if (r == 2)
      return INT32_MIN;
  }
  EXPECT(0, "no segment from (%.17g %.17g %.17g) misses every edge in 64 tries", p[0], p[1],
         p[2]);
  return INT32_MIN;
}

/* Whether some of m's nt tets holds p (closed tets, exactly). */
static int in_mesh(const tr_mesh *m, uint32_t nt, const box3 *tetbox, const double *p)
{
  tr_point P = tr_pt_d(p);
  const uint32_t *tv = tr_mesh_tets(m);
  box3 pb = point_box(&P, 1);
  for (uint32_t t = 0; t < nt; t++) {
    if (!boxes_meet(&pb, tetbox + t))
      continue;
    tr_point c[4];
    for (int i = 0; i < 4; i++)
      c[i] = tr_mesh_point(m, tv[4 * (size_t)t + i]);
    int inside = 1;
    for (int i = 0; i < 4 && inside; i++) {
      tr_point d[4] = {c[0], c[1], c[2], c[3]};
      d[i] = P;
      inside = tr_orient3d_p(&d[0], &d[1], &d[2], &d[3]) >= 0;
    }
    if (inside)
      return 1;
  }
  return 0;
}

typedef struct {
  uint32_t v[3];
} face3;

static int cmp_face(const void *x, const void *y)
{
  const face3 *a = x, *b = y;
  for (int k = 0; k < 3; k++)
    if (a->v[k] != b->v[k])
      return a->v[k] < b->v[k] ? -1 : 1;
  return 0;
}

/* Exact points made while splitting a face, freed together. */
typedef struct {
  tr_qpoint **q;
  size_t n, cap;
} qpool;

static tr_qpoint *pool_new(qpool *pl)
{
  if (pl->n == pl->cap) {
    pl->cap = pl->cap ? 2 * pl->cap : 16;
    pl->q = realloc(pl->q, sizeof *pl->q * pl->cap);
  }
  tr_qpoint *q = malloc(sizeof *q);
  tr_qpoint_init(q);
  return pl->q[pl->n++] = q;
}

static void pool_free(qpool *pl)
{
  for (size_t i = 0; i < pl->n; i++) {
    tr_qpoint_clear(pl->q[i]);
    free(pl->q[i]);
  }
  free(pl->q);
  memset(pl, 0, sizeof *pl);
}

/* Whether the convex polygon c[0..n-1] (positive area, in the plane of the triangles
 * t[0..nt-1], projected along axis `drop`) lies in their union. If no triangle holds
 * it whole, a triangle's edge line that has corners strictly on both sides splits it
 * and both halves are asked; when no edge line of any triangle crosses it, it lies in
 * a triangle or meets none's interior, and then (not held whole) is not covered. Each
 * split is by a line that cannot split either half again, so this ends. Exact. */
static int covered(const tr_point *c, int n, int drop, const tr_point (*t)[3], int nt,
                   qpool *pl)
{
  for (int i = 0; i < nt; i++) {
    int st = tr_orient2d_proj_p(&t[i][0], &t[i][1], &t[i][2], drop), in = 1;
    for (int k = 0; k < n && in; k++)
      for (int e = 0; e < 3 && in; e++)
        in = st * tr_orient2d_proj_p(&t[i][e], &t[i][(e + 1) % 3], &c[k], drop) >= 0;
    if (in)
      return 1;
  }
  int *sg = malloc(sizeof *sg * (size_t)n);
  for (int i = 0; i < nt; i++)
    for (int e = 0; e < 3; e++) {
      const tr_point *a = &t[i][e], *b = &t[i][(e + 1) % 3];
      int pos = 0, neg = 0;
      for (int k = 0; k < n; k++) {
        sg[k] = tr_orient2d_proj_p(a, b, &c[k], drop);
        pos += sg[k] > 0;
        neg += sg[k] < 0;
      }
      if (!pos || !neg)
        continue;
      tr_point *half[2] = {malloc(sizeof **half * (size_t)(n + 2)),
                           malloc(sizeof **half * (size_t)(n + 2))};
      int nh[2] = {0, 0};
      for (int k = 0; k < n; k++) {
        int k1 = (k + 1) % n;
        if (sg[k] >= 0)
          half[0][nh[0]++] = c[k];
        if (sg[k] <= 0)
          half[1][nh[1]++] = c[k];
        if (sg[k] * sg[k1] < 0) {
          tr_qpoint *q = pool_new(pl);
          int ok = tr_construct_line_line(a, b, &c[k], &c[k1], q) == 0;
          EXPECT(ok, "splitting a face: the lines do not meet");
          half[0][nh[0]++] = half[1][nh[1]++] = tr_pt_q(q);
        }
      }
      int r = covered(half[0], nh[0], drop, t, nt, pl) && covered(half[1], nh[1], drop, t, nt, pl);
      free(half[0]);
      free(half[1]);
      free(sg);
      return r;
    }
  free(sg);
  return 0;
}

/* Whether the face c[0..2] lies in the union of the input triangles in its plane. */
static int face_on_input(const tr_plc *s, const box3 *tbox, const tr_point *c)
{
  box3 fb = point_box(c, 3);
  int drop = 0;
  while (drop < 3 && tr_orient2d_proj_p(&c[0], &c[1], &c[2], drop) == 0)
    drop++;
  if (drop == 3)
    return 0; /* a face of no area */
  tr_point (*t)[3] = NULL;
  int nt = 0, cap = 0;
  for (uint32_t i = 0; i < s->ntris; i++) {
    if (!boxes_meet(&fb, tbox + i))
      continue;
    const uint32_t *v = s->tris + 3 * (size_t)i;
    tr_point a = soup_pt(s, v[0]), b = soup_pt(s, v[1]), d = soup_pt(s, v[2]);
    if (tr_orient3d_p(&c[0], &c[1], &c[2], &a) || tr_orient3d_p(&c[0], &c[1], &c[2], &b) ||
        tr_orient3d_p(&c[0], &c[1], &c[2], &d) || !tr_orient2d_proj_p(&a, &b, &d, drop))
      continue;
    if (nt == cap)
      t = realloc(t, sizeof *t * (size_t)(cap = cap ? 2 * cap : 8));
    t[nt][0] = a, t[nt][1] = b, t[nt][2] = d;
    nt++;
  }
  qpool pl = {0};
  int r = nt && covered(c, 3, drop, (const tr_point(*)[3])t, nt, &pl);
  pool_free(&pl);
  free(t);
  return r;
}

/* Every face of one tet lies in the union of the input triangles in its plane (in one
 * of them, or across several where the surface swaps turned a diagonal); returns the
 * count. */
static uint32_t check_boundary(const char *name, const tr_plc *s, const box3 *tbox,
                               const tr_mesh *m)
{
  uint32_t nt = tr_mesh_num_tets(m);
  const uint32_t *tv = tr_mesh_tets(m);
  face3 *f = malloc(sizeof *f * 4 * (size_t)(nt ? nt : 1));
  for (uint32_t t = 0; t < nt; t++)
    for (int k = 0; k < 4; k++) {
      face3 *x = f + 4 * (size_t)t + k;
      for (int i = 0, j = 0; i < 4; i++)
        if (i != k)
          x->v[j++] = tv[4 * (size_t)t + i];
      tr_sort3(x->v);
    }
  qsort(f, 4 * (size_t)nt, sizeof *f, cmp_face);
  uint32_t nb = 0, bad = 0;
  for (size_t i = 0; i < 4 * (size_t)nt;) {
    size_t j = i + 1;
    while (j < 4 * (size_t)nt && !cmp_face(f + i, f + j))
      j++;
    EXPECT(j - i <= 2, "%s: face (%u %u %u) in %zu tets", name, f[i].v[0], f[i].v[1],
           f[i].v[2], j - i);
    if (j - i == 1) {
      nb++;
      tr_point c[3];
      for (int k = 0; k < 3; k++)
        c[k] = tr_mesh_point(m, f[i].v[k]);
      if (!face_on_input(s, tbox, c) && bad++ < 5)
        EXPECT(0, "%s: boundary face (%u %u %u) lies on no input triangle", name, f[i].v[0],
               f[i].v[1], f[i].v[2]);
    }
    i = j;
  }
  EXPECT(bad == 0, "%s: %u boundary faces not on the input", name, bad);
  free(f);
  return nb;
}

/* Meshes soup s under opt (resolve on, exact points kept) and checks samples and the
 * boundary. */
static void check_one(const char *name, const tr_plc *s, tr_options opt, int nsamples)
{
  opt.resolve = opt.resolve ? opt.resolve : 1;
  opt.keep_exact = 1;
  tm_run r;
  tr_mesh *m = tm_mesh(&r, name, s, &opt, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T);
  if (!m) {
    tm_free(&r);
    return;
  }
  box3 *tbox = malloc(sizeof *tbox * (s->ntris ? s->ntris : 1));
  box3 box = {{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
  for (uint32_t t = 0; t < s->ntris; t++) {
    tr_point c[3];
    for (int k = 0; k < 3; k++)
      c[k] = soup_pt(s, s->tris[3 * (size_t)t + k]);
    tbox[t] = point_box(c, 3);
    for (int k = 0; k < 3; k++) {
      box.lo[k] = fmin(box.lo[k], tbox[t].lo[k]);
      box.hi[k] = fmax(box.hi[k], tbox[t].hi[k]);
    }
  }
  uint32_t nt = tr_mesh_num_tets(m);
  const uint32_t *tv = tr_mesh_tets(m);
  box3 *tetbox = malloc(sizeof *tetbox * (nt ? nt : 1));
  for (uint32_t t = 0; t < nt; t++) {
    tr_point c[4];
    for (int i = 0; i < 4; i++)
      c[i] = tr_mesh_point(m, tv[4 * (size_t)t + i]);
    tetbox[t] = point_box(c, 4);
  }
  uint32_t in = 0, out = 0, on = 0, wrong = 0;
  for (int i = 0; i < 2 * nsamples; i++) {
    double p[3];
    if (i < nsamples) { /* over the box and a little beyond */
      for (int k = 0; k < 3; k++) {
        double w = box.hi[k] - box.lo[k];
        p[k] = box.lo[k] - 0.05 * w + 1.1 * w * unit();
      }
    } else { /* next to a triangle: a corner combination rounded to doubles, moved by a
                * millionth of the box or not at all (then on it or next to it) */
      uint32_t t = (uint32_t)(unit() * s->ntris);
      const double *a = s->xyz + 3 * (size_t)s->tris[3 * (size_t)t],
                   *b = s->xyz + 3 * (size_t)s->tris[3 * (size_t)t + 1],
                   *c = s->xyz + 3 * (size_t)s->tris[3 * (size_t)t + 2];
      double u = unit(), v = unit();
      if (u + v > 1)
        u = 1 - u, v = 1 - v;
      double move = i % 2 ? 1e-6 : 0;
      for (int k = 0; k < 3; k++)
        p[k] = a[k] + u * (b[k] - a[k]) + v * (c[k] - a[k]) +
               move * (box.hi[k] - box.lo[k]) * (unit() - 0.5);
    }
    int w = winding(s, tbox, &box, p);
    if (w == INT32_MIN) {
      on++;
      continue;
    }
    int inside = in_mesh(m, nt, tetbox, p);
    in += w >= 1;
    out += w < 1;
    if (inside != (w >= 1) && wrong++ < 5)
      EXPECT(0, "%s: (%.17g %.17g %.17g): winding number %d, %s the mesh", name, p[0], p[1],
             p[2], w, inside ? "in" : "not in");
  }
  EXPECT(wrong == 0, "%s: %u of %d samples on the wrong side", name, wrong, 2 * nsamples);
  EXPECT(in > 0 && out > 0, "%s: samples %u inside and %u outside: both kinds wanted", name,
         in, out);
  uint32_t nb = check_boundary(name, s, tbox, m);
  printf("%s: %u tets, %u boundary faces on the input; samples: %u in the solid, %u outside, "
         "%u on the surface; %u on the wrong side\n",
         name, nt, nb, in, out, on, wrong);
  free(tbox);
  free(tetbox);
  tm_free(&r);
}

static int nsamples(void)
{
  const char *e = getenv("SAMPLES");
  int n = e ? atoi(e) : 400;
  return n > 0 ? n : 400;
}

static void check_file(const char *path, int n, int quality)
{
  tr_plc *s = tm_read(path);
  char name[1100];
  tr_options opt = tm_options();
  snprintf(name, sizeof name, "%s", path);
  check_one(name, s, opt, n);
  if (quality) {
    opt.quality_ratio = 1.414;
    snprintf(name, sizeof name, "%s --quality 1.414", path);
    check_one(name, s, opt, n / 2);
    opt.quality_ratio = 0;
  }
  opt.keep_surface = 1;
  snprintf(name, sizeof name, "%s --keep-surface", path);
  check_one(name, s, opt, n / 2);
  tr_plc_destroy(s);
}

static void t_corpus(const char *data)
{
  /* the self-intersecting ones (the grid and flat-doubles cases are tetrec resolve's) */
  static const char *files[] = {
      "resolve_cubes2.off",    "resolve_cubes2_rot.off",   "resolve_cubes2_ulp.off",
      "resolve_cubes3.off",    "resolve_cubes3_rot.off",   "resolve_cubes3_ulp.off",
      "resolve_dupshell.off",  "resolve_dupshell_rot.off", "resolve_dupshell_ulp.off",
      "resolve_coplanar.off",  "resolve_coplanar_rot.off", "resolve_coplanar_ulp.off",
      "resolve_spheres.off",   "resolve_spheres_rot.off",  "resolve_spheres_ulp.off",
      "resolve_corner_cut.off"};
  for (size_t i = 0; i < sizeof files / sizeof *files; i++) {
    char p[1024];
    snprintf(p, sizeof p, "%s/%s", data, files[i]);
    /* refinement on the turned and moved copies makes meshes of 10^4 tets on exact
     * corners, minutes of exact predicates here: the unmoved ones stand for them */
    check_file(p, nsamples(), !strstr(files[i], "_rot") && !strstr(files[i], "_ulp"));
  }
  /* the convention of winding_along's sign: the unit cube's centre has winding number 1 */
  char p[1024];
  snprintf(p, sizeof p, "%s/resolve_cube.off", data);
  tr_plc *cube = tm_read(p);
  box3 tbox[12], box = {{0, 0, 0}, {1, 1, 1}};
  for (uint32_t t = 0; t < cube->ntris && t < 12; t++) {
    tr_point c[3];
    for (int k = 0; k < 3; k++)
      c[k] = soup_pt(cube, cube->tris[3 * (size_t)t + k]);
    tbox[t] = point_box(c, 3);
  }
  double centre[3] = {0.5, 0.5, 0.5}, outside[3] = {1.5, 0.5, 0.5}, face[3] = {0.5, 0.5, 0};
  EXPECT(cube->ntris == 12 && winding(cube, tbox, &box, centre) == 1 &&
             winding(cube, tbox, &box, outside) == 0 &&
             winding(cube, tbox, &box, face) == INT32_MIN,
         "the unit cube: winding numbers 1 at its centre, 0 outside, none on a face");
  tr_plc_destroy(cube);
}

int main(int argc, char **argv)
{
  if (argc > 2 && !strcmp(argv[1], "files")) {
    for (int i = 2; i < argc; i++)
      check_file(argv[i], nsamples(), 1);
    return failures != 0;
  }
  static const texpect_case cases[] = {{"corpus", NULL, t_corpus}};
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
