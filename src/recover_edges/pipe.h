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

#include <string.h>

#include "recover_edges/flip.h"
#include "recover_edges/pipel.h"
#include "recover_edges/segmemo.h"

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
/* The same with the classifications taken from / added to memo (a memo of segment ab). */
tr_status tr_pipe_collect_memo(struct tr_mesh *m, uint32_t a, uint32_t b, tr_pipe *pipe,
                               uint32_t *via, tr_segmemo *memo);

/* Creates the exact Steiner points of a collected pipe (one per cut edge or face, shared
 * by every pipel that has it) and fills the iNod of EDG / FAC ends. *nadded counts them. */
tr_status tr_pipe_add_steiner(struct tr_mesh *m, uint32_t a, uint32_t b, tr_pipe *pipe,
                              uint32_t *nadded);

/* Decomposed pipels by the case of Table 2 and the table that was applied. */
enum {
  TR_PK_CASE1,    /* Table 5: NOD_EDG, EDG_NOD, EDG_DEG */
  TR_PK_CASE2_I,  /* Table 6 I: EDG_EDG on opposite edges */
  TR_PK_CASE2_S,  /* Table 6 II, S-type */
  TR_PK_CASE2_Z,  /* Table 6 II, Z-type */
  TR_PK_CASE3,    /* Table 7: NOD_FAC, FAC_NOD */
  TR_PK_CASE4,    /* Table 8: EDG_FAC, FAC_EDG */
  TR_PK_CASE5,    /* Table 9: FAC_FAC */
  TR_PK_COUNT
};

typedef struct tr_edge_stats {
  uint32_t by_swap23, by_swap44, by_pipels, already, split_at_vertex;
  uint32_t steiner_points;
  uint32_t pipels[TR_PK_COUNT]; /* decomposed pipels per kind */
  uint32_t raw[16];             /* decomposed pipels per raw type (low 4 bits) */
  uint32_t ghosts_split;        /* ghost tets replaced because their hull face was split */
  /* general flips (flip.h, tr_pipe_try_flips): kept flips by kind, and flips undone
   * because they did not shrink the pipe */
  uint32_t by_flips;            /* sub-segments recovered by general flips */
  uint32_t flip23, flip32, flip44, flipn, flip_hull, flips_undone;
  uint32_t midpoints;           /* sub-segments split at their midpoint (pass 2) */
} tr_edge_stats;

/* Adds the journal's kept flips to st by kind and empties the journal, its flips made for
 * good: what a search does once an attempt has succeeded. */
static inline void tr_pipe_count_flips(tr_flip_journal *j, tr_edge_stats *st)
{
  st->flip23 += j->flips[0];
  st->flip32 += j->flips[1];
  st->flip44 += j->flips[2];
  st->flipn += j->flips[3];
  st->flip_hull += j->flips[4];
  memset(j->flips, 0, sizeof j->flips);
  j->n = 0;
  j->delta = 0;
}

struct tr_edgeset;

/* Tries Swap23 (the pipe is two tets sharing the face ab crosses) or Swap44 (the four
 * tets around an edge cd that ab crosses). A Swap44 whose cd is in cons (the constraint
 * edges, may be NULL) is refused: it would delete a recovered input edge. *done = 1 iff
 * ab is now a mesh edge. */
tr_status tr_pipe_try_swaps(struct tr_mesh *m, uint32_t a, uint32_t b, const tr_pipe *p,
                            const struct tr_edgeset *cons, tr_edge_stats *st, int *done);

/* Recovers ab by general flips (flip.h) without Steiner points: Swap23 on the faces ab
 * crosses, edge removal (with bounded flipnm recursion) of the edges it crosses, never
 * deleting an edge in cons; an attempt is kept only if the number of real pipels strictly
 * drops (else it is undone), until ab is a mesh edge or no attempt helps (flipseg.c). p
 * must be Pipe(ab) with no vertex inside ab; on return it is the current Pipe(ab) unless
 * *done. Terminates: every kept attempt lowers the pipel count. *done = 1 iff ab is now a
 * mesh edge. memo: a memo of segment ab (e.g. the one p was collected with), or NULL. */
tr_status tr_pipe_try_flips(struct tr_mesh *m, uint32_t a, uint32_t b, tr_pipe *p,
                            const struct tr_edgeset *cons, tr_segmemo *memo,
                            tr_edge_stats *st, int *done);
/* The same with the edge removals' recursion depth given (tr_pipe_try_flips: 3). */
tr_status tr_pipe_try_flips_depth(struct tr_mesh *m, uint32_t a, uint32_t b, tr_pipe *p,
                                  const struct tr_edgeset *cons, tr_segmemo *memo, int depth,
                                  tr_edge_stats *st, int *done);
/* The same with at most `budget` flip attempts (made or refused, over all candidates and
 * rounds; 0 = no limit, flip.h's journal budget): the deep levels of edge recovery. */
tr_status tr_pipe_try_flips_budget(struct tr_mesh *m, uint32_t a, uint32_t b, tr_pipe *p,
                                   const struct tr_edgeset *cons, tr_segmemo *memo, int depth,
                                   uint32_t budget, tr_edge_stats *st, int *done);

/* The crossing of Pipe(ab) at an end: the far face or edge of the real pipel entered at
 * vertex a (at_a), or the near one of the pipel left at vertex b. Every such pipel has the
 * same one: where ab leaves the end's star first (last). The pipel's index, its crossing's
 * type (TR_FAC / TR_EDG) and code in the pipel's tet; -1 if there is none. */
int tr_pipe_end(const struct tr_mesh *m, const tr_pipe *p, uint32_t a, uint32_t b, int at_a,
                int *type, int *code);
/* The same crossing found in the star of the end alone, without collecting the pipe:
 * *found = 1 with *t (the pipel's tet), *type and *code when exactly one tet of the star
 * is such a pipel, 0 when none is, -1 when several are at b (then tr_pipe_end's choice rests
 * on the collection order: collect). At a the collection's order is the star's, so
 * there the first is taken. ball is scratch. */
tr_status tr_pipe_end_star(struct tr_mesh *m, uint32_t a, uint32_t b, int at_a,
                           tr_segmemo *memo, tr_u32buf *ball, uint32_t *t, int *type,
                           int *code, int *found);
/* Removes the faces and edges ab crosses one at a time from its ends, every flip admitted
 * only if ab crosses nothing it creates (TetGen's way, flipfirst.c); removals are kept
 * even when ab does not appear. depth, budget: as for tr_pipe_try_flips_budget; memo: a
 * memo of segment ab or NULL; mode: TR_FLIPFIRST_* bits. p must be Pipe(ab) with no vertex
 * inside ab; on return it is the current Pipe(ab) unless *done. */
tr_status tr_pipe_flip_first(struct tr_mesh *m, uint32_t a, uint32_t b, tr_pipe *p,
                             const struct tr_edgeset *cons, tr_segmemo *memo, int depth,
                             uint32_t budget, unsigned mode, tr_edge_stats *st, int *done);
/* edge removal only as TetGen's flips reach it (flip.h's journal field tetgen_flips) */
#define TR_FLIPFIRST_TETGEN 1u
/* without TetGen's star rule in the recursion (flip.h's journal field stars) */
#define TR_FLIPFIRST_NO_STARS 2u
/* when ab is still missing and the star rule cut a branch of the search, the search once
 * more without the rule: the rule is TetGen's pruning, and some edges are recovered only
 * through a branch it cuts (a nested removal that takes apart an outer shell) */
#define TR_FLIPFIRST_RETRY 4u
/* Splits ab at one exact point M (midsplit.c): its midpoint, or, when that lies in the
 * pipels at a or at b, the first point nested midpoints would reach between them; the
 * tets of Pipe(ab) whose closure holds M are replaced by the cone from M. When no short
 * point lies between them because ab winds around a hub edge that every pipel has, M is
 * where ab crosses the hub's face at a's end, and the hub is then removed by edge
 * removal unless guard (flip.h) protects it or no triangulation of its ring fits.
 * On success *mid = M's id and *done = 2 if the hub went, else 1; the mesh is unchanged
 * on failure (*done = 0). p must be the current Pipe(ab); it is stale afterwards. */
tr_status tr_pipe_split_mid(struct tr_mesh *m, uint32_t a, uint32_t b, const tr_pipe *p,
                            tr_flip_guard guard, void *ud, uint32_t *mid, int *done);

/* Decomposes every pipel of a pipe whose Steiner points were added (tr_pipe_add_steiner)
 * and splits the cut hull faces; counts the pipels in st->pipels / raw / ghosts_split. */
tr_status tr_pipe_decompose(struct tr_mesh *m, tr_pipe *p, tr_edge_stats *st);

/* Recovers segment ab (two mesh vertices) as a chain of mesh edges, alone: swaps if
 * possible, else Steiner points (the all-edges driver with the paper's order is
 * tr_recover_edges in recover_edges.h). */
tr_status tr_recover_edge(struct tr_mesh *m, uint32_t a, uint32_t b, tr_edge_stats *st);

/* 1 iff {a,b} is an edge of the mesh (searches Ball(a)). */
tr_status tr_mesh_has_edge(struct tr_mesh *m, uint32_t a, uint32_t b, int *yes);

/* An axis along which a and b differ exactly, a != b: exact coordinate comparisons on it
 * order the points of segment ab. The axis where their nearest doubles differ most (the
 * best conditioned; doubles that differ come from exact coordinates that differ, rounding
 * is monotone), or, when the nearest doubles are the same point (Steiner points closer
 * than an ulp on every axis: nested midpoints next to a sliver), the first axis where the
 * exact coordinates differ. Segments parallel to a coordinate plane have an axis where a
 * and b are exactly equal, so a fixed choice among equal doubles is not enough. -1 iff
 * a == b. */
static inline int tr_pipe_long_axis(const tr_point *a, const tr_point *b)
{
  int axis = 0;
  double best = -1;
  for (int k = 0; k < 3; k++) {
    double d = b->d[k] - a->d[k];
    d = d < 0 ? -d : d;
    if (d > best) {
      best = d;
      axis = k;
    }
  }
  if (best > 0)
    return axis;
  for (int k = 0; k < 3; k++)
    if (tr_cmp_coord_p(a, b, k) != 0)
      return k;
  return -1;
}

#endif
