/* Floating-point expansion arithmetic (Shewchuk 1997, "Adaptive Precision Floating-Point
 * Arithmetic and Fast Robust Geometric Predicates"), re-derived for tetrec.
 *
 * An expansion is an array of doubles e[0..n-1] whose exact sum is the represented
 * value; the components are nonoverlapping and sorted by increasing magnitude, so the
 * last component carries the sign (and, after zero elimination, is the largest one).
 *
 * Model (assumed, checked by tests/predicates): IEEE-754 binary64, round to nearest
 * even, no extended precision (x86-64 SSE2) and no contraction into FMA (the project
 * builds with -ffp-contract=off): every error-free transformation below relies on each
 * operation being rounded exactly once. The transformations are exact as long as no
 * intermediate result overflows and no product underflows; callers guarantee that by
 * a range check on their inputs (see orient.c, "exact range").
 *
 * epsilon = 2^-53 is a compile-time constant instead of Shewchuk's exactinit(): with
 * binary64 and round to nearest the unit roundoff is fixed by the format, so measuring
 * it at run time would only add a global and an initialisation order problem.
 */
#ifndef TR_EXPANSION_H
#define TR_EXPANSION_H

#include <gmp.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#define TR_EPS 0x1p-53
/* 2^ceil(53/2) + 1: multiplying by it splits a double into two 26-bit halves. */
#define TR_SPLITTER 134217729.0

/* x + y == a + b exactly, x = fl(a + b); requires |a| >= |b| (or a == 0). */
static inline void tr_fast_two_sum(double a, double b, double *x, double *y)
{
  double s = a + b;
  double bv = s - a; /* exact when |a| >= |b| (Dekker) */
  *x = s;
  *y = b - bv;
}

/* x + y == a + b exactly, x = fl(a + b), no precondition (Knuth's 6-operation form:
 * recover the parts of a and b that survived in s and add up what was lost). */
static inline void tr_two_sum(double a, double b, double *x, double *y)
{
  double s = a + b;
  double bv = s - a;
  double av = s - bv;
  double br = b - bv;
  double ar = a - av;
  *x = s;
  *y = ar + br;
}

/* x + y == a - b exactly, x = fl(a - b). */
static inline void tr_two_diff(double a, double b, double *x, double *y)
{
  double s = a - b;
  double bv = a - s;
  double av = s + bv;
  double br = bv - b;
  double ar = a - av;
  *x = s;
  *y = ar + br;
}

/* The error of x = fl(a - b): the y of tr_two_diff when x is already known. */
static inline double tr_two_diff_tail(double a, double b, double x)
{
  double bv = a - x;
  double av = x + bv;
  double br = bv - b;
  double ar = a - av;
  return ar + br;
}

/* hi + lo == a, each with at most 26 significant bits (Veltkamp), so products of
 * halves are exact. Needs |a| < 2^996 to keep TR_SPLITTER * a finite. */
static inline void tr_split(double a, double *hi, double *lo)
{
  double c = TR_SPLITTER * a;
  double big = c - a;
  double h = c - big;
  *hi = h;
  *lo = a - h;
}

/* x + y == a * b exactly, x = fl(a * b) (Dekker): subtract the four exact partial
 * products of the halves from x in decreasing order; each subtraction is exact, so
 * what remains is minus the rounding error of x. */
static inline void tr_two_product(double a, double b, double *x, double *y)
{
  double p = a * b, ah, al, bh, bl;
  tr_split(a, &ah, &al);
  tr_split(b, &bh, &bl);
  double e1 = p - ah * bh;
  double e2 = e1 - al * bh;
  double e3 = e2 - ah * bl;
  *x = p;
  *y = al * bl - e3;
}

/* Same with b already split (scale_expansion splits its scalar once). */
static inline void tr_two_product_presplit(double a, double b, double bh, double bl, double *x,
                                           double *y)
{
  double p = a * b, ah, al;
  tr_split(a, &ah, &al);
  double e1 = p - ah * bh;
  double e2 = e1 - al * bh;
  double e3 = e2 - ah * bl;
  *x = p;
  *y = al * bl - e3;
}

/* h = a*b - c*d as a zero-eliminated expansion (at most 4 components); returns its
 * length. The 2x2 minor every predicate here is built from. */
int tr_exp_two_two_diff_prod(double a, double b, double c, double d, double *h);

/* h = e + b (Grow-Expansion with zero elimination). h may not alias e. Returns the
 * length of h (<= elen + 1). */
int tr_exp_grow(int elen, const double *e, double b, double *h);
/* h = e + f (Fast-Expansion-Sum with zero elimination; needs round-to-even). h may not
 * alias e or f. Returns the length of h (<= elen + flen). */
int tr_exp_sum(int elen, const double *e, int flen, const double *f, double *h);
/* h = e - f, like tr_exp_sum. */
int tr_exp_diff(int elen, const double *e, int flen, const double *f, double *h);
/* h = b * e (Scale-Expansion with zero elimination). h may not alias e. Returns the
 * length of h (<= 2 * elen). */
int tr_exp_scale(int elen, const double *e, double b, double *h);
/* h = e with fewer components (Compress); h may alias e. Returns the new length. */
int tr_exp_compress(int elen, const double *e, double *h);
/* h = e * f exactly, compressed (the product of two expansions: f scaled by every
 * component of e, summed, then Compress so that later stages work on a handful of
 * components instead of the 2 ne nf the scalings produce). h holds 2 ne nf doubles,
 * scratch 4 ne nf; neither may alias e or f. Returns the length of h. */
int tr_exp_mul(int ne, const double *e, int nf, const double *f, double *h, double *scratch);
/* Floating approximation of the value of e (sum from the smallest component). */
double tr_exp_estimate(int elen, const double *e);
/* Exact sign of e (the sign of its largest nonzero component). */
static inline int tr_exp_sign(int elen, const double *e)
{
  for (int i = elen - 1; i >= 0; i--)
    if (e[i] != 0)
      return (e[i] > 0) - (e[i] < 0);
  return 0;
}
/* sign(e) if |e| > bound exactly (bound >= 0 a double), else 0. */
int tr_exp_sign_beyond(int elen, const double *e, double bound);
/* A double with the exact sign of e whose magnitude approximates e. */
double tr_exp_value(int elen, const double *e);

/* 1 iff every x[i] is 0 or lo <= |x[i]| <= hi: the "exact range" test of the adaptive
 * stages (bounds derived in orient.c). */
static inline int tr_exp_in_range(int n, const double *const *p, int dim, double lo, double hi)
{
  for (int i = 0; i < n; i++)
    for (int j = 0; j < dim; j++) {
      double a = fabs(p[i][j]);
      if (a != 0 && !(a >= lo && a <= hi))
        return 0;
    }
  return 1;
}

/* Exactness certificate for a plain floating evaluation (the "exactly representable"
 * stage, run before the expansions): 1 iff the n values d (exact coordinate
 * differences) are all integer multiples of q = 2^(E-k) where 2^E > max|d|, i.e. each
 * is below 2^k quanta. Then every product of deg of them is a multiple of q^deg below
 * 2^(deg k) q^deg, and a caller whose evaluation keeps every intermediate below
 * 2^53 q^deg (k chosen per predicate) computes its determinant without any rounding.
 * The exponent tests keep q^deg >= 2^-1074 (no underflow) and the result finite. */
static inline int tr_exp_exact_in_float(int n, const double *d, int k, int deg)
{
  double m = 0;
  for (int i = 0; i < n; i++) {
    /* fabs: a sign test would be a mispredicted branch; the ternary is one maxsd where
     * fmax is a libm call (NaN semantics) */
    const double a = fabs(d[i]);
    m = a > m ? a : m;
  }
  if (m == 0)
    return 1;
  /* e with 2^(e-1) <= m < 2^e from the exponent field (no libm call on this path);
   * subnormal or non-finite m is simply not certified. */
  uint64_t bits;
  memcpy(&bits, &m, sizeof bits);
  const int biased = (int)(bits >> 52 & 0x7ff);
  if (biased == 0 || biased == 0x7ff)
    return 0;
  const int e = biased - 1022;
  if (deg * (e - k) < -1074 || deg * e + 8 > 1023)
    return 0;
  const uint64_t sbits = (uint64_t)(k - e + 1023) << 52; /* 2^(k-e), normal here */
  double s;
  memcpy(&s, &sbits, sizeof s);
  for (int i = 0; i < n; i++) {
    double t = d[i] * s; /* exact unless it underflows, which the test below rejects */
    if (t != (double)(long long)t || (t == 0 && d[i] != 0))
      return 0;
  }
  return 1;
}

/* Exact fallback for inputs outside the exact range of expansion arithmetic: the sign
 * of det of the n x n matrix whose row i is (pts[i][0..dim-1], |pts[i]|^2 if lifted,
 * 1), n = dim + lifted + 1, computed with GMP integers. */
int tr_gmp_lifted_det_sign(int dim, int lifted, const double *const *pts);

#endif
