/* The validator of an arrangement (src/resolve), exact and independent of how it was
 * built: every property is checked from the input and the result alone.
 *  - vertices: distinct exact values; each input point is its vertex; each new vertex
 *    lies where it says (inside its input edge or triangle);
 *  - pieces: three distinct vertices, no two with the same three, each oriented as its
 *    sources say, inside each source triangle;
 *  - conservation: the pieces of each live input triangle cover it exactly: the sum of
 *    their areas projected in its frame (GMP rationals) equals its own, each positive;
 *    zero-area triangles have no piece;
 *  - surface complex: no two pieces meet except in a shared vertex or a shared edge
 *    (every edge of one against the other closed piece, exact; a sweep over boxes). */
#ifndef TR_TESTS_RESOLVE_TCHECK_H
#define TR_TESTS_RESOLVE_TCHECK_H

#include <gmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "core/plc.h"
#include "core/vtmap.h"
#include "input/validate.h"
#include "resolve/resolve.h"
#include "../pipeline/texpect.h"

typedef struct {
  const tr_arrangement *a;
  const struct tr_plc *p;
} tc_ctx;

static int tc_lex(const void *ctx, uint32_t x, uint32_t y)
{
  const tc_ctx *c = ctx;
  tr_point p = tr_arr_point(c->a, c->p, x), q = tr_arr_point(c->a, c->p, y);
  for (int i = 0; i < 3; i++) {
    int s = tr_cmp_coord_p(&p, &q, i);
    if (s)
      return s;
  }
  return 0;
}

/* out = twice the signed area of (a, b, c) projected along axis drop (kept axes cyclic). */
static void tc_area2(const tr_point *a, const tr_point *b, const tr_point *c, int drop, mpq_t out)
{
  int x = (drop + 1) % 3, y = (drop + 2) % 3;
  mpq_t ax, ay, bx, by, cx, cy, t;
  mpq_inits(ax, ay, bx, by, cx, cy, t, NULL);
  tr_point_get_q(a, x, ax);
  tr_point_get_q(a, y, ay);
  tr_point_get_q(b, x, bx);
  tr_point_get_q(b, y, by);
  tr_point_get_q(c, x, cx);
  tr_point_get_q(c, y, cy);
  mpq_sub(bx, bx, ax);
  mpq_sub(by, by, ay);
  mpq_sub(cx, cx, ax);
  mpq_sub(cy, cy, ay);
  mpq_mul(out, bx, cy);
  mpq_mul(t, by, cx);
  mpq_sub(out, out, t);
  mpq_clears(ax, ay, bx, by, cx, cy, t, NULL);
}

/* Pieces i and j meet other than in shared vertices and a shared edge. */
static int tc_improper(const tr_arrangement *a, const struct tr_plc *p, uint32_t i, uint32_t j)
{
  for (int side = 0; side < 2; side++) {
    const uint32_t *t = a->pieces[side ? j : i].v, *u = a->pieces[side ? i : j].v;
    tr_point U[3];
    for (int k = 0; k < 3; k++)
      U[k] = tr_arr_point(a, p, u[k]);
    for (int k = 0; k < 3; k++) {
      uint32_t x = t[k], y = t[(k + 1) % 3];
      tr_point X = tr_arr_point(a, p, x), Y = tr_arr_point(a, p, y);
      tr_isect r = tr_classify_segment_triangle(&X, &Y, &U[0], &U[1], &U[2]);
      for (int e = 0; e < r.n; e++) {
        const tr_hit *h = &r.end[e];
        if (!(h->type == TR_NOD && h->code < 3 && (u[h->code] == x || u[h->code] == y)))
          return 1;
      }
    }
  }
  return 0;
}

static void tc_box(const tr_arrangement *a, const struct tr_plc *p, uint32_t i, double lo[3],
                   double hi[3])
{
  for (int d = 0; d < 3; d++) {
    lo[d] = INFINITY;
    hi[d] = -INFINITY;
  }
  for (int k = 0; k < 3; k++) {
    tr_point q = tr_arr_point(a, p, a->pieces[i].v[k]);
    for (int d = 0; d < 3; d++) {
      double l = q.q ? q.q->lo[d] : q.d[d], h = q.q ? q.q->hi[d] : q.d[d];
      lo[d] = l < lo[d] ? l : lo[d];
      hi[d] = h > hi[d] ? h : hi[d];
    }
  }
}

static int tc_cmp_lox(const void *ctx, uint32_t x, uint32_t y)
{
  const double *b = ctx;
  return (b[6 * (size_t)x] > b[6 * (size_t)y]) - (b[6 * (size_t)x] < b[6 * (size_t)y]);
}

/* The soup of tests/data/resolve_cube.off and resolve_cube_moved.off (a unit cube and
 * the same moved by (0.5, 0.5, 0.5)): 16 points into xyz, 24 triangles into tris, the
 * second cube's after the first's. 0 when a file cannot be read. */
static inline int tc_two_cubes(const char *data, double xyz[48], uint32_t tris[72])
{
  char a[1024], b[1024];
  snprintf(a, sizeof a, "%s/resolve_cube.off", data);
  snprintf(b, sizeof b, "%s/resolve_cube_moved.off", data);
  struct tr_plc *pa = NULL, *pb = NULL;
  int ok = tr_plc_read(a, &pa) == TR_OK && tr_plc_read(b, &pb) == TR_OK;
  if (ok) {
    memcpy(xyz, pa->xyz, 24 * sizeof *xyz);
    memcpy(xyz + 24, pb->xyz, 24 * sizeof *xyz);
    memcpy(tris, pa->tris, 36 * sizeof *tris);
    for (int i = 0; i < 36; i++)
      tris[36 + i] = pb->tris[i] + 8;
  }
  if (pa)
    tr_plc_destroy(pa);
  if (pb)
    tr_plc_destroy(pb);
  return ok;
}

/* Checks every property above; returns the number of violations (also counted in
 * failures). */
static int tc_check(const char *name, const struct tr_plc *p, const tr_arrangement *a)
{
  int before = failures;
  tc_ctx c = {a, p};
  /* vertices */
  uint32_t *ord = malloc(sizeof *ord * (a->nverts + 1));
  for (uint32_t i = 0; i < a->nverts; i++)
    ord[i] = i;
  tr_sort_ids(ord, a->nverts, tc_lex, &c);
  for (uint32_t i = 1; i < a->nverts; i++)
    EXPECT(tc_lex(&c, ord[i - 1], ord[i]) != 0, "%s: vertices %u and %u are one point", name,
           ord[i - 1], ord[i]);
  free(ord);
  for (uint32_t i = 0; i < p->npoints; i++) {
    tr_point x = tr_pt_d(p->xyz + 3 * (size_t)i), y = tr_arr_point(a, p, a->of_input[i]);
    EXPECT(tr_equal_p(&x, &y), "%s: input point %u is not its vertex", name, i);
  }
  for (uint32_t v = 0; v < a->nverts; v++) {
    const tr_arr_vertex *x = a->verts + v;
    tr_point q = tr_arr_point(a, p, v);
    if (x->on == TR_ARR_ON_VERTEX) {
      EXPECT(x->input != TR_ARR_NONE && !x->q && x->a == v, "%s: vertex %u: bad input", name, v);
    } else if (x->on == TR_ARR_ON_EDGE) {
      tr_point e0 = tr_arr_point(a, p, x->a), e1 = tr_arr_point(a, p, x->b);
      EXPECT(x->a < x->b && tr_classify_point_segment(&q, &e0, &e1).type == TR_EDG,
             "%s: vertex %u is not inside edge (%u, %u)", name, v, x->a, x->b);
    } else {
      const uint32_t *t = p->tris + 3 * (size_t)x->a;
      tr_point T[3];
      for (int k = 0; k < 3; k++)
        T[k] = tr_pt_d(p->xyz + 3 * (size_t)t[k]);
      EXPECT(tr_classify_point_triangle(&q, &T[0], &T[1], &T[2]).type == TR_FAC,
             "%s: vertex %u is not inside triangle %u", name, v, x->a);
    }
  }
  /* pieces, conservation */
  mpq_t *sum = malloc(sizeof *sum * (p->ntris + 1)), ar, tot;
  mpq_inits(ar, tot, NULL);
  for (uint32_t t = 0; t < p->ntris; t++)
    mpq_init(sum[t]);
  int *drop = calloc(p->ntris + 1, sizeof *drop);
  for (uint32_t t = 0; t < p->ntris; t++) {
    const uint32_t *v = p->tris + 3 * (size_t)t;
    tr_point T[3];
    for (int k = 0; k < 3; k++)
      T[k] = tr_pt_d(p->xyz + 3 * (size_t)v[k]);
    drop[t] = -1;
    for (int d = 0; d < 3 && drop[t] < 0; d++)
      if (tr_orient2d_proj_p(&T[0], &T[1], &T[2], d))
        drop[t] = d;
  }
  tr_vtmap seen = {0};
  for (uint32_t i = 0; i < a->npieces; i++) {
    const tr_arr_piece *x = a->pieces + i;
    EXPECT(x->v[0] < a->nverts && x->v[1] < a->nverts && x->v[2] < a->nverts &&
           x->v[0] != x->v[1] && x->v[1] != x->v[2] && x->v[0] != x->v[2],
           "%s: piece %u has bad vertices", name, i);
    uint32_t k[3], st;
    tr_vtkey_face(x->v[0], x->v[1], x->v[2], k);
    tr_vtmap_put(&seen, 3, k, i, &st);
    EXPECT(st == i, "%s: pieces %u and %u have the same vertices", name, st, i);
    EXPECT(x->nsrc >= 1, "%s: piece %u has no source", name, i);
    tr_point P[3];
    for (int j = 0; j < 3; j++)
      P[j] = tr_arr_point(a, p, x->v[j]);
    for (uint32_t s = 0; s < x->nsrc; s++) {
      const tr_arr_source *y = a->src + x->src + s;
      EXPECT(y->tri < p->ntris && drop[y->tri] >= 0 && (y->sign == 1 || y->sign == -1),
             "%s: piece %u: bad source", name, i);
      if (y->tri >= p->ntris || drop[y->tri] < 0)
        continue;
      EXPECT(s == 0 ? y->sign == 1 : y->tri > a->src[x->src + s - 1].tri,
             "%s: piece %u: sources out of order", name, i);
      const uint32_t *v = p->tris + 3 * (size_t)y->tri;
      tr_point T[3];
      for (int k2 = 0; k2 < 3; k2++)
        T[k2] = tr_pt_d(p->xyz + 3 * (size_t)v[k2]);
      for (int j = 0; j < 3; j++)
        EXPECT(tr_classify_point_triangle(&P[j], &T[0], &T[1], &T[2]).type != TR_DEG,
               "%s: piece %u is not on its source %u", name, i, y->tri);
      tc_area2(&P[0], &P[1], &P[2], drop[y->tri], ar);
      tc_area2(&T[0], &T[1], &T[2], drop[y->tri], tot);
      EXPECT(mpq_sgn(ar) * y->sign == mpq_sgn(tot),
             "%s: piece %u is not oriented as source %u says", name, i, y->tri);
      if (y->sign < 0)
        mpq_neg(ar, ar);
      mpq_add(sum[y->tri], sum[y->tri], ar);
    }
    EXPECT(i == 0 || a->src[x->src].tri >= a->src[a->pieces[i - 1].src].tri,
           "%s: pieces not in the order of their first source", name);
  }
  tr_vtmap_free(&seen);
  for (uint32_t t = 0; t < p->ntris; t++) {
    if (drop[t] < 0) {
      EXPECT(mpq_sgn(sum[t]) == 0, "%s: zero-area triangle %u has pieces", name, t);
      continue;
    }
    const uint32_t *v = p->tris + 3 * (size_t)t;
    tr_point T[3];
    for (int k = 0; k < 3; k++)
      T[k] = tr_pt_d(p->xyz + 3 * (size_t)v[k]);
    tc_area2(&T[0], &T[1], &T[2], drop[t], tot);
    EXPECT(mpq_equal(sum[t], tot), "%s: the pieces of triangle %u do not cover it exactly",
           name, t);
  }
  for (uint32_t t = 0; t < p->ntris; t++)
    mpq_clear(sum[t]);
  mpq_clears(ar, tot, NULL);
  free(sum);
  free(drop);
  /* surface complex: a sweep along x over the pieces' boxes */
  uint32_t n = a->npieces;
  double *box = malloc(sizeof *box * 6 * (n + 1));
  uint32_t *o = malloc(sizeof *o * (n + 1));
  for (uint32_t i = 0; i < n; i++) {
    tc_box(a, p, i, box + 6 * (size_t)i, box + 6 * (size_t)i + 3);
    o[i] = i;
  }
  tr_sort_ids(o, n, tc_cmp_lox, box);
  int bad = 0;
  for (uint32_t x = 0; x < n && bad < 5; x++)
    for (uint32_t y = x + 1; y < n && box[6 * (size_t)o[y]] <= box[6 * (size_t)o[x] + 3]; y++) {
      const double *b1 = box + 6 * (size_t)o[x], *b2 = box + 6 * (size_t)o[y];
      if (b2[1] > b1[4] || b1[1] > b2[4] || b2[2] > b1[5] || b1[2] > b2[5])
        continue;
      if (tc_improper(a, p, o[x], o[y])) {
        EXPECT(0, "%s: pieces %u and %u intersect improperly", name, o[x], o[y]);
        bad++;
      }
    }
  free(box);
  free(o);
  return failures - before;
}

#endif
