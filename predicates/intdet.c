/* Exact insphere in fixed-width integers.
 *
 * Points on a sphere (or any nearly cospherical set) make |insphere| a few eps times
 * its permanent for most tests among close points: no floating filter can decide them
 * and the expansion stages, with their hundreds of two-sums and splits, dominated the
 * Delaunay build (87% of it on 2.5x10^5 points on a sphere). Yet their differences are
 * usually short: coordinates of close points share their binade, so p - e is an exact
 * double, and all twelve are integers below 2^62 times one power of two 2^-s. The
 * determinant is homogeneous of degree 5, so its sign is that of the integer
 * determinant, which has at most 317 bits:
 *   |d| < 2^62, minors |m| < 2 * 2^124 = 2^125 (int128),
 *   M = z m + z m + z m: |M| < 3 * 2^187 < 2^189 (three 64-bit limbs),
 *   lifts l = x^2 + y^2 + z^2 < 3 * 2^124 < 2^126 (unsigned int128),
 *   (l_a M_a - l_b M_b) + (l_c M_c - l_d M_d): |.| < 4 * 2^315 = 2^317 (five limbs).
 * Every limb array is two's complement modulo 2^(64 n): sums and products of residues
 * are the residues of the exact results, and the true values fit the signed range, so
 * the top bit of the last limb is the sign. No branch depends on the data's signs
 * (masks instead: random signs would mispredict).
 * When the rounded differences are not exact, the raw coordinates may still be
 * integers below 2^61 times one 2^-s; their int64 differences are then exact and
 * below 2^62. Otherwise (coordinates spanning more than 61 bits) the caller goes on
 * with expansions. */
#include "intdet.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#ifdef __SIZEOF_INT128__

__extension__ typedef __int128 i128;
__extension__ typedef unsigned __int128 u128;

/* out[i] = x[i] * 2^s exactly with |out[i]| < 2^k, s common to all (2^(k-1) <= the
 * largest |x[i]| * 2^s); 0 if some x[i] * 2^s is not an integer or 2^s is not a
 * normal double. */
static int to_int(int n, const double *x, int k, int64_t *out, int *s)
{
  double m = 0;
  for (int i = 0; i < n; i++) {
    const double a = fabs(x[i]);
    m = a > m ? a : m;
  }
  if (m == 0) {
    memset(out, 0, (size_t)n * sizeof *out);
    *s = 0;
    return 1;
  }
  uint64_t bits;
  memcpy(&bits, &m, sizeof bits);
  const int biased = (int)(bits >> 52 & 0x7ff);
  if (biased == 0 || biased == 0x7ff)
    return 0;
  const int sh = k - (biased - 1022); /* 2^(e-1) <= m < 2^e, e = biased - 1022 */
  if (sh < -1022 || sh > 1023)
    return 0;
  const uint64_t sbits = (uint64_t)(sh + 1023) << 52;
  double sc;
  memcpy(&sc, &sbits, sizeof sc);
  for (int i = 0; i < n; i++) {
    /* exact unless it underflows; an underflowed product is below 1, so it is either
     * a nonzero fraction or a 0 from a nonzero x: both rejected */
    const double t = x[i] * sc;
    const int64_t v = (int64_t)t; /* |t| < 2^k <= 2^62: defined */
    if ((double)v != t || (v == 0 && x[i] != 0))
      return 0;
    out[i] = v;
  }
  *s = sh;
  return 1;
}

/* acc += a * b modulo 2^192 (|a| < 2^63, |b| < 2^127). */
static inline void addmul3(uint64_t acc[3], int64_t a, i128 b)
{
  const uint64_t sa = -(uint64_t)(a < 0), sb = -(uint64_t)(b < 0);
  const uint64_t ua = ((uint64_t)a ^ sa) - sa;
  const u128 ub = ((u128)b ^ (((u128)sb << 64) | sb)) + (u128)(sb & 1);
  const u128 p0 = (u128)ua * (uint64_t)ub, p1 = (u128)ua * (uint64_t)(ub >> 64);
  const u128 t = (p0 >> 64) + (uint64_t)p1;
  const uint64_t r0 = (uint64_t)p0, r1 = (uint64_t)t,
                 r2 = (uint64_t)(t >> 64) + (uint64_t)(p1 >> 64);
  /* add -r as ~r + 1 when the signs differ */
  const uint64_t neg = sa ^ sb;
  u128 c = (u128)acc[0] + (r0 ^ neg) + (neg & 1);
  acc[0] = (uint64_t)c;
  c = (c >> 64) + acc[1] + (r1 ^ neg);
  acc[1] = (uint64_t)c;
  acc[2] += (uint64_t)(c >> 64) + (r2 ^ neg);
}

/* acc += (-1)^negate * m * l modulo 2^320 (m signed, |m| < 2^191; l < 2^128). */
static inline void addmul5(uint64_t acc[5], const uint64_t m[3], u128 l, uint64_t negate)
{
  const uint64_t sm = -(m[2] >> 63);
  u128 c = (u128)(m[0] ^ sm) + (sm & 1);
  const uint64_t a0 = (uint64_t)c;
  c = (c >> 64) + (m[1] ^ sm);
  const uint64_t a1 = (uint64_t)c;
  const uint64_t a2 = (uint64_t)(c >> 64) + (m[2] ^ sm);
  const uint64_t l0 = (uint64_t)l, l1 = (uint64_t)(l >> 64);
  uint64_t r[5];
  u128 p = (u128)a0 * l0;
  r[0] = (uint64_t)p;
  p = (u128)a1 * l0 + (uint64_t)(p >> 64);
  r[1] = (uint64_t)p;
  p = (u128)a2 * l0 + (uint64_t)(p >> 64);
  r[2] = (uint64_t)p;
  r[3] = (uint64_t)(p >> 64);
  p = (u128)a0 * l1 + r[1];
  r[1] = (uint64_t)p;
  p = (u128)a1 * l1 + r[2] + (uint64_t)(p >> 64);
  r[2] = (uint64_t)p;
  p = (u128)a2 * l1 + r[3] + (uint64_t)(p >> 64);
  r[3] = (uint64_t)p;
  r[4] = (uint64_t)(p >> 64);
  const uint64_t neg = sm ^ -(negate & 1);
  c = (neg & 1);
  for (int i = 0; i < 5; i++) {
    c += (u128)acc[i] + (r[i] ^ neg);
    acc[i] = (uint64_t)c;
    c >>= 64;
  }
}

static inline i128 minor2(int64_t a, int64_t b, int64_t c, int64_t d)
{
  return (i128)a * b - (i128)c * d;
}

static inline u128 lift(int64_t x, int64_t y, int64_t z)
{
  return (u128)((i128)x * x) + (u128)((i128)y * y) + (u128)((i128)z * z);
}

/* The insphere determinant of integer differences (|d| < 2^62), as five limbs. */
static void insphere_int(const int64_t d[12], uint64_t acc[5])
{
  const int64_t ax = d[0], ay = d[1], az = d[2], bx = d[3], by = d[4], bz = d[5];
  const int64_t cx = d[6], cy = d[7], cz = d[8], dx = d[9], dy = d[10], dz = d[11];
  const i128 ab = minor2(ax, by, bx, ay), ac = minor2(ax, cy, cx, ay);
  const i128 ad = minor2(ax, dy, dx, ay), bc = minor2(bx, cy, cx, by);
  const i128 bd = minor2(bx, dy, dx, by), cd = minor2(cx, dy, dx, cy);
  uint64_t M[4][3] = {{0}};
  addmul3(M[0], bz, cd);
  addmul3(M[0], -cz, bd);
  addmul3(M[0], dz, bc);
  addmul3(M[1], az, cd);
  addmul3(M[1], -cz, ad);
  addmul3(M[1], dz, ac);
  addmul3(M[2], az, bd);
  addmul3(M[2], -bz, ad);
  addmul3(M[2], dz, ab);
  addmul3(M[3], az, bc);
  addmul3(M[3], -bz, ac);
  addmul3(M[3], cz, ab);
  memset(acc, 0, 5 * sizeof *acc);
  addmul5(acc, M[0], lift(ax, ay, az), 0);
  addmul5(acc, M[1], lift(bx, by, bz), 1);
  addmul5(acc, M[2], lift(cx, cy, cz), 0);
  addmul5(acc, M[3], lift(dx, dy, dz), 1);
}

/* A double with the sign of the five-limb value times 2^-5s, magnitude approximate
 * (clamped to the smallest subnormal / DBL_MAX rather than 0 or infinity). */
static double limbs_value(const uint64_t acc[5], int s)
{
  const uint64_t sg = -(acc[4] >> 63);
  uint64_t x[5];
  u128 c = sg & 1;
  for (int i = 0; i < 5; i++) {
    c += (u128)(acc[i] ^ sg);
    x[i] = (uint64_t)c;
    c >>= 64;
  }
  double v = 0;
  for (int i = 4; i >= 0; i--)
    v = v * 0x1p64 + (double)x[i];
  if (v == 0)
    return 0;
  v = ldexp(v, -5 * s);
  if (v == 0)
    v = 0x1p-1074;
  else if (isinf(v))
    v = DBL_MAX;
  return sg ? -v : v;
}

int tr_insphere_int(const double *const p[5], const double dv[12], int exact_diffs,
                    double *out)
{
  int64_t d[12];
  int s;
  if (!(exact_diffs && to_int(12, dv, 62, d, &s))) {
    double raw[15];
    int64_t r[15];
    for (int i = 0; i < 5; i++)
      for (int j = 0; j < 3; j++)
        raw[3 * i + j] = p[i][j];
    if (!to_int(15, raw, 61, r, &s))
      return 0;
    for (int i = 0; i < 4; i++)
      for (int j = 0; j < 3; j++)
        d[3 * i + j] = r[3 * i + j] - r[12 + j]; /* |.| < 2^62 */
  }
  uint64_t acc[5];
  insphere_int(d, acc);
  *out = limbs_value(acc, s);
  return 1;
}

#else

int tr_insphere_int(const double *const p[5], const double dv[12], int exact_diffs,
                    double *out)
{
  (void)p;
  (void)dv;
  (void)exact_diffs;
  (void)out;
  return 0;
}

#endif
