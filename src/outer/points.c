/* Hole and region points (tr_plc_add_hole / tr_plc_add_region), applied to the colored
 * mesh: see points.h. Each point is located exactly: first against the input triangles
 * (a point on a facet names no cell: an error), then among the inner tets whose interval
 * box holds it, with exact orient3d on the (possibly rational) vertices. A point on a
 * face, edge or vertex of the mesh that is not on a facet is inside the closures of tets of
 * one cell only (cells, the outside among them, meet only on facets), so any tet found
 * names its cell, and a point in no inner tet lies outside the domain.
 *
 * All points are located in one pass over the triangles and one over the tets: the points
 * sit in a uniform grid (pgrid) and each triangle or tet asks only the cells its box
 * overlaps. A scan of everything per point made thousands of region points cost more
 * than the mesh (20,000 in a sphere holding 1000 cavities, 325,120 triangles: 90 s of CPU,
 * 2.0 s with the grid). A point records the
 * first triangle it lies on, in index order, so the messages name the same triangle as a
 * scan would. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "core/box.h"
#include "points.h"

/* Up to 64 cells per axis, about one point per cell. */
#define PG_MAX_RES 64u

typedef struct {
  uint32_t res[3];
  double lo[3], scale[3]; /* the cell of x along d: floor((x - lo[d]) * scale[d]), clamped */
  uint32_t *start, *item; /* the points of cell c: item[start[c] .. start[c + 1]) */
  const double *const *p; /* p[i]: point i's coordinates */
} pgrid;

/* Monotone in x (rounding is), so a box that holds a point covers the point's cell; safe
 * for any double: NaN and everything below lo go to cell 0. */
static uint32_t cell_of(const pgrid *g, int d, double x)
{
  double c = (x - g->lo[d]) * g->scale[d];
  if (!(c > 0))
    return 0;
  return c >= (double)g->res[d] ? g->res[d] - 1 : (uint32_t)c;
}

static uint32_t cell_index(const pgrid *g, const uint32_t k[3])
{
  return (k[2] * g->res[1] + k[1]) * g->res[0] + k[0];
}

static tr_status pgrid_build(pgrid *g, const double *const *p, uint32_t n)
{
  memset(g, 0, sizeof *g);
  g->p = p;
  double hi[3] = {0, 0, 0};
  for (int d = 0; d < 3 && n; d++)
    g->lo[d] = hi[d] = p[0][d];
  for (uint32_t i = 1; i < n; i++)
    for (int d = 0; d < 3; d++) {
      g->lo[d] = p[i][d] < g->lo[d] ? p[i][d] : g->lo[d];
      hi[d] = p[i][d] > hi[d] ? p[i][d] : hi[d];
    }
  uint32_t r = (uint32_t)ceil(cbrt((double)n));
  r = r < 1 ? 1 : r > PG_MAX_RES ? PG_MAX_RES : r;
  for (int d = 0; d < 3; d++) {
    double ext = hi[d] - g->lo[d];
    g->res[d] = ext > 0 && isfinite(ext) ? r : 1;
    g->scale[d] = g->res[d] > 1 ? (double)g->res[d] / ext : 0;
  }
  size_t ncell = (size_t)g->res[0] * g->res[1] * g->res[2];
  g->start = calloc(ncell + 1, sizeof *g->start);
  g->item = malloc(sizeof *g->item * n);
  uint32_t *cell = malloc(sizeof *cell * n);
  if (!g->start || !g->item || !cell) {
    free(cell);
    return tr_error(TR_ERR_NOMEM, "out of memory locating %u hole and region points", n);
  }
  for (uint32_t i = 0; i < n; i++) {
    uint32_t k[3] = {cell_of(g, 0, p[i][0]), cell_of(g, 1, p[i][1]), cell_of(g, 2, p[i][2])};
    cell[i] = cell_index(g, k);
    g->start[cell[i] + 1]++;
  }
  for (size_t c = 0; c < ncell; c++)
    g->start[c + 1] += g->start[c];
  for (uint32_t i = 0; i < n; i++) /* points of a cell in index order */
    g->item[g->start[cell[i]]++] = i;
  for (size_t c = ncell; c > 0; c--)
    g->start[c] = g->start[c - 1];
  g->start[0] = 0;
  free(cell);
  return TR_OK;
}

static void pgrid_free(pgrid *g)
{
  free(g->start);
  free(g->item);
}

/* Calls hit(ud, i) for every point i in the closed box [lo, hi] whose found[i] is still
 * TR_NONE; hit may set it. */
static void pgrid_query(const pgrid *g, const double lo[3], const double hi[3],
                        const uint32_t *found, void (*hit)(void *, uint32_t), void *ud)
{
  uint32_t a[3], b[3], k[3];
  for (int d = 0; d < 3; d++) {
    a[d] = cell_of(g, d, lo[d]);
    b[d] = cell_of(g, d, hi[d]);
  }
  for (k[2] = a[2]; k[2] <= b[2]; k[2]++)
    for (k[1] = a[1]; k[1] <= b[1]; k[1]++)
      for (k[0] = a[0]; k[0] <= b[0]; k[0]++) {
        uint32_t c = cell_index(g, k);
        for (uint32_t j = g->start[c]; j < g->start[c + 1]; j++) {
          uint32_t i = g->item[j];
          const double *q = g->p[i];
          if (found[i] != TR_NONE || q[0] < lo[0] || q[1] < lo[1] || q[2] < lo[2] ||
              q[0] > hi[0] || q[1] > hi[1] || q[2] > hi[2])
            continue;
          hit(ud, i);
        }
      }
}

typedef struct {
  const struct tr_plc *plc;
  const struct tr_mesh *m;
  const pgrid *g;
  uint32_t cur;   /* the triangle or tet being asked */
  uint32_t *found; /* per point: the first triangle it lies on / a tet that holds it */
} asker;

static void on_triangle(void *ud, uint32_t i)
{
  asker *q = ud;
  const uint32_t *v = q->plc->tris + 3 * (size_t)q->cur;
  tr_point P = tr_pt_d(q->g->p[i]);
  tr_point A = tr_plc_point(q->plc, v[0]), B = tr_plc_point(q->plc, v[1]),
           C = tr_plc_point(q->plc, v[2]);
  if (tr_classify_segment_triangle(&P, &P, &A, &B, &C).n)
    q->found[i] = q->cur;
}

static void in_tet(void *ud, uint32_t i)
{
  asker *q = ud;
  const uint32_t *tv = q->m->tv + 4 * (size_t)q->cur;
  tr_point P = tr_pt_d(q->g->p[i]), V[4];
  for (int k = 0; k < 4; k++)
    V[k] = tr_mesh_point(q->m, tv[k]);
  for (int k = 0; k < 4; k++) {
    tr_point W[4] = {V[0], V[1], V[2], V[3]};
    W[k] = P;
    if (tr_orient3d_p(&W[0], &W[1], &W[2], &W[3]) < 0) /* tets are positive */
      return;
  }
  q->found[i] = q->cur;
}

/* The interval box of points v[0..n-1]: their doubles, widened to the exact bounds of
 * those that are rational points (xq NULL: none; a Steiner point's or --resolve's corner's
 * double is only near it). */
static void exact_box(const double *xyz, tr_qpoint *const *xq, const uint32_t *v, int n,
                      double lo[3], double hi[3])
{
  tr_box_of(xyz, v, n, lo, hi);
  for (int k = 0; k < n; k++) {
    const tr_qpoint *q = xq ? xq[v[k]] : NULL;
    for (int d = 0; q && d < 3; d++) {
      lo[d] = q->lo[d] < lo[d] ? q->lo[d] : lo[d];
      hi[d] = q->hi[d] > hi[d] ? q->hi[d] : hi[d];
    }
  }
}

static void tet_box(const struct tr_mesh *m, uint32_t t, double lo[3], double hi[3])
{
  exact_box(m->xyz, m->vq, m->tv + 4 * (size_t)t, 4, lo, hi);
}

static void tri_box(const struct tr_plc *plc, uint32_t t, double lo[3], double hi[3])
{
  exact_box(plc->xyz, plc->xq, plc->tris + 3 * (size_t)t, 3, lo, hi);
}

/* facet[i]: the first input triangle point i lies on (closed), TR_NONE if none;
 * tet[i]: an inner tet whose closure holds it, TR_NONE if none (outside the domain). */
static tr_status locate_all(const struct tr_mesh *m, const struct tr_plc *plc,
                            const double *const *p, uint32_t n, uint32_t *facet, uint32_t *tet)
{
  pgrid g;
  TR_CHECK(pgrid_build(&g, p, n));
  for (uint32_t i = 0; i < n; i++)
    facet[i] = tet[i] = TR_NONE;
  asker q = {plc, m, &g, 0, facet};
  for (uint32_t t = 0; t < plc->ntris; t++) {
    double lo[3], hi[3];
    tri_box(plc, t, lo, hi);
    q.cur = t;
    pgrid_query(&g, lo, hi, facet, on_triangle, &q);
  }
  q.found = tet;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t) || !m->region[t])
      continue;
    double lo[3], hi[3];
    tet_box(m, t, lo, hi);
    q.cur = t;
    pgrid_query(&g, lo, hi, tet, in_tet, &q);
  }
  pgrid_free(&g);
  return TR_OK;
}

tr_status tr_outer_points(struct tr_mesh *m, const struct tr_plc *plc, int verbose,
                          uint32_t *nregions)
{
  if (plc->nholes == 0 && plc->nregions == 0)
    return TR_OK;
  uint32_t n = *nregions;
  /* per region id 0..n: 1 emptied by a hole; the region point that names it + 1 */
  uint8_t *hole = calloc((size_t)n + 1, 1);
  uint32_t *named = calloc((size_t)n + 1, sizeof *named), *newid = NULL;
  uint32_t np = plc->nholes + plc->nregions;
  const double **pts = malloc(sizeof *pts * np);
  uint32_t *facet = malloc(sizeof *facet * np), *tet = malloc(sizeof *tet * np);
  tr_status st = TR_OK;
  if (!hole || !named || !pts || !facet || !tet) {
    st = tr_error(TR_ERR_NOMEM, "out of memory applying hole and region points");
    goto done;
  }
  for (uint32_t i = 0; i < np; i++)
    pts[i] = i < plc->nholes ? plc->holes + 3 * (size_t)i
                             : plc->region_xyz + 3 * (size_t)(i - plc->nholes);
  if ((st = locate_all(m, plc, pts, np, facet, tet)) != TR_OK)
    goto done;
  for (uint32_t i = 0; i < np && st == TR_OK; i++) {
    int is_hole = i < plc->nholes;
    uint32_t j = is_hole ? i : i - plc->nholes;
    const double *p = pts[i];
    const char *what = is_hole ? "hole point" : "region point";
    if (facet[i] != TR_NONE) {
      uint32_t t = facet[i];
      st = tr_error(TR_ERR_INPUT,
                    "%s %u (%.17g, %.17g, %.17g) lies on triangle %u (input face %u): it "
                    "must lie strictly inside a cell", what, j, p[0], p[1], p[2], t,
                    plc->tri_source ? plc->tri_source[t] : t);
      break;
    }
    uint32_t t = tet[i];
    uint32_t r = t == TR_NONE ? 0 : m->region[t];
    if (r == 0) {
      /* a hole there removes nothing; an attribute there cannot be honoured */
      if (!is_hole) {
        st = tr_error(TR_ERR_INPUT,
                      "region point %u (%.17g, %.17g, %.17g) lies outside the domain", j,
                      p[0], p[1], p[2]);
        break;
      }
      /* Validation knows why the cell is empty: a hole point there did what it asked;
       * only one outside every shell removes nothing. */
      uint8_t why = plc->hole_cavity ? plc->hole_cavity[j] : 0;
      if (why == TR_HOLE_IN_CAVITY) {
        if (verbose >= 2)
          fprintf(stderr, "tetrec: hole point %u lies in a cavity the surface already leaves "
                          "empty\n", j);
      } else if (why) {
        if (verbose >= 2)
          fprintf(stderr, "tetrec: hole point %u: its cell was made empty by validation\n", j);
      } else if (verbose >= 1)
        fprintf(stderr,
                "tetrec: warning: hole point %u (%.17g, %.17g, %.17g) lies outside the "
                "domain: it removes nothing\n", j, p[0], p[1], p[2]);
      continue;
    }
    if (is_hole) {
      hole[r] = 1;
      if (verbose >= 2)
        fprintf(stderr, "tetrec: hole point %u empties region %u\n", j, r);
      continue;
    }
    if (named[r] && plc->region_attr[named[r] - 1] != plc->region_attr[j]) {
      st = tr_error(TR_ERR_INPUT,
                    "region points %u and %u lie in the same cell with different attributes "
                    "(%d, %d)", named[r] - 1, j, plc->region_attr[named[r] - 1],
                    plc->region_attr[j]);
      break;
    }
    if (!named[r])
      named[r] = j + 1;
  }
  if (st != TR_OK)
    goto done;
  for (uint32_t r = 1; r <= n; r++)
    if (hole[r] && named[r]) {
      st = tr_error(TR_ERR_INPUT, "region point %u lies in a cell a hole point empties",
                    named[r] - 1);
      goto done;
    }
  /* Ids: a region point's attribute, else the coloring's order among the regions left. */
  if (!(newid = malloc(sizeof *newid * ((size_t)n + 1)))) {
    st = tr_error(TR_ERR_NOMEM, "out of memory applying hole and region points");
    goto done;
  }
  uint32_t k = 0;
  newid[0] = 0;
  for (uint32_t r = 1; r <= n; r++) {
    newid[r] = hole[r] ? 0 : named[r] ? (uint32_t)plc->region_attr[named[r] - 1] : ++k;
    if (named[r] && verbose >= 2)
      fprintf(stderr, "tetrec: region point %u gives region %u attribute %d\n", named[r] - 1,
              r, plc->region_attr[named[r] - 1]);
  }
  for (uint32_t t = 0; t < m->nt; t++) {
    if (tr_tet_is_free(m, t))
      continue;
    uint32_t r = m->region[t];
    if (r && hole[r])
      m->flags[t] |= TR_TF_OUTER;
    m->region[t] = newid[r];
  }
  uint32_t left = 0;
  for (uint32_t r = 1; r <= n; r++)
    left += !hole[r];
  *nregions = left;
done:
  free(hole);
  free(named);
  free(newid);
  free(pts);
  free(facet);
  free(tet);
  return st;
}
