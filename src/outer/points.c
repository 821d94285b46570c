/* Hole and region points (tr_plc_add_hole / tr_plc_add_region), applied to the colored
 * mesh: see points.h. Each point is located exactly: first against the input triangles
 * (a point on a facet names no cell: an error), then in the mesh by a scan of the tets
 * whose interval box holds it, with exact orient3d on the (possibly rational) vertices.
 * A point on a face, edge or vertex of the mesh that is not on a facet is inside the
 * closures of tets of one cell only, so the first tet found names its cell. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "points.h"

/* Error if P lies on an input triangle (closed). */
static tr_status on_facet(const struct tr_plc *plc, const double *p, const char *what,
                          uint32_t i)
{
  tr_point P = tr_pt_d(p);
  for (uint32_t t = 0; t < plc->ntris; t++) {
    const uint32_t *v = plc->tris + 3 * (size_t)t;
    const double *a = plc->xyz + 3 * (size_t)v[0], *b = plc->xyz + 3 * (size_t)v[1],
                 *c = plc->xyz + 3 * (size_t)v[2];
    int out = 0;
    for (int d = 0; d < 3 && !out; d++) {
      double lo = a[d] < b[d] ? a[d] : b[d], hi = a[d] < b[d] ? b[d] : a[d];
      lo = c[d] < lo ? c[d] : lo;
      hi = c[d] > hi ? c[d] : hi;
      out = p[d] < lo || p[d] > hi;
    }
    if (out)
      continue;
    tr_point A = tr_pt_d(a), B = tr_pt_d(b), C = tr_pt_d(c);
    if (tr_classify_segment_triangle(&P, &P, &A, &B, &C).n)
      return tr_error(TR_ERR_INPUT,
                      "%s %u (%.17g, %.17g, %.17g) lies on triangle %u (input face %u): it "
                      "must lie strictly inside a cell", what, i, p[0], p[1], p[2], t,
                      plc->tri_source ? plc->tri_source[t] : t);
  }
  return TR_OK;
}

static void widen(const struct tr_mesh *m, uint32_t v, double lo[3], double hi[3])
{
  const tr_qpoint *q = m->vq ? m->vq[v] : NULL;
  for (int d = 0; d < 3; d++) {
    double a = q ? q->lo[d] : m->xyz[3 * (size_t)v + d], b = q ? q->hi[d] : a;
    lo[d] = a < lo[d] ? a : lo[d];
    hi[d] = b > hi[d] ? b : hi[d];
  }
}

/* A real tet whose closure holds p, or TR_NONE (outside the convex hull). */
static uint32_t locate(const struct tr_mesh *m, const double *p)
{
  tr_point P = tr_pt_d(p);
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    const uint32_t *tv = m->tv + 4 * (size_t)t;
    double lo[3] = {p[0], p[1], p[2]}, hi[3] = {p[0], p[1], p[2]};
    lo[0] = hi[0] = m->xyz[3 * (size_t)tv[0]];
    lo[1] = hi[1] = m->xyz[3 * (size_t)tv[0] + 1];
    lo[2] = hi[2] = m->xyz[3 * (size_t)tv[0] + 2];
    for (int k = 0; k < 4; k++)
      widen(m, tv[k], lo, hi);
    if (p[0] < lo[0] || p[1] < lo[1] || p[2] < lo[2] || p[0] > hi[0] || p[1] > hi[1] ||
        p[2] > hi[2])
      continue;
    tr_point V[4];
    for (int k = 0; k < 4; k++)
      V[k] = tr_mesh_point(m, tv[k]);
    int in = 1;
    for (int k = 0; k < 4 && in; k++) {
      tr_point W[4] = {V[0], V[1], V[2], V[3]};
      W[k] = P;
      in = tr_orient3d_p(&W[0], &W[1], &W[2], &W[3]) >= 0; /* tets are positive */
    }
    if (in)
      return t;
  }
  return TR_NONE;
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
  tr_status st = TR_OK;
  if (!hole || !named) {
    st = tr_error(TR_ERR_NOMEM, "out of memory applying hole and region points");
    goto done;
  }
  for (uint32_t i = 0; i < plc->nholes + plc->nregions && st == TR_OK; i++) {
    int is_hole = i < plc->nholes;
    uint32_t j = is_hole ? i : i - plc->nholes;
    const double *p = is_hole ? plc->holes + 3 * (size_t)j : plc->region_xyz + 3 * (size_t)j;
    const char *what = is_hole ? "hole point" : "region point";
    if ((st = on_facet(plc, p, what, j)) != TR_OK)
      break;
    uint32_t t = locate(m, p);
    uint32_t r = t == TR_NONE ? 0 : m->region[t];
    if (r == 0) {
      /* a hole there removes nothing; an attribute there cannot be honoured */
      if (!is_hole) {
        st = tr_error(TR_ERR_INPUT,
                      "region point %u (%.17g, %.17g, %.17g) lies outside the domain", j,
                      p[0], p[1], p[2]);
        break;
      }
      if (plc->hole_cavity && plc->hole_cavity[j]) {
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
  return st;
}
