/* Exact triangulation of planar polygons with holes.
 *
 * The facet is projected onto the coordinate plane that drops the axis where its normal
 * is largest; the projection is a bijection on the plane, so a triangulation there is a
 * triangulation in 3D, and all decisions are tr_orient2d signs on exact projected
 * doubles (projection only drops a coordinate; nothing is rounded). If the first loop is
 * clockwise in the projection we mirror v -> -v (exact) so the working polygon is
 * counterclockwise and holes clockwise; triangles are emitted in polygon order, so they
 * keep the orientation of the input loop.
 *
 * Holes are joined to the outer loop by bridge edges (any hole vertex to any visible
 * vertex: visibility is tested against every edge, so it is exact), then ears are clipped;
 * an ear is a strictly convex corner whose closed triangle holds no other non-convex
 * vertex. If no ear exists the polygon self-overlaps or is degenerate: that is an error,
 * never a guess. The ears found first make fans of thin triangles, so polyflip.c then
 * flips diagonals to raise the smallest angles (exactly valid flips, same orientation). */
#include "soup.h"
#include "io.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "polyflip.h"
#include "predicates.h"

typedef struct {
  double (*p)[2]; /* projected coordinates per local vertex */
  uint32_t *id;   /* global index per local vertex */
} ptab;

static int o2(const ptab *t, uint32_t a, uint32_t b, uint32_t c)
{
  return tr_sign(tr_orient2d(t->p[a], t->p[b], t->p[c]));
}

static int sgn(double x) { return (x > 0) - (x < 0); }

/* 1 iff q lies on the closed segment ab, given orient(a,b,q) == 0. */
static int on_seg(const ptab *t, uint32_t a, uint32_t b, uint32_t q)
{
  for (int k = 0; k < 2; k++) {
    double lo = t->p[a][k] < t->p[b][k] ? t->p[a][k] : t->p[b][k];
    double hi = t->p[a][k] < t->p[b][k] ? t->p[b][k] : t->p[a][k];
    if (t->p[q][k] < lo || t->p[q][k] > hi)
      return 0;
  }
  return 1;
}

/* Closed segments ab and cd intersect. */
static int seg_hit(const ptab *t, uint32_t a, uint32_t b, uint32_t c, uint32_t d)
{
  int o1 = o2(t, a, b, c), o3 = o2(t, c, d, a);
  int o2v = o2(t, a, b, d), o4 = o2(t, c, d, b);
  if (o1 * o2v < 0 && o3 * o4 < 0)
    return 1;
  if (o1 == 0 && on_seg(t, a, b, c))
    return 1;
  if (o2v == 0 && on_seg(t, a, b, d))
    return 1;
  if (o3 == 0 && on_seg(t, c, d, a))
    return 1;
  if (o4 == 0 && on_seg(t, c, d, b))
    return 1;
  return 0;
}

/* Point q against loop L (n local vertices): 1 strictly inside, 0 outside, -1 on it. */
static int in_loop(const ptab *t, const uint32_t *L, uint32_t n, const double q[2])
{
  int inside = 0;
  for (uint32_t i = 0; i < n; i++) {
    const double *a = t->p[L[i]], *b = t->p[L[(i + 1) % n]];
    double s = tr_orient2d(a, b, q);
    if (s == 0) {
      int on = 1;
      for (int k = 0; k < 2; k++) {
        double lo = a[k] < b[k] ? a[k] : b[k], hi = a[k] < b[k] ? b[k] : a[k];
        if (q[k] < lo || q[k] > hi)
          on = 0;
      }
      if (on)
        return -1;
    }
    if ((a[1] > q[1]) != (b[1] > q[1])) {
      /* The edge crosses the line v = q_v; count it iff the crossing is right of q. */
      if ((b[1] > a[1] && s > 0) || (b[1] < a[1] && s < 0))
        inside ^= 1;
    }
  }
  return inside;
}

/* Signed orientation of a loop: the lexicographically lowest vertex is a corner of the
 * convex hull, so the turn there is the loop's orientation (0: degenerate spike). */
static int loop_orient(const ptab *t, const uint32_t *L, uint32_t n)
{
  uint32_t m = 0;
  for (uint32_t i = 1; i < n; i++) {
    const double *a = t->p[L[i]], *b = t->p[L[m]];
    if (a[0] < b[0] || (a[0] == b[0] && a[1] < b[1]))
      m = i;
  }
  return o2(t, L[(m + n - 1) % n], L[m], L[(m + 1) % n]);
}

static void reverse(uint32_t *L, uint32_t n)
{
  for (uint32_t i = 0; i < n / 2; i++) {
    uint32_t x = L[i];
    L[i] = L[n - 1 - i];
    L[n - 1 - i] = x;
  }
}

/* Direction c->h strictly inside the interior wedge at c (prev a, next b; domain on the
 * left of the boundary). */
static int in_cone(const ptab *t, uint32_t a, uint32_t c, uint32_t b, uint32_t h)
{
  int turn = o2(t, a, c, b);
  int s1 = o2(t, a, c, h), s2 = o2(t, c, b, h);
  if (turn > 0)
    return s1 > 0 && s2 > 0;
  if (turn < 0)
    return !(s1 <= 0 && s2 <= 0);
  return s1 > 0 && s2 > 0; /* straight corner: h must be on the interior side */
}

/* Visibility of segment (x,y) against every edge of polygon P and of the pending holes.
 * Edges touching x or y's point are skipped: their relation is decided by the cones. */
static int visible(const ptab *t, const tr_u32vec *P, uint32_t *const *hl, const uint32_t *hn,
                   uint32_t nh, uint32_t x, uint32_t y)
{
  for (uint32_t i = 0; i < P->n; i++) {
    uint32_t a = P->a[i], b = P->a[(i + 1) % P->n];
    if (t->id[a] == t->id[x] || t->id[b] == t->id[x] || t->id[a] == t->id[y] ||
        t->id[b] == t->id[y])
      continue;
    if (seg_hit(t, a, b, x, y))
      return 0;
  }
  for (uint32_t k = 0; k < nh; k++)
    for (uint32_t i = 0; i < hn[k]; i++) {
      uint32_t a = hl[k][i], b = hl[k][(i + 1) % hn[k]];
      if (t->id[a] == t->id[x] || t->id[b] == t->id[x] || t->id[a] == t->id[y] ||
          t->id[b] == t->id[y])
        continue;
      if (seg_hit(t, a, b, x, y))
        return 0;
    }
  return 1;
}

static tr_status bridge(const ptab *t, tr_u32vec *P, uint32_t **hl, uint32_t *hn, uint32_t nh,
                        const char *what)
{
  /* hl[0] is joined now; hl[1..] are the holes still pending. */
  uint32_t *H = hl[0], m = hn[0];
  for (uint32_t hi = 0; hi < m; hi++) {
    uint32_t h = H[hi], hp = H[(hi + m - 1) % m], hx = H[(hi + 1) % m];
    for (uint32_t j = 0; j < P->n; j++) {
      uint32_t c = P->a[j], cp = P->a[(j + P->n - 1) % P->n], cx = P->a[(j + 1) % P->n];
      if (!in_cone(t, cp, c, cx, h) || !in_cone(t, hp, h, hx, c))
        continue;
      if (!visible(t, P, hl, hn, nh, h, c))
        continue;
      /* P[0..j], H[hi..], H[..hi], h, c, P[j+1..] */
      uint32_t extra = m + 2, old = P->n;
      for (uint32_t k = 0; k < extra; k++)
        TR_CHECK(tr_u32vec_push(P, 0));
      memmove(P->a + j + 1 + extra, P->a + j + 1, sizeof *P->a * (old - j - 1));
      for (uint32_t k = 0; k <= m; k++)
        P->a[j + 1 + k] = H[(hi + k) % m];
      P->a[j + 1 + m + 1] = c;
      return TR_OK;
    }
  }
  return tr_error(TR_ERR_INPUT, "%s: a hole cannot be connected to the outer boundary "
                  "(holes overlap each other or the boundary)", what);
}

/* Appends the triangles as local vertices, counterclockwise in t. */
static tr_status earclip(const ptab *t, tr_u32vec *P, tr_u32vec *out, const char *what)
{
  uint32_t n = P->n;
  uint32_t *prev = malloc(sizeof *prev * n), *next = malloc(sizeof *next * n);
  tr_status st = TR_OK;
  if (!prev || !next) {
    free(prev);
    free(next);
    return tr_error(TR_ERR_NOMEM, "out of memory triangulating a polygon");
  }
  for (uint32_t i = 0; i < n; i++) {
    prev[i] = (i + n - 1) % n;
    next[i] = (i + 1) % n;
  }
  uint32_t cur = 0, left = n, fails = 0;
  while (left > 3 && st == TR_OK) {
    uint32_t a = prev[cur], b = next[cur];
    uint32_t va = P->a[a], vc = P->a[cur], vb = P->a[b];
    int ear = o2(t, va, vc, vb) > 0;
    if (ear) {
      for (uint32_t k = next[b]; k != a; k = next[k]) {
        uint32_t q = P->a[k];
        if (t->id[q] == t->id[va] || t->id[q] == t->id[vb] || t->id[q] == t->id[vc])
          continue;
        if (o2(t, P->a[prev[k]], q, P->a[next[k]]) > 0)
          continue; /* a strictly convex vertex cannot be the first thing inside an ear */
        if (o2(t, va, vc, q) >= 0 && o2(t, vc, vb, q) >= 0 && o2(t, vb, va, q) >= 0) {
          ear = 0;
          break;
        }
      }
    }
    if (ear) {
      uint32_t tri[3] = {va, vc, vb};
      for (int k = 0; k < 3 && st == TR_OK; k++)
        st = tr_u32vec_push(out, tri[k]);
      next[a] = b;
      prev[b] = a;
      left--;
      cur = a;
      fails = 0;
    } else {
      cur = next[cur];
      if (++fails > left) {
        st = tr_error(TR_ERR_INPUT,
                      "%s: polygon is self-overlapping or degenerate (no ear among %u corners)",
                      what, left);
      }
    }
  }
  if (st == TR_OK) {
    uint32_t a = prev[cur], b = next[cur];
    if (o2(t, P->a[a], P->a[cur], P->a[b]) <= 0)
      st = tr_error(TR_ERR_INPUT, "%s: polygon is self-overlapping or degenerate", what);
    else {
      uint32_t tri[3] = {P->a[a], P->a[cur], P->a[b]};
      for (int k = 0; k < 3 && st == TR_OK; k++)
        st = tr_u32vec_push(out, tri[k]);
    }
  }
  free(prev);
  free(next);
  return st;
}

/* Edges of the loops must not cross or overlap (except at shared vertices): an ear
 * clipper can succeed on a self-overlapping polygon and silently produce overlap. */
static tr_status check_simple(const ptab *t, uint32_t *const *L, const uint32_t *n,
                              uint32_t nl, uint32_t total, const char *what)
{
  if ((uint64_t)total * total > 16000000u)
    return TR_OK; /* too large for the quadratic test: the self-intersection pass decides */
  for (uint32_t l = 0; l < nl; l++)
    for (uint32_t i = 0; i < n[l]; i++) {
      uint32_t a = L[l][i], b = L[l][(i + 1) % n[l]];
      if (t->id[a] == t->id[b])
        return tr_error(TR_ERR_INPUT, "%s: polygon repeats vertex %u consecutively", what,
                        t->id[a]);
      for (uint32_t m = l; m < nl; m++)
        for (uint32_t j = (m == l ? i + 1 : 0); j < n[m]; j++) {
          uint32_t c = L[m][j], d = L[m][(j + 1) % n[m]];
          int shared = (t->id[a] == t->id[c]) + (t->id[a] == t->id[d]) +
                       (t->id[b] == t->id[c]) + (t->id[b] == t->id[d]);
          int bad;
          if (shared >= 2)
            bad = 1; /* the same edge twice */
          else if (shared == 1) {
            /* Touching at the common vertex is fine; folding back along the edge is not. */
            uint32_t s = (t->id[a] == t->id[c] || t->id[a] == t->id[d]) ? a : b;
            uint32_t x = s == a ? b : a;
            uint32_t y = (t->id[c] == t->id[s]) ? d : c;
            /* Signs of differences of doubles are exact (a product could underflow). */
            bad = o2(t, s, x, y) == 0 &&
                  (sgn(t->p[x][0] - t->p[s][0]) * sgn(t->p[y][0] - t->p[s][0]) > 0 ||
                   sgn(t->p[x][1] - t->p[s][1]) * sgn(t->p[y][1] - t->p[s][1]) > 0);
          } else
            bad = seg_hit(t, a, b, c, d);
          if (bad)
            return tr_error(TR_ERR_INPUT,
                            "%s: polygon is self-overlapping: edge %u-%u meets edge %u-%u", what,
                            t->id[a], t->id[b], t->id[c], t->id[d]);
        }
    }
  return TR_OK;
}

tr_status tr_triangulate_facet(const double *xyz, const uint32_t *idx, const uint32_t *loop_first,
                               uint32_t nloops, uint32_t nidx, const double *holes,
                               uint32_t nholes, tr_u32vec *out, const char *what)
{
  tr_status st = TR_OK;
  uint32_t n0 = (nloops > 1 ? loop_first[1] : nidx) - loop_first[0];
  for (uint32_t l = 0; l < nloops; l++) {
    uint32_t len = (l + 1 < nloops ? loop_first[l + 1] : nidx) - loop_first[l];
    if (len < 3)
      return tr_error(TR_ERR_INPUT, "%s: polygon %u has %u vertices (at least 3 needed)", what,
                      l, len);
  }
  /* Projection: the axis with the largest normal component among those where three
   * corners of the first loop are exactly non-collinear. */
  const uint32_t *L0 = idx + loop_first[0];
  const double *a = xyz + 3 * (size_t)L0[0], *b = NULL;
  int drop = -1;
  for (uint32_t i = 1; i < n0 && !b; i++) {
    const double *q = xyz + 3 * (size_t)L0[i];
    if (q[0] != a[0] || q[1] != a[1] || q[2] != a[2])
      b = q;
  }
  for (uint32_t i = 1; i < n0 && b && drop < 0; i++) {
    const double *c = xyz + 3 * (size_t)L0[i];
    double best = 0;
    for (int k = 0; k < 3; k++) {
      double o = fabs(tr_orient2d_proj(a, b, c, k));
      if (o > best) {
        best = o;
        drop = k;
      }
    }
  }
  if (drop < 0)
    return tr_error(TR_ERR_INPUT, "%s: polygon has zero area (all vertices collinear)", what);
  int u = (drop + 1) % 3, v = (drop + 2) % 3;
  ptab t;
  t.p = malloc(sizeof *t.p * (nidx + nholes));
  t.id = malloc(sizeof *t.id * (nidx + nholes));
  uint32_t **L = malloc(sizeof *L * nloops), *Ln = malloc(sizeof *Ln * nloops);
  uint32_t *lidx = malloc(sizeof *lidx * nidx);
  char *is_hole = calloc(nloops, 1);
  uint32_t *side = malloc(sizeof *side * nidx);
  tr_u32vec P = {0}; /* the working polygon: local vertex per position */
  tr_u32vec loc = {0};
  if (!t.p || !t.id || !L || !Ln || !lidx || !is_hole || !side) {
    st = tr_error(TR_ERR_NOMEM, "out of memory triangulating %s", what);
    goto done;
  }
  for (uint32_t i = 0; i < nidx; i++) {
    const double *q = xyz + 3 * (size_t)idx[i];
    t.p[i][0] = q[u];
    t.p[i][1] = q[v];
    t.id[i] = idx[i];
    lidx[i] = i;
  }
  for (uint32_t i = 0; i < nholes; i++) {
    t.p[nidx + i][0] = holes[3 * i + u];
    t.p[nidx + i][1] = holes[3 * i + v];
    t.id[nidx + i] = UINT32_MAX;
  }
  for (uint32_t l = 0; l < nloops; l++) {
    L[l] = lidx + loop_first[l];
    Ln[l] = (l + 1 < nloops ? loop_first[l + 1] : nidx) - loop_first[l];
  }
  int s0 = loop_orient(&t, L[0], Ln[0]);
  if (s0 == 0) {
    st = tr_error(TR_ERR_INPUT, "%s: polygon is degenerate (it folds back on itself)", what);
    goto done;
  }
  if (s0 < 0) /* mirror so that the first loop is counterclockwise */
    for (uint32_t i = 0; i < nidx + nholes; i++)
      t.p[i][1] = -t.p[i][1];
  st = check_simple(&t, L, Ln, nloops, nidx, what);
  if (st != TR_OK)
    goto done;
  /* Classify the other loops. */
  for (uint32_t l = 1; l < nloops; l++) {
    if (nholes) {
      for (uint32_t h = 0; h < nholes; h++) {
        int r = in_loop(&t, L[l], Ln[l], t.p[nidx + h]);
        if (r < 0) {
          st = tr_error(TR_ERR_INPUT, "%s: hole point %u lies on polygon %u", what, h, l);
          goto done;
        }
        if (r)
          is_hole[l] = 1;
      }
    } else
      is_hole[l] = 1; /* no hole points: an inner loop is a hole (the only meaning it has) */
    if (!is_hole[l]) {
      st = tr_error(TR_ERR_UNSUPPORTED,
                    "%s: polygon %u is neither the outer boundary nor a hole (several outer "
                    "polygons or internal constraints in one facet are not supported)",
                    what, l);
      goto done;
    }
    if (in_loop(&t, L[0], Ln[0], t.p[L[l][0]]) != 1) {
      st = tr_error(TR_ERR_INPUT, "%s: hole polygon %u is not inside the outer polygon", what, l);
      goto done;
    }
    if (loop_orient(&t, L[l], Ln[l]) > 0)
      reverse(L[l], Ln[l]);
  }
  for (uint32_t i = 0; i < Ln[0] && st == TR_OK; i++)
    st = tr_u32vec_push(&P, L[0][i]);
  for (uint32_t l = 1; l < nloops && st == TR_OK; l++)
    st = bridge(&t, &P, L + l, Ln + l, nloops - l, what);
  if (st == TR_OK)
    st = earclip(&t, &P, &loc, what);
  if (st == TR_OK) {
    for (uint32_t l = 0; l < nloops; l++)
      for (uint32_t i = 0; i < Ln[l]; i++)
        side[L[l][i]] = L[l][(i + 1) % Ln[l]];
    tr_polyflip_in fin = {(const double(*)[2])t.p, t.id, xyz, side, loc.a, loc.n / 3};
    st = tr_polyflip(&fin, NULL);
  }
  for (uint32_t i = 0; i < loc.n && st == TR_OK; i++)
    st = tr_u32vec_push(out, t.id[loc.a[i]]);
done:
  tr_u32vec_free(&loc);
  free(side);
  tr_u32vec_free(&P);
  free(t.p);
  free(t.id);
  free(L);
  free(Ln);
  free(lidx);
  free(is_hole);
  return st;
}

/* Distance of p from the plane of triangle abc, and twice the triangle's area, in doubles:
 * a measure for a warning, never a decision. */
static double plane_dist(const double *a, const double *b, const double *c, const double *p,
                         double *area2)
{
  double u[3], v[3], w[3], n[3];
  for (int k = 0; k < 3; k++) {
    u[k] = b[k] - a[k];
    v[k] = c[k] - a[k];
    w[k] = p[k] - a[k];
  }
  n[0] = u[1] * v[2] - u[2] * v[1];
  n[1] = u[2] * v[0] - u[0] * v[2];
  n[2] = u[0] * v[1] - u[1] * v[0];
  double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  *area2 = len;
  return len > 0 ? fabs(n[0] * w[0] + n[1] * w[1] + n[2] * w[2]) / len : 0;
}

tr_status tr_plc_nonplanar(const struct tr_plc *plc, tr_nonplanar **out, uint32_t *n)
{
  *out = NULL;
  *n = 0;
  uint32_t cap = 0;
  if (!plc->tri_source)
    return TR_OK; /* one triangle per input facet: nothing to be non-planar */
  if (plc->xq)
    return TR_OK; /* --resolve's pieces of one input triangle: in its plane exactly, where
                     the nearest doubles of their rational corners are not */
  const double *x = plc->xyz;
  for (uint32_t t0 = 0, t1; t0 < plc->ntris; t0 = t1) {
    for (t1 = t0 + 1; t1 < plc->ntris && plc->tri_source[t1] == plc->tri_source[t0]; t1++)
      ;
    if (t1 - t0 < 2)
      continue;
    const uint32_t *r = plc->tris + 3 * (size_t)t0;
    int flat = 1;
    for (uint32_t i = 3 * t0; i < 3 * t1 && flat; i++)
      flat = tr_orient3d(x + 3 * (size_t)r[0], x + 3 * (size_t)r[1], x + 3 * (size_t)r[2],
                         x + 3 * (size_t)plc->tris[i]) == 0;
    if (flat)
      continue;
    /* the largest triangle's plane, then the farthest vertex from it */
    uint32_t big = t0;
    double best = -1, a2, dev = 0, size = 0;
    for (uint32_t t = t0; t < t1; t++) {
      const uint32_t *v = plc->tris + 3 * (size_t)t;
      plane_dist(x + 3 * (size_t)v[0], x + 3 * (size_t)v[1], x + 3 * (size_t)v[2],
                 x + 3 * (size_t)v[0], &a2);
      if (a2 > best) {
        best = a2;
        big = t;
      }
    }
    const uint32_t *b = plc->tris + 3 * (size_t)big;
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0}; /* set by the first point */
    for (uint32_t i = 3 * t0; i < 3 * t1; i++) {
      const double *p = x + 3 * (size_t)plc->tris[i];
      double d = plane_dist(x + 3 * (size_t)b[0], x + 3 * (size_t)b[1], x + 3 * (size_t)b[2], p,
                            &a2);
      dev = d > dev ? d : dev;
      for (int k = 0; k < 3; k++) {
        lo[k] = i == 3 * t0 || p[k] < lo[k] ? p[k] : lo[k];
        hi[k] = i == 3 * t0 || p[k] > hi[k] ? p[k] : hi[k];
      }
    }
    size = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                (hi[2] - lo[2]) * (hi[2] - lo[2]));
    if (*n == cap) {
      cap = cap ? 2 * cap : 16;
      tr_nonplanar *g = realloc(*out, sizeof *g * cap);
      if (!g) {
        free(*out);
        *out = NULL;
        *n = 0;
        return tr_error(TR_ERR_NOMEM, "out of memory");
      }
      *out = g;
    }
    tr_nonplanar *e = *out + (*n)++;
    e->facet = plc->tri_source[t0];
    e->first_tri = t0;
    e->ntris = t1 - t0;
    e->deviation = dev;
    e->relative = size > 0 ? dev / size : 0;
  }
  return TR_OK;
}
