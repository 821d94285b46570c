/* The surface under edit (edit.h): stars, slots, the queue and the envelope test that
 * every operation of the simplification goes through. */
#define _DEFAULT_SOURCE
#include <gmp.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "edit.h"

uint32_t tr_simp_root(tr_simp_edit *c, uint32_t v)
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

double tr_simp_min_angle(const double *a, const double *b, const double *c)
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

double tr_simp_tri_angle(const tr_simp_edit *c, uint32_t t)
{
  const uint32_t *v = c->tri + 3 * (size_t)t;
  return tr_simp_min_angle(tr_simp_at(c, v[0]), tr_simp_at(c, v[1]), tr_simp_at(c, v[2]));
}

/* sign of ((b-a) x (c-a)) . ((e-d) x (f-d)): a double filter (each side's error under
 * 32 u times the product of the 1-norms), exact rationals when it cannot tell */
int tr_simp_normal_dot_sign(const double *a, const double *b, const double *c, const double *d,
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

/* heap order: smaller angle first, then smaller slot */
static int before(tr_simp_hitem x, tr_simp_hitem y)
{
  return x.key < y.key || (x.key == y.key && x.t < y.t);
}

tr_status tr_simp_push(tr_simp_edit *c, uint32_t t)
{
  double key = tr_simp_tri_angle(c, t);
  if (!(key < TR_SIMP_TARGET_ANGLE))
    return TR_OK;
  if (c->nh == c->ch) {
    uint32_t nc = c->ch ? 2 * c->ch : 1024;
    tr_simp_hitem *h = realloc(c->h, sizeof *h * nc);
    if (!h)
      return tr_error(TR_ERR_NOMEM, "out of memory for the simplification queue");
    c->h = h, c->ch = nc;
  }
  tr_simp_hitem it = {key, t};
  uint32_t i = c->nh++;
  while (i > 0) {
    uint32_t p = (i - 1) / 2;
    if (before(c->h[p], it))
      break;
    c->h[i] = c->h[p];
    i = p;
  }
  c->h[i] = it;
  return TR_OK;
}

tr_simp_hitem tr_simp_pop(tr_simp_edit *c)
{
  tr_simp_hitem top = c->h[0], last = c->h[--c->nh];
  uint32_t i = 0;
  for (;;) {
    uint32_t l = 2 * i + 1, r = l + 1, m = i;
    tr_simp_hitem best = last;
    if (l < c->nh && before(c->h[l], best))
      m = l, best = c->h[l];
    if (r < c->nh && before(c->h[r], best))
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

tr_status tr_simp_star_add(tr_simp_edit *c, uint32_t v, uint32_t t)
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
void tr_simp_star_del(tr_simp_edit *c, uint32_t v, uint32_t t)
{
  uint32_t n = c->ninc[v], *a = c->inc[v];
  for (uint32_t i = 0; i < n; i++)
    if (a[i] == t) {
      memmove(a + i, a + i + 1, sizeof *a * (n - i - 1));
      c->ninc[v]--;
      return;
    }
}

tr_status tr_simp_new_slot(tr_simp_edit *c, const uint32_t v[3], uint32_t orig, uint32_t *id)
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

int tr_simp_is_feat(const tr_simp_edit *c, uint32_t a, uint32_t b)
{
  uint32_t k[2];
  tr_vtkey_edge(a, b, k);
  return tr_vtmap_get(&c->feat, 2, k) != TR_VTMAP_NONE;
}

/* the link of v: the other vertices of its triangles, each once, in star order */
uint32_t tr_simp_link(const tr_simp_edit *c, uint32_t v, uint32_t *out, uint32_t max)
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

tr_status tr_simp_add_target(tr_simp_edit *c, uint32_t t)
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


tr_status tr_simp_envelope(tr_simp_edit *c, const uint32_t *going, uint32_t ngoing,
                           uint32_t nt0, const uint32_t *around, uint32_t naround,
                           const double lo[3], const double hi[3], int *ok)
{
  tr_status st = TR_OK;
  *ok = 1;
  /* new -> input */
  for (uint32_t i = nt0; i < c->nt && *ok && st == TR_OK; i++) {
    const uint32_t *tv = c->tri + 3 * (size_t)i;
    double a[3], b[3];
    tr_simp_tri_box(tr_simp_at(c, tv[0]), tr_simp_at(c, tv[1]), tr_simp_at(c, tv[2]), a, b);
    c->ncand = 0;
    st = tr_simp_grid_query(&c->g, c->plc->xyz, c->plc->tris, a, b, c->d, &c->cand,
                            &c->ncand, &c->ccand);
    tr_simp_targets tg = {c->plc->xyz, c->plc->tris, c->cand, c->ncand};
    if (st == TR_OK && tr_simp_cover(tr_simp_at(c, tv[0]), tr_simp_at(c, tv[1]),
                                     tr_simp_at(c, tv[2]), &tg, c->d, NULL, NULL,
                                     TR_SIMP_COVER_BUDGET, NULL) != TR_COVER_YES)
      *ok = 0;
  }
  /* input -> new */
  if (*ok && st == TR_OK) {
    if (++c->tick == 0) {
      memset(c->mark, 0, sizeof *c->mark * c->cap);
      c->tick = 1;
    }
    c->nbuf = 0;
    for (uint32_t i = 0; i < ngoing; i++)
      c->mark[going[i]] = c->tick; /* going: never a target */
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
     * after the change; the others need covering, by the new triangles and the
     * current triangles at (the vertices that replaced) their vertices */
    uint32_t nc = 0;
    for (uint32_t i = 0; i < c->ncand; i++) {
      uint32_t t = c->cand[i];
      if (!c->dead[t] && c->mark[t] != c->tick)
        continue;
      c->cand[nc++] = t;
    }
    for (uint32_t i = nt0; i < c->nt && st == TR_OK; i++)
      st = tr_simp_add_target(c, i);
    for (uint32_t i = 0; i < naround && st == TR_OK; i++)
      for (uint32_t j = 0; j < c->ninc[around[i]] && st == TR_OK; j++)
        st = tr_simp_add_target(c, c->inc[around[i]][j]);
    for (uint32_t i = 0; i < nc && st == TR_OK; i++) {
      uint32_t t = c->cand[i];
      for (int k = 0; k < 3 && st == TR_OK; k++) {
        uint32_t r = tr_simp_root(c, c->plc->tris[3 * (size_t)t + k]);
        for (uint32_t j = 0; j < c->ninc[r] && st == TR_OK; j++)
          st = tr_simp_add_target(c, c->inc[r][j]);
      }
    }
    c->ncand = nc;
    tr_simp_targets tg = {c->x, c->tri, c->buf, c->nbuf};
    for (uint32_t i = 0; i < c->ncand && *ok && st == TR_OK; i++) {
      const uint32_t *tv = c->plc->tris + 3 * (size_t)c->cand[i];
      if (tr_simp_cover(tr_simp_at(c, tv[0]), tr_simp_at(c, tv[1]), tr_simp_at(c, tv[2]), &tg,
                        c->d, slo, shi, TR_SIMP_COVER_BUDGET, NULL) != TR_COVER_YES)
        *ok = 0;
    }
  }
  return st;
}

tr_status tr_simp_commit(tr_simp_edit *c, const uint32_t *going, uint32_t ngoing, uint32_t nt0)
{
  for (uint32_t i = 0; i < ngoing; i++) {
    const uint32_t *tv = c->tri + 3 * (size_t)going[i];
    c->dead[going[i]] = 1;
    for (int k = 0; k < 3; k++)
      tr_simp_star_del(c, tv[k], going[i]);
  }
  tr_status st = TR_OK;
  for (uint32_t i = nt0; i < c->nt && st == TR_OK; i++) {
    c->dead[i] = 0;
    for (int k = 0; k < 3 && st == TR_OK; k++)
      st = tr_simp_star_add(c, c->tri[3 * (size_t)i + k], i);
  }
  for (uint32_t i = nt0; i < c->nt && st == TR_OK; i++)
    st = tr_simp_push(c, i);
  return st;
}

tr_status tr_simp_edit_init(tr_simp_edit *c, const struct tr_plc *plc, double d,
                            const uint8_t *frozen, uint32_t *into)
{
  memset(c, 0, sizeof *c);
  c->plc = plc, c->d = d, c->into = into, c->frozen = frozen;
  c->x = plc->xyz;
  uint32_t nv = plc->npoints;
  for (uint32_t v = 0; v < nv; v++)
    into[v] = v;
  c->inc = calloc(nv ? nv : 1, sizeof *c->inc);
  c->ninc = calloc(nv ? nv : 1, sizeof *c->ninc);
  c->cinc = calloc(nv ? nv : 1, sizeof *c->cinc);
  c->cls = calloc(nv ? nv : 1, 1);
  if (!c->inc || !c->ninc || !c->cinc || !c->cls)
    return tr_error(TR_ERR_NOMEM, "out of memory for %u vertex stars", nv);
  for (uint32_t t = 0; t < plc->ntris; t++) {
    uint32_t id;
    TR_CHECK(tr_simp_new_slot(c, plc->tris + 3 * (size_t)t, t, &id));
    c->dead[id] = 0;
    for (int k = 0; k < 3; k++)
      TR_CHECK(tr_simp_star_add(c, plc->tris[3 * (size_t)t + k], id));
  }
  return tr_simp_grid_build(&c->g, plc->xyz, plc->tris, plc->ntris);
}

void tr_simp_edit_free(tr_simp_edit *c)
{
  for (uint32_t v = 0; v < c->plc->npoints && c->inc; v++)
    free(c->inc[v]);
  free(c->inc), free(c->ninc), free(c->cinc), free(c->cls);
  free(c->tri), free(c->orig), free(c->dead), free(c->mark), free(c->cand), free(c->h),
      free(c->buf);
  tr_vtmap_free(&c->feat);
  tr_simp_grid_free(&c->g);
  memset(c, 0, sizeof *c);
}
