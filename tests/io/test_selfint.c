/* Self-intersection of the input surface (src/input/selfint.c): the exact rules for two
 * triangles (improper contact at a vertex or an edge), coplanar neighbours against the
 * segment-triangle classifier, and the grid sweep, all-pairs and shortcut paths against
 * each other. Each case checks one property named by its meson test.
 * Usage: test_selfint CASE */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "core/plc.h"
#include "input/validate.h"
#include "predicates.h"
#include "qpoint.h"
#include "tetrec.h"
#include "../pipeline/texpect.h"

static tr_status check_pair(const double *xyz, uint32_t n, const uint32_t *tris)
{
  tr_plc *p;
  tr_plc_create(&p);
  tr_status s = tr_plc_set(p, xyz, n, tris, 2, NULL);
  tr_options o;
  tr_options_default(&o);
  o.allow_open = 1;
  if (s == TR_OK)
    s = tr_plc_validate(p, &o);
  tr_plc_destroy(p);
  return s;
}

/* Grid point (u, v) onto the plane spanned by (3, 1, 2) and (-1, 2, 5) through
 * (7, -4, 1): exact in doubles for small integers, and tilted against every axis. */
static void onto_tilted_plane(long long u, long long v, double *x)
{
  x[0] = 7 + 3 * (double)u - (double)v;
  x[1] = -4 + (double)u + 2 * (double)v;
  x[2] = 1 + 2 * (double)u + 5 * (double)v;
}

/* Exact improper-intersection rules for two triangles. */
static void t_selfint(void)
{
  /* shared edge, coplanar, opposite sides: allowed */
  double a[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0};
  uint32_t ta[] = {0, 1, 2, 1, 0, 3};
  EXPECT(check_pair(a, 4, ta) == TR_OK, "coplanar neighbours across an edge: %s", tr_last_error());
  /* shared edge, coplanar, same side (overlap) */
  double b[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.25, 0.25, 0};
  uint32_t tb[] = {0, 1, 2, 1, 0, 3};
  EXPECT(check_pair(b, 4, tb) == TR_ERR_SELF_INTERSECT, "overlap across a shared edge");
  /* shared vertex only, crossing through the other's interior */
  double c[] = {0, 0, 0, 2, 0, 0, 0, 2, 0, 1, 1, -1, 0.2, 0.2, 1};
  uint32_t tc[] = {0, 1, 2, 0, 3, 4};
  EXPECT(check_pair(c, 5, tc) == TR_ERR_SELF_INTERSECT, "piercing triangles sharing a vertex");
  /* shared vertex only, non-coplanar, touching only there: allowed */
  double d[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 1};
  uint32_t td[] = {0, 1, 2, 0, 3, 4};
  EXPECT(check_pair(d, 5, td) == TR_OK, "triangles sharing one vertex: %s", tr_last_error());
  /* T-junction: a vertex on the other's edge */
  double e[] = {0, 0, 0, 2, 0, 0, 0, 2, 0, 1, 0, 0, 1, 0, 1, 1, -1, 1};
  uint32_t te[] = {0, 1, 2, 3, 4, 5};
  EXPECT(check_pair(e, 6, te) == TR_ERR_SELF_INTERSECT, "vertex touching an edge interior");
  /* disjoint */
  double g[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1e-300, 1, 0, 1e-300, 0, 1, 1e-300};
  uint32_t tg[] = {0, 1, 2, 3, 4, 5};
  EXPECT(check_pair(g, 6, tg) == TR_OK, "parallel triangles 1e-300 apart: %s", tr_last_error());
  EXPECT(strstr(tr_last_error(), "") != NULL, "message");
  /* Coplanar pairs sharing an edge (the fast path of selfint.c) against a 2D answer
   * computed here: small integer coordinates mapped exactly onto a tilted plane. */
  uint64_t r = 0x9e3779b97f4a7c15ull;
  int improper_seen = 0, proper_seen = 0;
  for (int it = 0; it < 400; it++) {
    long long q2[4][2];
    for (int k = 0; k < 4; k++)
      for (int d = 0; d < 2; d++) {
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        q2[k][d] = (long long)(r % 11) - 5;
      }
    long long ex = q2[1][0] - q2[0][0], ey = q2[1][1] - q2[0][1];
    long long sp = ex * (q2[2][1] - q2[0][1]) - ey * (q2[2][0] - q2[0][0]);
    long long sq = ex * (q2[3][1] - q2[0][1]) - ey * (q2[3][0] - q2[0][0]);
    if (sp == 0 || sq == 0)
      continue; /* a corner on the shared line: not two triangles */
    if (q2[2][0] == q2[3][0] && q2[2][1] == q2[3][1])
      continue; /* the same triangle twice: validation merges it, a repair */
    double x[12];
    for (int k = 0; k < 4; k++)
      onto_tilted_plane(q2[k][0], q2[k][1], x + 3 * k);
    uint32_t tt[6] = {0, 1, 2, 1, 0, 3};
    int want = (sp > 0) == (sq > 0);
    tr_status st = check_pair(x, 4, tt);
    EXPECT((st == TR_ERR_SELF_INTERSECT) == want && (st == TR_OK || st == TR_ERR_SELF_INTERSECT),
           "coplanar pair %d sharing an edge (p %lld %lld, q %lld %lld): %s, want %s (%s)", it, q2[2][0], q2[2][1], q2[3][0], q2[3][1], tr_status_name(st),
           want ? "intersecting" : "valid", tr_last_error());
    improper_seen += want;
    proper_seen += !want;
  }
  EXPECT(improper_seen > 50 && proper_seen > 50, "both outcomes exercised (%d, %d)",
         improper_seen, proper_seen);
}

/* The rule written with the segment-triangle classifier (classify.h): some edge of one
 * triangle meets the other at a point that is not a vertex both share. */
static int classify_says_improper(const double *x, const uint32_t *t, const uint32_t *u)
{
  for (int side = 0; side < 2; side++) {
    if (side) {
      const uint32_t *w = t;
      t = u;
      u = w;
    }
    tr_point U[3];
    for (int k = 0; k < 3; k++)
      U[k] = tr_pt_d(x + 3 * u[k]);
    for (int k = 0; k < 3; k++) {
      uint32_t a = t[k], b = t[(k + 1) % 3];
      tr_point A = tr_pt_d(x + 3 * a), B = tr_pt_d(x + 3 * b);
      tr_isect r = tr_classify_segment_triangle(&A, &B, &U[0], &U[1], &U[2]);
      for (int i = 0; i < r.n; i++)
        if (!(r.end[i].type == TR_NOD && r.end[i].code < 3 &&
              (u[r.end[i].code] == a || u[r.end[i].code] == b)))
          return 1;
    }
  }
  return 0;
}

/* Coplanar pairs sharing one vertex or none (selfint.c decides them in 2D) against the
 * classifier's answer, on a 5x5 grid mapped exactly onto a tilted plane: touching
 * corners, corners on edges, collinear edges and overlaps all come up. */
static void t_selfint_coplanar(void)
{
  uint64_t r = 0x2545f4914f6cdd1dull;
  int seen[2][2] = {{0, 0}, {0, 0}}; /* [shared][improper] */
  for (int it = 0; it < 3000; it++) {
    long long q[6][2];
    for (int k = 0; k < 6; k++)
      for (int d = 0; d < 2; d++) {
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        q[k][d] = (long long)(r % 5) - 2;
      }
    int shared = it & 1;
    if (shared) { /* u = (0, 4, 5): corner 0 shared */
      q[3][0] = q[0][0];
      q[3][1] = q[0][1];
    }
    int bad = 0;
    for (int a = 0; a < 6 && !bad; a++)
      for (int b = a + 1; b < 6; b++)
        bad |= q[a][0] == q[b][0] && q[a][1] == q[b][1] && !(shared && a == 0 && b == 3);
    long long at = (q[1][0] - q[0][0]) * (q[2][1] - q[0][1]) - (q[1][1] - q[0][1]) * (q[2][0] - q[0][0]);
    long long au = (q[4][0] - q[3][0]) * (q[5][1] - q[3][1]) - (q[4][1] - q[3][1]) * (q[5][0] - q[3][0]);
    if (bad || at == 0 || au == 0)
      continue;
    double x[18];
    for (int k = 0; k < 6; k++)
      onto_tilted_plane(q[k][0], q[k][1], x + 3 * k);
    uint32_t tt[6] = {0, 1, 2, 3, 4, 5};
    double y[15];
    uint32_t n = 6;
    if (shared) { /* drop the duplicate corner 3: u = (0, 4, 5) renumbered */
      memcpy(y, x, 9 * sizeof *y);
      memcpy(y + 9, x + 12, 6 * sizeof *y);
      uint32_t ts[6] = {0, 1, 2, 0, 3, 4};
      memcpy(tt, ts, sizeof ts);
      n = 5;
    }
    const double *pts = shared ? y : x;
    int want = classify_says_improper(pts, tt, tt + 3);
    tr_status st = check_pair(pts, n, tt);
    EXPECT((st == TR_ERR_SELF_INTERSECT) == want && (st == TR_OK || st == TR_ERR_SELF_INTERSECT),
           "coplanar pair %d (%d shared): %s, classifier says %s (%s)", it, shared,
           tr_status_name(st), want ? "intersecting" : "valid", tr_last_error());
    seen[shared][want]++;
  }
  EXPECT(seen[0][0] > 50 && seen[0][1] > 50 && seen[1][0] > 50 && seen[1][1] > 50,
         "all four kinds exercised (%d %d %d %d)", seen[0][0], seen[0][1], seen[1][0], seen[1][1]);
}

static uint64_t sb_rng = 0x243f6a8885a308d3ull;
static double sb_unif(void)
{
  sb_rng ^= sb_rng << 13;
  sb_rng ^= sb_rng >> 7;
  sb_rng ^= sb_rng << 17;
  return (double)(sb_rng >> 11) * 0x1p-53;
}

/* A closed octahedral sphere (level k: 8 * 4^k triangles), points scaled by a random
 * radius jitter that keeps it a valid surface; then `extra` random triangles of size
 * `size` (long slivers if size > 1) joined to it as a soup. */
static struct tr_plc *sb_surface(int k, int extra, double size)
{
  int res = 1 << k, nv = 0, nt = 0;
  /* vertices of the octahedron's faces on a (res+1)-grid, per face (duplicates merged by
   * index arithmetic would be long; the soup below shares them by exact equality) */
  double *X = malloc(sizeof *X * 3 * (size_t)(8 * (res + 1) * (res + 2) / 2 + 3 * extra));
  uint32_t *T = malloc(sizeof *T * 3 * (size_t)(8 * res * res + extra));
  for (int f = 0; f < 8; f++) {
    double sx = f & 1 ? -1 : 1, sy = f & 2 ? -1 : 1, sz = f & 4 ? -1 : 1;
    int base = nv;
    for (int i = 0; i <= res; i++)
      for (int j = 0; i + j <= res; j++) {
        double a = (double)i / res, b = (double)j / res, c = 1 - a - b;
        double x = sx * a, y = sy * b, z = sz * c, r = sqrt(x * x + y * y + z * z);
        X[3 * nv] = x / r;
        X[3 * nv + 1] = y / r;
        X[3 * nv + 2] = z / r;
        nv++;
      }
#define SB_ID(i, j) (base + (i) * (res + 1) - (i) * ((i) - 1) / 2 + (j))
    int flip = (sx * sy * sz) < 0;
    for (int i = 0; i < res; i++)
      for (int j = 0; i + j < res; j++) {
        uint32_t a = (uint32_t)SB_ID(i, j), b = (uint32_t)SB_ID(i + 1, j),
                 c = (uint32_t)SB_ID(i, j + 1);
        T[3 * nt] = a;
        T[3 * nt + 1] = flip ? c : b;
        T[3 * nt + 2] = flip ? b : c;
        nt++;
        if (i + j + 1 < res) {
          uint32_t d = (uint32_t)SB_ID(i + 1, j + 1);
          T[3 * nt] = b;
          T[3 * nt + 1] = flip ? c : d;
          T[3 * nt + 2] = flip ? d : c;
          nt++;
        }
      }
#undef SB_ID
  }
  /* octant faces repeat their shared vertices (equal doubles): one id each */
  int *id = malloc(sizeof *id * (size_t)(nv ? nv : 1)), nu = 0;
  for (int v = 0; v < nv; v++) {
    id[v] = -1;
    for (int u = 0; u < nu && id[v] < 0; u++)
      if (X[3 * u] == X[3 * v] && X[3 * u + 1] == X[3 * v + 1] && X[3 * u + 2] == X[3 * v + 2])
        id[v] = u;
    if (id[v] < 0) {
      memmove(X + 3 * nu, X + 3 * v, 3 * sizeof *X);
      id[v] = nu++;
    }
  }
  for (int i = 0; i < 3 * nt; i++)
    T[i] = (uint32_t)id[T[i]];
  free(id);
  nv = nu;
  for (int e = 0; e < extra; e++) {
    double o[3] = {2.4 * sb_unif() - 1.2, 2.4 * sb_unif() - 1.2, 2.4 * sb_unif() - 1.2};
    for (int q = 0; q < 3; q++) {
      for (int d = 0; d < 3; d++)
        X[3 * nv + d] = o[d] + size * (sb_unif() - 0.5);
      T[3 * nt + q] = (uint32_t)nv++;
    }
    nt++;
  }
  struct tr_plc *p = NULL;
  if (tr_plc_create(&p) != TR_OK || tr_plc_set(p, X, (uint32_t)nv, T, (uint32_t)nt, NULL) != TR_OK) {
    tr_plc_destroy(p);
    p = NULL;
  }
  free(X);
  free(T);
  return p;
}

/* The grid, the sweep and all pairs name the same pair (the least) or none. */
static void t_selfint_broad(void)
{
  static const struct { int k, extra; double size; int want; } cs[] = {
      {3, 0, 0, 0},   {4, 0, 0, 0},   {3, 1, 0.3, -1}, {3, 20, 0.2, 1},
      {4, 60, 0.1, 1}, {2, 40, 3.0, 1}, {0, 200, 0.5, 1}, {3, 30, 2e-9, -1}};
  for (size_t c = 0; c < sizeof cs / sizeof cs[0]; c++) {
    struct tr_plc *p = sb_surface(cs[c].k, cs[c].extra, cs[c].size);
    EXPECT(p != NULL, "case %zu: surface built", c);
    if (!p)
      continue;
    char msg[3][512];
    tr_status st[3];
    static const int how[3] = {TR_SELFINT_GRID, TR_SELFINT_SWEEP, TR_SELFINT_ALL_PAIRS};
    for (int h = 0; h < 3; h++) {
      st[h] = tr_input_self_intersections_by(p, NULL, how[h]);
      snprintf(msg[h], sizeof msg[h], "%s", st[h] == TR_OK ? "" : tr_last_error());
    }
    for (int h = 1; h < 3; h++)
      EXPECT(st[h] == st[0] && !strcmp(msg[h], msg[0]),
             "case %zu: broad phase %d says \"%s\", the grid \"%s\"", c, h, msg[h], msg[0]);
    if (cs[c].want >= 0)
      EXPECT((st[0] == TR_ERR_SELF_INTERSECT) == cs[c].want, "case %zu: %s", c,
             cs[c].want ? "intersections found" : "a valid sphere passes");
    tr_plc_destroy(p);
  }
}

/* t is already in the soup T[0..nt) (the same three corners in any order)? */
static int soup_has(const uint32_t *T, uint32_t nt, const uint32_t *t)
{
  for (uint32_t o = 0; o < nt; o++) {
    int same = 0;
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++)
        same += T[3 * o + i] == t[j];
    if (same == 3)
      return 1;
  }
  return 0;
}

/* The soup's improper pairs by the general path (TR_SELFINT_REFERENCE) and with the
 * shortcuts (TR_SELFINT_ALL_PAIRS) must be the same list. Returns 0 when the soup could not
 * be built, else 1 with the reference list in *pr (the caller frees it), *nr pairs. */
static int shortcuts_as_reference(const double *X, uint32_t nv, const uint32_t *T, uint32_t nt,
                                  int round, uint32_t **pr, size_t *nr)
{
  struct tr_plc *p = NULL;
  uint32_t *pa = NULL;
  size_t na = 0;
  *pr = NULL;
  *nr = 0;
  if (tr_plc_create(&p) != TR_OK || tr_plc_set(p, X, nv, T, nt, NULL) != TR_OK) {
    EXPECT(0, "round %d: soup built", round);
    tr_plc_destroy(p);
    return 0;
  }
  EXPECT(tr_input_self_intersection_pairs(p, TR_SELFINT_REFERENCE, pr, nr) == TR_OK,
         "round %d: reference", round);
  EXPECT(tr_input_self_intersection_pairs(p, TR_SELFINT_ALL_PAIRS, &pa, &na) == TR_OK,
         "round %d: shortcuts", round);
  EXPECT(*nr == na && (!na || !memcmp(*pr, pa, 2 * na * sizeof *pa)),
         "round %d: the shortcuts list %zu improper pairs, the general path %zu", round, na, *nr);
  free(pa);
  tr_plc_destroy(p);
  return 1;
}

/* The narrow phase's shortcuts (the side of a point from one coordinate for a triangle
 * in a plane x_k = const; the interval test on the line where the two planes meet, at
 * most two orient3d, for pairs across each other's planes; the separating edge line for
 * coplanar pairs) against the general path (TR_SELFINT_REFERENCE): random soups of
 * triangles on the grid {0,1,2}^3, where triangles in axis planes, exactly coplanar
 * pairs, corners on the other's plane and shared vertices abound, then the same soups
 * moved off the grid's axes by a shear (no triangle in an axis plane) and scaled by a
 * power of two. Both must list the same improper pairs. */
static void t_selfint_narrow(void)
{
  int kinds[2] = {0, 0};
  for (int round = 0; round < 300; round++) {
    enum { NT = 24 };
    double X[27 * 3];
    uint32_t T[3 * NT];
    int shear = round % 3 == 2;
    for (int v = 0; v < 27; v++) {
      double x = v % 3, y = v / 3 % 3, z = v / 9;
      X[3 * v] = shear ? x + 0.5 * y : x * 0.25;
      X[3 * v + 1] = shear ? y + 0.25 * z : y * 0.25;
      X[3 * v + 2] = shear ? z + 0.125 * x : z * 0.25;
    }
    uint32_t nt = 0;
    while (nt < NT) {
      uint32_t *t = T + 3 * nt;
      for (int k = 0; k < 3; k++)
        t[k] = (uint32_t)(sb_unif() * 27);
      const double *a = X + 3 * t[0], *b = X + 3 * t[1], *c = X + 3 * t[2];
      int flat = 1; /* zero area: the validation rejects those before this test */
      for (int d = 0; d < 3; d++)
        flat = flat && tr_orient2d_proj(a, b, c, d) == 0;
      if (!flat && !soup_has(T, nt, t))
        nt++;
    }
    uint32_t *pr;
    size_t nr;
    if (!shortcuts_as_reference(X, 27, T, nt, round, &pr, &nr))
      continue;
    /* both verdicts exercised: pairs of the soup that meet improperly and that do not */
    kinds[0] += nr < (size_t)nt * (nt - 1) / 2;
    kinds[1] += nr > 0;
    free(pr);
  }
  EXPECT(kinds[0] > 100 && kinds[1] > 100, "both verdicts (%d, %d)", kinds[0], kinds[1]);
}

/* Coplanar pairs sharing one vertex (fans around a vertex of a flat CAD face) take the
 * cone test at that vertex; the general path tests corners and edge crossings. Random
 * soups of triangles on a 5x5 grid in one plane, the plane z = 0 or a tilted one
 * (z = x/4 + y/2, exact), must list the same improper pairs both ways, and fan pairs of
 * both verdicts must occur. */
static void t_selfint_fan(void)
{
  int fans[2] = {0, 0};
  for (int round = 0; round < 200; round++) {
    enum { NT = 20, NV = 25 };
    double X[NV * 3];
    uint32_t T[3 * NT];
    for (int v = 0; v < NV; v++) {
      double x = v % 5, y = v / 5;
      X[3 * v] = x;
      X[3 * v + 1] = y;
      X[3 * v + 2] = round % 2 ? 0.25 * x + 0.5 * y : 0;
    }
    uint32_t nt = 0;
    while (nt < NT) {
      uint32_t *t = T + 3 * nt;
      for (int k = 0; k < 3; k++)
        t[k] = (uint32_t)(sb_unif() * NV);
      if (tr_orient2d_proj(X + 3 * t[0], X + 3 * t[1], X + 3 * t[2], 2) != 0 &&
          !soup_has(T, nt, t))
        nt++;
    }
    uint32_t *pr;
    size_t nr;
    if (!shortcuts_as_reference(X, NV, T, nt, round, &pr, &nr))
      continue;
    for (uint32_t i = 0; i < nt; i++)
      for (uint32_t j = i + 1; j < nt; j++) {
        int shared = 0;
        for (int a = 0; a < 3; a++)
          for (int b = 0; b < 3; b++)
            shared += T[3 * i + a] == T[3 * j + b];
        if (shared != 1)
          continue;
        int bad = 0;
        for (size_t k = 0; k < nr && !bad; k++)
          bad = pr[2 * k] == i && pr[2 * k + 1] == j;
        fans[bad]++;
      }
    free(pr);
  }
  EXPECT(fans[0] > 1000 && fans[1] > 1000, "fan pairs of both verdicts (%d fine, %d improper)",
         fans[0], fans[1]);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"selfint", t_selfint, NULL},
      {"selfint_broad", t_selfint_broad, NULL},
      {"selfint_coplanar", t_selfint_coplanar, NULL},
      {"selfint_narrow", t_selfint_narrow, NULL},
      {"selfint_fan", t_selfint_fan, NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
