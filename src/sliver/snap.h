/* A snapshot of what refinement changes in the mesh and the sub-faces, and its exact
 * undo (the sliver stage's trials of points on constraints: caps.c, and the pinned tets'
 * refinement: sliver.c). */
#ifndef TETREC_SLIVER_SNAP_H
#define TETREC_SLIVER_SNAP_H

#include "sliver/sliver.h"

/* One trial's snapshot: what refinement may change. Vertices are only appended, and the
 * old ones keep their coordinates. The neighbour links are not copied (16 bytes a slot,
 * the largest part of the run's peak in this stage on CGAL's elephant at 2.1 million
 * tets): a trial changes the slots of a few cavities, and tr_sliver_snap_restore links
 * their old tets again by their faces; only the free slots' links (the free list) are
 * kept. Nor
 * are the slots' vertices, as a rule: the shape cache of the trial's caller holds them
 * (tr_sliver_shape_keys), and the trial measures without it. */
typedef struct tr_sliver_snap {
  uint32_t nv, nt, free_head, nfree;
  const uint32_t *tv; /* slot t's vertices at tv + stride * t */
  size_t stride;
  uint32_t *tv_own; /* tv when it is a copy (no cache to lend it) */
  uint32_t *region, *v2t;
  uint8_t *flags;
  uint32_t *free_tn; /* 5 per free slot: the slot, then its 4 links */
  uint32_t nfree_slots;
  tr_subfaces sub;
} tr_sliver_snap;

/* Takes the snapshot: the slots' vertices lent by c's shape cache, when it holds every
 * slot, else copied (so nothing may measure on c until z is restored or freed). Free
 * with tr_sliver_snap_free. */
tr_status tr_sliver_snap_take(const tr_sliver_ctx *c, const tr_subfaces *sub, tr_sliver_snap *z);
void tr_sliver_snap_free(tr_sliver_snap *z);
/* The mesh and sub-faces as they were at the snapshot, which is consumed. The caller
 * forgets what refers to the trial's vertices (ids from z->nv on go to other points). */
tr_status tr_sliver_snap_restore(struct tr_mesh *m, tr_subfaces *sub, tr_sliver_snap *z);
/* Slot t held a real tet at the snapshot. */
int tr_sliver_snap_real(const tr_sliver_snap *z, uint32_t t);
/* 1 when slot u holds another tet than at the snapshot (or none was there) */
int tr_sliver_snap_changed(const struct tr_mesh *m, const tr_sliver_snap *z, uint32_t u);
/* The context of a trial on the new sub-faces sub, made after a snapshot of nv0 vertices:
 * c's bounds and reference, no shape cache, and only the trial's new vertices movable (an
 * old vertex's exact point may be no double, and the snapshot keeps no coordinates).
 * Free with tr_sliver_ctx_free. */
tr_status tr_sliver_trial_ctx(const tr_sliver_ctx *c, const tr_subfaces *sub, uint32_t nv0,
                              tr_sliver_ctx *tc);

#endif
