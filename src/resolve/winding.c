/* The solid of an arrangement: its cells classified exactly by the winding number of the
 * input (issue 49, step 2; docs/resolve.md).
 *
 * Crossing a piece from its front (the side its normal points to) to its back raises the
 * winding number by the sum of its sources' signs: each source triangle counts +1 when
 * it is oriented as the piece, -1 when opposite. Around an edge, the pieces sorted by
 * angle bound wedges, and the two sides facing one wedge lie in one cell, so they have
 * the same number. Those two relations tie every side of a connected part of the
 * arrangement to one unknown: a union-find that keeps, per piece, the difference of its
 * front's number to its root's. A relation that contradicts the ones before (an open or
 * badly oriented soup) is the error, named by the edge and the pieces' input triangles.
 * One exact ray per connected part then fixes the unknown: the signed count of the
 * pieces it crosses. No tolerance anywhere: the angular order and the crossings are
 * orientation signs of exact points. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "resolve/resolve_impl.h"

/* ---- the weighted union-find: pot[x] = front(x) - front(par[x]) ---- */
typedef struct {
  uint32_t *par;
  int64_t *pot;
} wuf;

static uint32_t wuf_find(wuf *u, uint32_t x, int64_t *d)
{
  /* two passes: find the root and the sum, then point every node on the way at it */
  uint32_t r = x;
  int64_t sum = 0;
  while (u->par[r] != r) {
    sum += u->pot[r];
    r = u->par[r];
  }
  int64_t left = sum;
  while (u->par[x] != r && u->par[x] != x) {
    uint32_t nx = u->par[x];
    int64_t px = u->pot[x];
    u->par[x] = r;
    u->pot[x] = left;
    left -= px;
    x = nx;
  }
  *d = sum;
  return r;
}

/* front(x) - front(y) = d. 1: recorded or consistent, 0: contradicts earlier relations
 * (*off = what they say front(x) - front(y) is). The smaller root stays. */
static int wuf_relate(wuf *u, uint32_t x, uint32_t y, int64_t d, int64_t *off)
{
  int64_t dx, dy;
  uint32_t rx = wuf_find(u, x, &dx), ry = wuf_find(u, y, &dy);
  if (rx == ry) {
    *off = dx - dy;
    return dx - dy == d;
  }
  /* front(rx) - front(ry) = d - dx + dy */
  if (rx < ry) {
    u->par[ry] = rx;
    u->pot[ry] = -(d - dx + dy);
  } else {
    u->par[rx] = ry;
    u->pot[rx] = d - dx + dy;
  }
  return 1;
}

static int64_t piece_weight(const tr_arrangement *arr, uint32_t p)
{
  int64_t s = 0;
  const tr_arr_piece *x = arr->pieces + p;
  for (uint32_t k = 0; k < x->nsrc; k++)
    s += arr->src[x->src + k].sign;
  return s;
}

/* An edge slot: piece p, its corner k starts the edge (v[k], v[k+1]). */
typedef struct {
  uint32_t lo, hi, p;
  uint8_t fwd; /* 1: the piece runs lo -> hi */
} eslot;

static int cmp_eslot(const void *a, const void *b)
{
  const eslot *x = a, *y = b;
  if (x->lo != y->lo)
    return x->lo < y->lo ? -1 : 1;
  if (x->hi != y->hi)
    return x->hi < y->hi ? -1 : 1;
  return x->p < y->p ? -1 : x->p > y->p;
}

typedef struct {
  const tr_arrangement *arr;
  const struct tr_plc *plc;
} ctx;

static tr_point vpt(const ctx *c, uint32_t v) { return tr_arr_point(c->arr, c->plc, v); }

static uint32_t third(const tr_arrangement *arr, uint32_t p, uint32_t a, uint32_t b)
{
  const uint32_t *v = arr->pieces[p].v;
  for (int k = 0; k < 3; k++)
    if (v[k] != a && v[k] != b)
      return v[k];
  return v[0];
}

/* The half-turn around the axis a -> b that piece p's third corner c lies in, measured
 * from the reference half-plane of c0: 0 on it, 1 in (0, pi), 2 at pi, 3 in (pi, 2 pi).
 * -1: c is on the reference half-plane's own side of the axis in its plane, i.e. p
 * overlaps the reference piece (not a surface complex). */
static int half(const tr_point *A, const tr_point *B, const tr_point *C0, const tr_point *C,
                int drop)
{
  int o = tr_orient3d_p(A, B, C0, C);
  if (o > 0)
    return 1;
  if (o < 0)
    return 3;
  return tr_orient2d_proj_p(A, B, C, drop) == tr_orient2d_proj_p(A, B, C0, drop) ? -1 : 2;
}

/* Sorts the slots of one edge by angle around lo -> hi (insertion sort: few per edge).
 * 0, or -1 when two pieces overlap. */
static int radial_sort(const ctx *c, eslot *s, uint32_t n, int *hv)
{
  tr_point A = vpt(c, s[0].lo), B = vpt(c, s[0].hi);
  tr_point C0 = vpt(c, third(c->arr, s[0].p, s[0].lo, s[0].hi));
  int drop, sgn;
  if (rs_frame(&A, &B, &C0, &drop, &sgn) != 0)
    return -1;
  hv[0] = 0;
  for (uint32_t i = 1; i < n; i++) {
    tr_point C = vpt(c, third(c->arr, s[i].p, s[i].lo, s[i].hi));
    if ((hv[i] = half(&A, &B, &C0, &C, drop)) < 0)
      return -1;
  }
  for (uint32_t i = 1; i < n; i++)
    for (uint32_t j = i; j > 1; j--) {
      int before = hv[j] < hv[j - 1];
      if (hv[j] == hv[j - 1]) {
        if (hv[j] == 2)
          return -1; /* two pieces at pi: they overlap */
        tr_point Cj = vpt(c, third(c->arr, s[j].p, s[j].lo, s[j].hi));
        tr_point Ci = vpt(c, third(c->arr, s[j - 1].p, s[j - 1].lo, s[j - 1].hi));
        int o = tr_orient3d_p(&A, &B, &Cj, &Ci); /* > 0: Ci ahead of Cj */
        if (o == 0)
          return -1;
        before = o > 0;
      }
      if (!before)
        break;
      eslot x = s[j];
      s[j] = s[j - 1];
      s[j - 1] = x;
      int h = hv[j];
      hv[j] = hv[j - 1];
      hv[j - 1] = h;
    }
  return 0;
}

/* The input triangle a message names for piece p: the file's element when the reader
 * recorded it. */
static uint32_t src_name(const ctx *c, uint32_t p)
{
  uint32_t t = c->arr->src[c->arr->pieces[p].src].tri;
  return c->plc->tri_source ? c->plc->tri_source[t] : t;
}

/* The relations around every edge; the first contradiction is the error. */
static tr_status relate_edges(const ctx *c, wuf *u, const int64_t *wt)
{
  const tr_arrangement *arr = c->arr;
  size_t ns = 3 * (size_t)arr->npieces;
  eslot *s = malloc(sizeof *s * (ns ? ns : 1));
  int *hv = NULL;
  if (!s)
    return tr_error(TR_ERR_NOMEM, "solid: out of memory for %zu piece edges", ns);
  for (uint32_t p = 0; p < arr->npieces; p++)
    for (int k = 0; k < 3; k++) {
      uint32_t a = arr->pieces[p].v[k], b = arr->pieces[p].v[(k + 1) % 3];
      eslot *x = s + 3 * (size_t)p + k;
      x->lo = a < b ? a : b;
      x->hi = a < b ? b : a;
      x->p = p;
      x->fwd = a < b;
    }
  qsort(s, ns, sizeof *s, cmp_eslot);
  size_t hcap = 0;
  tr_status st = TR_OK;
  for (size_t i = 0; i < ns && st == TR_OK;) {
    size_t j = i + 1;
    while (j < ns && s[j].lo == s[i].lo && s[j].hi == s[i].hi)
      j++;
    uint32_t n = (uint32_t)(j - i);
    if (n > 2) {
      if (n > hcap && (st = rs_grow((void **)&hv, sizeof *hv, n, &hcap)) != TR_OK)
        break;
      if (radial_sort(c, s + i, n, hv) != 0) {
        st = tr_error(TR_ERR_INTERNAL, "solid: pieces %u and others overlap around edge "
                      "(%u, %u) of the arrangement (not a surface complex)", s[i].p,
                      s[i].lo, s[i].hi);
        break;
      }
    }
    /* The side of a piece facing increasing angle (right-hand turn about lo -> hi) is
     * its front when it runs lo -> hi. Consecutive pieces (cyclically) face one wedge:
     * ahead(x) = behind(next). Side numbers: front = f, back = f + weight. */
    for (uint32_t k = 0; k < n; k++) {
      const eslot *x = s + i + k, *y = s + i + (k + 1) % n;
      int64_t ox = x->fwd ? 0 : wt[x->p];  /* x's side ahead, relative to its front */
      int64_t oy = y->fwd ? wt[y->p] : 0;  /* y's side behind */
      int64_t off;
      if (!wuf_relate(u, x->p, y->p, oy - ox, &off)) {
        tr_point A = vpt(c, x->lo), B = vpt(c, x->hi);
        char who[64];
        if (n == 1)
          snprintf(who, sizeof who, "1 piece, of input triangle %u", src_name(c, x->p));
        else
          snprintf(who, sizeof who, "%u pieces, of input triangles %u and %u", n,
                   src_name(c, x->p), src_name(c, y->p));
        st = tr_error(TR_ERR_OPEN,
                      "%s%s--resolve: the winding number is not defined: around the edge "
                      "from (%.17g %.17g %.17g) to (%.17g %.17g %.17g) (%s) the numbers of "
                      "the cells disagree by %lld: an open surface or triangles oriented "
                      "against their neighbours",
                      c->plc->source ? c->plc->source : "", c->plc->source ? ": " : "",
                      A.d[0], A.d[1], A.d[2], B.d[0], B.d[1], B.d[2], who,
                      (long long)((oy - ox) - off));
        break;
      }
    }
    i = j;
  }
  free(s);
  free(hv);
  return st;
}

enum { NDIR = 9 };
static const double dir[NDIR][3] = {
    {0.31, 0.17, 1}, {1, -0.23, 0.41}, {0.57, 1, -0.29}, {-0.61, -0.37, 1}, {1, 0.13, 0.71},
    {0.83, 1, 0.47}, {-0.47, 0.89, 1}, {1, 1, -0.53},    {0, 0, 1}};

typedef struct {
  ctx c;
  const int64_t *wt;
  double *box; /* 6 per piece */
  double len;
  tr_qpoint s;
} caster;

static void point_box(const tr_point *p, double lo[3], double hi[3])
{
  for (int i = 0; i < 3; i++) {
    lo[i] = p->q ? p->q->lo[i] : p->d[i];
    hi[i] = p->q ? p->q->hi[i] : p->d[i];
  }
}

/* The winding number of the side of piece p that a ray from its centroid along dir[d]
 * leaves into: 1 and *w set, 0 when the ray grazes an edge or a vertex or runs in a
 * plane (try another). */
static int cast_dir(caster *k, uint32_t p, int d, int *front, int64_t *w)
{
  const tr_arrangement *arr = k->c.arr;
  const uint32_t *v = arr->pieces[p].v;
  tr_point P[3] = {vpt(&k->c, v[0]), vpt(&k->c, v[1]), vpt(&k->c, v[2])};
  tr_point S = tr_pt_q(&k->s);
  double far[3], slo[3], shi[3];
  for (int i = 0; i < 3; i++) {
    far[i] = k->s.near[i] + k->len * dir[d][i];
    slo[i] = k->s.lo[i] < far[i] ? k->s.lo[i] : far[i];
    shi[i] = k->s.hi[i] > far[i] ? k->s.hi[i] : far[i];
  }
  tr_point F = tr_pt_d(far);
  int o = tr_orient3d_p(&P[0], &P[1], &P[2], &F);
  if (o == 0)
    return 0;
  int64_t sum = 0;
  for (uint32_t q = 0; q < arr->npieces; q++) {
    const double *bx = k->box + 6 * (size_t)q;
    if (q == p || bx[0] > shi[0] || bx[1] > shi[1] || bx[2] > shi[2] || bx[3] < slo[0] ||
        bx[4] < slo[1] || bx[5] < slo[2])
      continue;
    const uint32_t *u = arr->pieces[q].v;
    tr_point U[3] = {vpt(&k->c, u[0]), vpt(&k->c, u[1]), vpt(&k->c, u[2])};
    tr_isect r = tr_classify_segment_triangle(&S, &F, &U[0], &U[1], &U[2]);
    if (r.n == 0)
      continue;
    if (r.n != 1 || r.end[0].type != TR_FAC || r.end[0].on_seg != TR_SEG_IN)
      return 0;
    /* leaving q through its front (S behind it) means S counts q's sources */
    int os = tr_orient3d_p(&U[0], &U[1], &U[2], &S);
    sum += os < 0 ? k->wt[q] : -k->wt[q];
  }
  *front = o > 0;
  *w = sum;
  return 1;
}

static void centroid(const ctx *c, uint32_t p, tr_qpoint *q)
{
  mpq_t x;
  mpq_init(x);
  for (int i = 0; i < 3; i++) {
    mpq_set_ui(q->c[i], 0, 1);
    for (int k = 0; k < 3; k++) {
      tr_point P = vpt(c, c->arr->pieces[p].v[k]);
      tr_point_get_q(&P, i, x);
      mpq_add(q->c[i], q->c[i], x);
    }
    mpq_set_ui(x, 3, 1);
    mpq_div(q->c[i], q->c[i], x);
  }
  mpq_clear(x);
  tr_qpoint_update(q);
}

void tr_solid_free(tr_solid *s)
{
  free(s->front);
  free(s->weight);
  free(s->keep);
  memset(s, 0, sizeof *s);
}

tr_status tr_solid_classify(const struct tr_plc *plc, const tr_arrangement *arr,
                            int keep_internal, tr_solid *sol)
{
  memset(sol, 0, sizeof *sol);
  uint32_t n = arr->npieces;
  size_t n1 = n ? n : 1;
  ctx c = {arr, plc};
  wuf u = {malloc(sizeof(uint32_t) * n1), malloc(sizeof(int64_t) * n1)};
  sol->front = malloc(sizeof *sol->front * n1);
  sol->weight = malloc(sizeof *sol->weight * n1);
  sol->keep = calloc(n1, 1);
  caster k;
  memset(&k, 0, sizeof k);
  k.c = c;
  k.wt = sol->weight;
  k.box = malloc(sizeof *k.box * 6 * n1);
  uint32_t *first = malloc(sizeof *first * n1); /* per root: the next piece to try */
  tr_status st = TR_OK;
  if (!u.par || !u.pot || !sol->front || !sol->weight || !sol->keep || !k.box || !first) {
    st = tr_error(TR_ERR_NOMEM, "solid: out of memory for %u pieces", n);
    goto done;
  }
  sol->npieces = n;
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (uint32_t p = 0; p < n; p++) {
    u.par[p] = p;
    u.pot[p] = 0;
    sol->weight[p] = piece_weight(arr, p);
    double *bx = k.box + 6 * (size_t)p;
    for (int j = 0; j < 3; j++) {
      tr_point P = vpt(&c, arr->pieces[p].v[j]);
      double l[3], h[3];
      point_box(&P, l, h);
      for (int i = 0; i < 3; i++) {
        bx[i] = j == 0 || l[i] < bx[i] ? l[i] : bx[i];
        bx[3 + i] = j == 0 || h[i] > bx[3 + i] ? h[i] : bx[3 + i];
        lo[i] = (p == 0 && j == 0) || l[i] < lo[i] ? l[i] : lo[i];
        hi[i] = (p == 0 && j == 0) || h[i] > hi[i] ? h[i] : hi[i];
      }
    }
  }
  if ((st = relate_edges(&c, &u, sol->weight)) != TR_OK)
    goto done;
  k.len = 2 * ((hi[0] - lo[0]) + (hi[1] - lo[1]) + (hi[2] - lo[2])) + 1;
  for (int i = 0; i < 3; i++)
    if (!(k.len + hi[i] - lo[i] < 1e300) || hi[i] > 1e300 || lo[i] < -1e300) {
      st = tr_error(TR_ERR_UNSUPPORTED, "--resolve: coordinates too large for the rays that "
                    "classify the cells");
      goto done;
    }
  tr_qpoint_init(&k.s);
  /* One ray per connected part, from its pieces in increasing order until one is clean
   * (at most 16 pieces of a part are tried). root_w: front number of each root. */
  int64_t *root_w = (int64_t *)sol->front; /* filled per root, then per piece */
  uint8_t *known = sol->keep;              /* reused as a per-root flag until the end */
  for (uint32_t p = 0; p < n; p++)
    first[p] = 0;
  for (uint32_t p = 0; p < n && st == TR_OK; p++) {
    int64_t dp;
    uint32_t r = wuf_find(&u, p, &dp);
    if (known[r] || first[r] >= 16)
      continue;
    first[r]++;
    if (r == p)
      sol->ncomponents++;
    centroid(&c, p, &k.s);
    for (int d = 0; d < NDIR; d++) {
      int front;
      int64_t w;
      sol->nrays++;
      if (cast_dir(&k, p, d, &front, &w)) {
        int64_t f = front ? w : w - sol->weight[p]; /* p's front number */
        root_w[r] = f - dp;
        known[r] = 1;
        break;
      }
    }
  }
  tr_qpoint_clear(&k.s);
  for (uint32_t p = 0; p < n && st == TR_OK; p++) {
    int64_t dp;
    uint32_t r = wuf_find(&u, p, &dp);
    if (!known[r])
      st = tr_error(TR_ERR_UNSUPPORTED, "--resolve: cannot classify the cells around input "
                    "triangle %u: every ray tried from 16 of its pieces grazes an edge",
                    src_name(&c, p));
  }
  if (st != TR_OK)
    goto done;
  /* roots first (r <= p), so root_w[r] is read before piece r's own slot is rewritten */
  for (uint32_t p = 0; p < n; p++) {
    int64_t dp;
    uint32_t r = wuf_find(&u, p, &dp);
    sol->front[p] = root_w[r] + dp;
  }
  for (uint32_t p = 0; p < n; p++) {
    int in_f = sol->front[p] >= 1, in_b = sol->front[p] + sol->weight[p] >= 1;
    uint8_t x = in_b && !in_f   ? TR_SOLID_KEEP
                : in_f && !in_b ? TR_SOLID_FLIP
                : in_f && keep_internal ? TR_SOLID_INTERNAL
                                        : TR_SOLID_DROP;
    sol->keep[p] = x;
    sol->nkept += x == TR_SOLID_KEEP || x == TR_SOLID_FLIP;
    sol->ninternal += x == TR_SOLID_INTERNAL;
  }
done:
  free(u.par);
  free(u.pot);
  free(k.box);
  free(first);
  if (st != TR_OK)
    tr_solid_free(sol);
  return st;
}

tr_status tr_solid_volume6(const struct tr_plc *plc, const tr_arrangement *arr,
                           const tr_solid *sol, mpq_t out)
{
  ctx c = {arr, plc};
  mpq_t m[3][3], t, d;
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      mpq_init(m[i][j]);
  mpq_inits(t, d, NULL);
  mpq_set_ui(out, 0, 1);
  for (uint32_t p = 0; p < arr->npieces; p++) {
    int kp = sol->keep[p];
    if (kp != TR_SOLID_KEEP && kp != TR_SOLID_FLIP)
      continue;
    for (int i = 0; i < 3; i++) {
      tr_point P = vpt(&c, arr->pieces[p].v[i]);
      for (int j = 0; j < 3; j++)
        tr_point_get_q(&P, j, m[i][j]);
    }
    /* det[a; b; c] = 6 * the signed volume of (0, a, b, c) */
    mpq_mul(t, m[1][1], m[2][2]);
    mpq_mul(d, m[1][2], m[2][1]);
    mpq_sub(t, t, d);
    mpq_mul(d, m[0][0], t);
    mpq_set(t, d);
    mpq_mul(d, m[1][0], m[2][2]);
    mpq_t e;
    mpq_init(e);
    mpq_mul(e, m[1][2], m[2][0]);
    mpq_sub(d, d, e);
    mpq_mul(e, m[0][1], d);
    mpq_sub(t, t, e);
    mpq_mul(d, m[1][0], m[2][1]);
    mpq_mul(e, m[1][1], m[2][0]);
    mpq_sub(d, d, e);
    mpq_mul(e, m[0][2], d);
    mpq_add(t, t, e);
    mpq_clear(e);
    if (kp == TR_SOLID_FLIP)
      mpq_neg(t, t);
    mpq_add(out, out, t);
  }
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      mpq_clear(m[i][j]);
  mpq_clears(t, d, NULL);
  return TR_OK;
}
