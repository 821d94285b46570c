/* Test support for the predicate tests: a deterministic RNG, an exact reference
 * written independently of the library (GMP rationals from the exact doubles,
 * determinants of coordinate differences by cofactor expansion, the definitions in
 * predicates.h), and input generators. */
#ifndef TR_TEST_PRED_REF_H
#define TR_TEST_PRED_REF_H

#include <gmp.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

/* ---- RNG (splitmix64): same sequence on every machine ---- */
typedef struct {
  uint64_t s;
} rng_t;

static inline uint64_t rng_u64(rng_t *r)
{
  uint64_t z = (r->s += 0x9e3779b97f4a7c15ull);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}
static inline double rng_unit(rng_t *r) { return (double)(rng_u64(r) >> 11) * 0x1p-53; }
static inline int rng_int(rng_t *r, int lo, int hi) /* inclusive */
{
  return lo + (int)(rng_u64(r) % (uint64_t)(hi - lo + 1));
}

/* ---- exact reference ---- */
/* out = det of the n x n (n <= 4) rational matrix m (row-major), cofactor expansion
 * along the first row. */
static void ref_det(int n, mpq_t *m, mpq_t out)
{
  if (n == 1) {
    mpq_set(out, m[0]);
    return;
  }
  mpq_t sub[9], t;
  for (int i = 0; i < (n - 1) * (n - 1); i++)
    mpq_init(sub[i]);
  mpq_init(t);
  mpq_set_ui(out, 0, 1);
  for (int j = 0; j < n; j++) {
    int k = 0;
    for (int r = 1; r < n; r++)
      for (int c = 0; c < n; c++)
        if (c != j)
          mpq_set(sub[k++], m[r * n + c]);
    ref_det(n - 1, sub, t);
    mpq_mul(t, t, m[j]);
    if (j % 2)
      mpq_sub(out, out, t);
    else
      mpq_add(out, out, t);
  }
  for (int i = 0; i < (n - 1) * (n - 1); i++)
    mpq_clear(sub[i]);
  mpq_clear(t);
}

/* Sign of det of the rows (p[i] - p[base]) over `dim` coordinates, i != base, with an
 * optional lifted column |p[i] - p[base]|^2. */
static int ref_diff_det_sign(int np, int dim, int lifted, int base, const double (*p)[3])
{
  const int n = dim + lifted;
  mpq_t m[16], x, y, out;
  for (int i = 0; i < n * n; i++)
    mpq_init(m[i]);
  mpq_init(x);
  mpq_init(y);
  mpq_init(out);
  int r = 0;
  for (int i = 0; i < np; i++) {
    if (i == base)
      continue;
    if (lifted)
      mpq_set_ui(m[r * n + dim], 0, 1);
    for (int j = 0; j < dim; j++) {
      mpq_set_d(x, p[i][j]);
      mpq_set_d(y, p[base][j]);
      mpq_sub(m[r * n + j], x, y);
      if (lifted) {
        mpq_mul(x, m[r * n + j], m[r * n + j]);
        mpq_add(m[r * n + dim], m[r * n + dim], x);
      }
    }
    r++;
  }
  ref_det(n, m, out);
  int s = mpq_sgn(out);
  for (int i = 0; i < n * n; i++)
    mpq_clear(m[i]);
  mpq_clear(x);
  mpq_clear(y);
  mpq_clear(out);
  return s;
}

/* The definitions of predicates.h. */
static inline int ref_orient2d(const double (*p)[3]) { return ref_diff_det_sign(3, 2, 0, 0, p); }
static inline int ref_orient3d(const double (*p)[3]) { return ref_diff_det_sign(4, 3, 0, 0, p); }
/* incircle = det[a-d, b-d, c-d with lifts]; insphere = -det[a-e, ..., d-e with lifts]
 * (the sign that makes e inside positive for a positive tet; see test_predicates.c,
 * "conventions"). */
static inline int ref_incircle(const double (*p)[3]) { return ref_diff_det_sign(4, 2, 1, 3, p); }
static inline int ref_insphere(const double (*p)[3])
{
  return -ref_diff_det_sign(5, 3, 1, 4, p);
}

static inline int sgn(double x) { return (x > 0) - (x < 0); }

#define CHECK(cond, ...)                    \
  do {                                      \
    if (!(cond)) {                          \
      if (fails < 10) {                     \
        fprintf(stderr, "FAIL: " __VA_ARGS__); \
        fputc('\n', stderr);                \
      }                                     \
      fails++;                              \
    }                                       \
  } while (0)

#endif
