/* The size field (sizing.h) and its use in refinement (refine_impl.h, rf_sizing_*).
 *
 * The size at a vertex is its target edge length h: given for the input points,
 * interpolated linearly over the background mesh for every other vertex when it is
 * inserted (TetGen interpolates over its initial mesh the same way, Si 2015; here the
 * background is the Delaunay tetrahedralization of the input points, which covers the
 * domain and needs no size at a recovery Steiner point). A tet is over the field when its
 * longest edge is longer than the mean of its four vertices' sizes, a sub-segment when it
 * is longer than the mean of its ends', a sub-face when its longest edge is longer than
 * the mean of its three vertices'; a vertex with size 0 (no bound) exempts every piece it
 * is on. Such a tet is refined as one over the radius-edge bound is (its circumcentre,
 * the same refusals); such a piece is queued for splitting as an encroached one is. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "predicates.h"
#include "refine/refine_impl.h"
#include "refine/sizing.h"

tr_status tr_sizing_build(const struct tr_plc *plc, int threads, tr_sizing *s)
{
  memset(s, 0, sizeof *s);
  s->h = plc->vsize;
  /* the doubles only: --resolve's exact corners (the last nxq points) have no size of
   * their own (0); the walk clamps a point beyond the hull to the tet it leaves by */
  tr_status st = tr_delaunay_build_threads(plc->xyz, plc->npoints - plc->nxq, threads, &s->bg);
  if (st != TR_ERR_DEGENERATE || !plc->nxq)
    return st;
  /* the doubles alone span no tet (tr_delaunay_build_exact): the exact corners join at
   * their nearest doubles, with size 0, so the tets at them bound nothing */
  tr_error_clear();
  return tr_delaunay_build_threads(plc->xyz, plc->npoints, threads, &s->bg);
}

void tr_sizing_free(tr_sizing *s)
{
  tr_mesh_destroy(s->bg);
  memset(s, 0, sizeof *s);
}

static double det3(const double *a, const double *b, const double *c, const double *d)
{
  double u[3], v[3], w[3];
  for (int i = 0; i < 3; i++) {
    u[i] = b[i] - a[i];
    v[i] = c[i] - a[i];
    w[i] = d[i] - a[i];
  }
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
         u[2] * (v[0] * w[1] - v[1] * w[0]);
}

double tr_sizing_at(const tr_sizing *s, const double p[3], uint32_t *hint)
{
  const struct tr_mesh *m = s->bg;
  uint32_t t = *hint;
  if (!(t < m->nt && tr_tet_is_real(m, t)))
    for (t = 0; t + 1 < m->nt && !tr_tet_is_real(m, t); t++)
      ; /* the canonical store has its real tets first: t = 0 */
  /* a visibility walk: on a Delaunay tetrahedralization it cannot cycle (Edelsbrunner
   * 1990); the bound only guards against a mistake */
  for (uint64_t step = 0, limit = 4 * (uint64_t)m->nt + 64; step < limit; step++) {
    const uint32_t *v = m->tv + 4 * (size_t)t;
    uint32_t next = TR_NONE;
    for (int k = 0; k < 4 && next == TR_NONE; k++) {
      const uint8_t *f = tr_face_vtx[k];
      if (tr_orient3d(m->xyz + 3 * (size_t)v[f[0]], m->xyz + 3 * (size_t)v[f[1]],
                      m->xyz + 3 * (size_t)v[f[2]], p) < 0)
        next = TR_NEIG(m, t, k);
    }
    if (next == TR_NONE || tr_tet_is_ghost(m, next))
      break; /* inside t, or beyond the hull across a face of t: t's values, clamped */
    t = next;
  }
  *hint = t;
  const uint32_t *v = m->tv + 4 * (size_t)t;
  double w[4], sum = 0, hv = 0;
  for (int k = 0; k < 4; k++) {
    if (!(s->h[v[k]] > 0))
      return 0;
    const uint8_t *f = tr_face_vtx[k];
    w[k] = det3(m->xyz + 3 * (size_t)v[f[0]], m->xyz + 3 * (size_t)v[f[1]],
                m->xyz + 3 * (size_t)v[f[2]], p);
    w[k] = w[k] > 0 ? w[k] : 0;
    sum += w[k];
  }
  for (int k = 0; k < 4; k++)
    hv += (sum > 0 ? w[k] / sum : 0.25) * s->h[v[k]];
  return hv;
}

/* h is linear on the tet, so halving it across the edge whose ends differ most halves
 * the volume and gives the midpoint the mean value; within a ratio of 1.2 the mean of the
 * vertices' h^-3 is close enough for an estimate */
static double inverse_cube(double vol, const double h[4], int depth)
{
  int a = 0, b = 1;
  double lo = h[0], hi = h[0];
  for (int i = 0; i < 4; i++) {
    lo = h[i] < lo ? h[i] : lo;
    hi = h[i] > hi ? h[i] : hi;
    for (int j = i + 1; j < 4; j++)
      if (fabs(h[i] - h[j]) > fabs(h[a] - h[b]))
        a = i, b = j;
  }
  if (hi <= 1.2 * lo || depth >= 48) {
    double s = 0;
    for (int i = 0; i < 4; i++)
      s += 1 / (h[i] * h[i] * h[i]);
    return vol * s / 4;
  }
  double x[4], y[4];
  memcpy(x, h, sizeof x);
  memcpy(y, h, sizeof y);
  x[a] = y[b] = 0.5 * (h[a] + h[b]);
  return inverse_cube(vol / 2, x, depth + 1) + inverse_cube(vol / 2, y, depth + 1);
}

double tr_sizing_inverse_cube(double vol, const double h[4])
{
  return inverse_cube(vol, h, 0);
}

/* ---- refinement's side (refine_impl.h) ---- */

static tr_status room(rf_ctx *c, uint32_t n)
{
  if (n <= c->capvh)
    return TR_OK;
  uint32_t nc = c->capvh ? c->capvh : 64;
  while (nc < n)
    nc = nc > UINT32_MAX / 2 ? UINT32_MAX : 2 * nc;
  double *h = realloc(c->vh, sizeof *h * nc);
  if (!h)
    return tr_error(TR_ERR_NOMEM, "out of memory for the sizes of %u vertices", n);
  memset(h + c->capvh, 0, sizeof *h * (nc - c->capvh));
  c->vh = h;
  c->capvh = nc;
  return TR_OK;
}

tr_status rf_sizing_init(rf_ctx *c)
{
  if (!c->par.sizing)
    return TR_OK;
  TR_CHECK(room(c, c->m->nv + 1));
  uint32_t n = c->par.nvsize < c->m->nv ? c->par.nvsize : c->m->nv;
  memcpy(c->vh, c->par.vsize, sizeof *c->vh * n);
  for (uint32_t v = n; v < c->m->nv; v++)
    c->vh[v] = tr_sizing_at(c->par.sizing, c->m->xyz + 3 * (size_t)v, &c->vh_hint);
  return TR_OK;
}

tr_status rf_sizing_vertex(rf_ctx *c, uint32_t pid)
{
  if (!c->par.sizing)
    return TR_OK;
  TR_CHECK(room(c, pid + 1));
  c->vh[pid] = tr_sizing_at(c->par.sizing, c->m->xyz + 3 * (size_t)pid, &c->vh_hint);
  return TR_OK;
}

/* The longest of the n(n-1)/2 edges of the n vertices v over the mean of their sizes
 * (squared lengths; 0 when one has none) */
static int over(const rf_ctx *c, const uint32_t *v, int n)
{
  double mean = 0, l2 = 0;
  for (int i = 0; i < n; i++) {
    if (v[i] >= c->capvh || !(c->vh[v[i]] > 0))
      return 0; /* a vertex with no size (none came through rf_sizing_vertex) */
    mean += c->vh[v[i]] / n;
    for (int j = i + 1; j < n; j++) {
      double d = rf_dist2(c->m->xyz + 3 * (size_t)v[i], c->m->xyz + 3 * (size_t)v[j]);
      l2 = d > l2 ? d : l2;
    }
  }
  return l2 > mean * mean;
}

int rf_sizing_tet_over(const rf_ctx *c, uint32_t t)
{
  return c->par.sizing && over(c, c->m->tv + 4 * (size_t)t, 4);
}

/* A vertex's insertion radius (or spacing) refuses circumcentres within it so that
 * refinement does not cascade (refine.c, too_close); a vertex put where the field was
 * coarse keeps a radius of that coarse size, and refused every circumcentre the finer
 * field asked for near it (a unit cube graded 0.02 to 0.32 along x+y+z: 4,912 tets left
 * over the field, longest edges 5.2 times their size). A tet over the field has its
 * longest edge over the mean size h, so its circumcentre lies at least h/2 from its
 * vertices: a refusal radius of at most h/2 there refuses only points closer to another
 * vertex than to the tet's own, and every point so inserted is at least half the smallest
 * size from its neighbours, which bounds their number. */
double rf_sizing_cap(const rf_ctx *c, uint32_t t)
{
  if (!rf_sizing_tet_over(c, t))
    return INFINITY;
  const uint32_t *v = c->m->tv + 4 * (size_t)t;
  return 0.125 * (c->vh[v[0]] + c->vh[v[1]] + c->vh[v[2]] + c->vh[v[3]]);
}

tr_status rf_sizing_scan(rf_ctx *c)
{
  if (!c->par.sizing)
    return TR_OK;
  for (; c->size_ss < c->nss; c->size_ss++) {
    uint32_t g = c->size_ss;
    if (!c->ssdead[g] && !c->ssnosplit[g] && over(c, c->ssv + 2 * (size_t)g, 2))
      TR_CHECK(tr_u32buf_push(&c->qseg, g));
  }
  for (; c->size_sf < c->nsf; c->size_sf++) {
    uint32_t f = c->size_sf;
    if (!c->sfdead[f] && !c->sfnosplit[f] && over(c, c->sfv + 3 * (size_t)f, 3))
      TR_CHECK(tr_u32buf_push(&c->qface, f));
  }
  return TR_OK;
}
