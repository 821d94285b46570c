/* Shape improvement of a polygon's triangulation by edge flips (polyflip.c), used by
 * polytri.c after ear clipping. */
#ifndef TR_IO_POLYFLIP_H
#define TR_IO_POLYFLIP_H

#include <stdint.h>

#include "../core/status.h"

/* A triangulation of one polygon (with its holes) in the polygon's working projection.
 * Vertices are local: p[x] is x's exact projected point, id[x] its index into xyz (the
 * 3D points), and the polygon's sides are the pairs {x, next[x]}. tri holds ntri
 * triangles, 3 local vertices each, all counterclockwise in p. */
typedef struct tr_polyflip_in {
  const double (*p)[2];
  const uint32_t *id;
  const double *xyz;
  const uint32_t *next;
  uint32_t *tri;
  uint32_t ntri;
} tr_polyflip_in;

/* Lawson flips of the diagonals (never a side) that raise the smaller minimum angle of
 * the two triangles beside them, measured on the 3D triangles; a flip is made only where
 * the quadrilateral is strictly convex in p (exact orient2d), so tri stays a
 * triangulation of the polygon, counterclockwise. Rewrites tri in place, deterministic.
 * *nflips (may be NULL) = the flips made. */
tr_status tr_polyflip(tr_polyflip_in *in, uint32_t *nflips);

/* The sine squared of the smallest angle of triangle abc in 3D (0 when degenerate), in
 * doubles; the same value for the three rotations of a triangle when called through
 * tr_polyflip's canonical order. Exposed for the tests. */
double tr_polyflip_shape(const double *a, const double *b, const double *c);

#endif
