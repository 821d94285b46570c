/* Exact detection of improperly intersecting input triangles.
 *
 * Two triangles may meet only in a common vertex or a common edge. Broad phase: a uniform
 * grid of cells about the size of a triangle's box; each triangle is listed in the cells
 * its box covers, and a pair whose boxes meet (exact doubles, compared closed) is tested
 * in the one cell that holds the low corner of the boxes' intersection. Cell indices come
 * from rounded arithmetic, which is harmless: the same monotone function places boxes
 * and corners, so that corner's cell is covered by both boxes. Surfaces whose boxes would
 * fill too many cells (long slivers across the domain) take a sweep along the longest
 * axis instead, which tests the same pairs.
 * Narrow phase: if the non-shared corners of one triangle lie strictly on one side of
 * the other's plane, the two can only meet in the shared vertices (exact orient3d). If
 * they all lie on it, the two are coplanar and a 2D test decides (coplanar_improper).
 * Otherwise the general path (method TR_SELFINT_REFERENCE, the tests' oracle): the
 * intersection of two closed triangles, when not empty, contains a point of an edge of
 * one of them, so classifying the six edges against the other triangle (classify.h,
 * exact, coplanar overlaps included) finds it; a hit is allowed only at a vertex the two
 * triangles share.
 * Shortcuts, each exact and checked against the general path by the tests: a triangle
 * lying in a plane x, y or z = const (most faces of CAD models, where orient3d is exactly
 * 0 and its adaptive stages run to the end) takes the side of a point from one coordinate
 * comparison; pairs whose planes meet in a line compare where each triangle meets that
 * line, two orient3d from the side signs already known, every degenerate sign included
 * (selfint_line.c; the six segment classifications cost ~20 times more, most of it in
 * the exact zeros of corners on the other's plane); coplanar pairs take 2D tests. */
#include <math.h>
#include <stdlib.h>

#include "classify.h"
#include "core/box.h"
#include "predicates.h"
#include "selfint_line.h"
#include "validate.h"

typedef struct {
  const struct tr_plc *plc;
  double *lo, *hi; /* 3 per triangle */
  int axis;        /* sweep axis: the longest extent of the input, fewest overlaps */
  /* plane[t] != 0: triangle t lies in the plane {x_k = const}, k = (plane[t] & 3) - 1,
   * and bit 2 is set when its normal points to -x_k; NULL: the reference path */
  uint8_t *plane;
  /* proj[t] (with plane): the axis k = proj[t] & 3 whose projection is t's 2D view, and
   * bit 2 set when t is clockwise there; NO_PROJ: t is flat in every projection */
  uint8_t *proj;
  /* o3[t] (with plane): t's cross product for the side of points (tr_o3plane) */
  tr_o3plane *o3;
  uint32_t bx, by; /* the improper pair found first in (x, y) order, x < y; bx = n: none */
  /* collect mode (tr_input_self_intersection_pairs): every improper pair, 2 per pair */
  int collect, oom;
  uint32_t *pairs;
  size_t npairs, cap;
} sweep;

static int cmp_lox(const void *ctx, uint32_t a, uint32_t b)
{
  const sweep *s = ctx;
  double x = s->lo[3 * (size_t)a + s->axis], y = s->lo[3 * (size_t)b + s->axis];
  return (x > y) - (x < y);
}

static int boxes_meet(const sweep *s, uint32_t i, uint32_t j)
{
  for (int d = 0; d < 3; d++)
    if (s->lo[3 * (size_t)j + d] > s->hi[3 * (size_t)i + d] ||
        s->lo[3 * (size_t)i + d] > s->hi[3 * (size_t)j + d])
      return 0;
  return 1;
}

static const double *P(const struct tr_plc *plc, uint32_t v) { return plc->xyz + 3 * (size_t)v; }

/* Sign of tr_orient3d(t0, t1, t2, v) for triangle it = (t0, t1, t2). On a plane
 * x_k = c, det[t1-t0; t2-t0; v-t0] expands along column k, whose only nonzero entry is
 * v_k - c, into (v_k - c) times the cofactor, which is tr_orient2d_proj(t0, t1, t2, k)
 * (its kept axes are in cyclic order): the sign of that is cached in plane[]. */
static int side(const sweep *s, uint32_t it, uint32_t v)
{
  const uint32_t *t = s->plc->tris + 3 * (size_t)it;
  uint8_t c = s->plane ? s->plane[it] : 0;
  if (c) {
    double x = P(s->plc, v)[(c & 3) - 1], o = P(s->plc, t[0])[(c & 3) - 1];
    int sg = (x > o) - (x < o);
    return c & 4 ? -sg : sg;
  }
  double det;
  if (s->o3 && tr_o3plane_filter(&s->o3[it], P(s->plc, t[0]), P(s->plc, v), &det))
    return tr_sign(det);
  return tr_sign(tr_orient3d(P(s->plc, t[0]), P(s->plc, t[1]), P(s->plc, t[2]), P(s->plc, v)));
}

/* The non-shared corners of triangle iu against the plane of triangle it: counts of
 * the signs +, - and 0 of side(), and in sg (if not NULL) the sign of each corner of
 * iu, 0 for a shared one. */
static void sides(const sweep *s, uint32_t it, uint32_t iu, int cnt[3], int *sg)
{
  const uint32_t *t = s->plc->tris + 3 * (size_t)it, *u = s->plc->tris + 3 * (size_t)iu;
  cnt[0] = cnt[1] = cnt[2] = 0;
  for (int k = 0; k < 3; k++) {
    int o = 0;
    if (u[k] != t[0] && u[k] != t[1] && u[k] != t[2]) {
      o = side(s, it, u[k]);
      cnt[o > 0 ? 0 : o < 0 ? 1 : 2]++;
    }
    if (sg)
      sg[k] = o;
  }
}

/* Counts from sides(): every non-shared corner strictly on one side of the plane (at
 * least one corner counted, none on the plane). */
static int strictly_one_side(const int c[3])
{
  return !c[2] && (!c[0] || !c[1]) && c[0] + c[1] > 0;
}

/* Non-shared corners of u strictly on one side of the plane of t. */
static int one_side(const sweep *s, uint32_t it, uint32_t iu)
{
  int c[3];
  sides(s, it, iu, c, NULL);
  return strictly_one_side(c);
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

/* Sign of orient2d of (a, b, c) with axis `drop` left out. */
static int o2(const struct tr_plc *plc, uint32_t a, uint32_t b, uint32_t c, int drop)
{
  return tr_sign(tr_orient2d_proj(P(plc, a), P(plc, b), P(plc, c), drop));
}

enum { NO_PROJ = 0xff };

/* The 2D view of triangle it: the axis to leave out, and its orientation there (*st, 0
 * only for a triangle flat in every projection). The reference path takes the first
 * axis with a nonzero orientation; the others read proj[], where run() put the axis of
 * the largest normal component. Any axis with a nonzero orientation projects t's plane
 * one to one, so the choice decides nothing; it only avoids the axes along which a
 * triangle in an axis plane is flat, whose exact zeros cost the adaptive stages. */
static int projection(const sweep *s, uint32_t it, int *st)
{
  if (s->proj && s->proj[it] != NO_PROJ) {
    *st = s->proj[it] & 4 ? -1 : 1;
    return s->proj[it] & 3;
  }
  const uint32_t *t = s->plc->tris + 3 * (size_t)it;
  int drop = 0;
  *st = 0;
  for (; drop < 3 && !*st; drop++)
    *st = o2(s->plc, t[0], t[1], t[2], drop);
  return drop - 1;
}

/* Triangles t and u sharing exactly the edge (a, b), with third corners p and q: they
 * meet only in that edge unless they are coplanar with p and q on the same side of it
 * (neither corner is on the line: zero-area triangles were rejected before). On CAD
 * surfaces most neighbours are coplanar, where the general test classifies six
 * segments; this decides them with one orient3d and two orient2d. */
static int edge_pair_improper(const sweep *s, uint32_t it, uint32_t a, uint32_t b, uint32_t q)
{
  /* (a, b, p) is an even permutation of triangle it: the same plane and side, and its
   * orientation in the projection is t's */
  if (side(s, it, q) != 0)
    return 0;
  int sp;
  int drop = projection(s, it, &sp);
  if (!sp)
    return 1; /* p on the line ab: not a triangle; cannot happen after validation */
  return sp == o2(s->plc, a, b, q, drop);
}

/* Vertex p in the closed triangle t (2D, t of orientation st != 0). */
static int in_closed(const struct tr_plc *plc, const uint32_t *t, int st, uint32_t p, int drop)
{
  for (int k = 0; k < 3; k++)
    if (st * o2(plc, t[k], t[(k + 1) % 3], p, drop) < 0)
      return 0;
  return 1;
}

/* Coplanar t and u sharing at most one vertex, in the projection that drops an axis along
 * which t is not flat (the projection is then one-to-one on their plane). They meet only
 * in shared vertices unless a non-shared corner of one lies in the other closed triangle
 * or two edges cross at a point interior to both: if the closed triangles meet elsewhere,
 * the boundary of one reaches into the other, and it either starts there (a corner
 * inside; the shared vertex is on the other's boundary, not inside) or crosses the
 * other's boundary, properly or through a corner. Plane-free orient2d tests replace the
 * exact zero orient3d of the general path, which on the flat faces of CAD models was
 * most of the validation's time. */
static int coplanar_improper(const sweep *s, uint32_t it, uint32_t iu)
{
  const struct tr_plc *plc = s->plc;
  const uint32_t *t = plc->tris + 3 * (size_t)it, *u = plc->tris + 3 * (size_t)iu;
  int st;
  int drop = projection(s, it, &st);
  int su = o2(plc, u[0], u[1], u[2], drop);
  for (int k = 0; k < 3; k++) {
    int ut = u[k] == t[0] || u[k] == t[1] || u[k] == t[2];
    int tu = t[k] == u[0] || t[k] == u[1] || t[k] == u[2];
    if ((!ut && in_closed(plc, t, st, u[k], drop)) || (!tu && in_closed(plc, u, su, t[k], drop)))
      return 1;
  }
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++) {
      uint32_t a = t[i], b = t[(i + 1) % 3], c = u[j], d = u[(j + 1) % 3];
      int o1 = o2(plc, a, b, c, drop), o2_ = o2(plc, a, b, d, drop);
      if (o1 * o2_ >= 0)
        continue;
      int o3 = o2(plc, c, d, a, drop), o4 = o2(plc, c, d, b, drop);
      if (o3 * o4 < 0)
        return 1;
    }
  return 0;
}

/* An edge of triangle t (corners t[0..2], orientation st != 0 in the projection) with
 * every corner of u strictly on its outer side. */
static int separates(const struct tr_plc *plc, const uint32_t *t, int st, const uint32_t *u,
                     int drop)
{
  for (int k = 0; k < 3; k++) {
    uint32_t a = t[k], b = t[(k + 1) % 3];
    int out = 1;
    for (int j = 0; j < 3 && out; j++)
      out = st * o2(plc, a, b, u[j], drop) < 0;
    if (out)
      return 1;
  }
  return 0;
}

/* Coplanar t and u sharing no vertex: they are disjoint iff an edge line of one has the
 * other strictly on its outer side. (The Minkowski difference t - u is a convex polygon
 * whose edges are an edge of t minus a corner of u or a corner of t minus an edge of u;
 * 0 is outside it iff strictly outside one of its edge lines, which says just that.) Most
 * such pairs on a flat face are apart, where this stops after a few orient2d. */
static int coplanar_apart_improper(const sweep *s, uint32_t it, uint32_t iu)
{
  const struct tr_plc *plc = s->plc;
  const uint32_t *t = plc->tris + 3 * (size_t)it, *u = plc->tris + 3 * (size_t)iu;
  int st;
  int drop = projection(s, it, &st);
  int su = o2(plc, u[0], u[1], u[2], drop);
  if (!st || !su)
    return coplanar_improper(s, it, iu); /* flat: not after validation */
  return !separates(plc, t, st, u, drop) && !separates(plc, u, su, t, drop);
}

/* t and u share exactly one vertex: f = (v, a, b) and g = (v, c, d), the two triangles
 * rotated to start at it (even permutations: the same orientations). */
static void from_shared_vertex(const uint32_t *t, const uint32_t *u, uint32_t f[3], uint32_t g[3])
{
  int kv = 0, ku = 0;
  while (t[kv] != u[0] && t[kv] != u[1] && t[kv] != u[2])
    kv++;
  while (u[ku] != t[kv])
    ku++;
  for (int k = 0; k < 3; k++) {
    f[k] = t[(kv + k) % 3];
    g[k] = u[(ku + k) % 3];
  }
}

/* x in the closed cone at v spanned by a and b, where s = sign orient2d(v, a, b) != 0:
 * the cone of an angle under 180 degrees is where the two half-planes through v, left
 * of va and right of vb (for s > 0), meet. */
static int in_cone(const struct tr_plc *plc, uint32_t v, uint32_t a, uint32_t b, int s,
                   uint32_t x, int drop)
{
  return s * o2(plc, v, a, x, drop) >= 0 && s * o2(plc, v, x, b, drop) >= 0;
}

/* Coplanar t = (v, a, b) and u = (v, c, d) sharing only v: near v each is its cone (the
 * closed angle at v), and each lies in its cone, so they meet beyond v iff the cones
 * share a ray. Two closed arcs of directions, each under 180 degrees, meet iff one holds
 * an end of the other: at most eight orient2d where coplanar_improper asks up to 45. A
 * fan of triangles around a vertex of a flat CAD face is made of such pairs. */
static int coplanar_fan_improper(const sweep *s, uint32_t it, uint32_t iu)
{
  const struct tr_plc *plc = s->plc;
  const uint32_t *t = plc->tris + 3 * (size_t)it, *u = plc->tris + 3 * (size_t)iu;
  int st;
  int drop = projection(s, it, &st);
  uint32_t f[3], g[3];
  from_shared_vertex(t, u, f, g);
  uint32_t v = f[0], a = f[1], b = f[2], c = g[1], d = g[2];
  int su = o2(plc, v, c, d, drop);
  if (!st || !su)
    return coplanar_improper(s, it, iu); /* flat: not after validation */
  return in_cone(plc, v, a, b, st, c, drop) || in_cone(plc, v, a, b, st, d, drop) ||
         in_cone(plc, v, c, d, su, a, drop) || in_cone(plc, v, c, d, su, b, drop);
}

static int improper(const sweep *s, uint32_t i, uint32_t j)
{
  const struct tr_plc *plc = s->plc;
  const uint32_t *t = plc->tris + 3 * (size_t)i, *u = plc->tris + 3 * (size_t)j;
  int shared = 0, tp = -1, uq = -1;
  for (int k = 0; k < 3; k++) {
    int in_u = t[k] == u[0] || t[k] == u[1] || t[k] == u[2];
    int in_t = u[k] == t[0] || u[k] == t[1] || u[k] == t[2];
    shared += in_u;
    if (!in_u)
      tp = k;
    if (!in_t)
      uq = k;
  }
  if (shared == 2)
    return edge_pair_improper(s, i, t[(tp + 1) % 3], t[(tp + 2) % 3], u[uq]);
  if (shared < 2) {
    /* the non-shared corners of u against the plane of t: all on one side, the pair is
     * fine; all on it, the coplanar test */
    int cu[3], ct[3], su[3], stt[3]; /* counts, and signs of u's and t's corners */
    sides(s, i, j, cu, su);
    if (strictly_one_side(cu))
      return 0;
    if (!cu[0] && !cu[1])
      return !s->plane ? coplanar_improper(s, i, j)
             : shared    ? coplanar_fan_improper(s, i, j)
                         : coplanar_apart_improper(s, i, j);
    sides(s, j, i, ct, stt);
    if (strictly_one_side(ct))
      return 0;
    /* the planes meet in a line: where each triangle meets it (selfint_line.c) */
    if (s->plane)
      return tr_selfint_line_improper(plc->xyz, t, u, stt, su, shared);
  } else if (one_side(s, i, j) || one_side(s, j, i)) {
    return 0;
  }
  return edges_hit(plc, t, u) || edges_hit(plc, u, t);
}

/* Every pair is tested (no early exit) and the reported one is the least (x, y): the
 * message does not depend on the broad phase. */
static void consider(sweep *s, uint32_t i, uint32_t j)
{
  uint32_t x = i < j ? i : j, y = i < j ? j : i;
  if (s->collect) {
    if (s->oom || !improper(s, x, y))
      return;
    if (s->npairs == s->cap) {
      size_t nc = s->cap ? 2 * s->cap : 64;
      uint32_t *np = realloc(s->pairs, sizeof *np * 2 * nc);
      if (!np) {
        s->oom = 1;
        return;
      }
      s->pairs = np;
      s->cap = nc;
    }
    s->pairs[2 * s->npairs] = x;
    s->pairs[2 * s->npairs++ + 1] = y;
    return;
  }
  if (x > s->bx || (x == s->bx && y >= s->by))
    return;
  if (improper(s, x, y)) {
    s->bx = x;
    s->by = y;
  }
}

static tr_status by_sweep(sweep *s, uint32_t n)
{
  uint32_t *ord = malloc(sizeof *ord * (n ? n : 1));
  double *box = malloc(sizeof *box * 2 * (size_t)(n ? n : 1));
  tr_status st = TR_OK;
  if (!ord || !box) {
    st = tr_error(TR_ERR_NOMEM, "out of memory checking self-intersections");
    goto done;
  }
  for (uint32_t t = 0; t < n; t++)
    ord[t] = t;
  if ((st = tr_sort_ids(ord, n, cmp_lox, s)) != TR_OK)
    goto done;
  /* the sweep-axis interval of each box, in sweep order: the inner loop streams */
  for (uint32_t a = 0; a < n; a++) {
    box[2 * (size_t)a] = s->lo[3 * (size_t)ord[a] + s->axis];
    box[2 * (size_t)a + 1] = s->hi[3 * (size_t)ord[a] + s->axis];
  }
  for (uint32_t a = 0; a < n; a++)
    for (uint32_t b = a + 1; b < n && box[2 * (size_t)b] <= box[2 * (size_t)a + 1]; b++)
      if (boxes_meet(s, ord[a], ord[b]))
        consider(s, ord[a], ord[b]);
done:
  free(ord);
  free(box);
  return st;
}

typedef struct {
  double org[3], inv[3]; /* cell of x on axis d: floor((x - org) * inv), clamped */
  uint32_t dim[3];
} grid;

static uint32_t cell_of(const grid *g, int d, double x)
{
  double c = (x - g->org[d]) * g->inv[d];
  if (!(c > 0)) /* also NaN-safe, though coordinates are finite */
    return 0;
  return c >= (double)(g->dim[d] - 1) ? g->dim[d] - 1 : (uint32_t)c;
}

/* Cells covered by t's box: [c0, c1] per axis; returns their number, capped. */
static uint64_t cover(const grid *g, const sweep *s, uint32_t t, uint32_t c0[3], uint32_t c1[3])
{
  uint64_t k = 1;
  for (int d = 0; d < 3; d++) {
    c0[d] = cell_of(g, d, s->lo[3 * (size_t)t + d]);
    c1[d] = cell_of(g, d, s->hi[3 * (size_t)t + d]);
    k *= (uint64_t)(c1[d] - c0[d] + 1);
  }
  return k;
}

/* *fallback = 1: the grid would hold too many entries (unless force): use the sweep. */
static tr_status by_grid(sweep *s, uint32_t n, const double ext[3], int force, int *fallback)
{
  *fallback = 1;
  grid g;
  double size = 0, lo0[3];
  for (int d = 0; d < 3; d++) {
    lo0[d] = s->lo[d];
    for (uint32_t t = 1; t < n; t++)
      lo0[d] = s->lo[3 * (size_t)t + d] < lo0[d] ? s->lo[3 * (size_t)t + d] : lo0[d];
  }
  for (uint32_t t = 0; t < n; t++) {
    double m = 0;
    for (int d = 0; d < 3; d++) {
      double w = s->hi[3 * (size_t)t + d] - s->lo[3 * (size_t)t + d];
      m = w > m ? w : m;
    }
    size += m;
  }
  size /= n; /* the mean box size: about one triangle per cell and axis */
  if (!(size > 0) || !isfinite(size))
    return TR_OK;
  /* at most ~2n cells */
  for (;;) {
    double cells = 1;
    for (int d = 0; d < 3; d++)
      cells *= floor(ext[d] / size) + 1;
    if (cells <= 2.0 * n + 8)
      break;
    size *= 1.25;
  }
  uint64_t ncell = 1;
  for (int d = 0; d < 3; d++) {
    g.org[d] = lo0[d];
    g.dim[d] = (uint32_t)(floor(ext[d] / size) + 1);
    g.inv[d] = 1.0 / size;
    ncell *= g.dim[d];
  }
  uint32_t *start = calloc(ncell + 1, sizeof *start), *list = NULL, *cr = NULL, *cc = NULL;
  double *cb = NULL; /* one cell's boxes: lo[3] hi[3] per entry */
  tr_status st = TR_OK;
  if (!start)
    return tr_error(TR_ERR_NOMEM, "out of memory checking self-intersections");
  uint64_t total = 0, cap = 16 * (uint64_t)n + 4096;
  uint32_t c0[3], c1[3];
  for (uint32_t t = 0; t < n && (force || total <= cap); t++)
    total += cover(&g, s, t, c0, c1);
  if (total > cap && !force)
    goto done; /* slivers across many cells */
  *fallback = 0;
  /* each triangle's cell range, c0[3] c1[3], computed once */
  if (!(cr = malloc(sizeof *cr * 6 * (size_t)n))) {
    st = tr_error(TR_ERR_NOMEM, "out of memory checking self-intersections");
    goto done;
  }
  total = 0;
  for (uint32_t t = 0; t < n; t++) {
    uint32_t *r = cr + 6 * (size_t)t;
    total += cover(&g, s, t, r, r + 3);
    for (uint32_t z = r[2]; z <= r[5]; z++)
      for (uint32_t y = r[1]; y <= r[4]; y++)
        for (uint32_t x = r[0]; x <= r[3]; x++)
          start[((uint64_t)z * g.dim[1] + y) * g.dim[0] + x + 1]++;
  }
  for (uint64_t c = 0; c < ncell; c++)
    start[c + 1] += start[c];
  if (!(list = malloc(sizeof *list * (total ? total : 1)))) {
    st = tr_error(TR_ERR_NOMEM, "out of memory checking self-intersections");
    goto done;
  }
  for (uint32_t t = 0; t < n; t++) { /* each cell's list in increasing t */
    const uint32_t *r = cr + 6 * (size_t)t;
    for (uint32_t z = r[2]; z <= r[5]; z++)
      for (uint32_t y = r[1]; y <= r[4]; y++)
        for (uint32_t x = r[0]; x <= r[3]; x++)
          list[start[((uint64_t)z * g.dim[1] + y) * g.dim[0] + x]++] = t;
  }
  for (uint64_t c = ncell; c > 0; c--) /* back to starts */
    start[c] = start[c - 1];
  start[0] = 0;
  /* Each cell's boxes copied side by side before its pairs are tested: k reads from the
   * scattered box array per cell instead of k^2 (those reads were most of the time). */
  uint32_t kmax = 0;
  for (uint64_t c = 0; c < ncell; c++)
    kmax = start[c + 1] - start[c] > kmax ? start[c + 1] - start[c] : kmax;
  if (!(cb = malloc(sizeof *cb * 6 * (size_t)(kmax ? kmax : 1))) ||
      !(cc = malloc(sizeof *cc * 3 * (size_t)(kmax ? kmax : 1)))) {
    st = tr_error(TR_ERR_NOMEM, "out of memory checking self-intersections");
    goto done;
  }
  for (uint64_t c = 0; c < ncell; c++) {
    uint32_t cx = (uint32_t)(c % g.dim[0]), cy = (uint32_t)(c / g.dim[0] % g.dim[1]),
             cz = (uint32_t)(c / g.dim[0] / g.dim[1]), k = start[c + 1] - start[c];
    const uint32_t *l = list + start[c];
    for (uint32_t a = 0; a < k; a++)
      for (int d = 0; d < 3; d++) {
        cb[6 * (size_t)a + d] = s->lo[3 * (size_t)l[a] + d];
        cb[6 * (size_t)a + 3 + d] = s->hi[3 * (size_t)l[a] + d];
        cc[3 * (size_t)a + d] = cr[6 * (size_t)l[a] + d];
      }
    for (uint32_t a = 0; a < k; a++)
      for (uint32_t b = a + 1; b < k; b++) {
        const double *bi = cb + 6 * (size_t)a, *bj = cb + 6 * (size_t)b;
        if (bj[0] > bi[3] || bi[0] > bj[3] || bj[1] > bi[4] || bi[1] > bj[4] ||
            bj[2] > bi[5] || bi[2] > bj[5])
          continue; /* boxes_meet */
        /* The pair belongs to the cell of the low corner of the boxes' intersection, the
         * larger low corner per axis; cell_of is monotone, so that corner's cell is the
         * larger of the two low corners' cells, which cover() gave. */
        const uint32_t *ca = cc + 3 * (size_t)a, *cj = cc + 3 * (size_t)b;
        if ((ca[0] > cj[0] ? ca[0] : cj[0]) != cx || (ca[1] > cj[1] ? ca[1] : cj[1]) != cy ||
            (ca[2] > cj[2] ? ca[2] : cj[2]) != cz)
          continue;
        consider(s, l[a], l[b]);
      }
  }
done:
  free(start);
  free(list);
  free(cr);
  free(cc);
  free(cb);
  return st;
}

/* The oracle of the tests: every pair. */
static void all_pairs(sweep *s, uint32_t n)
{
  for (uint32_t i = 0; i < n; i++)
    for (uint32_t j = i + 1; j < n; j++)
      if (boxes_meet(s, i, j))
        consider(s, i, j);
}

tr_status tr_input_self_intersections(const struct tr_plc *plc, const uint32_t *tri_orig)
{
  return tr_input_self_intersections_by(plc, tri_orig, TR_SELFINT_AUTO);
}

/* The broad phase chosen by method, calling consider() on every pair whose boxes meet. */
static tr_status run(sweep *sw, int method)
{
  const struct tr_plc *plc = sw->plc;
  sweep s = *sw;
  uint32_t n = plc->ntris;
  s.lo = malloc(sizeof(double) * 6 * (size_t)(n ? n : 1));
  s.plane = method == TR_SELFINT_REFERENCE ? NULL : malloc(2 * (size_t)(n ? n : 1));
  s.proj = s.plane ? s.plane + n : NULL;
  s.o3 = s.plane ? malloc(sizeof *s.o3 * (n ? n : 1)) : NULL;
  tr_status st = TR_OK;
  if (!s.lo || (method != TR_SELFINT_REFERENCE && (!s.plane || !s.o3))) {
    free(s.lo);
    free(s.plane);
    free(s.o3);
    return tr_error(TR_ERR_NOMEM, "out of memory checking self-intersections");
  }
  for (uint32_t t = 0; t < n && s.plane; t++) {
    const uint32_t *v = plc->tris + 3 * (size_t)t;
    const double *a = P(plc, v[0]), *b = P(plc, v[1]), *c = P(plc, v[2]);
    s.plane[t] = 0;
    for (int k = 0; k < 3 && !s.plane[t]; k++)
      if (a[k] == b[k] && b[k] == c[k]) {
        int o = tr_sign(tr_orient2d_proj(a, b, c, k));
        s.plane[t] = o ? (uint8_t)((k + 1) | (o < 0 ? 4 : 0)) : 0;
      }
    int k = 0, o = 0;
    if (s.plane[t]) { /* its own axis, its orientation there found above */
      k = (s.plane[t] & 3) - 1;
      o = s.plane[t] & 4 ? -1 : 1;
    } else { /* the largest normal component, in doubles: only a choice */
      double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
      double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
      double nx = fabs(uy * vz - uz * vy), ny = fabs(uz * vx - ux * vz),
             nz = fabs(ux * vy - uy * vx);
      k = ny > nx ? 1 : 0;
      k = nz > (k ? ny : nx) ? 2 : k;
      o = tr_sign(tr_orient2d_proj(a, b, c, k));
      for (int j = 1; j < 3 && !o; j++) /* the doubles chose a flat axis */
        o = tr_sign(tr_orient2d_proj(a, b, c, k = (k + 1) % 3));
    }
    s.proj[t] = o ? (uint8_t)(k | (o < 0 ? 4 : 0)) : NO_PROJ;
    tr_o3plane_init(&s.o3[t], a, b, c);
  }
  s.hi = s.lo + 3 * (size_t)n;
  for (uint32_t t = 0; t < n; t++)
    tr_box_of(plc->xyz, plc->tris + 3 * (size_t)t, 3, s.lo + 3 * (size_t)t, s.hi + 3 * (size_t)t);
  double ext[3] = {0, 0, 0};
  for (int d = 0; d < 3 && n; d++) {
    double lo = s.lo[d], h = s.hi[d];
    for (uint32_t t = 1; t < n; t++) {
      lo = s.lo[3 * (size_t)t + d] < lo ? s.lo[3 * (size_t)t + d] : lo;
      h = s.hi[3 * (size_t)t + d] > h ? s.hi[3 * (size_t)t + d] : h;
    }
    ext[d] = h - lo; /* only a heuristic: rounding here cannot change any answer */
  }
  s.axis = ext[1] > ext[s.axis] ? 1 : s.axis;
  s.axis = ext[2] > ext[s.axis] ? 2 : s.axis;
  int fallback = 1;
  if (method == TR_SELFINT_ALL_PAIRS || method == TR_SELFINT_REFERENCE) {
    all_pairs(&s, n);
    fallback = 0;
  } else if (method != TR_SELFINT_SWEEP && n > 1 && isfinite(ext[0] + ext[1] + ext[2]))
    st = by_grid(&s, n, ext, method == TR_SELFINT_GRID, &fallback);
  if (st == TR_OK && fallback)
    st = by_sweep(&s, n);
  free(s.lo);
  free(s.plane);
  free(s.o3);
  s.lo = s.hi = NULL;
  s.plane = s.proj = NULL;
  s.o3 = NULL;
  *sw = s;
  return st;
}

static int cmp_pair(const void *a, const void *b)
{
  const uint32_t *p = a, *q = b;
  if (p[0] != q[0])
    return p[0] < q[0] ? -1 : 1;
  return (p[1] > q[1]) - (p[1] < q[1]);
}

tr_status tr_input_self_intersection_pairs(const struct tr_plc *plc, int method,
                                           uint32_t **pairs, size_t *npairs)
{
  uint32_t n = plc->ntris;
  sweep s = {plc, NULL, NULL, 0, NULL, NULL, NULL, n, n, 1, 0, NULL, 0, 0};
  *pairs = NULL;
  *npairs = 0;
  tr_status st = run(&s, method);
  if (st == TR_OK && s.oom)
    st = tr_error(TR_ERR_NOMEM, "out of memory listing self-intersections");
  if (st != TR_OK) {
    free(s.pairs);
    return st;
  }
  /* the broad phases meet pairs in different orders: sort for one answer */
  if (s.npairs)
    qsort(s.pairs, s.npairs, 2 * sizeof *s.pairs, cmp_pair);
  *pairs = s.pairs;
  *npairs = s.npairs;
  return TR_OK;
}

tr_status tr_input_self_intersections_by(const struct tr_plc *plc, const uint32_t *tri_orig,
                                         int method)
{
  uint32_t n = plc->ntris;
  sweep s = {plc, NULL, NULL, 0, NULL, NULL, NULL, n, n, 0, 0, NULL, 0, 0};
  tr_status st = run(&s, method);
  if (st == TR_OK && s.bx < n) {
    uint32_t x = s.bx, y = s.by;
    st = tr_error(TR_ERR_SELF_INTERSECT,
                  "%s%striangles %u and %u intersect (input faces %u and %u)",
                  plc->source ? plc->source : "", plc->source ? ": " : "",
                  tri_orig ? tri_orig[x] : x, tri_orig ? tri_orig[y] : y,
                  plc->tri_source ? plc->tri_source[x] : x,
                  plc->tri_source ? plc->tri_source[y] : y);
  }
  return st;
}
