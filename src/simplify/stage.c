/* The stage (tr_simplify_surface): collapses and flips within the envelope
 * (improve.c), the exact self-intersection test of the input stage on the result, and
 * when two triangles of it cross, the points that made them frozen and the operations
 * run again from the input; then the result validated like an input and its two-sided
 * bound measured (bound.c), which must hold: the guarantee does not rest on the local
 * checks alone. */
#define _DEFAULT_SOURCE
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "improve.h"
#include "input/validate.h"
#include "simplify.h"

/* rounds of collapses with more frozen vertices before the input is kept as it is */
#define MAX_ROUNDS 4

double tr_simplify_diagonal(const struct tr_plc *plc)
{
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (size_t i = 0; i < 3 * (size_t)plc->ntris + 2 * (size_t)plc->nsegs; i++) {
    uint32_t v = i < 3 * (size_t)plc->ntris ? plc->tris[i] : plc->segs[i - 3 * plc->ntris];
    for (int k = 0; k < 3; k++) {
      lo[k] = fmin(lo[k], plc->xyz[3 * (size_t)v + k]);
      hi[k] = fmax(hi[k], plc->xyz[3 * (size_t)v + k]);
    }
  }
  double s = 0;
  for (int k = 0; k < 3; k++)
    s += hi[k] > lo[k] ? (hi[k] - lo[k]) * (hi[k] - lo[k]) : 0;
  return sqrt(s);
}

static uint32_t root(const uint32_t *into, uint32_t v)
{
  while (into[v] != v)
    v = into[v];
  return v;
}

/* The PLC of the surviving triangles: the points that stay, renumbered in order. */
static tr_status build(const struct tr_plc *in, const uint32_t *into, const tr_simp_result *r,
                       uint32_t *newid, tr_plc **out)
{
  const uint32_t *tris = r->tris, *tri_of = r->tri_of, nt = r->ntris;
  uint32_t n = 0;
  for (uint32_t v = 0; v < in->npoints; v++)
    newid[v] = into[v] == v ? n++ : UINT32_MAX;
  double *xyz = malloc(sizeof *xyz * 3 * (size_t)(n ? n : 1));
  uint32_t *t = malloc(sizeof *t * 3 * (size_t)(nt ? nt : 1));
  int32_t *mk = malloc(sizeof *mk * (nt ? nt : 1));
  tr_status st = xyz && t && mk ? TR_OK : tr_error(TR_ERR_NOMEM, "out of memory");
  tr_plc *p = NULL;
  if (st == TR_OK) {
    for (uint32_t v = 0; v < in->npoints; v++)
      if (newid[v] != UINT32_MAX)
        memcpy(xyz + 3 * (size_t)newid[v], in->xyz + 3 * (size_t)v, 3 * sizeof *xyz);
    for (size_t i = 0; i < 3 * (size_t)nt; i++)
      t[i] = newid[tris[i]];
    for (uint32_t i = 0; i < nt; i++)
      mk[i] = in->tri_marker ? in->tri_marker[tri_of[i]] : 0;
    st = tr_plc_create(&p);
  }
  if (st == TR_OK)
    st = tr_plc_set(p, xyz, n, t, nt, mk);
  if (st == TR_OK)
    st = tr_plc_copy_points(p, in);
  if (st == TR_OK && !(p->tri_source = malloc(sizeof *p->tri_source * (nt ? nt : 1))))
    st = tr_error(TR_ERR_NOMEM, "out of memory");
  for (uint32_t i = 0; st == TR_OK && i < nt; i++)
    p->tri_source[i] = in->tri_source ? in->tri_source[tri_of[i]] : tri_of[i];
  if (st == TR_OK && in->nsegs) {
    if (!(p->segs = malloc(sizeof *p->segs * 2 * (size_t)in->nsegs)))
      st = tr_error(TR_ERR_NOMEM, "out of memory");
    for (size_t i = 0; st == TR_OK && i < 2 * (size_t)in->nsegs; i++)
      p->segs[i] = newid[in->segs[i]]; /* their ends are frozen */
    if (st == TR_OK)
      p->nsegs = in->nsegs;
  }
  if (st == TR_OK && in->vsize) {
    if (!(p->vsize = malloc(sizeof *p->vsize * (n ? n : 1))))
      st = tr_error(TR_ERR_NOMEM, "out of memory");
    for (uint32_t v = 0; st == TR_OK && v < in->npoints; v++)
      if (newid[v] != UINT32_MAX)
        p->vsize[newid[v]] = in->vsize[v];
  }
  if (st == TR_OK && in->source && !(p->source = strdup(in->source)))
    st = tr_error(TR_ERR_NOMEM, "out of memory");
  free(xyz), free(t), free(mk);
  if (st != TR_OK)
    tr_plc_destroy(p), p = NULL;
  *out = p;
  return st;
}

tr_status tr_simplify_surface(struct tr_plc **plcp, double eps, const tr_options *opt,
                              tr_simp_stats *stats)
{
  memset(stats, 0, sizeof *stats);
  if (!(eps > 0) || !isfinite(eps))
    return tr_error(TR_ERR_USAGE, "surface tolerance %g: it is a finite number > 0 (a "
                    "fraction of the bounding box diagonal, e.g. 1e-3)", eps);
  struct tr_plc *in = *plcp;
  double diag = tr_simplify_diagonal(in), d = eps * diag;
  /* room for the rounding of Steiner points to doubles (2^-40 of the diagonal is where
   * the command warns) between what the collapses use and what is promised */
  double ds = d - 1e-6 * d - 0x1p-36 * diag;
  if (!(ds > 0) || in->ntris == 0)
    return TR_OK;
  uint32_t nv = in->npoints;
  uint8_t *frozen = calloc(nv ? nv : 1, 1);
  uint32_t *into = malloc(sizeof *into * (nv ? nv : 1));
  uint32_t *newid = malloc(sizeof *newid * (nv ? nv : 1));
  uint32_t *oldid = malloc(sizeof *oldid * (nv ? nv : 1));
  tr_status st = frozen && into && newid && oldid
                     ? TR_OK
                     : tr_error(TR_ERR_NOMEM, "out of memory for %u points", nv);
  for (size_t i = 0; st == TR_OK && i < 2 * (size_t)in->nsegs; i++)
    frozen[in->segs[i]] = 1;
  tr_plc *res = NULL;
  for (int round = 0; st == TR_OK && round < MAX_ROUNDS; round++) {
    tr_simp_result r;
    stats->rounds++;
    st = tr_simp_improve(in, ds, frozen, into, &r);
    if (st == TR_OK && r.collapses + r.flips == 0) {
      tr_simp_result_free(&r);
      break; /* nothing moved: the input as it is */
    }
    uint64_t nc = r.collapses, nf = r.flips;
    if (st == TR_OK)
      st = build(in, into, &r, newid, &res);
    uint32_t *pairs = NULL;
    size_t np = 0;
    if (st == TR_OK)
      st = tr_input_self_intersection_pairs(res, TR_SELFINT_AUTO, &pairs, &np);
    if (st == TR_OK && np == 0) {
      stats->collapses = nc, stats->flips = nf;
      free(pairs);
      tr_simp_result_free(&r);
      break;
    }
    /* freeze every input point that went into a point of a crossing triangle */
    for (uint32_t v = 0; v < nv; v++)
      if (newid[v] != UINT32_MAX)
        oldid[newid[v]] = v;
    uint8_t *hit = calloc(nv ? nv : 1, 1);
    if (st == TR_OK && !hit)
      st = tr_error(TR_ERR_NOMEM, "out of memory");
    for (size_t i = 0; st == TR_OK && i < 2 * np; i++)
      for (int k = 0; k < 3; k++)
        hit[oldid[res->tris[3 * (size_t)pairs[i] + k]]] = 1;
    for (uint32_t v = 0; st == TR_OK && v < nv; v++)
      if (hit[root(into, v)] && !frozen[v])
        frozen[v] = 1, stats->vertices_frozen++;
    free(hit), free(pairs);
    tr_simp_result_free(&r);
    tr_plc_destroy(res);
    res = NULL;
    if (opt && opt->verbose >= 2)
      fprintf(stderr, "tetrec: surface tolerance: %zu crossing pairs after %llu collapses and "
              "%llu flips, their vertices frozen\n", np, (unsigned long long)nc,
              (unsigned long long)nf);
  }
  free(frozen), free(into), free(newid), free(oldid);
  if (st == TR_OK && !res) {
    if (opt && opt->verbose >= 1 && stats->rounds >= MAX_ROUNDS)
      fprintf(stderr, "tetrec: warning: the simplified surface still crossed itself after "
              "%d rounds: the input surface is meshed as it is\n", MAX_ROUNDS);
    stats->collapses = stats->flips = 0;
    return TR_OK;
  }
  if (st == TR_OK) {
    tr_options vo;
    tr_options_default(&vo);
    vo.allow_open = opt ? opt->allow_open : 0;
    vo.verbose = 0;
    st = tr_plc_validate(res, &vo);
  }
  tr_simp_bound_result br;
  if (st == TR_OK)
    st = tr_simplify_bound(in->xyz, in->tris, in->ntris, res->xyz, res->tris, res->ntris, d,
                           &br);
  /* Each collapse was proven on its own pieces; the whole is proven again here, with
   * its own subdivision. Where that runs out of pieces (undecided) the promise cannot be
   * made: the input is meshed as it is. A proof of the contrary is a bug. */
  if (st == TR_OK && !br.ok && !br.undecided)
    st = tr_error(TR_ERR_INTERNAL, "the simplified surface is not within %g of the input "
                  "(%s triangle %u)", d, br.side ? "simplified" : "input", br.tri);
  if (st == TR_OK && !br.ok) {
    if (opt && opt->verbose >= 1)
      fprintf(stderr, "tetrec: warning: the simplified surface could not be proven within "
              "the tolerance as a whole (%s triangle %u undecided): the input surface is "
              "meshed as it is\n", br.side ? "simplified" : "input", br.tri);
    stats->collapses = stats->flips = 0;
    tr_plc_destroy(res);
    return TR_OK;
  }
  if (st != TR_OK) {
    tr_plc_destroy(res);
    return st;
  }
  stats->bound = diag > 0 ? br.measured / diag : 0;
  res->validated = in->validated;
  tr_plc_destroy(in);
  *plcp = res;
  return TR_OK;
}
