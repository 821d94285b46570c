/* The geometric conditions (1) and (3) of smooth.h, shared by the worklist and the
 * reference passes. */
#ifndef TR_SMOOTH_QUAD_H
#define TR_SMOOTH_QUAD_H

/* 1 iff A, B, C, D are exactly coplanar and the quadrilateral with diagonals AC and BD
 * is strictly convex. */
int tr_smooth_flat_convex(const double *A, const double *B, const double *C, const double *D);

#endif
