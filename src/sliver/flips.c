/* Flips that raise the smallest dihedral angle (sliver.h): Swap23 on a face of a bad tet,
 * or removal of one of its edges (Swap32, Swap44, n -> 2n-4), whichever gives the tets it
 * creates the largest smallest angle, provided that beats the tets it deletes. */
#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/orient_memo.h"
#include "refine/quality.h"
#include "sliver/sliver.h"
#include "sliver/ring.h"

#define SL_MAX_NEW (2 * SL_MAX_RING - 4)

/* A flip under consideration: the tets it deletes and the ones it creates. */
typedef struct cand {
  uint32_t old[SL_MAX_RING], nold;
  uint32_t newv[4 * SL_MAX_NEW], nnew;
  double oldmin, newmin;
} cand;

static int positive(const struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t c, uint32_t d)
{
  return tr_mesh_orient(m, a, b, c, d) > 0;
}

/* Tet t's smallest dihedral angle; its ratio raises *ratio to at least it. */
static double tet_min(const tr_sliver_ctx *c, uint32_t t, double *ratio)
{
  double r;
  double q = tr_sliver_tet_min(c, t, &r);
  if (ratio && r > *ratio)
    *ratio = r;
  return q;
}

/* The ratio of new tet p (vertex order as created) where tr_sliver_keeps_bounds looks at
 * it, 0 where it does not (no ratio bound, or an angle at least the bound): most
 * candidates need no circumsphere. */
static double ratio_of(const tr_sliver_ctx *c, const uint32_t p[4], double dih)
{
  double r = 0;
  if (c->keep.ratio > 0 && !(dih >= c->bound))
    r = tr_sliver_ratio_at(c->m, p, TR_NONE, NULL);
  return r;
}

static uint32_t region_of(const struct tr_mesh *m, uint32_t t)
{
  return m->region ? m->region[t] : 0;
}

/* Swap23 on face k of t: the face goes, the segment between the two apexes comes. Only a
 * flip whose new tets' smallest angle beats `floor` too (the best candidate so far) is
 * of use, so the others stop at their first tet that does not. */
static int face_cand(const tr_sliver_ctx *c, uint32_t t, int k, double floor, cand *x)
{
  const struct tr_mesh *m = c->m;
  uint32_t nb = m->tn[4 * (size_t)t + (size_t)k];
  if (nb == TR_NONE || !tr_tet_is_real(m, nb >> 2))
    return 0;
  const uint32_t *tv = m->tv + 4 * (size_t)t;
  uint32_t f[3] = {tv[tr_face_vtx[k][0]], tv[tr_face_vtx[k][1]], tv[tr_face_vtx[k][2]]};
  if (tr_sliver_protected(c, f, 3))
    return 0;
  uint32_t a = tv[k], b = m->tv[4 * (size_t)(nb >> 2) + (nb & 3)];
  double dih[3], was = 0;
  x->oldmin = fmin(tet_min(c, t, &was), tet_min(c, nb >> 2, &was));
  double beat = fmax(floor, x->oldmin);
  /* (f_i, f_i+1, b, a) positive for all three exactly when ab crosses the open face:
   * f is listed so that (f0, f1, f2, a) is positive */
  const double below = tr_dihedral_cos_below(beat); /* the screen of insert.c's cones */
  x->newmin = INFINITY;
  for (int i = 0; i < 3; i++) {
    uint32_t *p = x->newv + 4 * i;
    p[0] = f[i], p[1] = f[(i + 1) % 3], p[2] = b, p[3] = a;
    int flat;
    double lo = tr_sliver_min_cos_at(m, p, TR_NONE, NULL, &flat);
    if (tr_sliver_cos_loses(lo, flat, below, beat))
      return 0;
    dih[i] = tr_sliver_angle_of_cos(lo, flat);
    x->newmin = fmin(x->newmin, dih[i]);
    if (!(x->newmin > beat))
      return 0; /* the exact tests only for a flip worth making */
  }
  x->nnew = 3;
  x->old[0] = t;
  x->old[1] = nb >> 2;
  x->nold = 2;
  for (int i = 0; i < 3; i++) {
    const uint32_t *p = x->newv + 4 * i;
    if (!positive(m, p[0], p[1], p[2], p[3]) ||
        !tr_sliver_keeps_bounds(c, p, TR_NONE, NULL, region_of(m, t), ratio_of(c, p, dih[i]),
                                dih[i], was))
      return 0;
  }
  return 1;
}

void tr_sliver_ring_dp(tr_sliver_ring *R)
{
  int n = R->n;
  for (int i = 0; i + 1 < n; i++)
    R->val[i][i + 1] = INFINITY;
  for (int len = 2; len < n; len++)
    for (int i = 0; i + len < n; i++) {
      int j = i + len, bk = -1;
      /* a sub-polygon whose best is at or under the floor spoils every triangulation that
       * holds it: it counts as none (-1), and the ones over the floor come out the same */
      double best = R->floor, below = tr_dihedral_cos_below(best);
      for (int k = i + 1; k < j; k++) {
        double q = fmin(R->val[i][k], R->val[k][j]);
        if (q < 0 || q <= best)
          continue;
        uint32_t pa[4] = {R->A, R->r[i], R->r[k], R->r[j]};
        uint32_t pb[4] = {R->B, R->r[j], R->r[k], R->r[i]};
        /* each of the two tets must beat best: its cosine screened first (insert.c) */
        int fa, fb;
        double ca = tr_sliver_min_cos_at(R->m, pa, TR_NONE, NULL, &fa);
        if (tr_sliver_cos_loses(ca, fa, below, best))
          continue;
        double qa = tr_sliver_angle_of_cos(ca, fa);
        if (fmin(q, qa) <= best)
          continue;
        double cb = tr_sliver_min_cos_at(R->m, pb, TR_NONE, NULL, &fb);
        if (tr_sliver_cos_loses(cb, fb, below, best))
          continue;
        double qb = tr_sliver_angle_of_cos(cb, fb);
        q = fmin(q, fmin(qa, qb));
        if (q <= best || !positive(R->m, pa[0], pa[1], pa[2], pa[3]) ||
            !positive(R->m, pb[0], pb[1], pb[2], pb[3]) ||
            !tr_sliver_keeps_bounds(R->c, pa, TR_NONE, NULL, R->region, ratio_of(R->c, pa, qa),
                                    qa, R->was) ||
            !tr_sliver_keeps_bounds(R->c, pb, TR_NONE, NULL, R->region, ratio_of(R->c, pb, qb),
                                    qb, R->was))
          continue;
        best = q;
        below = tr_dihedral_cos_below(best);
        bk = k;
      }
      R->val[i][j] = bk < 0 ? -1 : best;
      R->cut[i][j] = (int8_t)bk;
    }
}

void tr_sliver_ring_emit(const tr_sliver_ring *R, int i, int j, uint32_t *newv, uint32_t *nnew)
{
  if (j - i < 2)
    return;
  int k = R->cut[i][j];
  uint32_t *p = newv + 4 * (size_t)*nnew;
  p[0] = R->A, p[1] = R->r[i], p[2] = R->r[k], p[3] = R->r[j];
  p[4] = R->B, p[5] = R->r[j], p[6] = R->r[k], p[7] = R->r[i];
  *nnew += 2;
  tr_sliver_ring_emit(R, i, k, newv, nnew);
  tr_sliver_ring_emit(R, k, j, newv, nnew);
}

/* Removal of edge ab of t: its shell (closed, real, 3..SL_MAX_RING tets, no protected
 * face around ab) replaced by the best triangulation of its ring. */
static tr_status edge_cand(const tr_sliver_ctx *c, uint32_t t, uint32_t a, uint32_t b,
                           double floor, tr_u32buf *sh, cand *x, int *ok)
{
  struct tr_mesh *m = c->m;
  *ok = 0;
  uint32_t e[2] = {a, b};
  if (tr_sliver_protected(c, e, 2))
    return TR_OK;
  int closed = 0;
  TR_CHECK(tr_shell(m, a, b, t, sh, &closed));
  int n = (int)sh->n;
  if (!closed || n < 3 || n > SL_MAX_RING)
    return TR_OK;
  tr_sliver_ring R;
  R.c = c;
  R.m = m;
  R.n = n;
  R.region = region_of(m, t);
  R.was = 0;
  x->oldmin = INFINITY;
  for (int i = 0; i < n; i++) {
    uint32_t u = sh->a[i], w = sh->a[(i + 1) % n];
    if (!tr_tet_is_real(m, u))
      return TR_OK;
    x->old[i] = u;
    x->oldmin = fmin(x->oldmin, tet_min(c, u, &R.was));
    /* the vertex u shares with the next tet besides a and b */
    R.r[i] = TR_NONE;
    for (int s = 0; s < 4; s++) {
      uint32_t v = m->tv[4 * (size_t)u + (size_t)s];
      if (v != a && v != b && tr_ncode(m, w, v) >= 0)
        R.r[i] = v;
    }
    if (R.r[i] == TR_NONE)
      return TR_OK;
  }
  x->nold = (uint32_t)n;
  for (int i = 0; i < n; i++) {
    uint32_t f[3] = {a, b, R.r[i]};
    if (tr_sliver_protected(c, f, 3))
      return TR_OK;
  }
  /* shell tet i+1 is {a, b, r[i], r[i+1]}: its parity orients the ring */
  uint32_t p[4] = {a, b, R.r[0], R.r[1 % n]};
  int even = tr_tet_even_order(m, x->old[1 % n], p);
  if (even < 0)
    return TR_OK;
  R.A = even ? a : b;
  R.B = even ? b : a;
  R.floor = fmax(floor, x->oldmin);
  tr_sliver_ring_dp(&R);
  if (!(R.val[0][n - 1] > x->oldmin))
    return TR_OK;
  x->nnew = 0;
  tr_sliver_ring_emit(&R, 0, n - 1, x->newv, &x->nnew);
  x->newmin = R.val[0][n - 1];
  *ok = 1;
  return TR_OK;
}

static tr_status apply(tr_sliver_ctx *c, const cand *x, tr_sliver_stats *st)
{
  struct tr_mesh *m = c->m;
  uint32_t ids[SL_MAX_NEW];
  uint32_t region = m->region ? m->region[x->old[0]] : 0; /* one region: no sub-face between */
  TR_CHECK(tr_mesh_replace(m, x->old, x->nold, x->newv, x->nnew, ids));
  for (uint32_t i = 0; m->region && i < x->nnew; i++)
    m->region[ids[i]] = region;
  TR_CHECK(tr_sliver_touch(c, x->newv, 4 * (size_t)x->nnew));
  if (x->nold == 2)
    st->flips23++;
  else if (x->nold == 3)
    st->flips32++;
  else if (x->nold == 4)
    st->flips44++;
  else
    st->flipsn++;
  return TR_OK;
}

tr_status tr_sliver_flip_tet(tr_sliver_ctx *c, uint32_t t, tr_u32buf *sh, tr_sliver_stats *st,
                             int *done)
{
  struct tr_mesh *m = c->m;
  tr_status s = TR_OK;
  cand best, x;
  int have = 0;
  *done = 0;
  best.newmin = -1;
  for (int e = 0; e < 6 && s == TR_OK; e++) {
    const uint32_t *v = m->tv + 4 * (size_t)t;
    int ok;
    s = edge_cand(c, t, v[tr_edge_vtx[e][0]], v[tr_edge_vtx[e][1]], best.newmin, sh, &x, &ok);
    if (ok && x.newmin > best.newmin)
      best = x, have = 1;
  }
  for (int k = 0; k < 4 && s == TR_OK; k++)
    if (face_cand(c, t, k, best.newmin, &x) && x.newmin > best.newmin)
      best = x, have = 1;
  if (have && s == TR_OK) {
    s = apply(c, &best, st);
    *done = s == TR_OK;
  }
  return s;
}

/* Slot t's tet found no flip at an epoch, and no tet at its vertices changed since. Every
 * tet its flips look at holds two of its vertices at least (the tets across its faces,
 * the shells of its edges, the fans around a sub-face's edge) and every constraint they
 * ask about three of them, so none of that changed either: the same search finds no flip
 * again (a third of cheese.off's flip searches, pass after pass). A slot whose tet was
 * replaced since has a new tet, whose vertices are stamped later. */
static int unchanged(const tr_sliver_ctx *c, uint32_t t)
{
  if (t >= c->nflip_failed || !c->flip_failed[t])
    return 0;
  const uint32_t *v = c->m->tv + 4 * (size_t)t;
  for (int k = 0; k < 4; k++)
    if (v[k] >= c->nvstamp || c->vstamp[v[k]] > c->flip_failed[t])
      return 0;
  return 1;
}

tr_status tr_sliver_flip_pass(tr_sliver_ctx *c, tr_sliver_stats *st)
{
  struct tr_mesh *m = c->m;
  tr_u32buf sh = {0};
  tr_status s = TR_OK;
  uint32_t nt = m->nt; /* tets made by this pass wait for the next */
  if (c->nflip_failed < nt) {
    uint64_t *a = realloc(c->flip_failed, sizeof *a * (size_t)nt);
    if (!a)
      return tr_error(TR_ERR_NOMEM, "out of memory for %u tet stamps", nt);
    memset(a + c->nflip_failed, 0, sizeof *a * (size_t)(nt - c->nflip_failed));
    c->flip_failed = a;
    c->nflip_failed = nt;
  }
  for (uint32_t t = 0; t < nt && s == TR_OK; t++) {
    if (!tr_tet_is_real(m, t) || !(tet_min(c, t, NULL) < c->bound))
      continue;
    int done;
    if (unchanged(c, t)) {
#ifndef NDEBUG /* the search the memo saves finds nothing */
      s = tr_sliver_flip_tet(c, t, &sh, st, &done);
      if (s == TR_OK && !done)
        s = tr_sliver_facet_flip_tet(c, t, st, &done);
      assert(s != TR_OK || !done);
#endif
      continue;
    }
    s = tr_sliver_flip_tet(c, t, &sh, st, &done);
    if (s == TR_OK && !done)
      s = tr_sliver_facet_flip_tet(c, t, st, &done);
    if (s == TR_OK && !done)
      c->flip_failed[t] = c->epoch;
  }
  tr_u32buf_free(&sh);
  return s;
}
