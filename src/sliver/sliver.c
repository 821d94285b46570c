/* The sliver stage's driver: the constraint sets, the angle measure, the rounds
 * (sliver.h). */
#include "sliver/sliver.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "refine/quality.h"
#include "refine/refine_impl.h" /* rf_volume_above: the bound decided as refinement does */
#include "tetrec.h"

double tr_sliver_min_dihedral_at(const struct tr_mesh *m, const uint32_t t[4], uint32_t v,
                                 const double x[3], double *ratio)
{
  const double *p[4];
  for (int i = 0; i < 4; i++)
    p[i] = t[i] == v ? x : m->xyz + 3 * (size_t)t[i];
  double r, w, lo = tr_tet_min_dihedral(p[0], p[1], p[2], p[3], &r, &w);
  if (ratio)
    *ratio = isnan(r) ? INFINITY : r;
  if (!(w != 0))
    return 0; /* flat in doubles: the worst there is */
  return isfinite(lo) ? lo : 0;
}

double tr_sliver_min_dihedral(const struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t c,
                              uint32_t d)
{
  uint32_t t[4] = {a, b, c, d};
  return tr_sliver_min_dihedral_at(m, t, TR_NONE, NULL, NULL);
}

/* The volume bound of region r: the smaller of max_volume and its region points'. */
static double volume_bound(const tr_sliver_bounds *k, uint32_t r)
{
  double b = k->max_volume;
  for (uint32_t i = 0; k->plc && i < k->plc->nregions; i++)
    if (k->plc->region_maxvol[i] > 0 && (uint32_t)k->plc->region_attr[i] == r &&
        (!(b > 0) || k->plc->region_maxvol[i] < b))
      b = k->plc->region_maxvol[i];
  return b;
}

int tr_sliver_keeps_bounds(const tr_sliver_ctx *c, const uint32_t p[4], uint32_t v,
                           const double x[3], uint32_t region, double ratio, double dih,
                           double ratio_was)
{
  if (c->keep.ratio > 0 && ratio > fmax(c->keep.ratio, ratio_was) && !(dih >= c->bound))
    return 0;
  double V = volume_bound(&c->keep, region);
  if (!(V > 0))
    return 1;
  tr_point q[4];
  for (int i = 0; i < 4; i++)
    q[i] = p[i] == v ? tr_pt_d(x) : tr_mesh_point(c->m, p[i]);
  return !rf_volume_above(&q[0], &q[1], &q[2], &q[3], V);
}

int tr_sliver_protected(const tr_sliver_ctx *c, const uint32_t *v, int nv)
{
  if (nv == 3) {
    uint32_t k[3] = {v[0], v[1], v[2]};
    tr_sort3(k);
    return bsearch(k, c->faces, c->nfaces, 3 * sizeof *k, tr_cmp_face_key) != NULL;
  }
  uint32_t k[2] = {v[0] < v[1] ? v[0] : v[1], v[0] < v[1] ? v[1] : v[0]};
  return bsearch(k, c->edges, c->nedges, 2 * sizeof *k, tr_cmp_edge_key) != NULL;
}

/* Sorts n keys of w ids each and drops repeats; returns the number kept. */
static uint32_t sort_unique(uint32_t *k, uint32_t n, size_t w,
                            int (*cmp)(const void *, const void *))
{
  if (!n)
    return 0;
  qsort(k, n, w * sizeof *k, cmp);
  uint32_t o = 1;
  for (uint32_t i = 1; i < n; i++)
    if (cmp(k + w * i, k + w * (o - 1)) != 0)
      memmove(k + w * o++, k + w * i, w * sizeof *k);
  return o;
}

void tr_sliver_ctx_free(tr_sliver_ctx *c)
{
  free(c->faces);
  free(c->edges);
  free(c->movable);
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
  size_t n = sub->n;
  c->faces = malloc(3 * sizeof *c->faces * (n ? n : 1));
  c->edges = malloc(6 * sizeof *c->edges * (n ? n : 1));
  c->movable = malloc(m->nv ? m->nv : 1);
  if (!c->faces || !c->edges || !c->movable)
    return tr_error(TR_ERR_NOMEM, "out of memory for the constraints of %zu sub-faces", n);
  for (uint32_t v = 0; v < m->nv; v++)
    c->movable[v] = v >= npoints && m->v2t[v] != TR_NONE &&
                    (!vkind || vkind[v] == TR_VERTEX_INTERIOR);
  for (size_t f = 0; f < n; f++) {
    const uint32_t *s = sub->v + 3 * f;
    memcpy(c->faces + 3 * f, s, 3 * sizeof *s);
    tr_sort3(c->faces + 3 * f);
    for (int j = 0; j < 3; j++) {
      uint32_t a = s[j], b = s[(j + 1) % 3];
      c->edges[6 * f + 2 * (size_t)j] = a < b ? a : b;
      c->edges[6 * f + 2 * (size_t)j + 1] = a < b ? b : a;
      c->movable[a] = 0; /* whatever vkind says: a sub-face vertex lies on a constraint */
    }
  }
  c->nfaces = sort_unique(c->faces, (uint32_t)n, 3, tr_cmp_face_key);
  c->nedges = sort_unique(c->edges, (uint32_t)(3 * n), 2, tr_cmp_edge_key);
  return TR_OK;
}

tr_status tr_sliver_remove(struct tr_mesh *m, const tr_subfaces *sub, const uint8_t *vkind,
                           uint32_t npoints, const tr_sliver_params *par, tr_sliver_stats *st)
{
  memset(st, 0, sizeof *st);
  if (par->level <= TR_SLIVER_OFF)
    return TR_OK;
  tr_sliver_ctx c;
  tr_status s = tr_sliver_ctx_init(&c, m, sub, vkind, npoints, par->bound);
  if (par->insert_bound > 0)
    c.insert_bound = par->insert_bound;
  c.keep = par->keep;
  uint64_t added = 0;
  for (int r = 0; s == TR_OK && r < par->rounds; r++) {
    tr_sliver_stats before = *st;
    s = tr_sliver_flip_pass(&c, st);
    if (s == TR_OK && par->level >= TR_SLIVER_SMOOTH)
      s = tr_sliver_smooth_pass(&c, st);
    added = st->points;
    if (s == TR_OK && par->level >= TR_SLIVER_INSERT)
      s = tr_sliver_insert_pass(&c, st);
    added = st->points - added;
    if (!memcmp(&before, st, sizeof before))
      break; /* a round that changed nothing: the next would not either */
  }
  if (s == TR_OK && added) { /* the last points' tets get their flips and moves too */
    s = tr_sliver_flip_pass(&c, st);
    if (s == TR_OK)
      s = tr_sliver_smooth_pass(&c, st);
  }
  tr_sliver_ctx_free(&c);
  return s;
}
