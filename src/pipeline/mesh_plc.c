/* tr_mesh_plc: validate -> smooth -> Delaunay -> edge recovery -> facet recovery ->
 * outer removal and regions -> flips of tets flat in doubles (src/output/flatflip.h) ->
 * compact output -> rounding of Steiner points to doubles (src/output/round.h), with the
 * seed paper's Table 14 statistics.
 *
 * Rounding runs on the compact store, after outer removal: its tets are exactly the ones
 * written, so the tets that are discarded do not constrain where a Steiner point's double
 * may move, and its xyz is the array the writers print. */
#define _DEFAULT_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "delaunay/delaunay.h"
#include "input/validate.h"
#include "outer/color.h"
#include "output/flatflip.h"
#include "output/round.h"
#include "pipeline.h"
#include "refine/refine_stage.h"
#include "smooth/smooth.h"

static tr_status copy_plc(const tr_plc *in, tr_plc **out)
{
  TR_CHECK(tr_plc_create(out));
  tr_plc *p = *out;
  tr_status st = tr_plc_set(p, in->xyz, in->npoints, in->tris, in->ntris, in->tri_marker);
  if (st == TR_OK && in->nsegs) {
    p->segs = malloc(sizeof *p->segs * 2 * (size_t)in->nsegs);
    if (!p->segs)
      st = tr_error(TR_ERR_NOMEM, "out of memory copying %u segments", in->nsegs);
    else {
      memcpy(p->segs, in->segs, sizeof *p->segs * 2 * (size_t)in->nsegs);
      p->nsegs = in->nsegs;
    }
  }
  if (st != TR_OK) {
    tr_plc_destroy(p);
    *out = NULL;
  } else
    p->validated = in->validated;
  return st;
}

static void say(const tr_options *opt, int level, const char *what, double secs)
{
  if (opt->verbose >= level)
    fprintf(stderr, "tetrec: %-22s %.3f s\n", what, secs);
}

tr_status tr_mesh_plc_flags(const tr_plc *plc, const tr_options *optin, tr_mesh **out,
                            tr_stats *stats, tr_plc **used, unsigned flags)
{
  tr_error_clear();
  double t0 = tr_pipeline_now();
  tr_options opt;
  if (optin)
    opt = *optin;
  else
    tr_options_default(&opt);
  tr_stats local;
  if (!stats)
    stats = &local;
  memset(stats, 0, sizeof *stats);
  if (out)
    *out = NULL;
  if (used)
    *used = NULL;
  if (!plc || !out)
    return tr_error(TR_ERR_USAGE, "tr_mesh_plc: NULL argument");
  tr_plc *p = NULL;
  struct tr_mesh *m = NULL, *res = NULL;
  uint32_t *edges = NULL, ne = 0, nopen = 0, nmulti = 0, nreg = 0;
  uint8_t *sides = NULL;
  tr_subfaces sub;
  memset(&sub, 0, sizeof sub);
  double secs[2];
  tr_status st = copy_plc(plc, &p);
  /* Validation works on a copy: the caller's PLC is const. One the caller validated
   * (tetrec mesh does, to print its report) is not validated twice, unless it was
   * validated as open and this call wants a closed surface. */
  if (st == TR_OK && !(p->validated == 1 || (p->validated == 2 && opt.allow_open)))
    st = tr_plc_validate(p, &opt);
  if (st == TR_OK && p->ntris == 0 && p->nsegs == 0)
    st = tr_error(TR_ERR_INPUT, "the input has no triangles to recover");
  double t1 = tr_pipeline_now();
  say(&opt, 2, "validation", t1 - t0);
  if (st == TR_OK) {
    stats->surface_nodes = p->npoints;
    stats->surface_facets = p->ntris;
  }
  if (st == TR_OK && opt.smooth) {
    st = tr_smooth_surface(p, &stats->surface_swaps);
    say(&opt, 2, "surface smoothing", tr_pipeline_now() - t1);
  }
  if (st == TR_OK)
    st = tr_pipeline_edges(p, &edges, &ne, &nopen, &nmulti);
  double t2 = tr_pipeline_now();
  if (st == TR_OK)
    st = tr_delaunay_build(p->xyz, p->npoints, &m);
  double t3 = tr_pipeline_now();
  say(&opt, 2, "Delaunay", t3 - t2);
  if (st == TR_OK && m->ndup)
    st = tr_error(TR_ERR_INTERNAL, "duplicate points survived validation");
  if (st == TR_OK) {
    st = tr_pipeline_recover(m, p, edges, ne, &sub, stats, secs);
    stats->recovery_seconds = secs[0] + secs[1];
    say(&opt, 2, "edge recovery", secs[0]);
    say(&opt, 2, "facet recovery", secs[1]);
  }
  double t4 = tr_pipeline_now();
  int keep_hull = opt.allow_open && (nopen > 0 || p->nsegs > 0);
  /* Not a union of closed 2-manifold shells (internal facets, cracks): which side of each
   * triangle is in the domain comes from the input's cell analysis, since FLAGE votes
   * cannot tell a region bounded only by internal facets from a cavity. */
  if (st == TR_OK && !keep_hull && (nopen > 0 || nmulti > 0)) {
    if (!(sides = malloc(p->ntris ? p->ntris : 1)))
      st = tr_error(TR_ERR_NOMEM, "out of memory for %u triangle sides", p->ntris);
    else
      st = tr_input_side_domains(p, sides);
  }
  if (st == TR_OK)
    st = tr_outer_color(m, &sub, keep_hull, sides, &nreg);
  free(sides);
  sides = NULL;
  /* Quality refinement (off by default): inner tets only, before the flips and rounding. */
  if (st == TR_OK && (opt.quality_ratio != 0 || opt.max_volume != 0 || opt.quality_min_dihedral != 0))
    st = tr_refine_stage(m, p, &sub, &opt, keep_hull, &stats->points_added_for_quality);
  /* Before compaction: the flips need the sub-faces, which are in m's numbering. */
  if (st == TR_OK)
    st = tr_round_flip_flat(m, &sub, p, &stats->rounding_flips);
  if (st == TR_OK && stats->rounding_flips && opt.verbose >= 2)
    fprintf(stderr, "tetrec: %llu flips took away tets flat in doubles\n",
            (unsigned long long)stats->rounding_flips);
  if (st == TR_OK)
    st = tr_pipeline_compact(m, &res);
  if (st == TR_OK && (flags & TR_PIPE_KEEP_EXACT)) {
    /* The caller writes the exact points: the repair would only move doubles nobody
     * prints, and where no doubles exist it searches for its whole budget (35 s of the
     * 37 s of Chazelle's polyhedron moved by ulps, against 1.3 s of recovery). */
    uint64_t flat = tr_round_nearest(res);
    if (flat && opt.verbose >= 1)
      fprintf(stderr,
              "tetrec: warning: %llu tets are flat or inverted with the Steiner points at "
              "their nearest doubles: only the exact output is valid\n",
              (unsigned long long)flat);
  } else if (st == TR_OK) {
    st = tr_round_steiner(res, opt.round_budget, &stats->rounding_repairs);
    if (st == TR_OK && stats->rounding_repairs && opt.verbose >= 1)
      fprintf(stderr,
              "tetrec: %llu Steiner points moved off their nearest double so that every "
              "tet is positive in doubles (exact positions: --exact)\n",
              (unsigned long long)stats->rounding_repairs);
  }
  say(&opt, 2, "outer removal, output", tr_pipeline_now() - t4);
  if (st == TR_OK && tr_mesh_num_tets(res) == 0)
    st = tr_error(TR_ERR_INPUT, "the surface encloses no tetrahedron (is it inside out?)");
  if (st == TR_OK) {
    stats->volume_nodes = res->nv;
    stats->volume_elements = tr_mesh_num_tets(res);
    tr_quality_stats(res, stats);
    if (opt.verbose >= 2)
      fprintf(stderr, "tetrec: %u regions\n", nreg);
  }
  tr_pipeline_subfaces_free(&sub);
  free(edges);
  tr_mesh_destroy(m);
  stats->total_seconds = tr_pipeline_now() - t0;
  struct rusage ru;
  if (getrusage(RUSAGE_SELF, &ru) == 0)
    stats->peak_memory_bytes = (uint64_t)ru.ru_maxrss * 1024u; /* Linux: kilobytes */
  if (st != TR_OK) {
    tr_mesh_destroy(res);
    tr_plc_destroy(p);
    return st;
  }
  *out = res;
  if (used)
    *used = p;
  else
    tr_plc_destroy(p);
  return TR_OK;
}

tr_status tr_mesh_plc_ex(const tr_plc *plc, const tr_options *opt, tr_mesh **out,
                         tr_stats *stats, tr_plc **used)
{
  return tr_mesh_plc_flags(plc, opt, out, stats, used, 0);
}

tr_status tr_mesh_plc(const tr_plc *plc, const tr_options *opt, tr_mesh **out, tr_stats *stats)
{
  return tr_mesh_plc_ex(plc, opt, out, stats, NULL);
}
