/* S-type / Z-type decomposition of a triangular face (the paper's Fig.1, DType).
 *
 * Setting: face k of a tet t (the face opposite local vertex k) has Steiner points on
 * two of its edges; the two edges share the face vertex `apex`; X and Y are the two other
 * face vertices, named so that (apex, X, Y) is the face's INWARD cyclic order in t, i.e.
 * tr_orient3d(v_apex, v_X, v_Y, v_k) > 0. The quadrilateral left after cutting off the
 * apex triangle is split by one of two diagonals:
 *    S-type: X to the Steiner point on edge apex-Y;
 *    Z-type: Y to the Steiner point on edge apex-X.
 * Seen from outside t with the apex on top, S's strokes (P-P, diagonal, base) trace an
 * angular S (the diagonal runs from upper left to lower right) and Z's trace a Z.
 * This matches the paper's Table 6: for t = ABCD, face ABD, apex D, P1 on AD, P2 on BD,
 * II-S uses diagonal B-P1 and II-Z uses A-P2 (checked by test_dtype).
 *
 * The tet across the face sees the reverse cyclic order, so the same diagonal has the
 * other type there: that is why the paper's Step 2 answers Z to a neighbour's S.
 */
#ifndef TR_RECOVER_EDGES_DTYPE_H
#define TR_RECOVER_EDGES_DTYPE_H

/* TR_DTYPE_S / TR_DTYPE_Z are defined once, in core/dectable.h, for pipels and clusterels;
 * both test suites check the definition against Table 6. */
#include "core/dectable.h"

/* For face k of a positive tet (local codes 0..3), apex != k: writes X and Y (local
 * codes) as defined above. */
void tr_dtype_xy(int k, int apex, int *x, int *y);

/* DType of face k with the given apex when the diagonal joins local vertex `from`
 * (one of the two non-apex face vertices) to the Steiner point on the other edge. */
int tr_dtype_of_diagonal(int k, int apex, int from);

/* The local vertex the diagonal starts from for the wanted DType. */
int tr_dtype_diagonal_from(int k, int apex, int dtype);

#endif
