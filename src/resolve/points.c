/* The arrangement's vertices: the input points and the new rational points, one vertex
 * per exact value. A value hashes the same whichever way it is held (a point whose
 * rational coordinates are all doubles hashes as those doubles), so a cut through an
 * input point, or the same crossing found from two pairs, gives one vertex. The hash
 * only finds candidates; equality is exact (tr_equal_p). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "resolve/resolve_impl.h"

tr_status rs_grow(void **p, size_t sz, size_t need, size_t *cap)
{
  if (need <= *cap)
    return TR_OK;
  size_t nc = *cap ? *cap : 16;
  while (nc < need)
    nc *= 2;
  if (nc > SIZE_MAX / sz)
    return tr_error(TR_ERR_NOMEM, "arrangement: array of %zu elements too large", nc);
  void *q = realloc(*p, nc * sz);
  if (!q)
    return tr_error(TR_ERR_NOMEM, "arrangement: out of memory for %zu elements", nc);
  *p = q;
  *cap = nc;
  return TR_OK;
}

static uint64_t mix(uint64_t h, uint64_t x)
{
  h = (h ^ x) * 0x9e3779b97f4a7c15ull;
  return h ^ (h >> 31);
}

static uint64_t hash_double(uint64_t h, double d)
{
  uint64_t u;
  if (d == 0)
    d = 0.0; /* -0 and +0 are one value */
  memcpy(&u, &d, sizeof u);
  return mix(h, u);
}

static uint64_t hash_mpz(uint64_t h, const mpz_t z)
{
  size_t n = mpz_size(z);
  h = mix(h, (uint64_t)mpz_sgn(z) + 2 + ((uint64_t)n << 2));
  for (size_t i = 0; i < n; i++)
    h = mix(h, (uint64_t)mpz_getlimbn(z, (mp_size_t)i));
  return h;
}

/* The hash of p's exact value. Rational coordinates are canonical (mpq), so their
 * homogeneous form (the lcm of the denominators) is too. */
static uint64_t hash_point(const tr_point *p)
{
  uint64_t h = 0x243f6a8885a308d3ull;
  const tr_qpoint *q = p->q;
  if (!q || (q->err[0] == 0 && q->err[1] == 0 && q->err[2] == 0)) {
    for (int i = 0; i < 3; i++)
      h = hash_double(h, p->d[i]);
    return h;
  }
  for (int i = 0; i < 3; i++)
    h = hash_mpz(h, q->hx[i]);
  return hash_mpz(h, q->hw);
}

static void key_of(uint64_t h, uint32_t k[2])
{
  k[0] = (uint32_t)h;
  k[1] = (uint32_t)(h >> 32);
  if (k[0] == TR_VTMAP_NONE) /* the map's empty-slot mark */
    k[0] = 0;
}

static tr_status append(rs_points *ps, const tr_point *p, uint32_t input, int on, uint32_t a,
                        uint32_t b, uint32_t *id)
{
  if (ps->n == TR_ARR_NONE - 1)
    return tr_error(TR_ERR_NOMEM, "arrangement: more than 2^32 vertices");
  size_t cap = ps->cap, cap2 = ps->cap;
  TR_CHECK(rs_grow((void **)&ps->v, sizeof *ps->v, (size_t)ps->n + 1, &cap));
  TR_CHECK(rs_grow((void **)&ps->next, sizeof *ps->next, (size_t)ps->n + 1, &cap2));
  ps->cap = (uint32_t)(cap < cap2 ? cap : cap2);
  tr_arr_vertex *x = ps->v + ps->n;
  memset(x, 0, sizeof *x);
  x->input = input;
  if (input == TR_ARR_NONE) {
    if (!(x->q = malloc(sizeof *x->q)))
      return tr_error(TR_ERR_NOMEM, "arrangement: out of memory for a point");
    tr_qpoint_init(x->q);
    tr_qpoint_set_point(x->q, p);
  }
  x->on = (uint8_t)on;
  x->a = a;
  x->b = b;
  ps->next[ps->n] = TR_ARR_NONE;
  *id = ps->n++;
  return TR_OK;
}

static int on_less(int on, uint32_t a, uint32_t b, const tr_arr_vertex *x)
{
  if (on != x->on)
    return on < x->on;
  if (a != x->a)
    return a < x->a;
  return b < x->b;
}

/* Looks p up: *id = its vertex or TR_ARR_NONE; k = the map key of its hash. */
static void lookup(const rs_points *ps, const tr_point *p, uint32_t k[2], uint32_t *id)
{
  key_of(hash_point(p), k);
  *id = TR_ARR_NONE;
  for (uint32_t v = tr_vtmap_get(&ps->map, 2, k); v != TR_VTMAP_NONE; v = ps->next[v]) {
    tr_point w = rs_pt(ps, v);
    if (tr_equal_p(p, &w)) {
      *id = v;
      return;
    }
  }
}

/* Links new vertex id into the chain of key k (at its end: the chain stays in id order). */
static tr_status link(rs_points *ps, const uint32_t k[2], uint32_t id)
{
  uint32_t head;
  TR_CHECK(tr_vtmap_put(&ps->map, 2, k, id, &head));
  if (head != id) {
    while (ps->next[head] != TR_ARR_NONE)
      head = ps->next[head];
    ps->next[head] = id;
  }
  return TR_OK;
}

tr_status rs_points_add(rs_points *ps, const tr_point *p, int on, uint32_t a, uint32_t b,
                        uint32_t *id)
{
  uint32_t k[2];
  lookup(ps, p, k, id);
  if (*id != TR_ARR_NONE) {
    tr_arr_vertex *x = ps->v + *id;
    if (on_less(on, a, b, x)) {
      x->on = (uint8_t)on;
      x->a = a;
      x->b = b;
    }
    return TR_OK;
  }
  TR_CHECK(append(ps, p, TR_ARR_NONE, on, a, b, id));
  return link(ps, k, *id);
}

tr_status rs_points_init(rs_points *ps, const struct tr_plc *plc, uint32_t *of_input,
                         uint64_t *ndup)
{
  memset(ps, 0, sizeof *ps);
  ps->plc = plc;
  *ndup = 0;
  TR_CHECK(tr_vtmap_reserve(&ps->map, 2, plc->npoints));
  for (uint32_t i = 0; i < plc->npoints; i++) {
    const double *x = plc->xyz + 3 * (size_t)i;
    if (!isfinite(x[0]) || !isfinite(x[1]) || !isfinite(x[2]))
      return tr_error(TR_ERR_INPUT, "arrangement: point %u is not finite", i);
    tr_point p = tr_pt_d(x);
    uint32_t k[2], id;
    lookup(ps, &p, k, &id);
    if (id != TR_ARR_NONE) {
      of_input[i] = id;
      ++*ndup;
      continue;
    }
    TR_CHECK(append(ps, &p, i, TR_ARR_ON_VERTEX, i, 0, &id));
    ps->v[id].a = id; /* the input point, named by its vertex */
    TR_CHECK(link(ps, k, id));
    of_input[i] = id;
  }
  return TR_OK;
}

void rs_points_free(rs_points *ps)
{
  for (uint32_t i = 0; i < ps->n; i++)
    if (ps->v[i].q) {
      tr_qpoint_clear(ps->v[i].q);
      free(ps->v[i].q);
    }
  free(ps->v);
  free(ps->next);
  tr_vtmap_free(&ps->map);
  memset(ps, 0, sizeof *ps);
}

int rs_frame(const tr_point *a, const tr_point *b, const tr_point *c, int *drop, int *sgn)
{
  mpq_t u[3], w[3], n[3], t, best;
  for (int i = 0; i < 3; i++) {
    mpq_inits(u[i], w[i], n[i], NULL);
    mpq_t pa;
    mpq_init(pa);
    tr_point_get_q(a, i, pa);
    tr_point_get_q(b, i, u[i]);
    tr_point_get_q(c, i, w[i]);
    mpq_sub(u[i], u[i], pa);
    mpq_sub(w[i], w[i], pa);
    mpq_clear(pa);
  }
  mpq_inits(t, best, NULL);
  *drop = -1;
  *sgn = 0;
  for (int k = 0; k < 3; k++) {
    int i = (k + 1) % 3, j = (k + 2) % 3;
    mpq_mul(n[k], u[i], w[j]);
    mpq_mul(t, u[j], w[i]);
    mpq_sub(n[k], n[k], t);
    mpq_abs(t, n[k]);
    if (mpq_sgn(t) && (*drop < 0 || mpq_cmp(t, best) > 0)) {
      mpq_set(best, t);
      *drop = k;
      *sgn = mpq_sgn(n[k]);
    }
  }
  for (int i = 0; i < 3; i++)
    mpq_clears(u[i], w[i], n[i], NULL);
  mpq_clears(t, best, NULL);
  return *drop < 0 ? -1 : 0;
}
