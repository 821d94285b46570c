/* Internal state of the refinement stage (refine.h), shared by its files:
 *   subs.c      the sub-face and sub-segment tables and the face map
 *   encroach.c  exact encroachment tests and the exact split points on constraints
 *   cavity.c    constrained Bowyer-Watson: locate, cavity, insertion
 *   refine.c    the queues, the main loop and the bad tets
 *   split.c     splitting a queued sub-segment or sub-face
 *   longs.c     the long sub-segments near a point (a close circumcentre's shortcut)
 *   memo.c      what a caller's tr_refine_memo keeps from one set-up for the next
 *   sizing.c    the size field: vertex sizes, the tets and pieces over it */
#ifndef TR_REFINE_IMPL_H
#define TR_REFINE_IMPL_H

#include <stdint.h>

#include "core/facets.h"
#include "core/vtmap.h"
#include "recover_edges/edgeset.h"
#include "refine/refine.h"

/* What a vertex lies on: for split points the constraint it was inserted on. */
enum { RF_FREE = 0, RF_INPUT = 1, RF_SEG = 2, RF_FACET = 3 };

/* The grid of the long sub-segments' diametral balls (longs.c). */
typedef struct rf_longs {
  int built;
  double o[3], h;  /* grid origin and cell size */
  tr_vtmap cells;  /* cell (i,j,k) -> its first entry in ent */
  tr_u32buf ent;   /* per entry: sub-segment, next entry of the cell (TR_VTMAP_NONE: end) */
  tr_u32buf wide;  /* sub-segments whose ball spans too many cells: scanned every query */
} rf_longs;

/* Cap clusters (capcluster.c): input triangles with a corner over 179 degrees, joined
 * across the edges they share, two caps or more. The constraints of one cluster lie within a sliver of their
 * length of each other without meeting at a small angle at one vertex; a piece of one is
 * not split for a point on another, and a bad tet whose shortest edge joins two of them
 * is left. */
typedef struct rf_caps {
  uint32_t n;     /* caps in clusters; 0: none, and the tables below are empty */
  tr_vtmap edge;  /* an input edge of a cap (sorted ids) -> its cluster */
  uint32_t *vert; /* per input vertex: the cluster of a cap at it, or TR_NONE */
  uint32_t *tri;  /* per input triangle: its cluster, or TR_NONE */
} rf_caps;

typedef struct rf_ctx {
  struct tr_mesh *m;
  const struct tr_plc *plc;
  tr_refine_params par;
  tr_refine_stats *st;
  /* the input's planar facets (core/facets.h): refinement works on facets, not
   * triangles; its inner edges are no constraints (none with par.keep_edges) */
  tr_facets fc;
  /* sub-faces: vertices (right-hand normal = the input triangle's), facet (the group id of
   * its input triangles, a triangle of the facet: it spans the facet's plane exactly) */
  uint32_t nsf, capsf;
  uint32_t *sfv, *sftri;
  uint32_t *sfexp; /* the input triangle export gives it, known from par.sub_exported, or
                      TR_NONE */
  uint8_t *sfdead;
  tr_vtmap fm;      /* sorted sub-face vertices -> sub-face id (rf_face_set); a split
                       sub-face's entry stays and points to a dead id */
  tr_vtmap trimap;  /* the input triangles by their vertices (angles.c) */
  rf_caps caps;
  /* sub-segments: vertices, the input edge (A,B) they lie on (input ids, A < B) */
  uint32_t nss, capss;
  uint32_t *ssv, *ssab;
  uint8_t *ssdead, *ssnosplit;
  tr_edgeset es; /* {u,v} -> sub-segment id (dead ids stay) */
  /* per vertex: RF_* kind and owner (input edge id = index into ssab pairs of the first
   * sub-segment of that edge, or input triangle) */
  uint32_t capv;
  uint8_t *vkind;
  uint32_t *vown; /* RF_SEG: a,b packed via seg id; RF_FACET: facet (group id) */
  /* insertion radius of the points refinement added (0 for the others): the distance to
   * their nearest vertex when inserted (Shewchuk 1998; Si 2015); a circumcentre closer
   * than that to such a point is not inserted (refine.c, too_close) */
  double *vrad;
  /* with par.spacing_radii (capv of them, grown with vrad): each vertex's spacing, its
   * insertion radius shrunk to its distance to every point later put next to it while
   * spacing_on (0: none) */
  double *vspace;
  int spacing_on;
  /* a circumcentre too close to a new vertex still has the long sub-segments it
   * encroaches split (refine.c, refine_tet); 0 after spacing_cap points */
  int close_splits;
  rf_longs longs; /* the pieces close splits may still take (longs.c) */
  /* 1 once the --spacing-radii cap ended ratio refinement: the tets over a volume bound
   * are still refined (refine.c, run), since that bound is the user's hard limit */
  int volume_only;
  uint8_t *sfnosplit;
  /* queues (FIFO through a head index) */
  tr_u32buf qseg, qface, qtet; /* qtet: 5 entries per item: tet, its 4 vertices */
  size_t hseg, hface, htet;
  /* scratch of one insertion */
  tr_u32buf cav, init, bfaces, stack, newsf, tmp, newtets;
  uint8_t *tstate; /* cavity state per tet slot (cavity.c), 0 at rest */
  uint32_t captstate;
  /* per vertex slot: the stamp of the last cone whose faces hold it, and there the first
   * of its coned-face incidences (3 * face + corner, chained by cnext) (cavity.c) */
  uint32_t *vcone, *vhead, capvcone, cone_stamp;
  tr_u32buf cnext;
  uint32_t split_seg; /* the sub-segment the point being inserted splits, or TR_NONE */
  /* sub-faces split for their shape (subshape.c): on in tr_refine with a ratio bound; the
   * sub-faces from shape_next on are not checked yet */
  int shape_on;
  double shape_bound;
  uint32_t shape_next;
  /* flat sub-faces (flat.c): per sub-segment id below nssfoot, the parameter along its
   * input edge of the vertex foot it is split at, NAN for none */
  double *ssfoot;
  uint32_t nssfoot;
  /* the size field (sizing.c), with par.sizing: per vertex slot below capvh its size (0:
   * none), the background tet last found, and the sub-segments and sub-faces from
   * size_ss / size_sf on not checked against it yet */
  double *vh;
  uint32_t capvh, vh_hint, size_ss, size_sf;
  /* rounds of parallel insertion (rounds.c): allowed (tr_refine only), and their state */
  int rounds_on;
  struct rround *rounds;
} rf_ctx;

/* Squared distance of two points in doubles (a measure for the rules, never a decision
 * of validity). */
static inline double rf_dist2(const double *a, const double *b)
{
  return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
         (a[2] - b[2]) * (a[2] - b[2]);
}

/* ---- longs.c ---- */
/* Sub-segment g is at least half its input edge (on the doubles). */
int rf_piece_long(const rf_ctx *c, uint32_t g);
/* A close circumcentre of a tet whose shortest edge has square emin splits g (refine.c):
 * g is at least twice that edge and at least half its input edge. */
int rf_close_split(const rf_ctx *c, uint32_t g, double emin);
/* *maybe = 0 only if no live sub-segment g with rf_close_split(c, g, emin) has p in its
 * diametral ball (exactly, rf_in_diametral); builds the grid on the first call. */
tr_status rf_longs_near(rf_ctx *c, const double p[3], double emin, int *maybe);
/* A new sub-segment g: into the grid if it is built and g is long. */
tr_status rf_longs_added(rf_ctx *c, uint32_t g);
void rf_longs_free(rf_longs *L);

/* ---- memo.c (what a tr_refine_memo keeps between set-ups) ---- */
/* Frees the tables rf_subs_init builds (fc, the sub-face and sub-segment arrays, fm,
 * trimap, es, vkind, vown), then zeroes all of *t. */
void rf_tables_free(rf_ctx *t);
/* The memo holds the tables of a set-up on these sub-faces, and the vertex ids they name
 * still name the same points (the memo's n: ids from n on may have been reused). */
int rf_memo_fits(const rf_ctx *c, const tr_subfaces *sub);
/* c's tables copied from the memo's (rf_memo_fits); c's vertex arrays have room. */
tr_status rf_memo_copy(rf_ctx *c);
/* The memo (if any) keeps a copy of c's tables, just built from sub; none when out of
 * memory (the copy only saves time). */
void rf_memo_keep(rf_ctx *c, const tr_subfaces *sub);
/* The tables that depend on the plc alone (facets, the triangle map, the cap clusters)
 * copied from the memo's when it holds them for c's plc and keep_edges (*have = 1), so a
 * set-up on other sub-faces rebuilds only theirs. */
tr_status rf_memo_plc_tables(rf_ctx *c, int *have);
/* The per-vertex lines of on_input_edge for nv vertices (subs.c): the memo's, its entries
 * from memo->n on reset, or without a memo a fresh array the caller frees. NULL when out
 * of memory: every test is then made in full. */
uint32_t *rf_memo_line(tr_refine_memo *memo, uint32_t nv);

/* ---- subs.c ---- */
/* Face keys in the shared vertex-tuple map: any listing of the face's vertices. */
static inline tr_status rf_face_set(tr_vtmap *f, const uint32_t v[3], uint32_t val)
{
  uint32_t k[3];
  tr_vtkey_face(v[0], v[1], v[2], k);
  return tr_vtmap_set(f, 3, k, val); /* a dead entry revived by a new sub-face */
}
static inline uint32_t rf_face_get(const tr_vtmap *f, uint32_t a, uint32_t b, uint32_t c)
{
  uint32_t k[3];
  tr_vtkey_face(a, b, c, k);
  return tr_vtmap_get(f, 3, k);
}
/* Builds the tables from sub (and the plc's triangles). */
tr_status rf_subs_init(rf_ctx *c, const tr_subfaces *sub);
tr_status rf_subface_add(rf_ctx *c, uint32_t a, uint32_t b, uint32_t d, uint32_t tri,
                         uint32_t *id);
tr_status rf_subseg_add(rf_ctx *c, uint32_t u, uint32_t v, uint32_t A, uint32_t B,
                        uint32_t *id);
/* The live sub-face with vertices {a,b,c}, TR_NONE if none. */
uint32_t rf_subface_of(const rf_ctx *c, uint32_t a, uint32_t b, uint32_t d);
/* The live sub-segment {u,v}, TR_NONE if none. */
uint32_t rf_subseg_of(const rf_ctx *c, uint32_t u, uint32_t v);
/* The live sub-faces back into a tr_subfaces (sorted by triangle, then vertex ids). */
tr_status rf_subs_export(const rf_ctx *c, tr_subfaces *out);
tr_status rf_vertex_room(rf_ctx *c, uint32_t nv);

/* ---- encroach.c ---- */
/* 1 iff p is strictly inside the diametral sphere of segment ab (exact). */
int rf_in_diametral(const tr_point *a, const tr_point *b, const tr_point *p);
/* 1 iff p is strictly inside the equatorial sphere of triangle abc (exact). */
int rf_in_equatorial(const tr_point *a, const tr_point *b, const tr_point *c,
                     const tr_point *p);
/* The split point of sub-segment s, exactly on its input edge (malloc'ed, initialised). */
tr_status rf_segment_split_point(rf_ctx *c, uint32_t s, tr_qpoint **out);
/* The split point of sub-face f: its circumcentre as a dyadic barycentric combination of
 * its input triangle's vertices (within 1/16 of f's size), located by a walk in the facet:
 * *where = the sub-face that holds it. When the walk meets a sub-segment first (the
 * circumcentre lies beyond it or on it), *encseg = that sub-segment and *where = TR_NONE
 * (*out is still the point, for the caller's rules); *out = NULL when no point is found. */
tr_status rf_facet_split_point(rf_ctx *c, uint32_t f, tr_qpoint **out, uint32_t *where,
                               uint32_t *encseg);
/* 1 iff the volume of tet abcd (positive) exceeds V exactly. */
int rf_volume_above(const tr_point *a, const tr_point *b, const tr_point *c, const tr_point *d,
                    double V);
/* 1 iff point p lies in the closed input triangle tri (exact). */
int rf_in_input_triangle(const rf_ctx *c, uint32_t tri, const tr_point *p);
/* The smallest triangle of facet g (a group id) whose closure holds p (exact), TR_NONE if
 * p is not in the closed facet. hint: a triangle to try first, or TR_NONE. */
uint32_t rf_facet_triangle_of(const rf_ctx *c, uint32_t g, const tr_point *p, uint32_t hint);

/* ---- angles.c ---- */
/* The cosine of the angle at o between o->p and o->q, in doubles (1 for a zero side): the
 * angle rules are thresholds on input geometry, decided once, not exact predicates. */
double rf_cos_angle(const double *o, const double *p, const double *q);
/* c[k] = rf_cos_angle at corner k of triangle x0 x1 x2 (o = x_k, p = x_k+1, q = x_k+2),
 * the same values, sharing the three edge vectors between the corners (a zero cosine may
 * be -0 where rf_cos_angle's is +0: equal in every comparison and to acos). */
void rf_tri_cos_angles(const double *x0, const double *x1, const double *x2, double c[3]);
/* 1 iff the constraints x and y lie on meet at an input vertex under a small angle. */
int rf_small_angle_edge(const rf_ctx *c, uint32_t x, uint32_t y);
/* 1 iff sub-segment (seg) / sub-face id is protected from a split caused by vertex v. */
int rf_protected(const rf_ctx *c, int seg, uint32_t id, uint32_t v);
/* The same for a point at pw on a constraint (kind RF_*, owner own) not inserted yet. */
int rf_protected_at(const rf_ctx *c, int seg, uint32_t id, int kind, uint32_t own,
                    const double *pw);

/* 1 iff sub-segment g, encroached by vertex v on a constraint meeting g's at a small
 * angle, may still be split to grade the wedge between them (angles.c). */
int rf_wedge_split(const rf_ctx *c, uint32_t g, uint32_t v);
tr_status rf_caps_build(rf_caps *k, const struct tr_plc *plc);
tr_status rf_caps_copy(rf_caps *dst, const rf_caps *src, const struct tr_plc *plc);
/* The cluster of input edge a-b, TR_NONE when it is no edge of a cap. */
uint32_t rf_caps_edge(const rf_caps *k, uint32_t a, uint32_t b);
void rf_caps_free(rf_caps *k);

/* ---- subshape.c ---- */
/* 1 iff sub-face f's radius-edge ratio exceeds bound, its shortest edge taken at least as
 * long as its ends' insertion radii, its smallest angle is not an input corner and its
 * shortest edge does not join two constraints meeting at a small angle. */
int rf_subface_shape_bad(const rf_ctx *c, uint32_t f, double bound);
/* Queues (c->qface) the sub-faces made since the last call that are bad for their shape. */
tr_status rf_subshape_scan(rf_ctx *c);
/* 1 iff sub-segment g, on an edge of f's input triangle, that f's split point encroaches
 * or lies beyond, may be split for f although protected near a sharp corner: a vertex of
 * f encroaches it, or its half is no shorter than f's shortest edge. */
int rf_subshape_may_split(const rf_ctx *c, uint32_t f, uint32_t g);

/* ---- flat.c ---- */
/* Queues (c->qseg) each sub-segment opposite an angle over 120 degrees of a live
 * sub-face, to be split at that vertex's foot (once: c->ssfoot); *pushed = 1 when one
 * was. */
tr_status rf_flat_scan(rf_ctx *c, int *pushed);
/* For a sub-segment g queued by rf_flat_scan, with parameter interval [lo, hi] on its
 * input edge: t = its split parameter, an exact rational inside (lo, hi); returns 1, else
 * 0 (g is split as any other). */
int rf_flat_split_param(const rf_ctx *c, uint32_t g, const mpq_t lo, const mpq_t hi, mpq_t t);

/* ---- sizing.c ---- */
/* The sizes of the vertices of c->m (par.vsize, then the field). */
tr_status rf_sizing_init(rf_ctx *c);
/* The size of vertex pid, just inserted, from the field. */
tr_status rf_sizing_vertex(rf_ctx *c, uint32_t pid);
/* 1 iff tet t's longest edge is over the mean of its vertices' sizes (none: 0). */
int rf_sizing_tet_over(const rf_ctx *c, uint32_t t);
/* The radius within which a vertex refuses tet t's circumcentre, at most (refine.c,
 * too_close): half the mean of t's vertices' sizes when t is over the field, INFINITY
 * otherwise. */
double rf_sizing_cap(const rf_ctx *c, uint32_t t);
/* Queues the sub-segments and sub-faces made since the last call that are over the
 * field (their longest edge over the mean of their vertices' sizes). */
tr_status rf_sizing_scan(rf_ctx *c);

/* ---- cavity.c ---- */
/* Straight walk from tet t towards p; *found = tet whose closure holds p, or TR_NONE; if
 * the walk is stopped by a sub-face, *blocker = that sub-face (else TR_NONE). */
tr_status rf_locate(rf_ctx *c, uint32_t t, const tr_point *p, uint32_t *found,
                    uint32_t *blocker);
/* The cavity of p from tet t0 (p in its closure): c->cav (tets), c->bfaces (coned faces,
 * as 4*tet+face). allow_split: p lies on a constraint and may split the sub-faces whose
 * input triangle holds it. *ok = 0 when no valid cavity exists (p is a vertex, or lies
 * on a constraint it may not split). */
tr_status rf_cavity(rf_ctx *c, uint32_t t0, const tr_point *p, uint32_t pid, int allow_split,
                    int *ok);
/* Forgets the cavity of the last successful rf_cavity without inserting. */
void rf_cavity_release(rf_ctx *c);

/* ---- refine.c ---- */
/* Bookkeeping after vertex pid (of kind RF_*, on constraint own) went in: its insertion
 * radius (rad, or its distance to the nearest vertex of its new tets when smaller), and
 * its new tets queued when bad. */
tr_status rf_after_insert(rf_ctx *c, uint32_t pid, int kind, uint32_t own, double rad);
/* The loop's own tests and steps, for rounds.c: tet t is bad; over its volume bound; left
 * for a small input angle; p within the radius of a vertex of the tets (or within cap);
 * t queued when bad; t refined as the loop does. */
int rf_tet_bad(const rf_ctx *c, uint32_t t);
int rf_too_big(const rf_ctx *c, uint32_t t);
int rf_forced_by_angle(const rf_ctx *c, uint32_t t);
int rf_too_close(const rf_ctx *c, const uint32_t *tets, size_t n, const double *p, double cap);
tr_status rf_push_tet(rf_ctx *c, uint32_t t);
tr_status rf_refine_tet(rf_ctx *c, uint32_t t);
/* The sub-segments and sub-faces of t that a vertex of t encroaches, queued (tet.c); *pushed
 * = 1 when one was. */
tr_status rf_own_encroached(rf_ctx *c, uint32_t t, int *pushed);

/* ---- rounds.c ---- */
/* The fewest points a round may add (else the next tet goes the serial way). */
#define RF_ROUND_LEAST 64u
/* Rounds are allowed here and enough bad tets are queued. */
int rf_round_wanted(const rf_ctx *c);
/* One round: up to `room` circumcentres of queued bad tets inserted on par.threads
 * threads, the rest of its tets refined by the serial loop, the losers queued first. The
 * same mesh for any thread count. */
tr_status rf_round(rf_ctx *c, uint64_t room);
void rf_rounds_free(rf_ctx *c);

/* ---- split.c ---- */
/* Splits sub-segment g (queued, live): inserted, or marked ssnosplit. */
tr_status rf_split_segment(rf_ctx *c, uint32_t g);
/* Splits sub-face f (queued, live): inserted, its encroached sub-segment queued first (f
 * queued again), or marked sfnosplit. */
tr_status rf_split_facet(rf_ctx *c, uint32_t f);

/* ---- insert.c ---- */
/* Replaces the cavity by the cone from vertex pid (already in the mesh), updates the
 * sub-faces and, when c->split_seg != TR_NONE, that sub-segment; the new tets are in
 * c->newtets. *ok = 0 (mesh unchanged, cavity released, pid removed when it is the last
 * vertex and in no tet) when the cone would not glue, or when the point is refused for
 * the doubles it and its cone are written as (rounding_allows). */
tr_status rf_insert(rf_ctx *c, uint32_t pid, int *ok);
/* The doubles' test of rf_insert for a point at the double x (no exact point of its own)
 * coned over the faces bf (4 * tet + face): no vertex of them inseparable from x, every
 * new tet strictly positive. */
int rf_cone_admits(const struct tr_mesh *m, const uint32_t *bf, size_t nbf, const double x[3]);

#endif
