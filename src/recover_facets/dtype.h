/* S-type and Z-type decomposition of a triangular face (the paper's DType), and the choice
 * of a clusterel decomposition case from the types its neighbours impose.
 *
 * Definition used everywhere in tetrec (it reproduces every S/Z name of Tables 6, 11 and
 * 12; the tests check this): let face F of tet t have two cut edges, meeting at the apex
 * X. List F's vertices in t's OUTWARD order (right-hand normal pointing out of t) starting
 * at the apex: (X, U, V). Let P_u be the cut point on XU and P_v the one on XV. The
 * triangle P_u P_v X is cut off; the quad U V P_v P_u is split by a diagonal:
 *   S-type: diagonal V-P_u;     Z-type: diagonal U-P_v.
 * (Paper, Fig.1 and Table 6 II: in ABD of t = ABCD, outward order (D, A, B), P1 on DA,
 * P2 on DB: S uses B-P1, Z uses A-P2.) The neighbour across F sees F in the opposite
 * order, so the same diagonal is S for one tet and Z for the other: this is why the
 * paper's selection rule answers "Z" when the decomposed neighbour has "S".
 *
 * S and Z swap under a reflection; orientation-preserving relabelings of t keep them.
 */
#ifndef TR_RECOVER_FACETS_DTYPE_H
#define TR_RECOVER_FACETS_DTYPE_H

#include <stdint.h>

#include "core/status.h"
#include "recover_facets/cluster_tables.h"

/* "Either type is fine" (the paper's Step 3), for tr_cluster_match's want[]. */
#define TR_DTYPE_ANY 2

/* The DType a table imposes on the face of old[0] opposite the name `opp` (one of
 * old[0]'s names): TR_DTYPE_S / TR_DTYPE_Z, or TR_DTYPE_NONE when that face does not
 * have exactly two cut edges (Steiner points with 2 carriers in it) meeting at a vertex,
 * or when the table's faces on it contain neither diagonal or both. Purely symbolic:
 * old[0] is taken as positively oriented. */
int tr_dtype_of_table(const tr_dectable *t, uint8_t opp);

/* 1 iff the permutation p[0..3] of {0,1,2,3} is even, 0 if odd, -1 if p is not a
 * permutation. */
int tr_perm_parity_even(const uint8_t p[4]);

/* Chooses the decomposition of a clusterel with 3 (THR_EDG) or 4 (FOU_EDG) cut edges.
 *   ncut, ecodes: the cut edges as ECodes (tr_ecode(start, end), local codes 0..3);
 *   want[k]:      the DType required for the clusterel's face k (opposite local code k):
 *                 TR_DTYPE_S, TR_DTYPE_Z or TR_DTYPE_ANY (faces with < 2 cut edges are
 *                 ignored).
 * On success *out is the case and perm[n] (n = name A..D) the local code of the vertex
 * that plays n; perm is an even permutation, so the case's tets stay positive, and the
 * Steiner points land where the case says (THR_EDG: P1 on AD, P2 on BD, P3 on CD;
 * FOU_EDG: P1 on AD, P2 on BD, P3 on BC, P4 on AC). Cases without H are preferred, then
 * the first case and labeling in a fixed order, so equal inputs give equal answers.
 * Every combination of S/Z requirements has a case (tested exhaustively).
 * TR_ERR_INTERNAL: the cut edges are not those of a plane cutting 3 edges at one vertex
 * or 4 edges (two opposite edges uncut). */
tr_status tr_cluster_match(int ncut, const uint8_t *ecodes, const int8_t want[4],
                           const tr_cluster_case **out, uint8_t perm[4]);

#endif
