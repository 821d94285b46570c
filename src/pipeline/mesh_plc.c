/* tr_mesh_plc: validate -> smooth -> Delaunay -> edge recovery -> facet recovery ->
 * outer removal and regions -> flips of tets flat in doubles (src/output/flatflip.h) ->
 * compact output -> rounding of Steiner points to doubles (src/output/round.h), with the
 * seed paper's Table 14 statistics.
 *
 * Rounding runs on the compact store, after outer removal: its tets are exactly the ones
 * written, so the tets that are discarded do not constrain where a Steiner point's double
 * may move, and its xyz is the array the writers print. */
#define _DEFAULT_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "delaunay/delaunay.h"
#include "input/options.h"
#include "input/validate.h"
#include "outer/color.h"
#include "outer/points.h"
#include "output/flatflip.h"
#include "output/round.h"
#include "recover_edges/recover_edges.h"
#include "pipeline.h"
#include "refine/quality.h"
#include "refine/refine_stage.h"
#include "resolve/resolve.h"
#include "sliver/sliver.h"
#include "simplify/simplify.h"
#include "smooth/smooth.h"

/* The caller's size field (tr_options.sizing) onto p, its copy of the caller's PLC, before
 * validation: the merges of duplicates carry it. */
static tr_status attach_sizing(tr_plc *p, const tr_options *opt)
{
  if (!opt->sizing)
    return opt->nsizing ? tr_error(TR_ERR_USAGE, "tr_options.sizing is NULL with nsizing %u",
                                   opt->nsizing)
                        : TR_OK;
  if (opt->nsizing != p->npoints)
    return tr_error(TR_ERR_USAGE, "tr_options.sizing has %u values for %u points: one target "
                    "edge length per input point", opt->nsizing, p->npoints);
  for (uint32_t i = 0; i < p->npoints; i++)
    if (!(opt->sizing[i] >= 0) || !isfinite(opt->sizing[i]))
      return tr_error(TR_ERR_USAGE, "tr_options.sizing[%u] is %g: a target edge length is > 0, "
                      "or 0 for no bound at that point", i, opt->sizing[i]);
  double *h = malloc(sizeof *h * (p->npoints ? p->npoints : 1));
  if (!h)
    return tr_error(TR_ERR_NOMEM, "out of memory for %u point sizes", p->npoints);
  memcpy(h, opt->sizing, sizeof *h * p->npoints);
  free(p->vsize);
  p->vsize = h;
  return TR_OK;
}

/* A stage's time, and the process's peak memory so far: the stage that raises it is the
 * one to look at when a mesh does not fit (issue 48: bytes per tet). */
static void say(const tr_options *opt, int stage, double secs)
{
  if (opt->verbose < 2)
    return;
  struct rusage ru;
  if (getrusage(RUSAGE_SELF, &ru) == 0)
    fprintf(stderr, "tetrec: %-22s %.3f s  peak %.1f MB\n", tr_stage_name(stage), secs,
            (double)ru.ru_maxrss / 1024); /* Linux: kilobytes */
  else
    fprintf(stderr, "tetrec: %-22s %.3f s\n", tr_stage_name(stage), secs);
}

/* An input point on no triangle is meshed as an isolated vertex when it lies in the
 * domain; outside it cannot be, and leaving it out silently would look like a lost
 * vertex. */
static void warn_dropped_points(const struct tr_mesh *res, const tr_plc *p)
{
  uint8_t *in = calloc(p->npoints ? p->npoints : 1, 1);
  if (!in)
    return; /* a warning only: no memory for it is no reason to fail the mesh */
  const struct tr_mesh_attrs *a = res->attrs;
  for (uint32_t v = 0; v < res->nv; v++) {
    uint32_t i = a && a->vkind ? (a->vkind[v] == TR_VERTEX_INPUT ? a->vindex[v] : UINT32_MAX) : v;
    if (i < p->npoints)
      in[i] = 1;
  }
  uint32_t n = 0, first = 0;
  for (uint32_t i = p->npoints; i-- > 0;)
    if (!in[i])
      n++, first = i;
  if (n)
    fprintf(stderr, "tetrec: warning: %u input point%s on no triangle lie%s outside the domain "
            "and %s not in the mesh (the first: point %u at %.17g %.17g %.17g)\n", n,
            n > 1 ? "s" : "", n > 1 ? "" : "s", n > 1 ? "are" : "is", first,
            p->xyz[3 * (size_t)first], p->xyz[3 * (size_t)first + 1],
            p->xyz[3 * (size_t)first + 2]);
  free(in);
}


/* Progress at a stage boundary, unless an earlier step failed. */
#define PROGRESS(stage, fraction)                                 \
  do {                                                            \
    if (st == TR_OK)                                              \
      st = tr_pipeline_progress(&opt, (stage), (fraction));       \
  } while (0)

/* What the pipeline does not do yet on a surface with exact points (--resolve's rational
 * corners, docs/resolve.md): said by name, never a mesh made on their doubles. */
static tr_status exact_modes(const tr_plc *p, const tr_options *opt)
{
  const char *mode = NULL;
  if (opt->surface_tolerance != 0)
    mode = "--surface-tolerance";
  else if (p->nholes)
    mode = "hole points";
  else if (opt->allow_open)
    mode = "--allow-open";
  if (!mode)
    return TR_OK;
  return tr_error(TR_ERR_UNSUPPORTED, "%s: --resolve: %u vertices of the solid's boundary are "
                  "rational points that are no doubles; they are meshed exactly, but %s "
                  "on such a surface is not implemented yet (docs/resolve.md)",
                  p->source ? p->source : "input", p->nxq, mode);
}

/* tr_pipeline_suppress, and the origins (vkind, from the recovery) of the boundary Steiner
 * points it relocated set to interior. A point on an input edge or triangle is a vertex of
 * that triangle's sub-faces (they tile it); a relocated point is a vertex of none after
 * (removed ones are in no tet and compaction drops them). */
static tr_status suppress(struct tr_mesh *m, tr_subfaces *sub, const tr_plc *p,
                          const tr_options *opt, int keep_hull, unsigned flags,
                          tr_stats *stats, uint8_t *vkind)
{
  uint32_t nv = m->nv;
  uint8_t *on = vkind ? calloc(nv ? nv : 1, 1) : NULL;
  if (vkind && !on)
    return tr_error(TR_ERR_NOMEM, "out of memory for %u vertex marks", nv);
  for (size_t i = 0; on && i < 3 * (size_t)sub->n; i++)
    on[sub->v[i]] = 1;
  tr_status st = tr_pipeline_suppress(m, sub, p, opt, keep_hull, flags, stats);
  if (st == TR_OK && on) {
    for (size_t i = 0; i < 3 * (size_t)sub->n; i++)
      on[sub->v[i]] |= 2;
    for (uint32_t v = p->npoints; v < nv; v++)
      if (on[v] == 1)
        vkind[v] = TR_VERTEX_INTERIOR;
  }
  free(on);
  return st;
}

tr_status tr_mesh_plc_flags(const tr_plc *plc, const tr_options *optin, tr_mesh **out,
                            tr_stats *statsout, tr_plc **used, unsigned flags)
{
  tr_error_clear();
  double t0 = tr_pipeline_now();
  tr_options opt;
  tr_options_read(optin, &opt);
  if (opt.keep_steiner)
    flags |= TR_PIPE_KEEP_STEINER;
  if (opt.keep_exact)
    flags |= TR_PIPE_KEEP_EXACT;
  tr_stats full, *stats = &full;
  memset(&full, 0, sizeof full);
  if (out)
    *out = NULL;
  if (used)
    *used = NULL;
  if (!plc || !out)
    return tr_error(TR_ERR_USAGE, "tr_mesh_plc: NULL argument");
  tr_plc *p = NULL;
  struct tr_mesh *m = NULL, *res = NULL;
  uint32_t *edges = NULL, ne = 0, nopen = 0, nmulti = 0, nreg = 0;
  uint8_t *sides = NULL, *vkind = NULL;
  uint32_t *vindex = NULL, *subtet = NULL, nsubtet = 0, *subhint = NULL;
  tr_subfaces sub;
  memset(&sub, 0, sizeof sub);
  double secs[2];
  double *stage = stats->stage_seconds;
  tr_status st = tr_pipeline_progress(&opt, TR_STAGE_VALIDATE, 0);
  if (st == TR_OK && (opt.optimize < TR_SLIVER_OFF || opt.optimize > TR_SLIVER_INSERT))
    st = tr_error(TR_ERR_USAGE, "optimize level %d: it is 0 (off), 1 (flips), 2 (flips "
                  "and smoothing) or 3 (flips, smoothing and new points)", opt.optimize);
  if (st == TR_OK)
    st = tr_plc_copy(plc, &p);
  if (st == TR_OK)
    st = attach_sizing(p, &opt);
  if (st == TR_OK && opt.resolve)
    st = tr_resolve_replace(&p, &opt, opt.verbose >= 2);
  /* Validation works on a copy: the caller's PLC is const. One the caller validated
   * (tetrec mesh does, to print its report) is not validated twice, unless it was
   * validated as open and this call wants a closed surface. */
  if (st == TR_OK && !(p->validated == 1 || (p->validated == 2 && opt.allow_open)))
    st = tr_plc_validate(p, &opt);
  if (p) {
    /* the caller's validation times when it validated, else this call's */
    stage[TR_STAGE_SELFINT] = p->validate_seconds[1];
    stage[TR_STAGE_NESTING] = p->validate_seconds[2];
    stage[TR_STAGE_VALIDATE] = p->validate_seconds[0] - p->validate_seconds[1] -
                               p->validate_seconds[2];
    if (stage[TR_STAGE_VALIDATE] < 0)
      stage[TR_STAGE_VALIDATE] = 0;
  }
  if (st == TR_OK && p->ntris == 0 && p->nsegs == 0)
    st = tr_error(TR_ERR_INPUT, "the input has no triangles to recover");
  if (st == TR_OK && p->nxq)
    st = exact_modes(p, &opt);
  /* --surface-tolerance: a simplified surface within the proven bound replaces p */
  if (st == TR_OK && opt.surface_tolerance != 0) {
    double ts = tr_pipeline_now();
    tr_simp_stats ss;
    st = tr_simplify_surface(&p, opt.surface_tolerance, &opt, &ss);
    stats->surface_tolerance_bound = ss.bound;
    stats->surface_collapses = ss.collapses;
    stats->surface_flips = ss.flips;
    stats->surface_tolerance_seconds = tr_pipeline_now() - ts;
    stage[TR_STAGE_VALIDATE] += stats->surface_tolerance_seconds;
    if (st == TR_OK && opt.verbose >= 2)
      fprintf(stderr, "tetrec: surface tolerance: %llu collapses, %llu flips, %u triangles "
              "left, bound %.3g of the diagonal, %.3f s\n", (unsigned long long)ss.collapses,
              (unsigned long long)ss.flips, p->ntris, ss.bound, stats->surface_tolerance_seconds);
  }
  PROGRESS(TR_STAGE_VALIDATE, 1);
  say(&opt, TR_STAGE_VALIDATE, stage[TR_STAGE_VALIDATE]);
  say(&opt, TR_STAGE_SELFINT, stage[TR_STAGE_SELFINT]);
  say(&opt, TR_STAGE_NESTING, stage[TR_STAGE_NESTING]);
  if (st == TR_OK) {
    stats->surface_nodes = p->npoints;
    stats->surface_facets = p->ntris;
    stats->hole_points = p->nholes, stats->region_points = p->nregions;
    stats->cavities = p->ncavities, stats->inclusions = p->ninclusions;
  }
  double t1 = tr_pipeline_now();
  /* --keep-surface: the input triangles are the output's faces, so no diagonal swaps */
  if (opt.smooth && !opt.keep_surface && !(p && p->nxq)) {
    PROGRESS(TR_STAGE_SMOOTH, 0);
    if (st == TR_OK)
      st = tr_smooth_surface(p, &stats->surface_swaps);
    PROGRESS(TR_STAGE_SMOOTH, 1);
    stage[TR_STAGE_SMOOTH] = tr_pipeline_now() - t1;
    say(&opt, TR_STAGE_SMOOTH, stage[TR_STAGE_SMOOTH]);
  }
  double t2 = tr_pipeline_now();
  PROGRESS(TR_STAGE_DELAUNAY, 0);
  if (st == TR_OK)
    st = tr_pipeline_edges(p, &edges, &ne, &nopen, &nmulti);
  if (st == TR_OK)
    st = opt.threads < 0
             ? tr_error(TR_ERR_USAGE, "tr_options.threads is %d (0: every core, or N > 0)",
                        opt.threads)
             : tr_delaunay_build_threads(p->xyz, p->npoints - p->nxq, opt.threads, &m);
  if (st == TR_ERR_DEGENERATE && p->nxq) { /* the doubles alone span no tet */
    tr_error_clear();
    st = tr_delaunay_build_exact(p->xyz, p->npoints - p->nxq, p->xq + (p->npoints - p->nxq),
                                 p->nxq, &m);
  } else if (st == TR_OK && p->nxq)
    st = tr_delaunay_insert_exact(m, p->xq + (p->npoints - p->nxq), p->nxq);
  PROGRESS(TR_STAGE_DELAUNAY, 1);
  double t3 = tr_pipeline_now();
  stage[TR_STAGE_DELAUNAY] = t3 - t2;
  say(&opt, TR_STAGE_DELAUNAY, t3 - t2);
  if (st == TR_OK && m->ndup)
    st = tr_error(TR_ERR_INTERNAL, "duplicate points survived validation");
  /* the coplanar diagonals the mesh chose among cocircular points (src/recover_edges/
   * surfswap.c); not in the paper's algorithm, and not where every input edge is to stay
   * an edge (--keep-edges) */
  double tswap = tr_pipeline_now();
  if (st == TR_OK && opt.smooth && !opt.keep_surface && !opt.keep_edges &&
      opt.recovery != 1 && !p->nxq) {
    uint64_t n2 = 0;
    st = tr_surface_swaps_to_mesh(p, m, edges, ne, &n2);
    if (st == TR_OK && n2) {
      stats->surface_swaps += n2;
      free(edges);
      edges = NULL;
      st = tr_pipeline_edges(p, &edges, &ne, &nopen, &nmulti);
    }
  }
  double swap_secs = tr_pipeline_now() - tswap; /* counted as edge recovery's */
  if (st == TR_OK) {
    st = tr_pipeline_recover(m, p, edges, ne, &sub, stats, secs, &opt, &vkind, &vindex,
                             &subhint);
    secs[0] += swap_secs;
    stats->recovery_seconds = secs[0] + secs[1];
    stage[TR_STAGE_EDGES] = secs[0];
    stage[TR_STAGE_FACETS] = secs[1];
    say(&opt, TR_STAGE_EDGES, secs[0]);
    say(&opt, TR_STAGE_FACETS, secs[1]);
  }
  double t4 = tr_pipeline_now();
  PROGRESS(TR_STAGE_COLOR, 0);
  int keep_hull = p && opt.allow_open && (nopen > 0 || p->nsegs > 0);
  /* Not a union of closed 2-manifold shells (internal facets, cracks): which side of each
   * triangle is in the domain comes from the input's cell analysis, since FLAGE votes
   * cannot tell a region bounded only by internal facets from a cavity. */
  if (st == TR_OK && !keep_hull && (nopen > 0 || nmulti > 0)) {
    if (!(sides = malloc(p->ntris ? p->ntris : 1)))
      st = tr_error(TR_ERR_NOMEM, "out of memory for %u triangle sides", p->ntris);
    else
      st = tr_input_side_domains(p, sides);
  }
  if (st == TR_OK && !(subtet = malloc(sizeof *subtet * (sub.n ? sub.n : 1))))
    st = tr_error(TR_ERR_NOMEM, "out of memory for %u sub-face tets", sub.n);
  if (st == TR_OK) {
    st = tr_outer_color_ex(m, &sub, keep_hull, sides, &nreg, subtet, subhint,
                           subhint ? sub.n : 0);
    nsubtet = sub.n;
  }
  if (st == TR_OK) /* hole and region points: their cells emptied or named */
    st = tr_outer_points(m, p, opt.verbose, &nreg);
  free(sides);
  sides = NULL;
  free(subhint); /* the mesh changes from here on */
  subhint = NULL;
  PROGRESS(TR_STAGE_COLOR, 1);
  double t44 = tr_pipeline_now();
  stage[TR_STAGE_COLOR] = t44 - t4;
  say(&opt, TR_STAGE_COLOR, t44 - t4);
  PROGRESS(TR_STAGE_SUPPRESS, 0);
  if (st == TR_OK)
    st = suppress(m, &sub, p, &opt, keep_hull, flags, stats, vkind);
  PROGRESS(TR_STAGE_SUPPRESS, 1);
  double t45 = tr_pipeline_now();
  stage[TR_STAGE_SUPPRESS] = t45 - t44;
  say(&opt, TR_STAGE_SUPPRESS, t45 - t44);
  /* Quality refinement (off by default): inner tets only, before the flips and rounding. */
  int region_bounds = 0; /* a region point with a maximum volume */
  for (uint32_t i = 0; p && i < p->nregions; i++)
    region_bounds |= p->region_maxvol[i] > 0;
  int refined = opt.quality_ratio != 0 || opt.max_volume != 0 ||
                opt.quality_min_dihedral != 0 || region_bounds || (p && p->vsize);
  if (st == TR_OK && refined) {
    PROGRESS(TR_STAGE_REFINE, 0);
    uint32_t nv0 = m->nv;
    if (st == TR_OK)
      st = tr_refine_stage(m, p, &sub, &opt, keep_hull, &stats->points_added_for_quality,
                           &stats->input_edges_merged, &stats->refine_budget_reached);
    if (st == TR_OK)
      st = tr_pipeline_origins_extend(m, p, &sub, edges, ne, nv0, &vkind, &vindex);
    /* sliver removal: refinement bounds the radius-edge ratio, which slivers meet */
    if (st == TR_OK && opt.optimize > 0) {
      /* a dihedral target D raises both bounds to D where it is above them */
      double dt = opt.quality_min_dihedral;
      /* at the point budget (refine_partial) none is left for sliver points: flips and
       * moves only (slab_1e-9 once took 100 s more adding 67k points to a mesh of flat
       * tets that refinement had left) */
      int level = stats->refine_budget_reached && opt.optimize > TR_SLIVER_SMOOTH
                      ? TR_SLIVER_SMOOTH
                      : opt.optimize;
      tr_sliver_params sp = {level, fmax(TR_SLIVER_BOUND, dt), TR_SLIVER_ROUNDS,
                             fmax(TR_SLIVER_INSERT_BOUND, dt),
                             {opt.quality_ratio, opt.max_volume, p, opt.keep_edges,
                              opt.quality_subface_ratio > 0, opt.keep_surface, 1, NULL, NULL, 0}};
      tr_sliver_stats ss;
      uint32_t nv1 = m->nv;
      st = tr_sliver_remove(m, &sub, vkind, p->npoints, &sp, &ss);
      if (st == TR_OK) /* its points: interior ones, and those on constraints under
                          pinned tets */
        st = tr_pipeline_origins_extend(m, p, &sub, edges, ne, nv1, &vkind, &vindex);
      /* net: a last-resort cavity may take out interior points (they leave the mesh) */
      stats->points_added_for_sliver = ss.points > ss.swallowed ? ss.points - ss.swallowed : 0;
      stats->sliver_flips = ss.flips23 + ss.flips32 + ss.flips44 + ss.flipsn + ss.facet_flips;
      stats->sliver_points_smoothed = ss.smoothed;
      if (st == TR_OK && opt.verbose >= 2)
        fprintf(stderr, "tetrec: sliver removal: %llu flips (2-3 %llu, 3-2 %llu, 4-4 %llu, "
                "n %llu), %llu interior points moved, %llu points added\n",
                (unsigned long long)stats->sliver_flips, (unsigned long long)ss.flips23,
                (unsigned long long)ss.flips32, (unsigned long long)ss.flips44,
                (unsigned long long)ss.flipsn, (unsigned long long)ss.smoothed,
                (unsigned long long)ss.points);
    }
    PROGRESS(TR_STAGE_REFINE, 1);
    stage[TR_STAGE_REFINE] = tr_pipeline_now() - t45;
    say(&opt, TR_STAGE_REFINE, stage[TR_STAGE_REFINE]);
  }
  double t5 = tr_pipeline_now();
  PROGRESS(TR_STAGE_ROUND, 0);
  /* Before compaction: the flips need the sub-faces, which are in m's numbering. */
  uint32_t nv_flips = m ? m->nv : 0; /* m is NULL once a stage before failed */
  if (st == TR_OK)
    st = tr_round_flip_flat(m, &sub, p, opt.max_volume, !stats->refine_budget_reached,
                            &stats->rounding_flips);
  if (st == TR_OK && m->nv > nv_flips) /* centroids of tets the flips made over -a */
    st = tr_pipeline_origins_extend(m, p, &sub, edges, ne, nv_flips, &vkind, &vindex);
  if (st == TR_OK && stats->rounding_flips && opt.verbose >= 2)
    fprintf(stderr, "tetrec: %llu flips took away tets flat in doubles\n",
            (unsigned long long)stats->rounding_flips);
  if (st == TR_OK) {
    tr_compact_in cin = {&sub, p->tri_marker, vkind, vindex, edges, ne, subtet, nsubtet};
    st = tr_pipeline_compact(m, &cin, &res);
  }
  if (st == TR_OK && (flags & TR_PIPE_KEEP_EXACT)) {
    /* The caller writes the exact points: the repair would only move doubles nobody
     * prints, and where no doubles exist it searches for its whole budget (35 s of the
     * 37 s of Chazelle's polyhedron moved by ulps, against 1.3 s of recovery). */
    uint64_t flat = tr_round_count_nonpositive(res, NULL);
    if (flat && opt.verbose >= 1)
      fprintf(stderr,
              "tetrec: warning: %llu tets are flat or inverted with the Steiner points at "
              "their unrepaired doubles: only the exact output is valid\n",
              (unsigned long long)flat);
  } else if (st == TR_OK) {
    st = tr_round_steiner(res, opt.round_budget, &stats->rounding_repairs);
    /* No double position exists for some Steiner point (a window under an ulp between
     * tets on a facet bumpy at subnormal scale): new vertices at the centroids of the
     * tets still flat (flatflip.h), then compaction and the repair once more. Only on
     * this failure, so every mesh the repair handles is written as before. */
    uint64_t ninserted = 0;
    uint32_t nv_ins = m->nv;
    if (st == TR_ERR_INVALID_MESH) {
      tr_status st2 = tr_pipeline_uncompact_steiner(m, res);
      if (st2 == TR_OK)
        st2 = tr_round_insert_flat(m, &sub, p, &ninserted);
      if (st2 != TR_OK)
        st = st2;
    }
    if (ninserted) {
      st = tr_pipeline_origins_extend(m, p, &sub, edges, ne, nv_ins, &vkind, &vindex);
      if (st == TR_OK && opt.verbose >= 2)
        fprintf(stderr, "tetrec: %llu points added where no double position was left\n",
                (unsigned long long)ninserted);
      tr_mesh_destroy(res);
      res = NULL;
      tr_compact_in cin = {&sub, p->tri_marker, vkind, vindex, edges, ne, subtet, nsubtet};
      if (st == TR_OK)
        st = tr_pipeline_compact(m, &cin, &res);
      if (st == TR_OK)
        st = tr_round_steiner(res, opt.round_budget, &stats->rounding_repairs);
    }
    if (st == TR_OK && stats->rounding_repairs && opt.verbose >= 1)
      fprintf(stderr,
              "tetrec: %llu Steiner points moved off their nearest double so that every "
              "tet is positive in doubles (exact positions: --exact)\n",
              (unsigned long long)stats->rounding_repairs);
    /* How far the written doubles lie from the constraints their exact points are on */
    uint32_t v;
    if (st == TR_OK)
      st = tr_mesh_double_deviation(res, p, &stats->double_deviation, &v);
    if (st == TR_OK && stats->double_deviation > 0x1p-40) {
      if (opt.strict_doubles)
        st = tr_error(TR_ERR_INVALID_MESH, "vertex %u is written %.3g of the bounding box "
                      "diagonal off the edge or facet it lies on (above 2^-40; "
                      "--strict-doubles, tr_options.strict_doubles)", v,
                      stats->double_deviation);
      else if (opt.verbose >= 1)
        fprintf(stderr, "tetrec: warning: vertex %u is written %.3g of the bounding box "
                "diagonal off the edge or facet it lies on exactly (above 2^-40; --exact "
                "writes it exactly)\n", v, stats->double_deviation);
    }
  }
  PROGRESS(TR_STAGE_ROUND, 1);
  stage[TR_STAGE_ROUND] = tr_pipeline_now() - t5;
  say(&opt, TR_STAGE_ROUND, stage[TR_STAGE_ROUND]);
  if (st == TR_OK && tr_mesh_num_tets(res) == 0)
    st = tr_error(TR_ERR_INPUT, "the surface encloses no tetrahedron (is it inside out?)");
  if (st == TR_OK && opt.verbose >= 1)
    warn_dropped_points(res, p);
  if (st == TR_OK) {
    stats->volume_nodes = res->nv;
    stats->volume_elements = tr_mesh_num_tets(res);
    double t6 = tr_pipeline_now();
    /* measured for whoever shows them: a caller's stats, or the notes below on a
     * dihedral target and on refinement (a tenth of a smooth model's keep-surface run
     * went to figures nobody asked for) */
    int quality = (statsout && !(flags & TR_PIPE_NO_QUALITY)) ||
                  (opt.verbose >= 1 && (opt.quality_min_dihedral > 0 || refined));
    if (quality)
      tr_quality_stats(res, stats);
    stage[TR_STAGE_STATS] = tr_pipeline_now() - t6;
    say(&opt, TR_STAGE_STATS, stage[TR_STAGE_STATS]);
    /* a dihedral target is worked towards, not guaranteed (input angles, tets pinned
     * between constraints): what is left under it is said, never passed over */
    double dt = opt.quality_min_dihedral;
    if (dt > 0 && stats->min_dihedral < dt && opt.verbose >= 1)
      fprintf(stderr, "tetrec: warning: %llu of %llu tets keep a dihedral angle under the "
              "target %g degrees (the smallest %.3g): sliver removal could not lift them\n",
              (unsigned long long)tr_quality_count_below(res, dt),
              (unsigned long long)stats->volume_elements, dt, stats->min_dihedral);
    tr_refine_over over;
    if (refined && (st = tr_refine_count_over(res, p, &opt, &over)) == TR_OK)
      stats->tets_over_bounds = over.either;
    /* the tets that input triangles with a small corner leave thin, and where: what the
     * user can change (refinement keeps every input triangle) */
    tr_quality_thin thin;
    if (st == TR_OK && stats->tets_dihedral_below_10 &&
        (st = tr_quality_thin_input(res, p, opt.keep_edges || opt.keep_surface, 10, 10,
                                    &thin)) == TR_OK) {
      stats->tets_dihedral_below_10_on_thin_input = thin.below_on_thin;
      stats->thin_input_triangles = thin.triangles;
      /* under --surface-tolerance p is the simplified surface: its triangles are the
       * ones meant, and the advice is a larger tolerance */
      int simplified = opt.surface_tolerance != 0;
      if (refined && thin.below_on_thin && opt.verbose >= 1)
        fprintf(stderr, "tetrec: note: %llu of the %llu tets under 10 degrees stand on %s "
                "triangles with a corner under 10 degrees (%llu such triangles; the thinnest, "
                "triangle %u of input face %u, has %.3g degrees at vertex %u): %s, and the "
                "boundary faces inside such a triangle are thin too; %s\n",
                (unsigned long long)thin.below_on_thin,
                (unsigned long long)stats->tets_dihedral_below_10,
                simplified ? "simplified surface" : "input", (unsigned long long)thin.triangles,
                thin.thinnest, p->tri_source ? p->tri_source[thin.thinnest] : thin.thinnest,
                thin.thinnest_angle, thin.thinnest_vertex,
                simplified ? "tetrec keeps every triangle of the simplified surface"
                           : "tetrec keeps every input triangle",
                simplified ? "a larger --surface-tolerance may remove more of them"
                           : "a surface without such triangles (or --surface-tolerance) gives "
                             "better tets");
    }
    if (opt.verbose >= 2)
      fprintf(stderr, "tetrec: %u regions\n", nreg);
  }
  tr_pipeline_subfaces_free(&sub);
  free(edges);
  free(vkind);
  free(vindex);
  free(subtet);
  free(subhint);
  tr_mesh_destroy(m);
  stats->total_seconds = tr_pipeline_now() - t0;
  struct rusage ru;
  if (getrusage(RUSAGE_SELF, &ru) == 0)
    stats->peak_memory_bytes = (uint64_t)ru.ru_maxrss * 1024u; /* Linux: kilobytes */
  stats->bytes_per_tet = stats->volume_elements ? (double)stats->peak_memory_bytes /
                                                     (double)stats->volume_elements
                                               : 0;
  if (statsout) {
    /* no more than the caller's struct holds (ABI growth, include/tetrec.h) */
    size_t n = statsout->size == 0 || statsout->size > sizeof full ? sizeof full
                                                                     : statsout->size;
    full.size = n;
    if (n >= sizeof full.size)
      memcpy(statsout, &full, n);
  }
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
