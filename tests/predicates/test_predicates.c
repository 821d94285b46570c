/* orient2d, orient3d, incircle, insphere (and orient2d_proj): exact signs against an
 * in-test GMP evaluation of the defining determinants (ref.h), exact zeros on
 * degenerate configurations, one-ulp perturbations, scaling by powers of two,
 * translation by large offsets, extreme and subnormal magnitudes, antisymmetry.
 * Usage: test_predicates <predicate> <property>. */
#include "predicates.h"
#include "ref.h"

#include <stdlib.h>
#include <string.h>

static int fails;

typedef double (*pfn)(const double (*p)[3]);
typedef struct {
  const char *name;
  int np, dim, lifted;
  pfn fn, exact;
  int (*ref)(const double (*p)[3]);
} pred_t;

static double w_o2(const double (*p)[3]) { return tr_orient2d(p[0], p[1], p[2]); }
static double w_o2x(const double (*p)[3]) { return tr_orient2d_exact(p[0], p[1], p[2]); }
static double w_o3(const double (*p)[3]) { return tr_orient3d(p[0], p[1], p[2], p[3]); }
static double w_o3x(const double (*p)[3]) { return tr_orient3d_exact(p[0], p[1], p[2], p[3]); }
/* orient3d through the cached plane of (p0, p1, p2): its filter, then the adaptive
 * stages; the filter's value must also be tr_orient3d_filter(p0, p3, p1, p2)'s, bit for bit */
static double w_o3p(const double (*p)[3])
{
  tr_o3plane P;
  tr_o3plane_init(&P, p[0], p[1], p[2]);
  double det, det2;
  int ok = tr_o3plane_filter(&P, p[0], p[3], &det);
  int ok2 = tr_orient3d_filter(p[0], p[3], p[1], p[2], &det2);
  if (ok != ok2 || memcmp(&det, &det2, sizeof det)) {
    fprintf(stderr, "o3plane: filter %d %a, tr_orient3d_filter %d %a\n", ok, det, ok2, det2);
    fails++;
  }
  return ok ? det : tr_orient3d_adapt(p[0], p[1], p[2], p[3]);
}
static double w_ic(const double (*p)[3]) { return tr_incircle(p[0], p[1], p[2], p[3]); }
static double w_icx(const double (*p)[3]) { return tr_incircle_exact(p[0], p[1], p[2], p[3]); }
static double w_is(const double (*p)[3]) { return tr_insphere(p[0], p[1], p[2], p[3], p[4]); }
static double w_isx(const double (*p)[3])
{
  return tr_insphere_exact(p[0], p[1], p[2], p[3], p[4]);
}

static const pred_t preds[] = {
    {"orient2d", 3, 2, 0, w_o2, w_o2x, ref_orient2d},
    {"orient3d", 4, 3, 0, w_o3, w_o3x, ref_orient3d},
    {"orient3d_plane", 4, 3, 0, w_o3p, w_o3x, ref_orient3d},
    {"incircle", 4, 2, 1, w_ic, w_icx, ref_incircle},
    {"insphere", 5, 3, 1, w_is, w_isx, ref_insphere},
};

/* ---- generators: pts[np][3], unused coordinates 0 ---- */
typedef double pts_t[5][3];

/* Integer points on the circle x^2+y^2 = R2 or the sphere x^2+y^2+z^2 = R3. */
enum { R2 = 5525, R3 = 1225 };
static int circle[256][2], ncircle, sphere[512][3], nsphere;

static void init_tables(void)
{
  for (int x = -80; x <= 80; x++)
    for (int y = -80; y <= 80; y++)
      if (x * x + y * y == R2 && ncircle < 256) {
        circle[ncircle][0] = x;
        circle[ncircle++][1] = y;
      }
  for (int x = -35; x <= 35; x++)
    for (int y = -35; y <= 35; y++)
      for (int z = -35; z <= 35; z++)
        if (x * x + y * y + z * z == R3 && nsphere < 512) {
          sphere[nsphere][0] = x;
          sphere[nsphere][1] = y;
          sphere[nsphere++][2] = z;
        }
}

static void gen_uniform(const pred_t *P, rng_t *r, pts_t p)
{
  memset(p, 0, sizeof(pts_t));
  for (int i = 0; i < P->np; i++)
    for (int j = 0; j < P->dim; j++)
      p[i][j] = rng_unit(r);
}

static void gen_grid(const pred_t *P, rng_t *r, pts_t p)
{
  memset(p, 0, sizeof(pts_t));
  for (int i = 0; i < P->np; i++)
    for (int j = 0; j < P->dim; j++)
      p[i][j] = rng_int(r, -3, 3);
}

/* An exactly degenerate configuration (collinear / coplanar / cocircular /
 * cospherical), on small integers scaled by 2^k and shifted by an integer offset
 * times 2^k: every coordinate stays exact. Also returns the center (for circles and
 * spheres) in *ctr. */
static void gen_degenerate(const pred_t *P, rng_t *r, pts_t p, double ctr[3], int k)
{
  memset(p, 0, sizeof(pts_t));
  int off[3] = {rng_int(r, -50, 50), rng_int(r, -50, 50), rng_int(r, -50, 50)};
  int u[3] = {rng_int(r, -5, 5), rng_int(r, -5, 5), rng_int(r, -5, 5)};
  int v[3] = {rng_int(r, -5, 5), rng_int(r, -5, 5), rng_int(r, -5, 5)};
  for (int i = 0; i < P->np; i++) {
    int s = rng_int(r, -6, 6), t = rng_int(r, -6, 6), q[3];
    if (P->lifted && P->dim == 2) {
      const int *c = circle[rng_int(r, 0, ncircle - 1)];
      q[0] = c[0];
      q[1] = c[1];
      q[2] = 0;
    } else if (P->lifted) {
      const int *c = sphere[rng_int(r, 0, nsphere - 1)];
      q[0] = c[0];
      q[1] = c[1];
      q[2] = c[2];
    } else {
      for (int j = 0; j < 3; j++)
        q[j] = s * u[j] + (P->dim == 3 ? t * v[j] : 0);
    }
    for (int j = 0; j < P->dim; j++)
      p[i][j] = ldexp((double)(q[j] + off[j]), k);
  }
  for (int j = 0; j < 3; j++)
    ctr[j] = ldexp((double)off[j], k);
}

/* Degenerate, then one coordinate moved by 1..3 ulps. */
static void gen_near(const pred_t *P, rng_t *r, pts_t p)
{
  double ctr[3];
  gen_degenerate(P, r, p, ctr, rng_int(r, -30, 30));
  int i = rng_int(r, 0, P->np - 1), j = rng_int(r, 0, P->dim - 1), n = rng_int(r, 1, 3);
  double dir = (rng_u64(r) & 1) ? INFINITY : -INFINITY;
  for (int m = 0; m < n; m++)
    p[i][j] = nextafter(p[i][j], dir);
}

/* Coordinates of very different magnitudes: each point (or each coordinate) is a
 * random value times 2^k, k in [-520, 520], sometimes subnormal or zero; or one axis
 * subnormal and the others ordinary (points near a face at 0 moved by subnormals: the
 * GMP fallback scales each column of an orientation on its own). */
static void gen_magnitudes(const pred_t *P, rng_t *r, pts_t p)
{
  memset(p, 0, sizeof(pts_t));
  int mode = rng_int(r, 0, 5), kp = rng_int(r, -520, 520);
  if (mode == 5) {
    int axis = rng_int(r, 0, P->dim - 1);
    for (int i = 0; i < P->np; i++)
      for (int j = 0; j < P->dim; j++)
        p[i][j] = j == axis ? rng_int(r, -4, 4) * 0x1p-1074 * (double)(1 << rng_int(r, 0, 3))
                            : (double)rng_int(r, 0, 64) / 4 + (rng_unit(r) < 0.5 ? 0x1p-40 : 0);
    return;
  }
  for (int i = 0; i < P->np; i++) {
    int k = mode == 0 ? kp : rng_int(r, -520, 520);
    for (int j = 0; j < P->dim; j++) {
      double m = rng_unit(r) - 0.5;
      if (mode == 1)
        k = rng_int(r, -520, 520);
      if (mode == 2) /* 1e-150 .. 1e150 with a small integer structure */
        p[i][j] = rng_int(r, -3, 3) * ((i + j) % 2 ? 1e150 : 1e-150);
      else if (mode == 3) /* subnormal */
        p[i][j] = rng_int(r, -4, 4) * 0x1p-1074 * (double)(1 << rng_int(r, 0, 20));
      else
        p[i][j] = ldexp(m, k);
    }
  }
  if (mode == 4) { /* a degenerate set at a huge or tiny scale */
    double ctr[3];
    gen_degenerate(P, r, p, ctr, rng_int(r, 0, 1) ? rng_int(r, 400, 900) : rng_int(r, -1000, -400));
  }
}

/* Nearly degenerate in floating point: the last point is a rounded point of the
 * line / plane / circle / sphere through the others (random real coordinates), then
 * moved by 0..2 ulps. Floating evaluation gets such signs wrong; only a sound filter
 * and exact stages get them right. */
static void gen_rounded(const pred_t *P, rng_t *r, pts_t p)
{
  gen_uniform(P, r, p);
  const int last = P->np - 1;
  double *a = p[0], *b = p[1], *c = p[2], *d = p[3];
  if (!P->lifted) {
    double s = rng_unit(r) * 4 - 2, t = rng_unit(r) * 4 - 2;
    for (int j = 0; j < P->dim; j++)
      p[last][j] = a[j] + s * (b[j] - a[j]) + (P->dim == 3 ? t * (c[j] - a[j]) : 0);
  } else if (P->dim == 2) {
    double bx = b[0] - a[0], by = b[1] - a[1], cx = c[0] - a[0], cy = c[1] - a[1];
    double den = 2 * (bx * cy - by * cx), lb = bx * bx + by * by, lc = cx * cx + cy * cy;
    double ox = (cy * lb - by * lc) / den, oy = (bx * lc - cx * lb) / den;
    double rad = sqrt(ox * ox + oy * oy), th = rng_unit(r) * 6.283185307179586;
    p[last][0] = a[0] + ox + rad * cos(th);
    p[last][1] = a[1] + oy + rad * sin(th);
  } else {
    double u[3], v[3], w[3], l[3];
    for (int j = 0; j < 3; j++) {
      u[j] = b[j] - a[j];
      v[j] = c[j] - a[j];
      w[j] = d[j] - a[j];
    }
    l[0] = (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) / 2;
    l[1] = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) / 2;
    l[2] = (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) / 2;
#define DET3(r0, r1, r2)                                                                  \
  ((r0)[0] * ((r1)[1] * (r2)[2] - (r1)[2] * (r2)[1]) -                                   \
   (r0)[1] * ((r1)[0] * (r2)[2] - (r1)[2] * (r2)[0]) +                                   \
   (r0)[2] * ((r1)[0] * (r2)[1] - (r1)[1] * (r2)[0]))
    double D = DET3(u, v, w), o[3];
    for (int k = 0; k < 3; k++) {
      double U[3] = {u[0], u[1], u[2]}, V[3] = {v[0], v[1], v[2]}, W[3] = {w[0], w[1], w[2]};
      U[k] = l[0];
      V[k] = l[1];
      W[k] = l[2];
      o[k] = DET3(U, V, W) / D;
    }
#undef DET3
    double rad = sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
    double z = rng_unit(r) * 2 - 1, th = rng_unit(r) * 6.283185307179586, q = sqrt(1 - z * z);
    double dir[3] = {q * cos(th), q * sin(th), z};
    for (int j = 0; j < 3; j++)
      p[last][j] = a[j] + o[j] + rad * dir[j];
  }
  int j = rng_int(r, 0, P->dim - 1), n = rng_int(r, 0, 2);
  double to = (rng_u64(r) & 1) ? INFINITY : -INFINITY;
  for (int m = 0; m < n; m++)
    p[last][j] = nextafter(p[last][j], to);
}

/* Integer configurations with up to ~2^30-wide coordinates: degenerate (line, plane,
 * or for the lifted predicates a degenerate set scaled up) and sometimes moved by one
 * unit. They straddle the limits of the "exactly representable" stage (2^16 and 2^9
 * quanta), where a wrong limit would round products and give wrong signs. */
static void gen_bigint(const pred_t *P, rng_t *r, pts_t p)
{
  memset(p, 0, sizeof(pts_t));
  int bu = rng_int(r, 0, 15), bs = rng_int(r, 0, 15);
  long long u[3], v[3], o[3];
  for (int j = 0; j < 3; j++) {
    u[j] = rng_int(r, -(1 << bu), 1 << bu);
    v[j] = rng_int(r, -(1 << bu), 1 << bu);
    o[j] = rng_int(r, -(1 << 20), 1 << 20);
  }
  for (int i = 0; i < P->np; i++) {
    long long s = rng_int(r, -(1 << bs), 1 << bs), t = rng_int(r, -(1 << bs), 1 << bs);
    if (P->dim == 2 && !P->lifted)
      t = 0;
    for (int j = 0; j < P->dim; j++)
      p[i][j] = (double)(o[j] + s * u[j] + t * v[j]);
  }
  if (P->lifted) { /* a cocircular / cospherical set scaled by an integer */
    double ctr[3];
    gen_degenerate(P, r, p, ctr, 0);
    double f = (double)rng_int(r, 1, 1 << rng_int(r, 0, 12));
    for (int i = 0; i < P->np; i++)
      for (int j = 0; j < P->dim; j++)
        p[i][j] *= f;
  }
  if (rng_u64(r) & 1)
    p[rng_int(r, 0, P->np - 1)][rng_int(r, 0, P->dim - 1)] += (rng_u64(r) & 1) ? 1 : -1;
}

/* A small configuration translated by an offset around 1e8 (rounded coordinates). */
static void gen_translated(const pred_t *P, rng_t *r, pts_t p)
{
  double ctr[3];
  if (rng_u64(r) & 1)
    gen_degenerate(P, r, p, ctr, -20);
  else
    for (int i = 0; i < P->np; i++)
      for (int j = 0; j < P->dim; j++)
        p[i][j] = rng_unit(r) * 1e-3;
  double off[3] = {1e8 * (1 + rng_unit(r)), -1e8 * (1 + rng_unit(r)), 1e8};
  for (int i = 0; i < P->np; i++)
    for (int j = 0; j < P->dim; j++)
      p[i][j] += off[j];
}

static void check_vs_ref(const pred_t *P, const pts_t p, const char *what)
{
  int s = sgn(P->fn((const double(*)[3])p)), e = P->ref((const double(*)[3])p);
  CHECK(s == e, "%s %s: sign %d, exact %d, first point (%a, %a, %a)", P->name, what, s, e,
        p[0][0], p[0][1], p[0][2]);
}

/* ---- properties ---- */

/* 10^5 random / degenerate / near-degenerate / extreme inputs against the GMP
 * reference. */
static void prop_random(const pred_t *P)
{
  rng_t r = {11 + (uint64_t)P->np * 7 + (uint64_t)P->lifted};
  pts_t p;
  double ctr[3];
  for (int i = 0; i < 100000; i++) {
    switch (i % 8) {
    case 7: gen_bigint(P, &r, p); break;
    case 6: gen_rounded(P, &r, p); break;
    case 0: gen_uniform(P, &r, p); break;
    case 1: gen_grid(P, &r, p); break;
    case 2: gen_degenerate(P, &r, p, ctr, rng_int(&r, -40, 40)); break;
    case 3: gen_near(P, &r, p); break;
    case 4: gen_magnitudes(P, &r, p); break;
    default: gen_translated(P, &r, p); break;
    }
    check_vs_ref(P, p, "random/degenerate case");
  }
}

/* The exact stage alone agrees with the reference. */
static void prop_exact_stage(const pred_t *P)
{
  rng_t r = {23 + (uint64_t)P->np};
  pts_t p;
  for (int i = 0; i < 20000; i++) {
    switch (i % 4) {
    case 0: gen_rounded(P, &r, p); break;
    case 1: gen_near(P, &r, p); break;
    case 2: gen_magnitudes(P, &r, p); break;
    default: gen_translated(P, &r, p); break;
    }
    int s = sgn(P->exact((const double(*)[3])p)), e = P->ref((const double(*)[3])p);
    CHECK(s == e, "%s exact stage: sign %d, reference %d", P->name, s, e);
  }
}

/* Exactly degenerate configurations give exactly 0, at every scale. */
static void prop_zero(const pred_t *P)
{
  rng_t r = {31 + (uint64_t)P->np};
  pts_t p;
  double ctr[3];
  for (int i = 0; i < 20000; i++) {
    int k = rng_int(&r, -900, 900);
    gen_degenerate(P, &r, p, ctr, k);
    double v = P->fn((const double(*)[3])p);
    CHECK(v == 0, "%s of a degenerate configuration scaled by 2^%d is %g, not 0", P->name, k, v);
  }
}

/* Moving one point by 1..3 ulps off the line / plane / circle / sphere gives the sign
 * predicted by the geometry of the move (independent of any determinant code), and
 * the reference agrees. */
static void prop_ulp(const pred_t *P)
{
  rng_t r = {41 + (uint64_t)P->np};
  pts_t p;
  double ctr[3];
  int nonzero = 0;
  for (int i = 0; i < 20000; i++) {
    gen_degenerate(P, &r, p, ctr, rng_int(&r, -30, 30));
    const int last = P->np - 1;
    int j = rng_int(&r, 0, P->dim - 1), n = rng_int(&r, 1, 3);
    double dir = (rng_u64(&r) & 1) ? 1.0 : -1.0;
    double old = p[last][j];
    for (int m = 0; m < n; m++)
      p[last][j] = nextafter(p[last][j], dir * INFINITY);
    /* Expected sign. Non-lifted: the determinant is linear in the moved coordinate,
     * with coefficient the cofactor, computed exactly on the integers below. Lifted:
     * power of the moved point with respect to the circle/sphere changes by
     * 2 (x_j - c_j) delta + delta^2, and the predicate is -sign(power) * orientation. */
    int expect;
    if (!P->lifted) {
      /* D(x) = (x - old) C with C the cofactor of the moved entry; C has the sign of
       * D(old + h) for any h > 0, here h = |old| or 1 (exact). */
      pts_t q;
      memcpy(q, p, sizeof q);
      q[last][j] = old + (old == 0 ? 1.0 : fabs(old));
      expect = P->ref((const double(*)[3])q) * (int)dir;
    } else {
      int orient = P->dim == 2 ? sgn(tr_orient2d(p[0], p[1], p[2]))
                               : sgn(tr_orient3d(p[0], p[1], p[2], p[3]));
      /* power change 2 (x_j - c_j) delta + delta^2: outward when moving away from the
       * center, and a tangent move (x_j == c_j) goes outward at second order. */
      int outward = old == ctr[j] ? 1 : sgn(old - ctr[j]) * (int)dir;
      expect = -outward * orient;
    }
    int s = sgn(P->fn((const double(*)[3])p));
    CHECK(s == expect, "%s one-ulp move (%d ulps, axis %d): sign %d, expected %d", P->name, n,
          j, s, expect);
    CHECK(P->ref((const double(*)[3])p) == expect, "%s reference disagrees with geometry",
          P->name);
    nonzero += expect != 0;
  }
  CHECK(nonzero > 5000, "%s: too few nonzero one-ulp cases (%d)", P->name, nonzero);
}

/* Scaling every coordinate by 2^k (when exact) does not change the sign. */
static void prop_scale(const pred_t *P)
{
  rng_t r = {53 + (uint64_t)P->np};
  pts_t p, q;
  double ctr[3];
  for (int i = 0; i < 5000; i++) {
    switch (i % 3) {
    case 0: gen_rounded(P, &r, p); break;
    case 1: gen_near(P, &r, p); break;
    default: gen_degenerate(P, &r, p, ctr, 0); break;
    }
    int s0 = sgn(P->fn((const double(*)[3])p));
    CHECK(s0 == P->ref((const double(*)[3])p), "%s unscaled sign wrong", P->name);
    for (int t = 0; t < 8; t++) {
      int k = rng_int(&r, -1100, 1000), exact = 1;
      for (int a = 0; a < P->np; a++)
        for (int b = 0; b < P->dim; b++) {
          q[a][b] = ldexp(p[a][b], k);
          exact &= isfinite(q[a][b]) && ldexp(q[a][b], -k) == p[a][b];
        }
      if (!exact)
        continue;
      int s = sgn(P->fn((const double(*)[3])q));
      CHECK(s == s0, "%s sign changed from %d to %d under scaling by 2^%d", P->name, s0, s, k);
    }
  }
}

/* Permuting the arguments multiplies the sign by the parity of the permutation. */
static void prop_antisymmetry(const pred_t *P)
{
  rng_t r = {61 + (uint64_t)P->np};
  pts_t p, q;
  double ctr[3];
  for (int i = 0; i < 10000; i++) {
    switch (i % 5) {
    case 0: gen_rounded(P, &r, p); break;
    case 1: gen_near(P, &r, p); break;
    case 2: gen_magnitudes(P, &r, p); break;
    case 3: gen_bigint(P, &r, p); break;
    default: gen_degenerate(P, &r, p, ctr, 0); break;
    }
    int perm[5] = {0, 1, 2, 3, 4}, parity = 1;
    for (int a = P->np - 1; a > 0; a--) {
      int b = rng_int(&r, 0, a);
      if (b != a) {
        int t = perm[a];
        perm[a] = perm[b];
        perm[b] = t;
        parity = -parity;
      }
    }
    for (int a = 0; a < P->np; a++)
      memcpy(q[a], p[perm[a]], sizeof q[a]);
    int s0 = sgn(P->fn((const double(*)[3])p)), s1 = sgn(P->fn((const double(*)[3])q));
    CHECK(s1 == parity * s0, "%s not antisymmetric: %d vs %d with parity %d", P->name, s0, s1,
          parity);
  }
}

/* ---- near-cospherical inputs (the Delaunay kernel's hard case) ----
 * They take insphere.c's fixed-width integer stage (intdet.c) or, when the coordinates
 * span too many bits for it, the expansion stages: both must match the reference. */

/* A standard normal (Box-Muller). */
static double rng_gauss(rng_t *r)
{
  const double u = 1.0 - rng_unit(r), v = rng_unit(r);
  return sqrt(-2.0 * log(u)) * cos(6.283185307179586 * v);
}

/* Five rounded points of the unit sphere within about 2^-k of each other (normalised
 * Gaussian directions around a random one), the way a sphere sample looks to the
 * Delaunay kernel; sometimes scaled by a power of two and/or translated, so that the
 * differences are exact (same binades), inexact (coordinates crossing 0 or binades)
 * or span more than 62 bits (a coordinate near 0). */
static void gen_sphere_cap(rng_t *r, pts_t p)
{
  double c[3], h = ldexp(1.0, -rng_int(r, 1, 24));
  for (int j = 0; j < 3; j++)
    c[j] = rng_gauss(r);
  if (rng_int(r, 0, 3) == 0) /* a centre direction in a coordinate plane: coordinates near 0 */
    c[rng_int(r, 0, 2)] = ldexp(rng_gauss(r), -rng_int(r, 10, 60));
  for (int i = 0; i < 5; i++) {
    double x[3], n = 0;
    for (int j = 0; j < 3; j++) {
      x[j] = c[j] + h * rng_gauss(r);
      n += x[j] * x[j];
    }
    n = sqrt(n);
    for (int j = 0; j < 3; j++)
      p[i][j] = x[j] / n;
  }
  const int mode = rng_int(r, 0, 3);
  if (mode == 1) {
    const int k = rng_int(r, -300, 300);
    for (int i = 0; i < 5; i++)
      for (int j = 0; j < 3; j++)
        p[i][j] = ldexp(p[i][j], k);
  } else if (mode == 2) { /* translated: rounded again, still near-cospherical */
    const double off[3] = {rng_int(r, -8, 8) * 0.5, rng_int(r, -8, 8) * 0.25, 3.0};
    for (int i = 0; i < 5; i++)
      for (int j = 0; j < 3; j++)
        p[i][j] += off[j];
  }
}

/* An exactly cospherical integer set (sphere table) scaled by 2^k and translated by a
 * multiple of 2^k up to 2^(k+b): differences are exact and short, raw coordinates
 * span b + 7 bits, across the integer stage's 61-bit limit for the raw form; one
 * coordinate sometimes moved by an ulp (then the differences may be inexact). */
static void gen_cospherical_offset(rng_t *r, pts_t p)
{
  const int k = rng_int(r, -200, 200), b = rng_int(r, 0, 64);
  double off[3];
  for (int j = 0; j < 3; j++)
    off[j] = ldexp((double)(rng_u64(r) >> 11) * 0x1p-53 * (rng_u64(r) & 1 ? 1 : -1), b);
  for (int i = 0; i < 5; i++) {
    const int *q = sphere[rng_int(r, 0, nsphere - 1)];
    for (int j = 0; j < 3; j++)
      p[i][j] = ldexp(floor(off[j]) + q[j], k);
  }
  if (rng_u64(r) & 1) {
    const int i = rng_int(r, 0, 4), j = rng_int(r, 0, 2);
    p[i][j] = nextafter(p[i][j], (rng_u64(r) & 1) ? INFINITY : -INFINITY);
  }
}

/* Coordinates at the integer stage's limits: differences that are full 53-bit
 * integers times 2^9 (|d| just below 2^62, every minor, M and lift near its bound), or
 * raw coordinates just below 2^61 with inexact differences, all signs mixed. */
static void gen_int_limits(rng_t *r, pts_t p)
{
  const int raw = rng_int(r, 0, 1), scale = rng_int(r, -100, 100);
  for (int i = 0; i < 5; i++)
    for (int j = 0; j < 3; j++) {
      double m = (double)(rng_u64(r) >> 11); /* < 2^53 */
      if (rng_u64(r) & 1)
        m = -m;
      if (raw)
        p[i][j] = ldexp(m, 7 + rng_int(r, 0, 1)); /* < 2^61 */
      else
        p[i][j] = i == 4 ? 0 : ldexp(m, 9); /* e = 0: d = a - e exact, < 2^62 */
      p[i][j] = ldexp(p[i][j], scale);
    }
  if (rng_u64(r) & 1) { /* make it nearly cospherical: e on the sphere through a..d */
    pts_t q;
    memcpy(q, p, sizeof q);
    for (int t = 0; t < 3; t++)
      q[4][t] = q[0][t];
    const int j = rng_int(r, 0, 2);
    q[4][j] = nextafter(q[4][j], INFINITY);
    memcpy(p, q, sizeof q);
  }
}

/* 40000 near-cospherical, exactly cospherical and limit-magnitude inputs against the
 * GMP reference, through tr_insphere and through the exact stage alone. */
static void prop_cospherical(const pred_t *P)
{
  rng_t r = {71};
  pts_t p;
  int zero = 0, nonzero = 0;
  for (int i = 0; i < 40000; i++) {
    switch (i % 4) {
    case 0:
    case 1: gen_sphere_cap(&r, p); break;
    case 2: gen_cospherical_offset(&r, p); break;
    default: gen_int_limits(&r, p); break;
    }
    check_vs_ref(P, p, "near-cospherical case");
    const int e = P->ref((const double(*)[3])p);
    CHECK(sgn(P->exact((const double(*)[3])p)) == e, "%s exact stage on a near-cospherical case",
          P->name);
    zero += e == 0;
    nonzero += e != 0;
  }
  CHECK(zero > 2000 && nonzero > 20000, "%s: too few cospherical (%d) or decided (%d) cases",
        P->name, zero, nonzero);
}

/* The documented sign conventions on explicit examples. */
static void prop_conventions(void)
{
  const double o[3] = {0, 0, 0}, x[3] = {1, 0, 0}, y[3] = {0, 1, 0}, z[3] = {0, 0, 1};
  const double in[3] = {0.25, 0.25, 0.25}, out[3] = {2, 2, 2};
  CHECK(tr_orient3d(o, x, y, z) > 0, "orient3d(o, x, y, z) must be positive");
  CHECK(tr_orient3d(o, y, x, z) < 0, "orient3d(o, y, x, z) must be negative");
  CHECK(tr_insphere(o, x, y, z, in) > 0, "a point inside a positive tet's sphere: positive");
  CHECK(tr_insphere(o, x, y, z, out) < 0, "a point outside: negative");
  CHECK(tr_insphere(o, y, x, z, in) < 0, "inside a negative tet's sphere: negative");
  CHECK(tr_orient2d(o, x, y) > 0, "orient2d(o, x, y) (counterclockwise) must be positive");
  CHECK(tr_incircle(o, x, y, in) > 0, "incircle of an inside point must be positive");
  CHECK(tr_incircle(o, x, y, out) < 0, "incircle of an outside point must be negative");
  /* orient2d_proj: cyclic kept axes, sign = component `drop` of the normal */
  const double a[3] = {0, 0, 0}, b[3] = {1, 2, 3}, c[3] = {-2, 1, 5};
  const double n[3] = {2 * 5 - 3 * 1, 3 * -2 - 1 * 5, 1 * 1 - 2 * -2};
  for (int k = 0; k < 3; k++)
    CHECK(sgn(tr_orient2d_proj(a, b, c, k)) == sgn(n[k]),
          "orient2d_proj(drop=%d) must have the sign of normal component %d", k, k);
  /* huge and tiny: the filters must not overflow or underflow into a wrong sign */
  const double H = 1e300, T = 1e-300;
  const double hx[3] = {H, 0, 0}, hy[3] = {0, H, 0}, hz[3] = {0, 0, H};
  const double tx[3] = {T, 0, 0}, ty[3] = {0, T, 0}, tz[3] = {0, 0, T};
  CHECK(tr_orient3d(o, hx, hy, hz) > 0, "orient3d at 1e300 must be positive");
  CHECK(tr_orient3d(o, tx, ty, tz) > 0, "orient3d at 1e-300 must be positive");
  const double hin[3] = {H / 4, H / 4, H / 4}, tin[3] = {T / 4, T / 4, T / 4};
  CHECK(tr_insphere(o, hx, hy, hz, hin) > 0, "insphere at 1e300 must be positive");
  CHECK(tr_insphere(o, tx, ty, tz, tin) > 0, "insphere at 1e-300 must be positive");
  const double far[3] = {-H, -H, -H};
  CHECK(tr_insphere(o, hx, hy, hz, far) < 0, "insphere far outside at 1e300 must be negative");
}

int main(int argc, char **argv)
{
  if (argc < 2)
    return 2;
  init_tables();
  if (!strcmp(argv[1], "conventions")) {
    prop_conventions();
  } else {
    if (argc < 3)
      return 2;
    const pred_t *P = NULL;
    for (size_t i = 0; i < sizeof preds / sizeof preds[0]; i++)
      if (!strcmp(argv[1], preds[i].name))
        P = &preds[i];
    if (!P)
      return 2;
    const char *w = argv[2];
    if (!strcmp(w, "random"))
      prop_random(P);
    else if (!strcmp(w, "exact_stage"))
      prop_exact_stage(P);
    else if (!strcmp(w, "zero"))
      prop_zero(P);
    else if (!strcmp(w, "ulp"))
      prop_ulp(P);
    else if (!strcmp(w, "scale"))
      prop_scale(P);
    else if (!strcmp(w, "antisymmetry"))
      prop_antisymmetry(P);
    else if (!strcmp(w, "cospherical") && P->lifted && P->dim == 3)
      prop_cospherical(P);
    else
      return 2;
  }
  if (fails)
    fprintf(stderr, "%s %s: %d failures\n", argv[1], argc > 2 ? argv[2] : "", fails);
  return fails ? 1 : 0;
}
