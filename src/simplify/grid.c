/* A uniform grid over triangle boxes: the candidates of the distance tests. Only a
 * choice of which triangles to test: every query range is widened by a cell on each
 * side, so rounding in the cell arithmetic never leaves out a triangle whose box meets
 * the query box. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "simplify_impl.h"

/* widen: 1 for queries (a cell more each side), 0 to register a triangle */
static void cell_range(const tr_simp_grid *g, const double *lo, const double *hi,
                       uint32_t c0[3], uint32_t c1[3], int widen)
{
  for (int k = 0; k < 3; k++) {
    double a = floor((lo[k] - g->lo[k]) / g->cell[k]) - widen;
    double b = floor((hi[k] - g->lo[k]) / g->cell[k]) + widen;
    a = a < 0 ? 0 : a > g->dim[k] - 1 ? g->dim[k] - 1 : a;
    b = b < 0 ? 0 : b > g->dim[k] - 1 ? g->dim[k] - 1 : b;
    if (!(a == a)) /* NaN: the whole axis */
      a = 0;
    if (!(b == b))
      b = g->dim[k] - 1;
    c0[k] = (uint32_t)a, c1[k] = (uint32_t)b;
  }
}

void tr_simp_grid_free(tr_simp_grid *g)
{
  free(g->start);
  free(g->item);
  free(g->stamp);
  free(g->box);
  memset(g, 0, sizeof *g);
}

tr_status tr_simp_grid_build(tr_simp_grid *g, const double *xyz, const uint32_t *tri,
                             uint32_t ntris)
{
  memset(g, 0, sizeof *g);
  g->ntris = ntris;
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (size_t i = 0; i < 3 * (size_t)ntris; i++)
    for (int k = 0; k < 3; k++) {
      double x = xyz[3 * (size_t)tri[i] + k];
      lo[k] = fmin(lo[k], x), hi[k] = fmax(hi[k], x);
    }
  double ext[3], vol = 1;
  for (int k = 0; k < 3; k++) {
    ext[k] = ntris ? hi[k] - lo[k] : 0;
    ext[k] = ext[k] > 0 ? ext[k] : 1;
    vol *= ext[k];
  }
  /* about one cell per triangle, fewer while the entries exceed 16 per triangle */
  for (double target = ntris > 8 ? ntris : 8;; target /= 8) {
    double h = cbrt(vol / target);
    size_t total = 1;
    for (int k = 0; k < 3; k++) {
      double n = ceil(ext[k] / h);
      n = n < 1 ? 1 : n > 1024 ? 1024 : n;
      g->dim[k] = (uint32_t)n;
      g->cell[k] = ext[k] / n;
      g->lo[k] = ntris ? lo[k] : 0;
      total *= g->dim[k];
    }
    size_t entries = 0;
    for (uint32_t t = 0; t < ntris; t++) {
      double a[3], b[3];
      const uint32_t *v = tri + 3 * (size_t)t;
      tr_simp_tri_box(xyz + 3 * (size_t)v[0], xyz + 3 * (size_t)v[1], xyz + 3 * (size_t)v[2],
                      a, b);
      uint32_t c0[3], c1[3];
      cell_range(g, a, b, c0, c1, 0);
      entries += (size_t)(c1[0] - c0[0] + 1) * (c1[1] - c0[1] + 1) * (c1[2] - c0[2] + 1);
    }
    if (entries > 16 * (size_t)ntris + 4096 && target > 8)
      continue;
    g->start = calloc(total + 1, sizeof *g->start);
    g->item = malloc(sizeof *g->item * (entries ? entries : 1));
    g->stamp = calloc(ntris ? ntris : 1, sizeof *g->stamp);
    g->box = malloc(sizeof *g->box * 6 * (size_t)(ntris ? ntris : 1));
    if (!g->start || !g->item || !g->stamp || !g->box || entries > UINT32_MAX) {
      tr_simp_grid_free(g);
      return tr_error(TR_ERR_NOMEM, "out of memory for a grid of %u triangles", ntris);
    }
    for (int pass = 0; pass < 2; pass++) {
      for (uint32_t t = 0; t < ntris; t++) {
        double a[3], b[3];
        const uint32_t *v = tri + 3 * (size_t)t;
        tr_simp_tri_box(xyz + 3 * (size_t)v[0], xyz + 3 * (size_t)v[1],
                        xyz + 3 * (size_t)v[2], a, b);
        uint32_t c0[3], c1[3];
        cell_range(g, a, b, c0, c1, 0);
        for (int k = 0; k < 3; k++)
          g->box[6 * (size_t)t + k] = a[k], g->box[6 * (size_t)t + 3 + k] = b[k];
        for (uint32_t z = c0[2]; z <= c1[2]; z++)
          for (uint32_t y = c0[1]; y <= c1[1]; y++)
            for (uint32_t x = c0[0]; x <= c1[0]; x++) {
              size_t c = ((size_t)z * g->dim[1] + y) * g->dim[0] + x;
              if (pass == 0)
                g->start[c + 1]++;
              else
                g->item[g->start[c]++] = t;
            }
      }
      if (pass == 0)
        for (size_t c = 0; c < total; c++)
          g->start[c + 1] += g->start[c];
      else
        for (size_t c = total; c > 0; c--)
          g->start[c] = g->start[c - 1];
    }
    g->start[0] = 0;
    return TR_OK;
  }
}

tr_status tr_simp_grid_query(tr_simp_grid *g, const double *xyz, const uint32_t *tri,
                             const double *lo, const double *hi, double d, uint32_t **out,
                             uint32_t *n, uint32_t *cap)
{
  (void)xyz, (void)tri;
  double a[3], b[3];
  for (int k = 0; k < 3; k++)
    a[k] = lo[k] - d * (1 + 0x1p-40), b[k] = hi[k] + d * (1 + 0x1p-40);
  if (++g->tick == 0) {
    memset(g->stamp, 0, sizeof *g->stamp * g->ntris);
    g->tick = 1;
  }
  uint32_t c0[3], c1[3];
  cell_range(g, a, b, c0, c1, 1);
  for (uint32_t z = c0[2]; z <= c1[2]; z++)
    for (uint32_t y = c0[1]; y <= c1[1]; y++)
      for (uint32_t x = c0[0]; x <= c1[0]; x++) {
        size_t c = ((size_t)z * g->dim[1] + y) * g->dim[0] + x;
        for (uint32_t s = g->start[c]; s < g->start[c + 1]; s++) {
          uint32_t t = g->item[s];
          if (g->stamp[t] == g->tick)
            continue;
          g->stamp[t] = g->tick;
          const double *bx = g->box + 6 * (size_t)t;
          if (bx[0] > b[0] || bx[1] > b[1] || bx[2] > b[2] || bx[3] < a[0] || bx[4] < a[1] ||
              bx[5] < a[2])
            continue;
          if (*n == *cap) {
            uint32_t nc = *cap ? 2 * *cap : 64;
            uint32_t *o = realloc(*out, sizeof *o * nc);
            if (!o)
              return tr_error(TR_ERR_NOMEM, "out of memory listing nearby triangles");
            *out = o, *cap = nc;
          }
          (*out)[(*n)++] = t;
        }
      }
  return TR_OK;
}
