/* tr_plc_validate: exact input checks and repairs, in the order that makes each step's
 * assumptions true for the next: merge duplicate vertices -> reject zero-area triangles
 * -> remove duplicate triangles -> edge census -> orientation repair -> self-intersection.
 * A union of closed 2-manifold shells (every edge in two triangles) is oriented shell by
 * shell (outward; cavities, told from inclusions by their given orientation and the hole
 * points, into themselves: nesting.c). Any other surface (internal facets:
 * edges in 3+ triangles; cracks and open surfaces: edges in 1) is checked for
 * self-intersections first and then oriented by its cells (cells.c), which also decides
 * whether its free edges lie inside the domain. Messages name input triangle numbers
 * (after polygon triangulation; "input face" is the polygon it came from) and input
 * vertex numbers, both 0-based. */
#define _POSIX_C_SOURCE 200809L
#include <gmp.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/edgesort.h"
#include "predicates.h"
#include "validate.h"

/* Monotonic seconds: the sub-step times of plc->validate_seconds (tetrec -v, --stats). */
static double vclock(void)
{
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int tr_cmp_point(const void *ctx, uint32_t a, uint32_t b)
{
  const double *x = ctx;
  for (int k = 0; k < 3; k++) {
    double p = x[3 * (size_t)a + k], q = x[3 * (size_t)b + k];
    if (p < q)
      return -1;
    if (p > q)
      return 1;
  }
  return 0; /* -0.0 == 0.0 here: they are the same point */
}

typedef struct {
  double x[3];
  uint32_t i;
} point_key;

static int cmp_point_key(const void *pa, const void *pb)
{
  const point_key *a = pa, *b = pb;
  int c = 0; /* tr_cmp_point's order (-0.0 == 0.0), then the index */
  for (int k = 0; k < 3 && !c; k++)
    c = (a->x[k] > b->x[k]) - (a->x[k] < b->x[k]);
  return c ? c : (a->i > b->i) - (a->i < b->i);
}

/* ord = 0..n-1 sorted by tr_cmp_point, equal points in index order (what a stable sort
 * gives): the coordinates copied beside the index, so that a comparison reads one
 * record instead of two random points. */
static tr_status sort_points(const double *xyz, uint32_t n, uint32_t *ord)
{
  point_key *k = malloc(sizeof *k * (n ? n : 1));
  if (!k)
    return tr_error(TR_ERR_NOMEM, "out of memory sorting %u points", n);
  for (uint32_t i = 0; i < n; i++) {
    memcpy(k[i].x, xyz + 3 * (size_t)i, sizeof k[i].x);
    k[i].i = i;
  }
  qsort(k, n, sizeof *k, cmp_point_key);
  for (uint32_t i = 0; i < n; i++)
    ord[i] = k[i].i;
  free(k);
  return TR_OK;
}

/* Merges exactly equal points into the first of each group and renumbers the rest
 * compactly; orig[new] = original index. */
static tr_status merge_vertices(struct tr_plc *plc, uint32_t *orig, tr_report *rep)
{
  uint32_t n = plc->npoints;
  uint32_t *ord = malloc(sizeof *ord * (n ? n : 1)), *map = malloc(sizeof *map * (n ? n : 1));
  tr_status st = TR_OK;
  if (!ord || !map) {
    st = tr_error(TR_ERR_NOMEM, "out of memory checking duplicate vertices");
    goto done;
  }
  if ((st = sort_points(plc->xyz, n, ord)) != TR_OK)
    goto done;
  for (uint32_t i = 0; i < n;) {
    uint32_t j = i + 1;
    while (j < n && tr_cmp_point(plc->xyz, ord[i], ord[j]) == 0)
      j++;
    for (uint32_t k = i; k < j; k++) {
      map[ord[k]] = ord[i]; /* stable sort: ord[i] is the lowest index of the group */
      if (k > i)
        tr_report_add(rep, TR_REP_DUPV, "vertex %u duplicates vertex %u (merged)", ord[k], ord[i]);
    }
    i = j;
  }
  uint32_t m = 0;
  for (uint32_t i = 0; i < n; i++) {
    if (map[i] == i) {
      memmove(plc->xyz + 3 * (size_t)m, plc->xyz + 3 * (size_t)i, 3 * sizeof(double));
      if (plc->vsize)
        plc->vsize[m] = plc->vsize[i];
      orig[m] = i;
      map[i] = m++;
    } else {
      map[i] = map[map[i]]; /* the representative has a lower index: already renumbered */
      /* one point, two target sizes: the finer one holds (0 is no bound) */
      double *h = plc->vsize ? plc->vsize + map[i] : NULL;
      if (h && plc->vsize[i] > 0 && (!(*h > 0) || plc->vsize[i] < *h))
        *h = plc->vsize[i];
    }
  }
  for (size_t t = 0; t < 3 * (size_t)plc->ntris; t++)
    plc->tris[t] = map[plc->tris[t]];
  for (size_t t = 0; t < 2 * (size_t)plc->nsegs; t++)
    plc->segs[t] = map[plc->segs[t]];
  for (size_t t = 0; t < 4 * (size_t)plc->ntets; t++)
    plc->tets[t] = map[plc->tets[t]];
  plc->npoints = m;
done:
  free(ord);
  free(map);
  return st;
}

/* "file: " before messages when the PLC came from a file. */
#define PRE(plc) (plc)->source ? (plc)->source : "", (plc)->source ? ": " : ""

static uint32_t src_of(const struct tr_plc *plc, uint32_t t)
{
  return plc->tri_source ? plc->tri_source[t] : t;
}

static tr_status zero_area(const struct tr_plc *plc, const uint32_t *orig, const uint32_t *tnum)
{
  for (uint32_t t = 0; t < plc->ntris; t++) {
    const uint32_t *v = plc->tris + 3 * (size_t)t;
    const double *a = plc->xyz + 3 * (size_t)v[0], *b = plc->xyz + 3 * (size_t)v[1],
                 *c = plc->xyz + 3 * (size_t)v[2];
    int flat = v[0] == v[1] || v[1] == v[2] || v[0] == v[2];
    if (!flat)
      flat = tr_orient2d_proj(a, b, c, 0) == 0 && tr_orient2d_proj(a, b, c, 1) == 0 &&
             tr_orient2d_proj(a, b, c, 2) == 0;
    if (flat)
      return tr_error(TR_ERR_INPUT,
                      "%s%striangle %u (input face %u) has zero area: vertices %u %u %u are "
                      "collinear or repeated",
                      plc->source ? plc->source : "", plc->source ? ": " : "", tnum[t],
                      src_of(plc, t), orig[v[0]], orig[v[1]], orig[v[2]]);
  }
  return TR_OK;
}

static void sorted3(const uint32_t *v, uint32_t s[3])
{
  uint32_t a = v[0], b = v[1], c = v[2], x;
  if (a > b) x = a, a = b, b = x;
  if (b > c) x = b, b = c, c = x;
  if (a > b) x = a, a = b, b = x;
  s[0] = a, s[1] = b, s[2] = c;
}

static int cmp_tri(const void *ctx, uint32_t a, uint32_t b)
{
  const uint32_t *t = ctx;
  uint32_t p[3], q[3];
  sorted3(t + 3 * (size_t)a, p);
  sorted3(t + 3 * (size_t)b, q);
  for (int k = 0; k < 3; k++)
    if (p[k] != q[k])
      return p[k] < q[k] ? -1 : 1;
  return 0;
}

/* ord = 0..n-1 sorted by cmp_tri, equal keys in index order: three stable counting
 * passes over the sorted vertex triples (last vertex first), O(n + nv) instead of a
 * comparison sort that sorted both triples in every comparison. Every id is < nv. */
static tr_status sort_triangles(const uint32_t *tris, uint32_t n, uint32_t nv, uint32_t *ord)
{
  uint32_t *key = malloc(sizeof *key * 3 * (size_t)(n ? n : 1));
  uint32_t *tmp = malloc(sizeof *tmp * (n ? n : 1));
  uint32_t *cnt = malloc(sizeof *cnt * ((size_t)nv + 1));
  if (!key || !tmp || !cnt) {
    free(key);
    free(tmp);
    free(cnt);
    return tr_error(TR_ERR_NOMEM, "out of memory sorting %u triangles", n);
  }
  for (uint32_t t = 0; t < n; t++) {
    sorted3(tris + 3 * (size_t)t, key + 3 * (size_t)t);
    ord[t] = t;
  }
  uint32_t *src = ord, *dst = tmp;
  for (int d = 2; d >= 0; d--) {
    memset(cnt, 0, sizeof *cnt * ((size_t)nv + 1));
    for (uint32_t i = 0; i < n; i++)
      cnt[key[3 * (size_t)src[i] + d] + 1]++;
    for (uint32_t v = 0; v < nv; v++)
      cnt[v + 1] += cnt[v];
    for (uint32_t i = 0; i < n; i++)
      dst[cnt[key[3 * (size_t)src[i] + d]]++] = src[i];
    uint32_t *x = src;
    src = dst;
    dst = x;
  }
  if (src != ord) /* three passes: the result is in tmp */
    memcpy(ord, src, sizeof *ord * n);
  free(key);
  free(tmp);
  free(cnt);
  return TR_OK;
}

/* Removes later copies of a triangle (same vertex set, either orientation). */
static tr_status duplicate_triangles(struct tr_plc *plc, uint32_t *tnum, tr_report *rep)
{
  uint32_t n = plc->ntris;
  uint32_t *ord = malloc(sizeof *ord * (n ? n : 1));
  char *drop = calloc(n ? n : 1, 1);
  tr_status st = TR_OK;
  if (!ord || !drop) {
    st = tr_error(TR_ERR_NOMEM, "out of memory checking duplicate triangles");
    goto done;
  }
  if ((st = sort_triangles(plc->tris, n, plc->npoints, ord)) != TR_OK)
    goto done;
  for (uint32_t i = 1; i < n; i++) {
    uint32_t first = i - 1;
    while (first > 0 && drop[ord[first]])
      first--;
    if (cmp_tri(plc->tris, ord[first], ord[i]) == 0) {
      drop[ord[i]] = 1;
      tr_report_add(rep, TR_REP_DUPT, "triangle %u duplicates triangle %u (removed)",
                    tnum[ord[i]], tnum[ord[first]]);
    }
  }
  uint32_t m = 0;
  for (uint32_t t = 0; t < n; t++) {
    if (drop[t])
      continue;
    memmove(plc->tris + 3 * (size_t)m, plc->tris + 3 * (size_t)t, 3 * sizeof *plc->tris);
    if (plc->tri_marker)
      plc->tri_marker[m] = plc->tri_marker[t];
    if (plc->tri_source)
      plc->tri_source[m] = plc->tri_source[t];
    tnum[m++] = tnum[t];
  }
  plc->ntris = m;
done:
  free(ord);
  free(drop);
  return st;
}

/* Edge census: e[3t+k] = edge k of triangle t, sorted by (min, max). */
static int cmp_edge(const void *ctx, uint32_t a, uint32_t b)
{
  const uint32_t *t = ctx;
  uint32_t a0 = t[a], a1 = t[3 * (a / 3) + (a % 3 + 1) % 3];
  uint32_t b0 = t[b], b1 = t[3 * (b / 3) + (b % 3 + 1) % 3];
  uint32_t p0 = a0 < a1 ? a0 : a1, p1 = a0 < a1 ? a1 : a0;
  uint32_t q0 = b0 < b1 ? b0 : b1, q1 = b0 < b1 ? b1 : b0;
  if (p0 != q0)
    return p0 < q0 ? -1 : 1;
  if (p1 != q1)
    return p1 < q1 ? -1 : 1;
  return 0;
}

static void flip(struct tr_plc *plc, uint32_t t)
{
  uint32_t x = plc->tris[3 * (size_t)t + 1];
  plc->tris[3 * (size_t)t + 1] = plc->tris[3 * (size_t)t + 2];
  plc->tris[3 * (size_t)t + 2] = x;
}

/* 6 * the signed volume bounded by triangles tris[0..n) (all if tris == NULL): the sum
 * of det[a; b; c] (origin 0), exact in integers: each double is m * 2^e with an integer
 * m, so scaling every coordinate by 2^-emin makes them all integers. out = the sum
 * scaled back (as a rational). */
static void volume6(const struct tr_plc *plc, const uint32_t *tris, uint32_t n, mpq_t out)
{
  int emin = INT32_MAX;
  for (uint32_t i = 0; i < n; i++)
    for (int k = 0; k < 3; k++)
      for (int d = 0; d < 3; d++) {
        uint32_t t = tris ? tris[i] : i;
        double x = plc->xyz[3 * (size_t)plc->tris[3 * (size_t)t + k] + d];
        if (x != 0) {
          int e;
          frexp(x, &e);
          if (e - 53 < emin)
            emin = e - 53;
        }
      }
  mpq_set_ui(out, 0, 1);
  if (emin == INT32_MAX)
    return;
  mpz_t sum, c[3][3], t1, t2;
  mpz_inits(sum, t1, t2, NULL);
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      mpz_init(c[i][j]);
  for (uint32_t i = 0; i < n; i++) {
    uint32_t t = tris ? tris[i] : i;
    for (int k = 0; k < 3; k++)
      for (int d = 0; d < 3; d++) {
        double x = plc->xyz[3 * (size_t)plc->tris[3 * (size_t)t + k] + d];
        int e = 0;
        double f = frexp(x, &e);
        mpz_set_d(c[k][d], ldexp(f, 53)); /* exact 53-bit integer */
        if (x != 0)
          mpz_mul_2exp(c[k][d], c[k][d], (mp_bitcnt_t)(e - 53 - emin));
      }
    for (int d = 0; d < 3; d++) { /* a . (b x c) */
      int d1 = (d + 1) % 3, d2 = (d + 2) % 3;
      mpz_mul(t1, c[1][d1], c[2][d2]);
      mpz_mul(t2, c[1][d2], c[2][d1]);
      mpz_sub(t1, t1, t2);
      mpz_addmul(sum, c[0][d], t1);
    }
  }
  mpq_set_z(out, sum);
  if (emin < 0)
    mpq_div_2exp(out, out, (mp_bitcnt_t)(-3 * (long)emin));
  else
    mpq_mul_2exp(out, out, (mp_bitcnt_t)(3 * (long)emin));
  mpz_clears(sum, t1, t2, NULL);
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      mpz_clear(c[i][j]);
}

/* The sign of volume6 when doubles decide it, else 0 (unknown). Every nonzero coordinate
 * in [2^-300, 2^300] keeps each product of three normal: then each term a . (b x c) is
 * off by at most 8u times its permanent p (u = 2^-53; the products' and differences'
 * roundings, with slack), and the running sum of n terms by n u times the sum of the
 * terms' magnitudes. The sums P and A, rounded themselves, are
 * covered by the factor 2 of slack. The exact sum is zero or of the other sign only when
 * |S| is within that bound. Most shells are decided here: the exact sum in integers
 * (volume6) was a quarter of the validation's time. */
static int shell_volume_sign_fast(const struct tr_plc *plc, const uint32_t *tris, uint32_t n)
{
  const double u = 0x1p-53; /* n < 2^32: n u < 2^-21 */
  double S = 0, P = 0, A = 0;
  for (uint32_t i = 0; i < n; i++) {
    const uint32_t *v = plc->tris + 3 * (size_t)(tris ? tris[i] : i);
    const double *a = plc->xyz + 3 * (size_t)v[0], *b = plc->xyz + 3 * (size_t)v[1],
                 *c = plc->xyz + 3 * (size_t)v[2];
    for (int d = 0; d < 3; d++) {
      double x[3] = {fabs(a[d]), fabs(b[d]), fabs(c[d])};
      for (int k = 0; k < 3; k++)
        if (x[k] != 0 && !(x[k] >= 0x1p-300 && x[k] <= 0x1p300))
          return 0;
    }
    double t = 0, p = 0;
    for (int d = 0; d < 3; d++) {
      int d1 = (d + 1) % 3, d2 = (d + 2) % 3;
      double q1 = b[d1] * c[d2], q2 = b[d2] * c[d1];
      t += a[d] * (q1 - q2);
      p += fabs(a[d]) * (fabs(q1) + fabs(q2));
    }
    S += t;
    P += p;
    A += fabs(t);
  }
  double err = 16 * u * P + 2 * (double)n * u * A;
  if (!isfinite(S) || !isfinite(err))
    return 0;
  return S > err ? 1 : S < -err ? -1 : 0;
}

static int shell_volume_sign(const struct tr_plc *plc, const uint32_t *tris, uint32_t n)
{
  int fast = shell_volume_sign_fast(plc, tris, n);
  if (fast)
    return fast;
  mpq_t v;
  mpq_init(v);
  volume6(plc, tris, n, v);
  int s = mpq_sgn(v);
  mpq_clear(v);
  return s;
}

/* volume6 on a surface with exact points: the triangles of doubles as above, those with
 * an exact corner in rationals. Their sum runs as a balanced binary tree (a binary
 * counter: level k holds the sum of 2^k terms, as tr_mesh_volume6 does): every exact
 * corner brings its own denominator, and a running total's grows to the lcm of all of
 * them, so a left-to-right sum is quadratic (the 703 scaled spheres' 54,714 corners). */
#define VOL_LEVELS 40
static tr_status volume6_exact(const struct tr_plc *plc, const uint32_t *tris, uint32_t n,
                               mpq_t out)
{
  uint32_t *dbl = malloc(sizeof *dbl * (n ? n : 1));
  if (!dbl)
    return tr_error(TR_ERR_NOMEM, "out of memory measuring the volume");
  uint32_t nd = 0;
  uint64_t used = 0; /* bit k: lev[k] holds a partial sum */
  mpq_t x[3][3], s, t, term, lev[VOL_LEVELS];
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      mpq_init(x[i][j]);
  for (int k = 0; k < VOL_LEVELS; k++)
    mpq_init(lev[k]);
  mpq_inits(s, t, term, NULL);
  for (uint32_t i = 0; i < n; i++) {
    uint32_t tri = tris ? tris[i] : i;
    const uint32_t *v = plc->tris + 3 * (size_t)tri;
    if (!plc->xq[v[0]] && !plc->xq[v[1]] && !plc->xq[v[2]]) {
      dbl[nd++] = tri;
      continue;
    }
    for (int k = 0; k < 3; k++) {
      tr_point p = tr_plc_point(plc, v[k]);
      for (int d = 0; d < 3; d++)
        tr_point_get_q(&p, d, x[k][d]);
    }
    mpq_set_ui(term, 0, 1); /* a . (b x c) */
    for (int d = 0; d < 3; d++) {
      int e = (d + 1) % 3, f = (d + 2) % 3;
      mpq_mul(s, x[1][e], x[2][f]);
      mpq_mul(t, x[1][f], x[2][e]);
      mpq_sub(s, s, t);
      mpq_mul(s, s, x[0][d]);
      mpq_add(term, term, s);
    }
    int k = 0;
    while (k < VOL_LEVELS - 1 && (used >> k & 1)) {
      mpq_add(term, term, lev[k]);
      used &= ~((uint64_t)1 << k);
      k++;
    }
    if (used >> k & 1)
      mpq_add(lev[k], lev[k], term);
    else
      mpq_swap(lev[k], term);
    used |= (uint64_t)1 << k;
  }
  volume6(plc, dbl, nd, out);
  for (int k = 0; k < VOL_LEVELS; k++)
    if (used >> k & 1)
      mpq_add(out, out, lev[k]);
  for (int i = 0; i < 3; i++)
    for (int j = 0; j < 3; j++)
      mpq_clear(x[i][j]);
  for (int k = 0; k < VOL_LEVELS; k++)
    mpq_clear(lev[k]);
  mpq_clears(s, t, term, NULL);
  free(dbl);
  return TR_OK;
}

tr_status tr_input_volume6(const struct tr_plc *plc, mpq_t out)
{
  if (plc->xq)
    return volume6_exact(plc, NULL, plc->ntris, out);
  volume6(plc, NULL, plc->ntris, out);
  return TR_OK;
}

tr_status tr_input_volume6_of(const struct tr_plc *plc, const uint32_t *tris, uint32_t n,
                              mpq_t out)
{
  if (plc->xq)
    return volume6_exact(plc, tris, n, out);
  volume6(plc, tris, n, out);
  return TR_OK;
}

/* 1 iff triangle t lists a then b consecutively. */
static int goes(const uint32_t *v, uint32_t a, uint32_t b)
{
  return (v[0] == a && v[1] == b) || (v[1] == a && v[2] == b) || (v[2] == a && v[0] == b);
}

static tr_status manifold_and_orient(struct tr_plc *plc, const uint32_t *orig,
                                     const uint32_t *tnum, int allow_open, tr_report *rep,
                                     int *selfint_done)
{
  uint32_t nt = plc->ntris, ne = 3 * nt;
  uint32_t *e = malloc(sizeof *e * (ne ? ne : 1));
  uint32_t *adj = malloc(sizeof *adj * (ne ? ne : 1)); /* 3t+k -> 3t'+k' across manifold edge */
  uint32_t *comp = malloc(sizeof *comp * (nt ? nt : 1)), *queue = malloc(sizeof *queue * (nt ? nt : 1));
  char *flipme = calloc(nt ? nt : 1, 1), *closed = NULL;
  tr_status st = TR_OK;
  if (!e || !adj || !comp || !queue || !flipme) {
    st = tr_error(TR_ERR_NOMEM, "out of memory checking the surface");
    goto done;
  }
  for (uint32_t i = 0; i < ne; i++) {
    e[i] = i;
    adj[i] = UINT32_MAX;
  }
  if ((st = tr_edge_slots_sorted(plc->tris, nt, plc->npoints, e)) != TR_OK)
    goto done;
  /* Edges with 1 triangle (free) or 3+ (internal facets, shells touching along an
   * edge) are legal; they send the surface to the cell analysis of cells.c, which
   * decides whether free edges lie inside the domain. */
  int general = 0;
  for (uint32_t i = 0; i < ne;) {
    uint32_t j = i + 1;
    while (j < ne && cmp_edge(plc->tris, e[i], e[j]) == 0)
      j++;
    if (j - i == 2) {
      adj[e[i]] = e[i + 1];
      adj[e[i + 1]] = e[i];
    } else
      general = 1;
    i = j;
  }
  /* Breadth-first over manifold edges; a neighbour must traverse the shared edge in the
   * opposite direction, else one of the two is flipped (relative to the start). */
  for (uint32_t t = 0; t < nt; t++)
    comp[t] = UINT32_MAX;
  uint32_t ncomp = 0;
  for (uint32_t s = 0; s < nt; s++) {
    if (comp[s] != UINT32_MAX)
      continue;
    uint32_t qh = 0, qt = 0;
    comp[s] = ncomp;
    queue[qt++] = s;
    while (qh < qt) {
      uint32_t t = queue[qh++];
      for (int k = 0; k < 3; k++) {
        uint32_t o = adj[3 * t + (uint32_t)k];
        if (o == UINT32_MAX)
          continue;
        uint32_t u = o / 3;
        uint32_t a = plc->tris[3 * t + (uint32_t)k], b = plc->tris[3 * t + ((uint32_t)k + 1) % 3];
        /* Effective directions after the flips decided so far. */
        int dt = goes(plc->tris + 3 * (size_t)t, a, b) ^ flipme[t];
        int du = goes(plc->tris + 3 * (size_t)u, a, b);
        int want = !dt; /* u must go b -> a */
        if (comp[u] == UINT32_MAX) {
          comp[u] = ncomp;
          flipme[u] = (char)(du != want);
          queue[qt++] = u;
        } else if ((du ^ flipme[u]) != want) {
          st = tr_error(TR_ERR_INPUT,
                        "%s%sthe surface is not orientable (Moebius-like): triangles %u and %u "
                        "cannot agree across edge (%u, %u)",
                      PRE(plc),
                        tnum[t], tnum[u], orig[a], orig[b]);
          goto done;
        }
      }
    }
    ncomp++;
  }
  /* Per shell: closed iff none of its edges is a boundary / non-manifold edge. */
  closed = malloc(ncomp ? ncomp : 1);
  if (!closed) {
    st = tr_error(TR_ERR_NOMEM, "out of memory");
    goto done;
  }
  memset(closed, 1, ncomp ? ncomp : 1);
  for (uint32_t i = 0; i < ne; i++)
    if (adj[i] == UINT32_MAX)
      closed[comp[i / 3]] = 0;
  for (uint32_t t = 0; t < nt; t++)
    if (flipme[t])
      flip(plc, t);
  if (general) {
    /* the cell analysis assumes triangles meet only in shared vertices and edges */
    double c0 = vclock();
    st = tr_input_self_intersections(plc, tnum);
    double c1 = vclock();
    plc->validate_seconds[1] += c1 - c0;
    if (st == TR_OK)
      st = tr_input_orient_cells(plc, tnum, orig, allow_open, flipme);
    plc->validate_seconds[2] += vclock() - c1;
    *selfint_done = 1;
    goto report;
  }
  /* Every edge has two triangles: a union of closed shells. Orient every closed shell
   * outward: positive enclosed volume. Triangles are grouped by shell with a counting
   * sort, so the order (and the report) is deterministic. */
  {
    uint32_t *start = calloc((size_t)ncomp + 1, sizeof *start), *order = e;
    if (!start) {
      st = tr_error(TR_ERR_NOMEM, "out of memory");
      goto done;
    }
    for (uint32_t t = 0; t < nt; t++)
      start[comp[t] + 1]++;
    for (uint32_t c = 0; c < ncomp; c++)
      start[c + 1] += start[c];
    for (uint32_t c = 0; c < ncomp; c++)
      queue[c] = start[c]; /* fill pointers; ncomp <= nt */
    for (uint32_t t = 0; t < nt; t++)
      order[queue[comp[t]]++] = t;
    /* Each closed shell's enclosed volume as given (the majority of its triangles as
     * read), then the nesting decides cavities (facing inward: negative volume) and
     * inclusions (outward). The nesting test needs consistently oriented shells, which
     * they are by now. */
    char *cavity = malloc(ncomp ? ncomp : 1);
    int8_t *given = calloc(ncomp ? ncomp : 1, 1), *sign = calloc(ncomp ? ncomp : 1, 1);
    if (!cavity || !given || !sign)
      st = tr_error(TR_ERR_NOMEM, "out of memory");
    for (uint32_t c = 0; c < ncomp && st == TR_OK; c++) {
      if (!closed[c])
        continue;
      uint32_t n = start[c + 1] - start[c], nflip = 0;
      sign[c] = (int8_t)shell_volume_sign(plc, order + start[c], n);
      for (uint32_t i = start[c]; i < start[c + 1]; i++)
        nflip += flipme[order[i]] != 0;
      given[c] = (int8_t)(2 * nflip < n ? sign[c] : 2 * nflip > n ? -sign[c] : 0);
      if (sign[c] == 0)
        st = tr_error(TR_ERR_INPUT,
                      "%s%sthe closed shell containing triangle %u encloses zero volume",
                      PRE(plc),
                      tnum[order[start[c]]]);
    }
    double c0 = vclock();
    if (st == TR_OK)
      st = tr_input_shell_cavities(plc, order, start, closed, ncomp, given, tnum, rep, cavity,
                                   &plc->ncavities, &plc->ninclusions);
    plc->validate_seconds[2] += vclock() - c0;
    for (uint32_t c = 0; c < ncomp && st == TR_OK; c++) {
      if (closed[c] && sign[c] != (cavity[c] ? -1 : 1)) {
        for (uint32_t i = start[c]; i < start[c + 1]; i++) {
          flip(plc, order[i]);
          flipme[order[i]] ^= 1;
        }
      }
    }
    free(given);
    free(sign);
    free(cavity);
    free(start);
  }
report:
  /* Report the net change per triangle: flipped for consistency, for outwardness, or
   * both (then unchanged). */
  for (uint32_t t = 0; t < nt && st == TR_OK; t++)
    if (flipme[t])
      tr_report_add(rep, TR_REP_FLIP,
                    "triangle %u (input face %u) flipped: orientation repaired to agree with "
                    "its neighbours and face outward", tnum[t], src_of(plc, t));
done:
  free(e);
  free(adj);
  free(comp);
  free(queue);
  free(flipme);
  free(closed);
  return st;
}

tr_status tr_plc_validate(tr_plc *plc, const tr_options *opt)
{
  tr_error_clear();
  double c0 = vclock();
  plc->validated = 0;
  memset(plc->validate_seconds, 0, sizeof plc->validate_seconds);
  plc->ncavities = plc->ninclusions = 0;
  free(plc->hole_cavity);
  plc->hole_cavity = NULL;
  if (plc->xq) {
    /* the boundary of a solid by winding number (src/resolve/surface.c): closed, oriented
     * outward and free of self-intersections by construction, exactly; the checks below
     * read doubles and would judge its rational points at their nearest doubles */
    plc->validated = 1;
    return TR_OK;
  }
  tr_options def;
  if (!opt) {
    tr_options_default(&def);
    opt = &def;
  }
  for (size_t i = 0; i < 3 * (size_t)plc->npoints; i++)
    if (!isfinite(plc->xyz[i]))
      return tr_error(TR_ERR_INPUT, "vertex %zu: coordinate is NaN or infinite", i / 3);
  for (size_t i = 0; i < 3 * (size_t)plc->ntris; i++)
    if (plc->tris[i] >= plc->npoints)
      return tr_error(TR_ERR_INPUT, "triangle %zu: vertex index %u out of range", i / 3,
                      plc->tris[i]);
  tr_report rep;
  memset(&rep, 0, sizeof rep);
  uint32_t *orig = malloc(sizeof *orig * (plc->npoints ? plc->npoints : 1));
  uint32_t *tnum = malloc(sizeof *tnum * (plc->ntris ? plc->ntris : 1));
  tr_status st = TR_OK;
  if (!orig || !tnum)
    st = tr_error(TR_ERR_NOMEM, "out of memory validating the input");
  for (uint32_t t = 0; st == TR_OK && t < plc->ntris; t++)
    tnum[t] = t;
  if (st == TR_OK)
    st = merge_vertices(plc, orig, &rep);
  if (st == TR_OK)
    st = zero_area(plc, orig, tnum);
  if (st == TR_OK)
    st = duplicate_triangles(plc, tnum, &rep);
  int selfint_done = 0;
  if (st == TR_OK)
    st = manifold_and_orient(plc, orig, tnum, opt->allow_open, &rep, &selfint_done);
  if (st == TR_OK && !selfint_done) {
    double c1 = vclock();
    st = tr_input_self_intersections(plc, tnum);
    plc->validate_seconds[1] += vclock() - c1;
  }
  free(plc->report);
  plc->report = tr_report_finish(&rep);
  plc->validated = st == TR_OK ? (uint8_t)(1 + (opt->allow_open != 0)) : 0;
  free(orig);
  free(tnum);
  plc->validate_seconds[0] = vclock() - c0;
  return st;
}
