/* The narrow phase of selfint.c for two triangles whose planes meet in a line. */
#ifndef TR_INPUT_SELFINT_LINE_H
#define TR_INPUT_SELFINT_LINE_H

#include <stdint.h>

/* Triangles t and u (corner ids into xyz) sharing `shared` (0 or 1) corners, not
 * coplanar: a[k] is the sign of tr_orient3d(u0, u1, u2, t[k]), b[k] of
 * tr_orient3d(t0, t1, t2, u[k]) (0 for a shared corner), and neither triple is all 0 or
 * all the same strict sign. Returns 1 iff the closed triangles meet somewhere other than
 * the shared corner. Two orient3d at most. */
int tr_selfint_line_improper(const double *xyz, const uint32_t *t, const uint32_t *u,
                             const int a[3], const int b[3], int shared);

#endif
