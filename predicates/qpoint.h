/* Exact points. A point is either an input point (three doubles) or an exact rational
 * point (GMP mpq_t coordinates) that carries a tight double box [lo, hi] enclosing it
 * and the nearest double rounding. Steiner points are rational points constructed
 * exactly (predicates/construct.c): they lie exactly on their edge or facet.
 *
 * Predicates on tr_point: an interval filter on the boxes first, then the adaptive
 * double predicate when every point is a plain double point, else exact rational
 * evaluation. Separated from constructions as in CGAL: predicates never build points.
 */
#ifndef TR_QPOINT_H
#define TR_QPOINT_H

#include <gmp.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct tr_qpoint {
  mpq_t c[3];      /* exact coordinates */
  double lo[3];    /* largest double <= c[i] */
  double hi[3];    /* smallest double >= c[i] */
  double near[3];  /* c[i] rounded to the nearest double (ties to even) */
  /* Derived with lo/hi/near by tr_qpoint_update (and set_d / set_point), kept because
   * the exact predicates need them on every call and rebuilding them (lcm, divexact)
   * was a tenth of the run time on Steiner-heavy models:
   *   hx[i] / hw = c[i] with hw > 0 the lcm of the denominators (homogeneous form);
   *   err[i] = max(hi[i] - near[i], near[i] - lo[i]) >= |c[i] - near[i]|, exact (the
   *   difference of neighbouring doubles is a power of two), 0 iff c[i] is a double,
   *   inf when c[i] is beyond the double range. */
  mpz_t hx[3], hw;
  double err[3];
} tr_qpoint;

/* A reference to a point of either kind: q == NULL means the point is exactly d. When
 * q != NULL, d should point to q->near. */
typedef struct tr_point {
  const double *d;
  const tr_qpoint *q;
} tr_point;

static inline tr_point tr_pt_d(const double *d)
{
  tr_point p = {d, 0};
  return p;
}
static inline tr_point tr_pt_q(const tr_qpoint *q)
{
  tr_point p = {q->near, q};
  return p;
}

/* 1 iff p and q are the same stored point (same double array or same rational), hence
 * equal: a sufficient test without arithmetic. Predicates on a repeated point are exactly
 * 0, but reaching that zero costs a failed filter and an exact stage, so callers that
 * often pass a vertex twice test this first. */
static inline int tr_pt_same(const tr_point *p, const tr_point *q)
{
  return p->d == q->d && p->q == q->q;
}

void tr_qpoint_init(tr_qpoint *q);
void tr_qpoint_clear(tr_qpoint *q);
void tr_qpoint_set_d(tr_qpoint *q, const double d[3]);
/* Recomputes lo/hi/near from c (call after changing c). */
void tr_qpoint_update(tr_qpoint *q);
/* Correct rounding of a rational to the nearest double (ties to even), subnormals
 * included. Overflow follows IEEE round-to-nearest: |x| >= DBL_MAX + ulp(DBL_MAX)/2
 * gives +-inf. */
double tr_q_round_nearest(const mpq_t x);
/* *lo = largest double <= x, *hi = smallest double >= x (equal iff x is a double).
 * Outside the double range the finite side saturates to +-DBL_MAX and the other side
 * is +-inf. */
void tr_q_round_bounds(const mpq_t x, double *lo, double *hi);
/* q = p exactly (q must be initialised). */
void tr_qpoint_set_point(tr_qpoint *q, const struct tr_point *p);
/* Exact coordinate i of p as a rational (sets out). */
void tr_point_get_q(const tr_point *p, int i, mpq_t out);
/* Homogeneous integer form of p: coordinate i = X[i] / W with W > 0 (all initialised
 * by the caller). Exact predicates and constructions work on these to avoid the gcds
 * of mpq arithmetic. For a rational point this copies q->hx, q->hw. */
void tr_point_get_hom(const tr_point *p, mpz_t X[3], mpz_t W);

/* Exact predicates on points of either kind; return -1, 0 or +1 with the conventions
 * of predicates.h. Evaluation: all plain doubles -> the adaptive double predicate;
 * else an interval filter on the boxes [lo, hi]; else exact rational arithmetic.
 *
 * tr_orient2d_proj_p projects by dropping axis `drop` and keeps the axes
 * ((drop+1)%3, (drop+2)%3) in that (cyclic) order, so its sign is the sign of component
 * `drop` of the normal (b-a)x(c-a). */
int tr_orient3d_p(const tr_point *a, const tr_point *b, const tr_point *c, const tr_point *d);
int tr_orient2d_proj_p(const tr_point *a, const tr_point *b, const tr_point *c, int drop);
/* incircle of the projections dropping axis `drop` (kept axes as in tr_orient2d_proj_p):
 * > 0 iff d lies inside the circle of a, b, c when tr_orient2d_proj_p(a, b, c) > 0. */
int tr_incircle_proj_p(const tr_point *a, const tr_point *b, const tr_point *c,
                       const tr_point *d, int drop);
int tr_insphere_p(const tr_point *a, const tr_point *b, const tr_point *c, const tr_point *d,
                  const tr_point *e);
/* Compare coordinate i of a and b: -1, 0, +1. */
int tr_cmp_coord_p(const tr_point *a, const tr_point *b, int i);
/* 1 iff a and b are the same point exactly. */
int tr_equal_p(const tr_point *a, const tr_point *b);

/* The exact predicates keep thread-local GMP temporaries so that hot loops do not
 * allocate; this frees the calling thread's (optional, e.g. before thread exit). */
void tr_exact_scratch_free(void);

#ifdef __cplusplus
}
#endif

#endif
