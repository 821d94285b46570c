/* tr_mesh_plc: validate -> smooth -> Delaunay -> edge recovery -> facet recovery ->
 * outer removal and regions -> rounding check -> compact output, with the seed paper's
 * Table 14 statistics. */
#define _DEFAULT_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "delaunay/delaunay.h"
#include "outer/color.h"
#include "pipeline.h"
#include "predicates.h"
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
  }
  return st;
}

/* Tets that would not be positive once their Steiner points are rounded to doubles: the
 * exact mesh is valid, the double output may not be (written exactly with --exact). */
static uint64_t rounding_inversions(const struct tr_mesh *m)
{
  uint64_t n = 0;
  if (!m->vq)
    return 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t) || (m->flags[t] & TR_TF_OUTER))
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    if (!m->vq[v[0]] && !m->vq[v[1]] && !m->vq[v[2]] && !m->vq[v[3]])
      continue;
    if (tr_orient3d(m->xyz + 3 * (size_t)v[0], m->xyz + 3 * (size_t)v[1],
                    m->xyz + 3 * (size_t)v[2], m->xyz + 3 * (size_t)v[3]) <= 0)
      n++;
  }
  return n;
}

static void say(const tr_options *opt, int level, const char *what, double secs)
{
  if (opt->verbose >= level)
    fprintf(stderr, "tetrec: %-22s %.3f s\n", what, secs);
}

tr_status tr_mesh_plc_ex(const tr_plc *plc, const tr_options *optin, tr_mesh **out,
                         tr_stats *stats, tr_plc **used)
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
  uint32_t *edges = NULL, ne = 0, nopen = 0, nreg = 0;
  tr_subfaces sub;
  memset(&sub, 0, sizeof sub);
  double secs[2];
  tr_status st = copy_plc(plc, &p);
  /* Validation works on a copy: the caller's PLC is const and may already have been
   * validated (then nothing changes: the repairs are idempotent). */
  if (st == TR_OK)
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
    st = tr_pipeline_edges(p, &edges, &ne, &nopen);
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
  if (st == TR_OK)
    st = tr_outer_color(m, &sub, opt.allow_open && (nopen > 0 || p->nsegs > 0), &nreg);
  if (st == TR_OK) {
    uint64_t inv = rounding_inversions(m);
    if (inv && opt.verbose >= 1)
      fprintf(stderr,
              "tetrec: warning: %llu tets are not positive once Steiner points are rounded "
              "to doubles (the exact mesh is valid; write it with --exact)\n",
              (unsigned long long)inv);
  }
  if (st == TR_OK)
    st = tr_pipeline_compact(m, &res);
  say(&opt, 2, "outer removal, output", tr_pipeline_now() - t4);
  if (st == TR_OK && tr_mesh_num_tets(res) == 0)
    st = tr_error(TR_ERR_INPUT, "the surface encloses no tetrahedron (is it inside out?)");
  if (st == TR_OK) {
    stats->volume_nodes = res->nv;
    stats->volume_elements = tr_mesh_num_tets(res);
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

tr_status tr_mesh_plc(const tr_plc *plc, const tr_options *opt, tr_mesh **out, tr_stats *stats)
{
  return tr_mesh_plc_ex(plc, opt, out, stats, NULL);
}
