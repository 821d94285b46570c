/* Exact tet volumes for the tests of volume bounds (refine and --keep-surface suites),
 * from the vertices' exact points with GMP, independent of the library's predicates. */
#ifndef TESTS_REFINE_TVOLUME_H
#define TESTS_REFINE_TVOLUME_H

#include <gmp.h>

#include "mesh/mesh.h"

static inline void tv_coords(const tr_mesh *m, uint32_t v, mpq_t c[3])
{
  tr_point p = tr_mesh_point(m, v);
  for (int i = 0; i < 3; i++)
    tr_point_get_q(&p, i, c[i]);
}

/* The tets of m (of region `region`, or all when it is UINT32_MAX) whose exact volume is
 * above V; *counted = the tets looked at. */
static inline uint32_t tv_count_over(const tr_mesh *m, double V, uint32_t region, uint32_t *counted)
{
  mpq_t v6, lim, x;
  mpq_inits(v6, lim, x, NULL);
  mpq_set_d(lim, V);
  mpq_set_ui(x, 6, 1);
  mpq_mul(lim, lim, x);
  uint32_t over = 0;
  *counted = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t) || (region != UINT32_MAX && m->region[t] != region))
      continue;
    (*counted)++;
    mpq_t a[3], b[3], c[3], d[3];
    for (int i = 0; i < 3; i++)
      mpq_inits(a[i], b[i], c[i], d[i], NULL);
    tv_coords(m, m->tv[4 * t], a);
    tv_coords(m, m->tv[4 * t + 1], b);
    tv_coords(m, m->tv[4 * t + 2], c);
    tv_coords(m, m->tv[4 * t + 3], d);
    for (int i = 0; i < 3; i++) {
      mpq_sub(b[i], b[i], a[i]);
      mpq_sub(c[i], c[i], a[i]);
      mpq_sub(d[i], d[i], a[i]);
    }
    /* det[b; c; d] */
    mpq_set_ui(v6, 0, 1);
    static const int P[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {1, 0, 2}, {2, 1, 0}};
    for (int k = 0; k < 6; k++) {
      mpq_mul(x, b[P[k][0]], c[P[k][1]]);
      mpq_mul(x, x, d[P[k][2]]);
      if (k < 3)
        mpq_add(v6, v6, x);
      else
        mpq_sub(v6, v6, x);
    }
    over += mpq_cmp(v6, lim) > 0;
    for (int i = 0; i < 3; i++)
      mpq_clears(a[i], b[i], c[i], d[i], NULL);
  }
  mpq_clears(v6, lim, x, NULL);
  return over;
}

#endif
