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

/* Memos of the sub-segments that pass 1 of edge recovery leaves missing, kept for its
 * next flip level and for pass 2, which walk and flip around the same segment again and
 * ask for the same tets (a classification is a function of the tet's vertex list and
 * the segment's ends, so a kept one never goes stale while no point is taken back: the
 * caller parks only while no vertex is removed). At most TR_SEGMEMO_STORE_MAX entries
 * are kept over all memos (at most about 80 MB); a memo that would pass it is dropped
 * (its classifications are then recomputed: never a different answer). On 65395.stl
 * --keep-surface they raised the peak memory from 15 to 25 MB. Zero-initialise. */
#define TR_SEGMEMO_STORE_MAX (1u << 20)
typedef struct tr_segmemo_store {
  tr_vtmap idx;      /* (a, b) -> index in g */
  tr_segmemo *g;     /* parked memos (an empty map where one was taken back) */
  uint32_t n, cap;
  uint64_t entries;  /* classifications held by the parked memos */
} tr_segmemo_store;

/* Frees *g and starts it as the memo of ab: the parked one if there is one (taken out
 * of the store), else an empty one. */
void tr_segmemo_take(tr_segmemo_store *s, tr_segmemo *g, const struct tr_mesh *m, uint32_t a,
                     uint32_t b);
/* Parks *g under its segment (or frees it when the store is full or out of memory);
 * *g is left empty either way. */
void tr_segmemo_park(tr_segmemo_store *s, tr_segmemo *g);
void tr_segmemo_store_free(tr_segmemo_store *s);

#endif
