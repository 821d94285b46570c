/* Un-split of the surface around a Steiner point: the fans of sub-faces on p, one per
 * input triangle, retriangulated without p by ear clipping in the triangle's plane. */
#include <math.h>
#include <string.h>

#include "core/box.h"
#include "suppress_int.h"

tr_status tr_sup_plane(const tr_plc *plc, uint32_t tri, int *drop, int *sign)
{
  const uint32_t *t = plc->tris + 3 * (size_t)tri;
  const double *a = plc->xyz + 3 * (size_t)t[0], *b = plc->xyz + 3 * (size_t)t[1],
               *c = plc->xyz + 3 * (size_t)t[2];
  /* in the frame 2^-e that brings the triangle's half extent into [1/2, 1): at
   * coordinates near 1e200 the products overflow (NaN orders nothing), near 1e-200 they
   * underflow; the power of two is exact, so the order is that of the triangle at unit
   * size, and the mesh that of the same surface at any scale */
  double u[3], w[3], n[3], lo[3], hi[3];
  tr_box_of(plc->xyz, t, 3, lo, hi);
  int e = tr_frame_exp(tr_box_half_extent(lo, hi));
  for (int i = 0; i < 3; i++) {
    u[i] = ldexp(b[i], -e) - ldexp(a[i], -e);
    w[i] = ldexp(c[i], -e) - ldexp(a[i], -e);
  }
  n[0] = fabs(u[1] * w[2] - u[2] * w[1]);
  n[1] = fabs(u[2] * w[0] - u[0] * w[2]);
  n[2] = fabs(u[0] * w[1] - u[1] * w[0]);
  /* The rounded normal only orders the axes to try; the exact sign decides. */
  int order[3] = {0, 1, 2};
  for (int i = 0; i < 3; i++)
    for (int j = i + 1; j < 3; j++)
      if (n[order[j]] > n[order[i]]) {
        int x = order[i];
        order[i] = order[j];
        order[j] = x;
      }
  tr_point pa = tr_plc_point(plc, t[0]), pb = tr_plc_point(plc, t[1]), pc = tr_plc_point(plc, t[2]);
  for (int i = 0; i < 3; i++) {
    int s = tr_orient2d_proj_p(&pa, &pb, &pc, order[i]);
    if (s) {
      *drop = order[i];
      *sign = s;
      return TR_OK;
    }
  }
  return tr_error(TR_ERR_INTERNAL, "input triangle %u is degenerate", tri);
}

static int ccw(const struct tr_mesh *m, int drop, int sign, uint32_t a, uint32_t b, uint32_t c)
{
  tr_point pa = tr_mesh_point(m, a), pb = tr_mesh_point(m, b), pc = tr_mesh_point(m, c);
  return sign * tr_orient2d_proj_p(&pa, &pb, &pc, drop);
}

tr_status tr_sup_triangulate(const struct tr_mesh *m, int drop, int sign, const uint32_t *poly,
                             uint32_t n, uint32_t *out)
{
  if (n < 3 || n > TR_SUP_MAX_POLY)
    return tr_error(TR_ERR_INTERNAL, "un-split: polygon of %u vertices", n);
  uint32_t ring[TR_SUP_MAX_POLY];
  memcpy(ring, poly, n * sizeof *ring);
  uint32_t k = 0;
  while (n > 3) {
    uint32_t i;
    for (i = 0; i < n; i++) {
      uint32_t a = ring[(i + n - 1) % n], b = ring[i], c = ring[(i + 1) % n];
      if (ccw(m, drop, sign, a, b, c) <= 0)
        continue;
      uint32_t j;
      for (j = 0; j < n; j++) {
        uint32_t w = ring[j];
        if (w == a || w == b || w == c)
          continue;
        if (ccw(m, drop, sign, a, b, w) >= 0 && ccw(m, drop, sign, b, c, w) >= 0 &&
            ccw(m, drop, sign, c, a, w) >= 0)
          break;
      }
      if (j == n)
        break;
    }
    if (i == n)
      return tr_error(TR_ERR_INTERNAL, "un-split: no ear in a polygon of %u vertices", n);
    out[k++] = ring[(i + n - 1) % n];
    out[k++] = ring[i];
    out[k++] = ring[(i + 1) % n];
    memmove(ring + i, ring + i + 1, (n - i - 1) * sizeof *ring);
    n--;
  }
  if (ccw(m, drop, sign, ring[0], ring[1], ring[2]) <= 0)
    return tr_error(TR_ERR_INTERNAL, "un-split: last triangle of the polygon is not convex");
  out[k++] = ring[0];
  out[k++] = ring[1];
  out[k++] = ring[2];
  return TR_OK;
}

/* The face (p,u,w) of sub-face s rotated to begin with p. */
static void rot_to(const sup_ctx *c, uint32_t s, uint32_t p, uint32_t *u, uint32_t *w)
{
  const uint32_t *f = c->v + 3 * (size_t)s;
  int i = f[0] == p ? 0 : f[1] == p ? 1 : 2;
  *u = f[(i + 1) % 3];
  *w = f[(i + 2) % 3];
}

tr_status sup_unsplit(sup_ctx *c, uint32_t p, const tr_u32buf *old, tr_u32buf *merged,
                      int *edge, int *ok)
{
  *ok = 0;
  *edge = 0;
  merged->n = 0;
  size_t nold = old->n;
  if (nold == 0 || nold > TR_SUP_MAX_POLY)
    return TR_OK;
  uint8_t used[TR_SUP_MAX_POLY] = {0};
  int nclosed = 0, nopen = 0;
  for (size_t s0 = 0; s0 < nold; s0++) {
    if (used[s0])
      continue;
    uint32_t tri = c->tri[old->a[s0]];
    /* this triangle's fan: u -> w per face */
    uint32_t fu[TR_SUP_MAX_POLY], fw[TR_SUP_MAX_POLY];
    uint32_t k = 0;
    for (size_t s = s0; s < nold; s++)
      if (!used[s] && c->tri[old->a[s]] == tri) {
        used[s] = 1;
        rot_to(c, old->a[s], p, &fu[k], &fw[k]);
        k++;
      }
    /* start: a u that is no face's w (open fan), else any (closed) */
    uint32_t start = 0;
    int closed = 1;
    for (uint32_t i = 0; i < k && closed; i++) {
      uint32_t j;
      for (j = 0; j < k && fw[j] != fu[i]; j++)
        ;
      if (j == k) {
        start = i;
        closed = 0;
      }
    }
    uint32_t poly[TR_SUP_MAX_POLY + 1], np = 0, cur = start, ntaken = 0;
    uint8_t taken[TR_SUP_MAX_POLY] = {0};
    poly[np++] = fu[cur];
    while (cur != TR_NONE) {
      taken[cur] = 1;
      ntaken++;
      poly[np++] = fw[cur];
      uint32_t nx = TR_NONE;
      for (uint32_t j = 0; j < k; j++)
        if (!taken[j] && fu[j] == fw[cur])
          nx = j;
      cur = nx;
    }
    if (ntaken != k)
      return TR_OK; /* not one chain */
    if (closed) {
      if (poly[np - 1] != poly[0])
        return TR_OK;
      np--;
    }
    if (np < 3 || np > TR_SUP_MAX_POLY)
      return TR_OK;
    for (uint32_t i = 0; i < np; i++)
      for (uint32_t j = i + 1; j < np; j++)
        if (poly[i] == poly[j])
          return TR_OK; /* the fan touches itself: not a simple polygon */
    if (closed)
      nclosed++;
    else
      nopen++;
    int drop, sign;
    TR_CHECK(tr_sup_plane(c->plc, tri, &drop, &sign));
    uint32_t out[3 * TR_SUP_MAX_POLY];
    tr_status st = tr_sup_triangulate(c->m, drop, sign, poly, np, out);
    if (st != TR_OK) {
      tr_error_clear();
      return TR_OK;
    }
    for (uint32_t i = 0; i < np - 2; i++) {
      TR_CHECK(tr_u32buf_push(merged, out[3 * i]));
      TR_CHECK(tr_u32buf_push(merged, out[3 * i + 1]));
      TR_CHECK(tr_u32buf_push(merged, out[3 * i + 2]));
      TR_CHECK(tr_u32buf_push(merged, tri));
    }
  }
  /* inside one triangle (one closed fan), or on an input edge (open fans only) */
  if (!((nclosed == 1 && nopen == 0) || (nclosed == 0 && nopen >= 2)))
    return TR_OK;
  *edge = nopen > 0;
  *ok = 1;
  return TR_OK;
}
