/* Edge flips that improve the shape of a polygon's triangulation.
 *
 * Ear clipping takes the first ear it finds, which on a convex or nearly convex polygon
 * makes a fan of thin triangles from one corner; their small angles become input angles
 * that refinement must then protect, and the mesh keeps the bad tets around them. Here
 * every diagonal (never a side of the polygon or of a hole) is flipped when that raises
 * the smaller of the two triangles' minimum angles (Lawson's local max-min-angle
 * criterion), until no diagonal can be improved.
 *
 * Validity is exact: a flip is made only when the quadrilateral of the two triangles is
 * strictly convex in the polygon's projection (tr_orient2d on the exact projected
 * doubles), so the two new triangles are counterclockwise, non-degenerate and cover the
 * same region; the result is a triangulation of the same polygon with the orientation
 * of its input loop. The angle measure, on the other hand, is a double-valued choice
 * and no validity decision: for a planar polygon it selects the constrained Delaunay
 * triangulation (up to rounding between nearly cocircular quadrilaterals, where either
 * diagonal is as good), for a non-planar one it is a heuristic on the 3D triangles.
 *
 * Termination: a flip strictly raises the minimum of its six angles, so the sorted list
 * of the triangles' measures (each a fixed function of the triangle, computed in a
 * canonical vertex order) rises lexicographically and no triangulation comes back; the
 * number of flips is also capped so that the work stays bounded whatever the rounding
 * does. Everything is sequential over arrays in a fixed order: same input, same output. */
#include "polyflip.h"
#include "soup.h"

#include <math.h>
#include <stdlib.h>

#include "predicates.h"

#define NONE UINT32_MAX

double tr_polyflip_shape(const double *a, const double *b, const double *c)
{
  double e[3][3], m = 0;
  for (int k = 0; k < 3; k++) {
    e[0][k] = b[k] - a[k];
    e[1][k] = c[k] - b[k];
    e[2][k] = a[k] - c[k];
    for (int i = 0; i < 3; i++)
      m = fabs(e[i][k]) > m ? fabs(e[i][k]) : m;
  }
  if (!(m > 0) || !isfinite(m))
    return 0;
  /* A power-of-two scale (exact) keeps squares of squares away from overflow and
   * underflow; the measure does not depend on the scale. */
  int ex;
  frexp(m, &ex);
  double s = ldexp(1.0, -ex), l[3];
  for (int i = 0; i < 3; i++) {
    for (int k = 0; k < 3; k++)
      e[i][k] *= s;
    l[i] = e[i][0] * e[i][0] + e[i][1] * e[i][1] + e[i][2] * e[i][2];
  }
  double n[3] = {e[0][1] * e[1][2] - e[0][2] * e[1][1], e[0][2] * e[1][0] - e[0][0] * e[1][2],
                 e[0][0] * e[1][1] - e[0][1] * e[1][0]};
  double n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  /* The smallest angle faces the shortest side; its sine is twice the area over the
   * product of the two other sides. */
  double lo = l[0] < l[1] ? l[0] : l[1], hi = l[0] < l[1] ? l[1] : l[0], mid;
  if (l[2] < lo) {
    mid = lo;
  } else if (l[2] > hi) {
    mid = hi;
    hi = l[2];
  } else
    mid = l[2];
  double d = mid * hi;
  return d > 0 ? n2 / d : 0;
}

/* The measure of a triangle of local vertices, from its rotation that starts at the
 * smallest local vertex, so that it is one value per triangle. */
static double shape_of(const tr_polyflip_in *in, uint32_t v0, uint32_t v1, uint32_t v2)
{
  uint32_t r[3] = {v0, v1, v2};
  int s = v1 < v0 ? (v2 < v1 ? 2 : 1) : (v2 < v0 ? 2 : 0);
  const double *x = in->xyz;
  return tr_polyflip_shape(x + 3 * (size_t)in->id[r[s]], x + 3 * (size_t)in->id[r[(s + 1) % 3]],
                           x + 3 * (size_t)in->id[r[(s + 2) % 3]]);
}

static int o2(const tr_polyflip_in *in, uint32_t a, uint32_t b, uint32_t c)
{
  return tr_sign(tr_orient2d(in->p[a], in->p[b], in->p[c]));
}

typedef struct {
  uint64_t key; /* the edge's two local vertices, smaller one high */
  uint32_t h;   /* half-edge: 3 * triangle + the corner it faces */
} hedge;

static int hedge_cmp(const void *x, const void *y)
{
  const hedge *a = x, *b = y;
  if (a->key != b->key)
    return a->key < b->key ? -1 : 1;
  return (a->h > b->h) - (a->h < b->h);
}

static uint32_t from_of(const uint32_t *T, uint32_t h) { return T[3 * (h / 3) + (h % 3 + 1) % 3]; }
static uint32_t to_of(const uint32_t *T, uint32_t h) { return T[3 * (h / 3) + (h % 3 + 2) % 3]; }

/* nb[h] = the opposite half-edge across a flippable diagonal, NONE across a side (or
 * anything that is not exactly two opposite half-edges, which a valid triangulation
 * never has: then the edge is simply left alone). */
static tr_status pair_up(const tr_polyflip_in *in, uint32_t *nb)
{
  uint32_t nh = 3 * in->ntri;
  hedge *e = malloc(sizeof *e * nh);
  if (!e)
    return tr_error(TR_ERR_NOMEM, "out of memory improving a polygon's triangulation");
  for (uint32_t h = 0; h < nh; h++) {
    uint32_t a = from_of(in->tri, h), b = to_of(in->tri, h);
    uint32_t lo = a < b ? a : b, hi = a < b ? b : a;
    e[h].key = (uint64_t)lo << 32 | hi;
    e[h].h = h;
    nb[h] = NONE;
  }
  qsort(e, nh, sizeof *e, hedge_cmp);
  for (uint32_t i = 0, j; i < nh; i = j) {
    for (j = i + 1; j < nh && e[j].key == e[i].key; j++)
      ;
    if (j - i != 2)
      continue;
    uint32_t h = e[i].h, g = e[i + 1].h;
    uint32_t a = from_of(in->tri, h), b = to_of(in->tri, h);
    if (in->next[a] == b || in->next[b] == a)
      continue; /* a side of the polygon or of a hole */
    if (from_of(in->tri, g) != b || to_of(in->tri, g) != a)
      continue;
    nb[h] = g;
    nb[g] = h;
  }
  free(e);
  return TR_OK;
}

tr_status tr_polyflip(tr_polyflip_in *in, uint32_t *nflips)
{
  uint32_t nt = in->ntri, *T = in->tri, done = 0;
  if (nflips)
    *nflips = 0;
  if (nt < 2)
    return TR_OK;
  uint32_t *nb = malloc(sizeof *nb * 3 * (size_t)nt);
  double *q = malloc(sizeof *q * nt);
  tr_u32vec s = {0}; /* half-edges to test */
  tr_status st = TR_OK;
  if (!nb || !q) {
    st = tr_error(TR_ERR_NOMEM, "out of memory improving a polygon's triangulation");
    goto out;
  }
  st = pair_up(in, nb);
  for (uint32_t t = 0; t < nt && st == TR_OK; t++)
    q[t] = shape_of(in, T[3 * t], T[3 * t + 1], T[3 * t + 2]);
  /* Pushed in reverse so that the first diagonal of the first triangle is tried first. */
  for (uint32_t h = 3 * nt; h-- > 0 && st == TR_OK;)
    if (nb[h] != NONE && h < nb[h])
      st = tr_u32vec_push(&s, h);
  /* Lawson's flips take O(n^2) in the worst case; the cap only bounds what rounding in
   * the measure could add to that. */
  uint64_t cap = (uint64_t)nt * nt + 16 * (uint64_t)nt;
  while (st == TR_OK && s.n > 0 && done < cap) {
    uint32_t h = s.a[--s.n], g = nb[h];
    if (g == NONE)
      continue;
    uint32_t t = h / 3, k = h % 3, u = g / 3, j = g % 3;
    uint32_t a = T[3 * t + k], b = T[3 * t + (k + 1) % 3], c = T[3 * t + (k + 2) % 3];
    uint32_t d = T[3 * u + j];
    /* t = abc and u = dcb are counterclockwise; the quadrilateral a b d c is strictly
     * convex iff the new triangles abd and adc are too. */
    if (o2(in, a, b, d) <= 0 || o2(in, a, d, c) <= 0)
      continue;
    double q1 = shape_of(in, a, b, d), q2 = shape_of(in, a, d, c);
    double old = q[t] < q[u] ? q[t] : q[u], new = q1 < q2 ? q1 : q2;
    if (!(new > old))
      continue;
    uint32_t n_ca = nb[3 * t + (k + 1) % 3], n_ab = nb[3 * t + (k + 2) % 3];
    uint32_t n_bd = nb[3 * u + (j + 1) % 3], n_dc = nb[3 * u + (j + 2) % 3];
    T[3 * t] = a, T[3 * t + 1] = b, T[3 * t + 2] = d;
    T[3 * u] = a, T[3 * u + 1] = d, T[3 * u + 2] = c;
    q[t] = q1;
    q[u] = q2;
    /* t: bd faces a, da faces b, ab faces d; u: dc faces a, ca faces d, ad faces c. */
    uint32_t ht[3] = {n_bd, 3 * u + 2, n_ab}, hu[3] = {n_dc, n_ca, 3 * t + 1};
    for (int i = 0; i < 3; i++) {
      nb[3 * t + i] = ht[i];
      nb[3 * u + i] = hu[i];
    }
    for (int i = 0; i < 3; i++) {
      if (i != 1 && ht[i] != NONE)
        nb[ht[i]] = 3 * t + (uint32_t)i;
      if (i != 2 && hu[i] != NONE)
        nb[hu[i]] = 3 * u + (uint32_t)i;
    }
    done++;
    /* The four outer edges now border a new triangle: test them again. */
    uint32_t again[4] = {3 * t, 3 * t + 2, 3 * u, 3 * u + 1};
    for (int i = 0; i < 4 && st == TR_OK; i++)
      if (nb[again[i]] != NONE)
        st = tr_u32vec_push(&s, again[i]);
  }
  if (nflips)
    *nflips = done;
out:
  free(nb);
  free(q);
  tr_u32vec_free(&s);
  return st;
}
