/* Cycle detection for the visibility walks through a mesh that need not be Delaunay
 * (refine/cavity.c, rf_locate).
 *
 * Such a walk can cycle: the face it leaves by is chosen from a start that rotates with
 * the step, so its state is (tet, step mod period), and the next state is a function of
 * that state alone (the point and the mesh do not change during the walk). A state seen
 * twice therefore means the walk never ends. Brent's method (1980) keeps the state at the
 * last power-of-two distance and compares each new state with it: a walk whose cycle of
 * L states starts at step T is stopped by step 2T + 3L + 2, with O(1) memory, and a walk
 * that ends is never stopped. Without it, the step bound of
 * 4 nt let 38 walks on a 3x10^5-tet mesh take 5% of a quality run. */
#ifndef TR_MESH_WALK_H
#define TR_MESH_WALK_H

#include <stdint.h>

typedef struct tr_walk_cycle {
  uint32_t mark;      /* the tet of the kept state */
  uint64_t mark_step; /* its step */
  uint64_t span;      /* steps until the kept state moves on (a power of two) */
} tr_walk_cycle;

static inline void tr_walk_cycle_init(tr_walk_cycle *w, uint32_t t0)
{
  w->mark = t0;
  w->mark_step = 0;
  w->span = 1;
}

/* After the walk's step number `step` (counted from 1) it stands in tet t: 1 iff the state
 * (t, step mod period) was seen before, so the walk cycles. */
static inline int tr_walk_cycle_seen(tr_walk_cycle *w, uint32_t t, uint64_t step,
                                     unsigned period)
{
  if (t == w->mark && (step - w->mark_step) % period == 0)
    return 1;
  if (step - w->mark_step == w->span) {
    w->mark = t;
    w->mark_step = step;
    w->span *= 2;
  }
  return 0;
}

#endif
