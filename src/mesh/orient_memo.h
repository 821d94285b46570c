/* Orientation signs of vertex 4-tuples, remembered while no point moves.
 *
 * Edge recovery by flips asks the same orientations again and again: the recursion of
 * tr_flip_remove_edge_nm undoes a failed branch and the next branch, or the next flip
 * level, tests the same faces and rings; the Swap23 after tr_flip23_blockers repeats its
 * three tests. On 65395.stl of the real-world corpus (--keep-surface) 97% of the 11.4
 * million orientation tests of the flips asked a tuple asked before, and the exact stages
 * of those (adaptive doubles, GMP on Steiner points) were a third of the run.
 *
 * The memo is keyed by vertex ids, so it is correct only while each id keeps its point:
 * a stage turns it on where points are only added (tr_mesh_orient_memo_on), calls
 * tr_mesh_orient_memo_forget when it moves a point (tr_mesh_pop_vertex forgets for a
 * vertex taken back), and turns it off
 * at its end. It is the shared vertex-tuple map (core/vtmap.h) on the sorted tuple,
 * grown from 4096 keys and emptied when it reaches TR_ORIENT_MEMO_KEYS, so its memory
 * stays bounded; the signs are exact either way, so the output does not depend on what
 * it holds. */
#ifndef TR_MESH_ORIENT_MEMO_H
#define TR_MESH_ORIENT_MEMO_H

#include <stdint.h>

#include "core/status.h"
#include "core/vtmap.h"

struct tr_mesh;

/* 2^16 keys: at most 2.6 MB of slots (2^18 was no faster); the working set of one edge's
 * flip search fits many times over. */
#define TR_ORIENT_MEMO_KEYS (1u << 16)

typedef struct tr_orient_memo {
  tr_vtmap map;   /* sorted tuple -> sign + 1 (0, 1, 2) */
  uint32_t room;  /* keys the map holds without growing */
  uint64_t asked; /* statistics for tests and profiling */
  uint64_t found;
} tr_orient_memo;

/* Exact sign of orient3d(a, b, c, d) (predicates.h convention) of the mesh's points,
 * from the memo when it is on. */
int tr_mesh_orient(const struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t c, uint32_t d);

/* Turns the memo on (empty). TR_ERR_NOMEM if its table cannot be had. */
tr_status tr_mesh_orient_memo_on(struct tr_mesh *m);
/* Turns it off and frees it (a no-op when it is off). */
void tr_mesh_orient_memo_off(struct tr_mesh *m);
/* Empties it: a vertex id is about to get another point, or a point moves. */
void tr_mesh_orient_memo_forget(struct tr_mesh *m);

#endif
