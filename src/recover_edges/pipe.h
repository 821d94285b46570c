/* Pipe(E): the tets a missing edge E = ab cuts (the paper's "pipe"), and the recovery of
 * E as a chain of mesh edges: Swap23 / Swap44 when the pipe allows them, else one Steiner
 * point per cut edge / face of the pipe and the decomposition of every pipel.
 *
 * A tet is a pipel when the closed segment ab meets it in a point that is not one of its
 * vertices (an edge or face point). That includes the EDG_DEG tets around a cut edge
 * that the segment only touches there: they must be split too, or the mesh would not be
 * conforming. The pipe is collected by a breadth-first search from Ball(a) across the
 * faces of pipels, classifying each tet exactly (tr_classify_segment_tet).
 *
 * If ab passes through an existing vertex V, E is recovered as a-V and V-b (the paper's
 * pipel types exclude that case).
 */
#ifndef TR_RECOVER_EDGES_PIPE_H
#define TR_RECOVER_EDGES_PIPE_H

#include "recover_edges/pipel.h"

typedef struct tr_pipe {
  tr_pipel *pl;
  uint32_t n, cap;
} tr_pipe;

void tr_pipe_free(tr_pipe *p);

/* Collects Pipe(ab) without changing the mesh. pipe->pl[i] gets iEle, type, iCod1/2 and,
 * for NOD ends, iNod (EDG/FAC ends: iNod = TR_NONE until tr_pipe_add_steiner). *via =
 * an existing vertex strictly inside ab, or TR_NONE (then the pipe is complete). */
tr_status tr_pipe_collect(struct tr_mesh *m, uint32_t a, uint32_t b, tr_pipe *pipe,
                          uint32_t *via);

/* Creates the exact Steiner points of a collected pipe (one per cut edge or face, shared
 * by every pipel that has it) and fills the iNod of EDG / FAC ends. *nadded counts them. */
tr_status tr_pipe_add_steiner(struct tr_mesh *m, uint32_t a, uint32_t b, tr_pipe *pipe,
                              uint32_t *nadded);

typedef struct tr_edge_stats {
  uint32_t by_swap23, by_swap44, by_pipels, already, split_at_vertex;
  uint32_t steiner_points;
} tr_edge_stats;

/* Recovers segment ab (two mesh vertices) as a chain of mesh edges. */
tr_status tr_recover_edge(struct tr_mesh *m, uint32_t a, uint32_t b, tr_edge_stats *st);

/* 1 iff {a,b} is an edge of the mesh (searches Ball(a)). */
tr_status tr_mesh_has_edge(struct tr_mesh *m, uint32_t a, uint32_t b, int *yes);

#endif
