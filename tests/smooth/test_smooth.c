/* The surface swaps' worklist (src/smooth/smooth.c) against the full passes it replaced
 * (smooth_passes.c): the same triangles, slot for slot, and the same swap count, on
 * random surfaces with flat regions, markers, folds, fins and flipped triangles. Closed
 * results go through tr_plc_validate and keep their exact volume. */
#include <gmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "input/validate.h"
#include "smooth/smooth.h"

#include "../pipeline/texpect.h"

static uint64_t rng = 0x9e3779b97f4a7c15ull;
static uint64_t next(void)
{
  rng ^= rng << 13;
  rng ^= rng >> 7;
  rng ^= rng << 17;
  return rng;
}
static uint32_t below(uint32_t n) { return (uint32_t)(next() % n); }

static int incircle(void *user, const double *const q[4], uint32_t A, uint32_t B, uint32_t C,
                    uint32_t D)
{
  (void)user, (void)A, (void)B, (void)C, (void)D;
  return tr_coplanar_incircle(q[0], q[2], q[1], q[3]);
}

/* A rule of the four ids only, which may undo its own swaps (the passes then run to the
 * limit). */
static int hashed(void *user, const double *const q[4], uint32_t A, uint32_t B, uint32_t C,
                  uint32_t D)
{
  (void)q;
  uint64_t h = *(const uint64_t *)user;
  h ^= A * 0x9e3779b97f4a7c15ull + B * 0xc2b2ae3d27d4eb4full + C * 0x165667b19e3779f9ull +
       D * 0xd6e8feb86659fd93ull;
  h ^= h >> 29;
  h *= 0xbf58476d1ce4e5b9ull;
  return (h >> 40) % 3 != 0;
}

/* Copies plc's points, triangles and markers into a new PLC (no validation). */
static tr_plc *clone(const tr_plc *p)
{
  tr_plc *c = NULL;
  if (tr_plc_create(&c) != TR_OK ||
      tr_plc_set(c, p->xyz, p->npoints, p->tris, p->ntris, p->tri_marker) != TR_OK)
    abort();
  return c;
}

/* Runs the worklist and the reference on copies of p with one rule; 1 if they agree. */
static int agree(const char *what, const tr_plc *p, tr_swap_rule rule, void *user,
                 uint64_t *nswaps)
{
  tr_plc *a = clone(p), *b = clone(p);
  uint64_t na = 0, nb = 0;
  tr_status sa = tr_smooth_surface_rule(a, rule, user, &na);
  tr_status sb = tr_smooth_surface_rule_passes(b, rule, user, &nb);
  int ok = sa == TR_OK && sb == TR_OK && na == nb &&
           !memcmp(a->tris, b->tris, sizeof *a->tris * 3 * (size_t)a->ntris);
  EXPECT(ok, "%s: worklist %llu swaps (%d), full passes %llu (%d), triangles %s", what,
         (unsigned long long)na, (int)sa, (unsigned long long)nb, (int)sb,
         memcmp(a->tris, b->tris, sizeof *a->tris * 3 * (size_t)a->ntris) ? "differ" : "same");
  *nswaps = na;
  tr_plc_destroy(a);
  tr_plc_destroy(b);
  return ok;
}

/* An n x n grid of points on the plane z = x + 2y (exact in doubles), its squares cut by
 * random diagonals, with random defects: a few points lifted off the plane, markers,
 * squares cut into fans around a midpoint, a flipped triangle, a fin on an edge. */
static tr_plc *sheet(uint32_t n)
{
  uint32_t np = (n + 1) * (n + 1), cap = 4 * n * n + 8;
  double *x = malloc(sizeof *x * 3 * (np + n * n + 1));
  uint32_t *t = malloc(sizeof *t * 3 * cap);
  int32_t *m = malloc(sizeof *m * cap);
  uint32_t lift = below(4), nmark = below(3) + 1;
  for (uint32_t j = 0; j <= n; j++)
    for (uint32_t i = 0; i <= n; i++) {
      double *p = x + 3 * (j * (n + 1) + i);
      p[0] = i + (below(5) == 0 ? 0.5 : 0.0); /* some rows off the lattice: not cocircular */
      p[1] = j;
      p[2] = p[0] + 2 * p[1] + (below(40) < lift ? 1.0 : 0.0);
    }
  uint32_t nt = 0;
#define V(i, j) ((j) * (n + 1) + (i))
  for (uint32_t j = 0; j < n; j++)
    for (uint32_t i = 0; i < n; i++) {
      uint32_t a = V(i, j), b = V(i + 1, j), c = V(i + 1, j + 1), d = V(i, j + 1);
      int32_t mk = (int32_t)below(nmark);
      uint32_t r = below(8);
      if (r == 0) { /* a fan around the square's midpoint, on the plane */
        double *p = x + 3 * np;
        p[0] = (x[3 * a] + x[3 * c]) / 2;
        p[1] = j + 0.5;
        p[2] = p[0] + 2 * p[1];
        uint32_t o = np++, q[4] = {a, b, c, d};
        for (int k = 0; k < 4; k++) {
          t[3 * nt] = q[k], t[3 * nt + 1] = q[(k + 1) % 4], t[3 * nt + 2] = o;
          m[nt++] = mk;
        }
        continue;
      }
      if (r < 4) {
        t[3 * nt] = a, t[3 * nt + 1] = b, t[3 * nt + 2] = c, m[nt++] = mk;
        t[3 * nt] = a, t[3 * nt + 1] = c, t[3 * nt + 2] = d, m[nt++] = mk;
      } else {
        t[3 * nt] = a, t[3 * nt + 1] = b, t[3 * nt + 2] = d, m[nt++] = mk;
        t[3 * nt] = b, t[3 * nt + 1] = c, t[3 * nt + 2] = d, m[nt++] = mk;
      }
    }
#undef V
  if (below(3) == 0 && nt) { /* a flipped triangle */
    uint32_t k = below(nt), s = t[3 * k];
    t[3 * k] = t[3 * k + 1];
    t[3 * k + 1] = s;
  }
  if (below(3) == 0 && nt) { /* a fin: a third triangle on an edge, off the plane */
    uint32_t k = below(nt);
    double *p = x + 3 * np;
    p[0] = 0.25, p[1] = 0.25, p[2] = 7;
    t[3 * nt] = t[3 * k + 1], t[3 * nt + 1] = t[3 * k], t[3 * nt + 2] = np++, m[nt++] = 0;
  }
  tr_plc *p = NULL;
  if (tr_plc_create(&p) != TR_OK || tr_plc_set(p, x, np, t, nt, m) != TR_OK)
    abort();
  free(x);
  free(t);
  free(m);
  return p;
}

static void t_sheets(void)
{
  uint64_t total = 0, seed = 1;
  uint32_t cases = 0, swapped = 0;
  for (int r = 0; r < 300; r++) {
    tr_plc *p = sheet(2 + below(12));
    uint64_t n = 0;
    char what[64];
    snprintf(what, sizeof what, "sheet %d incircle", r);
    agree(what, p, incircle, NULL, &n);
    total += n;
    swapped += n > 0;
    snprintf(what, sizeof what, "sheet %d hashed rule", r);
    seed = next();
    if (r % 10 == 0) /* the hashed rule may cycle: every pass to the limit */
      agree(what, p, hashed, &seed, &n);
    cases++;
    tr_plc_destroy(p);
  }
  EXPECT(swapped > cases / 2 && total > 1000,
         "sheets: only %u of %u sheets swapped, %llu swaps: the comparison tests little",
         swapped, cases, (unsigned long long)total);
}

/* The box [0, n]^3 with each face an n x n grid of unit squares cut by random diagonals
 * (every quad cocircular: the incircle rule swaps nothing), then some inner points moved
 * by -1/4, 0 or 1/4 along each face axis (quads no longer cocircular). */
static void t_boxes(void)
{
  uint64_t total = 0;
  for (int r = 0; r < 40; r++) {
    uint32_t n = 2 + below(6), nf = (n + 1) * (n + 1);
    double *x = malloc(sizeof *x * 3 * 6 * nf);
    uint32_t *t = malloc(sizeof *t * 3 * 12 * n * n);
    uint32_t np = 0, nt = 0;
    for (int f = 0; f < 6; f++) {
      int ax = f / 2, u = (ax + 1) % 3, v = (ax + 2) % 3;
      for (uint32_t j = 0; j <= n; j++)
        for (uint32_t i = 0; i <= n; i++) {
          double *p = x + 3 * np++;
          /* inner points with i and j even: no two in one square, so no triangle gets
           * two moved corners and none turns flat */
          int inner = i > 0 && i < n && j > 0 && j < n && i % 2 == 0 && j % 2 == 0;
          p[ax] = f % 2 ? n : 0;
          p[u] = i + (inner ? 0.25 * (double)below(3) - 0.25 : 0.0);
          p[v] = j + (inner ? 0.25 * (double)below(3) - 0.25 : 0.0);
        }
      uint32_t base = np - nf;
      for (uint32_t j = 0; j < n; j++)
        for (uint32_t i = 0; i < n; i++) {
          uint32_t a = base + j * (n + 1) + i, b = a + 1, c = b + n + 1, d = a + n + 1;
          if (below(2)) {
            t[3 * nt] = a, t[3 * nt + 1] = b, t[3 * nt + 2] = c, nt++;
            t[3 * nt] = a, t[3 * nt + 1] = c, t[3 * nt + 2] = d, nt++;
          } else {
            t[3 * nt] = a, t[3 * nt + 1] = b, t[3 * nt + 2] = d, nt++;
            t[3 * nt] = b, t[3 * nt + 1] = c, t[3 * nt + 2] = d, nt++;
          }
        }
    }
    tr_plc *p = NULL;
    if (tr_plc_create(&p) != TR_OK || tr_plc_set(p, x, np, t, nt, NULL) != TR_OK)
      abort();
    free(x);
    free(t);
    /* merges the shared border points and orients the faces outward */
    EXPECT(tr_plc_validate(p, NULL) == TR_OK, "box %d invalid: %s", r, tr_last_error());
    mpq_t v0, v1;
    mpq_init(v0);
    mpq_init(v1);
    tr_input_volume6(p, v0);
    uint64_t n0 = 0;
    char what[64];
    snprintf(what, sizeof what, "box %d", r);
    agree(what, p, incircle, NULL, &n0);
    total += n0;
    tr_plc *s = clone(p);
    uint64_t n1 = 0;
    EXPECT(tr_smooth_surface(s, &n1) == TR_OK && n1 == n0, "box %d: tr_smooth_surface %llu swaps",
           r, (unsigned long long)n1);
    tr_input_volume6(s, v1);
    EXPECT(mpq_equal(v0, v1), "box %d: smoothing changed the enclosed volume", r);
    EXPECT(tr_plc_validate(s, NULL) == TR_OK, "box %d smoothed invalid: %s", r, tr_last_error());
    EXPECT(tr_smooth_surface(s, &n1) == TR_OK && n1 == 0, "box %d: not at a fixed point", r);
    mpq_clear(v0);
    mpq_clear(v1);
    tr_plc_destroy(s);
    tr_plc_destroy(p);
  }
  EXPECT(total > 200, "boxes: %llu swaps in all: the comparison tests little",
         (unsigned long long)total);
}

/* A rule that always says yes undoes each swap in the next pass: both paths run
 * TR_SMOOTH_MAX_PASSES passes and end on the same triangles. */
static int always(void *user, const double *const q[4], uint32_t A, uint32_t B, uint32_t C,
                  uint32_t D)
{
  (void)user, (void)q, (void)A, (void)B, (void)C, (void)D;
  return 1;
}

static void t_cycle(void)
{
  /* two triangles on a square: one swap per pass, back and forth */
  const double x[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const uint32_t t[] = {0, 1, 2, 0, 2, 3};
  tr_plc *p = NULL;
  if (tr_plc_create(&p) != TR_OK || tr_plc_set(p, x, 4, t, 2, NULL) != TR_OK)
    abort();
  uint64_t n = 0;
  agree("square, always", p, always, NULL, &n);
  EXPECT(n == TR_SMOOTH_MAX_PASSES, "square: %llu swaps, want one per pass (%d)",
         (unsigned long long)n, TR_SMOOTH_MAX_PASSES);
  tr_plc_destroy(p);
  for (int r = 0; r < 20; r++) {
    p = sheet(3 + below(6));
    agree("sheet, always", p, always, NULL, &n);
    tr_plc_destroy(p);
  }
}

/* A strip of k thin rhombi along x, rhombus i = (2i,0) (2i+1,-1/2) (2i+2,0) (2i+1,1/2) cut
 * along its long diagonal; neighbours share a corner, so a pass swaps only every other
 * one and the rest wait for the next pass (its worklist): k swaps in all, each to the
 * short diagonal. */
static void t_fan(void)
{
  for (uint32_t k = 1; k <= 6; k++) {
    /* rhombus i: (2i,0) (2i+1,-1) (2i+2,0) (2i+1,1); neighbours share (2i+2,0) */
    uint32_t np = 3 * k + 1, nt = 2 * k;
    double *x = calloc(3 * (size_t)np, sizeof *x);
    uint32_t *t = malloc(sizeof *t * 3 * nt);
    for (uint32_t i = 0; i <= k; i++)
      x[3 * i] = 2.0 * i;
    for (uint32_t i = 0; i < k; i++) {
      uint32_t lo = k + 1 + 2 * i, hi = lo + 1;
      x[3 * lo] = 2.0 * i + 1, x[3 * lo + 1] = -0.5;
      x[3 * hi] = 2.0 * i + 1, x[3 * hi + 1] = 0.5;
      t[6 * i] = i, t[6 * i + 1] = i + 1, t[6 * i + 2] = hi;
      t[6 * i + 3] = i + 1, t[6 * i + 4] = i, t[6 * i + 5] = lo;
    }
    tr_plc *p = NULL;
    if (tr_plc_create(&p) != TR_OK || tr_plc_set(p, x, np, t, nt, NULL) != TR_OK)
      abort();
    free(x);
    free(t);
    uint64_t n = 0;
    agree("rhombus strip", p, incircle, NULL, &n);
    EXPECT(n == k, "rhombus strip of %u: %llu swaps, want %u", k, (unsigned long long)n, k);
    EXPECT(tr_smooth_surface(p, &n) == TR_OK && n == k, "rhombus strip of %u: %llu swaps", k,
           (unsigned long long)n);
    int vertical = 0; /* triangles holding a short diagonal (2i+1, +-1/2) */
    for (uint32_t t2 = 0; t2 < nt; t2++) {
      const uint32_t *v = p->tris + 3 * (size_t)t2;
      int lo = 0, hi = 0;
      for (int c = 0; c < 3; c++)
        lo |= v[c] > k && (v[c] - k - 1) % 2 == 0, hi |= v[c] > k && (v[c] - k - 1) % 2 == 1;
      vertical += lo && hi;
    }
    EXPECT(vertical == (int)nt, "rhombus strip of %u: %d of %u triangles on a short diagonal",
           k, vertical, nt);
    tr_plc_destroy(p);
  }
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"sheets", t_sheets, NULL},
      {"boxes", t_boxes, NULL},
      {"cycle", t_cycle, NULL},
      {"fan", t_fan, NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof cases[0]);
}
