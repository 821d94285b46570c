/* The refinement loop (refine.h): queues of encroached sub-segments, encroached sub-faces
 * and bad tets, served in that order (Shewchuk 1998: constraints are split before the
 * tets they would otherwise spoil). What one bad tet gets is decided in tet.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "refine/quality.h"
#include "refine/refine_impl.h"

uint64_t tr_refine_default_budget(uint32_t npoints, double domain_volume, double max_volume)
{
  double b = 100.0 * npoints + 100000;
  if (max_volume > 0 && domain_volume > 0)
    b += 20.0 * domain_volume / max_volume;
  /* a point costs about 1.2 KB and 60 us: past the ceiling a default run would fill the
   * memory of most machines for hours (-a 1e-300 asked for 4e9 points); a larger mesh
   * takes an explicit budget */
  double ceiling = 8.0 * npoints > TR_REFINE_BUDGET_CEILING ? 8.0 * npoints
                                                            : TR_REFINE_BUDGET_CEILING;
  return b > ceiling ? (uint64_t)ceiling : (uint64_t)b;
}

double tr_refine_region_bound_of(const uint32_t *ids, const double *bounds, uint32_t n,
                                 double max_volume, uint32_t region)
{
  uint32_t lo = 0, hi = n;
  while (lo < hi) {
    uint32_t mid = lo + (hi - lo) / 2;
    if (ids[mid] < region)
      lo = mid + 1;
    else
      hi = mid;
  }
  if (lo < n && ids[lo] == region && (!(max_volume > 0) || bounds[lo] < max_volume))
    return bounds[lo];
  return max_volume;
}

double tr_refine_tet_bound(const tr_refine_params *par, const struct tr_mesh *m, uint32_t t)
{
  if (!par->nregion_bounds || !m->region)
    return par->max_volume;
  return tr_refine_region_bound_of(par->region_id, par->region_max_volume, par->nregion_bounds,
                                   par->max_volume, m->region[t]);
}

/* Outer and ghost tets are freed; the faces they shared with inner tets become TR_NONE. */
static void discard_outer(struct tr_mesh *m)
{
  for (uint32_t t = 0; t < m->nt; t++)
    if (!tr_tet_is_free(m, t) && (tr_tet_is_ghost(m, t) || (m->flags[t] & TR_TF_OUTER)))
      m->flags[t] |= TR_TF_MARK;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (tr_tet_is_free(m, t) || (m->flags[t] & TR_TF_MARK))
      continue;
    for (int k = 0; k < 4; k++) {
      uint32_t n = TR_NEIG(m, t, k);
      if (n != TR_NONE && (m->flags[n] & TR_TF_MARK))
        m->tn[4 * (size_t)t + k] = TR_NONE;
    }
  }
  for (uint32_t t = 0; t < m->nt; t++)
    if (!tr_tet_is_free(m, t) && (m->flags[t] & TR_TF_MARK)) {
      m->flags[t] = 0;
      tr_tet_free(m, t);
    }
  for (uint32_t v = 0; v < m->nv; v++)
    m->v2t[v] = TR_NONE;
  for (uint32_t t = 0; t < m->nt; t++)
    if (!tr_tet_is_free(m, t))
      for (int i = 0; i < 4; i++)
        m->v2t[m->tv[4 * (size_t)t + i]] = t;
}

static void ctx_free(rf_ctx *c)
{
  rf_rounds_free(c);
  rf_longs_free(&c->longs);
  free(c->vrad);
  free(c->ssfoot);
  free(c->vspace);
  free(c->vh);
  tr_u32buf *b[] = {&c->qseg, &c->qface, &c->qtet, &c->cav, &c->init, &c->bfaces,
                    &c->stack, &c->newsf, &c->tmp, &c->newtets};
  for (size_t i = 0; i < sizeof b / sizeof *b; i++)
    tr_u32buf_free(b[i]);
  free(c->tstate);
  free(c->vcone);
  free(c->vhead);
  tr_u32buf_free(&c->cnext);
  rf_tables_free(c); /* last: it zeroes the whole context */
}

static size_t left(const tr_u32buf *q, size_t head, size_t w)
{
  return (q->n - head) / w;
}

/* Drops the served prefix of a queue once it is most of it. */
static void compact_queue(tr_u32buf *q, size_t *head)
{
  if (*head > 4096 && *head * 2 > q->n) {
    memmove(q->a, q->a + *head, (q->n - *head) * sizeof *q->a);
    q->n -= *head;
    *head = 0;
  }
}

/* The points refinement may add with spacings (par.spacing_radii): 20 per input point
 * plus 10,000, or twice the points a size field is expected to ask for (par.size_points)
 * when that is more, at most half the budget. Reaching it ends the stage (see
 * rf_after_insert). Without the field's share a graded mesh ended its radius-edge
 * refinement a tenth of the way (elephant.off graded 0.005 to 0.03: at 65,500 of 96,000
 * points, 3,396 tets left over the ratio bound). */
static uint64_t spacing_cap(const rf_ctx *c)
{
  uint64_t cap = 20 * (uint64_t)c->plc->npoints + 10000;
  if (cap < 2 * c->par.size_points)
    cap = 2 * c->par.size_points;
  return cap < c->par.budget / 2 ? cap : c->par.budget / 2;
}

/* The points a round (rounds.c) may add: the budget's and, while the spacings or the close
 * splits are on, spacing_cap's, so that the loop switches them off at the same point
 * count as without rounds. */
static uint64_t round_room(const rf_ctx *c)
{
  uint64_t room = c->par.budget > c->st->points ? c->par.budget - c->st->points : 0;
  uint64_t cap = spacing_cap(c);
  if ((c->spacing_on || c->close_splits) && cap - c->st->points < room)
    room = cap > c->st->points ? cap - c->st->points : 0;
  return room;
}

/* Serves the queues until they are empty; the caller seeds them. */
static tr_status run(rf_ctx *c)
{
  struct tr_mesh *m = c->m;
  for (;;) {
    TR_CHECK(rf_subshape_scan(c));
    TR_CHECK(rf_sizing_scan(c));
    if (c->spacing_on && c->st->points >= spacing_cap(c)) {
      c->spacing_on = 0; /* a cascade the spacings let through: see rf_after_insert */
      c->st->spacing_stopped = 1;
      /* ratio refinement ends here; the volume bounds and the size field do not: their
       * tets go on being refined, with the insertion radii (it once stopped with half the
       * tets of a cube under -a 1e-4 over the bound) */
      if (!(c->par.max_volume > 0) && !c->par.nregion_bounds && !c->par.sizing)
        return TR_OK;
      c->volume_only = 1;
    }
    if (c->close_splits && c->st->points >= spacing_cap(c))
      c->close_splits = 0; /* refine_tet */
    if (c->st->points >= c->par.budget && (left(&c->qseg, c->hseg, 1) || left(&c->qface, c->hface, 1) ||
                                            left(&c->qtet, c->htet, 5)))
      return tr_error(TR_ERR_NOMEM,
                      "refinement stopped at its point budget of %llu points (%llu on input "
                      "edges, %llu on input faces, %llu inside) with %zu bad tets and %zu "
                      "encroached constraint pieces still queued: an input angle too small "
                      "for the bound, or a part of the domain much thinner than its faces "
                      "are wide (its faces need points about as close as it is thin)? raise "
                      "--refine-budget, relax -q/-a, or keep the surface as given "
                      "(--keep-surface: interior points only)",
                      (unsigned long long)c->par.budget, (unsigned long long)c->st->on_segments,
                      (unsigned long long)c->st->on_facets, (unsigned long long)c->st->inside,
                      left(&c->qtet, c->htet, 5),
                      left(&c->qseg, c->hseg, 1) + left(&c->qface, c->hface, 1));
    if (c->hseg < c->qseg.n) {
      uint32_t g = c->qseg.a[c->hseg++];
      compact_queue(&c->qseg, &c->hseg);
      if (!c->ssdead[g] && !c->ssnosplit[g])
        TR_CHECK(rf_split_segment(c, g));
    } else if (c->hface < c->qface.n) {
      uint32_t f = c->qface.a[c->hface++];
      compact_queue(&c->qface, &c->hface);
      if (!c->sfdead[f] && !c->sfnosplit[f])
        TR_CHECK(rf_split_facet(c, f));
    } else if (rf_round_wanted(c) && round_room(c) >= RF_ROUND_LEAST) {
      TR_CHECK(rf_round(c, round_room(c)));
      if (c->htet > 5 * 4096 && c->htet * 2 > c->qtet.n) {
        memmove(c->qtet.a, c->qtet.a + c->htet, (c->qtet.n - c->htet) * sizeof *c->qtet.a);
        c->qtet.n -= c->htet;
        c->htet = 0;
      }
    } else if (c->htet < c->qtet.n) {
      uint32_t it[5];
      memcpy(it, c->qtet.a + c->htet, sizeof it);
      c->htet += 5;
      if (c->htet > 5 * 4096 && c->htet * 2 > c->qtet.n) {
        memmove(c->qtet.a, c->qtet.a + c->htet, (c->qtet.n - c->htet) * sizeof *c->qtet.a);
        c->qtet.n -= c->htet;
        c->htet = 0;
      }
      if (it[0] < m->nt && !tr_tet_is_free(m, it[0]) &&
          !memcmp(m->tv + 4 * (size_t)it[0], it + 1, 4 * sizeof *it) && rf_tet_bad(c, it[0]))
        TR_CHECK(rf_refine_tet(c, it[0]));
    } else
      return TR_OK;
  }
}

static tr_status seed_all(rf_ctx *c)
{
  for (uint32_t t = 0; t < c->m->nt; t++)
    if (!tr_tet_is_free(c->m, t))
      TR_CHECK(rf_push_tet(c, t));
  return TR_OK;
}

static void ctx_setup(rf_ctx *c, struct tr_mesh *m, const struct tr_plc *plc,
                      const tr_refine_params *par, tr_refine_stats *st)
{
  memset(st, 0, sizeof *st);
  memset(c, 0, sizeof *c);
  c->m = m;
  c->plc = plc;
  c->par = *par;
  c->st = st;
  c->split_seg = TR_NONE;
  if (!c->par.budget)
    c->par.budget = tr_refine_default_budget(plc->npoints, 0, 0);
}

/* Flat sub-faces (flat.c): one scan of what the loop left, then the loop again for the
 * splits it queued and the tets they make; none once the loop stopped at its point cap
 * (the loop would go on with the insertion radii, and merged_facet_notch.off's facet
 * splits then ran to the budget). */
static tr_status flat_pass(rf_ctx *c)
{
  if (c->st->spacing_stopped)
    return TR_OK;
  int pushed;
  TR_CHECK(rf_flat_scan(c, &pushed));
  return pushed ? run(c) : TR_OK;
}

/* A tet of the sliver stage's list: the pieces its own vertices encroach, else the
 * sub-faces it lies on (a flat tet on a sub-face is opened only by a point on it; the
 * split point, the sub-face's circumcentre, goes to a sub-segment it encroaches first,
 * as any facet split does). */
static tr_status open_pinned(rf_ctx *c, uint32_t t)
{
  int pushed;
  TR_CHECK(rf_own_encroached(c, t, &pushed));
  if (pushed)
    return TR_OK;
  const uint32_t *v = c->m->tv + 4 * (size_t)t;
  for (int k = 0; k < 4; k++) {
    uint32_t f = rf_subface_of(c, v[tr_face_vtx[k][0]], v[tr_face_vtx[k][1]], v[tr_face_vtx[k][2]]);
    if (f != TR_NONE && !c->sfnosplit[f] && !rf_protected(c, 0, f, v[k]))
      TR_CHECK(tr_u32buf_push(&c->qface, f));
  }
  return TR_OK;
}

tr_status tr_refine_open_pinned(struct tr_mesh *m, const struct tr_plc *plc, tr_subfaces *sub,
                                const tr_refine_params *par, const uint32_t *tets,
                                uint32_t ntets, tr_refine_stats *st)
{
  discard_outer(m); /* none after tr_refine; a mesh given directly may have them */
  rf_ctx c;
  ctx_setup(&c, m, plc, par, st);
  tr_status s = rf_subs_init(&c, sub);
  for (uint32_t i = 0; s == TR_OK && i < ntets; i++)
    if (tets[i] < m->nt && !tr_tet_is_free(m, tets[i]))
      s = open_pinned(&c, tets[i]);
  if (s == TR_OK)
    s = run(&c);
  if (s == TR_OK && par->flat_splits)
    s = flat_pass(&c); /* most flat sub-faces come from the splits above (flat.c) */
  if (s == TR_ERR_NOMEM && st->points >= c.par.budget) {
    tr_error_clear();
    s = TR_OK; /* the budget is the sliver stage's: what was split stays */
  }
  if (s == TR_OK)
    s = rf_subs_export(&c, sub);
  ctx_free(&c);
  return s;
}

/* The sliver polish's hook (sliver/caps.c): one named piece is split, a sub-segment
 * (nv = 2) or a sub-face (nv = 3), as an encroached one would be, and the cascade it
 * starts runs within par->budget (reaching it is no error). Nothing when the piece is
 * no constraint or may not be split. */
tr_status tr_refine_split_piece(struct tr_mesh *m, const struct tr_plc *plc, tr_subfaces *sub,
                                const tr_refine_params *par, const uint32_t *v, int nv,
                                tr_refine_stats *st)
{
  discard_outer(m);
  rf_ctx c;
  ctx_setup(&c, m, plc, par, st);
  tr_status s = rf_subs_init(&c, sub);
  if (s == TR_OK && nv == 2) {
    uint32_t g = rf_subseg_of(&c, v[0], v[1]);
    if (g != TR_NONE && !c.ssnosplit[g])
      s = tr_u32buf_push(&c.qseg, g);
  } else if (s == TR_OK && nv == 3) {
    uint32_t f = rf_subface_of(&c, v[0], v[1], v[2]);
    if (f != TR_NONE && !c.sfnosplit[f])
      s = tr_u32buf_push(&c.qface, f);
  }
  if (s == TR_OK)
    s = run(&c);
  if (s == TR_ERR_NOMEM && st->points >= c.par.budget) {
    tr_error_clear();
    s = TR_OK;
  }
  if (s == TR_OK && st->points)
    s = rf_subs_export(&c, sub);
  ctx_free(&c);
  return s;
}

tr_status tr_refine(struct tr_mesh *m, const struct tr_plc *plc, tr_subfaces *sub,
                    const tr_refine_params *par, tr_refine_stats *st)
{
  tr_refine_stats local;
  if (!st)
    st = &local;
  memset(st, 0, sizeof *st);
  if (plc->nsegs)
    return tr_error(TR_ERR_UNSUPPORTED, "quality refinement of inputs with free segments is "
                    "not supported yet (%u segments)", plc->nsegs);
  struct timespec t0;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t0);
  discard_outer(m);
  rf_ctx c;
  ctx_setup(&c, m, plc, par, st);
  tr_status s = rf_subs_init(&c, sub);
  /* off by default: on CGAL's models it costs more CPU and tets than it gains
   * (subshape.c) */
  c.shape_on = par->subface_ratio > 0;
  c.spacing_on = par->spacing_radii;
  c.close_splits = 1;
  c.rounds_on = 1; /* rounds.c: not in the sliver stage's hooks */
  c.shape_bound = par->subface_ratio;
  if (s == TR_OK)
    s = rf_sizing_init(&c);
  if (s == TR_OK && par->keep_surface) { /* the input triangles stay the boundary faces */
    memset(c.ssnosplit, 1, c.nss);
    memset(c.sfnosplit, 1, c.nsf);
  }
  if (s == TR_OK)
    s = seed_all(&c);
  if (s == TR_OK)
    s = run(&c);
  if (s == TR_OK && par->flat_splits)
    s = flat_pass(&c);
  if (s == TR_ERR_NOMEM && par->partial && st->points >= c.par.budget) {
    /* the loop stops between insertions, so the mesh holds every constraint: an
     * encroached piece left unsplit is still a chain of mesh edges or faces */
    if (par->verbose >= 1)
      fprintf(stderr, "tetrec: warning: %s; the mesh made so far is kept (sliver removal "
              "adds no point to it)\n", tr_last_error());
    tr_error_clear();
    st->budget_reached = 1;
    s = TR_OK;
  }
  if (s == TR_OK)
    s = rf_subs_export(&c, sub);
  if (par->verbose >= 2) {
    struct timespec t1;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t1);
    fprintf(stderr, "tetrec: refinement CPU (every thread): %.3f s\n",
            (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec));
  }
  if (par->verbose >= 1 && st->rounds)
    fprintf(stderr, "tetrec: refinement rounds: %llu, %llu points inserted in them on %d "
            "threads, %llu of their tets left to the serial loop\n",
            (unsigned long long)st->rounds, (unsigned long long)st->round_points,
            par->threads > 1 ? par->threads : 1, (unsigned long long)st->round_serial);
  if (par->verbose >= 1 && (s == TR_OK || s == TR_ERR_NOMEM))
    fprintf(stderr,
            "tetrec: refinement added %llu points (%llu on edges, %llu on facets, %llu "
            "inside; %llu times pieces queued to grade a small-angle wedge); bad tets left: %llu "
            "for small input angles, %llu whose circumcentre lies too close to a new vertex, "
            "%llu otherwise; %u input edges inside exactly "
            "planar facets merged away (--keep-edges keeps them)%s%s\n",
            (unsigned long long)st->points, (unsigned long long)st->on_segments,
            (unsigned long long)st->on_facets, (unsigned long long)st->inside,
            (unsigned long long)st->wedge_splits, (unsigned long long)st->skipped_small_angle,
            (unsigned long long)st->skipped_close,
            (unsigned long long)st->skipped_other, st->merged_edges,
            st->spacing_stopped ? "; the radius-edge refinement stopped at the point cap of "
                                  "--spacing-radii (volume bounds still met)" : "",
            par->keep_surface ? "; --keep-surface: no point on the surface, so a bad tet whose "
                                "circumcentre encroaches it is left" : "");
  ctx_free(&c);
  return s;
}
