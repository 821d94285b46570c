/* Shared by the files of src/resolve (see resolve.h for the split). */
#ifndef TR_RESOLVE_IMPL_H
#define TR_RESOLVE_IMPL_H

#include "core/vtmap.h"
#include "resolve/resolve.h"

/* ---- points.c: one vertex per exact value ---- */
typedef struct rs_points {
  const struct tr_plc *plc;
  tr_arr_vertex *v;
  uint32_t n, cap;
  uint32_t *next; /* the next vertex with the same hash, TR_ARR_NONE at the end */
  tr_vtmap map;   /* the 64-bit hash of a value, as two words -> its first vertex */
} rs_points;

/* Every input point, a vertex per new value; of_input[i] = the vertex of point i. */
tr_status rs_points_init(rs_points *ps, const struct tr_plc *plc, uint32_t *of_input,
                         uint64_t *ndup);
/* *id = the vertex of value p, added (p copied) if new. A vertex found again keeps the
 * least (on, a, b) of its findings: the feature of least dimension, then least index. */
tr_status rs_points_add(rs_points *ps, const tr_point *p, int on, uint32_t a, uint32_t b,
                        uint32_t *id);
void rs_points_free(rs_points *ps);
static inline tr_point rs_pt(const rs_points *ps, uint32_t id)
{
  const tr_arr_vertex *x = ps->v + id;
  return x->q ? tr_pt_q(x->q) : tr_pt_d(ps->plc->xyz + 3 * (size_t)x->input);
}

/* ---- pairs.c: the cuts every triangle carries ---- */
/* A cut on triangle tri: the segment of vertices (a, b), or the single point a when
 * b == TR_ARR_NONE. */
typedef struct rs_cut {
  uint32_t tri, a, b;
} rs_cut;

typedef struct rs_input {
  uint32_t ntris;
  uint32_t *tris; /* 3 per input triangle: its corners' vertices */
  uint8_t *live;  /* 0: zero area, dropped */
} rs_input;

/* in = the input's triangles on vertices, zero-area ones marked dead. */
tr_status rs_input_init(rs_input *in, const rs_points *ps, const uint32_t *of_input,
                        uint64_t *ndropped);
void rs_input_free(rs_input *in);
/* The cuts of every improper pair of live triangles, in pair order: *cuts (free it),
 * *ncuts; counts of pairs and of coplanar pairs. */
tr_status rs_pair_cuts(const rs_input *in, rs_points *ps, rs_cut **cuts, size_t *ncuts,
                       uint64_t *npairs, uint64_t *ncoplanar);

/* ---- cdt.c: constrained Delaunay triangulation in a triangle's plane ---- */
typedef struct rs_cdt rs_cdt;
tr_status rs_cdt_create(rs_cdt **c);
void rs_cdt_destroy(rs_cdt *c);
/* The CDT of the points pts[0..n) (pts[0..3) the triangle's corners, counterclockwise in
 * the frame, every other point inside or on the closed triangle, all distinct) with the
 * constraint segments segs[2i], segs[2i+1] (local indices; no two cross, no point inside
 * one). Frame: axis `drop` left out, the kept axes in cyclic order, mirrored when
 * sgn < 0. Cocircular ties are broken by a symbolic lift of the points in the order of
 * prio[] (distinct), so the result depends on the points, constraints and prio only:
 * coplanar triangles triangulate their common region alike. *tris: 3 local indices per
 * triangle, counterclockwise, valid until the next call. */
tr_status rs_cdt_run(rs_cdt *c, const tr_point *pts, const uint32_t *prio, uint32_t n,
                     int drop, int sgn, const uint32_t *segs, uint32_t nsegs,
                     const uint32_t **tris, uint32_t *ntris);

/* ---- subdiv.c: a triangle's pieces ---- */
typedef struct rs_sub rs_sub;
tr_status rs_sub_create(rs_sub **s);
void rs_sub_destroy(rs_sub *s);
/* The pieces of live triangle t carrying cuts[0..n) (all on t), appended as 3 vertices
 * each (oriented as t) to *out (length *nout, capacity *cap); *ncross counts the
 * crossings of two cuts found. */
tr_status rs_subdivide(rs_sub *s, const rs_input *in, rs_points *ps, uint32_t t,
                       const rs_cut *cuts, size_t n, uint32_t **out, size_t *nout, size_t *cap,
                       uint64_t *ncross);

/* The exact frame of triangle (a, b, c): *drop = the axis of the largest |normal|
 * component (ties: the least axis), *sgn = the sign of that component. Coplanar
 * triangles get the same axis. 0, or -1 for a zero-area triangle. */
int rs_frame(const tr_point *a, const tr_point *b, const tr_point *c, int *drop, int *sgn);

/* Grows *p (elements of size sz) to hold at least need; *cap updated. */
tr_status rs_grow(void **p, size_t sz, size_t need, size_t *cap);

#endif
