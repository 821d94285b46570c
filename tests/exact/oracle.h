/* Test-side exact oracles, written differently from the library on purpose: determinants
 * by Gaussian elimination over mpq (the library expands cofactors). */
#ifndef TR_TESTS_EXACT_ORACLE_H
#define TR_TESTS_EXACT_ORACLE_H

#include <gmp.h>

#include "qpoint.h"

/* sign of det of the n x n matrix m (row-major, destroyed) */
static inline int oracle_det_sign(mpq_t *m, int n)
{
  int sign = 1;
  mpq_t f, t;
  mpq_init(f);
  mpq_init(t);
  for (int col = 0; col < n; col++) {
    int piv = -1;
    for (int r = col; r < n; r++)
      if (mpq_sgn(m[r * n + col]) != 0) {
        piv = r;
        break;
      }
    if (piv < 0) {
      sign = 0;
      break;
    }
    if (piv != col) {
      for (int c = 0; c < n; c++)
        mpq_swap(m[piv * n + c], m[col * n + c]);
      sign = -sign;
    }
    if (mpq_sgn(m[col * n + col]) < 0)
      sign = -sign;
    for (int r = col + 1; r < n; r++) {
      if (mpq_sgn(m[r * n + col]) == 0)
        continue;
      mpq_div(f, m[r * n + col], m[col * n + col]);
      for (int c = col; c < n; c++) {
        mpq_mul(t, f, m[col * n + c]);
        mpq_sub(m[r * n + c], m[r * n + c], t);
      }
    }
  }
  mpq_clear(f);
  mpq_clear(t);
  return sign;
}

/* orient3d = -sign det[[x y z 1]] over rows a, b, c, d (subtracting row a and expanding
 * along the ones column gives det4 = -det[b-a; c-a; d-a]). */
static inline int oracle_orient3d(const tr_point *const p[4])
{
  mpq_t m[16];
  for (int i = 0; i < 16; i++)
    mpq_init(m[i]);
  for (int r = 0; r < 4; r++) {
    for (int i = 0; i < 3; i++)
      tr_point_get_q(p[r], i, m[4 * r + i]);
    mpq_set_ui(m[4 * r + 3], 1, 1);
  }
  int s = -oracle_det_sign(m, 4);
  for (int i = 0; i < 16; i++)
    mpq_clear(m[i]);
  return s;
}

/* insphere: the lifted 5x5 [[x y z x^2+y^2+z^2 1]] over a..e equals the library's det4,
 * whose negation is the insphere sign. */
static inline int oracle_insphere(const tr_point *const p[5])
{
  mpq_t m[25], t;
  for (int i = 0; i < 25; i++)
    mpq_init(m[i]);
  mpq_init(t);
  for (int r = 0; r < 5; r++) {
    mpq_set_ui(m[5 * r + 3], 0, 1);
    for (int i = 0; i < 3; i++) {
      tr_point_get_q(p[r], i, m[5 * r + i]);
      mpq_mul(t, m[5 * r + i], m[5 * r + i]);
      mpq_add(m[5 * r + 3], m[5 * r + 3], t);
    }
    mpq_set_ui(m[5 * r + 4], 1, 1);
  }
  int s = -oracle_det_sign(m, 5);
  for (int i = 0; i < 25; i++)
    mpq_clear(m[i]);
  mpq_clear(t);
  return s;
}

/* q = p0 + (num/den) (p1 - p0), exactly */
static inline void oracle_lerp(tr_qpoint *q, const tr_point *p0, const tr_point *p1, long num, long den)
{
  mpq_t t, x, y;
  mpq_init(t), mpq_init(x), mpq_init(y);
  mpq_set_si(t, num, (unsigned long)den);
  mpq_canonicalize(t);
  for (int i = 0; i < 3; i++) {
    tr_point_get_q(p0, i, x);
    tr_point_get_q(p1, i, y);
    mpq_sub(y, y, x);
    mpq_mul(y, y, t);
    mpq_add(q->c[i], x, y);
  }
  tr_qpoint_update(q);
  mpq_clear(t), mpq_clear(x), mpq_clear(y);
}

#endif
