/* Exact intersection classifiers, for every input including collinear and coplanar
 * overlaps. They answer in the seed paper's vocabulary so the pipel and clusterel code
 * can use them directly:
 *   intersection type: TR_DEG (no such intersection point), TR_NOD (at a vertex),
 *                      TR_EDG (in the relative interior of an edge),
 *                      TR_FAC (in the relative interior of a face),
 *                      TR_INT (interior of a tetrahedron, for segment-tet only).
 *   code: the paper's coding inside the simplex: NCode = vertex index 0..3;
 *         ECode = start | (end << 2) with start < end (edges 0-1,0-2,0-3,1-2,1-3,2-3);
 *         FCode = index of the vertex the face does not contain (a triangle's only face
 *         has code 3).
 * Each intersection is reported as at most two ends, ordered along the segment from
 * its first point a to its second point b; a single point has n == 1.
 */
#ifndef TR_CLASSIFY_H
#define TR_CLASSIFY_H

#include "qpoint.h"

enum { TR_DEG = 0, TR_NOD = 1, TR_EDG = 2, TR_FAC = 3, TR_INT = 4 };

/* Where an intersection end lies on the segment ab. */
enum { TR_SEG_A = 0, TR_SEG_B = 1, TR_SEG_IN = 2 };

static inline int tr_ecode(int start, int end) { return start | (end << 2); }
static inline int tr_ecode_start(int e) { return e & 3; }
static inline int tr_ecode_end(int e) { return (e >> 2) & 3; }

typedef struct tr_hit {
  uint8_t type;   /* TR_NOD / TR_EDG / TR_FAC / TR_INT in the other simplex */
  uint8_t code;   /* NCode / ECode / FCode in the other simplex */
  uint8_t on_seg; /* TR_SEG_A, TR_SEG_B or TR_SEG_IN */
} tr_hit;

typedef struct tr_isect {
  int n;          /* 0: disjoint; 1: one point; 2: a segment from end[0] to end[1] */
  tr_hit end[2];
} tr_isect;

/* Point p against segment ab: TR_DEG (off), TR_NOD with code 0/1 (at a/b), TR_EDG
 * (interior, code = tr_ecode(0,1)). */
tr_hit tr_classify_point_segment(const tr_point *p, const tr_point *a, const tr_point *b);
/* Point p against triangle t0t1t2: TR_DEG (off the closed triangle, including off its
 * plane), TR_NOD/TR_EDG/TR_FAC with codes in the triangle. */
tr_hit tr_classify_point_triangle(const tr_point *p, const tr_point *t0, const tr_point *t1,
                                  const tr_point *t2);
/* Segment ab against segment cd (codes relative to cd: NOD 0/1, EDG). */
tr_isect tr_classify_segment_segment(const tr_point *a, const tr_point *b, const tr_point *c,
                                     const tr_point *d);
/* Segment ab against the closed triangle t0t1t2 (coplanar overlaps give n == 2). */
tr_isect tr_classify_segment_triangle(const tr_point *a, const tr_point *b,
                                      const tr_point *t0, const tr_point *t1,
                                      const tr_point *t2);
/* Segment ab against the closed tetrahedron t[0..3] (positively oriented): the part of
 * ab inside it, each end typed NOD/EDG/FAC on the boundary or TR_INT inside. This is
 * the pipel entry/exit classification. */
tr_isect tr_classify_segment_tet(const tr_point *a, const tr_point *b, const tr_point *const t[4]);

#endif
