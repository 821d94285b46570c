/* Exact detection of improperly intersecting input triangles.
 *
 * Two triangles may meet only in a common vertex or a common edge. Broad phase: sort by
 * the low x of the bounding boxes and sweep (boxes are exact doubles, compared closed).
 * Narrow phase: if the non-shared corners of one triangle lie strictly on one side of
 * the other's plane, the two can only meet in the shared vertices (exact orient3d).
 * Otherwise the intersection of two closed triangles, when not empty, contains a point
 * of an edge of one of them, so classifying the six edges against the other triangle
 * (classify.h, exact, coplanar overlaps included) finds it; a hit is allowed only at a
 * vertex the two triangles share. */
#include <stdlib.h>

#include "classify.h"
#include "predicates.h"
#include "validate.h"

typedef struct {
  const struct tr_plc *plc;
  double *lo; /* 3 per triangle */
  int axis;   /* sweep axis: the longest extent of the input, fewest overlaps */
} sweep;

static int cmp_lox(const void *ctx, uint32_t a, uint32_t b)
{
  const sweep *s = ctx;
  double x = s->lo[3 * (size_t)a + s->axis], y = s->lo[3 * (size_t)b + s->axis];
  return (x > y) - (x < y);
}

static const double *P(const struct tr_plc *plc, uint32_t v) { return plc->xyz + 3 * (size_t)v; }

/* Non-shared corners of u strictly on one side of the plane of t. */
static int one_side(const struct tr_plc *plc, const uint32_t *t, const uint32_t *u)
{
  int side = 0;
  for (int k = 0; k < 3; k++) {
    if (u[k] == t[0] || u[k] == t[1] || u[k] == t[2])
      continue;
    int s = tr_sign(tr_orient3d(P(plc, t[0]), P(plc, t[1]), P(plc, t[2]), P(plc, u[k])));
    if (s == 0 || (side && s != side))
      return 0;
    side = s;
  }
  return side != 0;
}

/* Edges of t against triangle u: 1 if some hit is not at a shared vertex. */
static int edges_hit(const struct tr_plc *plc, const uint32_t *t, const uint32_t *u)
{
  tr_point U[3];
  for (int k = 0; k < 3; k++)
    U[k] = tr_pt_d(P(plc, u[k]));
  for (int k = 0; k < 3; k++) {
    uint32_t a = t[k], b = t[(k + 1) % 3];
    tr_point A = tr_pt_d(P(plc, a)), B = tr_pt_d(P(plc, b));
    tr_isect r = tr_classify_segment_triangle(&A, &B, &U[0], &U[1], &U[2]);
    for (int i = 0; i < r.n; i++) {
      const tr_hit *h = &r.end[i];
      int ok = h->type == TR_NOD && h->code < 3 && (u[h->code] == a || u[h->code] == b);
      if (!ok)
        return 1;
    }
  }
  return 0;
}

static int improper(const struct tr_plc *plc, uint32_t i, uint32_t j)
{
  const uint32_t *t = plc->tris + 3 * (size_t)i, *u = plc->tris + 3 * (size_t)j;
  if (one_side(plc, t, u) || one_side(plc, u, t))
    return 0;
  return edges_hit(plc, t, u) || edges_hit(plc, u, t);
}

tr_status tr_input_self_intersections(const struct tr_plc *plc, const uint32_t *tri_orig)
{
  uint32_t n = plc->ntris;
  sweep s = {plc, malloc(sizeof(double) * 6 * (size_t)(n ? n : 1)), 0};
  uint32_t *ord = malloc(sizeof *ord * (n ? n : 1));
  tr_status st = TR_OK;
  if (!s.lo || !ord) {
    st = tr_error(TR_ERR_NOMEM, "out of memory checking self-intersections");
    goto done;
  }
  double *hi = s.lo + 3 * (size_t)n;
  for (uint32_t t = 0; t < n; t++) {
    ord[t] = t;
    for (int d = 0; d < 3; d++) {
      double lo = P(plc, plc->tris[3 * (size_t)t])[d], h = lo;
      for (int k = 1; k < 3; k++) {
        double x = P(plc, plc->tris[3 * (size_t)t + k])[d];
        lo = x < lo ? x : lo;
        h = x > h ? x : h;
      }
      s.lo[3 * (size_t)t + d] = lo;
      hi[3 * (size_t)t + d] = h;
    }
  }
  double ext[3] = {0, 0, 0};
  for (int d = 0; d < 3 && n; d++) {
    double lo = s.lo[d], h = hi[d];
    for (uint32_t t = 1; t < n; t++) {
      lo = s.lo[3 * (size_t)t + d] < lo ? s.lo[3 * (size_t)t + d] : lo;
      h = hi[3 * (size_t)t + d] > h ? hi[3 * (size_t)t + d] : h;
    }
    ext[d] = h - lo; /* only a heuristic: rounding here cannot change any answer */
  }
  s.axis = ext[1] > ext[s.axis] ? 1 : s.axis;
  s.axis = ext[2] > ext[s.axis] ? 2 : s.axis;
  int a1 = (s.axis + 1) % 3, a2 = (s.axis + 2) % 3;
  if ((st = tr_sort_ids(ord, n, cmp_lox, &s)) != TR_OK)
    goto done;
  for (uint32_t a = 0; a < n; a++) {
    uint32_t i = ord[a];
    for (uint32_t b = a + 1;
         b < n && s.lo[3 * (size_t)ord[b] + s.axis] <= hi[3 * (size_t)i + s.axis]; b++) {
      uint32_t j = ord[b];
      if (s.lo[3 * (size_t)j + a1] > hi[3 * (size_t)i + a1] ||
          s.lo[3 * (size_t)i + a1] > hi[3 * (size_t)j + a1] ||
          s.lo[3 * (size_t)j + a2] > hi[3 * (size_t)i + a2] ||
          s.lo[3 * (size_t)i + a2] > hi[3 * (size_t)j + a2])
        continue;
      if (improper(plc, i, j)) {
        uint32_t x = i < j ? i : j, y = i < j ? j : i;
        st = tr_error(TR_ERR_SELF_INTERSECT,
                      "%s%striangles %u and %u intersect (input faces %u and %u)",
                      plc->source ? plc->source : "", plc->source ? ": " : "",
                      tri_orig ? tri_orig[x] : x, tri_orig ? tri_orig[y] : y,
                      plc->tri_source ? plc->tri_source[x] : x,
                      plc->tri_source ? plc->tri_source[y] : y);
        goto done;
      }
    }
  }
done:
  free(s.lo);
  free(ord);
  return st;
}
