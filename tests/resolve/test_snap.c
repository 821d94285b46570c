/* `tetrec resolve` (src/resolve/snap.c): the solid's boundary rounded to doubles (or
 * floats) and free of intersections. Every result goes through checks independent of
 * how it was made:
 *  - its vertices are distinct values (floats when asked);
 *  - the self-intersection test finds no improper pair, and tr_plc_validate accepts it
 *    (closed, no zero-area triangle, no crossing) without repairing anything;
 *  - its exact volume (tr_input_volume6) is within the rounding's reach of the solid's:
 *    |difference| <= 6 * 4 * area * move_bound (plus the error of summing the exact
 *    pieces' determinants in doubles when the solid has rational corners), and equal to
 *    tr_solid_volume6 when nothing was rounded; hand-counted where corners are doubles.
 * Usage: test_snap CASE tests/data */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "input/validate.h"
#include "resolve/resolve.h"
#include "resolve/snap.h"
#include "../pipeline/texpect.h"
#include "../pipeline/tmesh.h"

static tr_plc *data_file(const char *data, const char *name)
{
  char p[1024];
  snprintf(p, sizeof p, "%s/%s", data, name);
  return tm_read(p);
}

/* 6 times the volume of the solid of the soup p (winding number >= 1): *approx within
 * *err of it (each boundary piece's determinant exact, then rounded and summed in
 * doubles); and exact in v6 when every corner of the boundary is a double (exact sums
 * over rational corners grow a denominator that takes minutes: resolve.h). Returns 1 iff
 * v6 was set. */
typedef struct {
  int exact; /* v6 is set */
  mpq_t v6;
  double approx, err;
} vol6;

static int solid_volume6(const tr_plc *p, mpq_t v6, double *approx, double *err)
{
  tr_arrangement a;
  tr_solid s;
  memset(&s, 0, sizeof s);
  tr_status st = tr_arrangement_build(p, &a);
  if (st == TR_OK)
    st = tr_solid_classify(p, &a, 0, &s);
  EXPECT(st == TR_OK, "the exact solid: %s", tr_last_error());
  int doubles = 1;
  double sum = 0, comp = 0, mag = 0;
  uint32_t n = 0;
  mpq_t m[3][3], t, u, d;
  for (int i = 0; i < 9; i++)
    mpq_init(m[i / 3][i % 3]);
  mpq_inits(t, u, d, NULL);
  for (uint32_t i = 0; st == TR_OK && i < a.npieces; i++) {
    if (s.keep[i] != TR_SOLID_KEEP && s.keep[i] != TR_SOLID_FLIP)
      continue;
    for (int k = 0; k < 3; k++) {
      tr_point q = tr_arr_point(&a, p, a.pieces[i].v[k]);
      if (q.q && (q.q->err[0] != 0 || q.q->err[1] != 0 || q.q->err[2] != 0))
        doubles = 0;
      for (int c = 0; c < 3; c++)
        tr_point_get_q(&q, c, m[k][c]);
    }
    /* det[a; b; c] by cofactors along the first row */
    mpq_set_ui(d, 0, 1);
    for (int c = 0; c < 3; c++) {
      int c1 = (c + 1) % 3, c2 = (c + 2) % 3;
      mpq_mul(t, m[1][c1], m[2][c2]);
      mpq_mul(u, m[1][c2], m[2][c1]);
      mpq_sub(t, t, u);
      mpq_mul(t, t, m[0][c]);
      mpq_add(d, d, t);
    }
    double det = mpq_get_d(d); /* within an ulp of the piece's exact determinant */
    if (s.keep[i] == TR_SOLID_FLIP)
      det = -det;
    /* Neumaier's compensated sum */
    double y = sum + det;
    comp += fabs(sum) >= fabs(det) ? (sum - y) + det : (det - y) + sum;
    sum = y;
    mag += fabs(det);
    n++;
  }
  *approx = sum + comp;
  *err = (4.0 * n + 8) * 0x1p-52 * mag;
  int exact = st == TR_OK && doubles;
  if (exact)
    EXPECT(tr_solid_volume6(p, &a, &s, v6) == TR_OK, "volume: %s", tr_last_error());
  for (int i = 0; i < 9; i++)
    mpq_clear(m[i / 3][i % 3]);
  mpq_clears(t, u, d, NULL);
  tr_solid_free(&s);
  tr_arrangement_free(&a);
  return exact;
}

static int cmp_xyz(const void *ctx, uint32_t a, uint32_t b)
{
  const double *x = ctx, *p = x + 3 * (size_t)a, *q = x + 3 * (size_t)b;
  for (int k = 0; k < 3; k++)
    if (p[k] != q[k])
      return p[k] < q[k] ? -1 : 1;
  return 0;
}

static void vol6_of(const tr_plc *p, vol6 *v)
{
  mpq_init(v->v6);
  v->exact = solid_volume6(p, v->v6, &v->approx, &v->err);
}

/* The checks above on out, the result for the soup in; v = the solid's 6V. */
static void check_out(const char *name, const tr_plc *out, const tr_snap_info *si,
                      int to_float, const vol6 *v)
{
  uint32_t *ord = malloc(sizeof *ord * (out->npoints + 1));
  for (uint32_t i = 0; i < out->npoints; i++)
    ord[i] = i;
  tr_sort_ids(ord, out->npoints, cmp_xyz, out->xyz);
  for (uint32_t i = 1; i < out->npoints; i++)
    EXPECT(cmp_xyz(out->xyz, ord[i - 1], ord[i]) != 0, "%s: vertices %u and %u are one point",
           name, ord[i - 1], ord[i]);
  free(ord);
  for (uint32_t i = 0; to_float && i < 3 * out->npoints; i++)
    EXPECT((double)(float)out->xyz[i] == out->xyz[i], "%s: coordinate %u is no float", name, i);
  EXPECT(out->ntris == si->ntris && out->npoints == si->nverts, "%s: counts %u %u, info %u %u",
         name, out->npoints, out->ntris, si->nverts, si->ntris);
  /* the boundary alone (internal facets are the last ninternal triangles) */
  tr_plc *b = NULL;
  tr_plc_create(&b);
  EXPECT(tr_plc_set(b, out->xyz, out->npoints, out->tris, out->ntris - si->ninternal, NULL) ==
             TR_OK, "%s: copy", name);
  uint32_t *pairs = NULL;
  size_t np = 0;
  EXPECT(tr_input_self_intersection_pairs(out, TR_SELFINT_ALL_PAIRS, &pairs, &np) == TR_OK &&
             np == 0, "%s: %zu improper pairs (the first: %u and %u)", name, np,
         np ? pairs[0] : 0, np ? pairs[1] : 0);
  free(pairs);
  mpq_t w, d;
  mpq_inits(w, d, NULL);
  EXPECT(tr_input_volume6(b, w) == TR_OK, "%s: volume", name);
  double wd = mpq_get_d(w), dv6 = wd - v->approx;
  if (v->exact) {
    mpq_sub(d, w, v->v6);
    dv6 = mpq_get_d(d);
  }
  double area = 0;
  for (uint32_t t = 0; t < b->ntris; t++) {
    const double *p = b->xyz + 3 * b->tris[3 * t], *q = b->xyz + 3 * b->tris[3 * t + 1],
                 *r = b->xyz + 3 * b->tris[3 * t + 2];
    double u[3], v[3];
    for (int k = 0; k < 3; k++) {
      u[k] = q[k] - p[k];
      v[k] = r[k] - p[k];
    }
    double c0 = u[1] * v[2] - u[2] * v[1], c1 = u[2] * v[0] - u[0] * v[2],
           c2 = u[0] * v[1] - u[1] * v[0];
    area += 0.5 * sqrt(c0 * c0 + c1 * c1 + c2 * c2);
  }
  if (si->nrounded == 0)
    EXPECT(v->exact && mpq_sgn(d) == 0, "%s: nothing rounded, yet 6V %.17g differs from the "
           "solid's by %.3g", name, wd, dv6);
  else
    EXPECT(fabs(dv6) <= 24 * area * si->move_bound * (1 + 1e-9) +
                            (v->exact ? 0 : v->err + fabs(wd) * 0x1p-52),
           "%s: 6V differs from the solid's by %.3g, beyond 24 * area %.6g * move %.3g", name,
           dv6, area, si->move_bound);
  /* what tetrec mesh validates first: closed, no zero-area triangle, no crossing, and
   * nothing to repair (the boundary is oriented outward) */
  tr_status st = tr_plc_validate(b, NULL);
  EXPECT(st == TR_OK, "%s: validation: %s", name, tr_last_error());
  EXPECT(st != TR_OK || !strstr(tr_plc_report(b), "revers"), "%s: validation repaired: %s",
         name, tr_plc_report(b));
  mpq_clears(w, d, NULL);
  tr_plc_destroy(b);
}

/* in -> (mode, to_float): rounds, result checked; returns the result (free it). */
static tr_plc *run(const char *name, const tr_plc *in, int mode, int to_float, int max_rounds,
                   tr_snap_info *si, const vol6 *v)
{
  tr_plc *out = NULL;
  tr_status st = tr_resolve_snap(in, mode, to_float, max_rounds, &out, si);
  EXPECT(st == TR_OK && out, "%s: %s: %s", name, tr_status_name(st), tr_last_error());
  if (st != TR_OK)
    return NULL;
  EXPECT(si->left.pairs == 0 && si->left.zero == 0 && si->left.duplicate == 0 &&
             si->left.open == 0, "%s: defects left in the info", name);
  check_out(name, out, si, to_float, v);
  return out;
}

/* The corpus (tests/data/resolve_*.off, tests/resolve/gen_data.py): each as doubles and
 * as floats, with and without internal facets. Hand-counted volumes where every corner
 * of the solid is a double. */
static void t_corpus(const char *data)
{
  static const struct {
    const char *name;
    long num, den; /* 6V, 0: not hand-counted (tests/cgal checks it) */
    int rational;  /* 1: the solid has corners that are no doubles, 0: none, -1: either
                      (moved by an ulp, a face's diagonal crosses a face an ulp away at a
                      rational point or not) */
  } files[] = {
    {"cubes2", 45, 4, 0},   {"cubes2_rot", 0, 1, 1},   {"cubes2_ulp", 0, 1, -1},
    {"cubes3", 267, 16, 0}, {"cubes3_rot", 0, 1, 1},   {"cubes3_ulp", 0, 1, -1},
    {"dupshell", 6, 1, 0},  {"dupshell_rot", 0, 1, 0}, {"dupshell_ulp", 0, 1, -1},
    {"coplanar", 15, 1, 0}, {"coplanar_rot", 0, 1, 1}, {"coplanar_ulp", 0, 1, -1},
    {"spheres", 0, 1, 1},   {"spheres_rot", 0, 1, 1},  {"spheres_ulp", 0, 1, 1},
  };
  for (size_t i = 0; i < sizeof files / sizeof *files; i++) {
    char fn[256];
    snprintf(fn, sizeof fn, "resolve_%s.off", files[i].name);
    tr_plc *in = data_file(data, fn);
    vol6 v;
    vol6_of(in, &v);
    if (files[i].num) {
      mpq_t h;
      mpq_init(h);
      mpq_set_si(h, files[i].num, (unsigned long)files[i].den);
      EXPECT(v.exact && mpq_equal(h, v.v6), "%s: the exact solid's 6V %.17g, counted by hand "
             "%ld/%ld", fn, v.approx, files[i].num, files[i].den);
      mpq_clear(h);
    }
    for (int mode = 1; mode <= 2; mode++)
      for (int fl = 0; fl <= 1; fl++) {
        char name[300];
        snprintf(name, sizeof name, "%s mode %d %s", fn, mode, fl ? "floats" : "doubles");
        tr_snap_info si;
        if (mode == 2 && !strcmp(files[i].name, "coplanar_rot")) {
          /* the limit (docs/resolve.md): the contact faces, coplanar before the rotation,
           * are internal facets that the rounding leaves nearly coplanar; they cross each
           * other along long cuts, and each round multiplies them. Said, not hung. */
          tr_plc *out = NULL;
          tr_status st = tr_resolve_snap(in, mode, fl, TR_SNAP_ROUNDS, &out, &si);
          EXPECT(st == TR_ERR_SELF_INTERSECT && !out && strstr(tr_last_error(), "grows"),
                 "%s: %s: %s", name, tr_status_name(st), tr_last_error());
          continue;
        }
        tr_plc *out = run(name, in, mode, fl, TR_SNAP_ROUNDS, &si, &v);
        if (!out)
          continue;
        if (!fl && files[i].rational >= 0)
          EXPECT(files[i].rational ? si.nrounded > 0 : si.nrounded == 0,
                 "%s: %u vertices rounded", name, si.nrounded);
        /* near-degenerate by construction (the rotated cubes' edges were on each other's
         * faces): up to 4 rounds measured, the default allows 8 */
        EXPECT(si.rounds <= 4, "%s: %d rounds (at most 4 when measured)", name, si.rounds);
        tr_plc_destroy(out);
      }
    mpq_clear(v.v6);
    tr_plc_destroy(in);
  }
}

/* The two overlapping cubes with internal facets: the boundary's 36 triangles and the
 * 12 internal ones after them (test_solid counts the same pieces), the boundary the
 * same surface as without them. */
static void t_internal(const char *data)
{
  tr_plc *in = data_file(data, "resolve_cubes2.off");
  tr_plc *a = NULL, *b = NULL;
  tr_snap_info sa, sb;
  EXPECT(tr_resolve_snap(in, 1, 0, TR_SNAP_ROUNDS, &a, &sa) == TR_OK, "union: %s",
         tr_last_error());
  EXPECT(tr_resolve_snap(in, 2, 0, TR_SNAP_ROUNDS, &b, &sb) == TR_OK, "internal: %s",
         tr_last_error());
  if (a && b) {
    EXPECT(sa.ntris == 36 && sa.ninternal == 0, "union: %u triangles, %u internal", sa.ntris,
           sa.ninternal);
    EXPECT(sb.ntris == 48 && sb.ninternal == 12, "internal: %u triangles, %u internal",
           sb.ntris, sb.ninternal);
    /* the same boundary, corner for corner */
    int same = 1;
    for (uint32_t t = 0; t < 36; t++)
      for (int k = 0; k < 3; k++)
        for (int c = 0; c < 3; c++)
          same &= a->xyz[3 * a->tris[3 * t + k] + c] == b->xyz[3 * b->tris[3 * t + k] + c];
    EXPECT(same, "the boundary differs with internal facets");
    /* the internal facets bound the common cube [1/2, 1]^3, each oriented as its first
     * source: 6V = +-3/4 */
    tr_plc *inner = NULL;
    tr_plc_create(&inner);
    tr_plc_set(inner, b->xyz, b->npoints, b->tris + 3 * 36, 12, NULL);
    mpq_t v;
    mpq_init(v);
    tr_input_volume6(inner, v);
    mpq_abs(v, v);
    EXPECT(mpq_get_d(v) == 0.75, "internal facets: |6V| %.17g, expected 3/4", mpq_get_d(v));
    mpq_clear(v);
    tr_plc_destroy(inner);
  }
  tr_plc_destroy(a);
  tr_plc_destroy(b);
  tr_plc_destroy(in);
}

/* Tets at 2^52 + small integers, where an ulp is 1 and every crossing rounds a whole unit:
 * the rounded surface crosses itself again and takes 3 rounds (measured), each one
 * checked. Another soup of the same kind cycles (a rounded corner makes a crossing whose
 * own rounding undoes it): an error naming the pair, nothing returned. */
static void t_grid(const char *data)
{
  tr_plc *in = data_file(data, "resolve_grid_rounds.off");
  vol6 v;
  vol6_of(in, &v);
  tr_snap_info si;
  tr_plc *out = run("grid", in, 1, 0, TR_SNAP_ROUNDS, &si, &v);
  EXPECT(si.rounds == 3 && si.npairs_later > 0, "grid: %d rounds, %llu pairs made by rounding",
         si.rounds, (unsigned long long)si.npairs_later);
  tr_plc_destroy(out);
  /* with 2 rounds allowed it is an error */
  out = NULL;
  tr_status st = tr_resolve_snap(in, 1, 0, 2, &out, &si);
  EXPECT(st == TR_ERR_SELF_INTERSECT && !out && strstr(tr_last_error(), "after 2 rounds"),
         "grid in 2 rounds: %s: %s", tr_status_name(st), tr_last_error());
  tr_plc_destroy(out);
  mpq_clear(v.v6);
  tr_plc_destroy(in);
  in = data_file(data, "resolve_grid_cycle.off");
  out = NULL;
  st = tr_resolve_snap(in, 1, 0, TR_SNAP_ROUNDS, &out, &si);
  EXPECT(st == TR_ERR_SELF_INTERSECT && !out && strstr(tr_last_error(), "triangles") &&
             strstr(tr_last_error(), "nothing written"),
         "cycle: %s: %s", tr_status_name(st), tr_last_error());
  EXPECT(si.left.pairs > 0, "cycle: no pair left in the info");
  tr_plc_destroy(out);
  tr_plc_destroy(in);
}

/* The same input, the same output, byte for byte. */
static void t_determinism(const char *data)
{
  tr_plc *in = data_file(data, "resolve_spheres_rot.off");
  tr_plc *a = NULL, *b = NULL;
  tr_snap_info sa, sb;
  EXPECT(tr_resolve_snap(in, 2, 0, TR_SNAP_ROUNDS, &a, &sa) == TR_OK &&
             tr_resolve_snap(in, 2, 0, TR_SNAP_ROUNDS, &b, &sb) == TR_OK,
         "determinism: %s", tr_last_error());
  if (a && b)
    EXPECT(a->npoints == b->npoints && a->ntris == b->ntris &&
               !memcmp(a->xyz, b->xyz, sizeof *a->xyz * 3 * a->npoints) &&
               !memcmp(a->tris, b->tris, sizeof *a->tris * 3 * a->ntris) &&
               !memcmp(a->tri_marker, b->tri_marker, sizeof *a->tri_marker * a->ntris),
           "two runs differ");
  tr_plc_destroy(a);
  tr_plc_destroy(b);
  tr_plc_destroy(in);
}

/* Soups without a solid: errors naming why, nothing returned. */
static void t_errors(const char *data)
{
  tr_plc *cube = data_file(data, "resolve_cube.off");
  tr_plc *p = NULL, *out = NULL;
  tr_snap_info si;
  /* open: the last triangle left out */
  tr_plc_create(&p);
  tr_plc_set(p, cube->xyz, cube->npoints, cube->tris, cube->ntris - 1, NULL);
  tr_status st = tr_resolve_snap(p, 1, 0, TR_SNAP_ROUNDS, &out, &si);
  EXPECT(st == TR_ERR_OPEN && !out, "open: %s: %s", tr_status_name(st), tr_last_error());
  tr_plc_destroy(p);
  /* inside out */
  uint32_t *t = malloc(sizeof *t * 3 * cube->ntris);
  for (uint32_t i = 0; i < cube->ntris; i++) {
    t[3 * i] = cube->tris[3 * i];
    t[3 * i + 1] = cube->tris[3 * i + 2];
    t[3 * i + 2] = cube->tris[3 * i + 1];
  }
  tr_plc_create(&p);
  tr_plc_set(p, cube->xyz, cube->npoints, t, cube->ntris, NULL);
  st = tr_resolve_snap(p, 1, 0, TR_SNAP_ROUNDS, &out, &si);
  EXPECT(st == TR_ERR_INPUT && !out && strstr(tr_last_error(), "empty"), "inside out: %s: %s",
         tr_status_name(st), tr_last_error());
  tr_plc_destroy(p);
  free(t);
  st = tr_resolve_snap(cube, 3, 0, TR_SNAP_ROUNDS, &out, &si);
  EXPECT(st == TR_ERR_USAGE && !out, "mode 3: %s", tr_status_name(st));
  st = tr_resolve_snap(cube, 1, 0, 0, &out, &si);
  EXPECT(st == TR_ERR_USAGE && !out, "0 rounds: %s", tr_status_name(st));
  /* segments would be lost */
  uint32_t seg[2] = {0, 7};
  tr_plc_add_segments(cube, seg, 1);
  st = tr_resolve_snap(cube, 1, 0, TR_SNAP_ROUNDS, &out, &si);
  EXPECT(st == TR_ERR_UNSUPPORTED && !out && strstr(tr_last_error(), "segments"),
         "segments: %s: %s", tr_status_name(st), tr_last_error());
  tr_plc_destroy(cube);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
    {"corpus", NULL, t_corpus},
    {"internal", NULL, t_internal},
    {"grid", NULL, t_grid},
    {"determinism", NULL, t_determinism},
    {"errors", NULL, t_errors},
  };
  int r = texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
  tr_thread_cleanup();
  return r;
}
