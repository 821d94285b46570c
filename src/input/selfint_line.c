/* Two non-coplanar triangles against each other along the line where their planes meet
 * (after Guigue & Devillers 2003, with every degenerate sign handled and the proof below).
 *
 * T = (t0, t1, t2) and U = (u0, u1, u2) have planes meeting in a line L (the caller has
 * seen corners of U on both sides of T's plane or on it, not all on it, and likewise for
 * T). Each closed triangle meets L in a closed interval, and T and U meet exactly where
 * the two intervals do. Let n_T = (t1 - t0) x (t2 - t0), n_U likewise, d = n_T x n_U
 * (along L) and lambda(x) = d . x the position on L.
 *
 * An end of T's interval is reached from a corner p strictly off U's plane (sign
 * sp = orient3d(u0, u1, u2, p) != 0) along an edge towards a corner p' on the other side
 * or on the plane: i = p + alpha (p' - p), 0 < alpha <= 1. Likewise k = q + beta (q' - q)
 * for U, q strictly off T's plane (sign sq). Then, writing G(a, b, c, e) for
 * det[b - a; c - a; e - a] (the sign of tr_orient3d):
 *   G(p, p', q, q') = G(p, i, q, k) / (alpha beta)      (G is affine in each point)
 *   G(p, i, q, k)   = det[i - p; q - i; k - i]           (column operations)
 *                   = (lambda(k) - lambda(i)) / |d|^2 * det[i - p; q - i; d]
 * and with (i - p) x d = g n_T (both in T's plane), g |n_T|^2 = det[i - p; d; n_T]
 * = (i - p) . (d x n_T) = |n_T|^2 n_U . (i - p) = -|n_T|^2 n_U . (p - u0): the sign of g
 * is -sp, and det[i - p; q - i; d] = -g n_T . (q - i) = -g n_T . (q - t0) has the sign
 * sp sq. So
 *   sign(lambda(k) - lambda(i)) = sign G(p, p', q, q') * sp * sq,
 * one orient3d per comparison of an end of T with an end of U. The two ends i (towards
 * t_{k+1}) and j (towards t_{k+2}) of T reached from p = t_k compare without a
 * predicate: (i - p) x (j - p) = alpha alpha' n_T (the corners in T's cyclic order) and
 * also (lambda(j) - lambda(i)) / |d|^2 g n_T, so sign(lambda(j) - lambda(i)) = -sp; for U
 * the same with d's sign turned (d = -(n_U x n_T)): sign(lambda(l) - lambda(k)) = +sq.
 *
 * The signs of T's corners against U's plane, neither all equal and strict nor all 0 (a
 * shared corner is 0), either leave one corner p strictly alone on its side (the other
 * two opposite or 0): the interval is [i, j] as above; or are (+, +, 0) up to order and
 * sign: the interval is the one point at the 0 corner z, reached from either strict
 * corner with alpha = 1. Two intervals meet, closed, iff each starts before the other
 * ends: two orient3d. A shared corner v lies on L in both intervals; the triangles then
 * meet beyond v iff the intervals overlap in more than a point, the same two
 * comparisons strict. */
#include "selfint_line.h"

#include <stddef.h>

#include "predicates.h"

typedef struct {
  uint32_t p;      /* the corner strictly off the other plane */
  int sp;          /* its side of the other plane */
  uint32_t lo, hi; /* the corners p' towards the interval's low and high ends */
} span;

/* dir = -1 for T, +1 for U: the sign of lambda(j) - lambda(i) is dir * sp. */
static span span_of(const uint32_t *t, const int *a, int dir)
{
  span s;
  for (int k = 0; k < 3; k++) {
    int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
    if (a[k] && a[k1] != a[k] && a[k2] != a[k]) {
      s.p = t[k];
      s.sp = a[k];
      s.lo = dir * a[k] > 0 ? t[k1] : t[k2];
      s.hi = dir * a[k] > 0 ? t[k2] : t[k1];
      return s;
    }
  }
  /* two corners strictly on one side, the third, z, on the plane */
  int z = !a[0] ? 0 : !a[1] ? 1 : 2, k = (z + 1) % 3;
  s.p = t[k];
  s.sp = a[k];
  s.lo = s.hi = t[z];
  return s;
}

/* sign(lambda(U's end via q -> y) - lambda(T's end via p -> x)). */
static int later(const double *xyz, const span *T, uint32_t x, const span *U, uint32_t y)
{
  if (x == y) /* the same corner: the same point */
    return 0;
  const double *P = xyz + 3 * (size_t)T->p, *X = xyz + 3 * (size_t)x;
  const double *Q = xyz + 3 * (size_t)U->p, *Y = xyz + 3 * (size_t)y;
  return tr_sign(tr_orient3d(P, X, Q, Y)) * T->sp * U->sp;
}

int tr_selfint_line_improper(const double *xyz, const uint32_t *t, const uint32_t *u,
                             const int a[3], const int b[3], int shared)
{
  span T = span_of(t, a, -1), U = span_of(u, b, 1);
  if (!shared) /* closed intervals meet: U starts no later than T ends, and vice versa */
    return later(xyz, &T, T.hi, &U, U.lo) <= 0 && later(xyz, &T, T.lo, &U, U.hi) >= 0;
  if (T.lo == T.hi || U.lo == U.hi) /* an interval is the shared corner alone */
    return 0;
  return later(xyz, &T, T.hi, &U, U.lo) < 0 && later(xyz, &T, T.lo, &U, U.hi) > 0;
}
