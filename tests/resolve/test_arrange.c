/* The exact arrangement of a triangle soup (src/resolve): small configurations with
 * answers counted by hand, overlapping and duplicated cubes (also moved by one ulp), and
 * determinism. Every arrangement goes through tc_check (tcheck.h): exact conservation
 * of each input triangle's area and no improper contact between pieces.
 * Usage: test_arrange CASE [tests/data] */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tetrec.h"
#include "tcheck.h"

static struct tr_plc *make(const double *xyz, uint32_t n, const uint32_t *tris, uint32_t nt)
{
  tr_plc *p;
  tr_plc_create(&p);
  EXPECT(tr_plc_set(p, xyz, n, tris, nt, NULL) == TR_OK, "tr_plc_set: %s", tr_last_error());
  return p;
}

/* Builds and checks the arrangement; expected counts < 0 are not checked. */
static void expect(const char *name, const struct tr_plc *p, long nverts, long npieces,
                   long nmulti, long npairs, tr_arrangement *keep)
{
  tr_arrangement a;
  tr_status st = tr_arrangement_build(p, &a);
  EXPECT(st == TR_OK, "%s: %s", name, tr_last_error());
  if (st != TR_OK) {
    tr_arrangement_free(&a);
    return;
  }
  tc_check(name, p, &a);
  long multi = 0;
  for (uint32_t i = 0; i < a.npieces; i++)
    multi += a.pieces[i].nsrc > 1;
  EXPECT(nverts < 0 || a.nverts == (uint32_t)nverts, "%s: %u vertices, expected %ld", name,
         a.nverts, nverts);
  EXPECT(npieces < 0 || a.npieces == (uint32_t)npieces, "%s: %u pieces, expected %ld", name,
         a.npieces, npieces);
  EXPECT(nmulti < 0 || multi == nmulti, "%s: %ld pieces of several sources, expected %ld",
         name, multi, nmulti);
  EXPECT(npairs < 0 || a.npairs == (uint64_t)npairs, "%s: %llu pairs, expected %ld", name,
         (unsigned long long)a.npairs, npairs);
  if (keep)
    *keep = a;
  else
    tr_arrangement_free(&a);
}

static void expect_arrays(const char *name, const double *xyz, uint32_t n, const uint32_t *tris,
                          uint32_t nt, long nverts, long npieces, long nmulti, long npairs)
{
  struct tr_plc *p = make(xyz, n, tris, nt);
  expect(name, p, nverts, npieces, nmulti, npairs, NULL);
  tr_plc_destroy(p);
}

/* T1 in z = 0; T2 in x = 1 crosses T1's edge y = 0 and ends inside T1: the segment
 * from (1, 0, 0) (on T1's edge, inside T2) to (1, 0.5, 0) (on T2's edge, inside T1).
 * Each triangle gets one point on its boundary and one inside, joined: 5 points, 4 on
 * the hull, 2 * 5 - 4 - 2 = 4 pieces each; 2 new vertices. */
static void t_cross(void)
{
  double xyz[] = {0, 0, 0, 4, 0, 0, 0, 4, 0, 1, -1, -1, 1, -1, 1, 1, 2, 1};
  uint32_t tris[] = {0, 1, 2, 3, 4, 5};
  expect_arrays("cross", xyz, 6, tris, 2, 8, 8, 0, 1);
  /* the validator itself: the two triangles whole, or a piece missing, must fail it */
  struct tr_plc *p = make(xyz, 6, tris, 2);
  tr_arrangement a;
  expect("cross", p, 8, 8, 0, 1, &a);
  int f0 = failures;
  a.npieces--;
  int lost = tc_check("cross_missing_piece (expected to fail)", p, &a);
  a.npieces++;
  tr_arr_piece keep[2];
  memcpy(keep, a.pieces, sizeof keep);
  for (int t = 0; t < 2; t++) {
    for (int k = 0; k < 3; k++)
      a.pieces[t].v[k] = a.of_input[tris[3 * t + k]];
    a.pieces[t].src = t;
    a.pieces[t].nsrc = 1;
    a.src[t].tri = (uint32_t)t;
    a.src[t].sign = 1;
  }
  uint32_t np = a.npieces;
  a.npieces = 2;
  int whole = tc_check("cross_unsplit (expected to fail)", p, &a);
  a.npieces = np;
  failures = f0;
  EXPECT(lost > 0 && whole > 0, "the validator missed a lost piece (%d) or a crossing (%d)",
         lost, whole);
  memcpy(a.pieces, keep, sizeof keep);
  tr_arrangement_free(&a);
  tr_plc_destroy(p);
}

/* T2 in y = 1 pierces T1's interior along (1.25, 1, 0)-(1.75, 1, 0): T1 gets two inside
 * points, 2 * 5 - 3 - 2 = 5 pieces; T2 two boundary points, 2 * 5 - 5 - 2 = 3. */
static void t_pierce(void)
{
  double xyz[] = {0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, -1, 2, 1, -1, 1.5, 1, 1};
  uint32_t tris[] = {0, 1, 2, 3, 4, 5};
  expect_arrays("pierce", xyz, 6, tris, 2, 8, 8, 0, 1);
}

/* Touching only: at a common point given twice (one vertex, no split), along a common
 * edge given twice (no split); a corner inside the other triangle splits that one in 3,
 * a corner inside the other's edge splits it in 2 (pieces meet only at vertices). */
static void t_touch(void)
{
  double v[] = {0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 0, -1, 0, 1, 0, -1, 1};
  uint32_t tv[] = {0, 1, 2, 3, 4, 5};
  expect_arrays("touch_vertex", v, 6, tv, 2, 5, 2, 0, 0);
  double e[] = {0, 0, 0, 4, 0, 0, 0, 4, 0, 4, 0, 0, 0, 0, 0, 1, 1, 2};
  uint32_t te[] = {0, 1, 2, 3, 4, 5};
  expect_arrays("touch_edge", e, 6, te, 2, 4, 2, 0, 0);
  double in[] = {0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, 0, 2, 1, 1, 1, 2, 1};
  uint32_t ti[] = {0, 1, 2, 3, 4, 5};
  expect_arrays("touch_inside", in, 6, ti, 2, 6, 4, 0, 1);
  double on[] = {0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 0, 0, 2, 1, 1, 1, -1, 1};
  uint32_t to[] = {0, 1, 2, 3, 4, 5};
  expect_arrays("touch_on_edge", on, 6, to, 2, 6, 3, 0, 1);
}

/* Coplanar overlaps in z = 0. Star of David: the hexagon (2,0) (4,0) (5,2) (4,4) (2,4)
 * (1,2), 6 new vertices; each triangle: 3 tips + the hexagon in 4, the hexagon's 4
 * shared: 3 + 3 + 4 = 10 pieces. One inside another: the outer one is a triangle with a
 * triangular hole (6 points, hull 3: 7 pieces) and the inner one is one of them.
 * Identical triangles (the same points, and given again reversed): one piece, 2 or 3
 * sources. A unit square overlap (four cocircular points, no cut across it): both split
 * it along the same diagonal. */
static void t_coplanar(void)
{
  double h[] = {0, 0, 0, 6, 0, 0, 3, 6, 0, 0, 4, 0, 6, 4, 0, 3, -2, 0};
  uint32_t th[] = {0, 1, 2, 3, 5, 4};
  expect_arrays("hexagon", h, 6, th, 2, 12, 10, 4, 1);
  double in[] = {0, 0, 0, 8, 0, 0, 0, 8, 0, 1, 1, 0, 3, 1, 0, 1, 3, 0};
  uint32_t ti[] = {0, 1, 2, 3, 4, 5};
  expect_arrays("inside", in, 6, ti, 2, 6, 7, 1, 1);
  double id[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0};
  uint32_t tid[] = {0, 1, 2, 3, 4, 5, 2, 1, 0};
  expect_arrays("identical", id, 6, tid, 3, 3, 1, 1, 0);
  double sq[] = {0, 0, 0, 3, 0, 0, 0, 3, 0, 1, 1, 0, -11, 1, 0, 1, -11, 0};
  uint32_t tsq[] = {0, 1, 2, 3, 4, 5};
  struct tr_plc *p = make(sq, 6, tsq, 2);
  tr_arrangement a;
  expect("square", p, -1, -1, 2, 1, &a);
  tr_arrangement_free(&a);
  tr_plc_destroy(p);
}

/* Three vertical triangles over a fourth in z = 0, their cuts on it pairwise crossing
 * inside it: 3 corners + 6 cut ends + 3 crossings, hull 3: 2 * 12 - 3 - 2 = 19 pieces
 * from the fourth. */
static void t_three(void)
{
  double xyz[] = {-10, -10, 0, 10, -10, 0, 0, 10, 0,
                  /* in x = 1: y from -3 to 3 at z = 0 */
                  1, -3, -1, 1, 3, -1, 1, 0, 2,
                  /* in y = 1: x from -3 to 3 */
                  -3, 1, -1, 3, 1, -1, 0, 1, 2,
                  /* in x + y = 0: x from -3 to 3 */
                  -3, 3, -1, 3, -3, -1, 0, 0, 2};
  uint32_t tris[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  struct tr_plc *p = make(xyz, 12, tris, 4);
  tr_arrangement a;
  expect("three", p, -1, -1, 0, -1, &a);
  uint32_t from0 = 0;
  for (uint32_t i = 0; i < a.npieces; i++)
    from0 += a.src[a.pieces[i].src].tri == 0;
  EXPECT(from0 == 19, "three: %u pieces from the fourth triangle, expected 19", from0);
  EXPECT(a.ncrossings >= 3, "three: %llu crossings", (unsigned long long)a.ncrossings);
  tr_arrangement_free(&a);
  tr_plc_destroy(p);
}

/* A zero-area triangle crossing another is absorbed: no piece, no cut. A repeated
 * corner too. Repeated points are one vertex. */
static void t_degenerate(void)
{
  double xyz[] = {0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, -1, 2, 2, 1, 3, 3, 3, 0, 0, 0};
  uint32_t tris[] = {0, 1, 2, 3, 4, 5, 3, 3, 4, 6, 1, 2};
  struct tr_plc *p = make(xyz, 7, tris, 4);
  tr_arrangement a;
  expect("degenerate", p, 6, 1, 1, 0, &a);
  EXPECT(a.ndropped == 2 && a.ndup_points == 1, "degenerate: %llu dropped, %llu repeated",
         (unsigned long long)a.ndropped, (unsigned long long)a.ndup_points);
  tr_arrangement_free(&a);
  tr_plc_destroy(p);
}

/* The unit cube's 8 points and 12 triangles (as tests/data/resolve_cube.off), moved by
 * off, appended at point base. */
static void cube(double *xyz, uint32_t *tris, const double off[3], uint32_t base)
{
  static const uint32_t t[] = {1, 3, 7, 1, 7, 5, 0, 4, 6, 0, 6, 2, 2, 6, 7, 2, 7, 3,
                               0, 1, 5, 0, 5, 4, 4, 5, 7, 4, 7, 6, 0, 2, 3, 0, 3, 1};
  for (int i = 0; i < 8; i++)
    for (int d = 0; d < 3; d++)
      xyz[3 * i + d] = (double)(i >> d & 1) + off[d];
  for (int i = 0; i < 36; i++)
    tris[i] = t[i] + base;
}

/* Two unit cubes, the second moved by (0.5, 0.5, 0.5) (the files in tests/data). Their
 * surfaces meet in the skew hexagon h1 (1,.5,.5) h2 (1,1,.5) h3 (.5,1,.5) h4 (.5,1,1)
 * h5 (.5,.5,1) h6 (1,.5,1): each side lies in one triangle of each cube, and each
 * triangle with a side has both ends on its boundary (h1 on the diagonal y = z of face
 * x = 1, h2 on its edge y = 1, ...). 6 new vertices, 16 in all; 6 triangles of each cube
 * cut in 3 (5 boundary points), the other 12 whole: 36 + 12 = 48 pieces. Pairs: 6 along
 * a side, and at each h the 2 pairs that touch only there: 18. */
static void t_cubes(const char *data)
{
  double xyz[48];
  uint32_t tris[72];
  EXPECT(tc_two_cubes(data, xyz, tris), "read: %s", tr_last_error());
  expect_arrays("cubes", xyz, 16, tris, 24, 22, 48, 0, 18);
  /* the same by one ulp more: nothing special happened at 0.5 */
  double u = nextafter(0.5, 1), off[3] = {u, u, u}, zero[3] = {0, 0, 0};
  cube(xyz, tris, zero, 0);
  cube(xyz + 24, tris + 36, off, 8);
  expect_arrays("cubes_ulp", xyz, 16, tris, 24, 22, 48, 0, 18);
  /* and by one ulp less in x only */
  off[0] = nextafter(0.5, 0);
  off[1] = off[2] = 0.5;
  cube(xyz + 24, tris + 36, off, 8);
  expect_arrays("cubes_ulp_x", xyz, 16, tris, 24, -1, -1, 0, -1);
}

/* A cube given twice (the second shell on repeated points): 12 pieces of 2 sources, no
 * new vertex. Then the second shell moved by one ulp along x: its faces y, z = 0, 1
 * overlap the first's all but a sliver one ulp wide, its faces x = 0, 1 lie an ulp off. */
static void t_dupshell(void)
{
  double xyz[48];
  uint32_t tris[72];
  double zero[3] = {0, 0, 0}, ulp[3] = {0x1p-52, 0, 0};
  cube(xyz, tris, zero, 0);
  cube(xyz + 24, tris + 36, zero, 8);
  expect_arrays("dupshell", xyz, 16, tris, 24, 8, 12, 12, 0);
  cube(xyz + 24, tris + 36, ulp, 8);
  struct tr_plc *p = make(xyz, 16, tris, 24);
  tr_arrangement a;
  expect("dupshell_ulp", p, -1, -1, -1, -1, &a);
  EXPECT(a.ncoplanar > 0, "dupshell_ulp: no coplanar pair");
  long multi = 0;
  for (uint32_t i = 0; i < a.npieces; i++)
    multi += a.pieces[i].nsrc > 1;
  EXPECT(multi > 0, "dupshell_ulp: no overlap merged");
  tr_arrangement_free(&a);
  tr_plc_destroy(p);
}

/* The same input twice (copied to new memory) gives the same arrangement byte for byte:
 * vertices (exact values, what they lie on), pieces, sources. */
static char *dump(const struct tr_plc *p, const tr_arrangement *a, size_t *len)
{
  char *s;
  FILE *f = open_memstream(&s, len);
  for (uint32_t v = 0; v < a->nverts; v++) {
    tr_point q = tr_arr_point(a, p, v);
    mpq_t c;
    mpq_init(c);
    for (int i = 0; i < 3; i++) {
      tr_point_get_q(&q, i, c);
      gmp_fprintf(f, "%Qd ", c);
    }
    mpq_clear(c);
    fprintf(f, "%u %u %u %u\n", a->verts[v].input, a->verts[v].on, a->verts[v].a,
            a->verts[v].b);
  }
  for (uint32_t i = 0; i < a->npieces; i++) {
    const tr_arr_piece *x = a->pieces + i;
    fprintf(f, "%u %u %u %d:", x->v[0], x->v[1], x->v[2], x->marker);
    for (uint32_t k = 0; k < x->nsrc; k++)
      fprintf(f, " %u/%d", a->src[x->src + k].tri, a->src[x->src + k].sign);
    fprintf(f, "\n");
  }
  fclose(f);
  return s;
}

static void t_determinism(void)
{
  double xyz[72];
  uint32_t tris[108];
  double o0[3] = {0, 0, 0}, o1[3] = {0.5, 0.5, 0.5}, o2[3] = {0.25, -0.3, 0.7};
  cube(xyz, tris, o0, 0);
  cube(xyz + 24, tris + 36, o1, 8);
  cube(xyz + 48, tris + 72, o2, 16);
  char *d[2];
  size_t n[2];
  for (int r = 0; r < 2; r++) {
    struct tr_plc *p = make(xyz, 24, tris, 36);
    tr_arrangement a;
    expect("determinism", p, -1, -1, -1, -1, &a);
    d[r] = dump(p, &a, &n[r]);
    tr_arrangement_free(&a);
    tr_plc_destroy(p);
  }
  EXPECT(n[0] == n[1] && !memcmp(d[0], d[1], n[0]), "determinism: two runs differ");
  free(d[0]);
  free(d[1]);
}

/* Random soups on a small integer grid, where coplanar overlaps, collinear cuts, cuts
 * through vertices and three cuts through one point are the rule: every arrangement
 * must pass the validator. Coordinates are mapped onto a tilted plane or kept axis
 * aligned (exact either way: small integers). */
static void t_random(void)
{
  uint64_t r = 0x2545f4914f6cdd1dull;
  for (int it = 0; it < (getenv("RS_ITER") ? atoi(getenv("RS_ITER")) : 300); it++) {
    int big = it % 5 == 4; /* a larger soup on a larger grid */
    uint32_t nt = big ? 12 + (uint32_t)(it % 13) : 2 + (uint32_t)(it % 9), n = 3 * nt;
    double xyz[3 * 3 * 24];
    uint32_t tris[3 * 24];
    int grid = big ? 6 : it % 3 == 0 ? 2 : 4, flat = it % 4 == 1;
    for (uint32_t i = 0; i < n; i++) {
      for (int d = 0; d < 3; d++) {
        r ^= r << 13, r ^= r >> 7, r ^= r << 17;
        xyz[3 * i + d] = (double)(r % (uint64_t)(grid + 1));
      }
      if (flat) /* most triangles coplanar: z = x + y - 2 */
        xyz[3 * i + 2] = xyz[3 * i] + xyz[3 * i + 1] - 2;
      tris[i] = i;
    }
    char name[64];
    snprintf(name, sizeof name, "random_%d", it);
    struct tr_plc *p = make(xyz, n, tris, nt);
    expect(name, p, -1, -1, -1, -1, NULL);
    tr_plc_destroy(p);
  }
}

/* tr_incircle_proj_p (the CDT's predicate) against rational arithmetic, on rational
 * points near and on common circles (Pythagorean points of the unit circle, scaled and
 * moved), in every projection, mixed with double points. */
static void t_incircle(void)
{
  static const long pyth[][3] = {{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {7, 24, 25}, {20, 21, 29},
                                 {0, 1, 1}, {1, 0, 1}, {-3, 4, 5}, {-5, -12, 13}, {15, -8, 17}};
  uint64_t r = 88172645463325252ull;
  tr_qpoint q[4];
  for (int k = 0; k < 4; k++)
    tr_qpoint_init(&q[k]);
  mpq_t m[3][3], t, det;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      mpq_init(m[i][j]);
  mpq_inits(t, det, NULL);
  int zero = 0;
  for (int it = 0; it < 4000; it++) {
    int drop = it % 3, u = (drop + 1) % 3, v = (drop + 2) % 3;
    for (int k = 0; k < 4; k++) {
      r ^= r << 13, r ^= r >> 7, r ^= r << 17;
      const long *py = pyth[r % 10];
      long den = (long)(r >> 8 & 7) + 1;
      for (int i = 0; i < 3; i++) /* off-plane axis: any value */
        mpq_set_si(q[k].c[i], (long)(r >> (12 + 4 * i) & 15) - 7, (unsigned long)den);
      /* (1/3, -2/7) + (py0, py1) / py2 * 11/3, or slightly off it */
      mpq_set_si(q[k].c[u], 11 * py[0] * 7 + py[2] * 7, (unsigned long)(3 * py[2] * 7));
      mpq_set_si(q[k].c[v], 11 * py[1] * 21 - 6 * py[2] * 3, (unsigned long)(63 * py[2]));
      mpq_canonicalize(q[k].c[u]);
      mpq_canonicalize(q[k].c[v]);
      if (it % 4 == 3 && k == 3) { /* off the circle by 1/2^40 */
        mpq_set_si(t, 1, 1ul << 40);
        mpq_add(q[k].c[u], q[k].c[u], t);
      }
      tr_qpoint_update(&q[k]);
    }
    tr_point P[4];
    for (int k = 0; k < 4; k++)
      P[k] = tr_pt_q(&q[k]);
    for (int k = 0; k < 3; k++) {
      mpq_sub(m[k][0], q[k].c[u], q[3].c[u]);
      mpq_sub(m[k][1], q[k].c[v], q[3].c[v]);
      mpq_mul(m[k][2], m[k][0], m[k][0]);
      mpq_mul(t, m[k][1], m[k][1]);
      mpq_add(m[k][2], m[k][2], t);
    }
    mpq_set_ui(det, 0, 1);
    for (int k = 0; k < 3; k++) {
      int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      mpq_mul(t, m[k1][1], m[k2][2]);
      mpq_t w;
      mpq_init(w);
      mpq_mul(w, m[k1][2], m[k2][1]);
      mpq_sub(t, t, w);
      mpq_mul(t, t, m[k][0]);
      mpq_add(det, det, t);
      mpq_clear(w);
    }
    int got = tr_incircle_proj_p(&P[0], &P[1], &P[2], &P[3], drop);
    zero += mpq_sgn(det) == 0;
    EXPECT(got == mpq_sgn(det), "incircle %d: %d, exact %d", it, got, mpq_sgn(det));
  }
  EXPECT(zero > 100, "incircle: only %d cocircular cases", zero);
  for (int k = 0; k < 4; k++)
    tr_qpoint_clear(&q[k]);
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      mpq_clear(m[i][j]);
  mpq_clears(t, det, NULL);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
    {"cross", t_cross, NULL},
    {"pierce", t_pierce, NULL},
    {"touch", t_touch, NULL},
    {"coplanar", t_coplanar, NULL},
    {"three", t_three, NULL},
    {"degenerate", t_degenerate, NULL},
    {"cubes", NULL, t_cubes},
    {"dupshell", t_dupshell, NULL},
    {"determinism", t_determinism, NULL},
    {"random", t_random, NULL},
    {"incircle", t_incircle, NULL},
  };
  int r = texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
  tr_thread_cleanup();
  return r;
}
