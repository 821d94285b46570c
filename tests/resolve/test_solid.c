/* The solid of an arrangement by winding number (src/resolve/winding.c), with answers
 * counted by hand: which pieces bound it, which are internal, and its volume checked
 * exactly (GMP: the signed tets of the boundary pieces against the origin). Every
 * arrangement also goes through tc_check (tcheck.h). Usage: test_solid CASE [tests/data] */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tetrec.h"
#include "tcheck.h"

/* A cube of side s at off, faces split as in tests/data/resolve_cube.off, outward. */
static void cube(double *xyz, uint32_t *tris, const double off[3], double s, uint32_t base)
{
  static const uint32_t t[] = {1, 3, 7, 1, 7, 5, 0, 4, 6, 0, 6, 2, 2, 6, 7, 2, 7, 3,
                               0, 1, 5, 0, 5, 4, 4, 5, 7, 4, 7, 6, 0, 2, 3, 0, 3, 1};
  for (int i = 0; i < 8; i++)
    for (int d = 0; d < 3; d++)
      xyz[3 * i + d] = s * (double)(i >> d & 1) + off[d];
  for (int i = 0; i < 36; i++)
    tris[i] = t[i] + base;
}

static void flip(uint32_t *tri)
{
  uint32_t x = tri[1];
  tri[1] = tri[2];
  tri[2] = x;
}

typedef struct {
  long kept, internal, dropped;
  mpq_t vol6, internal6; /* 6 x the solid's volume; 6 x the internal pieces' (as oriented) */
} result;

/* The signed volume x 6 of the pieces of class cls, as oriented. */
static void class_volume6(const struct tr_plc *p, const tr_arrangement *a, const tr_solid *s,
                          int cls, mpq_t out)
{
  tr_solid only = *s;
  only.keep = malloc(a->npieces ? a->npieces : 1);
  for (uint32_t i = 0; i < a->npieces; i++)
    only.keep[i] = s->keep[i] == cls ? TR_SOLID_KEEP : TR_SOLID_DROP;
  tr_solid_volume6(p, a, &only, out);
  free(only.keep);
}

/* Arrangement + solid; 1 and r filled, or 0 with the status in *st. */
static int solve(const char *name, const double *xyz, uint32_t n, const uint32_t *tris,
                 uint32_t nt, int internal, result *r, tr_status *st)
{
  tr_plc *p;
  tr_plc_create(&p);
  EXPECT(tr_plc_set(p, xyz, n, tris, nt, NULL) == TR_OK, "%s: tr_plc_set: %s", name,
         tr_last_error());
  tr_arrangement a;
  *st = tr_arrangement_build(p, &a);
  EXPECT(*st == TR_OK, "%s: arrangement: %s", name, tr_last_error());
  tr_solid s;
  memset(&s, 0, sizeof s);
  if (*st == TR_OK) {
    tc_check(name, p, &a);
    *st = tr_solid_classify(p, &a, internal, &s);
  }
  if (*st == TR_OK) {
    r->kept = r->internal = r->dropped = 0;
    for (uint32_t i = 0; i < a.npieces; i++) {
      r->kept += s.keep[i] == TR_SOLID_KEEP || s.keep[i] == TR_SOLID_FLIP;
      r->internal += s.keep[i] == TR_SOLID_INTERNAL;
      r->dropped += s.keep[i] == TR_SOLID_DROP;
    }
    EXPECT(r->kept == s.nkept && r->internal == s.ninternal, "%s: counts", name);
    tr_solid_volume6(p, &a, &s, r->vol6);
    class_volume6(p, &a, &s, TR_SOLID_INTERNAL, r->internal6);
  }
  tr_solid_free(&s);
  tr_arrangement_free(&a);
  tr_plc_destroy(p);
  return *st == TR_OK;
}

static void expect_solid(const char *name, const double *xyz, uint32_t n, const uint32_t *tris,
                         uint32_t nt, int internal, long kept, long nint, const char *vol6,
                         const char *int6)
{
  result r;
  mpq_inits(r.vol6, r.internal6, NULL);
  tr_status st;
  if (solve(name, xyz, n, tris, nt, internal, &r, &st)) {
    EXPECT(kept < 0 || r.kept == kept, "%s: %ld boundary pieces, expected %ld", name, r.kept,
           kept);
    EXPECT(nint < 0 || r.internal == nint, "%s: %ld internal pieces, expected %ld", name,
           r.internal, nint);
    mpq_t want;
    mpq_init(want);
    mpq_set_str(want, vol6, 10);
    mpq_canonicalize(want);
    EXPECT(mpq_equal(want, r.vol6), "%s: 6 x volume %s, expected %s", name,
           mpq_get_str(NULL, 10, r.vol6), vol6);
    if (int6) {
      mpq_set_str(want, int6, 10);
      mpq_canonicalize(want);
      EXPECT(mpq_equal(want, r.internal6), "%s: 6 x internal volume %s, expected %s", name,
             mpq_get_str(NULL, 10, r.internal6), int6);
    }
    mpq_clear(want);
  } else
    EXPECT(0, "%s: %s", name, tr_last_error());
  mpq_clears(r.vol6, r.internal6, NULL);
}

static void expect_error(const char *name, const double *xyz, uint32_t n, const uint32_t *tris,
                         uint32_t nt, const char *says)
{
  result r;
  mpq_inits(r.vol6, r.internal6, NULL);
  tr_status st;
  int ok = solve(name, xyz, n, tris, nt, 0, &r, &st);
  EXPECT(!ok && st == TR_ERR_OPEN, "%s: expected TR_ERR_OPEN, got %s", name, tr_status_name(st));
  EXPECT(!ok && strstr(tr_last_error(), says), "%s: message '%s' does not say '%s'", name,
         tr_last_error(), says);
  mpq_clears(r.vol6, r.internal6, NULL);
}

/* One cube: 12 pieces, all kept, volume 1 (6 x = 6); reversed it bounds nothing. */
static void t_one(void)
{
  double xyz[24], zero[3] = {0, 0, 0};
  uint32_t tris[36];
  cube(xyz, tris, zero, 1, 0);
  expect_solid("cube", xyz, 8, tris, 12, 0, 12, 0, "6", NULL);
  for (int t = 0; t < 12; t++)
    flip(tris + 3 * t);
  expect_solid("cube_inside_out", xyz, 8, tris, 12, 0, 0, 0, "0", NULL);
}

/* Two unit cubes, the second moved by (0.5, 0.5, 0.5) (tests/data): the union has volume
 * 2 - 1/8 (6 x: 45/4). Their common cube [.5, 1]^3 is bounded by three quarter faces of
 * each, each cut by its face diagonal into 2 pieces: 12 internal pieces, 36 of the 48 on
 * the boundary; the internal ones, as oriented, bound the common cube (6 x: 3/4). Moved
 * by one ulp more (u = 0.5 + 2^-53): its far corner 1 + u rounds to 1.5. */
static void t_cubes(const char *data)
{
  double xyz[48];
  uint32_t tris[72];
  EXPECT(tc_two_cubes(data, xyz, tris), "read: %s", tr_last_error());
  expect_solid("cubes", xyz, 16, tris, 24, 0, 36, 0, "45/4", NULL);
  expect_solid("cubes_internal", xyz, 16, tris, 24, 1, 36, 12, "45/4", "3/4");
  double u = nextafter(0.5, 1), off[3] = {u, u, u}, zero[3] = {0, 0, 0};
  cube(xyz, tris, zero, 1, 0);
  cube(xyz + 24, tris + 36, off, 1, 8);
  /* 1 + u rounds to 1.5 in doubles: the second box is [u, 1.5]^3, so
   * 6 x (1 + (1.5 - u)^3 - (1 - u)^3) */
  mpq_t s, t, h;
  mpq_inits(s, t, h, NULL);
  mpq_set_d(h, xyz[24 + 21]); /* its corner 7's x */
  mpq_set_d(t, u);
  mpq_sub(h, h, t);
  mpq_mul(s, h, h);
  mpq_mul(h, s, h); /* (1.5 - u)^3 */
  mpq_set_d(s, 1);
  mpq_sub(s, s, t);
  mpq_mul(t, s, s);
  mpq_mul(t, t, s); /* (1 - u)^3 */
  mpq_set_ui(s, 1, 1);
  mpq_add(s, s, h);
  mpq_sub(s, s, t);
  mpq_set_ui(t, 6, 1);
  mpq_mul(s, s, t);
  char *want = mpq_get_str(NULL, 10, s);
  expect_solid("cubes_ulp", xyz, 16, tris, 24, 0, 36, 0, want, NULL);
  free(want);
  mpq_clears(s, t, h, NULL);
}

/* The same cube twice: every piece has two sources, weight 2, winding 2 inside: one
 * boundary of 12 pieces, volume 1. Once reversed: weight 0, no solid. */
static void t_dupshell(void)
{
  double xyz[48], zero[3] = {0, 0, 0};
  uint32_t tris[72];
  cube(xyz, tris, zero, 1, 0);
  cube(xyz + 24, tris + 36, zero, 1, 8);
  expect_solid("dupshell", xyz, 16, tris, 24, 0, 12, 0, "6", NULL);
  for (int t = 12; t < 24; t++)
    flip(tris + 3 * t);
  expect_solid("dupshell_cancel", xyz, 16, tris, 24, 0, 0, 0, "0", NULL);
  /* and moved by one ulp: two cubes overlapping in all but a slab one ulp thick */
  double ulp[3] = {0x1p-52, 0, 0};
  cube(xyz + 24, tris + 36, ulp, 1, 8);
  /* the union spans 1 + 2^-52 in x: 6 x = 6 + 3 / 2^51 */
  expect_solid("dupshell_ulp", xyz, 16, tris, 24, 0, -1, 0, "13510798882111491/2251799813685248",
               NULL);
}

/* A unit cube inside a cube of side 3 (at (1, 1, 1)): facing outward it is an internal
 * facet of the solid (winding 2 inside it): dropped, volume 27; kept as internal on
 * request (12 pieces). Facing inward it is a cavity: 24 boundary pieces, volume 26. */
static void t_nested(void)
{
  double xyz[48], zero[3] = {0, 0, 0}, one[3] = {1, 1, 1};
  uint32_t tris[72];
  cube(xyz, tris, zero, 3, 0);
  cube(xyz + 24, tris + 36, one, 1, 8);
  expect_solid("nested", xyz, 16, tris, 24, 0, 12, 0, "162", NULL);
  expect_solid("nested_internal", xyz, 16, tris, 24, 1, 12, 12, "162", "6");
  for (int t = 12; t < 24; t++)
    flip(tris + 3 * t);
  expect_solid("nested_cavity", xyz, 16, tris, 24, 0, 24, 0, "156", NULL);
}

/* Badly oriented and open soups: the winding number is not defined, an error that names
 * the input triangles. */
static void t_errors(void)
{
  double xyz[48], zero[3] = {0, 0, 0};
  uint32_t tris[72];
  cube(xyz, tris, zero, 1, 0);
  flip(tris); /* one triangle of face x = 1 */
  expect_error("one_triangle_flipped", xyz, 8, tris, 12, "input triangles");
  flip(tris + 3); /* the whole face */
  expect_error("one_face_flipped", xyz, 8, tris, 12, "not defined");
  cube(xyz, tris, zero, 1, 0);
  expect_error("open_box", xyz, 8, tris, 10, "(1 piece, of input triangle 6)"); /* no z = 0 face */
  /* the same with a second cube moved by one ulp overlapping it */
  double ulp[3] = {0x1p-52, 0x1p-52, 0};
  cube(xyz + 24, tris + 30, ulp, 1, 8);
  expect_error("open_box_and_cube_ulp", xyz, 16, tris, 22, "not defined");
}

/* Random unions of cubes of side 2 at integer positions in [0, 3]^3 (duplicates, shared
 * faces, edges and corners included): all such cubes' face diagonals have one direction
 * per plane, so every new vertex is an integer or half-integer point. The solid's volume
 * must be the number of unit voxels some cube covers, counted directly. RS_ITER=N runs N
 * (default 300). */
static void t_random_cubes(void)
{
  const char *e = getenv("RS_ITER");
  long iters = e ? atol(e) : 300;
  uint64_t seed = 0x9e3779b97f4a7c15u;
  double xyz[8 * 24];
  uint32_t tris[36 * 8];
  for (long it = 0; it < iters; it++) {
    seed = seed * 6364136223846793005u + 1442695040888963407u;
    int n = 2 + (int)((seed >> 33) % 4), cov[5][5][5];
    memset(cov, 0, sizeof cov);
    for (int c = 0; c < n; c++) {
      seed = seed * 6364136223846793005u + 1442695040888963407u;
      double off[3] = {(double)((seed >> 20) % 4), (double)((seed >> 30) % 4),
                       (double)((seed >> 40) % 4)};
      cube(xyz + 24 * c, tris + 36 * c, off, 2, 8 * (uint32_t)c);
      for (int x = 0; x < 2; x++)
        for (int y = 0; y < 2; y++)
          for (int z = 0; z < 2; z++)
            cov[(int)off[0] + x][(int)off[1] + y][(int)off[2] + z] = 1;
    }
    long vox = 0;
    for (int x = 0; x < 5; x++)
      for (int y = 0; y < 5; y++)
        for (int z = 0; z < 5; z++)
          vox += cov[x][y][z];
    char name[64], want[32];
    snprintf(name, sizeof name, "random_cubes_%ld", it);
    snprintf(want, sizeof want, "%ld", 6 * vox);
    expect_solid(name, xyz, 8 * (uint32_t)n, tris, 12 * (uint32_t)n, it % 2, -1, -1, want,
                 NULL);
  }
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
    {"one", t_one, NULL},
    {"cubes", NULL, t_cubes},
    {"dupshell", t_dupshell, NULL},
    {"nested", t_nested, NULL},
    {"errors", t_errors, NULL},
    {"random_cubes", t_random_cubes, NULL},
  };
  int r = texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
  tr_thread_cleanup();
  return r;
}
