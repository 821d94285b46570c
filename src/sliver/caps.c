/* Points on the constraints for the polish's worst tets (sliver.h, polish.c): a tet with
 * all four vertices on the surface, or standing on an input triangle with a small angle,
 * is pinned between constraints, and no flip, move or interior point opens it (beam.off:
 * 12 tets whose worst, 8.9 degrees, spans a 0.4 x 1.8 side of the box; TetGen splits the
 * long input edges once more and gets 17.4). Here the constraint pieces of such a tet are
 * split by refinement itself (tr_refine_split_piece: the same exact points on input edges
 * and triangles as any encroached piece), one piece per trial: the sub-segment of the
 * tet's smallest dihedral angle, then its sub-faces, then its other sub-segments. A trial
 * is kept only when the smallest angle of the tets it created beats that of the tets it
 * deleted (the worst tet among them) and the new tets keep the ratio bound as the other
 * steps do; otherwise the mesh and the sub-faces are put back exactly as they were
 * (a snapshot of the tet slots, the vertex count and the sub-faces). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "refine/quality.h"
#include "refine/refine.h"
#include "refine/refine_stage.h"
#include "sliver/sliver.h"
#include "sliver/snap.h"

/* *better = 1 when the tets the trial created beat the ones it deleted, the worst tet t
 * among them, and keep the bounds (as tr_sliver_keeps_bounds: a new tet over max(ratio
 * bound, the deleted tets' largest ratio) only with no angle under c->bound; none over
 * its region's volume bound, which the trial's refinement leaves when it stops at its
 * point budget: two boxes under region bounds once kept such a trial). A tet deleted and
 * made again (in another slot or rotation: a cavity's rim) is neither. */
static tr_status improved(const tr_sliver_ctx *c, const tr_sliver_snap *z, uint32_t t,
                         double top_ratio, int *better)
{
  const struct tr_mesh *m = c->m;
  *better = 0;
  tr_vtmap old = {0};
  uint32_t key[4], tkey[4];
  tr_sliver_tet_key(z->tv + z->stride * (size_t)t, tkey);
  tr_status s = TR_OK;
  for (uint32_t u = 0; u < z->nt && s == TR_OK; u++)
    if (tr_sliver_snap_real(z, u) && tr_sliver_snap_changed(m, z, u)) {
      tr_sliver_tet_key(z->tv + z->stride * (size_t)u, key);
      s = tr_vtmap_set(&old, 4, key, u);
    }
  double newmin = INFINITY, newratio = 0;
  int again = 0, nnew = 0, nold = 0, over = 0;
  for (uint32_t u = 0; u < m->nt && s == TR_OK; u++) {
    if (!tr_tet_is_real(m, u) || !tr_sliver_snap_changed(m, z, u))
      continue;
    tr_sliver_tet_key(m->tv + 4 * (size_t)u, key);
    uint32_t was = tr_vtmap_get(&old, 4, key);
    if (was != TR_VTMAP_NONE) {
      again += !memcmp(key, tkey, sizeof key);
      s = tr_vtmap_set(&old, 4, key, TR_NONE - 1); /* made again: not deleted */
      continue;
    }
    double r, q = tr_sliver_min_dihedral_at(m, m->tv + 4 * (size_t)u, TR_NONE, NULL, &r);
    if (!tr_sliver_keeps_bounds(c, m->tv + 4 * (size_t)u, TR_NONE, NULL,
                                m->region ? m->region[u] : 0, 0, INFINITY, 0))
      over = 1; /* the volume part: the ratio part is decided below */
    nnew = q < newmin ? 1 : nnew + (q == newmin);
    newmin = fmin(newmin, q);
    if (!(q >= c->bound))
      newratio = fmax(newratio, r);
  }
  double oldmin = INFINITY, was = 0;
  int gone = 0;
  for (uint32_t u = 0; u < z->nt && s == TR_OK; u++) {
    if (!tr_sliver_snap_real(z, u) || !tr_sliver_snap_changed(m, z, u))
      continue;
    tr_sliver_tet_key(z->tv + z->stride * (size_t)u, key);
    if (tr_vtmap_get(&old, 4, key) == TR_NONE - 1)
      continue;
    gone += !memcmp(key, tkey, sizeof key);
    double r, q = tr_sliver_min_dihedral_at(m, z->tv + z->stride * (size_t)u, TR_NONE, NULL, &r);
    nold = q < oldmin ? 1 : nold + (q == oldmin);
    oldmin = fmin(oldmin, q);
    was = fmax(was, r);
  }
  tr_vtmap_free(&old);
  /* a congruent copy of the worst tet elsewhere in the trial (3torus: symmetric caps)
   * keeps the minimum; fewer tets at it is progress all the same */
  *better = s == TR_OK && gone && !again && !over &&
            (newmin > oldmin || (newmin == oldmin && nnew < nold)) &&
            !(c->keep.ratio > 0 && newratio > tr_sliver_ratio_allowed(c, fmax(was, top_ratio)));
  return s;
}

tr_status tr_sliver_step_tet(tr_sliver_ctx *tc, uint32_t u, tr_u32buf *sh, tr_u32buf *ball,
                             void *scratch, tr_sliver_stats *st, uint32_t *points, int *done)
{
  uint32_t v[4];
  memcpy(v, tc->m->tv + 4 * (size_t)u, sizeof v);
  *done = 0;
  tr_status s = tr_sliver_flip_tet(tc, u, sh, st, done);
  for (int j = 0; j < 4 && s == TR_OK && !*done; j++)
    s = tr_sliver_smooth_vertex(tc, v[j], INFINITY, ball, st, done);
  if (s == TR_OK && !*done && *points < SL_CAP_POINTS) {
    s = tr_sliver_insert_tet(tc, u, scratch, done);
    *points += (uint32_t)*done;
    st->points += (uint64_t)*done;
  }
  return s;
}

/* The trial's new tets under the bound get the polish's steps (a split leaves slivers
 * next to the new points that they open), SL_CAP_PASSES times over them. */
static tr_status tidy(tr_sliver_ctx *tc, const tr_sliver_snap *z, void *scratch,
                      tr_sliver_stats *st)
{
  struct tr_mesh *m = tc->m;
  tr_u32buf sh = {0}, ball = {0};
  tr_status s = TR_OK;
  uint32_t points = 0;
  for (int pass = 0; pass < SL_CAP_PASSES && s == TR_OK; pass++) {
    uint32_t nt = m->nt;
    for (uint32_t u = 0; u < nt && s == TR_OK; u++) {
      if (!tr_tet_is_real(m, u) || !tr_sliver_snap_changed(m, z, u) ||
          !(tr_sliver_tet_min(tc, u, NULL) < tc->bound))
        continue;
      int done;
      s = tr_sliver_step_tet(tc, u, &sh, &ball, scratch, st, &points, &done);
    }
  }
  tr_u32buf_free(&sh);
  tr_u32buf_free(&ball);
  return s;
}

/* The pieces to try for tet t, best first, into p (2 or 3 vertex ids each, n[i] of them):
 * the sub-face edges in the order of their dihedral angles (refinement splits those that
 * are sub-segments), the sub-face of the smallest angle's faces first. */
static int pieces(const tr_sliver_ctx *c, uint32_t t, uint32_t p[][3], int n[])
{
  const struct tr_mesh *m = c->m;
  const uint32_t *v = m->tv + 4 * (size_t)t;
  const double *q[4];
  for (int i = 0; i < 4; i++)
    q[i] = m->xyz + 3 * (size_t)v[i];
  double r, w, d[6];
  if (!tr_tet_shape(q[0], q[1], q[2], q[3], &r, &w, d, NULL))
    for (int e = 0; e < 6; e++) /* no circumcentre: the angles are still there */
      if (!isfinite(d[e]))
        d[e] = 0;
  int order[6] = {0, 1, 2, 3, 4, 5};
  for (int i = 1; i < 6; i++) /* stable: ties to the lower edge code */
    for (int j = i; j > 0 && d[order[j - 1]] > d[order[j]]; j--) {
      int x = order[j];
      order[j] = order[j - 1];
      order[j - 1] = x;
    }
  int k = 0;
  /* the worst edge, then the sub-faces of t on it, then the other sub-face edges */
  int e0 = order[0], a = tr_edge_vtx[e0][0], b = tr_edge_vtx[e0][1];
  uint32_t ev[2] = {v[a], v[b]};
  if (tr_sliver_protected(c, ev, 2)) {
    p[k][0] = ev[0], p[k][1] = ev[1], n[k++] = 2;
  }
  for (int f = 0; f < 4; f++) {
    if (f == a || f == b)
      continue; /* face f lacks vertex f: it holds edge ab only when f is neither */
    uint32_t fv[3] = {v[tr_face_vtx[f][0]], v[tr_face_vtx[f][1]], v[tr_face_vtx[f][2]]};
    if (tr_sliver_protected(c, fv, 3)) {
      memcpy(p[k], fv, sizeof fv);
      n[k++] = 3;
    }
  }
  for (int i = 1; i < 6 && k < SL_CAP_PIECES; i++) {
    uint32_t uv[2] = {v[tr_edge_vtx[order[i]][0]], v[tr_edge_vtx[order[i]][1]]};
    if (tr_sliver_protected(c, uv, 2)) {
      p[k][0] = uv[0], p[k][1] = uv[1], n[k++] = 2;
    }
  }
  return k < SL_CAP_PIECES ? k : SL_CAP_PIECES;
}

/* The fan of tet t: the sub-face edges at its vertices on constraints that are no edge of
 * t, in the order of those vertices and of their stars, at most SL_CAP_FAN. */
static tr_status fan(tr_sliver_ctx *c, uint32_t t, uint32_t p[][3], int n[], int *np)
{
  struct tr_mesh *m = c->m;
  uint32_t v[4];
  memcpy(v, m->tv + 4 * (size_t)t, sizeof v);
  tr_u32buf ball = {0};
  tr_status s = TR_OK;
  *np = 0;
  for (int i = 0; i < 4 && s == TR_OK && *np < SL_CAP_FAN; i++) {
    if (c->movable[v[i]])
      continue;
    s = tr_ball(m, v[i], 0, &ball);
    for (size_t j = 0; j < ball.n && s == TR_OK && *np < SL_CAP_FAN; j++) {
      const uint32_t *tv = m->tv + 4 * (size_t)ball.a[j];
      for (int k = 0; k < 4 && *np < SL_CAP_FAN; k++) {
        uint32_t e[2] = {v[i], tv[k]};
        int dup = tv[k] == v[i];
        for (int l = 0; l < 4; l++) /* an edge of t: tried with t's own pieces */
          dup |= tv[k] == v[l];
        for (int l = 0; l < *np && !dup; l++)
          dup = (p[l][0] == e[0] && p[l][1] == e[1]) || (p[l][0] == e[1] && p[l][1] == e[0]);
        if (dup || !tr_sliver_protected(c, e, 2))
          continue;
        p[*np][0] = e[0], p[*np][1] = e[1], n[(*np)++] = 2;
      }
    }
  }
  tr_u32buf_free(&ball);
  return s;
}

tr_status tr_sliver_cap_tet(tr_sliver_ctx *c, tr_subfaces *sub, uint32_t t, int wide,
                            void *scratch, tr_vtmap *refused, tr_sliver_stats *st, int *done,
                            int *tried)
{
  struct tr_mesh *m = c->m;
  *done = 0;
  *tried = 0;
  if (!c->keep.plc || !sub)
    return TR_OK;
  uint32_t p[SL_CAP_PIECES + SL_CAP_FAN + 8][3];
  int n[SL_CAP_PIECES + SL_CAP_FAN + 8], np = 0;
  if (wide)
    TR_CHECK(fan(c, t, p, n, &np));
  else
    np = pieces(c, t, p, n);
  if (!np)
    return TR_OK;
  /* the mesh's largest ratio among the tets the bound looks at (cached); it moves with
   * the steps before, so the allowance caps it at the stage's start (improved) */
  double top_ratio = 0;
  for (uint32_t u = 0; u < m->nt; u++)
    if (tr_tet_is_real(m, u)) {
      double r, q = tr_sliver_tet_min(c, u, &r);
      if (!(q >= c->bound))
        top_ratio = fmax(top_ratio, r);
    }
  tr_refine_params rp;
  memset(&rp, 0, sizeof rp);
  /* the refinement's own ratio bound: the new tets around the piece that are over it
   * are refined as there (beam: one split leaves the long tets next to it) */
  rp.ratio = c->keep.ratio;
  rp.max_volume = c->keep.max_volume;
  rp.keep_edges = c->keep.keep_edges;
  rp.wedge_grading = c->keep.wedge_grading;
  rp.budget = SL_CAP_POINTS;
  rp.sub_exported = 1; /* tr_refine's or a hook's output (tr_sliver_remove) */
  rp.memo = c->memo;
  rp.region_id = c->keep.region_id;
  rp.region_max_volume = c->keep.region_max_volume;
  rp.nregion_bounds = c->keep.nregion_bounds;
  tr_status s = TR_OK;
  for (int i = 0; i < np && s == TR_OK && !*done; i++) {
    uint32_t key[3] = {p[i][0], p[i][1], n[i] == 3 ? p[i][2] : TR_NONE};
    for (int a = 1; a < n[i]; a++) /* sorted: the piece whatever its order */
      for (int b = a; b > 0 && key[b - 1] > key[b]; b--) {
        uint32_t x = key[b];
        key[b] = key[b - 1];
        key[b - 1] = x;
      }
    if (refused && tr_vtmap_get(refused, 3, key) != TR_VTMAP_NONE)
      continue;
    tr_sliver_snap z;
    s = tr_sliver_snap_take(c, sub, &z);
    if (s != TR_OK)
      break;
    tr_refine_stats rs;
    memset(&rs, 0, sizeof rs);
    tr_status r = tr_refine_split_piece(m, c->keep.plc, sub, &rp, p[i], n[i], &rs);
    if (r != TR_OK)
      tr_error_clear(); /* e.g. a point past the bit-size guard: this piece stays */
    ++*tried;
    if (r == TR_OK && !rs.points && refused)
      s = tr_vtmap_set(refused, 3, key, 0);
    tr_sliver_ctx tc;
    memset(&tc, 0, sizeof tc);
    tr_sliver_stats ts = *st;
    if (r == TR_OK && rs.points) {
      r = tr_sliver_trial_ctx(c, sub, z.nv, &tc);
      if (r == TR_OK)
        r = tidy(&tc, &z, scratch, &ts);
      if (r != TR_OK)
        tr_error_clear();
    }
    int better = 0;
    if (r == TR_OK && rs.points)
      s = improved(c, &z, t, top_ratio, &better);
    if (s == TR_OK && better) {
      for (uint32_t v = 0; v < z.nv; v++) /* the old vertices' flags again */
        tc.movable[v] = c->movable[v];
      /* and c's measures and failed insertions: keyed by vertex ids, and no old vertex
       * moved (the polish's rounds would measure every tet and try every insertion that
       * failed again, the bulk of the cost) */
      tc.shapes = c->shapes; /* its entries of changed slots name other tets: measured again */
      c->shapes = NULL;
      tr_vtmap f = tc.failed;
      tc.failed = c->failed;
      c->failed = f;
      tr_sliver_snap_free(&z);
      tr_sliver_ctx_free(c);
      *c = tc;
      *st = ts;
      st->points += rs.points;
      st->on_constraints += rs.on_segments + rs.on_facets;
      *done = 1;
    } else {
      tr_sliver_ctx_free(&tc);
      if (c->memo && c->memo->n > z.nv) /* the trial's vertex ids go to other points */
        c->memo->n = z.nv;
      uint32_t nv0 = z.nv;
      s = tr_sliver_snap_restore(m, sub, &z);
      /* c's other measures hold: the trial moved no old vertex */
      tr_sliver_forget_from(c, nv0);
    }
  }
  return s;
}
