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

#ifdef __cplusplus
extern "C" {
#endif

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
 * (interior, code = tr_ecode(0,1)). If a == b: NOD 0 when p == a, else DEG.
 * on_seg is unused (0) in point results. */
tr_hit tr_classify_point_segment(const tr_point *p, const tr_point *a, const tr_point *b);
/* Point p against triangle t0t1t2: TR_DEG (off the closed triangle, including off its
 * plane), TR_NOD/TR_EDG/TR_FAC with codes in the triangle. A degenerate (collinear)
 * triangle gives TR_DEG for every p. */
tr_hit tr_classify_point_triangle(const tr_point *p, const tr_point *t0, const tr_point *t1,
                                  const tr_point *t2);
/* Segment ab against segment cd (codes relative to cd: NOD 0 = c, NOD 1 = d, EDG = the
 * interior of cd). Cases:
 *  - not coplanar, parallel and distinct, or apart: n = 0;
 *  - crossing or touching in one point: n = 1 (T-junctions and shared endpoints
 *    included; on_seg says whether the point is a, b or inside ab);
 *  - collinear overlap: n = 2, the overlap's ends ordered from a to b, each end is one
 *    of a, b, c, d (a NOD when it is c or d, else EDG with on_seg A or B); collinear
 *    segments touching at one point give n = 1.
 * A degenerate segment (a == b or c == d) is treated as a point: n = 1 if it lies on the
 * other segment. */
tr_isect tr_classify_segment_segment(const tr_point *a, const tr_point *b, const tr_point *c,
                                     const tr_point *d);
/* Segment ab against the closed triangle t0t1t2. Cases:
 *  - a and b strictly on one side of the plane: n = 0;
 *  - transversal (strictly on both sides): n <= 1, the crossing point is FAC 3, EDG on
 *    an edge or NOD at a vertex, on_seg = TR_SEG_IN;
 *  - exactly one of a, b in the plane: n <= 1, that endpoint classified in the
 *    triangle (on_seg A or B);
 *  - ab in the plane: the overlap of ab with the triangle, n = 0, 1 (touching a vertex or
 *    an edge from outside, or a == b) or 2 (ordered from a to b; each end NOD/EDG/FAC,
 *    an end inside ab is where ab crosses the boundary).
 * A degenerate triangle gives n = 0. */
tr_isect tr_classify_segment_triangle(const tr_point *a, const tr_point *b,
                                      const tr_point *t0, const tr_point *t1,
                                      const tr_point *t2);
/* Segment ab against the closed tetrahedron t[0..3], which must be positively oriented
 * (tr_orient3d_p(t0,t1,t2,t3) > 0; not checked: a negative tet gives wrong answers):
 * the part of ab inside it. n = 0: disjoint. n = 1: one common point (the segment
 * touches a vertex, crosses only an edge (the pipel EDG_DEG case), touches a face from
 * outside at an endpoint, or a == b inside). n = 2: entry end[0] and exit end[1] in the
 * order a -> b, each NOD (vertex code), EDG (ECode), FAC (FCode = the face's opposite
 * vertex) on the boundary, or TR_INT when it is an endpoint a/b strictly inside.
 * Segments lying in a face plane or along an edge are handled like any other: their
 * ends are typed by all the faces they lie on (e.g. along an edge: EDG/NOD ends). */
tr_isect tr_classify_segment_tet(const tr_point *a, const tr_point *b, const tr_point *const t[4]);

/* The same for a != b with the points known by number and every orientation asked of
 * o3(ud, p, q, r, s), the exact sign of tr_orient3d_p of points p, q, r, s: 0..3 the
 * tet's vertices, TR_PT_A and TR_PT_B the segment's ends; sa (sb) is the tet vertex that
 * is the point a (b), -1 if none. The same answer as tr_classify_segment_tet, for callers
 * that know their points by id and remember orientations (edge recovery asks the
 * orientations of the same faces against the same ends over and over). */
enum { TR_PT_A = 4, TR_PT_B = 5 };
typedef int (*tr_orient_fn)(void *ud, int p, int q, int r, int s);
tr_isect tr_classify_segment_tet_o(tr_orient_fn o3, void *ud, int sa, int sb);

#ifdef __cplusplus
}
#endif

#endif
