/* Input edges and the two recovery stages. */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "pipeline.h"
#include "pipeline/pipeline_config.h"
#include "core/edgesort.h"
#include "recover_edges/recover_edges.h"

double tr_pipeline_now(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Triangles only: the edge slots grouped by two counting passes (core/edgesort.h) rather
 * than a comparison sort of all 3n slots, which was a tenth of the Delaunay stage's time.
 * The same list and counts as the general path below. */
static tr_status triangle_edges(const struct tr_plc *plc, uint32_t **edges, uint32_t *n,
                                uint32_t *nopen, uint32_t *nmulti)
{
  size_t ns = 3 * (size_t)plc->ntris;
  uint32_t nv = 0;
  for (size_t i = 0; i < ns; i++)
    nv = plc->tris[i] >= nv ? plc->tris[i] + 1 : nv;
  uint32_t *slot = malloc(sizeof *slot * (ns ? ns : 1));
  uint32_t *e = malloc(sizeof *e * 2 * (ns ? ns : 1));
  tr_status st = TR_OK;
  if (!slot || !e)
    st = tr_error(TR_ERR_NOMEM, "out of memory listing %zu input edges", ns);
  if (st == TR_OK)
    st = tr_edge_slots_sorted(plc->tris, plc->ntris, nv, slot);
  if (st != TR_OK) {
    free(slot);
    free(e);
    return st;
  }
  size_t j = 0;
  for (size_t i = 0; i < ns;) {
    uint32_t a = plc->tris[slot[i]], b = plc->tris[3 * (slot[i] / 3) + (slot[i] % 3 + 1) % 3];
    uint32_t lo = a < b ? a : b, hi = a < b ? b : a, ntri = 0;
    size_t k = i;
    for (; k < ns; k++) {
      uint32_t c = plc->tris[slot[k]], d = plc->tris[3 * (slot[k] / 3) + (slot[k] % 3 + 1) % 3];
      if ((c < d ? c : d) != lo || (c < d ? d : c) != hi)
        break;
      ntri++;
    }
    if (ntri == 1)
      (*nopen)++;
    else if (ntri > 2)
      (*nmulti)++;
    e[2 * j] = lo;
    e[2 * j + 1] = hi;
    j++;
    i = k;
  }
  free(slot);
  *edges = e;
  *n = (uint32_t)j;
  return TR_OK;
}

tr_status tr_pipeline_edges(const struct tr_plc *plc, uint32_t **edges, uint32_t *n,
                            uint32_t *nopen, uint32_t *nmulti)
{
  size_t nt = 3 * (size_t)plc->ntris, ne = nt + plc->nsegs;
  *edges = NULL;
  *n = *nopen = *nmulti = 0;
  if (!plc->nsegs)
    return triangle_edges(plc, edges, n, nopen, nmulti);
  uint32_t *e = malloc(sizeof *e * 3 * (ne ? ne : 1));
  if (!e)
    return tr_error(TR_ERR_NOMEM, "out of memory listing %zu input edges", ne);
  /* third slot: 1 for a triangle edge, 0 for a segment, to count open edges */
  for (size_t i = 0; i < ne; i++) {
    uint32_t a, b;
    if (i < nt) {
      a = plc->tris[i];
      b = plc->tris[3 * (i / 3) + (i % 3 + 1) % 3];
    } else {
      a = plc->segs[2 * (i - nt)];
      b = plc->segs[2 * (i - nt) + 1];
    }
    e[3 * i] = a < b ? a : b;
    e[3 * i + 1] = a < b ? b : a;
    e[3 * i + 2] = i < nt;
  }
  qsort(e, ne, 3 * sizeof *e, tr_cmp_edge_key);
  size_t j = 0;
  for (size_t i = 0; i < ne;) {
    size_t k = i;
    uint32_t ntri = 0;
    while (k < ne && e[3 * k] == e[3 * i] && e[3 * k + 1] == e[3 * i + 1])
      ntri += e[3 * k++ + 2];
    if (ntri == 1)
      (*nopen)++;
    else if (ntri > 2)
      (*nmulti)++;
    e[2 * j] = e[3 * i];
    e[2 * j + 1] = e[3 * i + 1];
    j++;
    i = k;
  }
  *edges = e;
  *n = (uint32_t)j;
  return TR_OK;
}

void tr_pipeline_subfaces_free(tr_subfaces *sub)
{
  free(sub->v);
  free(sub->tri);
  memset(sub, 0, sizeof *sub);
}

#if !TR_HAVE_RECOVERY
typedef struct {
  uint32_t k[3];
} key3;
static void sort_small(uint32_t *s, int n)
{
  for (int i = 0; i < n - 1; i++)
    for (int j = 0; j < n - 1 - i; j++)
      if (s[j] > s[j + 1]) {
        uint32_t x = s[j];
        s[j] = s[j + 1];
        s[j + 1] = x;
      }
}

/* Without the recovery stages: succeed exactly when every input edge and triangle is
 * already in the Delaunay mesh (then the sub-faces are the triangles themselves). */
static tr_status recover_none(struct tr_mesh *m, const struct tr_plc *plc,
                              const uint32_t *edges, uint32_t ne, tr_subfaces *sub,
                              tr_stats *stats)
{
  size_t nf = 4 * (size_t)m->nt, n = 0;
  key3 *f = malloc(sizeof *f * (nf ? nf : 1));
  uint32_t *el = malloc(sizeof *el * 2 * 6 * (size_t)(m->nt ? m->nt : 1));
  tr_status st = TR_OK;
  if (!f || !el) {
    st = tr_error(TR_ERR_NOMEM, "out of memory");
    goto done;
  }
  size_t nel = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    for (int k = 0; k < 4; k++) {
      for (int i = 0; i < 3; i++)
        f[n].k[i] = m->tv[4 * (size_t)t + tr_face_vtx[k][i]];
      sort_small(f[n++].k, 3);
    }
    for (int e = 0; e < 6; e++) {
      uint32_t p[2] = {m->tv[4 * (size_t)t + tr_edge_vtx[e][0]],
                       m->tv[4 * (size_t)t + tr_edge_vtx[e][1]]};
      sort_small(p, 2);
      el[2 * nel] = p[0];
      el[2 * nel++ + 1] = p[1];
    }
  }
  qsort(f, n, sizeof *f, tr_cmp_face_key);
  qsort(el, nel, 2 * sizeof *el, tr_cmp_edge_key);
  uint64_t missing_e = 0, missing_f = 0;
  uint32_t first_e = TR_NONE, first_f = TR_NONE;
  for (uint32_t i = 0; i < ne; i++)
    if (!bsearch(edges + 2 * (size_t)i, el, nel, 2 * sizeof *el, tr_cmp_edge_key)) {
      if (!missing_e++)
        first_e = i;
    }
  for (uint32_t t = 0; t < plc->ntris; t++) {
    key3 q;
    memcpy(q.k, plc->tris + 3 * (size_t)t, sizeof q.k);
    sort_small(q.k, 3);
    if (!bsearch(&q, f, n, sizeof *f, tr_cmp_face_key) && !missing_f++)
      first_f = t;
  }
  stats->missing_edges = missing_e;
  stats->missing_facets = missing_f;
  if (missing_e || missing_f) {
    if (missing_e)
      st = tr_error(TR_ERR_UNSUPPORTED,
                    "%llu input edges are missing after Delaunay (first: (%u, %u)) and this "
                    "build has no boundary recovery stages",
                    (unsigned long long)missing_e, edges[2 * (size_t)first_e],
                    edges[2 * (size_t)first_e + 1]);
    else
      st = tr_error(TR_ERR_UNSUPPORTED,
                    "%llu input triangles are missing after Delaunay (first: %u) and this "
                    "build has no boundary recovery stages",
                    (unsigned long long)missing_f, first_f);
    goto done;
  }
  sub->n = plc->ntris;
  sub->v = malloc(sizeof *sub->v * 3 * (size_t)(sub->n ? sub->n : 1));
  sub->tri = malloc(sizeof *sub->tri * (sub->n ? sub->n : 1));
  if (!sub->v || !sub->tri) {
    st = tr_error(TR_ERR_NOMEM, "out of memory");
    goto done;
  }
  memcpy(sub->v, plc->tris, sizeof *sub->v * 3 * (size_t)sub->n);
  for (uint32_t t = 0; t < sub->n; t++)
    sub->tri[t] = t;
done:
  free(f);
  free(el);
  return st;
}
#endif

tr_status tr_pipeline_progress(const tr_options *opt, int stage, double fraction)
{
  if (opt->progress && opt->progress(opt->progress_user, tr_stage_name(stage), fraction))
    return tr_error(TR_ERR_CANCELLED, "cancelled by the progress callback at %s (%g)",
                    tr_stage_name(stage), fraction);
  return TR_OK;
}

tr_status tr_pipeline_recover(struct tr_mesh *m, const struct tr_plc *plc,
                              const uint32_t *edges, uint32_t ne, tr_subfaces *sub,
                              tr_stats *stats, double secs[2], const tr_options *opt,
                              uint8_t **vkind, uint32_t **vindex, uint32_t **subhint)
{
  memset(sub, 0, sizeof *sub);
  if (subhint)
    *subhint = NULL;
  secs[0] = secs[1] = 0;
  *vkind = NULL;
  *vindex = NULL;
  int recovery = opt->recovery;
  if (recovery < 0 || recovery > 2)
    return tr_error(TR_ERR_USAGE, "tr_options.recovery is %d: 0 (default), 1 (paper) or 2 "
                    "(no facet flips)", recovery);
  TR_CHECK(tr_pipeline_progress(opt, TR_STAGE_EDGES, 0));
#if TR_HAVE_RECOVERY
  tr_edge_chains chains;
  tr_edge_recovery_stats es;
  tr_facet_recovery_stats fs;
  memset(&chains, 0, sizeof chains);
  memset(&es, 0, sizeof es);
  memset(&fs, 0, sizeof fs);
  double t0 = tr_pipeline_now();
  /* the paper's algorithm: Swap23/Swap44 then pipels; Swap32 then clusterels */
  tr_edge_recovery_opts eo = {0};
  tr_facet_recovery_opts fo = {0};
  eo.no_flips = eo.no_midpoints = eo.no_lawson = fo.paper = recovery == 1;
  fo.no_flips = recovery == 2;
  /* its flat edges after the others (read in doubles: not for exact points) */
  eo.surface = recovery == 1 || plc->nxq ? NULL : plc;
  /* Every mode allows the same flip attempts per search (recover_edges.c). --keep-surface
   * had 2,000 instead of 20,000 while a stuck end of a segment was searched again in
   * every round (flipfirst.c); since the rounds stay at the end that moves, 20,000 costs
   * 6% more attempts than 2,000 over the corpus in keep mode (5.03 against 4.75
   * million), adds fewer points for edges (1254 against 1326), and 77343.stl meshes where
   * 2,000 and 3,000 left a point that could not be taken off the surface (exit 11). */
  tr_status st = tr_recover_edges_ex(m, edges, ne, &eo, &chains, &es);
  double t1 = tr_pipeline_now();
  secs[0] = t1 - t0;
  stats->missing_edges = es.missing_edges;
  stats->edges_recovered_by_swap = es.recovered_by_swap;
  stats->points_added_for_edges = es.points_added;
  if (st == TR_OK)
    st = tr_pipeline_progress(opt, TR_STAGE_EDGES, 1);
  if (st == TR_OK)
    st = tr_pipeline_progress(opt, TR_STAGE_FACETS, 0);
  if (st == TR_OK) {
    t1 = tr_pipeline_now();
    st = tr_recover_facets_ex(m, plc->tris, plc->ntris, &chains, &fo, sub, &fs, subhint);
    secs[1] = tr_pipeline_now() - t1;
    stats->missing_facets = fs.missing_facets;
    stats->facets_recovered_by_swap = fs.recovered_by_swap;
    stats->points_added_for_facets = fs.points_added;
    stats->facets_recovered_by_cavity = fs.recovered_by_cavity;
  }
  if (st == TR_OK)
    st = tr_pipeline_origins(m, plc->npoints, &chains, sub, vkind, vindex);
  tr_edge_chains_free(&chains);
#else
  (void)recovery; /* nothing is recovered in this build */
  double t0 = tr_pipeline_now();
  tr_status st = recover_none(m, plc, edges, ne, sub, stats);
  secs[0] = tr_pipeline_now() - t0;
  if (st == TR_OK)
    st = tr_pipeline_progress(opt, TR_STAGE_EDGES, 1);
  if (st == TR_OK)
    st = tr_pipeline_progress(opt, TR_STAGE_FACETS, 0);
#endif
  if (st == TR_OK)
    st = tr_pipeline_progress(opt, TR_STAGE_FACETS, 1);
  return st;
}
