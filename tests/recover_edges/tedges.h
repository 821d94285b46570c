/* Edge lists for the recovery tests: pairs of vertex ids, sorted and without repeats, the
 * form recover_edges takes its input edges in. */
#ifndef TR_TEST_TEDGES_H
#define TR_TEST_TEDGES_H

#include <stdint.h>
#include <stdlib.h>

static int cmp_edge(const void *x, const void *y)
{
  const uint32_t *a = x, *b = y;
  if (a[0] != b[0])
    return a[0] < b[0] ? -1 : 1;
  return a[1] < b[1] ? -1 : a[1] > b[1];
}

/* Puts each of the n edges low id first, sorts them and drops repeats; returns the new count. */
static inline uint32_t sort_edges(uint32_t *e, uint32_t n)
{
  for (uint32_t i = 0; i < n; i++)
    if (e[2 * i] > e[2 * i + 1]) {
      uint32_t t = e[2 * i];
      e[2 * i] = e[2 * i + 1];
      e[2 * i + 1] = t;
    }
  qsort(e, n, 2 * sizeof *e, cmp_edge);
  uint32_t k = 0;
  for (uint32_t i = 0; i < n; i++)
    if (k == 0 || cmp_edge(e + 2 * i, e + 2 * (k - 1)) != 0) {
      e[2 * k] = e[2 * i];
      e[2 * k + 1] = e[2 * i + 1];
      k++;
    }
  return k;
}

#endif
