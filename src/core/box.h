/* The axis-aligned box of a few indexed points: the prefilter of every exact
 * triangle-against-triangle or point-in-element question (self-intersection, cells,
 * deviation, rounding). Comparisons only, so the box is exact. */
#ifndef TR_CORE_BOX_H
#define TR_CORE_BOX_H

#include <math.h>
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

/* The largest half side of the box lo..hi: 0.5 hi - 0.5 lo never overflows, unlike
 * hi - lo. */
static inline double tr_box_half_extent(const double lo[3], const double hi[3])
{
  double h = 0;
  for (int d = 0; d < 3; d++) {
    double x = 0.5 * hi[d] - 0.5 * lo[d];
    h = x > h ? x : h;
  }
  return h;
}

/* The frame of a few points whose double formulas (normals, squared lengths, products
 * of degree up to 4 of coordinate differences) overflow near 1e200 and underflow near
 * 1e-200: their coordinates times 2^-e, e the exponent that brings their half extent
 * `half` into [1/2, 1) (0 for a flat or non-finite extent: nothing to scale). A power
 * of two scales exactly, so the figures are those of the same points at unit size. */
static inline int tr_frame_exp(double half)
{
  return half > 0 && isfinite(half) ? ilogb(half) + 1 : 0;
}

#endif
