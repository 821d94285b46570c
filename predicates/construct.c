/* Exact constructions of Steiner points, in homogeneous integer coordinates.
 *
 * Each input point is taken as an integer 4-vector h = (X, Y, Z, W), W > 0
 * (tr_point_get_hom). Every point of the line through a and b is a combination
 * alpha h_a + beta h_b, so a construction only has to find the one combination that
 * satisfies a linear condition L(h) = 0:
 *   line-plane: L(h) = N . h, the plane's homogeneous equation;
 *   line-line:  L(h) = the 2D line through c, d (in a coordinate projection) . h.
 * With alpha = L(h_b), beta = -L(h_a) the condition holds identically
 * (L(alpha h_a + beta h_b) = L(h_b) L(h_a) - L(h_a) L(h_b) = 0), and the result's W is
 * zero exactly when the line is parallel to the plane / other line. Only integer
 * multiplications are needed; one gcd per coordinate canonicalises the result. The
 * double box and nearest rounding then come from tr_qpoint_update.
 *
 * The integer temporaries are thread-local and kept between calls: with fresh ones,
 * malloc/realloc took about a quarter of the instructions (callgrind).
 */
#include "construct.h"

#include "qpoint.h"

enum { NT = 40 };
static _Thread_local mpz_t scratch[NT];
static _Thread_local int scratch_ready;

static mpz_t *temps(void)
{
  if (!scratch_ready) {
    for (int i = 0; i < NT; i++)
      mpz_init(scratch[i]);
    scratch_ready = 1;
  }
  return scratch;
}

void tr_construct_scratch_free(void)
{
  if (!scratch_ready)
    return;
  for (int i = 0; i < NT; i++)
    mpz_clear(scratch[i]);
  scratch_ready = 0;
}

/* out = alpha h_a + beta h_b as a rational point; returns -1 if its W is 0. */
static int combine(const mpz_t *ha, const mpz_t *hb, mpz_srcptr alpha, mpz_srcptr beta,
                   mpz_t *tmp, tr_qpoint *out)
{
  mpz_mul(tmp[3], alpha, ha[3]);
  mpz_addmul(tmp[3], beta, hb[3]);
  if (mpz_sgn(tmp[3]) == 0)
    return -1;
  for (int i = 0; i < 3; i++) {
    mpz_mul(tmp[i], alpha, ha[i]);
    mpz_addmul(tmp[i], beta, hb[i]);
  }
  /* write only after reading everything: out may alias an input */
  for (int i = 0; i < 3; i++) {
    mpz_set(mpq_numref(out->c[i]), tmp[i]);
    mpz_set(mpq_denref(out->c[i]), tmp[3]);
    mpq_canonicalize(out->c[i]);
  }
  tr_qpoint_update(out);
  return 0;
}

/* The plane through p, q, r as N . (X, Y, Z, W) = 0: with the scaled edge vectors
 * u = X_q W_p - X_p W_q, v = X_r W_p - X_p W_r (positive multiples of q - p, r - p),
 * n = u x v is a positive multiple of the normal, and for x = X / W,
 * n . (x - p) = 0  <=>  W_p (n . X) - (n . X_p) W = 0. */
int tr_construct_line_plane(const tr_point *a, const tr_point *b, const tr_point *p,
                            const tr_point *q, const tr_point *r, tr_qpoint *out)
{
  mpz_t *t = temps();
  mpz_t *ha = t, *hb = t + 4, *hp = t + 8, *hq = t + 12, *hr = t + 16, *u = t + 20,
        *v = t + 23, *n = t + 26, *N = t + 29, *s = t + 33, *tmp = t + 35;
  tr_point_get_hom(a, ha, ha[3]);
  tr_point_get_hom(b, hb, hb[3]);
  tr_point_get_hom(p, hp, hp[3]);
  tr_point_get_hom(q, hq, hq[3]);
  tr_point_get_hom(r, hr, hr[3]);
  for (int i = 0; i < 3; i++) {
    mpz_mul(u[i], hq[i], hp[3]);
    mpz_submul(u[i], hp[i], hq[3]);
    mpz_mul(v[i], hr[i], hp[3]);
    mpz_submul(v[i], hp[i], hr[3]);
  }
  for (int i = 0; i < 3; i++) {
    int j = (i + 1) % 3, k = (i + 2) % 3;
    mpz_mul(n[i], u[j], v[k]);
    mpz_submul(n[i], u[k], v[j]);
  }
  mpz_set_ui(N[3], 0);
  for (int i = 0; i < 3; i++) {
    mpz_mul(N[i], n[i], hp[3]);
    mpz_submul(N[3], n[i], hp[i]);
  }
  /* s[0] = N . h_a, s[1] = N . h_b */
  for (int k = 0; k < 2; k++) {
    const mpz_t *h = k ? hb : ha;
    mpz_set_ui(s[k], 0);
    for (int i = 0; i < 4; i++)
      mpz_addmul(s[k], N[i], h[i]);
  }
  mpz_neg(s[0], s[0]); /* beta = -N . h_a */
  int ret = combine(ha, hb, s[1], s[0], tmp, out);
  return ret;
}

/* Lines ab and cd, coplanar. The direction cross product n = (b - a) x (d - c) (up to a
 * positive factor) is nonzero iff they are not parallel; projecting along the axis k of
 * the largest |n_k| (compared exactly; any nonzero n_k would be exact, the largest keeps
 * the projection well away from degenerate) keeps both lines distinct and crossing. In
 * that projection the 2D homogeneous line through c and d is l = c2 x d2 with
 * c2 = (X_u, X_v, W), and l . (u, v, W) = 0 is the linear condition. */
int tr_construct_line_line(const tr_point *a, const tr_point *b, const tr_point *c,
                           const tr_point *d, tr_qpoint *out)
{
  if (tr_orient3d_p(a, b, c, d) != 0)
    return -1;
  mpz_t *t = temps();
  mpz_t *ha = t, *hb = t + 4, *hc = t + 8, *hd = t + 12, *e = t + 16, *f = t + 19,
        *n = t + 22, *l = t + 25, *s = t + 28, *tmp = t + 30;
  tr_point_get_hom(a, ha, ha[3]);
  tr_point_get_hom(b, hb, hb[3]);
  tr_point_get_hom(c, hc, hc[3]);
  tr_point_get_hom(d, hd, hd[3]);
  for (int i = 0; i < 3; i++) {
    mpz_mul(e[i], hb[i], ha[3]);
    mpz_submul(e[i], ha[i], hb[3]);
    mpz_mul(f[i], hd[i], hc[3]);
    mpz_submul(f[i], hc[i], hd[3]);
  }
  int k = -1;
  for (int i = 0; i < 3; i++) {
    int j = (i + 1) % 3, h = (i + 2) % 3;
    mpz_mul(n[i], e[j], f[h]);
    mpz_submul(n[i], e[h], f[j]);
    if (mpz_sgn(n[i]) != 0 && (k < 0 || mpz_cmpabs(n[i], n[k]) > 0))
      k = i;
  }
  int ret = -1;
  if (k >= 0) {
    const int iu = (k + 1) % 3, iv = (k + 2) % 3;
    /* l = (cu, cv, cw) x (du, dv, dw) */
    mpz_mul(l[0], hc[iv], hd[3]);
    mpz_submul(l[0], hc[3], hd[iv]);
    mpz_mul(l[1], hc[3], hd[iu]);
    mpz_submul(l[1], hc[iu], hd[3]);
    mpz_mul(l[2], hc[iu], hd[iv]);
    mpz_submul(l[2], hc[iv], hd[iu]);
    for (int q = 0; q < 2; q++) {
      const mpz_t *h = q ? hb : ha;
      mpz_mul(s[q], l[0], h[iu]);
      mpz_addmul(s[q], l[1], h[iv]);
      mpz_addmul(s[q], l[2], h[3]);
    }
    mpz_neg(s[0], s[0]);
    ret = combine(ha, hb, s[1], s[0], tmp, out);
  }
  return ret;
}
