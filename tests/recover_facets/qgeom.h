/* Exact rational geometry for the recover_facets tests, independent of the library's
 * predicates so that the tables are checked against plain arithmetic. */
#ifndef TESTS_RECOVER_FACETS_QGEOM_H
#define TESTS_RECOVER_FACETS_QGEOM_H

#include <gmp.h>
#include <stdint.h>

typedef struct qv {
  mpq_t c[3];
} qv;

static inline void qv_init(qv *p)
{
  for (int i = 0; i < 3; i++)
    mpq_init(p->c[i]);
}
static inline void qv_clear(qv *p)
{
  for (int i = 0; i < 3; i++)
    mpq_clear(p->c[i]);
}
static inline void qv_set_si(qv *p, long x, long y, long z)
{
  mpq_set_si(p->c[0], x, 1);
  mpq_set_si(p->c[1], y, 1);
  mpq_set_si(p->c[2], z, 1);
}
static inline void qv_set(qv *p, const qv *q)
{
  for (int i = 0; i < 3; i++)
    mpq_set(p->c[i], q->c[i]);
}
static inline void qv_sub(qv *r, const qv *a, const qv *b)
{
  for (int i = 0; i < 3; i++)
    mpq_sub(r->c[i], a->c[i], b->c[i]);
}
/* r = a + s (b - a) */
static inline void qv_lerp(qv *r, const qv *a, const qv *b, const mpq_t s)
{
  mpq_t t;
  mpq_init(t);
  for (int i = 0; i < 3; i++) {
    mpq_sub(t, b->c[i], a->c[i]);
    mpq_mul(t, t, s);
    mpq_add(r->c[i], a->c[i], t);
  }
  mpq_clear(t);
}
static inline void qv_cross(qv *r, const qv *a, const qv *b)
{
  mpq_t t;
  mpq_init(t);
  qv tmp;
  qv_init(&tmp);
  mpq_mul(tmp.c[0], a->c[1], b->c[2]);
  mpq_mul(t, a->c[2], b->c[1]);
  mpq_sub(tmp.c[0], tmp.c[0], t);
  mpq_mul(tmp.c[1], a->c[2], b->c[0]);
  mpq_mul(t, a->c[0], b->c[2]);
  mpq_sub(tmp.c[1], tmp.c[1], t);
  mpq_mul(tmp.c[2], a->c[0], b->c[1]);
  mpq_mul(t, a->c[1], b->c[0]);
  mpq_sub(tmp.c[2], tmp.c[2], t);
  qv_set(r, &tmp);
  qv_clear(&tmp);
  mpq_clear(t);
}
static inline void qv_dot(mpq_t r, const qv *a, const qv *b)
{
  mpq_t t;
  mpq_init(t);
  mpq_mul(r, a->c[0], b->c[0]);
  mpq_mul(t, a->c[1], b->c[1]);
  mpq_add(r, r, t);
  mpq_mul(t, a->c[2], b->c[2]);
  mpq_add(r, r, t);
  mpq_clear(t);
}
/* r = det[b-a; c-a; d-a] (6 times the signed volume; > 0 iff abcd is positive in the
 * library's convention). */
static inline void qv_det(mpq_t r, const qv *a, const qv *b, const qv *c, const qv *d)
{
  qv u, v, w;
  qv_init(&u);
  qv_init(&v);
  qv_init(&w);
  qv_sub(&u, b, a);
  qv_sub(&v, c, a);
  qv_sub(&w, d, a);
  qv_cross(&u, &u, &v);
  qv_dot(r, &u, &w);
  qv_clear(&u);
  qv_clear(&v);
  qv_clear(&w);
}
static inline int qv_orient(const qv *a, const qv *b, const qv *c, const qv *d)
{
  mpq_t r;
  mpq_init(r);
  qv_det(r, a, b, c, d);
  int s = mpq_sgn(r);
  mpq_clear(r);
  return s;
}
static inline int qv_equal(const qv *a, const qv *b)
{
  return mpq_equal(a->c[0], b->c[0]) && mpq_equal(a->c[1], b->c[1]) &&
         mpq_equal(a->c[2], b->c[2]);
}

/* Deterministic generator (xorshift64*), so every run checks the same configurations. */
static inline uint64_t rng_next(uint64_t *s)
{
  *s ^= *s >> 12;
  *s ^= *s << 25;
  *s ^= *s >> 27;
  return *s * 2685821657736338717ull;
}
/* Uniform integer in [lo, hi]. */
static inline long rng_range(uint64_t *s, long lo, long hi)
{
  return lo + (long)(rng_next(s) % (uint64_t)(hi - lo + 1));
}
/* A random rational strictly inside (0, 1). */
static inline void rng_open01(uint64_t *s, mpq_t r)
{
  long den = rng_range(s, 2, 50);
  long num = rng_range(s, 1, den - 1);
  mpq_set_si(r, num, (unsigned long)den);
  mpq_canonicalize(r);
}

#endif
