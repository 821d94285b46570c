/* The public tr_plc_* functions: life cycle, copying arrays in, reading files. */
#define _POSIX_C_SOURCE 200809L
#include "plc.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "status.h"

void tr_plc_clear(struct tr_plc *plc)
{
  free(plc->xyz);
  free(plc->tris);
  free(plc->tri_marker);
  free(plc->tri_source);
  free(plc->segs);
  free(plc->tets);
  free(plc->holes);
  free(plc->hole_cavity);
  free(plc->region_xyz);
  free(plc->region_attr);
  free(plc->region_maxvol);
  free(plc->source);
  free(plc->report);
  free(plc->fan_notes);
  free(plc->fan_facet);
  free(plc->vsize);
  for (uint32_t i = 0; plc->xq && i < plc->npoints; i++)
    if (plc->xq[i]) {
      tr_qpoint_clear(plc->xq[i]);
      free(plc->xq[i]);
    }
  free(plc->xq);
  free(plc->tri_inner);
  memset(plc, 0, sizeof *plc);
}

tr_status tr_plc_copy_exact(struct tr_plc *dst, const struct tr_plc *src)
{
  if (!src->xq)
    return TR_OK;
  if (!(dst->xq = calloc(dst->npoints ? dst->npoints : 1, sizeof *dst->xq)))
    return tr_error(TR_ERR_NOMEM, "out of memory copying %u exact points", src->nxq);
  for (uint32_t i = 0; i < src->npoints && i < dst->npoints; i++) {
    if (!src->xq[i])
      continue;
    if (!(dst->xq[i] = malloc(sizeof *dst->xq[i])))
      return tr_error(TR_ERR_NOMEM, "out of memory copying %u exact points", src->nxq);
    tr_qpoint_init(dst->xq[i]);
    tr_point q = tr_pt_q(src->xq[i]);
    tr_qpoint_set_point(dst->xq[i], &q);
  }
  dst->nxq = src->nxq;
  if (src->tri_inner && dst->ntris == src->ntris) {
    if (!(dst->tri_inner = malloc(dst->ntris ? dst->ntris : 1)))
      return tr_error(TR_ERR_NOMEM, "out of memory copying %u triangle sides", dst->ntris);
    memcpy(dst->tri_inner, src->tri_inner, dst->ntris);
  }
  return TR_OK;
}

tr_status tr_plc_create(tr_plc **out)
{
  tr_error_clear();
  *out = calloc(1, sizeof **out);
  if (!*out)
    return tr_error(TR_ERR_NOMEM, "out of memory creating a PLC");
  return TR_OK;
}

void tr_plc_destroy(tr_plc *plc)
{
  if (!plc)
    return;
  tr_plc_clear(plc);
  free(plc);
}

tr_status tr_plc_set(tr_plc *plc, const double *xyz, uint32_t npoints, const uint32_t *tris,
                     uint32_t ntris, const int32_t *markers)
{
  tr_error_clear();
  if (!plc || (npoints && !xyz) || (ntris && !tris))
    return tr_error(TR_ERR_USAGE, "tr_plc_set: NULL array with a nonzero count");
  if (npoints > UINT32_MAX / 8 || ntris > UINT32_MAX / 8)
    return tr_error(TR_ERR_NOMEM, "tr_plc_set: too many points or triangles");
  for (size_t i = 0; i < 3 * (size_t)npoints; i++)
    if (!isfinite(xyz[i]))
      return tr_error(TR_ERR_INPUT, "point %zu: coordinate %zu is NaN or infinite", i / 3, i % 3);
  for (size_t i = 0; i < 3 * (size_t)ntris; i++)
    if (tris[i] >= npoints)
      return tr_error(TR_ERR_INPUT, "triangle %zu: vertex index %u out of range (%u points)",
                      i / 3, tris[i], npoints);
  struct tr_plc n;
  memset(&n, 0, sizeof n);
  n.npoints = npoints;
  n.ntris = ntris;
  n.xyz = malloc(sizeof *n.xyz * 3 * (size_t)(npoints ? npoints : 1));
  n.tris = malloc(sizeof *n.tris * 3 * (size_t)(ntris ? ntris : 1));
  n.tri_marker = calloc(ntris ? ntris : 1, sizeof *n.tri_marker);
  if (!n.xyz || !n.tris || !n.tri_marker) {
    tr_plc_clear(&n);
    return tr_error(TR_ERR_NOMEM, "out of memory copying the PLC");
  }
  /* hole and region points are coordinates: they survive a new point set */
  n.nholes = plc->nholes, n.holes = plc->holes;
  free(plc->hole_cavity); /* decided by the next validation */
  plc->hole_cavity = NULL;
  n.nregions = plc->nregions, n.region_xyz = plc->region_xyz;
  n.region_attr = plc->region_attr, n.region_maxvol = plc->region_maxvol;
  plc->holes = plc->region_xyz = plc->region_maxvol = NULL;
  plc->region_attr = NULL;
  memcpy(n.xyz, xyz, sizeof *n.xyz * 3 * (size_t)npoints);
  memcpy(n.tris, tris, sizeof *n.tris * 3 * (size_t)ntris);
  if (markers)
    memcpy(n.tri_marker, markers, sizeof *markers * (size_t)ntris);
  tr_plc_clear(plc);
  *plc = n;
  return TR_OK;
}


/* Room for element n of an array that holds n: the capacity is the next power of two
 * (an array only ever grows here), so a million tr_plc_add_region calls are a few dozen
 * reallocations, not a million. */
static tr_status grow(void **a, size_t elem, uint32_t n)
{
  if (n & (n - 1))
    return TR_OK; /* n is no power of two: there is room up to the next one */
  void *x = realloc(*a, elem * (n ? 2 * (size_t)n : 1));
  if (!x)
    return tr_error(TR_ERR_NOMEM, "out of memory adding a point to the PLC");
  *a = x;
  return TR_OK;
}

static tr_status finite3(const char *what, double x, double y, double z)
{
  if (!isfinite(x) || !isfinite(y) || !isfinite(z))
    return tr_error(TR_ERR_INPUT, "%s (%.17g, %.17g, %.17g): a coordinate is NaN or infinite",
                    what, x, y, z);
  return TR_OK;
}

tr_status tr_plc_add_segments(tr_plc *plc, const uint32_t *segs, uint32_t nsegs)
{
  tr_error_clear();
  if (!plc || (nsegs && !segs))
    return tr_error(TR_ERR_USAGE, "tr_plc_add_segments: NULL argument");
  if (nsegs > UINT32_MAX / 8 - plc->nsegs)
    return tr_error(TR_ERR_NOMEM, "tr_plc_add_segments: too many segments");
  for (size_t i = 0; i < 2 * (size_t)nsegs; i++)
    if (segs[i] >= plc->npoints)
      return tr_error(TR_ERR_INPUT, "segment %zu: vertex index %u out of range (%u points)",
                      i / 2, segs[i], plc->npoints);
  for (uint32_t i = 0; i < nsegs; i++)
    if (segs[2 * (size_t)i] == segs[2 * (size_t)i + 1])
      return tr_error(TR_ERR_INPUT, "segment %u: both ends are vertex %u", i, segs[2 * (size_t)i]);
  uint32_t *x = realloc(plc->segs, sizeof *x * 2 * ((size_t)plc->nsegs + nsegs + 1));
  if (!x)
    return tr_error(TR_ERR_NOMEM, "out of memory adding %u segments", nsegs);
  memcpy(x + 2 * (size_t)plc->nsegs, segs, sizeof *x * 2 * (size_t)nsegs);
  plc->segs = x;
  plc->nsegs += nsegs;
  plc->validated = 0;
  return TR_OK;
}

tr_status tr_plc_add_hole(tr_plc *plc, double x, double y, double z)
{
  tr_error_clear();
  if (!plc)
    return tr_error(TR_ERR_USAGE, "tr_plc_add_hole: NULL PLC");
  TR_CHECK(finite3("hole point", x, y, z));
  if (plc->nholes >= UINT32_MAX / 8)
    return tr_error(TR_ERR_NOMEM, "too many hole points");
  TR_CHECK(grow((void **)&plc->holes, 3 * sizeof(double), plc->nholes));
  free(plc->hole_cavity);
  plc->hole_cavity = NULL;
  double *h = plc->holes + 3 * (size_t)plc->nholes++;
  h[0] = x, h[1] = y, h[2] = z;
  plc->validated = 0; /* a hole point can make a nested shell a cavity */
  return TR_OK;
}

tr_status tr_plc_add_region(tr_plc *plc, double x, double y, double z, int32_t attribute,
                            double max_volume)
{
  tr_error_clear();
  if (!plc)
    return tr_error(TR_ERR_USAGE, "tr_plc_add_region: NULL PLC");
  TR_CHECK(finite3("region point", x, y, z));
  if (isnan(max_volume))
    return tr_error(TR_ERR_INPUT, "region point (%.17g, %.17g, %.17g): maximum volume is NaN",
                    x, y, z);
  if (plc->nregions >= UINT32_MAX / 8)
    return tr_error(TR_ERR_NOMEM, "too many region points");
  uint32_t n = plc->nregions;
  TR_CHECK(grow((void **)&plc->region_xyz, 3 * sizeof(double), n));
  TR_CHECK(grow((void **)&plc->region_attr, sizeof(int32_t), n));
  TR_CHECK(grow((void **)&plc->region_maxvol, sizeof(double), n));
  double *r = plc->region_xyz + 3 * (size_t)n;
  r[0] = x, r[1] = y, r[2] = z;
  plc->region_attr[n] = attribute;
  plc->region_maxvol[n] = max_volume;
  plc->nregions = n + 1;
  return TR_OK;
}

tr_status tr_plc_copy_points(struct tr_plc *dst, const struct tr_plc *src)
{
  for (uint32_t i = 0; i < src->nholes; i++) {
    const double *h = src->holes + 3 * (size_t)i;
    TR_CHECK(tr_plc_add_hole(dst, h[0], h[1], h[2]));
  }
  for (uint32_t i = 0; i < src->nregions; i++) {
    const double *r = src->region_xyz + 3 * (size_t)i;
    TR_CHECK(tr_plc_add_region(dst, r[0], r[1], r[2], src->region_attr[i],
                               src->region_maxvol[i]));
  }
  if (src->hole_cavity && src->nholes == dst->nholes) {
    if (!(dst->hole_cavity = malloc(dst->nholes)))
      return tr_error(TR_ERR_NOMEM, "out of memory copying hole points");
    memcpy(dst->hole_cavity, src->hole_cavity, dst->nholes);
  }
  dst->ncavities = src->ncavities;
  dst->ninclusions = src->ninclusions;
  return TR_OK;
}

uint32_t tr_plc_num_holes(const tr_plc *plc) { return plc ? plc->nholes : 0; }
uint32_t tr_plc_num_regions(const tr_plc *plc) { return plc ? plc->nregions : 0; }
uint32_t tr_plc_num_points(const tr_plc *plc) { return plc ? plc->npoints : 0; }
uint32_t tr_plc_num_triangles(const tr_plc *plc) { return plc ? plc->ntris : 0; }
const double *tr_plc_points(const tr_plc *plc) { return plc ? plc->xyz : NULL; }
const uint32_t *tr_plc_triangles(const tr_plc *plc) { return plc ? plc->tris : NULL; }
const char *tr_plc_report(const tr_plc *plc)
{
  return plc && plc->report ? plc->report : "";
}

uint32_t tr_plc_num_fans(const tr_plc *plc) { return plc ? plc->nfans : 0; }

const char *tr_plc_fan_notes(const tr_plc *plc)
{
  return plc && plc->fan_notes ? plc->fan_notes : "";
}

tr_status tr_plc_copy(const tr_plc *in, tr_plc **out)
{
  TR_CHECK(tr_plc_create(out));
  tr_plc *p = *out;
  tr_status st = tr_plc_set(p, in->xyz, in->npoints, in->tris, in->ntris, in->tri_marker);
  if (st == TR_OK)
    st = tr_plc_copy_points(p, in);
  if (st == TR_OK)
    st = tr_plc_copy_exact(p, in);
  if (st == TR_OK && in->source && !(p->source = strdup(in->source)))
    st = tr_error(TR_ERR_NOMEM, "out of memory copying the PLC");
  if (st == TR_OK && in->tri_source) {
    if (!(p->tri_source = malloc(sizeof *p->tri_source * (in->ntris ? in->ntris : 1))))
      st = tr_error(TR_ERR_NOMEM, "out of memory copying %u triangle sources", in->ntris);
    else
      memcpy(p->tri_source, in->tri_source, sizeof *p->tri_source * in->ntris);
  }
  if (st == TR_OK && in->nsegs) {
    p->segs = malloc(sizeof *p->segs * 2 * (size_t)in->nsegs);
    if (!p->segs)
      st = tr_error(TR_ERR_NOMEM, "out of memory copying %u segments", in->nsegs);
    else {
      memcpy(p->segs, in->segs, sizeof *p->segs * 2 * (size_t)in->nsegs);
      p->nsegs = in->nsegs;
    }
  }
  if (st == TR_OK && in->vsize) {
    if (!(p->vsize = malloc(sizeof *p->vsize * (in->npoints ? in->npoints : 1))))
      st = tr_error(TR_ERR_NOMEM, "out of memory copying %u point sizes", in->npoints);
    else
      memcpy(p->vsize, in->vsize, sizeof *p->vsize * in->npoints);
  }
  if (st != TR_OK) {
    tr_plc_destroy(p);
    *out = NULL;
  } else {
    p->validated = in->validated;
    memcpy(p->validate_seconds, in->validate_seconds, sizeof p->validate_seconds);
  }
  return st;
}
