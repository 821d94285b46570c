/* The surface under edit (edit.c) and the operations on it: edge collapses (collapse.c)
 * and flips (flip.c), chosen by improve.c. Triangles live in slots that are never
 * reused: an operation writes its
 * new triangles past the live ones, tests them, and either commits (the old ones die, the
 * new ones live) or drops them by resetting nt. Each vertex keeps the list of its live
 * triangles (its star) in a fixed order, and the triangles still worth working on sit in
 * a heap by smallest angle, worst first (ties by slot), so every run edits the same way. */
#ifndef TR_SIMPLIFY_EDIT_H
#define TR_SIMPLIFY_EDIT_H

#include <stdint.h>

#include "core/plc.h"
#include "core/vtmap.h"
#include "improve.h"
#include "simplify_impl.h"

/* vertex classes: what a vertex may do */
enum { TR_SIMP_FREE = 0, TR_SIMP_FROZEN = 1, TR_SIMP_CHAIN = 2, TR_SIMP_GONE = 3 };

/* pieces one cover test may cut a triangle into before it counts as a refusal */
#define TR_SIMP_COVER_BUDGET 4096

typedef struct tr_simp_hitem {
  double key;
  uint32_t t;
} tr_simp_hitem;

typedef struct tr_simp_edit {
  const struct tr_plc *plc; /* the input: the envelope is around its triangles */
  const double *x;          /* its points (none ever moves) */
  double d;
  uint32_t *tri, *orig, nt, cap; /* slots: 3 vertex ids, the input triangle it came from */
  uint8_t *dead;
  uint32_t *mark, tick; /* per triangle slot, for target lists */
  uint32_t **inc, *ninc, *cinc; /* stars */
  uint8_t *cls;          /* per point: TR_SIMP_FREE ... */
  const uint8_t *frozen; /* per point: frozen by the stage, no operation touches it */
  tr_vtmap feat;         /* feature edges of the current surface */
  tr_simp_grid g;        /* over the input triangles */
  uint32_t *cand, ncand, ccand;
  tr_simp_hitem *h;
  uint32_t nh, ch;
  uint32_t *buf, nbuf, cbuf; /* targets */
  uint32_t *into;            /* the vertex each removed one went to */
} tr_simp_edit;

static inline const double *tr_simp_at(const tr_simp_edit *c, uint32_t v)
{
  return c->x + 3 * (size_t)v;
}

static inline int tr_simp_has(const uint32_t *t, uint32_t v)
{
  return t[0] == v || t[1] == v || t[2] == v;
}

/* Sets up the surface of plc (its triangles in slots 0 .. ntris, their stars, the grid
 * of the input) with d and the stage's frozen points; into[v] = v. */
tr_status tr_simp_edit_init(tr_simp_edit *c, const struct tr_plc *plc, double d,
                            const uint8_t *frozen, uint32_t *into);
void tr_simp_edit_free(tr_simp_edit *c);
static inline int tr_simp_is_frozen(const tr_simp_edit *c, uint32_t v)
{
  return c->frozen && c->frozen[v];
}

/* The vertex v went to, following removals (path compression on the way). */
uint32_t tr_simp_root(tr_simp_edit *c, uint32_t v);
/* Smallest corner angle in degrees, in doubles (a choice of what to improve, never a
 * decision about the bound or validity). */
double tr_simp_min_angle(const double *a, const double *b, const double *c);
double tr_simp_tri_angle(const tr_simp_edit *c, uint32_t t);
/* The exact sign of ((b-a) x (c-a)) . ((e-d) x (f-d)). */
int tr_simp_normal_dot_sign(const double *a, const double *b, const double *c, const double *d,
                            const double *e, const double *f);
/* Queues t if its smallest angle is under TR_SIMP_TARGET_ANGLE; pops the worst. */
tr_status tr_simp_push(tr_simp_edit *c, uint32_t t);
tr_simp_hitem tr_simp_pop(tr_simp_edit *c);
tr_status tr_simp_star_add(tr_simp_edit *c, uint32_t v, uint32_t t);
void tr_simp_star_del(tr_simp_edit *c, uint32_t v, uint32_t t);
/* A new slot past the live ones holding v, dead until committed. */
tr_status tr_simp_new_slot(tr_simp_edit *c, const uint32_t v[3], uint32_t orig, uint32_t *id);
int tr_simp_is_feat(const tr_simp_edit *c, uint32_t a, uint32_t b);
/* The other vertices of v's triangles, each once, in star order (at most max). */
uint32_t tr_simp_link(const tr_simp_edit *c, uint32_t v, uint32_t *out, uint32_t max);
/* Whether replacing the live triangles going[0 .. ngoing) by the new slots nt0 .. nt
 * keeps the two-sided envelope, proven (*ok = 0 also when a cover test runs out of
 * pieces): every new triangle lies within d of the input, and every input triangle near
 * the old ones (its box meets [lo, hi], the old ones' box) that is no longer in the
 * surface as itself lies within d of the new triangles, the current triangles at the
 * vertices around[0 .. naround) (the region's boundary) and those at its own vertices'
 * roots. An input triangle still alive, and not going, covers itself. */
tr_status tr_simp_envelope(tr_simp_edit *c, const uint32_t *going, uint32_t ngoing,
                           uint32_t nt0, const uint32_t *around, uint32_t naround,
                           const double lo[3], const double hi[3], int *ok);
/* Makes the replacement: going[] (not c->inc's own memory) dies, slots nt0 .. nt live,
 * stars follow, the new triangles are queued. */
tr_status tr_simp_commit(tr_simp_edit *c, const uint32_t *going, uint32_t ngoing,
                         uint32_t nt0);

/* ---- the operations: each tests everything it needs and either makes its change
 * (*done = 1, committed) or leaves the surface as it was ---- */
/* Feature edges of the input and each input point's class (collapse.c). */
tr_status tr_simp_classify(tr_simp_edit *c);
/* Collapse u -> v (collapse.c); into[u] = v when made. */
tr_status tr_simp_try_collapse(tr_simp_edit *c, uint32_t u, uint32_t v, int *done);
/* Flip of edge ab (flip.c). */
tr_status tr_simp_try_flip(tr_simp_edit *c, uint32_t a, uint32_t b, int *done);

#endif
