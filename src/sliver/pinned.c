/* Points on the constraints under the pinned tets (sliver.h): a tet the rounds leave under
 * SL_PINNED_BOUND with three or four vertices no move may touch and a face on a sub-face
 * opens only with a point on that constraint, which refinement puts there
 * (tr_refine_open_pinned).
 *
 * That refinement runs without the ratio bound (with it, rotor_small went from 93,635 to
 * 190,864 tets against TetGen's 60,221), so it may leave a tet under the stage's bound
 * with a ratio over the largest the stage started from, which the stage promises not to
 * leave (tr_sliver_ratio_allowed); most of them the rounds after it open, but one pinned
 * between constraints stays (star_rounding_budget.off: a point on a facet 0.012 from a
 * vertex of the other facet of a 12.5 degree input edge, ratio 97.25 where the stage
 * started from 52.98). So the refinement is a trial: the tets it leaves that break the
 * promise get the rounds' steps (a flip, moves of the new points, an interior point, as
 * in caps.c); when one is still left, the mesh is put back exactly (snap.h) and the
 * refinement runs again without the pinned tets near those, SL_PINNED_TRIES times at
 * most, each time over a wider neighbourhood; then without points. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "refine/refine.h"
#include "sliver/sliver.h"
#include "sliver/snap.h"

#define SL_PINNED_TRIES 4

/* The tets under SL_PINNED_BOUND (or the dihedral target, when one raised the insertion
 * bound) with three or four vertices no move may touch and a face on a sub-face: what
 * flips, moves and interior points leave of them is pinned there (bench/quality: most
 * tets under 10 degrees on the CAD models), and only a point on the constraint opens it. */
static tr_status pinned_tets(const tr_sliver_ctx *c, tr_u32buf *out)
{
  const struct tr_mesh *m = c->m;
  double bound = c->insert_bound > TR_SLIVER_INSERT_BOUND ? c->insert_bound : SL_PINNED_BOUND;
  out->n = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (tr_tet_is_free(m, t))
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    int fixed = 0;
    for (int i = 0; i < 4; i++)
      fixed += !c->movable[v[i]];
    if (fixed < 3 || !(tr_sliver_tet_min(c, t, NULL) < bound))
      continue;
    int touches = 0;
    for (int k = 0; k < 4 && !touches; k++) {
      uint32_t f[3] = {v[tr_face_vtx[k][0]], v[tr_face_vtx[k][1]], v[tr_face_vtx[k][2]]};
      touches = tr_sliver_protected(c, f, 3);
    }
    if (touches)
      TR_CHECK(tr_u32buf_push(out, t));
  }
  return TR_OK;
}

/* Slot u holds a real tet the trial made that breaks the promise: an angle under the
 * stage's bound and a ratio over `limit` (measured as the stage's own checks measure). */
static int breaks(const tr_sliver_ctx *c, const tr_sliver_snap *z, uint32_t u, double limit)
{
  const struct tr_mesh *m = c->m;
  if (!tr_tet_is_real(m, u) || !tr_sliver_snap_changed(m, z, u))
    return 0;
  double r, q = tr_sliver_min_dihedral_at(m, m->tv + 4 * (size_t)u, TR_NONE, NULL, &r);
  return !(q >= c->bound) && r > limit;
}

static tr_status broken(const tr_sliver_ctx *c, const tr_sliver_snap *z, double limit,
                        tr_u32buf *out)
{
  out->n = 0;
  for (uint32_t u = 0; u < c->m->nt; u++)
    if (breaks(c, z, u, limit))
      TR_CHECK(tr_u32buf_push(out, u));
  return TR_OK;
}

/* The rounds' steps on the tets in bad (slots), SL_CAP_PASSES times, in the trial's
 * context tc (only the trial's points move); bad = what is left of them. */
static tr_status repair(tr_sliver_ctx *tc, const tr_sliver_snap *z, double limit,
                        void *scratch, tr_u32buf *bad, tr_sliver_stats *st)
{
  tr_u32buf sh = {0}, ball = {0};
  tr_status s = TR_OK;
  uint32_t points = 0;
  for (int pass = 0; pass < SL_CAP_PASSES && bad->n && s == TR_OK; pass++) {
    for (size_t i = 0; i < bad->n && s == TR_OK; i++) {
      uint32_t u = bad->a[i];
      if (!breaks(tc, z, u, limit)) /* an earlier step replaced it */
        continue;
      int done;
      s = tr_sliver_step_tet(tc, u, &sh, &ball, scratch, st, &points, &done);
    }
    if (s == TR_OK)
      s = broken(tc, z, limit, bad);
  }
  tr_u32buf_free(&sh);
  tr_u32buf_free(&ball);
  return s;
}

/* The centroid of tet t and its longest edge. */
static double tet_reach(const struct tr_mesh *m, uint32_t t, double g[3])
{
  const uint32_t *v = m->tv + 4 * (size_t)t;
  double len = 0;
  for (int j = 0; j < 3; j++)
    g[j] = 0;
  for (int i = 0; i < 4; i++) {
    const double *p = m->xyz + 3 * (size_t)v[i];
    for (int j = 0; j < 3; j++)
      g[j] += p[j] / 4;
    for (int k = i + 1; k < 4; k++) {
      const double *q = m->xyz + 3 * (size_t)v[k];
      double d2 = 0;
      for (int j = 0; j < 3; j++)
        d2 += (p[j] - q[j]) * (p[j] - q[j]);
      len = fmax(len, sqrt(d2));
    }
  }
  return len;
}

/* Takes out of list the pinned tets whose centroid lies within f times the two longest
 * edges of one of the broken tets described in at (4 doubles each: centroid, longest
 * edge; nat of them); returns how many went. */
static uint32_t drop_near(const struct tr_mesh *m, tr_u32buf *list, const double *at,
                          size_t nat, double f)
{
  size_t n = 0;
  for (size_t i = 0; i < list->n; i++) {
    double g[3], len = tet_reach(m, list->a[i], g);
    int near = 0;
    for (size_t b = 0; b < nat && !near; b++) {
      const double *w = at + 4 * b;
      double d2 = 0;
      for (int j = 0; j < 3; j++)
        d2 += (g[j] - w[j]) * (g[j] - w[j]);
      near = !(sqrt(d2) > f * (len + w[3])); /* NaN: near */
    }
    if (!near)
      list->a[n++] = list->a[i];
  }
  uint32_t gone = (uint32_t)(list->n - n);
  list->n = n;
  return gone;
}

/* One refinement of the pinned tets in list, kept (*kept = 1, the points it and the repair
 * added in *added, st counting them) when no tet breaks the promise after the repair;
 * else undone exactly, and `at` holds the broken tets (drop_near's form, *nat of them). */
static tr_status trial(tr_sliver_ctx *c, tr_subfaces *sub, const tr_u32buf *list,
                       double limit, void *scratch, tr_sliver_stats *st, int *kept,
                       tr_refine_stats *rs, double **at, size_t *nat)
{
  struct tr_mesh *m = c->m;
  const struct tr_plc *plc = c->keep.plc;
  tr_refine_params rp;
  memset(&rp, 0, sizeof rp);
  /* no ratio bound: the new tets around a split piece are not refined further (file
   * comment); the flips, moves and points of the next round work on them */
  rp.ratio = 0;
  rp.max_volume = c->keep.max_volume;
  rp.keep_edges = c->keep.keep_edges;
  rp.flat_splits = c->keep.flat_splits;
  rp.wedge_grading = c->keep.wedge_grading;
  rp.budget = TR_SLIVER_POINTS(m->nv); /* its own: the interior points may have used theirs */
  rp.sub_exported = 1; /* tr_refine's or a hook's output (tr_sliver_remove) */
  rp.memo = c->memo;
  rp.region_id = c->keep.region_id;
  rp.region_max_volume = c->keep.region_max_volume;
  rp.nregion_bounds = c->keep.nregion_bounds;
  *kept = 0;
  *nat = 0;
  tr_sliver_snap z;
  TR_CHECK(tr_sliver_snap_take(c, sub, &z));
  tr_status s = tr_refine_open_pinned(m, plc, sub, &rp, list->a, (uint32_t)list->n, rs);
  tr_u32buf bad = {0};
  tr_sliver_stats ts = *st;
  if (s == TR_OK && rs->points)
    s = broken(c, &z, limit, &bad);
  if (s == TR_OK && bad.n) {
    tr_sliver_ctx tc;
    s = tr_sliver_trial_ctx(c, sub, z.nv, &tc);
    if (s == TR_OK)
      s = repair(&tc, &z, limit, scratch, &bad, &ts);
    tr_sliver_ctx_free(&tc);
  }
  if (s == TR_OK && bad.n) {
    double *a = realloc(*at, sizeof *a * 4 * bad.n);
    if (!a)
      s = tr_error(TR_ERR_NOMEM, "out of memory for %zu tets", bad.n);
    else
      *at = a;
    for (size_t i = 0; s == TR_OK && i < bad.n; i++)
      a[4 * i + 3] = tet_reach(m, bad.a[i], a + 4 * i);
    *nat = bad.n;
  }
  tr_u32buf_free(&bad);
  if (s == TR_OK && *nat) {
    if (c->memo && c->memo->n > z.nv) /* the trial's vertex ids go to other points */
      c->memo->n = z.nv;
    uint32_t nv0 = z.nv;
    s = tr_sliver_snap_restore(m, sub, &z);
    tr_sliver_forget_from(c, nv0); /* c's other measures hold: no old vertex moved */
    return s;
  }
  tr_sliver_snap_free(&z);
  TR_CHECK(s);
  *st = ts;
  *kept = 1;
  return TR_OK;
}

tr_status tr_sliver_open_pinned(tr_sliver_ctx *c, tr_subfaces *sub, uint32_t npoints,
                                tr_sliver_stats *st, uint64_t *added)
{
  struct tr_mesh *m = c->m;
  *added = 0;
  tr_u32buf list = {0};
  tr_status s = pinned_tets(c, &list);
  if (s != TR_OK || !list.n) {
    tr_u32buf_free(&list);
    return s;
  }
  /* the promise: what the stage started from (no limit when that is not known) */
  const double limit = tr_sliver_ratio_allowed(c, INFINITY);
  void *scratch = tr_sliver_insert_scratch();
  double *at = NULL;
  size_t nat = 0;
  tr_refine_stats rs;
  int kept = 0;
  uint32_t nv0 = m->nv;
  if (!scratch)
    s = tr_error(TR_ERR_NOMEM, "out of memory for the pinned tets' trial");
  for (int k = 0; s == TR_OK && !kept && k < SL_PINNED_TRIES; k++) {
    /* nothing near the broken tets to leave out (the same trial again), or nothing left */
    if (nat && (!drop_near(m, &list, at, nat, (double)(1 << k)) || !list.n))
      break;
    s = trial(c, sub, &list, limit, scratch, st, &kept, &rs, &at, &nat);
  }
  free(at);
  free(scratch);
  tr_u32buf_free(&list);
  if (s != TR_OK || !kept)
    return s;
  tr_sliver_forget_all(c); /* refinement may have changed any tet */
  tr_sliver_forget_flips(c);
  /* the repair's interior points are counted in st already */
  *added = rs.points;
  st->points += rs.points;
  st->on_constraints += rs.on_segments + rs.on_facets;
  if (!rs.points)
    return TR_OK;
  /* the context again: the new sub-faces and their vertices fixed, refinement's new
   * interior points movable */
  uint8_t *was = c->movable;
  c->movable = NULL;
  tr_sliver_ctx keep = *c;
  tr_sliver_ctx_free(c);
  s = tr_sliver_ctx_init(c, m, sub, NULL, npoints, keep.bound);
  if (s == TR_OK)
    for (uint32_t v = 0; v < nv0; v++)
      c->movable[v] &= was[v];
  free(was);
  c->insert_bound = keep.insert_bound;
  /* the next insertion pass: as many interior points as went on the constraints */
  c->point_budget = st->points + rs.points;
  c->keep = keep.keep;
  c->memo = keep.memo;
  c->ratio_start = keep.ratio_start;
  c->sub = keep.sub;
  c->facets = keep.facets;
  c->thin = keep.thin;
  return s;
}
