/* Flips of an edge inside a facet (sliver.h): two sub-faces a b c and a b d of one input
 * triangle, or of one merged facet, become a c d and b c d, the other diagonal of their
 * quadrilateral.
 *
 * Why: refinement and the sliver stage put points on facets through 3D cavities, so a
 * facet's sub-faces need not be a good 2D triangulation: a point placed near the
 * hypotenuse of a right-angled sub-face leaves a sub-face with an angle near 180 degrees
 * on that edge, and every tet standing on it has a dihedral angle near 0 (couplingdown's
 * worst tet, 0.49 degrees; on rotor_small 116 of the 866 tets under 10 degrees). The
 * flips of flips.c never touch a sub-face, and flat.c only splits a sub-segment opposite
 * such an angle. Any triangulation of the facet conforms to it, so the edge may go.
 *
 * On each side of the facet (one on the mesh's boundary), the tets around a b form a fan
 * from face a b c to face a b d, whose third vertices make an open ring c ... d. The fan
 * goes, and the best triangulation of the ring's polygon, closed by c d, coned to a and
 * to b, comes (flips.c's edge removal, tr_sliver_ring_dp: every tet exactly positive);
 * the triangle on c d gives the new sub-faces. Kept when the new tets' smallest angle
 * beats the old ones' and they keep the bounds, as every flip.
 *
 * Fans of at most SL_FACET_FAN tets per side (sliver.h): with two, the flip is the 2-2
 * (4-4) one; of SL_FACET_FAN_LONG where a tet has no such flip, outside thin triangles.
 * bench/quality, one run each on a noisy machine: at most 2 tets everywhere, 61 of 74
 * models meet issue 17's targets, 72.4 s of CPU against TetGen's 72.5; at most 3
 * everywhere, 61 (joint met, femur's smallest angle lost), 78.8 s against 74.9; at most
 * 6, 61, 80.6 s against 75.0 (pinion 3.7 -> 4.5 s back to back); 2, then 3 as above,
 * 62 (joint met, femur kept), 71.2 s against 73.9. A sub-face of a merged facet is
 * labelled again after the flip (label), as refinement expects (hard/chazelle_g2 failed
 * its debug check when the labels were kept). */
#include <math.h>
#include <string.h>

#include "core/facets.h"
#include "refine/quality.h"
#include "sliver/ring.h"
#include "sliver/sliver.h"

static uint32_t subface_of(const tr_sliver_ctx *c, uint32_t a, uint32_t b, uint32_t d)
{
  uint32_t k[3];
  tr_vtkey_face(a, b, d, k);
  return tr_vtmap_get(&c->faces, 3, k);
}

/* The label of sub-face S of input triangle tri's facet: tri when the facet is that
 * triangle alone, else (as refinement labels them, subs.c) the facet's smallest triangle
 * that holds S's exact centroid; TR_NONE if none does. */
static uint32_t label(const tr_sliver_ctx *c, const uint32_t S[3], uint32_t tri)
{
  const tr_facets *F = c->facets;
  const struct tr_plc *plc = c->keep.plc;
  if (!F || tr_facets_size(F, F->group[tri]) == 1)
    return tri;
  const uint32_t G = F->group[tri];
  const int k = tr_plc_tri_axis(plc, G);
  if (k < 0)
    return TR_NONE;
  tr_qpoint q;
  tr_qpoint_init(&q);
  tr_mesh_centroid_q(c->m, S, &q);
  tr_point p = tr_pt_q(&q);
  uint32_t out = tr_facets_triangle_of(F, plc, G, k, &p, TR_NONE);
  tr_qpoint_clear(&q);
  return out;
}

/* One flip under consideration: the old tets of both sides, the new ones. A side's fan
 * of n <= SL_FACET_FAN_LONG tets has a ring of n + 1 vertices, whose n - 1 triangles give
 * 2 (n - 1) new tets. */
_Static_assert(SL_FACET_FAN_LONG + 1 <= SL_MAX_RING, "a fan's ring fits tr_sliver_ring");
typedef struct fcand {
  uint32_t old[2 * SL_FACET_FAN_LONG], nold;
  uint32_t newv[4 * 4 * SL_FACET_FAN_LONG], nnew, region[4 * SL_FACET_FAN_LONG];
  uint32_t f, g, a, b, c0, d0; /* sub-faces a b c0 and a b d0 */
  int sides;                    /* 1: the facet is on the mesh's boundary */
  double newmin;
} fcand;

static int same_facet(const tr_sliver_ctx *c, uint32_t t, uint32_t u)
{
  return c->facets ? c->facets->group[t] == c->facets->group[u] : t == u;
}

/* One side of the facet at edge ab: the fan of tets from t (which has sub-face a b c0) to
 * the one with a sub-face a b d of the same facet, into x->old, and its ring c0 ... d into
 * R; *g = that sub-face. 0 when a sub-face of another facet or the mesh's boundary comes
 * first, or the fan has more than maxfan tets. */
static int fan(const tr_sliver_ctx *c, uint32_t t, uint32_t a, uint32_t b, uint32_t c0,
               uint32_t tri, int maxfan, uint32_t *g, fcand *x, tr_sliver_ring *R)
{
  const struct tr_mesh *m = c->m;
  uint32_t u = t, p = c0, first = x->nold;
  int n = 0;
  R->r[n++] = c0;
  for (;;) {
    if (u == TR_NONE || !tr_tet_is_real(m, u) || n > maxfan)
      return 0;
    x->old[x->nold++] = u;
    const uint32_t *v = m->tv + 4 * (size_t)u;
    uint32_t w = TR_NONE;
    for (int i = 0; i < 4; i++)
      if (v[i] != a && v[i] != b && v[i] != p)
        w = v[i];
    R->r[n++] = w;
    uint32_t fw[3] = {a, b, w};
    if (tr_sliver_protected(c, fw, 3)) {
      *g = subface_of(c, a, b, w);
      if (*g == TR_VTMAP_NONE || !same_facet(c, c->sub->tri[*g], tri))
        return 0;
      break;
    }
    u = TR_NEIG(m, u, tr_ncode(m, u, p)); /* across a b w */
    p = w;
  }
  if (n < 3)
    return 0; /* a b c0 d would be flat: no mesh has it */
  R->n = n;
  uint32_t q[4] = {a, b, R->r[0], R->r[1]};
  int even = tr_tet_even_order(m, x->old[first], q);
  if (even < 0)
    return 0;
  R->A = even ? a : b;
  R->B = even ? b : a;
  R->c = c;
  R->m = m;
  R->region = m->region ? m->region[t] : 0;
  return 1;
}

/* The flip of edge ab of sub-face f = face k of t (c0 its third vertex): each side's fan
 * replaced by the best triangulation of its ring coned to a and b, the ring's ends c0 and
 * d0 joined (the new sub-faces a c0 d0, b c0 d0), if both sides' beat `floor` and the old
 * tets; *x filled, 1 returned. With maxfan over SL_FACET_FAN only a flip with a longer
 * fan on some side: the others were weighed with SL_FACET_FAN, against the same floor. */
static int edge_flip(const tr_sliver_ctx *c, uint32_t t, int k, uint32_t f, uint32_t a,
                     uint32_t b, uint32_t c0, int maxfan, double floor, fcand *x,
                     tr_sliver_ring R[2])
{
  const struct tr_mesh *m = c->m;
  const uint32_t tri = c->sub->tri[f];
  uint32_t g[2] = {TR_NONE, TR_NONE};
  x->nold = 0;
  if (!fan(c, t, a, b, c0, tri, maxfan, &g[0], x, &R[0]))
    return 0;
  int sides = 1;
  uint32_t t3 = TR_NEIG(m, t, k); /* the other side of f, if any */
  if (t3 != TR_NONE) {
    if (!fan(c, t3, a, b, c0, tri, maxfan, &g[1], x, &R[1]) || g[1] != g[0])
      return 0;
    sides = 2;
  }
  x->sides = sides;
  if (g[0] == f)
    return 0;
  int longest = 0;
  for (int s = 0; s < sides; s++)
    longest = R[s].n - 1 > longest ? R[s].n - 1 : longest;
  if (maxfan > SL_FACET_FAN && longest <= SL_FACET_FAN)
    return 0;
  const uint32_t d0 = R[0].r[R[0].n - 1];
  double oldmin = INFINITY, was = 0;
  for (uint32_t i = 0; i < x->nold; i++) {
    double r;
    oldmin = fmin(oldmin, tr_sliver_tet_min(c, x->old[i], &r));
    was = fmax(was, r);
  }
  x->nnew = 0;
  x->newmin = INFINITY;
  for (int s = 0; s < sides; s++) {
    R[s].was = was;
    R[s].floor = fmax(floor, oldmin);
    tr_sliver_ring_dp(&R[s]);
    double v = R[s].val[0][R[s].n - 1];
    if (!(v > R[s].floor))
      return 0;
    x->newmin = fmin(x->newmin, v);
    uint32_t from = x->nnew;
    tr_sliver_ring_emit(&R[s], 0, R[s].n - 1, x->newv, &x->nnew);
    for (uint32_t i = from; i < x->nnew; i++)
      x->region[i] = R[s].region;
  }
  x->f = f, x->g = g[0], x->a = a, x->b = b, x->c0 = c0, x->d0 = d0;
  return 1;
}

/* Carries out x unless a new sub-face has no label (*done = 0), which a valid mesh never
 * gives: the new sub-faces tile the old ones, which lie in the facet. */
static tr_status apply(tr_sliver_ctx *c, const fcand *x, int *done)
{
  struct tr_mesh *m = c->m;
  tr_subfaces *sub = c->sub;
  uint32_t *F = sub->v + 3 * (size_t)x->f, *G = sub->v + 3 * (size_t)x->g, k[3];
  /* f loses b to d0, g loses a to c0; the sub-faces keep their slots and orientation */
  uint32_t Sf[3], Sg[3];
  for (int i = 0; i < 3; i++) {
    Sf[i] = F[i] == x->b ? x->d0 : F[i];
    Sg[i] = G[i] == x->a ? x->c0 : G[i];
  }
  const uint32_t lf = label(c, Sf, sub->tri[x->f]), lg = label(c, Sg, sub->tri[x->f]);
  *done = lf != TR_NONE && lg != TR_NONE;
  if (!*done)
    return TR_OK;
  uint32_t ids[4 * SL_FACET_FAN_LONG];
  /* one side: the facet is on the mesh's boundary, where its new faces have no neighbour */
  if (x->sides == 2)
    TR_CHECK(tr_mesh_replace(m, x->old, x->nold, x->newv, x->nnew, ids));
  else
    TR_CHECK(tr_mesh_replace_open(m, x->old, x->nold, x->newv, x->nnew, ids));
  for (uint32_t i = 0; m->region && i < x->nnew; i++)
    m->region[ids[i]] = x->region[i];
  /* the new tets hold a, b, c0 and d0: every vertex of the sub-faces that change */
  TR_CHECK(tr_sliver_touch(c, x->newv, 4 * (size_t)x->nnew));
  tr_vtkey_face(F[0], F[1], F[2], k);
  TR_CHECK(tr_vtmap_set(&c->faces, 3, k, TR_VTMAP_NONE));
  tr_vtkey_face(G[0], G[1], G[2], k);
  TR_CHECK(tr_vtmap_set(&c->faces, 3, k, TR_VTMAP_NONE));
  memcpy(F, Sf, sizeof Sf);
  memcpy(G, Sg, sizeof Sg);
  sub->tri[x->f] = lf;
  sub->tri[x->g] = lg;
  tr_vtkey_face(F[0], F[1], F[2], k);
  TR_CHECK(tr_vtmap_set(&c->faces, 3, k, x->f));
  tr_vtkey_face(G[0], G[1], G[2], k);
  TR_CHECK(tr_vtmap_set(&c->faces, 3, k, x->g));
  tr_vtkey_edge(x->a, x->b, k);
  TR_CHECK(tr_vtmap_set(&c->edges, 2, k, TR_VTMAP_NONE));
  tr_vtkey_edge(x->c0, x->d0, k);
  return tr_vtmap_set(&c->edges, 2, k, x->f);
}

tr_status tr_sliver_facet_flip_tet(tr_sliver_ctx *c, uint32_t t, tr_sliver_stats *st, int *done)
{
  const struct tr_mesh *m = c->m;
  *done = 0;
  if (!c->sub)
    return TR_OK;
  fcand best, x;
  tr_sliver_ring R[2];
  best.newmin = -1;
  int have = 0;
  /* the longer fans only where the short ones give nothing, and not in a thin triangle,
   * whose sub-faces a refinement at its small corner makes next (femur: a flip with 3
   * there left a 0.17 degree tet between points on two input edges 1.3 degrees apart) */
  for (int maxfan = SL_FACET_FAN; maxfan <= SL_FACET_FAN_LONG && !have; maxfan++)
    for (int k = 0; k < 4; k++) {
      const uint32_t *tv = m->tv + 4 * (size_t)t;
      uint32_t fv[3] = {tv[tr_face_vtx[k][0]], tv[tr_face_vtx[k][1]], tv[tr_face_vtx[k][2]]};
      if (!tr_sliver_protected(c, fv, 3))
        continue;
      uint32_t f = subface_of(c, fv[0], fv[1], fv[2]);
      if (f == TR_VTMAP_NONE || (maxfan > SL_FACET_FAN && c->thin && c->thin[c->sub->tri[f]]))
        continue;
      for (int j = 0; j < 3; j++)
        if (edge_flip(c, t, k, f, fv[j], fv[(j + 1) % 3], fv[(j + 2) % 3], maxfan, best.newmin,
                      &x, R) &&
            x.newmin > best.newmin)
          best = x, have = 1;
    }
  if (!have)
    return TR_OK;
  TR_CHECK(apply(c, &best, done));
  st->facet_flips += (uint64_t)*done;
  return TR_OK;
}
