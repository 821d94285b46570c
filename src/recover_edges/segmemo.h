/* Memo of tr_classify_segment_tet for one segment ab during its recovery by flips.
 *
 * Flip attempts that are made and undone, and the re-collection of Pipe(ab) after a kept
 * flip, classify the same tets again and again; the points never move while ab is
 * flipped for, so a tet's classification is a function of its vertex list (in slot
 * order: the codes are slot numbers), kept in the shared vertex-tuple map with the
 * oriented 4-tuple as key. On allocation failure the memo just stops growing (results
 * are then recomputed), so it never changes an answer.
 */
#ifndef TR_RECOVER_EDGES_SEGMEMO_H
#define TR_RECOVER_EDGES_SEGMEMO_H

#include "classify.h"
#include "core/vtmap.h"
#include "mesh/mesh.h"

typedef struct tr_segmemo {
  uint32_t a, b;
  tr_vtmap map; /* tet listing -> packed tr_isect: n, end types and codes (on_seg is
                  not kept) */
} tr_segmemo;

/* Starts an empty memo for segment ab (no allocation yet). */
void tr_segmemo_init(tr_segmemo *g, const struct tr_mesh *m, uint32_t a, uint32_t b);
void tr_segmemo_free(tr_segmemo *g);
/* tr_classify_segment_tet(a, b, tet v) with end[].on_seg = 0; v must be a real tet. */
tr_isect tr_segmemo_classify(tr_segmemo *g, const struct tr_mesh *m, const uint32_t v[4]);
/* The same without a memo of tets, for segment ab of mesh vertices a != b (on_seg is
 * set): the orientations go through the mesh's orientation memo (mesh/orient_memo.h)
 * when it is on, which keeps the exact ones across tets that share a face and across the
 * recovery's repeated searches for one segment. */
tr_isect tr_segmemo_classify_ids(const struct tr_mesh *m, uint32_t a, uint32_t b,
                                 const uint32_t v[4]);

#endif
