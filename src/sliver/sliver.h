/* Sliver removal after quality refinement (issue 17): Delaunay refinement bounds the
 * radius-edge ratio, which leaves slivers (four nearly coplanar points on a small
 * circumsphere, dihedral angles near 0 and 180 degrees). This stage raises the worst
 * dihedral angle locally, by flips and moves and, at level 3, new interior points:
 *
 *  - flips.c: for every tet whose smallest dihedral angle is under the bound, the flips
 *    that remove one of its faces (2-3) or one of its edges (3-2, 4-4, and edge removal
 *    n -> 2n-4 up to SL_MAX_RING, the triangulation of the ring chosen by dynamic
 *    programming to maximise the smallest dihedral angle). A flip is done only when the
 *    smallest dihedral angle of the tets it creates is strictly larger than that of the
 *    tets it deletes, and never deletes a constraint: a sub-face (tr_subfaces) or an edge
 *    of one (so no input edge either). Validity is exact: every new tet strictly positive
 *    by tr_orient3d_p on the exact points.
 *  - facetflip.c: where none of those helps, the flip of an edge inside a facet (sub-faces
 *    a b c, a b d -> a c d, b c d) with the fans of tets around it on both sides, of
 *    SL_FACET_FAN tets a side, else SL_FACET_FAN_LONG outside thin input triangles,
 *    under the same rules; the sub-faces, their labels and the constraint sets follow.
 *  - smooth.c: every interior vertex (on no input edge or triangle, not an input point)
 *    whose star holds such a tet is moved to a double position that strictly raises the
 *    smallest dihedral angle of its star, accepted only when every tet of the star is
 *    exactly positive with the new point. A moved vertex stays strictly inside its star,
 *    so it never reaches a constraint; its exact point becomes the double itself.
 *    The pass walks only the stars of the vertices of tets under the bound (the others do
 *    not move), and the flip pass skips a tet that found no flip while no tet at its
 *    vertices changed (tr_sliver_touch): the same result, without the searches.
 *  - insert.c (level 3): a tet under TR_SLIVER_INSERT_BOUND gets a new interior point at
 *    its circumcentre (a double), or between it and the centroid, or over one of its
 *    sub-faces, or, for a tet with three or four fixed vertices (a cap pinned between
 *    constraints, whose circumcentre lies far off), off the plane of its largest face on
 *    either side; by a cavity that crosses no sub-face, holds none between two of its
 *    tets and is star-shaped about the point, kept when the new tets' smallest angle
 *    beats the cavity's; at most TR_SLIVER_POINTS(nv) points per stage.
 *  - pinned.c, after the rounds (level 3, with the plc in keep): a tet still under
 *    SL_PINNED_BOUND with three or four vertices on constraints and a face on a sub-face
 *    is pinned there; refinement (tr_refine_open_pinned) splits the piece under it,
 *    exactly on its input edge or triangle, and a round of flips, moves and points
 *    follows, SL_PINNED_ROUNDS times at most, then one more round (the caps next to the
 *    last constraint points). That refinement runs without the ratio bound (the volume
 *    bounds hold), so its new tets may be over the ratio bound, but a tet under the
 *    stage's bound only up to the largest ratio the stage started from: it is a trial,
 *    undone (snap.c) and run again without the pinned tets near a tet that breaks this
 *    and that the rounds' steps do not open.
 *  - polish.c, last: the rounds only look at tets under the bound, so a small mesh whose
 *    worst tet is above it kept its refinement angles (icosahedron.off: 20.9 degrees).
 *    The globally worst tets, whatever their angle, worst first, get the best flip,
 *    moves of their movable vertices and (level 3) a new interior point, each kept
 *    under the same rules; a few rounds over the 32 + nt/1024 worst tets. A worst tet
 *    none of them opens (level 3, with the plc) gets points on its constraint pieces
 *    (caps.c: refinement splits one sub-segment or sub-face, the new tets get flips,
 *    moves and points), kept only when its tets beat the ones they replace and undone
 *    exactly otherwise, within 16 trials (8 on 16,384 tets or more); then, for each
 *    round's worst tet (from the second round on) on a mesh under 16,384 tets, the constraint pieces at its
 *    vertices on constraints, within 16 more (a corner whose input edges fix the angle:
 *    part.off). A piece refinement refused is not tried again.
 *
 * Angles are measured in doubles (src/refine/quality.h, on m->xyz): they only rank
 * choices; every topological decision is exact. Both steps run in fixed passes in slot /
 * vertex index order with ties broken by order, so the result is deterministic. Since
 * every flip, move and interior point strictly raises the minimum over the tets it
 * touches and leaves the others alone, they never lower the mesh's smallest dihedral
 * angle; the pinned tets' points on constraints may (joint.off: 0.23 -> 0.0003 degrees,
 * while its share of tets under 10 degrees went from 30% to 14%; with the last round and
 * the off-plane points, 0.97 degrees and 11%). */
#ifndef TR_SLIVER_H
#define TR_SLIVER_H

#include <stdint.h>

#include "core/vtmap.h"
#include "mesh/mesh.h"
#include "recover_facets/recover_facets.h"

/* Levels of tr_options.optimize. */
enum { TR_SLIVER_OFF = 0, TR_SLIVER_FLIPS = 1, TR_SLIVER_SMOOTH = 2, TR_SLIVER_INSERT = 3 };

/* The pipeline's choice: tets under 20 degrees are worked on (the bench's figures are the
 * share under 10 and the minimum), in up to 3 rounds of (flips, smoothing, insertion), and
 * a last flip and smoothing pass when the last round added points. */
#define TR_SLIVER_BOUND 20.0
#define TR_SLIVER_ROUNDS 3

/* Insertion works on the worse tets only (each point costs), within a budget of points per
 * stage that grows with the mesh. */
#define TR_SLIVER_INSERT_BOUND 15.0
#define TR_SLIVER_POINTS(nv) ((uint64_t)(nv) / 4 + 100)

/* Rounds of points on the constraints under pinned tets, each followed by a round of flips,
 * moves and interior points (sliver.c). */
#define SL_PINNED_ROUNDS 2
#define SL_PINNED_BOUND 10.0 /* degrees: the pinned tets that get points on constraints */

#define SL_MAX_RING 7 /* largest edge shell the flips remove (7 tets -> 10) */
#define SL_FACET_FAN 2 /* most tets on one side of a facet flip's edge (facetflip.c) */
/* ... and when a tet has no flip with SL_FACET_FAN, on a triangle without a corner under
 * SL_FACET_THIN_CORNER degrees (facetflip.c) */
#define SL_FACET_FAN_LONG 3
#define SL_FACET_THIN_CORNER 10.0

/* The refinement's bounds hold after the stage: a new tet's volume is at most its region's
 * bound (exactly, as refinement decides it), and its radius-edge ratio at most the ratio
 * bound or, where a tet it replaces was already over it, the largest ratio of those. */
typedef struct tr_sliver_bounds {
  double ratio;                /* radius-edge bound (0: none) */
  double max_volume;           /* volume bound for every tet (0: none) */
  const struct tr_plc *plc;    /* NULL, or its region points' maximum volumes by attribute */
  int keep_edges;              /* refinement's tr_refine_params.keep_edges */
  int flat_splits;             /* refinement's tr_refine_params.flat_splits */
  int keep_surface;            /* --keep-surface: no point on a constraint, so no pinned
                                  tets' points (sliver.c) and no cap trials (caps.c) */
  int wedge_grading;           /* refinement's tr_refine_params.wedge_grading */
  /* plc's region bounds as tr_refine_region_bounds makes them (ids sorted): tr_sliver_remove
   * builds them once, for the per-tet bound checks and the refinement trials */
  const uint32_t *region_id;
  const double *region_max_volume;
  uint32_t nregion_bounds;
} tr_sliver_bounds;

typedef struct tr_sliver_params {
  int level;     /* TR_SLIVER_FLIPS, TR_SLIVER_SMOOTH or TR_SLIVER_INSERT */
  double bound;  /* degrees: tets with a smaller dihedral angle are worked on */
  int rounds;    /* rounds of (flip pass, smoothing pass) */
  double insert_bound; /* degrees: tets under it get new points (level 3); 0: the default
                          TR_SLIVER_INSERT_BOUND */
  tr_sliver_bounds keep;
} tr_sliver_params;

typedef struct tr_sliver_stats {
  uint64_t flips23, flips32, flips44, flipsn; /* n: edge removal with a shell of 5+ */
  uint64_t facet_flips;                       /* edges inside facets (facetflip.c) */
  uint64_t smoothed;                          /* accepted vertex moves */
  uint64_t points;                            /* points added, all kinds */
  uint64_t on_constraints; /* of them on input edges and triangles (pinned tets) */
  uint64_t swallowed; /* interior vertices the last resort's cavities took out (in no tet) */
} tr_sliver_stats;

/* What the steps may not touch, built once from the sub-faces. */
struct tr_sliver_shapes; /* sliver.c: the cache of tr_sliver_tet_min */

typedef struct tr_sliver_ctx {
  struct tr_mesh *m;
  tr_vtmap faces;          /* the sub-faces (sorted vertices, tr_vtkey_face) */
  tr_vtmap edges;          /* their edges (tr_vtkey_edge) */
  struct tr_sliver_shapes *shapes; /* per tet slot: its smallest angle and ratio */
  uint8_t *movable;        /* nv: 1 for a vertex smoothing may move */
  double bound;
  double insert_bound;     /* insertion: tets with a smaller angle get a point */
  uint64_t point_budget;   /* insertion: points the stage may add */
  tr_vtmap failed;         /* insertion: tets (sorted vertices) no candidate point opened;
                              later passes skip them (most stay pinned) */
  /* The flip pass's memo (flips.c): `epoch` counts the changes; vstamp[v] (nv entries)
   * is the epoch of the last change of a tet at v (created, deleted, or a vertex of it
   * moved: tr_sliver_touch); flip_failed[t] the epoch at which slot t's tet found no
   * flip (0: never, or forgotten). */
  uint64_t epoch;
  uint64_t *vstamp;
  uint32_t nvstamp;
  uint64_t *flip_failed;
  uint32_t nflip_failed;
  tr_sliver_bounds keep;
  /* the refinement set-ups' memo (refine.h), tr_sliver_remove's, shared by the contexts
   * it rebuilds and by the trials' (not owned; NULL: none) */
  struct tr_refine_memo *memo;
  /* the sub-faces, which the facet flips rewrite (tr_sliver_remove's; NULL: no facet
     flips), and the input's facets: a flip stays within one, and a merged facet's
     sub-faces are labelled again with the triangle that holds their centroid, which a
     flip may move (NULL: every triangle is a facet of its own) */
  tr_subfaces *sub;
  const struct tr_facets *facets;
  /* per input triangle, 1 if a facet of its own with a corner under SL_FACET_THIN_CORNER
     (tr_facets_thin_triangles; NULL: none is) */
  const uint8_t *thin;
  /* the largest radius-edge ratio of the mesh the stage started from (tr_sliver_remove;
   * 0: none known): no allowance of tr_sliver_ratio_allowed goes above it (or the ratio
   * bound), whatever the replaced tets' ratios, which earlier steps may have raised */
  double ratio_start;
} tr_sliver_ctx;

/* The context of one mesh: c->m = m, the constraint sets of sub, the movable vertices
 * (vkind: see tr_sliver_remove), no bounds to keep (set c->keep after), insertion's
 * bound and budget TR_SLIVER_INSERT_BOUND and TR_SLIVER_POINTS(m->nv). Free with
 * tr_sliver_ctx_free. */
tr_status tr_sliver_ctx_init(tr_sliver_ctx *c, struct tr_mesh *m, const tr_subfaces *sub,
                             const uint8_t *vkind, uint32_t npoints, double bound);
void tr_sliver_ctx_free(tr_sliver_ctx *c);

/* The smallest dihedral angle of tet (a,b,c,d) on m->xyz, degrees; 0 for a tet flat in
 * doubles. */
double tr_sliver_min_dihedral(const struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t c,
                              uint32_t d);
/* The same with vertex v's coordinates replaced by x (v may be none of them); *ratio (may
 * be NULL) = its radius-edge ratio. */
double tr_sliver_min_dihedral_at(const struct tr_mesh *m, const uint32_t t[4], uint32_t v,
                                 const double x[3], double *ratio);
/* tr_sliver_min_dihedral_at without a ratio, in two steps: the smallest of the six
 * cosines (*flat = 1 for a tet flat in doubles), then its angle, the same double. A
 * caller that only asks whether the angle beats a bound screens the cosine against
 * tr_dihedral_cos_below first: most candidates lose there, without an arccosine. */
double tr_sliver_min_cos_at(const struct tr_mesh *m, const uint32_t t[4], uint32_t v,
                            const double x[3], int *flat);
double tr_sliver_angle_of_cos(double lo, int flat);
/* The screen itself: 1 when the angle of (lo, flat) is surely at most `bound`, whose
 * tr_dihedral_cos_below is `below` (a flat tet's angle is 0). */
static inline int tr_sliver_cos_loses(double lo, int flat, double below, double bound)
{
  return flat ? !(0 > bound) : lo < below;
}
/* The radius-edge ratio tr_sliver_min_dihedral_at gives in *ratio, alone (the same
 * double, without the angles it would also measure). */
double tr_sliver_ratio_at(const struct tr_mesh *m, const uint32_t t[4], uint32_t v,
                          const double x[3]);
/* tr_sliver_min_dihedral_at(m, m->tv + 4 * t, TR_NONE, NULL, ratio) (the same doubles),
 * remembered per slot: every pass measures every tet, and most did not change since the
 * last. A slot's entry holds its vertex ids, so a tet a flip or a point replaced is
 * measured again; a vertex move must call tr_sliver_forget on the tets of its star, and
 * any other change of coordinates tr_sliver_forget_all. */
double tr_sliver_tet_min(const tr_sliver_ctx *c, uint32_t t, double *ratio);
/* Fetches the cache entries of tr_sliver_tet_min for tets t[0..n) ahead of their use: a
 * cavity's tets are asked for one after the other, each a miss in a big mesh. */
void tr_sliver_tet_min_prefetch(const tr_sliver_ctx *c, const uint32_t *t, uint32_t n);
void tr_sliver_forget(const tr_sliver_ctx *c, uint32_t t);
void tr_sliver_forget_all(const tr_sliver_ctx *c);
/* Forgets the entries that name a vertex id from nv on: ids given back (a trial undone)
 * go to other points. */
void tr_sliver_forget_from(const tr_sliver_ctx *c, uint32_t nv);
/* The cache's vertex ids as a copy of the tet store: afterwards slot t's entry holds
 * m->tv[4t..4t+4) at key + stride * t, for every t < m->nt (stale entries are measured
 * again, free slots' entries set to their ids), until the next call that measures on c.
 * NULL when c has no cache (or no memory to extend it to every slot), or the mesh has
 * ghost tets. caps.c's trials use it as their snapshot of the slots. */
const uint32_t *tr_sliver_shape_keys(const tr_sliver_ctx *c, size_t *stride);

/* The largest ratio a new tet with an angle under c->bound may have where the tets it
 * replaces had ratios up to ratio_was: max(c->keep.ratio, ratio_was), but never above
 * max(c->keep.ratio, c->ratio_start). The replaced tets' ratio alone is a moving
 * reference: a tet with no angle under the bound may have any ratio (below), so a step
 * that replaces one made by an earlier step could pass that ratio on to a sliver
 * (star_rounding_budget.off: 52.98 at the start, 97.25 at the end). */
double tr_sliver_ratio_allowed(const tr_sliver_ctx *c, double ratio_was);

/* 1 iff tet p (positive, exact points; vertex v at the double x when v is one of them) of
 * region `region` keeps c->keep: its exact volume at most the region's bound, and its ratio
 * (given) at most tr_sliver_ratio_allowed(c, ratio_was) unless its smallest dihedral angle
 * `dih` (given) is at least c->bound: a tet with no angle under the bound is well shaped
 * whatever its ratio (small dihedral angles are what the ratio misses, not the reverse). */
int tr_sliver_keeps_bounds(const tr_sliver_ctx *c, const uint32_t p[4], uint32_t v,
                           const double x[3], uint32_t region, double ratio, double dih,
                           double ratio_was);

/* A change of the mesh for the flip pass's memo (sliver.h): the n vertex ids v[0..n)
 * (the new tets' vertices of a flip or an insertion: every vertex of the tets it deleted
 * is one of them) get a new epoch; tr_sliver_touch_tets the vertices of the n tets
 * `tets` (a moved vertex's star). tr_sliver_forget_flips: every slot's failure
 * forgotten (a change made without these, e.g. refinement). */
tr_status tr_sliver_touch(tr_sliver_ctx *c, const uint32_t *v, size_t n);
tr_status tr_sliver_touch_tets(tr_sliver_ctx *c, const uint32_t *tets, size_t n);
void tr_sliver_forget_flips(tr_sliver_ctx *c);

/* 1 iff the face / edge (any vertex order) is a constraint the flips must keep. */
int tr_sliver_protected(const tr_sliver_ctx *c, const uint32_t *v, int nv);

/* 1 when no cavity of the point x that keeps t can pass the insertion's tests (reach.c):
 * the segment from inside t to x leaves the mesh or crosses a protected face. 0 says
 * nothing. On the doubles of m->xyz, for the screened candidates. */
int tr_sliver_segment_blocked(const tr_sliver_ctx *c, uint32_t t, const double x[3]);

/* One flip pass over the tets in slot order (flips.c). */
tr_status tr_sliver_flip_pass(tr_sliver_ctx *c, tr_sliver_stats *st);
/* The best flip of tet t (a face or an edge of it) whose new tets' smallest angle beats the
 * tets it deletes, done (*done = 1) if there is one; sh: scratch for the edge shells. */
tr_status tr_sliver_flip_tet(tr_sliver_ctx *c, uint32_t t, tr_u32buf *sh, tr_sliver_stats *st,
                             int *done);
/* The best flip of an edge inside a facet at a sub-face of t (facetflip.c):
 * done (*done = 1) when its new tets' smallest angle beats the old ones' and they keep
 * the bounds; c->sub and the constraint sets follow. */
tr_status tr_sliver_facet_flip_tet(tr_sliver_ctx *c, uint32_t t, tr_sliver_stats *st, int *done);
/* One smoothing pass over the movable vertices in index order (smooth.c). */
tr_status tr_sliver_smooth_pass(tr_sliver_ctx *c, tr_sliver_stats *st);
/* For moves of vertex v whose star is `ball` (smooth.c; the ratio pass uses them too):
 * tr_sliver_star_closed: every face of the star through v has a real tet behind it (v is
 * inside the mesh). tr_sliver_star_valid: every tet of the star is exactly positive with v
 * at the double x (so x lies strictly inside the star's link) and keeps the bounds (its
 * ratio over the bound only up to `was`, the star's largest as it is); cs (may be NULL):
 * each tet's smallest cosine with v at x, none flat. */
int tr_sliver_star_closed(const struct tr_mesh *m, const tr_u32buf *ball, uint32_t v);
int tr_sliver_star_valid(const tr_sliver_ctx *c, const tr_u32buf *ball, uint32_t v,
                         const double x[3], double was, const double *cs);
/* Moves of interior vertices whose star holds a tet over the ratio bound (ratio.c), last:
 * the rounds may leave such tets where they have no angle under the bound. */
tr_status tr_sliver_ratio_pass(tr_sliver_ctx *c, tr_sliver_stats *st);
/* Up to SL_MOVES moves of vertex v (if movable) while its star's smallest angle is under
 * `bound`, each raising it; *moved = 1 if one was made. ball: scratch. */
tr_status tr_sliver_smooth_vertex(tr_sliver_ctx *c, uint32_t v, double bound, tr_u32buf *ball,
                                  tr_sliver_stats *st, int *moved);
/* One insertion pass over the tets in slot order, while st->points < c->point_budget
 * (insert.c); a new vertex is movable. */
tr_status tr_sliver_insert_pass(tr_sliver_ctx *c, tr_sliver_stats *st);
/* A new interior point for tet t as the pass does it (*done = 1; not counted in st), unless
 * t failed before (c->failed; a failure is remembered). scratch: tr_sliver_insert_scratch()
 * (free() it; NULL: out of memory). */
tr_status tr_sliver_insert_tet(tr_sliver_ctx *c, uint32_t t, void *scratch, int *done);
/* Points on the constraints under the pinned tets (pinned.c, after the rounds): the tets
 * under SL_PINNED_BOUND with three or four fixed vertices and a face on a sub-face get
 * refinement's points there (tr_refine_open_pinned, within its own TR_SLIVER_POINTS),
 * kept only when no tet it leaves under the bound has a ratio over
 * tr_sliver_ratio_allowed(c, INFINITY) after a repair of those, else undone and tried
 * again without the pinned tets near them; then c again on the new sub-faces (their
 * vertices fixed, refinement's interior points movable). *added = points on the
 * constraints (0: none kept). */
tr_status tr_sliver_open_pinned(tr_sliver_ctx *c, tr_subfaces *sub, uint32_t npoints,
                                tr_sliver_stats *st, uint64_t *added);
/* The polish's last resort for a pinned tet (three or four vertices on constraints) that
 * nothing else opened: the same candidates, with cavities carved off the vertices they
 * swallow, else with cavities that may swallow interior points on no constraint (they
 * leave the mesh). Not remembered in c->failed. */
tr_status tr_sliver_insert_last(tr_sliver_ctx *c, uint32_t t, void *scratch, int *done,
                                 uint32_t *gone);
void *tr_sliver_insert_scratch(void);
/* The final polish (polish.c): the globally worst tets, whatever their angle, get flips,
 * moves and points (as par->level allows) that raise their local minimum; at level 3 with
 * c->keep.plc and sub, also points on their constraint pieces (caps.c). */
tr_status tr_sliver_polish(tr_sliver_ctx *c, tr_subfaces *sub, int level, tr_sliver_stats *st);

/* Constraint pieces tried per tet, points per trial (the piece's split and the cascade of
 * encroached pieces it starts). */
#define SL_CAP_PIECES 4
#define SL_CAP_POINTS 8
#define SL_CAP_FAN 8 /* pieces of a wide trial */
#define SL_CAP_PASSES 2 /* of flips, moves and interior points over a trial's new tets */
/* The rounds' steps on tet u, cheapest first: a flip, a move of one of its vertices, an
 * interior point while *points < SL_CAP_POINTS (counted there and in st->points);
 * *done = 1 when one was made. sh, ball: scratch (caps.c; the cap trials and the pinned
 * tets' repair). */
tr_status tr_sliver_step_tet(tr_sliver_ctx *tc, uint32_t u, tr_u32buf *sh, tr_u32buf *ball,
                             void *scratch, tr_sliver_stats *st, uint32_t *points, int *done);
/* caps.c: the constraint pieces of tet t (its worst edge's sub-segment, its sub-faces
 * there, its other sub-segments; wide: instead the other sub-face edges at its vertices
 * on constraints, up to SL_CAP_FAN) split by refinement, one per trial, the first whose new
 * tets' smallest angle beats the deleted tets' (t among them) kept (*done = 1, c rebuilt
 * on the new sub-faces), every other trial undone exactly; *tried = trials made.
 * refused (or NULL): the pieces (sorted vertex ids, TR_NONE third for a sub-segment)
 * refinement did not split (a sub-segment protected at a small input angle, a cavity it
 * could not make); they are not tried again, and a piece that adds no point goes in.
 * scratch: tr_sliver_insert_scratch(). */
tr_status tr_sliver_cap_tet(tr_sliver_ctx *c, tr_subfaces *sub, uint32_t t, int wide,
                            void *scratch, tr_vtmap *refused, tr_sliver_stats *st, int *done,
                            int *tried);

/* The stage: m holds only inner tets (tr_refine's output), sub their sub-faces as
 * tr_refine exported them (their triangles are taken as they are: tr_refine_params'
 * sub_exported), vkind the vertex origins (tetrec.h's enum tr_vertex_origin; NULL: none
 * known, so only vertices above npoints on no sub-face move). */
tr_status tr_sliver_remove(struct tr_mesh *m, tr_subfaces *sub, const uint8_t *vkind,
                           uint32_t npoints, const tr_sliver_params *par, tr_sliver_stats *st);

/* The live tets renumbered along a Hilbert curve of their centroids, free slots dropped
 * (order.c): tr_sliver_remove's first step. */
tr_status tr_sliver_sort_tets(struct tr_mesh *m);

/* A tet's vertex ids sorted: its key whatever its rotation (the polish and its cap
 * trials match tets across a rebuild by it). */
static inline void tr_sliver_tet_key(const uint32_t *v, uint32_t key[4])
{
  for (int i = 0; i < 4; i++)
    key[i] = v[i];
  for (int i = 1; i < 4; i++)
    for (int j = i; j > 0 && key[j - 1] > key[j]; j--) {
      uint32_t x = key[j];
      key[j] = key[j - 1];
      key[j - 1] = x;
    }
}

#endif
