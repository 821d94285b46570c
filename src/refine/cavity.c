/* Constrained Bowyer-Watson insertion for the refinement stage (refine.h).
 *
 * The recovered mesh is constrained, not Delaunay, so the usual cavity (every tet whose
 * circumsphere holds the point, connected) need not be star-shaped. The cavity is grown
 * by the exact insphere test through non-constraint faces, then shrunk: a tet leaves it
 * while one of its faces on the cavity's boundary is not strictly visible from the
 * point (TetGen's "cavity expansion then reduction" idea, Si 2015), while the cavity
 * would swallow a vertex or a sub-segment, or would hold a sub-face on both sides that
 * the point may not split. The tets that hold the point itself are never taken out: if
 * one has to be, the insertion is refused. What remains is star-shaped from the point,
 * so coning its boundary gives positive tets, exactly. */
#include <stdlib.h>
#include <string.h>

#include "predicates/predicates.h"
#include "mesh/walk.h"
#include "refine/refine_impl.h"

static tr_point face_pt(const rf_ctx *c, uint32_t t, int k, int i)
{
  return tr_mesh_point(c->m, c->m->tv[4 * (size_t)t + tr_face_vtx[k][i]]);
}

/* Sign of orient3d(face k of t, p): > 0 on t's side. */
static int face_side(const rf_ctx *c, uint32_t t, int k, const tr_point *p)
{
  tr_point a = face_pt(c, t, k, 0), b = face_pt(c, t, k, 1), d = face_pt(c, t, k, 2);
  return tr_orient3d_p(&a, &b, &d, p);
}

static uint32_t face_subface(const rf_ctx *c, uint32_t t, int k)
{
  const uint32_t *v = c->m->tv + 4 * (size_t)t;
  return rf_subface_of(c, v[tr_face_vtx[k][0]], v[tr_face_vtx[k][1]], v[tr_face_vtx[k][2]]);
}

tr_status rf_locate(rf_ctx *c, uint32_t t, const tr_point *p, uint32_t *found,
                    uint32_t *blocker)
{
  struct tr_mesh *m = c->m;
  *found = TR_NONE;
  *blocker = TR_NONE;
  uint64_t max = 4 * (uint64_t)m->nt + 64;
  tr_walk_cycle cyc; /* the start rotates with the step: its period is 4 */
  tr_walk_cycle_init(&cyc, t);
  for (uint64_t step = 0; step < max; step++) {
    /* the first face to try rotates with the step: a fixed order cycles more often in a
     * mesh that is not Delaunay (this one can too: cyc stops it); deterministic all the
     * same */
    int start = (int)(step % 4), next = -1;
    uint32_t wall = TR_NONE;
    int walled = 0;
    for (int j = 0; j < 4; j++) {
      int k = (start + j) % 4;
      if (face_side(c, t, k, p) >= 0)
        continue;
      uint32_t sf = face_subface(c, t, k);
      if (sf != TR_NONE || m->tn[4 * (size_t)t + k] == TR_NONE) {
        if (!walled) {
          wall = sf;
          walled = 1;
        }
        continue;
      }
      next = k;
      break;
    }
    if (next < 0) {
      if (!walled)
        *found = t;
      else
        *blocker = wall;
      return TR_OK;
    }
    t = TR_NEIG(m, t, next);
    if (tr_walk_cycle_seen(&cyc, t, step + 1, 4))
      break;
  }
  return TR_OK; /* a walk that does not end: the caller skips the point */
}

/* 1 iff p is strictly inside the circumsphere of tet t (exact; perturbed when every
 * point is a double). */
static int conflicts(const rf_ctx *c, uint32_t t, const tr_point *p, uint32_t pid)
{
  const uint32_t *v = c->m->tv + 4 * (size_t)t;
  tr_point q[4];
  int dbl = !p->q;
  for (int i = 0; i < 4; i++) {
    q[i] = tr_mesh_point(c->m, v[i]);
    dbl &= !q[i].q;
  }
  if (dbl)
    return tr_insphere_sos(q[0].d, q[1].d, q[2].d, q[3].d, p->d, v[0], v[1], v[2], v[3], pid) > 0;
  return tr_insphere_p(&q[0], &q[1], &q[2], &q[3], p) > 0;
}

enum { ST_IN = 1, ST_INIT = 2, ST_KEEP = 4 };

static int in_cav(const rf_ctx *c, uint32_t t)
{
  return t != TR_NONE && (c->tstate[t] & ST_IN);
}

static void clear_state(rf_ctx *c)
{
  for (size_t i = 0; i < c->cav.n; i++)
    c->tstate[c->cav.a[i]] = 0;
}

static tr_status add_tet(rf_ctx *c, uint32_t t)
{
  c->tstate[t] |= ST_IN;
  TR_CHECK(tr_u32buf_push(&c->cav, t));
  return tr_u32buf_push(&c->stack, t);
}

/* May p split sub-face sf? p must lie in its closed facet (its input triangle, or the
 * union of the triangles of its merged planar facet: the cavity crosses inner edges)
 * and strictly inside
 * its circumcircle (for p in the plane, its equatorial sphere): the sub-faces of a facet
 * that p removes are then those of a 2D Bowyer-Watson cavity in the facet, which keeps
 * the facet's triangulation free of the needle-like sub-faces that a cavity taken from
 * the 3D tets alone leaves there (their huge circumcircles are encroached from afar, and
 * their splits pile up). */
#define RF_GMEMO 4
typedef struct {
  uint32_t g[RF_GMEMO];
  uint8_t in[RF_GMEMO];
  unsigned next;
} gmemo;

/* Is p in the closed facet g? Asked for many sub-faces of one facet within a cavity. */
static int in_facet(const rf_ctx *c, gmemo *x, uint32_t g, const tr_point *p)
{
  for (int i = 0; i < RF_GMEMO; i++)
    if (x->g[i] == g)
      return x->in[i];
  unsigned i = x->next++ % RF_GMEMO;
  x->g[i] = g;
  x->in[i] = rf_facet_triangle_of(c, g, p, TR_NONE) != TR_NONE;
  return x->in[i];
}

static int crossable_of(const rf_ctx *c, gmemo *gm, uint32_t sf, const tr_point *p,
                        int allow_split)
{
  if (!allow_split || !in_facet(c, gm, c->sftri[sf], p))
    return 0;
  const uint32_t *v = c->sfv + 3 * (size_t)sf;
  tr_point a = tr_mesh_point(c->m, v[0]), b = tr_mesh_point(c->m, v[1]),
           d = tr_mesh_point(c->m, v[2]);
  return rf_in_equatorial(&a, &b, &d, p);
}

/* crossable's answers within one cavity (one p): the reduction asks again for every
 * sub-face inside the cavity, from both sides, at every pass, and a Steiner point's
 * exact tests run in rationals (the profile of rotor_small: 7% of the run in them).
 * Direct-mapped by sub-face id; a collision only evicts. */
#define RF_XMEMO 64
typedef struct {
  uint32_t sf[RF_XMEMO];
  uint8_t ans[RF_XMEMO];
  gmemo gm;
} xmemo;

static int crossable(const rf_ctx *c, xmemo *x, uint32_t sf, const tr_point *p,
                     int allow_split)
{
  if (!allow_split)
    return 0;
  uint32_t i = sf & (RF_XMEMO - 1);
  if (x->sf[i] != sf) {
    x->ans[i] = (uint8_t)crossable_of(c, &x->gm, sf, p, allow_split);
    x->sf[i] = sf;
  }
  return x->ans[i];
}

/* The cavity becomes the tets flagged KEEP that are reachable from the initial ones. */
static tr_status reconnect(rf_ctx *c)
{
  struct tr_mesh *m = c->m;
  c->tmp.n = 0;
  for (size_t i = 0; i < c->cav.n; i++)
    TR_CHECK(tr_u32buf_push(&c->tmp, c->cav.a[i]));
  for (size_t i = 0; i < c->tmp.n; i++)
    c->tstate[c->tmp.a[i]] &= (uint8_t)~ST_IN;
  c->cav.n = c->stack.n = 0;
  for (size_t i = 0; i < c->init.n; i++)
    TR_CHECK(add_tet(c, c->init.a[i]));
  while (c->stack.n) {
    uint32_t t = c->stack.a[--c->stack.n];
    for (int k = 0; k < 4; k++) {
      uint32_t n = TR_NEIG(m, t, k);
      if (n != TR_NONE && !(c->tstate[n] & ST_IN) && (c->tstate[n] & ST_KEEP))
        TR_CHECK(add_tet(c, n));
    }
  }
  for (size_t i = 0; i < c->tmp.n; i++)
    if (!(c->tstate[c->tmp.a[i]] & ST_IN))
      c->tstate[c->tmp.a[i]] = 0;
  return TR_OK;
}

/* The vertices of the coned faces, for the lose check below: stamped in c->vcone, each
 * with the list of its coned faces (c->vhead, c->cnext), which answers "is this edge on a
 * coned face?" in the degree of one end. A linear scan of the coned faces per vertex and
 * sub-segment was quadratic (mpi.off: cavities of thousands of tets behind nearly flat
 * input polygons); sorting them instead took 9% of cheese.off's CPU. */
static tr_status coned_build(rf_ctx *c)
{
  const struct tr_mesh *m = c->m;
  if (c->capvcone < m->nv) {
    uint32_t cap = m->cap_v > m->nv ? m->cap_v : m->nv;
    uint32_t *v = realloc(c->vcone, sizeof *v * (size_t)cap);
    if (v)
      c->vcone = v;
    uint32_t *h = realloc(c->vhead, sizeof *h * (size_t)cap);
    if (h)
      c->vhead = h;
    if (!v || !h)
      return tr_error(TR_ERR_NOMEM, "out of memory for %u vertex stamps", cap);
    memset(v + c->capvcone, 0, sizeof *v * (size_t)(cap - c->capvcone));
    c->capvcone = cap;
  }
  if (++c->cone_stamp == 0) { /* wrapped: no stale stamp may match */
    memset(c->vcone, 0, sizeof *c->vcone * (size_t)c->capvcone);
    c->cone_stamp = 1;
  }
  c->cnext.n = 0;
  for (size_t i = 0; i < c->bfaces.n; i++) {
    const uint32_t *v = m->tv + 4 * (size_t)(c->bfaces.a[i] >> 2);
    int k = (int)(c->bfaces.a[i] & 3);
    for (int j = 0; j < 3; j++) {
      uint32_t w = v[tr_face_vtx[k][j]];
      int seen = c->vcone[w] == c->cone_stamp;
      c->vcone[w] = c->cone_stamp;
      TR_CHECK(tr_u32buf_push(&c->cnext, seen ? c->vhead[w] : TR_NONE));
      c->vhead[w] = (uint32_t)(3 * i + (size_t)j);
    }
  }
  return TR_OK;
}

/* Is edge {a,b} on a coned face? */
static int on_coned(const rf_ctx *c, uint32_t a, uint32_t b)
{
  if (c->vcone[a] != c->cone_stamp || c->vcone[b] != c->cone_stamp)
    return 0;
  for (uint32_t x = c->vhead[a]; x != TR_NONE; x = c->cnext.a[x]) {
    uint32_t f = c->bfaces.a[x / 3];
    const uint32_t *v = c->m->tv + 4 * (size_t)(f >> 2);
    int k = (int)(f & 3);
    for (int j = 0; j < 3; j++)
      if (v[tr_face_vtx[k][j]] == b)
        return 1;
  }
  return 0;
}

/* Takes t out of the cavity (it stays flagged IN until reconnect); 0 if t holds p. */
static int drop_tet(rf_ctx *c, uint32_t t)
{
  if (c->tstate[t] & ST_INIT)
    return 0;
  c->tstate[t] &= (uint8_t)~ST_KEEP;
  return 1;
}

static tr_status tstate_room(rf_ctx *c)
{
  if (c->m->cap_t <= c->captstate)
    return TR_OK;
  uint8_t *s = realloc(c->tstate, c->m->cap_t);
  if (!s)
    return tr_error(TR_ERR_NOMEM, "out of memory for %u tet states", c->m->cap_t);
  memset(s + c->captstate, 0, c->m->cap_t - c->captstate);
  c->tstate = s;
  c->captstate = c->m->cap_t;
  return TR_OK;
}

/* One pass of the reduction: 1 if some tet was taken out, -1 if a tet holding p would
 * have to be; fills c->bfaces. */
static tr_status reduce_once(rf_ctx *c, xmemo *x, const tr_point *p, int allow_split,
                             int *res)
{
  struct tr_mesh *m = c->m;
  int drop = 0;
  c->bfaces.n = 0;
  for (size_t i = 0; i < c->cav.n; i++)
    c->tstate[c->cav.a[i]] |= ST_KEEP;
  for (size_t i = 0; i < c->cav.n; i++) {
    uint32_t t = c->cav.a[i];
    for (int k = 0; k < 4; k++) {
      uint32_t n = TR_NEIG(m, t, k);
      uint32_t sf = face_subface(c, t, k);
      if (in_cav(c, n)) {
        /* a sub-face inside the cavity that p may not split */
        if (sf != TR_NONE && !crossable(c, x, sf, p, allow_split)) {
          if (!drop_tet(c, n) && !drop_tet(c, t)) {
            *res = -1;
            return TR_OK;
          }
          drop = 1;
        }
        continue;
      }
      int s = face_side(c, t, k, p);
      if (s > 0) {
        TR_CHECK(tr_u32buf_push(&c->bfaces, 4 * t + (uint32_t)k));
        continue;
      }
      if (s == 0 && n == TR_NONE && sf != TR_NONE && crossable(c, x, sf, p, allow_split))
        continue; /* a domain-boundary sub-face that p splits: nothing beyond it */
      if (!drop_tet(c, t)) {
        *res = -1;
        return TR_OK;
      }
      drop = 1;
    }
  }
  if (!drop) {
    /* a vertex or a sub-segment (other than the one p splits) the cone would lose */
    TR_CHECK(coned_build(c));
    for (size_t i = 0; i < c->cav.n; i++) {
      uint32_t t = c->cav.a[i];
      const uint32_t *v = m->tv + 4 * (size_t)t;
      int lose = 0;
      for (int j = 0; j < 4 && !lose; j++)
        lose = c->vcone[v[j]] != c->cone_stamp;
      for (int e = 0; e < 6 && !lose; e++) {
        uint32_t a = v[tr_edge_vtx[e][0]], b = v[tr_edge_vtx[e][1]];
        uint32_t g = rf_subseg_of(c, a, b);
        lose = g != TR_NONE && g != c->split_seg && !on_coned(c, a, b);
      }
      if (lose) {
        if (!drop_tet(c, t)) {
          *res = -1;
          return TR_OK;
        }
        drop = 1;
      }
    }
  }
  *res = drop;
  return TR_OK;
}

/* The tets that pass after pass of reduce_once would take out for a coned face that p
 * does not see, and those that are then cut off from the tets holding p, taken out by a
 * worklist of faces: only a face that has just come onto the cavity's boundary needs a
 * test. After reduce_once's first pass no sub-face lies inside the cavity with the
 * cavity on both sides, so that rule is spent; the visibility rule and the reachability
 * only take out more as the cavity shrinks, so every order of taking tets out ends at
 * the same cavity, the largest one on which they take out nothing: the one that
 * reduce_once's passes reach (each a full sweep, hundreds of them on mpi.off's cavities
 * of thousands of tets, where they took two thirds of the run; a small cavity keeps
 * the passes, which cost less there than this sweep and its reconnect). *fail = 1 when a tet
 * holding p would have to go. The cavity is rebuilt by reconnect, in its order. */
#define RF_SETTLE_ABOVE 64 /* tets: a smaller cavity settles in a pass or two */
static tr_status settle(rf_ctx *c, xmemo *x, const tr_point *p, int allow_split, int *fail)
{
  struct tr_mesh *m = c->m;
  int dropped = 0;
  c->stack.n = 0;
  for (size_t i = 0; i < c->cav.n; i++) {
    uint32_t t = c->cav.a[i];
    c->tstate[t] |= ST_KEEP;
    for (int k = 0; k < 4; k++)
      if (!in_cav(c, TR_NEIG(m, t, k)))
        TR_CHECK(tr_u32buf_push(&c->stack, 4 * t + (uint32_t)k));
  }
  /* the cavity here: the tets flagged both IN and KEEP */
  while (c->stack.n) {
    uint32_t f = c->stack.a[--c->stack.n], t = f >> 2;
    int k = (int)(f & 3);
    if (!(c->tstate[t] & ST_KEEP))
      continue;
    uint32_t n = TR_NEIG(m, t, k);
    if (n != TR_NONE && (c->tstate[n] & ST_IN) && (c->tstate[n] & ST_KEEP))
      continue;
    int s = face_side(c, t, k, p);
    if (s > 0)
      continue;
    if (s == 0 && n == TR_NONE) {
      uint32_t sf = face_subface(c, t, k);
      if (sf != TR_NONE && crossable(c, x, sf, p, allow_split))
        continue;
    }
    if (!drop_tet(c, t)) {
      *fail = 1;
      return TR_OK;
    }
    dropped = 1;
    for (int j = 0; j < 4; j++) {
      uint32_t a = m->tn[4 * (size_t)t + (size_t)j];
      if (a != TR_NONE && (c->tstate[a >> 2] & ST_IN) && (c->tstate[a >> 2] & ST_KEEP))
        TR_CHECK(tr_u32buf_push(&c->stack, a));
    }
  }
  /* a tet cut off from the ones holding p borders only tets cut off with it or tets
   * outside: taking it out leaves no new coned face on the rest */
  return dropped ? reconnect(c) : TR_OK;
}

tr_status rf_cavity(rf_ctx *c, uint32_t t0, const tr_point *p, uint32_t pid, int allow_split,
                    int *ok)
{
  struct tr_mesh *m = c->m;
  *ok = 0;
  c->cav.n = c->init.n = c->stack.n = c->bfaces.n = 0;
  TR_CHECK(tstate_room(c));
  xmemo xm, *x = &xm;
  memset(&xm, 0, sizeof xm);
  memset(xm.sf, 0xff, sizeof xm.sf);
  memset(xm.gm.g, 0xff, sizeof xm.gm.g);
  /* 1. the tets whose closure holds p: across the faces whose plane holds p */
  TR_CHECK(add_tet(c, t0));
  tr_status st = TR_OK;
  int fail = 0;
  while (c->stack.n && !fail && st == TR_OK) {
    uint32_t t = c->stack.a[--c->stack.n];
    int zeros = 0;
    for (int k = 0; k < 4 && !fail && st == TR_OK; k++) {
      if (face_side(c, t, k, p) != 0)
        continue;
      zeros++;
      uint32_t n = TR_NEIG(m, t, k);
      uint32_t sf = face_subface(c, t, k);
      if (sf != TR_NONE && !crossable(c, x, sf, p, allow_split))
        fail = 1; /* p lies on a constraint it may not split */
      else if (n != TR_NONE && !in_cav(c, n))
        st = add_tet(c, n);
    }
    if (zeros >= 3)
      fail = 1; /* p is a vertex of t */
  }
  for (size_t i = 0; st == TR_OK && !fail && i < c->cav.n; i++) {
    st = tr_u32buf_push(&c->init, c->cav.a[i]);
    c->tstate[c->cav.a[i]] |= ST_INIT;
  }
  /* 2. growth through non-constraint faces by the insphere test, and across sub-faces
   * that p splits */
  c->stack.n = 0;
  for (size_t i = 0; st == TR_OK && !fail && i < c->cav.n; i++)
    st = tr_u32buf_push(&c->stack, c->cav.a[i]);
  while (st == TR_OK && !fail && c->stack.n) {
    uint32_t t = c->stack.a[--c->stack.n];
    for (int k = 0; k < 4 && st == TR_OK; k++) {
      uint32_t n = TR_NEIG(m, t, k);
      if (n == TR_NONE || in_cav(c, n))
        continue;
      uint32_t sf = face_subface(c, t, k);
      if (sf != TR_NONE ? crossable(c, x, sf, p, allow_split) : conflicts(c, n, p, pid))
        st = add_tet(c, n);
    }
  }
  /* 3. reduction: a full pass, then the rest of the visibility rule by settle, then a
   * full pass again, which finds nothing more to drop for that rule and checks for lost
   * vertices and sub-segments */
  while (st == TR_OK && !fail) {
    int res = 0;
    st = reduce_once(c, x, p, allow_split, &res);
    if (st != TR_OK || res == 0)
      break;
    if (res < 0)
      fail = 1;
    else
      st = reconnect(c);
    if (st == TR_OK && !fail && c->cav.n > RF_SETTLE_ABOVE)
      st = settle(c, x, p, allow_split, &fail);
  }
  if (st != TR_OK || fail) {
    clear_state(c);
    return st;
  }
  *ok = 1;
  return TR_OK;
}

void rf_cavity_release(rf_ctx *c)
{
  clear_state(c);
}
