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

typedef struct tr_qpoint {
  mpq_t c[3];      /* exact coordinates */
  double lo[3];    /* largest double <= c[i] */
  double hi[3];    /* smallest double >= c[i] */
  double near[3];  /* c[i] rounded to the nearest double (ties to even) */
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

void tr_qpoint_init(tr_qpoint *q);
void tr_qpoint_clear(tr_qpoint *q);
void tr_qpoint_set_d(tr_qpoint *q, const double d[3]);
/* Recomputes lo/hi/near from c (call after changing c). */
void tr_qpoint_update(tr_qpoint *q);
/* Correct rounding of a rational to the nearest double (ties to even), subnormals
 * and overflow included. */
double tr_q_round_nearest(const mpq_t x);
/* Exact coordinate i of p as a rational (sets out). */
void tr_point_get_q(const tr_point *p, int i, mpq_t out);

/* Exact predicates on points of either kind; return -1, 0 or +1 with the conventions
 * of predicates.h. */
int tr_orient3d_p(const tr_point *a, const tr_point *b, const tr_point *c, const tr_point *d);
int tr_orient2d_proj_p(const tr_point *a, const tr_point *b, const tr_point *c, int drop);
int tr_insphere_p(const tr_point *a, const tr_point *b, const tr_point *c, const tr_point *d,
                  const tr_point *e);
/* Compare coordinate i of a and b: -1, 0, +1. */
int tr_cmp_coord_p(const tr_point *a, const tr_point *b, int i);
/* 1 iff a and b are the same point exactly. */
int tr_equal_p(const tr_point *a, const tr_point *b);

#endif
