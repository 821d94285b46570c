/* The exact arrangement of a triangle soup (issue 49, step 1; docs/resolve.md).
 *
 * Every pair of input triangles that meets improperly (src/input/selfint.c finds the
 * pairs) is cut along its exact intersection, each triangle is triangulated exactly in
 * its plane along every cut it carries, and identical pieces from several triangles
 * become one piece that remembers all of them. The result is a surface complex: two
 * pieces meet only in a shared vertex or a shared edge. No tolerance anywhere: every new
 * vertex is an exact rational point, identified by its exact value.
 *
 * Split by concern:
 *   points.c   the vertices: input points and new rational points, one per exact value
 *   pairs.c    the input's cleanup (duplicate points, zero-area triangles) and the exact
 *              intersection of each improper pair: points and segments per triangle
 *   subdiv.c   per triangle: the crossings of its segments, the split segments
 *   cdt.c      the exact constrained Delaunay triangulation in a triangle's plane
 *   arrange.c  the driver, identical pieces merged, the result */
#ifndef TR_RESOLVE_RESOLVE_H
#define TR_RESOLVE_RESOLVE_H

#include <stdint.h>

#include "core/plc.h"
#include "core/status.h"
#include "qpoint.h"

#define TR_ARR_NONE UINT32_MAX

/* What a vertex lies on, the feature of least dimension it was found on (ties: the least
 * index), so that a later stage can insert it where the input has it. */
enum { TR_ARR_ON_VERTEX = 0, TR_ARR_ON_EDGE = 1, TR_ARR_ON_TRI = 2 };

typedef struct tr_arr_vertex {
  uint32_t input;  /* the input point (the first of its exact value), TR_ARR_NONE if new */
  tr_qpoint *q;    /* new vertices: the exact point, owned; NULL for input points */
  uint8_t on;      /* TR_ARR_ON_*: an input point (a = this vertex), inside the input edge
                      of vertices (a, b), a < b, or inside input triangle a */
  uint32_t a, b;
} tr_arr_vertex;

typedef struct tr_arr_source {
  uint32_t tri; /* input triangle */
  int32_t sign; /* +1: the piece is oriented as the triangle, -1: opposite */
} tr_arr_source;

typedef struct tr_arr_piece {
  uint32_t v[3];      /* vertex ids, oriented as its first source */
  uint32_t src, nsrc; /* its sources: arr->src[src .. src + nsrc), by triangle */
  int32_t marker;     /* the first source's marker (the least input triangle) */
} tr_arr_piece;

typedef struct tr_arrangement {
  uint32_t nverts, npieces, nsrc;
  tr_arr_vertex *verts;
  tr_arr_piece *pieces;
  tr_arr_source *src;
  uint32_t *of_input; /* npoints of the input: the vertex of each input point */
  /* counts for reports: improper pairs, of which coplanar; input triangles dropped as
   * zero-area; input points that repeat an earlier one; crossings of two cuts inside a
   * triangle */
  uint64_t npairs, ncoplanar, ndropped, ndup_points, ncrossings;
} tr_arrangement;

/* arr = the arrangement of plc's triangles (arr zeroed by the call; free with
 * tr_arrangement_free, also after a failure). Input points of equal value are one vertex;
 * zero-area triangles (collinear or repeated corners) give no piece. Vertices: every
 * input point of a new value in input order, then the new points in the order they are
 * found (pairs in increasing order, then triangles in increasing order); pieces by their
 * first source triangle; all independent of hash order and addresses. */
tr_status tr_arrangement_build(const struct tr_plc *plc, tr_arrangement *arr);
void tr_arrangement_free(tr_arrangement *arr);

/* ---- winding.c: the solid (issue 49 step 2) ---- */
/* What becomes of a piece: dropped (both sides in the solid or both out, or its sources
 * cancel), kept as oriented (its back is in the solid), kept flipped (its front is),
 * or kept as an internal facet (both sides in the solid, on request). */
enum { TR_SOLID_DROP = 0, TR_SOLID_KEEP = 1, TR_SOLID_FLIP = 2, TR_SOLID_INTERNAL = 3 };

typedef struct tr_solid {
  uint32_t npieces;
  int64_t *front;  /* per piece: the winding number on its front (where its normal points) */
  int64_t *weight; /* per piece: the sum of its sources' signs; back = front + weight */
  uint8_t *keep;   /* per piece: TR_SOLID_* */
  uint32_t nkept, ninternal; /* pieces on the boundary (kept or flipped), internal ones */
  uint32_t ncomponents, nrays; /* connected parts (by edges), rays cast */
} tr_solid;

/* sol = the solid of arr (the arrangement of plc): the cells with winding number >= 1.
 * Pieces between two solid cells are TR_SOLID_INTERNAL when keep_internal, else dropped.
 * An input whose winding number is not defined (an open soup, or triangles oriented
 * against their neighbours) is TR_ERR_OPEN naming the edge and the input triangles
 * (plc->tri_source's numbering when the reader set it). Free with tr_solid_free (also
 * after a failure). */
tr_status tr_solid_classify(const struct tr_plc *plc, const tr_arrangement *arr,
                            int keep_internal, tr_solid *sol);
void tr_solid_free(tr_solid *sol);
/* out (initialised) = 6 times the exact volume of the solid: the signed volumes of the
 * boundary pieces, oriented outward, against the origin. A check for tests: the sum's
 * denominator is the lcm of the pieces', which grows with every rational corner (minutes
 * on 300k pieces with thousands of them). */
tr_status tr_solid_volume6(const struct tr_plc *plc, const tr_arrangement *arr,
                           const tr_solid *sol, mpq_t out);

/* ---- surface.c: what the pipeline meshes under --resolve ---- */
typedef struct tr_resolve_info {
  uint64_t npairs;                  /* improper pairs of input triangles */
  uint32_t npieces, nkept, ninternal, ncomponents;
  uint32_t nnew;                    /* new vertices on the solid's boundary */
  uint32_t nexact;                  /* of which rational points that are no doubles */
  int identity;                     /* 1: the input as given bounds its solid */
  double seconds;                   /* wall-clock time of the arrangement and the solid */
} tr_resolve_info;

/* *out = the boundary of in's solid (mode 1: winding number >= 1, the pieces inside it
 * dropped; mode 2: kept as internal facets) as a new PLC: the pieces' vertices (input
 * points in input order, then new ones), the pieces oriented outward, each with its
 * marker, tri_source naming its first source's input element, vsize carried (0 at new
 * points), hole and region points copied. *out = NULL when in itself is that boundary
 * (every triangle one piece, kept as given): the caller meshes in unchanged. The solid's
 * boundary having a vertex that is no double is TR_ERR_UNSUPPORTED naming it, input
 * segments with a changed surface too; an empty solid is TR_ERR_INPUT. */
tr_status tr_resolve_plc(const struct tr_plc *in, int mode, struct tr_plc **out,
                         tr_resolve_info *info);
/* What the command and the pipeline do with it (opt->resolve the mode): *p replaced by
 * its validated copy when tr_plc_validate(opt) accepts it, so that an input valid before
 * gives the same mesh; else by the boundary of its solid (kept when it bounds it as
 * given). With `report` one line on stderr of what it found. */
tr_status tr_resolve_replace(struct tr_plc **p, const struct tr_options *opt, int report);

/* The point of vertex v (d: the input's coordinates). */
static inline tr_point tr_arr_point(const tr_arrangement *arr, const struct tr_plc *plc,
                                    uint32_t v)
{
  const tr_arr_vertex *x = arr->verts + v;
  return x->q ? tr_pt_q(x->q) : tr_pt_d(plc->xyz + 3 * (size_t)x->input);
}

#endif
