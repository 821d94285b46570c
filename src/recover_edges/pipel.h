/* Decomposition of one pipel (the paper's "Recovering a missing edge by adding Steiner
 * points"): the pipel's raw type picks the case of Table 2, the case picks the table,
 * the table is matched to the tet by an even relabeling and instantiated.
 *
 * Raw types -> cases (Table 2), with a = first, b = second intersection type:
 *   Case 1  NOD_EDG, EDG_NOD, EDG_DEG        Table 5
 *   Case 2  EDG_EDG                          Table 6 (I: opposite edges; II: S or Z)
 *   Case 3  NOD_FAC, FAC_NOD                 Table 7
 *   Case 4  EDG_FAC, FAC_EDG                 Table 8
 *   Case 5  FAC_FAC                          Table 9 (Scheme 1)
 * NOD_NOD and NOD_DEG are degenerate (no decomposition needed or possible).
 *
 * DType rule for Case 2 II (the paper's Steps 1-3): the face with both cut edges is
 * split like the neighbour across it already split it; if that neighbour is not a
 * decomposed pipel, S-type is taken. The neighbour's split is read from its dectets
 * (which diagonal is an edge there), which is what the paper's "S there -> Z here"
 * amounts to, without trusting stored bits.
 */
#ifndef TR_RECOVER_EDGES_PIPEL_H
#define TR_RECOVER_EDGES_PIPEL_H

#include "recover_edges/decompose.h"

/* Case number 1..5 of a raw pipel type (low 4 bits), 0 for the degenerate ones, -1 for
 * an invalid type. */
int tr_pipel_case(uint8_t type);

/* Decomposes pl (a member of pipe[0..npipe)). pl->iEle, type, iCod1/2 and iNod1/2 must be
 * set: for a NOD end, iNod is the mesh vertex and iCod its NCode; for EDG / FAC ends,
 * iNod is the Steiner vertex (already in the mesh, exactly on that edge / face) and iCod
 * its ECode / FCode in iEle. On success pl->dectets / nTets are set and the DType bits of
 * pl->type record the split of any face with two cut edges. */
tr_status tr_pipel_decompose(struct tr_mesh *m, tr_pipel *pipe, uint32_t npipe, tr_pipel *pl);

#endif
