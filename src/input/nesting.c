/* Nesting of closed shells, so that a cavity is oriented with its normals pointing into
 * the cavity (out of the domain) while an outer shell points outward.
 *
 * A shell lies inside another iff a point of it off the other does (shells may share
 * vertices but do not cross: validation checks that after orientation). Point in
 * shell: count the exact crossings of the segment from the point to a point above the
 * whole input with the shell's triangles (tr_classify_segment_triangle). A crossing must
 * be a clean pass through a triangle's interior; if the segment grazes an edge, a vertex
 * or lies in a triangle's plane, another far point is tried. The points tried are the
 * shell's vertices, then the exact centroids of its triangles: a vertex on the other
 * shell makes every segment from it start there, and all the vertices of a shell can be
 * on another (a cavity whose corners touch the outer shell: a voxel left empty among 18,
 * found by the pipeline fuzzer), the interiors of its triangles cannot. Every decision
 * is exact; only the choice of the far points is arbitrary. */
#include <math.h>

#include "classify.h"
#include "validate.h"

/* 1 inside, 0 outside, -1 undecided (every ray tried was degenerate). */
static int inside(const struct tr_plc *plc, const tr_point *P, const uint32_t *tris, uint32_t n,
                  double zfar, double ext)
{
  static const double off[8][2] = {{0, 0},       {0.31, 0.17}, {-0.23, 0.41}, {0.57, -0.29},
                                   {-0.61, -0.37}, {0.13, 0.71}, {0.83, 0.47}, {-0.47, 0.89}};
  for (int k = 0; k < 8; k++) {
    double q[3] = {P->d[0] + off[k][0] * ext, P->d[1] + off[k][1] * ext, zfar};
    tr_point Q = tr_pt_d(q);
    int count = 0, clean = 1;
    for (uint32_t i = 0; i < n && clean; i++) {
      const uint32_t *v = plc->tris + 3 * (size_t)tris[i];
      tr_point A = tr_pt_d(plc->xyz + 3 * (size_t)v[0]), B = tr_pt_d(plc->xyz + 3 * (size_t)v[1]),
               C = tr_pt_d(plc->xyz + 3 * (size_t)v[2]);
      tr_isect r = tr_classify_segment_triangle(P, &Q, &A, &B, &C);
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

/* The number of closed shells other than c that contain point P, or -1 if a ray test
 * was undecided. */
static int depth_of(const struct tr_plc *plc, const tr_point *P, uint32_t c,
                    const uint32_t *order, const uint32_t *start, const char *closed,
                    uint32_t ncomp, double zfar, double ext)
{
  int depth = 0;
  for (uint32_t d = 0; d < ncomp; d++) {
    if (d == c || !closed[d])
      continue;
    int r = inside(plc, P, order + start[d], start[d + 1] - start[d], zfar, ext);
    if (r < 0)
      return -1;
    depth += r;
  }
  return depth;
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
    int depth = -1;
    uint64_t n = start[c + 1] - start[c];
    /* vertices first (doubles, cheap), then the triangles' centroids */
    for (uint64_t i = 0; i < 4 * n && depth < 0; i++) {
      uint32_t t = order[start[c] + i % n];
      if (i < 3 * n) {
        tr_point P = tr_pt_d(plc->xyz + 3 * (size_t)plc->tris[3 * (size_t)t + i / n]);
        depth = depth_of(plc, &P, c, order, start, closed, ncomp, zfar, ext);
      } else {
        tr_qpoint q;
        tr_qpoint_init(&q);
        tr_input_tri_centroid(plc, t, &q);
        tr_point P = tr_pt_q(&q);
        depth = depth_of(plc, &P, c, order, start, closed, ncomp, zfar, ext);
        tr_qpoint_clear(&q);
      }
    }
    if (depth < 0)
      return tr_error(TR_ERR_UNSUPPORTED,
                      "cannot decide whether the shell containing triangle %u is a cavity "
                      "(every ray tried grazes an edge)", order[start[c]]);
    cavity[c] = (char)(depth & 1);
  }
  return TR_OK;
}
