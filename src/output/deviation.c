/* How far the written doubles of Steiner points lie from the constraints they are exactly
 * on (issue 18): rounding to doubles, and the repair of src/output/round.c, move a Steiner
 * point off its edge or facet by up to a few ulps of its coordinates, which is tiny
 * relative to the model except when the model sits far from the origin (a model
 * translated by 2^40 puts ulps at 2^-12).
 *
 * The constraint of a Steiner point is found from its exact point: the first input
 * triangle (in index order, among those whose box holds the point) that holds it in its
 * closed interior, by the exact classifier, and then its edge (TR_EDG) or its plane
 * (TR_FAC); else the first input segment that holds it. Coplanar diagonals swapped by
 * smoothing lie in the union of their two input triangles, so one of those holds them. The
 * distance of the written double from that line or plane is computed with rationals and
 * rounded once at the end; the result is divided by the diagonal of the input's bounding
 * box. This is a measurement for the user, no decision of the mesher depends on it. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "core/box.h"
#include "core/plc.h"
#include "deviation.h"

/* squared distance of p from the line ab (edge) or the plane abc (c != NULL), exact */
static double dist2(const double *p, const double *a, const double *b, const double *c)
{
  mpq_t u[3], w[3], v[3], n[3], t, s, num, den;
  mpq_t *all[] = {u, w, v, n};
  for (int i = 0; i < 4; i++)
    for (int k = 0; k < 3; k++)
      mpq_init(all[i][k]);
  mpq_inits(t, s, num, den, NULL);
  for (int k = 0; k < 3; k++) {
    mpq_set_d(u[k], b[k]);
    mpq_set_d(t, a[k]);
    mpq_sub(u[k], u[k], t); /* b - a */
    mpq_set_d(w[k], p[k]);
    mpq_sub(w[k], w[k], t); /* p - a */
    if (c) {
      mpq_set_d(v[k], c[k]);
      mpq_sub(v[k], v[k], t); /* c - a */
    }
  }
  /* n = u x (c ? v : w) */
  mpq_t *y = c ? v : w;
  for (int k = 0; k < 3; k++) {
    int i = (k + 1) % 3, j = (k + 2) % 3;
    mpq_mul(t, u[i], y[j]);
    mpq_mul(s, u[j], y[i]);
    mpq_sub(n[k], t, s);
  }
  if (c) { /* (n . w)^2 / |n|^2 */
    for (int k = 0; k < 3; k++) {
      mpq_mul(t, n[k], w[k]);
      mpq_add(num, num, t);
      mpq_mul(t, n[k], n[k]);
      mpq_add(den, den, t);
    }
    mpq_mul(num, num, num);
  } else { /* |u x w|^2 / |u|^2 */
    for (int k = 0; k < 3; k++) {
      mpq_mul(t, n[k], n[k]);
      mpq_add(num, num, t);
      mpq_mul(t, u[k], u[k]);
      mpq_add(den, den, t);
    }
  }
  double r = mpq_sgn(den) ? (mpq_div(num, num, den), mpq_get_d(num)) : 0;
  for (int i = 0; i < 4; i++)
    for (int k = 0; k < 3; k++)
      mpq_clear(all[i][k]);
  mpq_clears(t, s, num, den, NULL);
  return r;
}

static const double *X(const struct tr_plc *plc, uint32_t v) { return plc->xyz + 3 * (size_t)v; }

static int box_holds(const struct tr_plc *plc, const uint32_t *v, int nv, const tr_qpoint *q)
{
  double lo[3], hi[3];
  tr_box_of(plc->xyz, v, nv, lo, hi);
  for (int i = 0; plc->xq && i < nv; i++) /* an exact corner: its box, not its double */
    for (int k = 0; plc->xq[v[i]] && k < 3; k++) {
      lo[k] = plc->xq[v[i]]->lo[k] < lo[k] ? plc->xq[v[i]]->lo[k] : lo[k];
      hi[k] = plc->xq[v[i]]->hi[k] > hi[k] ? plc->xq[v[i]]->hi[k] : hi[k];
    }
  for (int k = 0; k < 3; k++)
    if (q->hi[k] < lo[k] || q->lo[k] > hi[k])
      return 0;
  return 1;
}

/* Squared distance of the double p from the constraint exact point q lies on; -1 if q is
 * on no input triangle or segment. */
static double from_constraint(const struct tr_plc *plc, const uint32_t *cand, uint32_t ncand,
                              const tr_qpoint *q, const double *p)
{
  tr_point Q = tr_pt_q(q);
  for (uint32_t i = 0; i < ncand; i++) {
    const uint32_t *t = plc->tris + 3 * (size_t)cand[i];
    if (!box_holds(plc, t, 3, q))
      continue;
    /* exact corners decide where q lies; the distance is measured to their doubles */
    tr_point A = tr_plc_point(plc, t[0]), B = tr_plc_point(plc, t[1]), C = tr_plc_point(plc, t[2]);
    tr_hit h = tr_classify_point_triangle(&Q, &A, &B, &C);
    if (h.type == TR_FAC)
      return dist2(p, X(plc, t[0]), X(plc, t[1]), X(plc, t[2]));
    if (h.type == TR_EDG)
      return dist2(p, X(plc, t[tr_ecode_start(h.code)]), X(plc, t[tr_ecode_end(h.code)]), NULL);
    if (h.type == TR_NOD) { /* not a Steiner point's place, but measured all the same */
      const double *a = X(plc, t[h.code]);
      return (p[0] - a[0]) * (p[0] - a[0]) + (p[1] - a[1]) * (p[1] - a[1]) +
             (p[2] - a[2]) * (p[2] - a[2]);
    }
  }
  for (uint32_t s = 0; s < plc->nsegs; s++) {
    const uint32_t *e = plc->segs + 2 * (size_t)s;
    if (!box_holds(plc, e, 2, q))
      continue;
    tr_point A = tr_pt_d(X(plc, e[0])), B = tr_pt_d(X(plc, e[1]));
    if (tr_classify_point_segment(&Q, &A, &B).type != TR_DEG)
      return dist2(p, X(plc, e[0]), X(plc, e[1]), NULL);
  }
  return -1;
}

/* Triangles by cell of a uniform grid over the input's box, about one per cell: the
 * candidates of a point are those of its nearest double's cell (a triangle is listed in
 * every cell its box meets, widened by one cell so that a point a rounding away from a
 * cell border is still found). */
typedef struct {
  double org[3], inv[3];
  uint32_t dim[3];
  uint32_t *start, *list;
} tgrid;

static uint32_t cell(const tgrid *g, int k, double x)
{
  double c = (x - g->org[k]) * g->inv[k];
  if (!(c > 0))
    return 0;
  return c >= (double)(g->dim[k] - 1) ? g->dim[k] - 1 : (uint32_t)c;
}

static void span(const tgrid *g, const struct tr_plc *plc, uint32_t t, uint32_t c0[3],
                 uint32_t c1[3])
{
  const uint32_t *v = plc->tris + 3 * (size_t)t;
  for (int k = 0; k < 3; k++) {
    double lo = X(plc, v[0])[k], hi = lo;
    for (int i = 1; i < 3; i++) {
      lo = X(plc, v[i])[k] < lo ? X(plc, v[i])[k] : lo;
      hi = X(plc, v[i])[k] > hi ? X(plc, v[i])[k] : hi;
    }
    c0[k] = cell(g, k, lo);
    c1[k] = cell(g, k, hi);
    c0[k] = c0[k] ? c0[k] - 1 : 0;
    c1[k] = c1[k] + 1 < g->dim[k] ? c1[k] + 1 : c1[k];
  }
}

/* 0: built; 1: the grid would be too large (long slivers), use every triangle. */
static int grid_build(tgrid *g, const struct tr_plc *plc, const double lo[3], const double hi[3])
{
  uint32_t n = plc->ntris;
  double side = cbrt((double)n) + 1;
  uint64_t ncell = 1;
  for (int k = 0; k < 3; k++) {
    double ext = hi[k] - lo[k];
    g->dim[k] = ext > 0 && isfinite(ext) ? (uint32_t)side : 1;
    g->org[k] = lo[k];
    g->inv[k] = ext > 0 && isfinite(ext) ? g->dim[k] / ext : 0;
    ncell *= g->dim[k];
  }
  uint64_t total = 0, cap = 64 * (uint64_t)n + 4096;
  uint32_t c0[3], c1[3];
  for (uint32_t t = 0; t < n && total <= cap; t++) {
    span(g, plc, t, c0, c1);
    total += (uint64_t)(c1[0] - c0[0] + 1) * (c1[1] - c0[1] + 1) * (c1[2] - c0[2] + 1);
  }
  if (total > cap)
    return 1;
  g->start = calloc(ncell + 1, sizeof *g->start);
  g->list = malloc(sizeof *g->list * (total ? total : 1));
  if (!g->start || !g->list)
    return 1;
  for (int pass = 0; pass < 2; pass++) {
    for (uint32_t t = 0; t < n; t++) {
      span(g, plc, t, c0, c1);
      for (uint32_t z = c0[2]; z <= c1[2]; z++)
        for (uint32_t y = c0[1]; y <= c1[1]; y++)
          for (uint32_t x = c0[0]; x <= c1[0]; x++) {
            uint64_t c = ((uint64_t)z * g->dim[1] + y) * g->dim[0] + x;
            if (pass == 0)
              g->start[c + 1]++;
            else
              g->list[g->start[c]++] = t; /* increasing t within a cell */
          }
    }
    if (pass == 0)
      for (uint64_t c = 0; c < ncell; c++)
        g->start[c + 1] += g->start[c];
    else {
      for (uint64_t c = ncell; c > 0; c--)
        g->start[c] = g->start[c - 1];
      g->start[0] = 0;
    }
  }
  return 0;
}

/* The input's bounding box diagonal and the triangle grid (or the list of every
 * triangle when the grid would be too large). */
typedef struct {
  double diag;
  tgrid g;
  uint32_t *every;
} finder;

static tr_status finder_init(finder *f, const struct tr_plc *plc)
{
  memset(f, 0, sizeof *f);
  double lo[3], hi[3];
  for (int k = 0; k < 3; k++) {
    lo[k] = hi[k] = plc->xyz[k];
    for (uint32_t i = 1; i < plc->npoints; i++) {
      double x = plc->xyz[3 * (size_t)i + k];
      lo[k] = x < lo[k] ? x : lo[k];
      hi[k] = x > hi[k] ? x : hi[k];
    }
  }
  f->diag = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                 (hi[2] - lo[2]) * (hi[2] - lo[2]));
  if (grid_build(&f->g, plc, lo, hi)) {
    free(f->g.start);
    free(f->g.list);
    f->g.start = f->g.list = NULL;
    f->every = malloc(sizeof *f->every * (plc->ntris ? plc->ntris : 1));
    if (!f->every)
      return tr_error(TR_ERR_NOMEM, "out of memory measuring the written doubles");
    for (uint32_t t = 0; t < plc->ntris; t++)
      f->every[t] = t;
  }
  return TR_OK;
}

static void finder_free(finder *f)
{
  free(f->g.start);
  free(f->g.list);
  free(f->every);
}

/* The candidate triangles of a point: those of its cell, or all. */
static const uint32_t *candidates(const finder *f, const struct tr_plc *plc, const double *x,
                                  uint32_t *n)
{
  if (f->every) {
    *n = plc->ntris;
    return f->every;
  }
  const tgrid *g = &f->g;
  uint64_t c = ((uint64_t)cell(g, 2, x[2]) * g->dim[1] + cell(g, 1, x[1])) * g->dim[0] +
               cell(g, 0, x[0]);
  *n = g->start[c + 1] - g->start[c];
  return g->list + g->start[c];
}

tr_status tr_mesh_double_deviation(const struct tr_mesh *m, const struct tr_plc *plc,
                                   double *dev, uint32_t *vertex)
{
  *dev = 0;
  *vertex = TR_NONE;
  if (!m->vq || !plc->npoints)
    return TR_OK;
  finder f;
  int have_finder = 0;
  double best = 0;
  for (uint32_t v = 0; v < m->nv; v++) {
    const tr_qpoint *q = m->vq[v];
    const double *p = m->xyz + 3 * (size_t)v;
    if (!q || (q->err[0] == 0 && q->err[1] == 0 && q->err[2] == 0 && p[0] == q->near[0] &&
               p[1] == q->near[1] && p[2] == q->near[2]))
      continue; /* written exactly */
    if (!have_finder) {
      /* built for the first rounded point only: most meshes keep none (on the stanford
       * bunny of the corpus, --keep-surface, the grid was 4% of the run for nothing) */
      TR_CHECK(finder_init(&f, plc));
      have_finder = 1;
    }
    uint32_t ncand;
    const uint32_t *cand = candidates(&f, plc, q->near, &ncand);
    double d2 = from_constraint(plc, cand, ncand, q, p);
    if (d2 > best) {
      best = d2;
      *vertex = v;
    }
  }
  if (have_finder) {
    *dev = f.diag > 0 ? sqrt(best) / f.diag : 0;
    finder_free(&f);
  }
  return TR_OK;
}

/* Squared distance from p to the closed triangle abc, in doubles (a measure): the nearest
 * point is in the face, on an edge or at a corner, by the signs of barycentric terms. */
static double tri_dist2(const double *p, const double *a, const double *b, const double *c)
{
  double ab[3], ac[3], ap[3], r[3];
  for (int k = 0; k < 3; k++) {
    ab[k] = b[k] - a[k];
    ac[k] = c[k] - a[k];
    ap[k] = p[k] - a[k];
  }
#define DOT(u, v) ((u)[0] * (v)[0] + (u)[1] * (v)[1] + (u)[2] * (v)[2])
  double d1 = DOT(ab, ap), d2 = DOT(ac, ap), s = 0, t = 0;
  double bp[3] = {p[0] - b[0], p[1] - b[1], p[2] - b[2]};
  double cp[3] = {p[0] - c[0], p[1] - c[1], p[2] - c[2]};
  double d3 = DOT(ab, bp), d4 = DOT(ac, bp), d5 = DOT(ab, cp), d6 = DOT(ac, cp);
  double va = d3 * d6 - d5 * d4, vb = d5 * d2 - d1 * d6, vc = d1 * d4 - d3 * d2;
#undef DOT
  if (d1 <= 0 && d2 <= 0)
    s = t = 0;
  else if (d3 >= 0 && d4 <= d3)
    s = 1, t = 0;
  else if (d6 >= 0 && d5 <= d6)
    s = 0, t = 1;
  else if (vc <= 0 && d1 >= 0 && d3 <= 0)
    s = d1 / (d1 - d3), t = 0;
  else if (vb <= 0 && d2 >= 0 && d6 <= 0)
    s = 0, t = d2 / (d2 - d6);
  else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    s = 1 - w, t = w;
  } else {
    double den = 1 / (va + vb + vc);
    s = vb * den, t = vc * den;
  }
  for (int k = 0; k < 3; k++)
    r[k] = ap[k] - s * ab[k] - t * ac[k];
  return r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
}

tr_status tr_plc_points_distance(const struct tr_plc *plc, const double *xyz, uint32_t first,
                                 uint32_t n, const uint8_t *on, double *dev, uint32_t *vertex)
{
  *dev = 0;
  *vertex = TR_NONE;
  if (!plc->npoints || !plc->ntris || first >= n)
    return TR_OK;
  finder f;
  TR_CHECK(finder_init(&f, plc));
  double best = 0;
  for (uint32_t v = first; v < n; v++) {
    if (on && !on[v])
      continue;
    const double *p = xyz + 3 * (size_t)v;
    uint32_t ncand;
    const uint32_t *cand = candidates(&f, plc, p, &ncand);
    double near = INFINITY;
    for (uint32_t i = 0; i < ncand; i++) {
      const uint32_t *t = plc->tris + 3 * (size_t)cand[i];
      double d2 = tri_dist2(p, X(plc, t[0]), X(plc, t[1]), X(plc, t[2]));
      near = d2 < near ? d2 : near;
    }
    if (near < INFINITY && near > best) { /* a point far from every triangle: not measured */
      best = near;
      *vertex = v;
    }
  }
  *dev = f.diag > 0 ? sqrt(best) / f.diag : 0;
  finder_free(&f);
  return TR_OK;
}
