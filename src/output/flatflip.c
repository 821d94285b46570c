/* Flips that take away tets flat in doubles: see flatflip.h. */
#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "output/flatflip.h"
#include "output/round.h"
#include "refine/refine.h"
#include "refine/refine_impl.h" /* rf_volume_above: the bound decided as refinement does */
#include "refine/refine_stage.h"

typedef struct {
  struct tr_mesh *m;
  const tr_plc *plc;
  double max_volume;
  /* the region points' bounds, sorted by id (tr_refine_region_bounds) */
  uint32_t *region_id, nregion_bounds;
  double *region_bound;
  uint32_t *sub; /* the sub-faces as sorted triples, in lexicographic order */
  uint32_t nsub;
  tr_u32buf shell;
} ctx;

static int kept(const struct tr_mesh *m, uint32_t t)
{
  return t != TR_NONE && tr_tet_is_real(m, t) && !(m->flags[t] & TR_TF_OUTER);
}

/* The exact orientation of tet v[0..3]. */
static int exact_sign(const struct tr_mesh *m, const uint32_t *v)
{
  tr_point p[4];
  for (int i = 0; i < 4; i++)
    p[i] = tr_mesh_point(m, v[i]);
  return tr_orient3d_p(&p[0], &p[1], &p[2], &p[3]);
}

static int is_subface(const ctx *c, uint32_t a, uint32_t b, uint32_t d)
{
  uint32_t key[3] = {a, b, d};
  tr_sort3(key);
  return bsearch(key, c->sub, c->nsub, 3 * sizeof *c->sub, tr_cmp_face_key) != NULL;
}

/* Edge ab lies on an input segment (a segment not on any triangle: the sub-face test
 * does not see it). */
static int on_segment(const ctx *c, uint32_t a, uint32_t b)
{
  tr_point pa = tr_mesh_point(c->m, a), pb = tr_mesh_point(c->m, b);
  for (uint32_t i = 0; i < c->plc->nsegs; i++) {
    tr_point s0 = tr_mesh_point(c->m, c->plc->segs[2 * i]),
             s1 = tr_mesh_point(c->m, c->plc->segs[2 * i + 1]);
    if (tr_classify_point_segment(&pa, &s0, &s1).type != TR_DEG &&
        tr_classify_point_segment(&pb, &s0, &s1).type != TR_DEG)
      return 1;
  }
  return 0;
}

/* Tet v of region r keeps its volume bound. */
static int within_bound(const ctx *c, const uint32_t *v, uint32_t r)
{
  double b = tr_refine_region_bound_of(c->region_id, c->region_bound, c->nregion_bounds,
                                       c->max_volume, r);
  if (!(b > 0))
    return 1;
  tr_point p[4];
  for (int i = 0; i < 4; i++)
    p[i] = tr_mesh_point(c->m, v[i]);
  return !rf_volume_above(&p[0], &p[1], &p[2], &p[3], b);
}

static tr_status commit(ctx *c, const uint32_t *old, uint32_t nold, const uint32_t *newv,
                        uint32_t nnew)
{
  uint32_t region = c->m->region[old[0]], ids[2 * TR_FLATFLIP_MAX_SHELL];
  TR_CHECK(tr_mesh_replace(c->m, old, nold, newv, nnew, ids));
  for (uint32_t i = 0; i < nnew; i++)
    c->m->region[ids[i]] = region;
  return TR_OK;
}

/* Swap23 across face k of t. */
static tr_status try_23(ctx *c, uint32_t t, int k, int *done)
{
  struct tr_mesh *m = c->m;
  uint32_t code = m->tn[4 * (size_t)t + (size_t)k], u = code == TR_NONE ? TR_NONE : code >> 2;
  *done = 0;
  if (!kept(m, u) || m->region[u] != m->region[t])
    return TR_OK;
  const uint32_t *tv = m->tv + 4 * (size_t)t;
  const uint8_t *f = tr_face_vtx[k];
  if (is_subface(c, tv[f[0]], tv[f[1]], tv[f[2]]))
    return TR_OK;
  uint32_t e = m->tv[4 * (size_t)u + (code & 3)];
  uint32_t newv[12];
  int before = tr_round_flat(m, tv) + tr_round_flat(m, m->tv + 4 * (size_t)u), after = 0;
  /* the new tets are t with one vertex of face k replaced by e: all positive iff the
   * segment from t's fourth vertex to e crosses the face's interior */
  for (int i = 0; i < 3; i++) {
    memcpy(newv + 4 * i, tv, 4 * sizeof *tv);
    newv[4 * i + f[i]] = e;
    if (exact_sign(m, newv + 4 * i) <= 0)
      return TR_OK;
    after += tr_round_flat(m, newv + 4 * i);
  }
  if (after >= before)
    return TR_OK;
  uint32_t old[2] = {t, u};
  TR_CHECK(commit(c, old, 2, newv, 3));
  *done = 1;
  return TR_OK;
}

/* Edge removal of edge e of t: the shell's ring r_0..r_{n-1} (r_i shared by shell tets i
 * and i+1) triangulated as a fan from r_f; each triangle (p,q,s) in ring order gives the
 * tets (p,q,s,a) and (p,q,s,b). With sg = the sign of (a, b, r_0, r_1) (the same for
 * every (a, b, r_{i-1}, r_i) of a closed ring), (p,q,s,a) has sign -sg and (p,q,s,b) sign
 * sg when ab crosses the triangle: each is listed so that it is positive and must then
 * be so exactly. */
static tr_status try_edge(ctx *c, uint32_t t, int e, int *done)
{
  struct tr_mesh *m = c->m;
  *done = 0;
  uint32_t a = m->tv[4 * (size_t)t + tr_edge_vtx[e][0]], b = m->tv[4 * (size_t)t + tr_edge_vtx[e][1]];
  int closed;
  TR_CHECK(tr_shell(m, a, b, t, &c->shell, &closed));
  uint32_t n = (uint32_t)c->shell.n;
  if (!closed || n < 3 || n > TR_FLATFLIP_MAX_SHELL)
    return TR_OK;
  uint32_t sh[TR_FLATFLIP_MAX_SHELL], ring[TR_FLATFLIP_MAX_SHELL];
  memcpy(sh, c->shell.a, n * sizeof *sh);
  int before = 0;
  for (uint32_t i = 0; i < n; i++) {
    if (!kept(m, sh[i]) || m->region[sh[i]] != m->region[t])
      return TR_OK;
    before += tr_round_flat(m, m->tv + 4 * (size_t)sh[i]);
  }
  for (uint32_t i = 0; i < n; i++) {
    const uint32_t *x = m->tv + 4 * (size_t)sh[i], *y = m->tv + 4 * (size_t)sh[(i + 1) % n];
    ring[i] = TR_NONE;
    for (int j = 0; j < 4; j++)
      if (x[j] != a && x[j] != b)
        for (int l = 0; l < 4; l++)
          if (y[l] == x[j])
            ring[i] = x[j];
    if (ring[i] == TR_NONE)
      return tr_error(TR_ERR_INTERNAL, "flat flips: shell of edge (%u,%u) is not a ring", a, b);
  }
  for (uint32_t i = 0; i < n; i++)
    if (is_subface(c, a, b, ring[i]))
      return TR_OK;
  if (c->plc->nsegs && on_segment(c, a, b))
    return TR_OK;
  uint32_t abr[4] = {a, b, ring[0], ring[1]};
  int sg = exact_sign(m, abr);
  uint32_t best[8 * (TR_FLATFLIP_MAX_SHELL - 2)], cand[8 * (TR_FLATFLIP_MAX_SHELL - 2)];
  int best_after = before;
  uint32_t nnew = 2 * (n - 2), nfan = n == 3 ? 1 : n;
  for (uint32_t f = 0; f < nfan; f++) {
    int after = 0, ok = 1;
    for (uint32_t j = 1; j + 1 < n && ok; j++) {
      uint32_t p = ring[f], q = ring[(f + j) % n], s = ring[(f + j + 1) % n];
      uint32_t *ta = cand + 8 * (j - 1), *tb = ta + 4;
      /* (p,q,s,a) should have sign -sg: listed (p,s,q,a) when sg > 0 */
      ta[0] = p, ta[1] = sg > 0 ? s : q, ta[2] = sg > 0 ? q : s, ta[3] = a;
      tb[0] = p, tb[1] = sg > 0 ? q : s, tb[2] = sg > 0 ? s : q, tb[3] = b;
      ok = 0 < exact_sign(m, ta) && 0 < exact_sign(m, tb);
      after += tr_round_flat(m, ta) + tr_round_flat(m, tb);
    }
    if (ok && after < best_after) {
      best_after = after;
      memcpy(best, cand, 4 * nnew * sizeof *best);
    }
  }
  if (best_after >= before)
    return TR_OK;
  TR_CHECK(commit(c, sh, n, best, nnew));
  *done = 1;
  return TR_OK;
}

/* The last resort for a tet t that no flip takes away and no double position of its
 * Steiner points repairs (chazelle_g4_ulps: a Steiner point on an input edge between two
 * wall facets bumpy at subnormal scale, whose two tets with a wall vertex as apex leave
 * it a window of 0.49 ulp in x): a new vertex at t's centroid g, a double, connected to
 * the boundary of a cavity grown from t across each face g does not see strictly (exactly
 * and in doubles) until it sees all, so every new tet is positive exactly and in doubles.
 * The growth stops at a sub-face, a tet that is not kept or of another region, or
 * TR_FLATFLIP_MAX_CAVITY tets; it is refused when a vertex of the cavity is not on its
 * boundary (it would be dropped) or an edge inside it lies on an input segment. */
#define TR_FLATFLIP_MAX_CAVITY 32
static int sees(const struct tr_mesh *m, const uint32_t *v)
{
  return exact_sign(m, v) > 0 && !tr_round_flat(m, v);
}

static tr_status try_insert(ctx *c, uint32_t t, int *done)
{
  struct tr_mesh *m = c->m;
  *done = 0;
  const uint32_t *tv = m->tv + 4 * (size_t)t;
  double g[3];
  for (int i = 0; i < 3; i++)
    g[i] = 0.25 * (m->xyz[3 * (size_t)tv[0] + i] + m->xyz[3 * (size_t)tv[1] + i] +
                   m->xyz[3 * (size_t)tv[2] + i] + m->xyz[3 * (size_t)tv[3] + i]);
  uint32_t region = m->region[t], pid;
  TR_CHECK(tr_mesh_add_vertex(m, g, &pid));
  uint32_t cav[TR_FLATFLIP_MAX_CAVITY], ncav = 1, newv[4 * 4 * TR_FLATFLIP_MAX_CAVITY], nnew;
  cav[0] = t;
  int ok = 0;
  while (!ok) {
    /* the cavity's boundary faces, as the new tets with g in the opposite vertex's slot */
    nnew = 0;
    uint32_t bad_t = TR_NONE;
    int bad_k = -1;
    for (uint32_t i = 0; i < ncav; i++)
      for (int k = 0; k < 4; k++) {
        uint32_t code = m->tn[4 * (size_t)cav[i] + (size_t)k], u = code == TR_NONE ? TR_NONE : code >> 2;
        int inside = 0;
        for (uint32_t j = 0; j < ncav && !inside; j++)
          inside = cav[j] == u;
        if (inside)
          continue;
        uint32_t *w = newv + 4 * nnew++;
        memcpy(w, m->tv + 4 * (size_t)cav[i], 4 * sizeof *w);
        w[k] = pid;
        if (bad_t == TR_NONE && !sees(m, w)) {
          bad_t = cav[i];
          bad_k = k;
        }
      }
    if (bad_t == TR_NONE) {
      ok = 1;
      break;
    }
    const uint32_t *bv = m->tv + 4 * (size_t)bad_t;
    const uint8_t *f = tr_face_vtx[bad_k];
    uint32_t code = m->tn[4 * (size_t)bad_t + (size_t)bad_k], u = code == TR_NONE ? TR_NONE : code >> 2;
    if (ncav == TR_FLATFLIP_MAX_CAVITY || !kept(m, u) || m->region[u] != region ||
        is_subface(c, bv[f[0]], bv[f[1]], bv[f[2]]))
      break;
    cav[ncav++] = u;
  }
  /* every vertex of the cavity on its boundary; no edge inside it on an input segment */
  for (uint32_t i = 0; i < ncav && ok; i++)
    for (int k = 0; k < 4 && ok; k++) {
      uint32_t x = m->tv[4 * (size_t)cav[i] + k];
      int found = 0;
      for (uint32_t j = 0; j < 4 * nnew && !found; j++)
        found = newv[j] == x;
      ok = found;
    }
  if (ok && c->plc->nsegs)
    for (uint32_t i = 0; i < ncav && ok; i++)
      for (int e = 0; e < 6 && ok; e++) {
        uint32_t a = m->tv[4 * (size_t)cav[i] + tr_edge_vtx[e][0]],
                 b = m->tv[4 * (size_t)cav[i] + tr_edge_vtx[e][1]];
        int on_boundary = 0;
        for (uint32_t j = 0; j < nnew && !on_boundary; j++) {
          const uint32_t *w = newv + 4 * j;
          int ha = 0, hb = 0;
          for (int l = 0; l < 4; l++)
            ha |= w[l] == a, hb |= w[l] == b;
          on_boundary = ha && hb;
        }
        ok = on_boundary || !on_segment(c, a, b);
      }
  if (!ok) {
    m->nv--; /* the vertex just added (the last slot), referenced by no tet */
    return TR_OK;
  }
  uint32_t ids[4 * TR_FLATFLIP_MAX_CAVITY];
  TR_CHECK(tr_mesh_replace(m, cav, ncav, newv, nnew, ids));
  for (uint32_t i = 0; i < nnew; i++)
    m->region[ids[i]] = region;
  *done = 1;
  return TR_OK;
}

/* Tets still flat in doubles after run(): each gets try_insert (tr_round_insert_flat). */
static tr_status insert_all(ctx *c, uint64_t *ninserted)
{
  struct tr_mesh *m = c->m;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!kept(m, t) || !tr_round_flat(m, m->tv + 4 * (size_t)t))
      continue;
    int done = 0;
    TR_CHECK(try_insert(c, t, &done));
    *ninserted += (uint64_t)done;
  }
  return TR_OK;
}

static tr_status run(ctx *c, uint64_t *nflips)
{
  struct tr_mesh *m = c->m;
  for (int changed = 1; changed;) {
    changed = 0;
    for (uint32_t t = 0; t < m->nt; t++) {
      if (!kept(m, t) || !tr_round_flat(m, m->tv + 4 * (size_t)t))
        continue;
      int done = 0;
      for (int k = 0; k < 4 && !done; k++)
        TR_CHECK(try_23(c, t, k, &done));
      for (int e = 0; e < 6 && !done; e++)
        TR_CHECK(try_edge(c, t, e, &done));
      if (done) {
        (*nflips)++;
        changed = 1;
      }
    }
  }
  return TR_OK;
}

/* A flip makes fewer, larger tets (3-2, edge removal), and a tet it makes may be over the
 * volume bound refinement met (chazelle_rounding_budget.off under -a 1.024: one). Such a
 * tet is split in four at its centroid, a double (an interior point: written exactly),
 * when the four new tets are positive exactly and in doubles; each split quarters the
 * volume, so the passes end. Refusing those flips instead left tets flat in doubles that
 * the rounding repair could not fix. The pass runs with any volume bound, flips or not. */
static tr_status split_over_bound(ctx *c)
{
  struct tr_mesh *m = c->m;
  for (int changed = 1; changed;) {
    changed = 0;
    for (uint32_t t = 0; t < m->nt; t++) {
      if (!kept(m, t) || within_bound(c, m->tv + 4 * (size_t)t, m->region[t]))
        continue;
      uint32_t v[4], newv[16], pid = m->nv, ids[4];
      memcpy(v, m->tv + 4 * (size_t)t, sizeof v);
      double g[3];
      for (int i = 0; i < 3; i++)
        g[i] = 0.25 * (m->xyz[3 * (size_t)v[0] + i] + m->xyz[3 * (size_t)v[1] + i] +
                       m->xyz[3 * (size_t)v[2] + i] + m->xyz[3 * (size_t)v[3] + i]);
      tr_point q[4], pg = tr_pt_d(g);
      for (int i = 0; i < 4; i++)
        q[i] = tr_mesh_point(m, v[i]);
      int ok = 1;
      for (int k = 0; k < 4 && ok; k++) {
        memcpy(newv + 4 * k, v, sizeof v);
        newv[4 * k + k] = pid;
        tr_point r[4] = {q[0], q[1], q[2], q[3]};
        r[k] = pg;
        const double *x[4];
        for (int i = 0; i < 4; i++)
          x[i] = i == k ? g : m->xyz + 3 * (size_t)v[i];
        ok = tr_orient3d_p(&r[0], &r[1], &r[2], &r[3]) > 0 && tr_orient3d(x[0], x[1], x[2], x[3]) > 0;
      }
      if (!ok)
        continue;
      uint32_t id;
      TR_CHECK(tr_mesh_add_vertex(m, g, &id));
      uint32_t region = m->region[t];
      TR_CHECK(tr_mesh_replace(m, &t, 1, newv, 4, ids));
      for (int i = 0; i < 4; i++)
        m->region[ids[i]] = region;
      changed = 1;
    }
  }
  return TR_OK;
}

tr_status tr_round_flip_flat(struct tr_mesh *m, const tr_subfaces *sub, const tr_plc *plc,
                             double max_volume, int split_over, uint64_t *nflips)
{
  *nflips = 0;
  if (!m->region)
    return TR_OK;
  int bounded = max_volume > 0;
  for (uint32_t i = 0; i < plc->nregions; i++)
    bounded |= plc->region_maxvol[i] > 0;
  bounded &= split_over != 0;
  /* no Steiner point: the doubles are the exact points */
  int flat = m->vq && tr_round_count_nonpositive(m, NULL) > 0;
  if (!flat && !bounded)
    return TR_OK;
  ctx c = {.m = m, .plc = plc, .max_volume = max_volume, .nsub = flat ? sub->n : 0};
  double least = 0;
  TR_CHECK(tr_refine_region_bounds(plc, &c.region_id, &c.region_bound, &c.nregion_bounds, &least));
  c.sub = malloc(3 * sizeof *c.sub * (c.nsub ? c.nsub : 1));
  if (!c.sub) {
    free(c.region_id);
    free(c.region_bound);
    return tr_error(TR_ERR_NOMEM, "out of memory for %u sub-faces", sub->n);
  }
  for (uint32_t i = 0; i < c.nsub; i++) {
    memcpy(c.sub + 3 * (size_t)i, sub->v + 3 * (size_t)i, 3 * sizeof *c.sub);
    tr_sort3(c.sub + 3 * (size_t)i);
  }
  qsort(c.sub, c.nsub, 3 * sizeof *c.sub, tr_cmp_face_key);
  tr_status st = flat ? run(&c, nflips) : TR_OK;
  /* also the last net under every stage before: refinement's and sliver removal's own
   * steps keep the bounds, and a tet still over one here is a defect they missed */
  if (st == TR_OK && bounded)
    st = split_over_bound(&c);
  free(c.sub);
  free(c.region_id);
  free(c.region_bound);
  tr_u32buf_free(&c.shell);
  return st;
}

tr_status tr_round_insert_flat(struct tr_mesh *m, const tr_subfaces *sub, const tr_plc *plc,
                               uint64_t *ninserted)
{
  *ninserted = 0;
  if (!m->region || !m->vq || tr_round_count_nonpositive(m, NULL) == 0)
    return TR_OK;
  ctx c = {.m = m, .plc = plc, .nsub = sub->n};
  c.sub = malloc(3 * sizeof *c.sub * (c.nsub ? c.nsub : 1));
  if (!c.sub)
    return tr_error(TR_ERR_NOMEM, "out of memory for %u sub-faces", sub->n);
  for (uint32_t i = 0; i < c.nsub; i++) {
    memcpy(c.sub + 3 * (size_t)i, sub->v + 3 * (size_t)i, 3 * sizeof *c.sub);
    tr_sort3(c.sub + 3 * (size_t)i);
  }
  qsort(c.sub, c.nsub, 3 * sizeof *c.sub, tr_cmp_face_key);
  tr_status st = insert_all(&c, ninserted);
  free(c.sub);
  return st;
}
