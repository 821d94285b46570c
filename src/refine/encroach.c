/* Exact encroachment tests and the exact split points of the refinement stage.
 *
 * Filters: both tests are polynomials in coordinate differences. Each difference is taken
 * in doubles from the points' nearest doubles. With e the points' own rounding errors
 * (tr_qpoint.err, 0 for doubles), the true difference is the computed one d times
 * (1 + theta), |theta| <= e / |d| + 2^-52 (the subtraction's rounding included); theta is
 * the largest such bound over the differences of a test, and at most 2^-20 (a zero
 * difference must be exact). A homogeneous polynomial of degree k in the differences then
 * moves by at most ((1 + theta)^k - 1) < 1.01 k theta of its permanent (the same
 * evaluation on absolute values), and its floating-point evaluation by less than 2^-48 of
 * it (under 30 operations), so a value beyond (1.01 k theta + 2^-47) of the permanent has
 * the exact sign for k <= 6. Every nonzero difference must also lie in [2^-150, 2^150], so that
 * no product of six of them under- or overflows. Otherwise: exact rationals (GMP). */
#include <math.h>
#include <stdlib.h>

#include "core/box.h"
#include "predicates/predicates.h"
#include "refine/refine_impl.h"

/* d[i] = b - a in doubles, *theta raised to its relative error bound (see the top); 0
 * when the filter's conditions fail. Before, the filter asked e <= 2^-45 |d| of every
 * difference, which a point on a constraint fails about 40 ulps from a neighbour: on
 * CGAL's elephant under -a 4e-7, every one of the 65k volume tests a run made went to GMP
 * (16% of its CPU). */
static int diff_ok(const tr_point *a, const tr_point *b, double d[3], double *theta)
{
  for (int i = 0; i < 3; i++) {
    double ea = a->q ? a->q->err[i] : 0, eb = b->q ? b->q->err[i] : 0;
    d[i] = b->d[i] - a->d[i];
    double ad = fabs(d[i]), e = ea + eb;
    if (!isfinite(d[i]) || (ad == 0 && e != 0))
      return 0;
    if (ad != 0 && (ad < 0x1p-150 || ad > 0x1p150))
      return 0;
    if (e != 0) {
      double t = e / ad * (1 + 0x1p-50) + 0x1p-52; /* e/ad rounded, and the margin */
      if (!(t <= 0x1p-20))
        return 0;
      *theta = t > *theta ? t : *theta;
    } else
      *theta = 0x1p-52 > *theta ? 0x1p-52 : *theta;
  }
  return 1;
}

/* The filter's threshold for a homogeneous polynomial of degree k (see the top). */
static double filter_bound(int k, double theta)
{
  return 1.01 * k * theta + 0x1p-47;
}

static void get_q3(const tr_point *p, mpq_t out[3])
{
  for (int i = 0; i < 3; i++)
    tr_point_get_q(p, i, out[i]);
}

/* X[k] = the coordinates of pts[k] times the least common denominator of all of them:
 * integers, for the exact stages of homogeneous polynomials in coordinate differences
 * (their sign does not change under a positive scale). mpq would normalise (a gcd) after
 * every product, which made these tests the hottest of refinement on the cocircular
 * sub-faces of CAD models' right angles. X[k][i] are initialised here. */
static void scaled_ints(const tr_point *const *pts, int n, mpz_t (*X)[3])
{
  mpq_t x;
  mpz_t L;
  mpq_init(x);
  mpz_init_set_ui(L, 1);
  for (int k = 0; k < n; k++)
    for (int i = 0; i < 3; i++) {
      tr_point_get_q(pts[k], i, x);
      mpz_lcm(L, L, mpq_denref(x));
    }
  for (int k = 0; k < n; k++)
    for (int i = 0; i < 3; i++) {
      tr_point_get_q(pts[k], i, x);
      mpz_init(X[k][i]);
      mpz_divexact(X[k][i], L, mpq_denref(x));
      mpz_mul(X[k][i], X[k][i], mpq_numref(x));
    }
  mpz_clear(L);
  mpq_clear(x);
}

int rf_in_diametral(const tr_point *a, const tr_point *b, const tr_point *p)
{
  double u[3], v[3], th = 0;
  if (diff_ok(a, p, u, &th) && diff_ok(b, p, v, &th)) {
    /* (p-a).(p-b) = u.v with u = p - a, v = p - b */
    double s = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    double perm = fabs(u[0] * v[0]) + fabs(u[1] * v[1]) + fabs(u[2] * v[2]);
    if (fabs(s) > filter_bound(2, th) * perm)
      return s < 0;
    if (perm == 0)
      return 0;
  }
  const tr_point *pts[3] = {a, b, p};
  mpz_t X[3][3], x, y, s;
  scaled_ints(pts, 3, X);
  mpz_inits(x, y, s, NULL);
  for (int i = 0; i < 3; i++) {
    mpz_sub(x, X[2][i], X[0][i]);
    mpz_sub(y, X[2][i], X[1][i]);
    mpz_addmul(s, x, y);
  }
  int r = mpz_sgn(s) < 0;
  for (int k = 0; k < 3; k++)
    mpz_clears(X[k][0], X[k][1], X[k][2], NULL);
  mpz_clears(x, y, s, NULL);
  return r;
}

/* det3 of rows x, y, z and its permanent on absolute values. */
static double det3(const double x[3], const double y[3], const double z[3])
{
  return x[0] * (y[1] * z[2] - y[2] * z[1]) - x[1] * (y[0] * z[2] - y[2] * z[0]) +
         x[2] * (y[0] * z[1] - y[1] * z[0]);
}
static double per3(const double x[3], const double y[3], const double z[3])
{
  double X[3], Y[3], Z[3];
  for (int i = 0; i < 3; i++) {
    X[i] = fabs(x[i]);
    Y[i] = fabs(y[i]);
    Z[i] = fabs(z[i]);
  }
  return X[0] * (Y[1] * Z[2] + Y[2] * Z[1]) + X[1] * (Y[0] * Z[2] + Y[2] * Z[0]) +
         X[2] * (Y[0] * Z[1] + Y[1] * Z[0]);
}

static void qdet3(mpq_t out, mpq_t x[3], mpq_t y[3], mpq_t z[3], mpq_t t)
{
  mpq_set_ui(out, 0, 1);
  static const int P[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {1, 0, 2}, {2, 1, 0}};
  for (int k = 0; k < 6; k++) {
    mpq_mul(t, x[P[k][0]], y[P[k][1]]);
    mpq_mul(t, t, z[P[k][2]]);
    if (k < 3)
      mpq_add(out, out, t);
    else
      mpq_sub(out, out, t);
  }
}

static void zdet3(mpz_t out, mpz_t x[3], mpz_t y[3], mpz_t z[3], mpz_t t)
{
  mpz_set_ui(out, 0);
  static const int P[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {1, 0, 2}, {2, 1, 0}};
  for (int k = 0; k < 6; k++) {
    mpz_mul(t, x[P[k][0]], y[P[k][1]]);
    if (k < 3)
      mpz_addmul(out, t, z[P[k][2]]);
    else
      mpz_submul(out, t, z[P[k][2]]);
  }
}

/* The sphere through a, b, c centred in their plane, lifted: with u = b-a, v = c-a,
 * q = p-a, n = u x v, the rows (u,|u|^2), (v,|v|^2), (n,0) span the kernel of the lifted
 * sphere's linear form, and det4[them; (q,|q|^2)] = |n|^2 (|q|^2 - 2 centre.q), negative
 * exactly when p is inside. Expanded along the lifted column:
 *   det4 = -|u|^2 D(v,n,q) + |v|^2 D(u,n,q) + |q|^2 D(u,v,n). */
int rf_in_equatorial(const tr_point *a, const tr_point *b, const tr_point *c,
                     const tr_point *p)
{
  double u[3], v[3], q[3], th = 0;
  if (diff_ok(a, b, u, &th) && diff_ok(a, c, v, &th) && diff_ok(a, p, q, &th)) {
    double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                   u[0] * v[1] - u[1] * v[0]};
    double na[3] = {fabs(u[1] * v[2]) + fabs(u[2] * v[1]), fabs(u[2] * v[0]) + fabs(u[0] * v[2]),
                    fabs(u[0] * v[1]) + fabs(u[1] * v[0])};
    double wu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    double wv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    double wq = q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    double d = -wu * det3(v, n, q) + wv * det3(u, n, q) + wq * det3(u, v, n);
    double perm = wu * per3(v, na, q) + wv * per3(u, na, q) + wq * per3(u, v, na);
    if (isfinite(perm) && fabs(d) > filter_bound(6, th) * perm)
      return d < 0;
    if (perm == 0)
      return 0;
  }
  /* homogeneous of degree 6 in the differences: on scaled integers (scaled_ints) */
  mpz_t X[4][3], U[3], V[3], Q[3], N[3], w[3], t, s, r;
  const tr_point *pts[4] = {a, b, c, p};
  scaled_ints(pts, 4, X);
  mpz_inits(t, s, r, NULL);
  for (int i = 0; i < 3; i++) {
    mpz_inits(U[i], V[i], Q[i], N[i], w[i], NULL);
    mpz_sub(U[i], X[1][i], X[0][i]);
    mpz_sub(V[i], X[2][i], X[0][i]);
    mpz_sub(Q[i], X[3][i], X[0][i]);
  }
  for (int i = 0; i < 3; i++) {
    int j = (i + 1) % 3, k = (i + 2) % 3;
    mpz_mul(N[i], U[j], V[k]);
    mpz_submul(N[i], U[k], V[j]);
  }
  mpz_t *rows[3] = {U, V, Q};
  for (int k = 0; k < 3; k++)
    for (int i = 0; i < 3; i++)
      mpz_addmul(w[k], rows[k][i], rows[k][i]);
  zdet3(r, V, N, Q, t);
  mpz_submul(s, r, w[0]);
  zdet3(r, U, N, Q, t);
  mpz_addmul(s, r, w[1]);
  zdet3(r, U, V, N, t);
  mpz_addmul(s, r, w[2]);
  int res = mpz_sgn(s) < 0;
  for (int k = 0; k < 4; k++)
    mpz_clears(X[k][0], X[k][1], X[k][2], NULL);
  for (int i = 0; i < 3; i++)
    mpz_clears(U[i], V[i], Q[i], N[i], w[i], NULL);
  mpz_clears(t, s, r, NULL);
  return res;
}

/* An axis along which the projection of input triangle tri is not degenerate (exact). */
static int tri_drop(const rf_ctx *c, uint32_t tri)
{
  const uint32_t *T = c->plc->tris + 3 * (size_t)tri;
  tr_point a = tr_mesh_point(c->m, T[0]), b = tr_mesh_point(c->m, T[1]),
           d = tr_mesh_point(c->m, T[2]);
  /* the largest normal component first: the best conditioned projection */
  double u[3], v[3], n[3];
  for (int i = 0; i < 3; i++) {
    u[i] = b.d[i] - a.d[i];
    v[i] = d.d[i] - a.d[i];
  }
  for (int i = 0; i < 3; i++)
    n[i] = fabs(u[(i + 1) % 3] * v[(i + 2) % 3] - u[(i + 2) % 3] * v[(i + 1) % 3]);
  int best = n[1] > n[0] ? 1 : 0;
  best = n[2] > n[best] ? 2 : best;
  if (tr_orient2d_proj_p(&a, &b, &d, best) != 0)
    return best;
  for (int i = 0; i < 3; i++)
    if (tr_orient2d_proj_p(&a, &b, &d, i) != 0)
      return i;
  return 0;
}

int rf_in_input_triangle(const rf_ctx *c, uint32_t tri, const tr_point *p)
{
  const uint32_t *T = c->plc->tris + 3 * (size_t)tri;
  tr_point a = tr_mesh_point(c->m, T[0]), b = tr_mesh_point(c->m, T[1]),
           d = tr_mesh_point(c->m, T[2]);
  if (tr_orient3d_p(&a, &b, &d, p) != 0)
    return 0;
  return tr_plc_tri_holds(c->plc, tri, tri_drop(c, tri), p);
}

uint32_t rf_facet_triangle_of(const rf_ctx *c, uint32_t g, const tr_point *p, uint32_t hint)
{
  if (tr_facets_size(&c->fc, g) == 1)
    return rf_in_input_triangle(c, g, p) ? g : TR_NONE;
  const uint32_t *T = c->plc->tris + 3 * (size_t)g;
  tr_point a = tr_mesh_point(c->m, T[0]), b = tr_mesh_point(c->m, T[1]),
           d = tr_mesh_point(c->m, T[2]);
  if (tr_orient3d_p(&a, &b, &d, p) != 0)
    return TR_NONE;
  /* every triangle of the facet spans its plane, so g's axis serves them all */
  return tr_facets_triangle_of(&c->fc, c->plc, g, tri_drop(c, g), p, hint);
}

/* Parameter of point x (on the line AB) along A -> B, exactly, on the axis where AB is
 * longest. */
static void param_on(const tr_point *A, const tr_point *B, const tr_point *x, mpq_t t)
{
  int ax = 0;
  for (int i = 1; i < 3; i++)
    if (fabs(B->d[i] - A->d[i]) > fabs(B->d[ax] - A->d[ax]))
      ax = i;
  mpq_t a, b;
  mpq_inits(a, b, NULL);
  tr_point_get_q(A, ax, a);
  tr_point_get_q(B, ax, b);
  tr_point_get_q(x, ax, t);
  mpq_sub(t, t, a);
  mpq_sub(b, b, a);
  mpq_div(t, t, b);
  mpq_clears(a, b, NULL);
}

/* The largest power of two <= x (x > 0 rational), as a rational. */
static void pow2_below(const mpq_t x, mpq_t out)
{
  long e = (long)mpz_sizeinbase(mpq_numref(x), 2) - (long)mpz_sizeinbase(mpq_denref(x), 2) + 1;
  for (;; e--) {
    mpq_set_ui(out, 1, 1);
    if (e >= 0)
      mpq_mul_2exp(out, out, (unsigned long)e);
    else
      mpq_div_2exp(out, out, (unsigned long)-e);
    if (mpq_cmp(out, x) <= 0)
      return;
  }
}

static tr_qpoint *point_on_edge(const tr_point *A, const tr_point *B, const mpq_t t)
{
  tr_qpoint *q = malloc(sizeof *q);
  if (!q)
    return NULL;
  tr_qpoint_init(q);
  mpq_t a, b;
  mpq_inits(a, b, NULL);
  for (int i = 0; i < 3; i++) {
    tr_point_get_q(A, i, a);
    tr_point_get_q(B, i, b);
    mpq_sub(b, b, a);
    mpq_mul(b, b, t);
    mpq_add(q->c[i], a, b);
  }
  mpq_clears(a, b, NULL);
  tr_qpoint_update(q);
  return q;
}

tr_status rf_segment_split_point(rf_ctx *c, uint32_t s, tr_qpoint **out)
{
  uint32_t A = c->ssab[2 * (size_t)s], B = c->ssab[2 * (size_t)s + 1];
  uint32_t u = c->ssv[2 * (size_t)s], v = c->ssv[2 * (size_t)s + 1];
  tr_point pA = tr_mesh_point(c->m, A), pB = tr_mesh_point(c->m, B);
  tr_point pu = tr_mesh_point(c->m, u), pv = tr_mesh_point(c->m, v);
  mpq_t lo, hi, t, w;
  mpq_inits(lo, hi, t, w, NULL);
  if (u == A)
    mpq_set_ui(lo, 0, 1);
  else if (u == B)
    mpq_set_ui(lo, 1, 1);
  else
    param_on(&pA, &pB, &pu, lo);
  if (v == A)
    mpq_set_ui(hi, 0, 1);
  else if (v == B)
    mpq_set_ui(hi, 1, 1);
  else
    param_on(&pA, &pB, &pv, hi);
  if (mpq_cmp(lo, hi) > 0)
    mpq_swap(lo, hi);
  int at_a = mpq_sgn(lo) == 0, at_b = mpq_cmp_ui(hi, 1, 1) == 0;
  if (rf_flat_split_param(c, s, lo, hi, t)) {
    /* at a flat sub-face's vertex foot (flat.c) */
  } else if (at_a && at_b) {
    mpq_set_ui(t, 1, 2);
  } else if (at_a || at_b) {
    /* concentric shells about the input vertex (Shewchuk 1998): the split point's distance
     * from it is a power of two r in [1/3, 2/3] of the sub-segment's length (exactly one
     * lies there), the same r on every input edge at that vertex, so points on two such
     * edges at a small angle do not encroach each other's pieces without end. r / |AB| is
     * irrational in general, so the parameter is r / |AB| rounded to 12 significant bits:
     * the shells of two edges then agree to 2^-11 */
    /* |AB| in the frame 2^-e0 that brings its half extent into [1/2, 1): the squares
     * underflow to L = 0 (a NaN parameter reached GMP, which aborts) at 2^-600 and
     * overflow at 2^600. tr below is r / |AB|, a ratio, the same in any frame; and a
     * power of two scales exactly, so the shells at 2^k are those at 1 times 2^k. */
    double h = 0, L = 0;
    for (int i = 0; i < 3; i++)
      h = fmax(h, fabs(0.5 * pB.d[i] - 0.5 * pA.d[i]));
    int e0 = tr_frame_exp(h);
    for (int i = 0; i < 3; i++) {
      double d = ldexp(pB.d[i], -e0) - ldexp(pA.d[i], -e0);
      L += d * d;
    }
    L = sqrt(L);
    mpq_sub(w, hi, lo);
    double D = mpq_get_d(w) * L;
    int e;
    frexp(2 * D / 3, &e); /* 2D/3 = f 2^e, f in [1/2, 1): 2^(e-1) <= 2D/3 */
    double tr = ldexp(1.0, e - 1) / L;
    int te;
    frexp(tr, &te);
    double tq = ldexp(floor(ldexp(tr, 12 - te) + 0.5), te - 12);
    if (isfinite(tq))
      mpq_set_d(t, tq);
    else
      mpq_set_ui(t, 0, 1); /* GMP aborts on inf and NaN; the fallback below takes over */
    if (at_b) {
      mpq_set_ui(w, 1, 1);
      mpq_sub(t, w, t);
    }
    /* inside the sub-segment by a margin (it is, unless L's rounding misled; then the
     * power-of-two fraction of the parameter interval below is used) */
    mpq_sub(w, hi, lo);
    if (!(tq > 0) || !isfinite(tq) || mpq_cmp(t, lo) <= 0 || mpq_cmp(t, hi) >= 0) {
      mpq_mul_2exp(w, w, 1);
      mpq_set_ui(t, 3, 1);
      mpq_div(w, w, t);
      pow2_below(w, t);
      if (at_b) {
        mpq_set_ui(w, 1, 1);
        mpq_sub(t, w, t);
      }
    }
  } else {
    /* the dyadic point of least denominator 2^m with 2^-m <= (hi - lo)/4 below the
     * midpoint: within a quarter of the sub-segment of its middle, exactly the midpoint
     * when both ends are dyadic */
    mpq_sub(w, hi, lo);
    mpq_div_2exp(w, w, 2);
    pow2_below(w, t); /* t = 2^-m */
    mpq_add(w, lo, hi);
    mpq_div_2exp(w, w, 1);
    mpq_div(w, w, t);
    mpz_t f;
    mpz_init(f);
    mpz_fdiv_q(f, mpq_numref(w), mpq_denref(w));
    mpq_set_z(w, f);
    mpz_clear(f);
    mpq_mul(t, t, w);
  }
  tr_qpoint *q = point_on_edge(&pA, &pB, t);
  mpq_clears(lo, hi, t, w, NULL);
  if (!q)
    return tr_error(TR_ERR_NOMEM, "out of memory for a split point");
  *out = q;
  return TR_OK;
}

/* Barycentric coordinates of x in the triangle (a, b, c) projected along `drop`, doubles. */
static void bary(const double *a, const double *b, const double *c, const double *x, int drop,
                 double w[3])
{
  int i = (drop + 1) % 3, j = (drop + 2) % 3;
  double det = (b[i] - a[i]) * (c[j] - a[j]) - (b[j] - a[j]) * (c[i] - a[i]);
  double l1 = ((x[i] - a[i]) * (c[j] - a[j]) - (x[j] - a[j]) * (c[i] - a[i])) / det;
  double l2 = ((b[i] - a[i]) * (x[j] - a[j]) - (b[j] - a[j]) * (x[i] - a[i])) / det;
  w[0] = 1 - l1 - l2;
  w[1] = l1;
  w[2] = l2;
}

/* Circumcentre of a triangle in 3D, doubles. */
static int tri_circumcentre(const double *a, const double *b, const double *c, double out[3])
{
  double u[3], v[3], n[3];
  for (int i = 0; i < 3; i++) {
    u[i] = b[i] - a[i];
    v[i] = c[i] - a[i];
  }
  for (int i = 0; i < 3; i++)
    n[i] = u[(i + 1) % 3] * v[(i + 2) % 3] - u[(i + 2) % 3] * v[(i + 1) % 3];
  double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  if (!(nn > 0))
    return 0;
  double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2], vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  double vn[3], nu[3];
  for (int i = 0; i < 3; i++) {
    vn[i] = v[(i + 1) % 3] * n[(i + 2) % 3] - v[(i + 2) % 3] * n[(i + 1) % 3];
    nu[i] = n[(i + 1) % 3] * u[(i + 2) % 3] - n[(i + 2) % 3] * u[(i + 1) % 3];
  }
  for (int i = 0; i < 3; i++)
    out[i] = a[i] + (uu * vn[i] + vv * nu[i]) / (2 * nn);
  return isfinite(out[0]) && isfinite(out[1]) && isfinite(out[2]);
}

/* The sub-face of the same input triangle across edge e (v[e], v[e+1]) of sub-face f, found
 * in the shell of that edge; TR_NONE if none. */
static tr_status facet_neighbour(rf_ctx *c, uint32_t f, int e, uint32_t *out)
{
  const uint32_t *S = c->sfv + 3 * (size_t)f;
  uint32_t a = S[e], b = S[(e + 1) % 3], t;
  *out = TR_NONE;
  TR_CHECK(tr_ball_find_domain(c->m, S[0], S[1], S[2], &t));
  if (t == TR_NONE)
    return tr_error(TR_ERR_INTERNAL, "refinement: sub-face %u is not a mesh face", f);
  int closed;
  c->stack.n = 0;
  TR_CHECK(tr_shell(c->m, a, b, t, &c->stack, &closed));
  for (size_t i = 0; i < c->stack.n; i++) {
    const uint32_t *v = c->m->tv + 4 * (size_t)c->stack.a[i];
    for (int k = 0; k < 4; k++) {
      if (v[k] == a || v[k] == b)
        continue;
      uint32_t g = rf_subface_of(c, a, b, v[k]);
      if (g != TR_NONE && g != f && c->sftri[g] == c->sftri[f]) {
        *out = g;
        return TR_OK;
      }
    }
  }
  return TR_OK;
}

tr_status rf_facet_split_point(rf_ctx *c, uint32_t f, tr_qpoint **out, uint32_t *where,
                               uint32_t *encseg)
{
  *out = NULL;
  *where = *encseg = TR_NONE;
  const uint32_t g = c->sftri[f];
  const uint32_t *S = c->sfv + 3 * (size_t)f;
  /* the point is a combination of the vertices of one triangle of the facet (any spans
   * its plane exactly): the one whose box holds the sub-face's centroid, in doubles (a
   * choice, not a decision: near f the weights stay small) */
  uint32_t tri = g;
  if (tr_facets_size(&c->fc, g) > 1) {
    double cen[3];
    for (int i = 0; i < 3; i++)
      cen[i] = (c->m->xyz[3 * (size_t)S[0] + i] + c->m->xyz[3 * (size_t)S[1] + i] +
                c->m->xyz[3 * (size_t)S[2] + i]) / 3;
    for (uint32_t i = c->fc.start[g]; i < c->fc.start[g + 1]; i++) {
      const uint32_t *U = c->plc->tris + 3 * (size_t)c->fc.member[i];
      int in = 1;
      for (int j = 0; j < 3 && in; j++) {
        double x0 = c->plc->xyz[3 * (size_t)U[0] + j], x1 = c->plc->xyz[3 * (size_t)U[1] + j],
               x2 = c->plc->xyz[3 * (size_t)U[2] + j];
        in = cen[j] >= fmin(x0, fmin(x1, x2)) && cen[j] <= fmax(x0, fmax(x1, x2));
      }
      if (in) {
        tri = c->fc.member[i];
        break;
      }
    }
  }
  const uint32_t *T = c->plc->tris + 3 * (size_t)tri;
  tr_point pt[3], ps[3];
  for (int i = 0; i < 3; i++) {
    pt[i] = tr_mesh_point(c->m, T[i]);
    ps[i] = tr_mesh_point(c->m, S[i]);
  }
  int drop = tri_drop(c, tri);
  /* target: the sub-face's circumcentre, wherever it falls in the facet (Shewchuk 1998);
   * when it falls outside, the facet walk below meets the sub-segment it encroaches */
  double cc[3], target[3];
  if (!tri_circumcentre(ps[0].d, ps[1].d, ps[2].d, cc))
    return TR_OK;
  bary(pt[0].d, pt[1].d, pt[2].d, cc, drop, target);
  if (!isfinite(target[0]) || !isfinite(target[1]) || fabs(target[0]) > 0x1p30 ||
      fabs(target[1]) > 0x1p30)
    return TR_OK;
  double big = 0, small = 0;
  for (int i = 0; i < 3; i++)
    for (int k = 0; k < 3; k++) {
      big = fmax(big, fabs(pt[i].d[k] - pt[(i + 1) % 3].d[k]));
      small = fmax(small, fabs(ps[i].d[k] - ps[(i + 1) % 3].d[k]));
    }
  /* p = A + w1 (B - A) + w2 (C - A): weights to 2^-m move it by at most 2^-m 2 big, kept
   * under small / 16 so that p is the circumcentre for all purposes (a point near a
   * corner of the sub-face would make a short edge there, and the next split points
   * would pile up at it) */
  int m0 = 5;
  if (small > 0 && big > small)
    m0 += (int)ceil(log2(big / small));
  double want[3];
  for (int i = 0; i < 3; i++)
    want[i] = target[0] * pt[0].d[i] + target[1] * pt[1].d[i] + target[2] * pt[2].d[i];
  tr_qpoint *q = malloc(sizeof *q);
  if (!q)
    return tr_error(TR_ERR_NOMEM, "out of memory for a split point");
  tr_qpoint_init(q);
  mpq_t w[3], x;
  mpq_inits(w[0], w[1], w[2], x, NULL);
  int ok = 0;
  for (int m = m0; m <= 62 && !ok; m++) {
    double sc = ldexp(1.0, m);
    mpq_set_d(w[0], floor(target[0] * sc + 0.5));
    mpq_set_d(w[1], floor(target[1] * sc + 0.5));
    mpq_div_2exp(w[0], w[0], (unsigned long)m);
    mpq_div_2exp(w[1], w[1], (unsigned long)m);
    mpq_set_ui(w[2], 1, 1);
    mpq_sub(w[2], w[2], w[0]);
    mpq_sub(w[2], w[2], w[1]);
    for (int i = 0; i < 3; i++) {
      mpq_set_ui(q->c[i], 0, 1);
      for (int k = 0; k < 3; k++) {
        tr_point_get_q(&pt[k], i, x);
        mpq_mul(x, x, w[k]);
        mpq_add(q->c[i], q->c[i], x);
      }
    }
    tr_qpoint_update(q);
    double dist = 0;
    for (int i = 0; i < 3; i++)
      dist = fmax(dist, fabs(q->near[i] - want[i]));
    ok = dist <= small / 16;
  }
  mpq_clears(w[0], w[1], w[2], x, NULL);
  /* the walk in the facet from f to the sub-face that holds p, exact; it stops at a
   * sub-segment p lies beyond or on */
  tr_point p = tr_pt_q(q);
  uint32_t cur = f;
  tr_status st = TR_OK;
  for (int step = 0; ok && step < 100000; step++) {
    const uint32_t *v = c->sfv + 3 * (size_t)cur;
    tr_point a[3];
    for (int i = 0; i < 3; i++)
      a[i] = tr_mesh_point(c->m, v[i]);
    int s0 = tr_orient2d_proj_p(&a[0], &a[1], &a[2], drop), next = -1;
    for (int e = 0; e < 3 && next < 0; e++) {
      int s = s0 * tr_orient2d_proj_p(&a[e], &a[(e + 1) % 3], &p, drop);
      uint32_t g = rf_subseg_of(c, v[e], v[(e + 1) % 3]);
      if (s < 0 || (s == 0 && g != TR_NONE)) {
        if (g != TR_NONE) {
          *encseg = g;
          ok = 0;
          break;
        }
        next = e;
      }
    }
    if (!ok)
      break;
    if (next < 0) {
      *where = cur;
      break;
    }
    uint32_t nb;
    if ((st = facet_neighbour(c, cur, next, &nb)) != TR_OK || nb == TR_NONE) {
      ok = 0;
      break;
    }
    cur = nb;
  }
  /* the walk crossed inner edges only, so p is in the facet; said exactly all the same */
  if (st == TR_OK && *where != TR_NONE && tr_facets_size(&c->fc, g) > 1 &&
      rf_facet_triangle_of(c, g, &p, tri) == TR_NONE)
    *where = TR_NONE;
  if (st != TR_OK || (*where == TR_NONE && *encseg == TR_NONE)) {
    tr_qpoint_clear(q);
    free(q);
    return st;
  }
  *out = q; /* with *encseg set: where the circumcentre is, for the caller's rules */
  return TR_OK;
}

int rf_volume_above(const tr_point *a, const tr_point *b, const tr_point *c, const tr_point *d,
                    double V)
{
  double u[3], v[3], w[3], th = 0;
  double v6 = 6 * V; /* within 2^-53 of 6V */
  if (diff_ok(a, b, u, &th) && diff_ok(a, c, v, &th) && diff_ok(a, d, w, &th) && isfinite(v6)) {
    double det = det3(u, v, w), perm = per3(u, v, w);
    double x = det - v6;
    if (isfinite(perm) && fabs(x) > filter_bound(3, th) * perm + 0x1p-50 * fabs(v6))
      return x > 0;
  }
  mpq_t A[3], B[3], C[3], D[3], t, s, q;
  for (int i = 0; i < 3; i++)
    mpq_inits(A[i], B[i], C[i], D[i], NULL);
  mpq_inits(t, s, q, NULL);
  get_q3(a, A);
  get_q3(b, B);
  get_q3(c, C);
  get_q3(d, D);
  for (int i = 0; i < 3; i++) {
    mpq_sub(B[i], B[i], A[i]);
    mpq_sub(C[i], C[i], A[i]);
    mpq_sub(D[i], D[i], A[i]);
  }
  qdet3(s, B, C, D, t);
  mpq_set_d(q, V);
  mpq_set_ui(t, 6, 1);
  mpq_mul(q, q, t);
  int r = mpq_cmp(s, q) > 0;
  for (int i = 0; i < 3; i++)
    mpq_clears(A[i], B[i], C[i], D[i], NULL);
  mpq_clears(t, s, q, NULL);
  return r;
}
