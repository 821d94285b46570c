/* The axis-aligned box of a few indexed points: the prefilter of every exact
 * triangle-against-triangle or point-in-element question (self-intersection, cells,
 * deviation, rounding). Comparisons only, so the box is exact. */
#ifndef TR_CORE_BOX_H
#define TR_CORE_BOX_H

#include <stddef.h>
#include <stdint.h>

/* lo, hi = the smallest and largest coordinates of xyz[3 v[i] ..], i < n (n >= 1). */
static inline void tr_box_of(const double *xyz, const uint32_t *v, int n, double lo[3], double hi[3])
{
  for (int d = 0; d < 3; d++) {
    double l = xyz[3 * (size_t)v[0] + d], h = l;
    for (int i = 1; i < n; i++) {
      double x = xyz[3 * (size_t)v[i] + d];
      l = x < l ? x : l;
      h = x > h ? x : h;
    }
    lo[d] = l;
    hi[d] = h;
  }
}

#endif
