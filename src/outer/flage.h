/* OUTER / INNER labels of the tets that hold a surface facet (the seed paper's FLAGE,
 * Table 13, Eq.(2)), the seeds of the coloring that removes outer tets.
 *
 * Let ABC be a surface facet ordered with its right-hand normal pointing out of the
 * domain (paper's hypothesis 1), and ABCD a positively oriented tet holding it
 * (hypothesis 2, the library's convention), with ia, ib, ic, id the codes (NCodes) of
 * A, B, C, D in that tet. Then tr_orient3d(A,B,C,D) has the sign of the permutation
 * (ia,ib,ic,id): D, and with it the tet, lies beyond the outward normal exactly when the
 * permutation is even. So FLAGE is a parity: OUTER for even, INNER for odd.
 * The printed Table 13 is the exact complement of this in all 24 entries (it lists
 * (0,1,2,3), i.e. D beyond ABC's outward normal, as INNER): it is consistent with inward
 * facet normals or negatively oriented tets, not with the hypotheses as printed, which
 * Tables 3-12 do follow (their tets are positive: see test_tables.c in tests/recover_edges
 * and tests/recover_facets).
 * tests/recover_facets/test_flage.c records the printed table, checks that it is exactly
 * the complement, and checks the corrected table against this parity and the geometry.
 */
#ifndef TR_OUTER_FLAGE_H
#define TR_OUTER_FLAGE_H

#include "core/status.h"
#include "qpoint.h"

enum { TR_INNER = 0, TR_OUTER = 1 };

/* Eq.(2): etype of the tet from the codes of A, B, C, D; -1 if (ia,ib,ic,id) is not a
 * permutation of 0..3. */
int tr_flage(int ia, int ib, int ic, int id);

/* The same decided on coordinates: OUTER iff tr_orient3d(a,b,c,d) > 0, i.e. d lies on
 * the side the right-hand normal of abc points to. -1 if the four points are coplanar. */
int tr_etype_geom(const tr_point *a, const tr_point *b, const tr_point *c, const tr_point *d);

/* The paper's rule for a recovered sub-facet ABC of the surface facet EFG (outward
 * order): start from tr_flage(ia,ib,ic,id) and reverse it when the normals of ABC and
 * EFG point in opposite directions. The normals are compared exactly through the
 * orientations of D (which is off the common plane) against abc and efg.
 * TR_ERR_INTERNAL if the codes are not a permutation, a, b, c are not in the plane of
 * efg, or d is. */
tr_status tr_etype_subfacet(int ia, int ib, int ic, int id, const tr_point *a,
                            const tr_point *b, const tr_point *c, const tr_point *d,
                            const tr_point *e, const tr_point *f, const tr_point *g,
                            int *etype);

#endif
