/* One triangle's pieces: its cuts made a planar straight-line graph, then triangulated.
 *
 * Cuts from different pairs can cross inside the triangle (at the point common to three
 * planes, or where a coplanar neighbour's edge crosses a cut): those crossings are
 * constructed exactly and become vertices. Then every cut is split at every point of the
 * triangle inside it (crossings, ends of other cuts, single-point cuts), so that no two
 * cuts cross and no point lies inside one: the input the constrained triangulation needs.
 * The same point found on another triangle is the same vertex (points.c), so two
 * triangles split their common segment at the same points.
 *
 * Every pair of cuts and every cut against every point is tested: quadratic in the cuts
 * of one triangle, which the models measured keep small (docs/resolve.md). */
#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "construct.h"
#include "input/validate.h"
#include "predicates.h"
#include "resolve/resolve_impl.h"

struct rs_sub {
  tr_vtmap loc;    /* vertex -> local index */
  uint32_t *pid;   /* local index -> vertex */
  tr_point *pts;   /* local index -> point */
  size_t np, cpid, cpts;
  uint32_t *seg, *split; /* local pairs: the cuts, the split cuts */
  size_t nseg, cseg, nsplit, csplit;
  uint32_t *on;    /* the points inside one cut, sorted */
  size_t con;
  double *box;     /* lo[3] hi[3] per point, enclosing it */
  size_t cbox;
  rs_cdt *cdt;
  tr_qpoint q;
  const rs_points *ps;
};

tr_status rs_sub_create(rs_sub **s)
{
  if (!(*s = calloc(1, sizeof **s)))
    return tr_error(TR_ERR_NOMEM, "arrangement: out of memory");
  tr_qpoint_init(&(*s)->q);
  return rs_cdt_create(&(*s)->cdt);
}

void rs_sub_destroy(rs_sub *s)
{
  if (!s)
    return;
  tr_vtmap_free(&s->loc);
  free(s->pid);
  free(s->pts);
  free(s->seg);
  free(s->split);
  free(s->on);
  free(s->box);
  rs_cdt_destroy(s->cdt);
  tr_qpoint_clear(&s->q);
  free(s);
}

/* *l = the local index of vertex v, added if new. */
static tr_status local(rs_sub *s, const rs_points *ps, uint32_t v, uint32_t *l)
{
  uint32_t stored;
  TR_CHECK(tr_vtmap_put(&s->loc, 1, &v, (uint32_t)s->np, &stored));
  *l = stored;
  if (stored != s->np)
    return TR_OK;
  TR_CHECK(rs_grow((void **)&s->pid, sizeof *s->pid, s->np + 1, &s->cpid));
  TR_CHECK(rs_grow((void **)&s->box, 6 * sizeof *s->box, s->np + 1, &s->cbox));
  s->pid[s->np] = v;
  tr_point p = rs_pt(ps, v);
  double *b = s->box + 6 * s->np;
  for (int i = 0; i < 3; i++) {
    b[i] = p.q ? p.q->lo[i] : p.d[i];
    b[3 + i] = p.q ? p.q->hi[i] : p.d[i];
  }
  s->np++;
  return TR_OK;
}

static tr_status add_seg(uint32_t **seg, size_t *n, size_t *cap, uint32_t a, uint32_t b)
{
  TR_CHECK(rs_grow((void **)seg, 2 * sizeof **seg, *n + 1, cap));
  (*seg)[2 * *n] = a < b ? a : b;
  (*seg)[2 * (*n)++ + 1] = a < b ? b : a;
  return TR_OK;
}

static int cmp_seg(const void *x, const void *y)
{
  const uint32_t *a = x, *b = y;
  if (a[0] != b[0])
    return a[0] < b[0] ? -1 : 1;
  return (a[1] > b[1]) - (a[1] < b[1]);
}

static size_t unique_segs(uint32_t *seg, size_t n)
{
  if (!n)
    return 0;
  qsort(seg, n, 2 * sizeof *seg, cmp_seg);
  size_t m = 1;
  for (size_t i = 1; i < n; i++)
    if (cmp_seg(seg + 2 * i, seg + 2 * (m - 1)))
      memcpy(seg + 2 * m++, seg + 2 * i, 2 * sizeof *seg);
  return m;
}

/* The boxes of the points of local indices a, b and the box of c, d can meet. */
static int boxes_meet(const rs_sub *s, uint32_t a, uint32_t b, uint32_t c, uint32_t d)
{
  const double *A = s->box + 6 * a, *B = s->box + 6 * b, *C = s->box + 6 * c,
               *D = s->box + 6 * d;
  for (int i = 0; i < 3; i++) {
    double l1 = A[i] < B[i] ? A[i] : B[i], h1 = A[3 + i] > B[3 + i] ? A[3 + i] : B[3 + i];
    double l2 = C[i] < D[i] ? C[i] : D[i], h2 = C[3 + i] > D[3 + i] ? C[3 + i] : D[3 + i];
    if (l1 > h2 || l2 > h1)
      return 0;
  }
  return 1;
}

/* Lexicographic order of local points: monotone along any line. */
static int cmp_lex(const void *ctx, uint32_t a, uint32_t b)
{
  const rs_sub *s = ctx;
  const tr_point *p = s->pts + a, *q = s->pts + b;
  for (int i = 0; i < 3; i++) {
    int c = tr_cmp_coord_p(p, q, i);
    if (c)
      return c;
  }
  return 0;
}

static tr_status refresh_pts(rs_sub *s)
{
  TR_CHECK(rs_grow((void **)&s->pts, sizeof *s->pts, s->np, &s->cpts));
  for (size_t i = 0; i < s->np; i++)
    s->pts[i] = rs_pt(s->ps, s->pid[i]);
  return TR_OK;
}

tr_status rs_subdivide(rs_sub *s, const rs_input *in, rs_points *ps, uint32_t t,
                       const rs_cut *cuts, size_t n, uint32_t **out, size_t *nout, size_t *cap,
                       uint64_t *ncross)
{
  const uint32_t *tv = in->tris + 3 * (size_t)t;
  s->ps = ps;
  s->np = s->nseg = s->nsplit = 0;
  tr_vtmap_clear(&s->loc);
  uint32_t l, m;
  for (int k = 0; k < 3; k++)
    TR_CHECK(local(s, ps, tv[k], &l));
  for (size_t i = 0; i < n; i++) {
    TR_CHECK(local(s, ps, cuts[i].a, &l));
    if (cuts[i].b == TR_ARR_NONE)
      continue;
    TR_CHECK(local(s, ps, cuts[i].b, &m));
    if (l != m)
      TR_CHECK(add_seg(&s->seg, &s->nseg, &s->cseg, l, m));
  }
  s->nseg = unique_segs(s->seg, s->nseg);
  /* crossings of two cuts at a point inside both */
  for (size_t i = 0; i < s->nseg; i++)
    for (size_t j = i + 1; j < s->nseg; j++) {
      uint32_t a = s->seg[2 * i], b = s->seg[2 * i + 1], c = s->seg[2 * j], d = s->seg[2 * j + 1];
      if (a == c || a == d || b == c || b == d || !boxes_meet(s, a, b, c, d))
        continue;
      tr_point A = rs_pt(ps, s->pid[a]), B = rs_pt(ps, s->pid[b]), C = rs_pt(ps, s->pid[c]),
               D = rs_pt(ps, s->pid[d]);
      tr_isect r = tr_classify_segment_segment(&A, &B, &C, &D);
      if (r.n != 1 || r.end[0].on_seg != TR_SEG_IN || r.end[0].type != TR_EDG)
        continue;
      if (tr_construct_line_line(&A, &B, &C, &D, &s->q))
        return tr_error(TR_ERR_INTERNAL, "arrangement: a crossing not constructed");
      tr_point x = tr_pt_q(&s->q);
      uint32_t v;
      TR_CHECK(rs_points_add(ps, &x, TR_ARR_ON_TRI, t, 0, &v));
      TR_CHECK(local(s, ps, v, &l));
      ++*ncross;
    }
  TR_CHECK(refresh_pts(s));
  /* every cut split at the points inside it */
  for (size_t i = 0; i < s->nseg; i++) {
    uint32_t a = s->seg[2 * i], b = s->seg[2 * i + 1];
    size_t k = 0;
    for (uint32_t p = 0; p < s->np; p++) {
      if (p == a || p == b || !boxes_meet(s, a, b, p, p))
        continue;
      if (tr_classify_point_segment(&s->pts[p], &s->pts[a], &s->pts[b]).type != TR_EDG)
        continue;
      TR_CHECK(rs_grow((void **)&s->on, sizeof *s->on, k + 1, &s->con));
      s->on[k++] = p;
    }
    if (k > 1)
      TR_CHECK(tr_sort_ids(s->on, (uint32_t)k, cmp_lex, s));
    int rev = cmp_lex(s, a, b) > 0;
    uint32_t prev = a;
    for (size_t j = 0; j < k; j++) {
      uint32_t p = s->on[rev ? k - 1 - j : j];
      TR_CHECK(add_seg(&s->split, &s->nsplit, &s->csplit, prev, p));
      prev = p;
    }
    TR_CHECK(add_seg(&s->split, &s->nsplit, &s->csplit, prev, b));
  }
  s->nsplit = unique_segs(s->split, s->nsplit);
  int drop, sgn;
  if (rs_frame(&s->pts[0], &s->pts[1], &s->pts[2], &drop, &sgn))
    return tr_error(TR_ERR_INTERNAL, "arrangement: a live triangle of zero area");
  const uint32_t *tris;
  uint32_t nt;
  TR_CHECK(rs_cdt_run(s->cdt, s->pts, s->pid, (uint32_t)s->np, drop, sgn, s->split,
                      (uint32_t)s->nsplit, &tris, &nt));
  TR_CHECK(rs_grow((void **)out, 3 * sizeof **out, *nout + nt, cap));
  for (uint32_t k = 0; k < nt; k++)
    for (int j = 0; j < 3; j++)
      (*out)[3 * (*nout + k) + j] = s->pid[tris[3 * k + j]];
  *nout += nt;
  return TR_OK;
}
