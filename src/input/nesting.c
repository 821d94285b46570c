/* Nesting of closed shells, so that a cavity is oriented with its normals pointing into
 * the cavity (out of the domain) while an outer shell points outward.
 *
 * A shell lies inside another iff a vertex of it does (the shells do not intersect:
 * validation checks that after orientation, and a touching pair is reported there).
 * Point in shell: count the exact crossings of the segment from the point to a point
 * above the whole input with the shell's triangles (tr_classify_segment_triangle). A
 * crossing must be a clean pass through a triangle's interior; if the segment grazes an
 * edge, a vertex or lies in a triangle's plane, another far point is tried, and after a
 * few tries another vertex of the shell. Every decision is exact; only the choice of the
 * far points is arbitrary. */
#include <math.h>

#include "classify.h"
#include "validate.h"

/* 1 inside, 0 outside, -1 undecided (every ray tried was degenerate). */
static int inside(const struct tr_plc *plc, const double *p, const uint32_t *tris, uint32_t n,
                  double zfar, double ext)
{
  static const double off[8][2] = {{0, 0},       {0.31, 0.17}, {-0.23, 0.41}, {0.57, -0.29},
                                   {-0.61, -0.37}, {0.13, 0.71}, {0.83, 0.47}, {-0.47, 0.89}};
  for (int k = 0; k < 8; k++) {
    double q[3] = {p[0] + off[k][0] * ext, p[1] + off[k][1] * ext, zfar};
    tr_point P = tr_pt_d(p), Q = tr_pt_d(q);
    int count = 0, clean = 1;
    for (uint32_t i = 0; i < n && clean; i++) {
      const uint32_t *v = plc->tris + 3 * (size_t)tris[i];
      tr_point A = tr_pt_d(plc->xyz + 3 * (size_t)v[0]), B = tr_pt_d(plc->xyz + 3 * (size_t)v[1]),
               C = tr_pt_d(plc->xyz + 3 * (size_t)v[2]);
      tr_isect r = tr_classify_segment_triangle(&P, &Q, &A, &B, &C);
      if (r.n == 0)
        continue;
      if (r.n == 1 && r.end[0].type == TR_FAC && r.end[0].on_seg == TR_SEG_IN)
        count++;
      else
        clean = 0;
    }
    if (clean)
      return count & 1;
  }
  return -1;
}

tr_status tr_input_shell_cavities(const struct tr_plc *plc, const uint32_t *order,
                                  const uint32_t *start, const char *closed, uint32_t ncomp,
                                  char *cavity)
{
  uint32_t nclosed = 0;
  for (uint32_t c = 0; c < ncomp; c++) {
    cavity[c] = 0;
    nclosed += closed[c] != 0;
  }
  if (nclosed < 2)
    return TR_OK;
  double zmax = -INFINITY, lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (size_t i = 0; i < plc->npoints; i++)
    for (int d = 0; d < 3; d++) {
      double x = plc->xyz[3 * i + d];
      lo[d] = x < lo[d] ? x : lo[d];
      hi[d] = x > hi[d] ? x : hi[d];
    }
  zmax = hi[2];
  /* Strictly above every vertex; ext only spreads the tries. */
  double zfar = zmax + (fabs(zmax) + 1), ext = (hi[0] - lo[0]) + (hi[1] - lo[1]) + 1;
  if (!isfinite(zfar) || !isfinite(ext))
    return tr_error(TR_ERR_UNSUPPORTED, "coordinates too large to decide shell nesting");
  for (uint32_t c = 0; c < ncomp; c++) {
    if (!closed[c])
      continue;
    int depth = 0, decided = 0;
    /* A few vertices of c: a vertex shared with another shell would sit on it. */
    for (uint32_t i = start[c]; i < start[c + 1] && i < start[c] + 4 && !decided; i++) {
      const double *p = plc->xyz + 3 * (size_t)plc->tris[3 * (size_t)order[i]];
      depth = 0;
      decided = 1;
      for (uint32_t d = 0; d < ncomp && decided; d++) {
        if (d == c || !closed[d])
          continue;
        int r = inside(plc, p, order + start[d], start[d + 1] - start[d], zfar, ext);
        if (r < 0)
          decided = 0;
        else
          depth += r;
      }
    }
    if (!decided)
      return tr_error(TR_ERR_UNSUPPORTED,
                      "cannot decide whether the shell containing triangle %u is a cavity "
                      "(every ray tried grazes an edge)", order[start[c]]);
    cavity[c] = (char)(depth & 1);
  }
  return TR_OK;
}
