/* The refinement stage as the pipeline calls it: option checks, the default budget, the
 * statistics rows (refine.h, quality.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core/memtrim.h"
#include "delaunay/delaunay.h"
#include "refine/quality.h"
#include "refine/refine_stage.h"
#include "refine/sizing.h"

tr_status tr_refine_check_options(const tr_options *opt)
{
  /* D is the sliver stage's target: it can only be worked towards by flips, moves and
   * points (small input angles force smaller ones), so it needs that stage, and above
   * the regular tet's 70.53 degrees no tet meets it */
  if (opt->quality_min_dihedral != 0 &&
      !(opt->quality_min_dihedral > 0 && opt->quality_min_dihedral <= 70))
    return tr_error(TR_ERR_USAGE, "minimum dihedral target %g: it must be in (0, 70] degrees "
                    "(the regular tet's angle is 70.53)", opt->quality_min_dihedral);
  if (opt->quality_min_dihedral != 0 && opt->optimize <= 0)
    return tr_error(TR_ERR_USAGE, "a minimum dihedral target (--quality R/D) is worked "
                    "towards by sliver removal, which --optimize 0 turns off");
  if (opt->quality_ratio != 0 && !(opt->quality_ratio >= 1 && isfinite(opt->quality_ratio)))
    return tr_error(TR_ERR_USAGE, "radius-edge bound %g: it must be at least 1 (the regular "
                    "tet has 0.61; bounds below 1 cannot be met in general)",
                    opt->quality_ratio);
  if (opt->quality_subface_ratio != 0 &&
      !(opt->quality_subface_ratio >= 1 && isfinite(opt->quality_subface_ratio)))
    return tr_error(TR_ERR_USAGE, "sub-face radius-edge bound %g: it must be at least 1",
                    opt->quality_subface_ratio);
  if (opt->quality_subface_ratio != 0 && opt->keep_surface)
    return tr_error(TR_ERR_USAGE, "--subface-quality splits boundary triangles, which "
                    "--keep-surface keeps as they are");
  if (opt->max_volume != 0 && !(opt->max_volume > 0 && isfinite(opt->max_volume)))
    return tr_error(TR_ERR_USAGE, "maximum volume %g: it must be positive", opt->max_volume);
  return TR_OK;
}

typedef struct {
  uint32_t id;
  double bound;
} region_bound;

static int cmp_region_bound(const void *pa, const void *pb)
{
  const region_bound *a = pa, *b = pb;
  return a->id < b->id ? -1 : a->id > b->id;
}

tr_status tr_refine_region_bounds(const struct tr_plc *plc, uint32_t **ids, double **bounds,
                                  uint32_t *n_out, double *least)
{
  /* Per-region bounds of the region points (src/outer/points.c gave each one's cell the
   * attribute as its region id), sorted by id, the smallest where an id repeats */
  region_bound *rb = malloc(sizeof *rb * (plc->nregions ? plc->nregions : 1));
  uint32_t *id = malloc(sizeof *id * (plc->nregions ? plc->nregions : 1));
  double *bound = malloc(sizeof *bound * (plc->nregions ? plc->nregions : 1));
  if (!rb || !id || !bound) {
    free(rb);
    free(id);
    free(bound);
    return tr_error(TR_ERR_NOMEM, "out of memory for %u region bounds", plc->nregions);
  }
  uint32_t nb = 0, n = 0;
  for (uint32_t i = 0; i < plc->nregions; i++)
    if (plc->region_maxvol[i] > 0) {
      rb[nb].id = (uint32_t)plc->region_attr[i];
      rb[nb++].bound = plc->region_maxvol[i];
      if (!(*least > 0) || plc->region_maxvol[i] < *least)
        *least = plc->region_maxvol[i];
    }
  qsort(rb, nb, sizeof *rb, cmp_region_bound);
  for (uint32_t i = 0; i < nb; i++)
    if (n && id[n - 1] == rb[i].id) {
      if (rb[i].bound < bound[n - 1])
        bound[n - 1] = rb[i].bound;
    } else {
      id[n] = rb[i].id;
      bound[n++] = rb[i].bound;
    }
  free(rb);
  *ids = id;
  *bounds = bound;
  *n_out = n;
  return TR_OK;
}

/* par's volume bounds: opt->max_volume and plc's region points' (none when plc is NULL;
 * *id and *bound, which par points to, are the caller's to free); *least = the smallest
 * of them (0: none). */
static tr_status volume_bounds(const struct tr_plc *plc, const tr_options *opt,
                               tr_refine_params *par, uint32_t **id, double **bound,
                               double *least)
{
  par->max_volume = opt->max_volume;
  *least = opt->max_volume;
  *id = NULL;
  *bound = NULL;
  if (!plc)
    return TR_OK;
  uint32_t n;
  TR_CHECK(tr_refine_region_bounds(plc, id, bound, &n, least));
  par->region_id = *id;
  par->region_max_volume = *bound;
  par->nregion_bounds = n;
  return TR_OK;
}

tr_status tr_refine_stage(struct tr_mesh *m, const struct tr_plc *plc, tr_subfaces *sub,
                          const tr_options *opt, int keep_hull, uint64_t *points,
                          uint64_t *merged, uint64_t *budget_reached)
{
  TR_CHECK(tr_refine_check_options(opt));
  if (keep_hull)
    return tr_error(TR_ERR_UNSUPPORTED, "quality refinement of an open surface meshed within "
                    "its convex hull is not supported yet");
  tr_refine_params par;
  memset(&par, 0, sizeof par);
  par.ratio = opt->quality_ratio;
  par.subface_ratio = opt->quality_subface_ratio;
  par.verbose = opt->verbose;
  /* under --keep-surface no facet is merged either: its input edges are boundary edges */
  par.keep_edges = opt->keep_edges || opt->keep_surface;
  par.keep_surface = opt->keep_surface;
  par.flat_splits = 1; /* flat.c, which weighs its cost; after the pinned splits too under
                          --subface-quality (tr_sliver_bounds) */
  par.wedge_grading = 1; /* angles.c */
  par.spacing_radii = opt->refine_spacing_radii;
  par.partial = opt->refine_partial;
  /* rounds.c: the mesh is the same for any count */
  par.threads = tr_delaunay_thread_count(opt->threads > 0 ? opt->threads : 0);
  par.round_min = opt->refine_rounds;
  /* the smallest of all bounds sizes the default budget */
  double least, *bound;
  uint32_t *id;
  tr_sizing field;
  memset(&field, 0, sizeof field);
  double *vh = NULL;
  if (plc && plc->vsize) {
    tr_status s = tr_sizing_build(plc, opt->threads, &field);
    if (s == TR_OK && !(vh = malloc(sizeof *vh * (m->nv ? m->nv : 1))))
      s = tr_error(TR_ERR_NOMEM, "out of memory for the sizes of %u vertices", m->nv);
    if (s != TR_OK) {
      tr_sizing_free(&field);
      return s;
    }
    uint32_t hint = 0;
    for (uint32_t v = 0; v < m->nv; v++)
      vh[v] = v < plc->npoints ? plc->vsize[v] : tr_sizing_at(&field, m->xyz + 3 * (size_t)v, &hint);
    par.sizing = &field;
    par.vsize = vh;
    par.nvsize = m->nv;
  }
  tr_status vs = volume_bounds(plc, opt, &par, &id, &bound, &least);
  if (vs != TR_OK) {
    tr_sizing_free(&field);
    free(vh);
    return vs;
  }
  /* each tet holds at most its bound: the bounds alone ask for at least `need` tets. A
   * tet whose edges are at most h has a volume of at most h^3 / (6 sqrt 2), the regular
   * tet's, so the field asks for at least 6 sqrt 2 times the integral of h^-3 */
  double vol = 0, need = 0, need_size = 0;
  for (uint32_t t = 0; t < m->nt; t++)
    if (tr_tet_is_real(m, t) && !(m->flags[t] & TR_TF_OUTER)) {
      const uint32_t *v = m->tv + 4 * (size_t)t;
      double r, w, d[6];
      tr_tet_shape(m->xyz + 3 * (size_t)v[0], m->xyz + 3 * (size_t)v[1],
                   m->xyz + 3 * (size_t)v[2], m->xyz + 3 * (size_t)v[3], &r, &w, d, NULL);
      vol += w;
      double b = tr_refine_tet_bound(&par, m, t), nb = b > 0 ? w / b : 0, ns = 0;
      if (vh && vh[v[0]] > 0 && vh[v[1]] > 0 && vh[v[2]] > 0 && vh[v[3]] > 0) {
        double h4[4] = {vh[v[0]], vh[v[1]], vh[v[2]], vh[v[3]]};
        ns = 6 * sqrt(2) * tr_sizing_inverse_cube(w, h4);
      }
      need += nb > ns ? nb : ns;
      need_size += ns;
    }
  /* with a field, the default budget counts the tets it and the volume bounds ask for as
   * tr_refine_default_budget counts a volume bound's (20 points per bound volume) */
  uint64_t budget = opt->refine_budget ? opt->refine_budget
                    : vh ? tr_refine_default_budget(plc->npoints, need, 1)
                         : tr_refine_default_budget(plc->npoints, vol, least);
  /* about 5.5 tets per point in a refined mesh */
  par.size_points = (uint64_t)fmin(4 * need_size / 5.5, 1e15);
  if (vh && opt->verbose >= 2)
    fprintf(stderr, "tetrec: the size field asks for about %.3g tets (at least %.3g; point "
            "budget %llu)\n", 4 * need_size, need_size, (unsigned long long)budget);
  /* a refined mesh has about 6 tets per point (8 taken, to refuse only what cannot fit):
   * what the budget cannot reach is refused now, not after hours of refinement */
  if (need / 8 > (double)budget) {
    free(id);
    free(bound);
    tr_sizing_free(&field);
    free(vh);
    char what[64];
    if (need_size / 8 > (double)budget)
      snprintf(what, sizeof what, "the size field (--sizing)");
    else if (opt->max_volume > 0)
      snprintf(what, sizeof what, "-a %g%s", opt->max_volume,
               par.nregion_bounds ? " with the regions' bounds" : "");
    else
      snprintf(what, sizeof what, "the regions' volume bounds");
    return tr_error(TR_ERR_NOMEM, "%s asks for at least %.3g tets in a domain of volume %.6g, "
                    "about %.3g points: over the point budget of %llu points "
                    "(--refine-budget); relax the bound or raise the budget", what, need, vol,
                    need / 6, (unsigned long long)budget);
  }
  par.budget = budget;
  tr_refine_stats rs;
  tr_status s = tr_refine(m, plc, sub, &par, &rs);
  *points = rs.points;
  *merged = rs.merged_edges;
  *budget_reached = (uint64_t)rs.budget_reached;
  free(id);
  free(bound);
  tr_sizing_free(&field);
  free(vh);
  /* refinement's queues and scratch are gone: their pages back to the system before
   * the sliver stage allocates (core/memtrim.h) */
  tr_release_free_memory();
  return s;
}

void tr_quality_stats(const struct tr_mesh *m, tr_stats *s)
{
  tr_quality q;
  tr_quality_measure(m, &q);
  s->min_dihedral = q.min_dihedral;
  s->max_dihedral = q.max_dihedral;
  s->max_radius_edge = q.max_radius_edge;
  s->tets_dihedral_below_5 = q.below5;
  s->tets_dihedral_below_10 = q.below10;
  memcpy(s->dihedral_histogram, q.dihedral_hist, sizeof s->dihedral_histogram);
  memcpy(s->radius_edge_histogram, q.ratio_hist, sizeof s->radius_edge_histogram);
}

tr_status tr_refine_count_over(const struct tr_mesh *m, const struct tr_plc *plc,
                               const tr_options *opt, tr_refine_over *over)
{
  tr_refine_params par;
  memset(&par, 0, sizeof par);
  double least, *bound;
  uint32_t *id;
  TR_CHECK(volume_bounds(plc, opt, &par, &id, &bound, &least));
  tr_refine_over c = {0, 0, 0};
  for (uint32_t t = 0; t < m->nt; t++)
    if (tr_tet_is_real(m, t) && !(m->flags[t] & TR_TF_OUTER)) {
      const uint32_t *v = m->tv + 4 * (size_t)t;
      double r, w;
      tr_tet_shape(m->xyz + 3 * (size_t)v[0], m->xyz + 3 * (size_t)v[1],
                   m->xyz + 3 * (size_t)v[2], m->xyz + 3 * (size_t)v[3], &r, &w, NULL, NULL);
      double b = tr_refine_tet_bound(&par, m, t);
      int bad_ratio = opt->quality_ratio > 0 && r > opt->quality_ratio;
      int bad_volume = b > 0 && w > b;
      c.ratio += (uint64_t)bad_ratio;
      c.volume += (uint64_t)bad_volume;
      c.either += (uint64_t)(bad_ratio || bad_volume);
    }
  free(id);
  free(bound);
  *over = c;
  return TR_OK;
}
