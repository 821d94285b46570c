/* `tetrec resolve`: the solid's boundary rounded to doubles, free of intersections
 * (snap.c; docs/resolve.md). */
#ifndef TR_RESOLVE_SNAP_H
#define TR_RESOLVE_SNAP_H

#include <stdint.h>

#include "core/plc.h"
#include "core/status.h"

/* The rounds the command allows before it gives up (docs/resolve.md: one or two were
 * needed on every model measured). */
#define TR_SNAP_ROUNDS 8

/* What the self-intersection test found on a rounded surface: improper pairs,
 * zero-area triangles, duplicate triangles (either orientation), open edges; and, not a
 * defect, edges of more than two triangles (parts of the solid touching along an edge,
 * or internal facets: valid for `tetrec mesh`, listed by `check-surface`). */
typedef struct tr_snap_defects {
  uint64_t pairs;
  uint32_t zero, duplicate, open;
  uint32_t nonmanifold;
} tr_snap_defects;

typedef struct tr_snap_info {
  uint64_t npairs;         /* improper pairs of the input */
  uint64_t npairs_later;   /* improper pairs the rounding made, over the later rounds */
  uint32_t npieces, ncomponents; /* the input's arrangement: pieces, connected parts */
  uint32_t nnew;           /* new vertices of the input's arrangement */
  uint32_t nrounded;       /* vertices rounded to doubles, over all rounds */
  uint32_t nmerged;        /* vertices that rounded onto another's double */
  uint32_t ncollapsed;     /* triangles dropped: two of their corners merged */
  double max_move;         /* the largest distance a vertex moved in one rounding */
  double move_bound;       /* the sum over rounds of each round's largest move: no point of
                              the written surface's vertices is farther from where the
                              exact solid has it */
  int rounds;              /* arrangement + solid + rounding, at least 1 */
  uint32_t nverts, ntris, ninternal; /* the result; its last ninternal triangles are the
                                        internal facets */
  tr_snap_defects left;    /* what the last round's test found (all 0 on success) */
  double seconds;          /* wall-clock time */
} tr_snap_info;

/* *out = the boundary of in's solid (winding number >= 1; mode 2: the internal facets
 * too, after the boundary) in doubles (to_float: in floats, for STL): the exact
 * arrangement's kept pieces, oriented outward, each vertex at its nearest double (float),
 * vertices that land on one value merged,
 * triangles collapsed by that dropped; while the result has improper pairs, zero-area or
 * duplicate triangles or open edges, resolved and rounded again, up to max_rounds times.
 * Each triangle keeps its piece's marker and, in tri_source, the input element of its
 * first source. Still defective after max_rounds: TR_ERR_SELF_INTERSECT naming the first
 * pair's triangles and corners, *out NULL. Errors of the soup as tr_resolve_plc's
 * (TR_ERR_OPEN undefined winding number, TR_ERR_INPUT empty solid); input segments:
 * TR_ERR_UNSUPPORTED. Hole and region points are not copied. */
tr_status tr_resolve_snap(const struct tr_plc *in, int mode, int to_float, int max_rounds,
                          struct tr_plc **out, tr_snap_info *info);

#endif
