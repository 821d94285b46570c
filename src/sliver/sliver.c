/* The sliver stage's driver: the constraint sets, the angle measure, the rounds
 * (sliver.h). */
#include "sliver/sliver.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/facets.h"
#include "core/prefetch.h"
#include "refine/quality.h"
#include "refine/refine_impl.h" /* rf_volume_above: the bound decided as refinement does */
#include "refine/refine_stage.h"
#include "tetrec.h"

double tr_sliver_min_dihedral_at(const struct tr_mesh *m, const uint32_t t[4], uint32_t v,
                                 const double x[3], double *ratio)
{
  const double *p[4];
  for (int i = 0; i < 4; i++)
    p[i] = t[i] == v ? x : m->xyz + 3 * (size_t)t[i];
  double r, w, lo;
  if (ratio) {
    lo = tr_tet_min_dihedral(p[0], p[1], p[2], p[3], &r, &w);
    *ratio = isnan(r) ? INFINITY : r;
  } else /* no circumsphere needed */
    lo = tr_dihedral_of_cos(tr_tet_min_cos(p[0], p[1], p[2], p[3], &w));
  if (!(w != 0))
    return 0; /* flat in doubles: the worst there is */
  return isfinite(lo) ? lo : 0;
}

double tr_sliver_min_cos_at(const struct tr_mesh *m, const uint32_t t[4], uint32_t v,
                            const double x[3], int *flat)
{
  const double *p[4];
  for (int i = 0; i < 4; i++)
    p[i] = t[i] == v ? x : m->xyz + 3 * (size_t)t[i];
  double w, lo = tr_tet_min_cos(p[0], p[1], p[2], p[3], &w);
  *flat = !(w != 0);
  return lo;
}

double tr_sliver_angle_of_cos(double lo, int flat)
{
  if (flat)
    return 0; /* as tr_sliver_min_dihedral_at */
  double a = tr_dihedral_of_cos(lo);
  return isfinite(a) ? a : 0;
}

double tr_sliver_ratio_at(const struct tr_mesh *m, const uint32_t t[4], uint32_t v,
                          const double x[3])
{
  const double *p[4];
  for (int i = 0; i < 4; i++)
    p[i] = t[i] == v ? x : m->xyz + 3 * (size_t)t[i];
  double r, w; /* tr_tet_min_dihedral's ratio: tr_tet_shape's */
  tr_tet_shape(p[0], p[1], p[2], p[3], &r, &w, NULL, NULL);
  return isnan(r) ? INFINITY : r;
}

double tr_sliver_min_dihedral(const struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t c,
                              uint32_t d)
{
  uint32_t t[4] = {a, b, c, d};
  return tr_sliver_min_dihedral_at(m, t, TR_NONE, NULL, NULL);
}

double tr_sliver_ratio_allowed(const tr_sliver_ctx *c, double ratio_was)
{
  double r = fmax(c->keep.ratio, ratio_was);
  return c->ratio_start > 0 ? fmin(r, fmax(c->keep.ratio, c->ratio_start)) : r;
}

int tr_sliver_keeps_bounds(const tr_sliver_ctx *c, const uint32_t p[4], uint32_t v,
                           const double x[3], uint32_t region, double ratio, double dih,
                           double ratio_was)
{
  if (c->keep.ratio > 0 && ratio > tr_sliver_ratio_allowed(c, ratio_was) && !(dih >= c->bound))
    return 0;
  double V = tr_refine_region_bound_of(c->keep.region_id, c->keep.region_max_volume,
                                       c->keep.nregion_bounds, c->keep.max_volume, region);
  if (!(V > 0))
    return 1;
  tr_point q[4];
  for (int i = 0; i < 4; i++)
    q[i] = p[i] == v ? tr_pt_d(x) : tr_mesh_point(c->m, p[i]);
  return !rf_volume_above(&q[0], &q[1], &q[2], &q[3], V);
}

int tr_sliver_protected(const tr_sliver_ctx *c, const uint32_t *v, int nv)
{
  uint32_t k[3];
  /* a constraint's vertices are never movable (tr_sliver_ctx_init clears them, and only
   * new interior points become movable), and most faces asked about have a movable one:
   * no key to sort and no probe for them (this function went from 3.7% to 1.7% of
   * cheese.off's CPU) */
  int any = 0;
  for (int i = 0; i < nv; i++)
    any |= c->movable[v[i]];
  if (any) {
#ifndef NDEBUG
    if (nv == 3)
      tr_vtkey_face(v[0], v[1], v[2], k);
    else
      tr_vtkey_edge(v[0], v[1], k);
    assert(tr_vtmap_get(nv == 3 ? &c->faces : &c->edges, (uint32_t)nv, k) == TR_VTMAP_NONE);
#endif
    return 0;
  }
  if (nv == 3) {
    tr_vtkey_face(v[0], v[1], v[2], k);
    return tr_vtmap_get(&c->faces, 3, k) != TR_VTMAP_NONE;
  }
  tr_vtkey_edge(v[0], v[1], k);
  return tr_vtmap_get(&c->edges, 2, k) != TR_VTMAP_NONE;
}

/* One slot's measure; an entry whose ids are all TR_NONE holds nothing (a real tet has
 * real vertices). */
typedef struct sl_shape {
  uint32_t v[4];
  double dih, ratio;
} sl_shape;

struct tr_sliver_shapes {
  sl_shape *e;
  uint32_t cap;
};

/* S's entries up to slot t at least (and m->nt), empty ones added; left as they were
 * when out of memory */
static void shapes_grow(struct tr_sliver_shapes *S, uint32_t t, uint32_t nt)
{
  uint32_t cap = S->cap ? S->cap : 1024;
  while (cap <= t && cap < UINT32_MAX / 2)
    cap *= 2;
  if (cap < nt)
    cap = nt;
  sl_shape *e = realloc(S->e, sizeof *e * (size_t)cap);
  if (e) {
    memset(e + S->cap, 0xff, sizeof *e * (size_t)(cap - S->cap));
    S->e = e;
    S->cap = cap;
  }
}

double tr_sliver_tet_min(const tr_sliver_ctx *c, uint32_t t, double *ratio)
{
  const uint32_t *tv = c->m->tv + 4 * (size_t)t;
  struct tr_sliver_shapes *S = c->shapes;
  if (S && t >= S->cap)
    shapes_grow(S, t, c->m->nt);
  if (!S || t >= S->cap) /* no memory for the cache: measured every time */
    return tr_sliver_min_dihedral_at(c->m, tv, TR_NONE, NULL, ratio);
  sl_shape *e = S->e + t;
  if (e->v[0] != tv[0] || e->v[1] != tv[1] || e->v[2] != tv[2] || e->v[3] != tv[3]) {
    e->dih = tr_sliver_min_dihedral_at(c->m, tv, TR_NONE, NULL, &e->ratio);
    memcpy(e->v, tv, sizeof e->v);
  }
  if (ratio)
    *ratio = e->ratio;
  return e->dih;
}

void tr_sliver_tet_min_prefetch(const tr_sliver_ctx *c, const uint32_t *t, uint32_t n)
{
  const struct tr_sliver_shapes *S = c->shapes;
  for (uint32_t i = 0; S && i < n; i++)
    if (t[i] < S->cap)
      TR_PREFETCH(S->e + t[i]);
}

void tr_sliver_forget(const tr_sliver_ctx *c, uint32_t t)
{
  if (c->shapes && t < c->shapes->cap)
    memset(c->shapes->e[t].v, 0xff, sizeof c->shapes->e[t].v);
}

void tr_sliver_forget_from(const tr_sliver_ctx *c, uint32_t nv)
{
  if (!c->shapes)
    return;
  for (uint32_t t = 0; t < c->shapes->cap; t++) {
    uint32_t *v = c->shapes->e[t].v;
    if (v[0] != TR_NONE && (v[0] >= nv || v[1] >= nv || v[2] >= nv || v[3] >= nv))
      memset(v, 0xff, 4 * sizeof *v);
  }
}

void tr_sliver_forget_all(const tr_sliver_ctx *c)
{
  if (c->shapes && c->shapes->cap)
    memset(c->shapes->e, 0xff, sizeof *c->shapes->e * (size_t)c->shapes->cap);
}

const uint32_t *tr_sliver_shape_keys(const tr_sliver_ctx *c, size_t *stride)
{
  const struct tr_mesh *m = c->m;
  struct tr_sliver_shapes *S = c->shapes;
  if (S && m->nt && S->cap < m->nt)
    shapes_grow(S, m->nt - 1, m->nt);
  if (!S || S->cap < m->nt)
    return NULL;
  for (uint32_t t = 0; t < m->nt; t++) {
    const uint32_t *tv = m->tv + 4 * (size_t)t;
    uint32_t *k = S->e[t].v;
    if (!memcmp(k, tv, sizeof S->e[t].v))
      continue;
    if (tr_tet_is_real(m, t))
      tr_sliver_tet_min(c, t, NULL); /* measured again: the same double */
    else if (tv[0] == TR_NONE || tv[1] == TR_NONE || tv[2] == TR_NONE || tv[3] == TR_NONE)
      memcpy(k, tv, sizeof S->e[t].v); /* an entry that holds nothing */
    else
      return NULL; /* a ghost tet: an entry with its ids would claim a measure */
  }
  *stride = sizeof *S->e / sizeof *S->e[0].v;
  return S->e[0].v;
}

tr_status tr_sliver_touch(tr_sliver_ctx *c, const uint32_t *v, size_t n)
{
  const uint32_t nv = c->m->nv;
  if (c->nvstamp < nv) { /* a new point's id */
    uint64_t want = (uint64_t)nv + nv / 2 + 16;
    uint32_t cap = want > UINT32_MAX ? UINT32_MAX : (uint32_t)want;
    uint64_t *a = realloc(c->vstamp, sizeof *a * (size_t)cap);
    if (!a)
      return tr_error(TR_ERR_NOMEM, "out of memory for %u vertex stamps", cap);
    memset(a + c->nvstamp, 0, sizeof *a * (size_t)(cap - c->nvstamp));
    c->vstamp = a;
    c->nvstamp = cap;
  }
  c->epoch++;
  for (size_t i = 0; i < n; i++)
    c->vstamp[v[i]] = c->epoch;
  return TR_OK;
}

tr_status tr_sliver_touch_tets(tr_sliver_ctx *c, const uint32_t *tets, size_t n)
{
  for (size_t i = 0; i < n; i++)
    TR_CHECK(tr_sliver_touch(c, c->m->tv + 4 * (size_t)tets[i], 4));
  return TR_OK;
}

void tr_sliver_forget_flips(tr_sliver_ctx *c)
{
  if (c->nflip_failed)
    memset(c->flip_failed, 0, sizeof *c->flip_failed * (size_t)c->nflip_failed);
}

void tr_sliver_ctx_free(tr_sliver_ctx *c)
{
  free(c->vstamp);
  free(c->flip_failed);
  tr_vtmap_free(&c->faces);
  tr_vtmap_free(&c->edges);
  if (c->shapes)
    free(c->shapes->e);
  free(c->shapes);
  free(c->movable);
  tr_vtmap_free(&c->failed);
  memset(c, 0, sizeof *c);
}

tr_status tr_sliver_ctx_init(tr_sliver_ctx *c, struct tr_mesh *m, const tr_subfaces *sub,
                             const uint8_t *vkind, uint32_t npoints, double bound)
{
  memset(c, 0, sizeof *c);
  c->m = m;
  c->bound = bound;
  c->insert_bound = TR_SLIVER_INSERT_BOUND;
  c->point_budget = TR_SLIVER_POINTS(m->nv);
  if (sub->n > UINT32_MAX / 3)
    return tr_error(TR_ERR_UNSUPPORTED, "%u sub-faces: too many for the sliver stage", sub->n);
  uint32_t n = sub->n;
  c->movable = malloc(m->nv ? m->nv : 1);
  c->shapes = calloc(1, sizeof *c->shapes);
  c->epoch = 1; /* above every stamp: 0 is "no failure" in flip_failed */
  c->vstamp = calloc(m->nv ? m->nv : 1, sizeof *c->vstamp);
  c->nvstamp = m->nv;
  if (!c->movable || !c->shapes || !c->vstamp)
    return tr_error(TR_ERR_NOMEM, "out of memory for the sliver stage of %u vertices", m->nv);
  TR_CHECK(tr_vtmap_reserve(&c->faces, 3, n));
  TR_CHECK(tr_vtmap_reserve(&c->edges, 2, 3 * n / 2 + 1));
  /* most probes ask about a face or an edge that is no constraint */
  TR_CHECK(tr_vtmap_filter(&c->faces));
  TR_CHECK(tr_vtmap_filter(&c->edges));
  for (uint32_t v = 0; v < m->nv; v++)
    c->movable[v] = v >= npoints && m->v2t[v] != TR_NONE &&
                    (!vkind || vkind[v] == TR_VERTEX_INTERIOR);
  for (uint32_t f = 0; f < n; f++) {
    const uint32_t *s = sub->v + 3 * (size_t)f;
    uint32_t k[3];
    tr_vtkey_face(s[0], s[1], s[2], k);
    TR_CHECK(tr_vtmap_put(&c->faces, 3, k, f, NULL));
    for (int j = 0; j < 3; j++) {
      uint32_t a = s[j], b = s[(j + 1) % 3];
      tr_vtkey_edge(a, b, k);
      TR_CHECK(tr_vtmap_put(&c->edges, 2, k, f, NULL));
      c->movable[a] = 0; /* whatever vkind says: a sub-face vertex lies on a constraint */
    }
  }
  return TR_OK;
}

static tr_status round_of(tr_sliver_ctx *c, const tr_sliver_params *par, tr_sliver_stats *st)
{
  TR_CHECK(tr_sliver_flip_pass(c, st));
  if (par->level >= TR_SLIVER_SMOOTH)
    TR_CHECK(tr_sliver_smooth_pass(c, st));
  if (par->level >= TR_SLIVER_INSERT)
    TR_CHECK(tr_sliver_insert_pass(c, st));
  return TR_OK;
}

tr_status tr_sliver_remove(struct tr_mesh *m, tr_subfaces *sub, const uint8_t *vkind,
                           uint32_t npoints, const tr_sliver_params *par, tr_sliver_stats *st)
{
  memset(st, 0, sizeof *st);
  if (par->level <= TR_SLIVER_OFF)
    return TR_OK;
  TR_CHECK(tr_sliver_sort_tets(m)); /* order.c: walks stay in cache */
  tr_sliver_ctx c;
  tr_status s = tr_sliver_ctx_init(&c, m, sub, vkind, npoints, par->bound);
  if (par->insert_bound > 0)
    c.insert_bound = par->insert_bound;
  c.keep = par->keep;
  uint32_t *region_id = NULL;
  double *region_bound = NULL, least = 0;
  if (s == TR_OK && par->keep.plc) {
    s = tr_refine_region_bounds(par->keep.plc, &region_id, &region_bound,
                                &c.keep.nregion_bounds, &least);
    c.keep.region_id = region_id;
    c.keep.region_max_volume = region_bound;
  }
  /* the facet flips rewrite sub-faces: not under --keep-surface, where each input
   * triangle is one */
  tr_facets facets = {0};
  uint8_t *thin = NULL;
  if (s == TR_OK && !par->keep.keep_surface && par->keep.plc) {
    const struct tr_plc *plc = par->keep.plc;
    s = tr_facets_build(plc, par->keep.keep_edges, &facets);
    c.sub = sub;
    c.facets = &facets;
    thin = malloc(plc->ntris ? plc->ntris : 1);
    tr_quality_thin tq;
    if (s == TR_OK && !thin)
      s = tr_error(TR_ERR_NOMEM, "out of memory for %u triangle flags", plc->ntris);
    if (s == TR_OK)
      tr_facets_thin_triangles(plc, &facets, SL_FACET_THIN_CORNER, thin, &tq);
    c.thin = thin;
  }
  /* the reference of every ratio allowance (tr_sliver_ratio_allowed), fixed here: the
   * shapes measured now are the ones the first flip pass asks for */
  for (uint32_t t = 0; s == TR_OK && c.keep.ratio > 0 && t < m->nt; t++)
    if (tr_tet_is_real(m, t)) {
      double r;
      tr_sliver_tet_min(&c, t, &r);
      c.ratio_start = fmax(c.ratio_start, r);
    }
  tr_refine_memo memo = {0};
  c.memo = &memo;
  uint64_t added = 0;
  for (int r = 0; s == TR_OK && r < par->rounds; r++) {
    tr_sliver_stats before = *st;
    added = st->points;
    s = round_of(&c, par, st);
    added = st->points - added;
    if (!memcmp(&before, st, sizeof before))
      break; /* a round that changed nothing: the next would not either */
  }
  /* the tets left pinned between constraints get points on them, then a round of their
   * own (a plc is needed: refinement's points are placed on its input edges and faces) */
  int pinned_points = c.keep.plc && !c.keep.keep_surface && par->level >= TR_SLIVER_INSERT;
  for (int r = 0; s == TR_OK && pinned_points && r < SL_PINNED_ROUNDS; r++) {
    uint64_t on;
    s = tr_sliver_open_pinned(&c, sub, npoints, st, &on);
    if (s != TR_OK || !on)
      break;
    s = round_of(&c, par, st);
    added = on;
  }
  if (s == TR_OK && added) { /* the last points' tets get their flips and moves too */
    s = tr_sliver_flip_pass(&c, st);
    if (s == TR_OK)
      s = tr_sliver_smooth_pass(&c, st);
    /* then one more round with interior points: a constraint point of the last
     * open_pinned can leave a flat cap next to it that only such a point opens
     * (joint.off: a 0.0003 degree tet, 0.97 degrees after this round), within as many
     * points as went on the constraints */
    if (s == TR_OK && par->level >= TR_SLIVER_INSERT) {
      c.point_budget = st->points + added;
      s = round_of(&c, par, st);
    }
  }
  if (s == TR_OK) /* the worst tets, also those over the bound */
    s = tr_sliver_polish(&c, sub, par->level, st);
  if (s == TR_OK && par->level >= TR_SLIVER_SMOOTH)
    s = tr_sliver_ratio_pass(&c, st);
  tr_sliver_ctx_free(&c);
  tr_refine_memo_free(&memo);
  tr_facets_free(&facets);
  free(thin);
  free(region_id);
  free(region_bound);
  return s;
}
