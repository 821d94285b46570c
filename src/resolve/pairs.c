/* The cuts: the exact intersection of every improper pair of input triangles.
 *
 * The pairs come from the self-intersection test (src/input/selfint.c, its grid or sweep
 * broad phase and exact narrow phase), run on the input with repeated points merged
 * (corners renamed to the first point of their value, so that "shared vertex" means
 * "same point") and zero-area triangles left out (they bound nothing and give no piece).
 *
 * Two triangles in different planes meet in a segment or a point of the line common to
 * the planes. That set is convex, and its ends are points of edges of one triangle in the
 * other: the classifier of each edge against the other triangle (classify.h) gives them
 * all, and the two extreme ones (lexicographic order is monotone along a line) are the
 * segment. Coplanar triangles meet in a convex polygon: the parts of each one's edges
 * inside the other are its sides, cut on both (so both get split along the other's
 * boundary, and their common region the same way). */
#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "construct.h"
#include "input/validate.h"
#include "predicates.h"
#include "resolve/resolve_impl.h"

tr_status rs_input_init(rs_input *in, const rs_points *ps, const uint32_t *of_input,
                        uint64_t *ndropped)
{
  const struct tr_plc *plc = ps->plc;
  memset(in, 0, sizeof *in);
  in->ntris = plc->ntris;
  in->tris = malloc(sizeof *in->tris * 3 * (size_t)(plc->ntris ? plc->ntris : 1));
  in->live = malloc(plc->ntris ? plc->ntris : 1);
  if (!in->tris || !in->live)
    return tr_error(TR_ERR_NOMEM, "arrangement: out of memory for %u triangles", plc->ntris);
  *ndropped = 0;
  for (uint32_t t = 0; t < plc->ntris; t++) {
    const uint32_t *v = plc->tris + 3 * (size_t)t;
    uint32_t *w = in->tris + 3 * (size_t)t;
    for (int k = 0; k < 3; k++) {
      if (v[k] >= plc->npoints)
        return tr_error(TR_ERR_INPUT, "arrangement: triangle %u has point %u of %u", t, v[k],
                        plc->npoints);
      w[k] = of_input[v[k]];
    }
    int live = w[0] != w[1] && w[1] != w[2] && w[0] != w[2];
    if (live) {
      const double *a = plc->xyz + 3 * (size_t)v[0], *b = plc->xyz + 3 * (size_t)v[1],
                   *c = plc->xyz + 3 * (size_t)v[2];
      live = tr_orient2d_proj(a, b, c, 0) != 0 || tr_orient2d_proj(a, b, c, 1) != 0 ||
             tr_orient2d_proj(a, b, c, 2) != 0;
    }
    in->live[t] = (uint8_t)live;
    *ndropped += !live;
  }
  return TR_OK;
}

void rs_input_free(rs_input *in)
{
  free(in->tris);
  free(in->live);
  memset(in, 0, sizeof *in);
}

typedef struct {
  const rs_input *in;
  rs_points *ps;
  rs_cut *cuts;
  size_t n, cap;
  tr_qpoint q;
} ctx;

static tr_status push(ctx *x, uint32_t t, uint32_t a, uint32_t b)
{
  TR_CHECK(rs_grow((void **)&x->cuts, sizeof *x->cuts, x->n + 1, &x->cap));
  x->cuts[x->n].tri = t;
  x->cuts[x->n].a = a;
  x->cuts[x->n++].b = b;
  return TR_OK;
}

static const double *xyz_of(const ctx *x, uint32_t v)
{
  return x->ps->plc->xyz + 3 * (size_t)x->ps->v[v].input;
}

/* The vertex at end h of the classification of edge (a, b) of a triangle against
 * triangle y (corners Y, vertices yv); flat: ab lies in y's plane. */
static tr_status end_vertex(ctx *x, uint32_t a, uint32_t b, const tr_point *A,
                            const tr_point *B, const uint32_t *yv, const tr_point *Y,
                            int flat, const tr_hit *h, uint32_t *id)
{
  if (h->on_seg == TR_SEG_A) {
    *id = a;
    return TR_OK;
  }
  if (h->on_seg == TR_SEG_B) {
    *id = b;
    return TR_OK;
  }
  if (h->type == TR_NOD) {
    *id = yv[h->code];
    return TR_OK;
  }
  uint32_t ea = a < b ? a : b, eb = a < b ? b : a;
  int r;
  if (flat) {
    if (h->type != TR_EDG)
      return tr_error(TR_ERR_INTERNAL, "arrangement: a flat edge ends inside a triangle");
    int s = tr_ecode_start(h->code), e = tr_ecode_end(h->code);
    r = tr_construct_line_line(A, B, &Y[s], &Y[e], &x->q);
    uint32_t fa = yv[s] < yv[e] ? yv[s] : yv[e], fb = yv[s] < yv[e] ? yv[e] : yv[s];
    if (fa < ea || (fa == ea && fb < eb))
      ea = fa, eb = fb;
  } else {
    r = tr_construct_line_plane(A, B, &Y[0], &Y[1], &Y[2], &x->q);
  }
  if (r)
    return tr_error(TR_ERR_INTERNAL, "arrangement: an intersection point not constructed");
  tr_point p = tr_pt_q(&x->q);
  return rs_points_add(x->ps, &p, TR_ARR_ON_EDGE, ea, eb, id);
}

/* Lexicographic comparison of vertices (exact). */
static int lex(const rs_points *ps, uint32_t a, uint32_t b)
{
  tr_point p = rs_pt(ps, a), q = rs_pt(ps, b);
  for (int i = 0; i < 3; i++) {
    int c = tr_cmp_coord_p(&p, &q, i);
    if (c)
      return c;
  }
  return 0;
}

static tr_status pair_cuts(ctx *x, uint32_t t, uint32_t u, uint64_t *ncoplanar)
{
  const uint32_t *tv = x->in->tris + 3 * (size_t)t, *uv = x->in->tris + 3 * (size_t)u;
  tr_point T[3], U[3];
  for (int k = 0; k < 3; k++) {
    T[k] = tr_pt_d(xyz_of(x, tv[k]));
    U[k] = tr_pt_d(xyz_of(x, uv[k]));
  }
  /* side of each corner against the other's plane */
  int st[3], su[3], coplanar = 1;
  for (int k = 0; k < 3; k++) {
    su[k] = tr_sign(tr_orient3d(T[0].d, T[1].d, T[2].d, U[k].d));
    st[k] = tr_sign(tr_orient3d(U[0].d, U[1].d, U[2].d, T[k].d));
    coplanar &= su[k] == 0;
  }
  *ncoplanar += coplanar;
  uint32_t ids[12];
  int nid = 0;
  for (int side = 0; side < 2; side++) {
    const uint32_t *xv = side ? uv : tv, *yv = side ? tv : uv;
    const tr_point *X = side ? U : T, *Y = side ? T : U;
    const int *sx = side ? su : st; /* X's corners against Y's plane */
    for (int k = 0; k < 3; k++) {
      int k1 = (k + 1) % 3;
      tr_isect r = tr_classify_segment_triangle(&X[k], &X[k1], &Y[0], &Y[1], &Y[2]);
      uint32_t e[2];
      for (int i = 0; i < r.n; i++)
        TR_CHECK(end_vertex(x, xv[k], xv[k1], &X[k], &X[k1], yv, Y, !sx[k] && !sx[k1],
                            &r.end[i], &e[i]));
      if (coplanar) { /* each piece of boundary inside the other, on both */
        uint32_t b = r.n == 2 && e[1] != e[0] ? e[1] : TR_ARR_NONE;
        if (r.n) {
          TR_CHECK(push(x, t, e[0], b));
          TR_CHECK(push(x, u, e[0], b));
        }
        continue;
      }
      for (int i = 0; i < r.n; i++) {
        int seen = 0;
        for (int j = 0; j < nid; j++)
          seen |= ids[j] == e[i];
        if (!seen)
          ids[nid++] = e[i];
      }
    }
  }
  if (coplanar || !nid)
    return TR_OK;
  uint32_t lo = ids[0], hi = ids[0];
  for (int j = 1; j < nid; j++) {
    if (lex(x->ps, ids[j], lo) < 0)
      lo = ids[j];
    if (lex(x->ps, ids[j], hi) > 0)
      hi = ids[j];
  }
  uint32_t b = hi != lo ? hi : TR_ARR_NONE;
  TR_CHECK(push(x, t, lo, b));
  return push(x, u, lo, b);
}

tr_status rs_pair_cuts(const rs_input *in, rs_points *ps, rs_cut **cuts, size_t *ncuts,
                       uint64_t *npairs, uint64_t *ncoplanar)
{
  const struct tr_plc *plc = ps->plc;
  *cuts = NULL;
  *ncuts = 0;
  *npairs = *ncoplanar = 0;
  uint32_t nlive = 0;
  for (uint32_t t = 0; t < in->ntris; t++)
    nlive += in->live[t];
  /* the live triangles on the first point of each value */
  uint32_t *live = malloc(sizeof *live * (nlive ? nlive : 1));
  uint32_t *tris = malloc(sizeof *tris * 3 * (size_t)(nlive ? nlive : 1));
  if (!live || !tris) {
    free(live);
    free(tris);
    return tr_error(TR_ERR_NOMEM, "arrangement: out of memory for %u triangles", nlive);
  }
  for (uint32_t t = 0, k = 0; t < in->ntris; t++)
    if (in->live[t]) {
      live[k] = t;
      for (int j = 0; j < 3; j++)
        tris[3 * (size_t)k + j] = ps->v[in->tris[3 * (size_t)t + j]].input;
      k++;
    }
  struct tr_plc sub;
  memset(&sub, 0, sizeof sub);
  sub.npoints = plc->npoints;
  sub.xyz = plc->xyz;
  sub.ntris = nlive;
  sub.tris = tris;
  uint32_t *pairs = NULL;
  size_t np = 0;
  tr_status st = tr_input_self_intersection_pairs(&sub, TR_SELFINT_AUTO, &pairs, &np);
  ctx x;
  memset(&x, 0, sizeof x);
  x.in = in;
  x.ps = ps;
  tr_qpoint_init(&x.q);
  for (size_t i = 0; i < np && st == TR_OK; i++)
    st = pair_cuts(&x, live[pairs[2 * i]], live[pairs[2 * i + 1]], ncoplanar);
  tr_qpoint_clear(&x.q);
  free(pairs);
  free(live);
  free(tris);
  if (st != TR_OK) {
    free(x.cuts);
    return st;
  }
  *npairs = np;
  *cuts = x.cuts;
  *ncuts = x.n;
  return TR_OK;
}
