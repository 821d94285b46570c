/* Randomized checks of the classifiers on small grids (many degeneracies): against a
 * brute-force rational oracle that clips the segment parameter t in [0,1] with exact
 * mpq values (no library predicate involved), and self-consistency between the
 * classifiers (segment-tet vs segment-triangle on its faces, segment-segment on its
 * edges, point-segment on its vertices). */
#include "check.h"
#include "classify.h"
#include "oracle.h"
#include "qpoint.h"

enum { NPTS = 6 };

static tr_qpoint Q[NPTS];
static double D[NPTS][3];
static tr_point PT[NPTS];

/* point i: a grid double in {0..3}^3, or a rational grid point in {0..9}/3 */
static void random_point(int i, int rational)
{
  for (int k = 0; k < 3; k++) {
    if (rational) {
      mpq_set_si(Q[i].c[k], check_irand(0, 9), 3);
      mpq_canonicalize(Q[i].c[k]);
    } else {
      D[i][k] = (double)check_irand(0, 3);
      mpq_set_d(Q[i].c[k], D[i][k]);
    }
  }
  tr_qpoint_update(&Q[i]);
  PT[i] = rational ? tr_pt_q(&Q[i]) : tr_pt_d(D[i]);
}

/* out = det[q-p; r-p; s-p] */
static void qdet(mpq_t out, const tr_point *p, const tr_point *q, const tr_point *r,
                 const tr_point *s)
{
  mpq_t m[9], x;
  mpq_init(x);
  const tr_point *v[3] = {q, r, s};
  for (int k = 0; k < 9; k++)
    mpq_init(m[k]);
  for (int row = 0; row < 3; row++)
    for (int c = 0; c < 3; c++) {
      tr_point_get_q(v[row], c, m[3 * row + c]);
      tr_point_get_q(p, c, x);
      mpq_sub(m[3 * row + c], m[3 * row + c], x);
    }
  /* rule of Sarrus, unlike the library's cofactors */
  mpq_set_ui(out, 0, 1);
  static const int pos[3][3] = {{0, 4, 8}, {1, 5, 6}, {2, 3, 7}};
  static const int neg[3][3] = {{2, 4, 6}, {0, 5, 7}, {1, 3, 8}};
  for (int t = 0; t < 3; t++) {
    mpq_mul(x, m[pos[t][0]], m[pos[t][1]]);
    mpq_mul(x, x, m[pos[t][2]]);
    mpq_add(out, out, x);
    mpq_mul(x, m[neg[t][0]], m[neg[t][1]]);
    mpq_mul(x, x, m[neg[t][2]]);
    mpq_sub(out, out, x);
  }
  for (int k = 0; k < 9; k++)
    mpq_clear(m[k]);
  mpq_clear(x);
}

/* 2D orient of projections dropping axis k (cyclic kept axes) */
static void qorient2(mpq_t out, const tr_point *a, const tr_point *b, const tr_point *c, int k)
{
  mpq_t v[6], x;
  const tr_point *p[3] = {a, b, c};
  for (int i = 0; i < 6; i++)
    mpq_init(v[i]);
  mpq_init(x);
  for (int i = 0; i < 3; i++) {
    tr_point_get_q(p[i], (k + 1) % 3, v[2 * i]);
    tr_point_get_q(p[i], (k + 2) % 3, v[2 * i + 1]);
  }
  for (int i = 1; i < 3; i++) {
    mpq_sub(v[2 * i], v[2 * i], v[0]);
    mpq_sub(v[2 * i + 1], v[2 * i + 1], v[1]);
  }
  mpq_mul(out, v[2], v[5]);
  mpq_mul(x, v[3], v[4]);
  mpq_sub(out, out, x);
  for (int i = 0; i < 6; i++)
    mpq_clear(v[i]);
  mpq_clear(x);
}

/* ---- the clip oracle: constraints f_i(t) = fa_i + t (fb_i - fa_i) >= 0, t in [lo,hi] ---- */
typedef struct oclip {
  int m;
  mpq_t fa[4], fb[4];
  mpq_t lo, hi;
  int empty;
} oclip;

static void oclip_init(oclip *c, int m)
{
  c->m = m;
  for (int i = 0; i < 4; i++)
    mpq_init(c->fa[i]), mpq_init(c->fb[i]);
  mpq_init(c->lo), mpq_init(c->hi);
  mpq_set_ui(c->lo, 0, 1);
  mpq_set_ui(c->hi, 1, 1);
  c->empty = 0;
}
static void oclip_clear(oclip *c)
{
  for (int i = 0; i < 4; i++)
    mpq_clear(c->fa[i]), mpq_clear(c->fb[i]);
  mpq_clear(c->lo), mpq_clear(c->hi);
}
/* restrict [lo,hi] by fa + t (fb - fa) >= 0 (or == 0 when eq) */
static void oclip_add(oclip *c, const mpq_t fa, const mpq_t fb, int eq)
{
  if (c->empty)
    return;
  int sa = mpq_sgn(fa), sb = mpq_sgn(fb);
  if (eq) {
    if (sa == 0 && sb == 0)
      return;
    if (mpq_equal(fa, fb)) {
      c->empty = 1;
      return;
    }
  } else {
    if (sa < 0 && sb < 0) {
      c->empty = 1;
      return;
    }
    if (sa >= 0 && sb >= 0)
      return;
  }
  mpq_t t;
  mpq_init(t);
  mpq_sub(t, fa, fb);
  mpq_div(t, fa, t);
  if (eq || sa < 0) /* raises lo */
    if (mpq_cmp(t, c->lo) > 0)
      mpq_set(c->lo, t);
  if (eq || sb < 0) /* lowers hi */
    if (mpq_cmp(t, c->hi) < 0)
      mpq_set(c->hi, t);
  if (mpq_cmp(c->lo, c->hi) > 0)
    c->empty = 1;
  mpq_clear(t);
}
static int oclip_zmask(const oclip *c, const mpq_t t)
{
  mpq_t v;
  mpq_init(v);
  int z = 0;
  for (int i = 0; i < c->m; i++) {
    mpq_sub(v, c->fb[i], c->fa[i]);
    mpq_mul(v, v, t);
    mpq_add(v, v, c->fa[i]);
    z |= (mpq_sgn(v) == 0) << i;
  }
  mpq_clear(v);
  return z;
}
static int seg_of(const mpq_t t)
{
  if (mpq_sgn(t) == 0)
    return TR_SEG_A;
  if (mpq_cmp_ui(t, 1, 1) == 0)
    return TR_SEG_B;
  return TR_SEG_IN;
}
static tr_hit typed(int z, int m, int seg)
{
  int k = 0, out[4], no = 0, in1 = -1;
  for (int i = 0; i < m; i++) {
    if (z >> i & 1)
      k++, in1 = i;
    else
      out[no++] = i;
  }
  tr_hit h = {0, 0, (uint8_t)seg};
  if (m == 4) {
    if (k == 0) h.type = TR_INT;
    else if (k == 1) h.type = TR_FAC, h.code = (uint8_t)in1;
    else if (k == 2) h.type = TR_EDG, h.code = (uint8_t)tr_ecode(out[0], out[1]);
    else h.type = TR_NOD, h.code = (uint8_t)out[0];
  } else {
    if (k == 0) h.type = TR_FAC, h.code = 3;
    else if (k == 1) h.type = TR_EDG, h.code = (uint8_t)tr_ecode(out[0], out[1]);
    else h.type = TR_NOD, h.code = (uint8_t)out[0];
  }
  return h;
}
static tr_isect oclip_result(const oclip *c)
{
  tr_isect r = {0, {{0, 0, 0}, {0, 0, 0}}};
  if (c->empty)
    return r;
  r.n = mpq_equal(c->lo, c->hi) ? 1 : 2;
  r.end[0] = typed(oclip_zmask(c, c->lo), c->m, seg_of(c->lo));
  if (r.n == 2)
    r.end[1] = typed(oclip_zmask(c, c->hi), c->m, seg_of(c->hi));
  return r;
}

static tr_isect oracle_seg_tet(const tr_point *a, const tr_point *b, const tr_point *const t[4])
{
  oclip c;
  oclip_init(&c, 4);
  for (int i = 0; i < 4; i++) {
    const tr_point *p[4] = {t[0], t[1], t[2], t[3]};
    p[i] = a;
    qdet(c.fa[i], p[0], p[1], p[2], p[3]);
    p[i] = b;
    qdet(c.fb[i], p[0], p[1], p[2], p[3]);
  }
  for (int i = 0; i < 4; i++)
    oclip_add(&c, c.fa[i], c.fb[i], 0);
  tr_isect r = oclip_result(&c);
  oclip_clear(&c);
  return r;
}

static tr_isect oracle_seg_tri(const tr_point *a, const tr_point *b, const tr_point *const t[3])
{
  oclip c;
  oclip_init(&c, 3);
  mpq_t ha, hb, n;
  mpq_init(ha), mpq_init(hb), mpq_init(n);
  qdet(ha, t[0], t[1], t[2], a);
  qdet(hb, t[0], t[1], t[2], b);
  oclip_add(&c, ha, hb, 1);
  int k = 0, s = 0;
  for (k = 0; k < 3; k++) {
    qorient2(n, t[0], t[1], t[2], k);
    if ((s = mpq_sgn(n)) != 0)
      break;
  }
  for (int i = 0; i < 3; i++) {
    qorient2(c.fa[i], t[(i + 1) % 3], t[(i + 2) % 3], a, k);
    qorient2(c.fb[i], t[(i + 1) % 3], t[(i + 2) % 3], b, k);
    if (s < 0)
      mpq_neg(c.fa[i], c.fa[i]), mpq_neg(c.fb[i], c.fb[i]);
    oclip_add(&c, c.fa[i], c.fb[i], 0);
  }
  tr_isect r = oclip_result(&c);
  oclip_clear(&c);
  mpq_clear(ha), mpq_clear(hb), mpq_clear(n);
  return r;
}

static int same(tr_isect x, tr_isect y)
{
  if (x.n != y.n)
    return 0;
  for (int i = 0; i < x.n; i++)
    if (x.end[i].type != y.end[i].type || x.end[i].code != y.end[i].code ||
        x.end[i].on_seg != y.end[i].on_seg)
      return 0;
  return 1;
}

static void show(const char *what, tr_isect r)
{
  fprintf(stderr, "  %s: n=%d [%d %d %d] [%d %d %d]\n", what, r.n, r.end[0].type, r.end[0].code,
          r.end[0].on_seg, r.end[1].type, r.end[1].code, r.end[1].on_seg);
}

static void init_points(void)
{
  for (int i = 0; i < NPTS; i++)
    tr_qpoint_init(&Q[i]);
}
static void clear_points(void)
{
  for (int i = 0; i < NPTS; i++)
    tr_qpoint_clear(&Q[i]);
}

static void seg_tet_matches_oracle(void)
{
  init_points();
  int nonempty = 0;
  for (int it = 0; it < 20000; it++) {
    for (int i = 0; i < NPTS; i++)
      random_point(i, it % 4 == 3 && i % 2);
    const tr_point *t[4] = {&PT[0], &PT[1], &PT[2], &PT[3]};
    int o = tr_orient3d_p(t[0], t[1], t[2], t[3]);
    if (o == 0 || tr_equal_p(&PT[4], &PT[5]))
      continue;
    if (o < 0)
      t[0] = &PT[1], t[1] = &PT[0];
    tr_isect got = tr_classify_segment_tet(&PT[4], &PT[5], t);
    tr_isect want = oracle_seg_tet(&PT[4], &PT[5], t);
    nonempty += want.n > 0;
    CHECK(same(got, want), "iteration %d", it);
    if (!same(got, want))
      show("got", got), show("want", want);
  }
  CHECK(nonempty > 2000, "enough intersecting cases (%d)", nonempty);
  clear_points();
}

/* tr_classify_segment_tet_o (points by number, orientations from a callback, the ends
 * that are tet vertices named) answers as tr_classify_segment_tet on the points, also
 * when a or b is a vertex of the tet (edge recovery's pipes start at one), and as the
 * oracle. */
typedef struct six {
  const tr_point *p[6];
} six;
static int six_orient(void *ud, int p, int q, int r, int s)
{
  const six *x = ud;
  return tr_orient3d_p(x->p[p], x->p[q], x->p[r], x->p[s]);
}

static void seg_tet_by_number_matches_points(void)
{
  init_points();
  int shared = 0, nonempty = 0;
  for (int it = 0; it < 20000; it++) {
    for (int i = 0; i < NPTS; i++)
      random_point(i, it % 4 == 3 && i % 2);
    const tr_point *t[4] = {&PT[0], &PT[1], &PT[2], &PT[3]};
    int o = tr_orient3d_p(t[0], t[1], t[2], t[3]);
    if (o == 0)
      continue;
    if (o < 0)
      t[0] = &PT[1], t[1] = &PT[0];
    const tr_point *a = &PT[4], *b = &PT[5];
    int sa = -1, sb = -1;
    if (it % 3 == 1)
      sa = it % 4, a = t[sa];
    else if (it % 3 == 2)
      sb = (it + 1) % 4, b = t[sb];
    if (tr_equal_p(a, b))
      continue;
    six x = {{t[0], t[1], t[2], t[3], a, b}};
    tr_isect got = tr_classify_segment_tet_o(six_orient, &x, sa, sb);
    tr_isect want = tr_classify_segment_tet(a, b, t);
    tr_isect ref = oracle_seg_tet(a, b, t);
    shared += sa >= 0 || sb >= 0;
    nonempty += want.n > 0;
    CHECK(same(got, want) && same(want, ref), "iteration %d (a = vertex %d, b = vertex %d)", it,
          sa, sb);
    if (!same(got, want))
      show("by number", got), show("on points", want);
  }
  CHECK(shared > 5000 && nonempty > 4000, "enough cases: %d with a shared vertex, %d meeting",
        shared, nonempty);
  clear_points();
}

static void seg_tri_matches_oracle(void)
{
  init_points();
  int coplanar = 0;
  for (int it = 0; it < 20000; it++) {
    for (int i = 0; i < 5; i++)
      random_point(i, it % 4 == 3 && i % 2);
    const tr_point *t[3] = {&PT[0], &PT[1], &PT[2]};
    int deg = 1;
    for (int k = 0; k < 3; k++)
      deg &= tr_orient2d_proj_p(t[0], t[1], t[2], k) == 0;
    if (deg || tr_equal_p(&PT[3], &PT[4]))
      continue;
    if (it % 3 == 0) { /* force b into the plane: a combination of the vertices */
      oracle_lerp(&Q[5], t[0], t[1], check_irand(-3, 6), 3);
      tr_point m = tr_pt_q(&Q[5]);
      tr_qpoint tmp;
      tr_qpoint_init(&tmp);
      tr_qpoint_set_point(&tmp, &m);
      tr_point mm = tr_pt_q(&tmp);
      oracle_lerp(&Q[5], &mm, t[2], check_irand(-3, 6), 3);
      tr_qpoint_clear(&tmp);
      PT[4] = tr_pt_q(&Q[5]);
      if (it % 2 == 0) { /* and a too */
        oracle_lerp(&Q[3], t[0], t[2], check_irand(-3, 6), 2);
        PT[3] = tr_pt_q(&Q[3]);
      }
      if (tr_equal_p(&PT[3], &PT[4]))
        continue;
    }
    tr_isect got = tr_classify_segment_triangle(&PT[3], &PT[4], t[0], t[1], t[2]);
    tr_isect want = oracle_seg_tri(&PT[3], &PT[4], t);
    coplanar += tr_orient3d_p(t[0], t[1], t[2], &PT[3]) == 0 &&
                tr_orient3d_p(t[0], t[1], t[2], &PT[4]) == 0 && want.n == 2;
    CHECK(same(got, want), "iteration %d", it);
    if (!same(got, want))
      show("got", got), show("want", want);
  }
  CHECK(coplanar > 500, "enough coplanar overlaps (%d)", coplanar);
  clear_points();
}

/* segment-segment oracle: parameters along ab of the common part, in mpq vectors */
static tr_isect oracle_seg_seg(const tr_point *a, const tr_point *b, const tr_point *c,
                               const tr_point *d)
{
  tr_isect r = {0, {{0, 0, 0}, {0, 0, 0}}};
  mpq_t A[3], U[3], C[3], V[3], W[3], x, y, n2, t0, t1, s, w;
  mpq_t *all[] = {A, U, C, V, W};
  for (int j = 0; j < 5; j++)
    for (int i = 0; i < 3; i++)
      mpq_init(all[j][i]);
  mpq_init(x), mpq_init(y), mpq_init(n2), mpq_init(t0), mpq_init(t1), mpq_init(s), mpq_init(w);
  for (int i = 0; i < 3; i++) {
    tr_point_get_q(a, i, A[i]);
    tr_point_get_q(b, i, U[i]);
    mpq_sub(U[i], U[i], A[i]); /* U = b - a */
    tr_point_get_q(c, i, C[i]);
    tr_point_get_q(d, i, V[i]);
    mpq_sub(V[i], V[i], C[i]); /* V = d - c */
    mpq_sub(C[i], C[i], A[i]); /* C = c - a */
  }
  /* W = U x V */
  for (int i = 0; i < 3; i++) {
    mpq_mul(x, U[(i + 1) % 3], V[(i + 2) % 3]);
    mpq_mul(y, U[(i + 2) % 3], V[(i + 1) % 3]);
    mpq_sub(W[i], x, y);
  }
  mpq_set_ui(n2, 0, 1);
  for (int i = 0; i < 3; i++)
    mpq_mul(x, W[i], W[i]), mpq_add(n2, n2, x);
  /* coplanarity: C . W == 0 */
  mpq_set_ui(s, 0, 1);
  for (int i = 0; i < 3; i++)
    mpq_mul(x, C[i], W[i]), mpq_add(s, s, x);
  mpq_set_ui(y, 0, 1); /* |U|^2 */
  for (int i = 0; i < 3; i++)
    mpq_mul(x, U[i], U[i]), mpq_add(y, y, x);
  int code0 = -1, code1 = -1;
  if (mpq_sgn(n2) == 0) {
    /* parallel: collinear iff C x U == 0 */
    int col = 1;
    for (int i = 0; i < 3; i++) {
      mpq_mul(x, C[(i + 1) % 3], U[(i + 2) % 3]);
      mpq_mul(w, C[(i + 2) % 3], U[(i + 1) % 3]);
      col &= mpq_equal(x, w) != 0;
    }
    if (col) {
      /* tc = C.U / |U|^2, td = (C+V).U / |U|^2 */
      mpq_set_ui(t0, 0, 1), mpq_set_ui(t1, 0, 1);
      for (int i = 0; i < 3; i++) {
        mpq_mul(x, C[i], U[i]), mpq_add(t0, t0, x);
        mpq_add(w, C[i], V[i]), mpq_mul(x, w, U[i]), mpq_add(t1, t1, x);
      }
      mpq_div(t0, t0, y), mpq_div(t1, t1, y);
      int cfirst = mpq_cmp(t0, t1) < 0;
      mpq_t *lo = cfirst ? &t0 : &t1, *hi = cfirst ? &t1 : &t0;
      code0 = cfirst ? 0 : 1;
      code1 = cfirst ? 1 : 0;
      mpq_set_ui(x, 0, 1), mpq_set_ui(w, 1, 1);
      if (mpq_cmp(*lo, x) < 0)
        mpq_set(*lo, x), code0 = -1; /* start at a */
      if (mpq_cmp(*hi, w) > 0)
        mpq_set(*hi, w), code1 = -1;
      if (mpq_cmp(*lo, *hi) <= 0) {
        r.n = mpq_equal(*lo, *hi) ? 1 : 2;
        int sl = seg_of(*lo), sh = seg_of(*hi);
        /* an end of ab that coincides with c or d is that node */
        r.end[0].type = code0 >= 0 ? TR_NOD : TR_EDG;
        r.end[0].code = (uint8_t)(code0 >= 0 ? code0 : tr_ecode(0, 1));
        r.end[0].on_seg = (uint8_t)sl;
        r.end[1].type = code1 >= 0 ? TR_NOD : TR_EDG;
        r.end[1].code = (uint8_t)(code1 >= 0 ? code1 : tr_ecode(0, 1));
        r.end[1].on_seg = (uint8_t)sh;
        if (r.n == 1) { /* a single point: whichever description is a node wins */
          if (code0 < 0 && code1 >= 0)
            r.end[0].type = TR_NOD, r.end[0].code = (uint8_t)code1;
          r.end[1] = (tr_hit){0, 0, 0};
        }
      }
    }
  } else if (mpq_sgn(s) == 0) {
    /* s = ((C x V) . W) / n2 along ab, w = ((C x U) . W) / n2 along cd */
    mpq_set_ui(t0, 0, 1), mpq_set_ui(t1, 0, 1);
    for (int i = 0; i < 3; i++) {
      mpq_mul(x, C[(i + 1) % 3], V[(i + 2) % 3]);
      mpq_mul(w, C[(i + 2) % 3], V[(i + 1) % 3]);
      mpq_sub(x, x, w);
      mpq_mul(x, x, W[i]);
      mpq_add(t0, t0, x);
      mpq_mul(x, C[(i + 1) % 3], U[(i + 2) % 3]);
      mpq_mul(w, C[(i + 2) % 3], U[(i + 1) % 3]);
      mpq_sub(x, x, w);
      mpq_mul(x, x, W[i]);
      mpq_add(t1, t1, x);
    }
    mpq_div(t0, t0, n2), mpq_div(t1, t1, n2);
    if (mpq_sgn(t0) >= 0 && mpq_cmp_ui(t0, 1, 1) <= 0 && mpq_sgn(t1) >= 0 &&
        mpq_cmp_ui(t1, 1, 1) <= 0) {
      r.n = 1;
      r.end[0].on_seg = (uint8_t)seg_of(t0);
      r.end[0].type = (uint8_t)(seg_of(t1) == TR_SEG_IN ? TR_EDG : TR_NOD);
      r.end[0].code = (uint8_t)(seg_of(t1) == TR_SEG_A ? 0 : seg_of(t1) == TR_SEG_B ? 1 : tr_ecode(0, 1));
    }
  }
  for (int j = 0; j < 5; j++)
    for (int i = 0; i < 3; i++)
      mpq_clear(all[j][i]);
  mpq_clear(x), mpq_clear(y), mpq_clear(n2), mpq_clear(t0), mpq_clear(t1), mpq_clear(s),
      mpq_clear(w);
  return r;
}

static void seg_seg_matches_oracle(void)
{
  init_points();
  int hits = 0, overlaps = 0;
  for (int it = 0; it < 30000; it++) {
    for (int i = 0; i < 4; i++)
      random_point(i, it % 4 == 3 && i % 2);
    if (it % 2) /* flatten to z = 0 for many coplanar pairs */
      for (int i = 0; i < 4; i++) {
        mpq_set_ui(Q[i].c[2], 0, 1);
        D[i][2] = 0;
        tr_qpoint_update(&Q[i]);
      }
    if (it % 5 == 0) { /* collinear: c, d on line ab */
      oracle_lerp(&Q[2], &PT[0], &PT[1], check_irand(-3, 6), 3);
      oracle_lerp(&Q[3], &PT[0], &PT[1], check_irand(-3, 6), 3);
      PT[2] = tr_pt_q(&Q[2]), PT[3] = tr_pt_q(&Q[3]);
    }
    if (tr_equal_p(&PT[0], &PT[1]) || tr_equal_p(&PT[2], &PT[3]))
      continue;
    tr_isect got = tr_classify_segment_segment(&PT[0], &PT[1], &PT[2], &PT[3]);
    tr_isect want = oracle_seg_seg(&PT[0], &PT[1], &PT[2], &PT[3]);
    hits += want.n > 0;
    overlaps += want.n == 2;
    CHECK(same(got, want), "iteration %d", it);
    if (!same(got, want))
      show("got", got), show("want", want);
  }
  CHECK(hits > 3000 && overlaps > 500, "enough hits (%d) and overlaps (%d)", hits, overlaps);
  clear_points();
}

/* segment-tet agrees with segment-triangle on its faces, segment-segment on its edges
 * and point-segment at its vertices. */
static void seg_tet_consistent_with_faces(void)
{
  init_points();
  for (int it = 0; it < 10000; it++) {
    for (int i = 0; i < NPTS; i++)
      random_point(i, it % 4 == 3 && i % 2);
    const tr_point *t[4] = {&PT[0], &PT[1], &PT[2], &PT[3]};
    int o = tr_orient3d_p(t[0], t[1], t[2], t[3]);
    const tr_point *a = &PT[4], *b = &PT[5];
    if (o == 0 || tr_equal_p(a, b))
      continue;
    if (o < 0)
      t[0] = &PT[1], t[1] = &PT[0];
    tr_isect r = tr_classify_segment_tet(a, b, t);
    tr_isect f[4];
    int faces_hit = 0;
    for (int k = 0; k < 4; k++) {
      f[k] = tr_classify_segment_triangle(a, b, t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4]);
      faces_hit += f[k].n > 0;
    }
    if (r.n == 0)
      CHECK(faces_hit == 0, "disjoint from the tet but touching a face (iteration %d)", it);
    if (faces_hit == 0 && r.n > 0)
      CHECK(r.n == 2 && r.end[0].type == TR_INT && r.end[1].type == TR_INT,
            "inside without touching a face (iteration %d)", it);
    for (int e = 0; e < r.n; e++) {
      tr_hit h = r.end[e];
      if (h.type == TR_FAC) {
        int found = 0;
        for (int j = 0; j < f[h.code].n; j++)
          found |= f[h.code].end[j].type == TR_FAC && f[h.code].end[j].on_seg == h.on_seg;
        CHECK(found, "FAC %d end not seen by the face triangle (iteration %d)", h.code, it);
      } else if (h.type == TR_EDG) {
        tr_isect s = tr_classify_segment_segment(a, b, t[tr_ecode_start(h.code)],
                                                 t[tr_ecode_end(h.code)]);
        int found = 0;
        for (int j = 0; j < s.n; j++)
          found |= s.end[j].type == TR_EDG && s.end[j].on_seg == h.on_seg;
        CHECK(found, "EDG %d end not seen on the edge (iteration %d)", h.code, it);
      } else if (h.type == TR_NOD) {
        tr_hit p = tr_classify_point_segment(t[h.code], a, b);
        int want = h.on_seg == TR_SEG_A ? TR_NOD : h.on_seg == TR_SEG_B ? TR_NOD : TR_EDG;
        CHECK(p.type == want, "NOD %d end not on the segment (iteration %d)", h.code, it);
      } else
        CHECK(h.type == TR_INT && h.on_seg != TR_SEG_IN, "INT only at a or b (iteration %d)", it);
    }
  }
  clear_points();
}

/* point-triangle agrees with the orientation signs (barycentric test in the oracle) */
static void point_triangle_matches_orient(void)
{
  init_points();
  int on = 0;
  for (int it = 0; it < 20000; it++) {
    for (int i = 0; i < 4; i++)
      random_point(i, it % 4 == 3 && i % 2);
    const tr_point *t[3] = {&PT[0], &PT[1], &PT[2]};
    if (it % 2) { /* p in the plane */
      tr_qpoint tmp;
      tr_qpoint_init(&tmp);
      oracle_lerp(&tmp, t[0], t[1], check_irand(-2, 4), 2);
      tr_point m = tr_pt_q(&tmp);
      oracle_lerp(&Q[3], &m, t[2], check_irand(-2, 4), 2);
      PT[3] = tr_pt_q(&Q[3]);
      tr_qpoint_clear(&tmp);
    }
    const tr_point *p = &PT[3];
    int deg = 1;
    for (int k = 0; k < 3; k++)
      deg &= tr_orient2d_proj_p(t[0], t[1], t[2], k) == 0;
    if (deg)
      continue;
    tr_hit h = tr_classify_point_triangle(p, t[0], t[1], t[2]);
    /* oracle: the zero-length segment p-p against the triangle */
    oclip c;
    oclip_init(&c, 3);
    mpq_t ha, n;
    mpq_init(ha), mpq_init(n);
    qdet(ha, t[0], t[1], t[2], p);
    int k = 0, s = 0;
    for (k = 0; k < 3; k++) {
      qorient2(n, t[0], t[1], t[2], k);
      if ((s = mpq_sgn(n)) != 0)
        break;
    }
    tr_hit want = {TR_DEG, 0, 0};
    if (mpq_sgn(ha) == 0) {
      int z = 0, outside = 0;
      for (int i = 0; i < 3; i++) {
        qorient2(n, t[(i + 1) % 3], t[(i + 2) % 3], p, k);
        int v = mpq_sgn(n) * s;
        outside |= v < 0;
        z |= (v == 0) << i;
      }
      if (!outside)
        want = typed(z, 3, 0), on++;
    }
    CHECK(h.type == want.type && h.code == want.code, "iteration %d: got %d/%d want %d/%d", it,
          h.type, h.code, want.type, want.code);
    mpq_clear(ha), mpq_clear(n);
    oclip_clear(&c);
  }
  CHECK(on > 2000, "enough points on the triangle (%d)", on);
  clear_points();
}

int main(int argc, char **argv)
{
  static const check_case cases[] = {
      {"seg_tet_matches_oracle", seg_tet_matches_oracle},
      {"seg_tet_by_number_matches_points", seg_tet_by_number_matches_points},
      {"seg_tri_matches_oracle", seg_tri_matches_oracle},
      {"seg_seg_matches_oracle", seg_seg_matches_oracle},
      {"seg_tet_consistent_with_faces", seg_tet_consistent_with_faces},
      {"point_triangle_matches_orient", point_triangle_matches_orient},
  };
  int r = check_main(argc, argv, cases, (int)(sizeof cases / sizeof cases[0]));
  tr_exact_scratch_free();
  return r;
}
