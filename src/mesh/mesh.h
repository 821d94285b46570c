/* The mesh store: tetrahedra in flat uint32_t arrays, HXT style.
 *
 *   tv[4*t + k]  vertex k of tet t (k = its NCode). tv[4*t] == TR_NONE: t is free.
 *   tn[4*t + k]  neighbour across face k (the face opposite vertex k, FCode = k),
 *                encoded as 4*t' + k' where k' is the face of t' shared with t;
 *                TR_NONE when there is none. So NEIG(t,k) = tn[4t+k] >> 2 and the
 *                shared face's code in the neighbour comes for free as tn[4t+k] & 3.
 *
 * Orientation (one convention, see include/tetrec.h): tet (v0,v1,v2,v3) is positive iff
 * tr_orient3d(v0,v1,v2,v3) > 0. The vertices of face k listed in tr_face_vtx[k] order
 * (a,b,c) satisfy orient3d(a,b,c,vk) > 0: seen from vk they turn clockwise, i.e. their
 * right-hand normal points into the tet.
 *
 * Convex hull: the Delaunay stage uses ghost tets: tets with vertex TR_GHOST in slot 3
 * (see delaunay/), so every real tet has 4 neighbours; ghost tets are skipped by
 * iterators that say so and removed by outer removal.
 *
 * Memory per tet slot: tv 16 + tn 16 + flags 1 bytes, plus 4 bytes of region id only once
 * tr_mesh_enable_regions() was called (37 <= 40).
 */
#ifndef TR_MESH_H
#define TR_MESH_H

#include <stddef.h>
#include <stdint.h>

#include "../../predicates/qpoint.h"
#include "../core/status.h"

#ifdef __cplusplus
extern "C" {
#endif

#define TR_NONE UINT32_MAX
/* The single vertex "at infinity" of the ghost tets. Never a valid vertex index. */
#define TR_GHOST (UINT32_MAX - 1)

/* tr_face_vtx[k] = the three vertex codes of face k, ordered as explained above:
 * {1,3,2}, {0,2,3}, {0,3,1}, {0,1,2}. */
extern const uint8_t tr_face_vtx[4][3];
/* The six edges in ECode order 0-1, 0-2, 0-3, 1-2, 1-3, 2-3 (the paper's Table 1). */
extern const uint8_t tr_edge_vtx[6][2];
/* tr_face_rot[k][j] (j != k): face j listed in tr_face_vtx[j] order and rotated to begin
 * with vertex code k is (k, tr_face_rot[k][j][0], tr_face_rot[k][j][1]). Used to glue
 * tets that share a vertex: two tets sharing face {k,u,v} list it as (k,u,v) and (k,v,u).
 * tr_face_rot[k][k] is {k,k} (unused). */
extern const uint8_t tr_face_rot[4][4][2];

/* Per-tet flag bits. TR_TF_MARK is a scratch bit: every routine that sets it clears it
 * before returning, so at rest it is 0 everywhere. */
enum {
  TR_TF_MARK = 1u << 0,    /* scratch: visited by the running traversal */
  TR_TF_MARK2 = 1u << 1,   /* second scratch bit (same rule) */
  TR_TF_OUTER = 1u << 2,   /* classified outside the domain (outer removal) */
  TR_TF_USER = 1u << 4     /* bits 4..7 free for later stages */
};

/* What an output mesh knows of its input, for the accessors of include/tetrec.h
 * (src/pipeline/access.c). Only the meshes that tr_mesh_plc and tr_delaunay return have
 * it; every array is malloc'ed and freed by tr_mesh_destroy. */
struct tr_mesh_attrs {
  uint32_t *tets;         /* NULL, or 4 per real tet when tv has ghost or free slots */
  uint32_t ntets;
  uint32_t nfaces;        /* faces on input triangles (tetrec.h's boundary faces) */
  uint32_t *faces;        /* 3 * nfaces, oriented like their input triangle */
  uint32_t *face_tri;     /* nfaces: the input triangle */
  int32_t *face_marker;   /* nfaces: its marker */
  uint8_t *vkind;         /* NULL (every vertex an input vertex), or nv enum tr_vertex_origin */
  uint32_t *vindex;       /* nv: the input vertex, edge or triangle */
  uint32_t nedges;
  uint32_t *edges;        /* 2 * nedges: the input edges, a < b, sorted */
};
void tr_mesh_attrs_free(struct tr_mesh_attrs *a);
/* Fills m->attrs->tets (creating attrs) with the real tets, for a store that keeps ghost
 * or free slots (tr_delaunay's), so that tr_mesh_tets returns a dense array. */
tr_status tr_mesh_attach_dense_tets(struct tr_mesh *m);

/* The public opaque handle of include/tetrec.h is the store itself. */
struct tr_mesh {
  /* vertices */
  uint32_t nv, cap_v;
  double *xyz;        /* 3 * cap_v; for a Steiner point: its nearest double, or after
                       * tr_mesh_plc its repaired double (src/output/round.h) */
  tr_qpoint **vq;     /* NULL, or cap_v entries: exact point of a Steiner vertex (owned),
                         NULL for input points */
  uint32_t *v2t;      /* cap_v: one tet incident to the vertex, TR_NONE if none */
  /* tets */
  uint32_t nt, cap_t; /* slots in use (free ones included) and capacity */
  uint32_t *tv, *tn;  /* 4 * cap_t each, see above */
  uint8_t *flags;     /* cap_t, TR_TF_* bits */
  uint32_t *region;   /* NULL, or cap_t region ids (see tr_mesh_enable_regions) */
  uint32_t free_head; /* free list of slots, linked through tn[4*t] */
  uint32_t nfree;
  /* Delaunay bookkeeping: duplicate input points */
  uint32_t ndup;      /* number of input points dropped as duplicates */
  uint32_t *dup_map;  /* NULL, or nv entries: dup_map[i] = kept vertex equal to point i
                         (dup_map[i] == i for kept points; TR_NONE for an interior point
                         a sliver cavity swallowed, src/sliver/insert.c: in no tet) */
  struct tr_mesh_attrs *attrs; /* NULL, or output attributes (see above) */
  struct tr_orient_memo *omemo; /* NULL, or the orientation memo (orient_memo.h) */
};
typedef struct tr_mesh tr_mesh_store;

/* A growable uint32 array for traversal results (Ball, Shell). Zero-initialise it; free
 * its `a` with free() or tr_u32buf_free. */
typedef struct tr_u32buf {
  uint32_t *a;
  size_t n, cap;
} tr_u32buf;
tr_status tr_u32buf_push(tr_u32buf *b, uint32_t x);
tr_status tr_u32buf_reserve(tr_u32buf *b, size_t cap);
void tr_u32buf_free(tr_u32buf *b);

/* ---- life cycle ---- */
/* An empty store with room for the given numbers of vertices and tets (hints, may be 0). */
tr_status tr_mesh_create(uint32_t vcap, uint32_t tcap, struct tr_mesh **out);
/* tr_mesh_destroy() is in tetrec.h. */
tr_status tr_mesh_reserve_vertices(struct tr_mesh *m, uint32_t vcap);
tr_status tr_mesh_reserve_tets(struct tr_mesh *m, uint32_t tcap);
/* Allocates the region array (filled with 0). */
tr_status tr_mesh_enable_regions(struct tr_mesh *m);

/* ---- vertices ---- */
/* Appends an input point (copied), *idx = its index. v2t is TR_NONE until a tet uses it. */
tr_status tr_mesh_add_vertex(struct tr_mesh *m, const double xyz[3], uint32_t *idx);
/* Appends a Steiner point; the store takes ownership of q (allocated with malloc,
 * initialised with tr_qpoint_init) and frees it with tr_qpoint_clear + free. */
tr_status tr_mesh_add_steiner(struct tr_mesh *m, tr_qpoint *q, uint32_t *idx);
/* The same for a point the recovery just constructed, after a size guard: exact Steiner
 * points built from earlier Steiner points can grow in bit size from one to the next
 * (an intersection's coordinates have the sizes of its inputs added up), and past
 * TR_STEINER_MAX_BITS (numerators and denominators of the three coordinates together)
 * every predicate on them takes seconds. Past it: TR_ERR_UNSUPPORTED with a message, q
 * not taken (the caller frees it), instead of a run that does not end. Subnormal input
 * coordinates have 1,074-bit denominators, so their Steiner points start large: on
 * Chazelle's polyhedron moved by ulps (zeros moved to subnormals) a facet Steiner point
 * built on edge Steiner points needs 20,615 bits and the whole recovery 0.9 s; the limit
 * leaves that a margin of 3.2. */
#define TR_STEINER_MAX_BITS 65536
tr_status tr_mesh_add_constructed(struct tr_mesh *m, tr_qpoint *q, uint32_t *idx);
/* Takes back the last vertex, a point no tet uses (a split that did not go ahead): frees
 * its exact point, and empties the orientation memo (orient_memo.h), since the id will
 * name another point. */
void tr_mesh_pop_vertex(struct tr_mesh *m);
/* The exact point of vertex v (v must not be TR_GHOST). */
static inline tr_point tr_mesh_point(const struct tr_mesh *m, uint32_t v)
{
  if (m->vq && m->vq[v])
    return tr_pt_q(m->vq[v]);
  return tr_pt_d(m->xyz + 3 * (size_t)v);
}

/* q (initialised by the caller) = the exact centroid of vertices v[0..2]: which input
 * triangle of a merged facet holds a sub-face is asked of it (refine/subs.c,
 * sliver/facetflip.c). */
void tr_mesh_centroid_q(const struct tr_mesh *m, const uint32_t v[3], tr_qpoint *q);

/* ---- tets ---- */
static inline int tr_tet_is_free(const struct tr_mesh *m, uint32_t t)
{
  return m->tv[4 * (size_t)t] == TR_NONE;
}
static inline int tr_tet_is_ghost(const struct tr_mesh *m, uint32_t t)
{
  return m->tv[4 * (size_t)t + 3] == TR_GHOST;
}
/* A live tet that is not a ghost. */
static inline int tr_tet_is_real(const struct tr_mesh *m, uint32_t t)
{
  return !tr_tet_is_free(m, t) && !tr_tet_is_ghost(m, t);
}
/* NEIG(t,k) of the paper: the tet across face k, TR_NONE if none. */
static inline uint32_t TR_NEIG(const struct tr_mesh *m, uint32_t t, int k)
{
  uint32_t c = m->tn[4 * (size_t)t + (size_t)k];
  return c == TR_NONE ? TR_NONE : c >> 2;
}

/* A new slot (from the free list, else appended) with vertices (a,b,c,d), no neighbours,
 * flags 0; updates v2t of its vertices. The caller guarantees the orientation. */
tr_status tr_tet_new(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t c, uint32_t d,
                     uint32_t *t);
/* Frees slot t. Neighbours still pointing to t are the caller's business; v2t entries
 * pointing to t are not repaired (use tr_mesh_replace for consistent edits). */
void tr_tet_free(struct tr_mesh *m, uint32_t t);
/* Links face k1 of t1 with face k2 of t2 (both directions). */
static inline void tr_glue(struct tr_mesh *m, uint32_t t1, int k1, uint32_t t2, int k2)
{
  m->tn[4 * (size_t)t1 + (size_t)k1] = 4 * t2 + (uint32_t)k2;
  m->tn[4 * (size_t)t2 + (size_t)k2] = 4 * t1 + (uint32_t)k1;
}

/* Sorts three vertex ids in place: the key of a face whatever its orientation. */
static inline void tr_sort3(uint32_t f[3])
{
  uint32_t t;
  if (f[0] > f[1]) { t = f[0]; f[0] = f[1]; f[1] = t; }
  if (f[1] > f[2]) { t = f[1]; f[1] = f[2]; f[2] = t; }
  if (f[0] > f[1]) { t = f[0]; f[0] = f[1]; f[1] = t; }
}

/* qsort / bsearch order of face keys (three sorted vertex ids): lexicographic. */
static inline int tr_cmp_face_key(const void *pa, const void *pb)
{
  const uint32_t *a = (const uint32_t *)pa, *b = (const uint32_t *)pb; /* C++ tests too */
  for (int i = 0; i < 3; i++)
    if (a[i] != b[i])
      return a[i] < b[i] ? -1 : 1;
  return 0;
}

/* qsort / bsearch order of edge keys (two sorted vertex ids): lexicographic. */
static inline int tr_cmp_edge_key(const void *pa, const void *pb)
{
  const uint32_t *a = (const uint32_t *)pa, *b = (const uint32_t *)pb;
  if (a[0] != b[0])
    return a[0] < b[0] ? -1 : 1;
  return a[1] < b[1] ? -1 : a[1] > b[1];
}

/* A fixed hash of a vertex triple (sort it first where orientation must not matter): the
 * face tables take their slot from its high bits, so no run depends on addresses. */
static inline uint64_t tr_hash3(const uint32_t k[3])
{
  return k[0] * 0x9e3779b97f4a7c15ull ^ k[1] * 0xc2b2ae3d27d4eb4full ^
         k[2] * 0x165667b19e3779f9ull;
}

/* Rotates a face to begin with its smallest vertex id: the same turn, one listing. */
static inline void tr_rotate_min3(uint32_t w[3])
{
  int s = w[1] < w[0] ? 1 : 0;
  if (w[2] < w[s])
    s = 2;
  uint32_t r[3] = {w[s], w[(s + 1) % 3], w[(s + 2) % 3]};
  w[0] = r[0];
  w[1] = r[1];
  w[2] = r[2];
}

/* ---- the paper's codes ---- */
/* Inline: the flip searches of edge recovery ask these codes millions of times (a tenth
 * of the samples of a --keep-surface run on 65395.stl went to the calls). */
/* NCode: slot 0..3 of vertex v in t, -1 if v is not a vertex of t. */
static inline int tr_ncode(const struct tr_mesh *m, uint32_t t, uint32_t v)
{
  const uint32_t *tv = m->tv + 4 * (size_t)t;
  for (int k = 0; k < 4; k++)
    if (tv[k] == v)
      return k;
  return -1;
}
/* ECode of edge {a,b} in t: start | end << 2 with start < end, -1 if not an edge of t.
 * (Named tr_tet_ecode because classify.h's tr_ecode(start,end) builds a code.) */
static inline int tr_tet_ecode(const struct tr_mesh *m, uint32_t t, uint32_t a, uint32_t b)
{
  int i = tr_ncode(m, t, a), j = tr_ncode(m, t, b);
  if (i < 0 || j < 0 || i == j)
    return -1;
  return i < j ? (i | j << 2) : (j | i << 2);
}
/* FCode of face {a,b,c} in t: the slot of the fourth vertex, -1 if not a face of t. */
static inline int tr_fcode(const struct tr_mesh *m, uint32_t t, uint32_t a, uint32_t b,
                           uint32_t c)
{
  int i = tr_ncode(m, t, a), j = tr_ncode(m, t, b), k = tr_ncode(m, t, c);
  if (i < 0 || j < 0 || k < 0 || i == j || j == k || i == k)
    return -1;
  return 6 - i - j - k;
}
/* Parity of (p0..p3) as an ordering of t's vertices: 1 even (same orientation as t), 0
 * odd, -1 if they are not t's vertices. */
int tr_tet_even_order(const struct tr_mesh *m, uint32_t t, const uint32_t p[4]);

/* ---- traversals (iter.c) ---- */
/* Ball(P): every tet incident to vertex p, found by a breadth-first search through faces
 * containing p from v2t[p]. Ghost tets are included iff with_ghosts. out is reset first.
 * TR_ERR_INVALID_MESH if v2t[p] does not contain p. */
tr_status tr_ball(struct tr_mesh *m, uint32_t p, int with_ghosts, tr_u32buf *out);
/* The same search, stopped at the first real tet that also has vertex b and, unless c is
 * TR_NONE, vertex c: *t = that tet, TR_NONE if p, b (, c) span no edge (face) of the mesh
 * (an edge or face on the hull is also in the real tet inside it). The presence tests of
 * both recovery stages: no allocation for balls of up to 256 tets. */
tr_status tr_ball_find(struct tr_mesh *m, uint32_t p, uint32_t b, uint32_t c, uint32_t *t);
/* tr_ball_find for a mesh of the domain alone (outer tets freed, as in refinement): there
 * a vertex where parts of the domain touch (two cubes sharing an edge) has a ball of two
 * or more pieces, and the one v2t names need not hold the edge. The balls of p, b and c
 * are searched in turn, then every tet: *t = TR_NONE only if the edge (face) is no
 * mesh edge (face) at all. */
tr_status tr_ball_find_domain(struct tr_mesh *m, uint32_t p, uint32_t b, uint32_t c,
                              uint32_t *t);
/* with_ghosts: the first tet in tr_ball(p, 1)'s order that has b (and c), ghost or not. */
tr_status tr_ball_find_ex(struct tr_mesh *m, uint32_t p, uint32_t b, uint32_t c,
                          int with_ghosts, uint32_t *t);
/* All at once: tet[i] = the first real tet in slot order with triangle i (tris[3i..3i+2])
 * as a face, TR_NONE if the triangle is not a face of the mesh. The real tets of each
 * vertex listed in two passes over the tets, and a scan of one short list per triangle:
 * for many triangles, much cheaper than a tr_ball_find each. */
tr_status tr_mesh_find_faces(const struct tr_mesh *m, const uint32_t *tris, uint32_t n,
                             uint32_t *tet);
/* All at once: present[i] = 1 if {edges[2i], edges[2i+1]} (two distinct vertex ids below
 * nv, either order) is an edge of a real tet, else 0. One pass over the tets listing each
 * vertex's higher neighbours (with repeats) and one scan of a short list per edge: for
 * many edges, much cheaper than a tr_ball_find each. */
tr_status tr_mesh_find_edges(const struct tr_mesh *m, const uint32_t *edges, uint32_t n,
                             uint8_t *present);
/* Shell(E): the tets around edge {a,b} in rotational order, starting with t0 (a tet that
 * has edge ab; TR_NONE = find one through Ball(a)). Rotation is right-handed about a->b:
 * for consecutive tets the third vertices turn counter-clockwise seen from b towards a.
 * Ghost tets are part of the cycle. *closed = 1 if the cycle closes; 0 if it hits a
 * missing neighbour, in which case the list starts at one boundary and ends at the other. */
tr_status tr_shell(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t t0, tr_u32buf *out,
                   int *closed);

/* ---- generic edits (replace.c) ---- */
/* Replaces the tets old[0..nold) by nnew new tets with vertices newv[4*i..4*i+3] (each
 * positively oriented, ghosts allowed with TR_GHOST in slot 3): the new tets are glued to
 * each other and to the neighbours of the old region by matching faces, slots are reused,
 * v2t is repaired. Fails with TR_ERR_INTERNAL (and leaves the mesh unchanged) when the new
 * tets do not have exactly the boundary of the old region. new_ids (may be NULL) receives
 * the slots of the new tets. */
tr_status tr_mesh_replace(struct tr_mesh *m, const uint32_t *old, uint32_t nold,
                          const uint32_t *newv, uint32_t nnew, uint32_t *new_ids);
/* The same where the region meets the mesh's boundary: a face of the old region with no
 * neighbour may be gone from the new tets, and a new face matched by none is left with
 * no neighbour (a flip of two boundary faces: sliver/facetflip.c). The caller vouches
 * that the new tets fill the old region; faces with a neighbour must match as above. */
tr_status tr_mesh_replace_open(struct tr_mesh *m, const uint32_t *old, uint32_t nold,
                               const uint32_t *newv, uint32_t nnew, uint32_t *new_ids);

/* ---- export ---- */
/* Number of live non-ghost tets (O(slots)). */
uint32_t tr_mesh_count_real(const struct tr_mesh *m);
/* The real tets as a compact malloc'ed array of 4 * *ntets vertex ids, in slot order. */
tr_status tr_mesh_export_tets(const struct tr_mesh *m, uint32_t **tets, uint32_t *ntets);

#ifdef __cplusplus
}
#endif

#endif
