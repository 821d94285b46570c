/* Edge collapses inside the envelope, worst triangle first (tr_simp_collapse).
 *
 * A collapse u -> v removes vertex u: its triangles that hold v go, the others get v in
 * place of u. It is made only when
 *  - u may move that way: u is on no feature edge, or on exactly two (a chain) and uv is
 *    one of them (so the chain stays a chain of edges); feature edges are sharp ones
 *    (normals more than TR_SIMP_SHARP_DEG apart), marker boundaries, open and
 *    non-manifold edges, and their ends and corners never move;
 *  - the topology stays: u's star is one disk, and the links of u and v share exactly
 *    the two vertices opposite uv (the link condition), no triangle is made twice;
 *  - no normal turns over: each new triangle's normal has a positive dot product with
 *    the one it replaces (exact sign);
 *  - the smallest angle of the triangles changed grows (a choice, in doubles);
 *  - the envelope holds both ways: every new triangle lies within d of the input
 *    surface, and every input point that was within d of u's old star is within d of
 *    the new triangles and their neighbours (input points farther than d from the old
 *    star were covered by triangles the collapse leaves alone). Both proven by
 *    tr_simp_cover; a piece budget run out counts as a refusal.
 * Self-intersections are left to the caller (stage.c), which checks the whole result
 * exactly and freezes what took part. Everything is decided in a fixed order (the heap
 * breaks ties by triangle id), so the result is the same on every run. */
#define _DEFAULT_SOURCE
#include <gmp.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "collapse.h"
#include "core/vtmap.h"
#include "simplify.h"
#include "simplify_impl.h"

#define COVER_BUDGET 4096

enum { FREE = 0, FROZEN = 1, CHAIN = 2, GONE = 3 };

typedef struct {
  double key;
  uint32_t t;
} hitem;

typedef struct {
  const struct tr_plc *plc;
  const double *x;
  double d;
  uint32_t *tri, *orig, nt, cap;
  uint8_t *dead;
  uint32_t *mark, tick; /* per triangle slot, for target lists */
  uint32_t **inc, *ninc, *cinc;
  uint8_t *cls;
  tr_vtmap feat;
  tr_simp_grid g;
  uint32_t *cand, ncand, ccand;
  hitem *h;
  uint32_t nh, ch;
  uint32_t *buf, nbuf, cbuf; /* targets */
  uint32_t *into;            /* the vertex each removed one went to */
} ctx;

static uint32_t root_of(ctx *c, uint32_t v)
{
  uint32_t r = v;
  while (c->into[r] != r)
    r = c->into[r];
  while (c->into[v] != r) { /* path compression: the roots stay */
    uint32_t n = c->into[v];
    c->into[v] = r;
    v = n;
  }
  return r;
}

static const double *P(const ctx *c, uint32_t v) { return c->x + 3 * (size_t)v; }

static double min_angle(const double *a, const double *b, const double *c)
{
  const double *p[3] = {a, b, c};
  double m = 180;
  for (int i = 0; i < 3; i++) {
    double u[3], v[3], x[3];
    for (int k = 0; k < 3; k++)
      u[k] = p[(i + 1) % 3][k] - p[i][k], v[k] = p[(i + 2) % 3][k] - p[i][k];
    x[0] = u[1] * v[2] - u[2] * v[1];
    x[1] = u[2] * v[0] - u[0] * v[2];
    x[2] = u[0] * v[1] - u[1] * v[0];
    double ang = atan2(sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]),
                       u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) * (180 / M_PI);
    m = ang < m ? ang : m;
  }
  return m;
}

static double tri_angle(const ctx *c, uint32_t t)
{
  const uint32_t *v = c->tri + 3 * (size_t)t;
  return min_angle(P(c, v[0]), P(c, v[1]), P(c, v[2]));
}

/* sign of ((b-a) x (c-a)) . ((e-d) x (f-d)): a double filter (each side's error under
 * 32 u times the product of the 1-norms), exact rationals when it cannot tell */
static int normal_dot_sign(const double *a, const double *b, const double *c, const double *d,
                           const double *e, const double *f)
{
  double u[3], v[3], w[3], z[3], n[3], m[3];
  for (int k = 0; k < 3; k++)
    u[k] = b[k] - a[k], v[k] = c[k] - a[k], w[k] = e[k] - d[k], z[k] = f[k] - d[k];
  n[0] = u[1] * v[2] - u[2] * v[1], n[1] = u[2] * v[0] - u[0] * v[2];
  n[2] = u[0] * v[1] - u[1] * v[0];
  m[0] = w[1] * z[2] - w[2] * z[1], m[1] = w[2] * z[0] - w[0] * z[2];
  m[2] = w[0] * z[1] - w[1] * z[0];
  double s = n[0] * m[0] + n[1] * m[1] + n[2] * m[2];
  double n1 = (fabs(u[0]) + fabs(u[1]) + fabs(u[2])) * (fabs(v[0]) + fabs(v[1]) + fabs(v[2]));
  double m1 = (fabs(w[0]) + fabs(w[1]) + fabs(w[2])) * (fabs(z[0]) + fabs(z[1]) + fabs(z[2]));
  double err = 0x1p-44 * n1 * m1;
  if (s > err)
    return 1;
  if (s < -err)
    return -1;
  mpq_t q[12], N[3], M[3], t;
  for (int i = 0; i < 12; i++)
    mpq_init(q[i]);
  for (int i = 0; i < 3; i++)
    mpq_init(N[i]), mpq_init(M[i]);
  mpq_init(t);
  const double *src[4][2] = {{b, a}, {c, a}, {e, d}, {f, d}};
  for (int r = 0; r < 4; r++)
    for (int k = 0; k < 3; k++) {
      mpq_set_d(q[3 * r + k], src[r][0][k]);
      mpq_set_d(t, src[r][1][k]);
      mpq_sub(q[3 * r + k], q[3 * r + k], t);
    }
  for (int k = 0; k < 3; k++) {
    int i = (k + 1) % 3, j = (k + 2) % 3;
    mpq_mul(N[k], q[i], q[3 + j]);
    mpq_mul(t, q[j], q[3 + i]);
    mpq_sub(N[k], N[k], t);
    mpq_mul(M[k], q[6 + i], q[9 + j]);
    mpq_mul(t, q[6 + j], q[9 + i]);
    mpq_sub(M[k], M[k], t);
  }
  mpq_set_ui(t, 0, 1);
  for (int k = 0; k < 3; k++) {
    mpq_mul(N[k], N[k], M[k]);
    mpq_add(t, t, N[k]);
  }
  int sg = mpq_sgn(t);
  for (int i = 0; i < 12; i++)
    mpq_clear(q[i]);
  for (int i = 0; i < 3; i++)
    mpq_clear(N[i]), mpq_clear(M[i]);
  mpq_clear(t);
  return sg;
}

static tr_status push_heap(ctx *c, uint32_t t)
{
  double key = tri_angle(c, t);
  if (!(key < TR_SIMP_TARGET_ANGLE))
    return TR_OK;
  if (c->nh == c->ch) {
    uint32_t nc = c->ch ? 2 * c->ch : 1024;
    hitem *h = realloc(c->h, sizeof *h * nc);
    if (!h)
      return tr_error(TR_ERR_NOMEM, "out of memory for the simplification queue");
    c->h = h, c->ch = nc;
  }
  uint32_t i = c->nh++;
  while (i > 0) {
    uint32_t p = (i - 1) / 2;
    if (c->h[p].key < key || (c->h[p].key == key && c->h[p].t < t))
      break;
    c->h[i] = c->h[p];
    i = p;
  }
  c->h[i] = (hitem){key, t};
  return TR_OK;
}

static hitem pop_heap(ctx *c)
{
  hitem top = c->h[0], last = c->h[--c->nh];
  uint32_t i = 0;
  for (;;) {
    uint32_t l = 2 * i + 1, r = l + 1, m = i;
    hitem best = last;
    if (l < c->nh && (c->h[l].key < best.key || (c->h[l].key == best.key && c->h[l].t < best.t)))
      m = l, best = c->h[l];
    if (r < c->nh && (c->h[r].key < best.key || (c->h[r].key == best.key && c->h[r].t < best.t)))
      m = r, best = c->h[r];
    if (m == i)
      break;
    c->h[i] = c->h[m];
    i = m;
  }
  if (c->nh)
    c->h[i] = last;
  return top;
}

static tr_status inc_add(ctx *c, uint32_t v, uint32_t t)
{
  if (c->ninc[v] == c->cinc[v]) {
    uint32_t nc = c->cinc[v] ? 2 * c->cinc[v] : 8;
    uint32_t *a = realloc(c->inc[v], sizeof *a * nc);
    if (!a)
      return tr_error(TR_ERR_NOMEM, "out of memory for vertex stars");
    c->inc[v] = a, c->cinc[v] = nc;
  }
  c->inc[v][c->ninc[v]++] = t;
  return TR_OK;
}

/* keeps the order of the rest: the stars are walked in order, for one answer */
static void inc_del(ctx *c, uint32_t v, uint32_t t)
{
  uint32_t n = c->ninc[v], *a = c->inc[v];
  for (uint32_t i = 0; i < n; i++)
    if (a[i] == t) {
      memmove(a + i, a + i + 1, sizeof *a * (n - i - 1));
      c->ninc[v]--;
      return;
    }
}

static tr_status new_slot(ctx *c, const uint32_t v[3], uint32_t orig, uint32_t *id)
{
  if (c->nt == c->cap) {
    uint32_t nc = 2 * c->cap + 16;
    uint32_t *t = realloc(c->tri, sizeof *t * 3 * (size_t)nc);
    if (t)
      c->tri = t;
    uint32_t *o = t ? realloc(c->orig, sizeof *o * nc) : NULL;
    if (o)
      c->orig = o;
    uint8_t *d = o ? realloc(c->dead, nc) : NULL;
    if (d)
      c->dead = d;
    uint32_t *mk = d ? realloc(c->mark, sizeof *mk * nc) : NULL;
    if (!mk)
      return tr_error(TR_ERR_NOMEM, "out of memory for %u triangles", nc);
    c->mark = mk;
    memset(c->mark + c->cap, 0, sizeof *mk * (nc - c->cap));
    c->cap = nc;
  }
  *id = c->nt++;
  memcpy(c->tri + 3 * (size_t)*id, v, sizeof *v * 3);
  c->orig[*id] = orig;
  c->dead[*id] = 1; /* alive once the collapse is made */
  c->mark[*id] = 0;
  return TR_OK;
}

static int is_feat(const ctx *c, uint32_t a, uint32_t b)
{
  uint32_t k[2];
  tr_vtkey_edge(a, b, k);
  return tr_vtmap_get(&c->feat, 2, k) != TR_VTMAP_NONE;
}

static int has(const uint32_t *t, uint32_t v) { return t[0] == v || t[1] == v || t[2] == v; }

/* the link of v: the other vertices of its triangles, each once, in star order */
static uint32_t link_of(const ctx *c, uint32_t v, uint32_t *out, uint32_t max)
{
  uint32_t n = 0;
  for (uint32_t i = 0; i < c->ninc[v]; i++) {
    const uint32_t *t = c->tri + 3 * (size_t)c->inc[v][i];
    for (int k = 0; k < 3; k++) {
      uint32_t w = t[k], j = 0;
      if (w == v)
        continue;
      while (j < n && out[j] != w)
        j++;
      if (j == n && n < max)
        out[n++] = w;
    }
  }
  return n;
}

static tr_status add_target(ctx *c, uint32_t t)
{
  if (c->mark[t] == c->tick)
    return TR_OK;
  c->mark[t] = c->tick;
  if (c->nbuf == c->cbuf) {
    uint32_t nc = c->cbuf ? 2 * c->cbuf : 256;
    uint32_t *b = realloc(c->buf, sizeof *b * nc);
    if (!b)
      return tr_error(TR_ERR_NOMEM, "out of memory for target triangles");
    c->buf = b, c->cbuf = nc;
  }
  c->buf[c->nbuf++] = t;
  return TR_OK;
}

#define MAXLINK 256

/* Tries u -> v; *done = 1 when made. */
static tr_status try_collapse(ctx *c, uint32_t u, uint32_t v, int *done)
{
  *done = 0;
  if (c->cls[u] != FREE && c->cls[u] != CHAIN)
    return TR_OK;
  if (c->cls[u] == CHAIN && !is_feat(c, u, v))
    return TR_OK;
  uint32_t lu[MAXLINK], lv[MAXLINK];
  uint32_t nu = link_of(c, u, lu, MAXLINK), nv = link_of(c, v, lv, MAXLINK);
  if (nu >= MAXLINK || nv >= MAXLINK || c->ninc[u] != nu)
    return TR_OK;
  /* the two triangles on uv and their apexes */
  uint32_t apex[2], na = 0;
  for (uint32_t i = 0; i < c->ninc[u]; i++) {
    const uint32_t *t = c->tri + 3 * (size_t)c->inc[u][i];
    if (!has(t, v))
      continue;
    for (int k = 0; k < 3; k++)
      if (t[k] != u && t[k] != v && na < 2)
        apex[na++] = t[k];
      else if (t[k] != u && t[k] != v)
        na = 3;
  }
  if (na != 2)
    return TR_OK;
  uint32_t common = 0;
  for (uint32_t i = 0; i < nu; i++)
    for (uint32_t j = 0; j < nv; j++)
      if (lu[i] == lv[j] && lu[i] != u && lu[i] != v) {
        if (lu[i] != apex[0] && lu[i] != apex[1])
          return TR_OK;
        common++;
      }
  if (common != 2)
    return TR_OK;
  uint32_t w = UINT32_MAX;
  if (c->cls[u] == CHAIN) {
    for (uint32_t i = 0; i < nu; i++)
      if (lu[i] != v && is_feat(c, u, lu[i]))
        w = lu[i];
    if (w == UINT32_MAX || w == apex[0] || w == apex[1])
      return TR_OK;
  }
  /* the new triangles, in slots past the live ones */
  uint32_t nt0 = c->nt, nnew = 0;
  double old_min = 180, new_min = 180;
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  tr_status st = TR_OK;
  int ok = 1;
  for (uint32_t i = 0; i < c->ninc[u] && ok && st == TR_OK; i++) {
    uint32_t t = c->inc[u][i];
    const uint32_t *tv = c->tri + 3 * (size_t)t;
    old_min = fmin(old_min, tri_angle(c, t));
    for (int k = 0; k < 3; k++)
      for (int j = 0; j < 3; j++)
        lo[j] = fmin(lo[j], P(c, tv[k])[j]), hi[j] = fmax(hi[j], P(c, tv[k])[j]);
    if (has(tv, v))
      continue;
    uint32_t nvx[3];
    for (int k = 0; k < 3; k++)
      nvx[k] = tv[k] == u ? v : tv[k];
    uint32_t id;
    st = new_slot(c, nvx, c->orig[t], &id);
    tv = c->tri + 3 * (size_t)t; /* the array may have moved */
    if (st != TR_OK)
      break;
    nnew++;
    if (normal_dot_sign(P(c, tv[0]), P(c, tv[1]), P(c, tv[2]), P(c, nvx[0]), P(c, nvx[1]),
                        P(c, nvx[2])) <= 0)
      ok = 0;
    new_min = fmin(new_min, tri_angle(c, id));
  }
  if (ok && st == TR_OK && !(new_min > old_min))
    ok = 0;
  /* envelope, new -> input */
  for (uint32_t i = nt0; i < c->nt && ok && st == TR_OK; i++) {
    const uint32_t *tv = c->tri + 3 * (size_t)i;
    double a[3], b[3];
    tr_simp_tri_box(P(c, tv[0]), P(c, tv[1]), P(c, tv[2]), a, b);
    c->ncand = 0;
    st = tr_simp_grid_query(&c->g, c->plc->xyz, c->plc->tris, a, b, c->d, &c->cand,
                            &c->ncand, &c->ccand);
    tr_simp_targets tg = {c->plc->xyz, c->plc->tris, c->cand, c->ncand};
    if (st == TR_OK && tr_simp_cover(P(c, tv[0]), P(c, tv[1]), P(c, tv[2]), &tg, c->d, NULL,
                                     NULL, COVER_BUDGET, NULL) != TR_COVER_YES)
      ok = 0;
  }
  /* envelope, input -> new: the input near the old star against the new triangles
   * and the current triangles around it */
  if (ok && st == TR_OK) {
    if (++c->tick == 0) {
      memset(c->mark, 0, sizeof *c->mark * c->cap);
      c->tick = 1;
    }
    c->nbuf = 0;
    for (uint32_t i = 0; i < c->ninc[u]; i++)
      c->mark[c->inc[u][i]] = c->tick; /* going */
    double slo[3], shi[3];
    double m = 0;
    for (int k = 0; k < 3; k++)
      m = fmax(m, fmax(fabs(lo[k]), fabs(hi[k])));
    for (int k = 0; k < 3; k++)
      slo[k] = lo[k] - c->d * (1 + 0x1p-40) - 0x1p-40 * m,
      shi[k] = hi[k] + c->d * (1 + 0x1p-40) + 0x1p-40 * m;
    c->ncand = 0;
    if (st == TR_OK)
      st = tr_simp_grid_query(&c->g, c->plc->xyz, c->plc->tris, lo, hi, c->d, &c->cand,
                              &c->ncand, &c->ccand);
    /* an input triangle still in the surface and not in the old star covers itself
     * after the collapse; the others need covering, by the new triangles and the
     * current triangles at (the vertices that replaced) their vertices */
    uint32_t nc = 0;
    for (uint32_t i = 0; i < c->ncand; i++) {
      uint32_t t = c->cand[i];
      if (!c->dead[t] && c->mark[t] != c->tick)
        continue;
      c->cand[nc++] = t;
    }
    for (uint32_t i = nt0; i < c->nt && st == TR_OK; i++)
      st = add_target(c, i);
    for (uint32_t i = 0; i < nu && st == TR_OK; i++)
      for (uint32_t j = 0; j < c->ninc[lu[i]] && st == TR_OK; j++)
        st = add_target(c, c->inc[lu[i]][j]);
    for (uint32_t i = 0; i < nc && st == TR_OK; i++) {
      uint32_t t = c->cand[i];
      for (int k = 0; k < 3 && st == TR_OK; k++) {
        uint32_t r = root_of(c, c->plc->tris[3 * (size_t)t + k]);
        for (uint32_t j = 0; j < c->ninc[r] && st == TR_OK; j++)
          st = add_target(c, c->inc[r][j]);
      }
    }
    c->ncand = nc;
    tr_simp_targets tg = {c->x, c->tri, c->buf, c->nbuf};
    for (uint32_t i = 0; i < c->ncand && ok && st == TR_OK; i++) {
      const uint32_t *tv = c->plc->tris + 3 * (size_t)c->cand[i];
      if (tr_simp_cover(P(c, tv[0]), P(c, tv[1]), P(c, tv[2]), &tg, c->d, slo, shi,
                        COVER_BUDGET, NULL) != TR_COVER_YES)
        ok = 0;
    }
  }
  if (!ok || st != TR_OK) {
    c->nt = nt0;
    return st;
  }
  /* made: the old star goes, the new triangles come */
  uint32_t nold = c->ninc[u];
  uint32_t *old = malloc(sizeof *old * (nold ? nold : 1));
  if (!old)
    return tr_error(TR_ERR_NOMEM, "out of memory collapsing an edge");
  memcpy(old, c->inc[u], sizeof *old * nold);
  for (uint32_t i = 0; i < nold; i++) {
    const uint32_t *tv = c->tri + 3 * (size_t)old[i];
    c->dead[old[i]] = 1;
    for (int k = 0; k < 3; k++)
      if (tv[k] != u)
        inc_del(c, tv[k], old[i]);
  }
  free(old);
  c->ninc[u] = 0;
  c->cls[u] = GONE;
  for (uint32_t i = nt0; i < c->nt && st == TR_OK; i++) {
    c->dead[i] = 0;
    for (int k = 0; k < 3 && st == TR_OK; k++)
      st = inc_add(c, c->tri[3 * (size_t)i + k], i);
  }
  if (st == TR_OK && w != UINT32_MAX) {
    uint32_t k[2];
    tr_vtkey_edge(v, w, k);
    st = tr_vtmap_set(&c->feat, 2, k, 1);
  }
  for (uint32_t i = nt0; i < c->nt && st == TR_OK; i++)
    st = push_heap(c, i);
  *done = st == TR_OK;
  (void)nnew;
  return st;
}

static void normal(const double *a, const double *b, const double *c, double n[3])
{
  double u[3], v[3];
  for (int k = 0; k < 3; k++)
    u[k] = b[k] - a[k], v[k] = c[k] - a[k];
  n[0] = u[1] * v[2] - u[2] * v[1], n[1] = u[2] * v[0] - u[0] * v[2];
  n[2] = u[0] * v[1] - u[1] * v[0];
}

/* Feature edges of the input, then each vertex's class. Which edges are sharp is a choice
 * (doubles); it only decides what may move, never validity. */
static tr_status classify(ctx *c, const uint8_t *frozen)
{
  const struct tr_plc *p = c->plc;
  tr_vtmap em = {0};
  uint32_t ne = 0, *cnt = malloc(sizeof *cnt * 3 * (size_t)(p->ntris ? p->ntris : 1));
  uint32_t *t0 = malloc(sizeof *t0 * 3 * (size_t)(p->ntris ? p->ntris : 1));
  uint32_t *t1 = malloc(sizeof *t1 * 3 * (size_t)(p->ntris ? p->ntris : 1));
  tr_status st = cnt && t0 && t1 ? tr_vtmap_reserve(&em, 2, 3 * p->ntris)
                                 : tr_error(TR_ERR_NOMEM, "out of memory for the edges");
  for (uint32_t t = 0; t < p->ntris && st == TR_OK; t++)
    for (int k = 0; k < 3 && st == TR_OK; k++) {
      uint32_t key[2], id;
      tr_vtkey_edge(p->tris[3 * (size_t)t + k], p->tris[3 * (size_t)t + (k + 1) % 3], key);
      st = tr_vtmap_put(&em, 2, key, ne, &id);
      if (st != TR_OK)
        break;
      if (id == ne)
        cnt[ne] = 0, t0[ne] = t, t1[ne] = UINT32_MAX, ne++;
      if (cnt[id]++ == 1)
        t1[id] = t;
    }
  const double cosmax = cos(TR_SIMP_SHARP_DEG * M_PI / 180);
  uint8_t *sharp = st == TR_OK ? calloc(ne ? ne : 1, 1) : NULL;
  if (st == TR_OK && !sharp)
    st = tr_error(TR_ERR_NOMEM, "out of memory for the edges");
  for (uint32_t e = 0; e < ne && st == TR_OK; e++) {
    if (cnt[e] != 2) {
      sharp[e] = 2; /* open or non-manifold: its vertices stay */
      continue;
    }
    const uint32_t *a = p->tris + 3 * (size_t)t0[e], *b = p->tris + 3 * (size_t)t1[e];
    int32_t ma = p->tri_marker ? p->tri_marker[t0[e]] : 0;
    int32_t mb = p->tri_marker ? p->tri_marker[t1[e]] : 0;
    double n1[3], n2[3];
    normal(P(c, a[0]), P(c, a[1]), P(c, a[2]), n1);
    normal(P(c, b[0]), P(c, b[1]), P(c, b[2]), n2);
    double dt = n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2];
    double l = sqrt(n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2]) *
               sqrt(n2[0] * n2[0] + n2[1] * n2[1] + n2[2] * n2[2]);
    if (ma != mb || !(dt >= cosmax * l))
      sharp[e] = 1;
  }
  for (uint32_t t = 0; t < p->ntris && st == TR_OK; t++)
    for (int k = 0; k < 3 && st == TR_OK; k++) {
      uint32_t key[2];
      tr_vtkey_edge(p->tris[3 * (size_t)t + k], p->tris[3 * (size_t)t + (k + 1) % 3], key);
      uint32_t e = tr_vtmap_get(&em, 2, key);
      if (sharp[e] == 1)
        st = tr_vtmap_set(&c->feat, 2, key, 1);
    }
  for (uint32_t v = 0; v < p->npoints && st == TR_OK; v++) {
    uint8_t cl = frozen && frozen[v] ? FROZEN : FREE;
    uint32_t nf = 0;
    if (c->ninc[v] == 0)
      cl = FROZEN;
    for (uint32_t i = 0; i < c->ninc[v] && cl != FROZEN; i++) {
      const uint32_t *t = p->tris + 3 * (size_t)c->inc[v][i];
      for (int k = 0; k < 3; k++) {
        uint32_t a = t[k], b = t[(k + 1) % 3], key[2];
        if (a != v)
          continue; /* each edge at v once: as it leaves v in this triangle */
        for (int s = 0; s < 2; s++) {
          tr_vtkey_edge(v, s ? t[(k + 2) % 3] : b, key);
          uint32_t e = tr_vtmap_get(&em, 2, key);
          if (sharp[e] == 2)
            cl = FROZEN;
          else if (sharp[e] == 1 && s == 0)
            nf++;
        }
      }
    }
    /* one disk: walking across the edges around v comes back after all its triangles */
    if (cl != FROZEN) {
      uint32_t start = c->inc[v][0], cur = start, steps = 0;
      do {
        const uint32_t *t = p->tris + 3 * (size_t)cur;
        uint32_t nxt = t[0] == v ? t[2] : t[1] == v ? t[0] : t[1]; /* previous vertex */
        uint32_t found = UINT32_MAX;
        for (uint32_t i = 0; i < c->ninc[v]; i++) {
          const uint32_t *s = p->tris + 3 * (size_t)c->inc[v][i];
          if (c->inc[v][i] != cur && has(s, nxt))
            found = c->inc[v][i];
        }
        cur = found;
        steps++;
      } while (cur != UINT32_MAX && cur != start && steps <= c->ninc[v]);
      if (cur != start || steps != c->ninc[v])
        cl = FROZEN;
    }
    if (cl != FROZEN)
      cl = nf == 0 ? FREE : nf == 2 ? CHAIN : FROZEN;
    c->cls[v] = cl;
  }
  tr_vtmap_free(&em);
  free(cnt), free(t0), free(t1), free(sharp);
  return st;
}

tr_status tr_simp_collapse(const struct tr_plc *plc, double d, const uint8_t *frozen,
                           uint32_t **tris, uint32_t **tri_of, uint32_t *ntris,
                           uint32_t *into, uint64_t *ncollapse)
{
  ctx c;
  memset(&c, 0, sizeof c);
  c.plc = plc, c.x = plc->xyz, c.d = d, c.into = into;
  *tris = *tri_of = NULL;
  *ntris = 0;
  *ncollapse = 0;
  uint32_t nv = plc->npoints;
  for (uint32_t v = 0; v < nv; v++)
    into[v] = v;
  c.inc = calloc(nv ? nv : 1, sizeof *c.inc);
  c.ninc = calloc(nv ? nv : 1, sizeof *c.ninc);
  c.cinc = calloc(nv ? nv : 1, sizeof *c.cinc);
  c.cls = calloc(nv ? nv : 1, 1);
  tr_status st = c.inc && c.ninc && c.cinc && c.cls
                     ? TR_OK
                     : tr_error(TR_ERR_NOMEM, "out of memory for %u vertex stars", nv);
  for (uint32_t t = 0; t < plc->ntris && st == TR_OK; t++) {
    uint32_t id;
    st = new_slot(&c, plc->tris + 3 * (size_t)t, t, &id);
    if (st == TR_OK)
      c.dead[id] = 0;
    for (int k = 0; k < 3 && st == TR_OK; k++)
      st = inc_add(&c, plc->tris[3 * (size_t)t + k], id);
  }
  if (st == TR_OK)
    st = classify(&c, frozen);
  if (st == TR_OK)
    st = tr_simp_grid_build(&c.g, plc->xyz, plc->tris, plc->ntris);
  for (uint32_t t = 0; t < c.nt && st == TR_OK; t++)
    st = push_heap(&c, t);
  while (st == TR_OK && c.nh) {
    hitem it = pop_heap(&c);
    if (c.dead[it.t])
      continue;
    const uint32_t *tv = c.tri + 3 * (size_t)it.t;
    /* its edges, shortest first (ties: in triangle order) */
    uint32_t e[3][2];
    double len[3];
    for (int k = 0; k < 3; k++) {
      e[k][0] = tv[k], e[k][1] = tv[(k + 1) % 3];
      const double *a = P(&c, e[k][0]), *b = P(&c, e[k][1]);
      len[k] = (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
               (a[2] - b[2]) * (a[2] - b[2]);
    }
    int ord[3] = {0, 1, 2};
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 2 - i; j++)
        if (len[ord[j + 1]] < len[ord[j]]) {
          int x = ord[j];
          ord[j] = ord[j + 1], ord[j + 1] = x;
        }
    int done = 0;
    for (int i = 0; i < 3 && !done && st == TR_OK; i++) {
      uint32_t a = e[ord[i]][0], b = e[ord[i]][1];
      st = try_collapse(&c, a, b, &done);
      if (done)
        into[a] = b;
      if (!done && st == TR_OK) {
        st = try_collapse(&c, b, a, &done);
        if (done)
          into[b] = a;
      }
    }
    *ncollapse += done;
  }
  /* the surviving triangles in slot order */
  uint32_t n = 0;
  for (uint32_t t = 0; t < c.nt; t++)
    n += !c.dead[t];
  if (st == TR_OK) {
    *tris = malloc(sizeof **tris * 3 * (size_t)(n ? n : 1));
    *tri_of = malloc(sizeof **tri_of * (n ? n : 1));
    if (!*tris || !*tri_of)
      st = tr_error(TR_ERR_NOMEM, "out of memory for %u triangles", n);
  }
  if (st == TR_OK) {
    uint32_t j = 0;
    for (uint32_t t = 0; t < c.nt; t++)
      if (!c.dead[t]) {
        memcpy(*tris + 3 * (size_t)j, c.tri + 3 * (size_t)t, 3 * sizeof **tris);
        (*tri_of)[j++] = c.orig[t];
      }
    *ntris = n;
  } else {
    free(*tris), free(*tri_of);
    *tris = *tri_of = NULL;
  }
  for (uint32_t v = 0; v < nv && c.inc; v++)
    free(c.inc[v]);
  free(c.inc), free(c.ninc), free(c.cinc), free(c.cls);
  free(c.tri), free(c.orig), free(c.dead), free(c.mark), free(c.cand), free(c.h), free(c.buf);
  tr_vtmap_free(&c.feat);
  tr_simp_grid_free(&c.g);
  return st;
}
