/* The public tr_plc_* functions: life cycle, copying arrays in, reading files. */
#include "plc.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../io/io.h"
#include "status.h"

void tr_plc_clear(struct tr_plc *plc)
{
  free(plc->xyz);
  free(plc->tris);
  free(plc->tri_marker);
  free(plc->tri_source);
  free(plc->segs);
  free(plc->tets);
  free(plc->source);
  free(plc->report);
  memset(plc, 0, sizeof *plc);
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
  memcpy(n.xyz, xyz, sizeof *n.xyz * 3 * (size_t)npoints);
  memcpy(n.tris, tris, sizeof *n.tris * 3 * (size_t)ntris);
  if (markers)
    memcpy(n.tri_marker, markers, sizeof *markers * (size_t)ntris);
  tr_plc_clear(plc);
  *plc = n;
  return TR_OK;
}

tr_status tr_plc_read(const char *path, tr_plc **out)
{
  tr_error_clear();
  *out = NULL;
  tr_plc *p;
  TR_CHECK(tr_plc_create(&p));
  tr_status st = tr_io_read_file(path, p);
  if (st != TR_OK) {
    tr_plc_destroy(p);
    return st;
  }
  *out = p;
  return TR_OK;
}

uint32_t tr_plc_num_points(const tr_plc *plc) { return plc ? plc->npoints : 0; }
uint32_t tr_plc_num_triangles(const tr_plc *plc) { return plc ? plc->ntris : 0; }
const double *tr_plc_points(const tr_plc *plc) { return plc ? plc->xyz : NULL; }
const uint32_t *tr_plc_triangles(const tr_plc *plc) { return plc ? plc->tris : NULL; }
const char *tr_plc_report(const tr_plc *plc)
{
  return plc && plc->report ? plc->report : "";
}
