/* Exact intersection classifiers (see classify.h for the codes).
 *
 * Only exact orientation predicates on the given points are used; no point is ever
 * constructed. The clipping of a segment by a triangle (in its plane) or by a
 * tetrahedron is a Cyrus-Beck clip done with signs only:
 *
 *   The simplex is the intersection of half-spaces g_i >= 0, g_i affine, g_i = 0 on
 *   facet i (the one opposite vertex i). Along ab, g_i(a + t(b-a)) is affine in t, so
 *   each constraint whose signs at a and b differ ("crossing" constraint) either enters
 *   (g_i(a) < 0 <= g_i(b)) or exits (g_i(a) >= 0 > g_i(b)) at
 *   t_i = g_i(a) / D_i, D_i = g_i(a) - g_i(b). The part of ab inside is [max of a and
 *   the entering t_i, min of b and the exiting t_i]. Comparing two crossing parameters:
 *     t_i - t_j = N_ij / (D_i D_j),  N_ij = g_i(b) g_j(a) - g_i(a) g_j(b).
 *   N_ij is a product of orientation values, but it has a one-predicate form: facets i
 *   and j share the vertices k, l (the other two), both g vanish at t_k, so
 *   g_i(x) = n_i.(x - t_k) and by the Binet-Cauchy identity
 *     N_ij = (n_i x n_j).((b - t_k) x (a - t_k)).
 *   n_i x n_j is parallel to the shared edge: n_i x n_j = c (t_l - t_k), hence
 *     N_ij = c * orient3d(t_k, t_l, b, a).
 *   The sign of c is the parity of the permutation (i, j, k, l) for a positively
 *   oriented tet (check on t = (0, e1, e2, e3): g_0 = 1-x-y-z, g_i = x_i, and
 *   n_1 x n_2 = e3 = t_3 - t_0 for (1,2,0,3), an even permutation; the sign cannot
 *   change over the connected set of positive tets since c never vanishes there).
 *   In 2D (a triangle, projected to a coordinate plane where it has orientation sign s,
 *   f_i(x) = s orient2d(t_{i+1}, t_{i+2}, x)), the same identity with the 2D cross
 *   product gives, for j = i+1 and shared vertex k = i+2 (indices mod 3):
 *     n_i x n_j = orient2d(t_0, t_1, t_2),  N_ij = -s-signed orient2d(a, b, t_k),
 *   i.e. sign N_{i,i+1} = -s * sign orient2d(a, b, t_{i+2}).
 * An end of the clipped part lies on facet j iff g_j is zero there: at a or b that is
 * read off directly; at a crossing point X_i inside ab it holds for j = i, for every
 * crossing j with t_j = t_i, and for every j with g_j(a) = g_j(b) = 0 (ab in facet j);
 * no other j can vanish at an inner point of ab since g_j is affine along it.
 */
#include "classify.h"

/* ---------------- generic sign-only Cyrus-Beck clip ---------------- */

enum { POS_A = -1, POS_B = -2 }; /* otherwise: index of the crossing constraint */

typedef struct clipper {
  int m;           /* number of half-spaces: 3 (triangle) or 4 (tet) */
  int ga[4], gb[4];
  /* sign of N_ij (i != j, both crossing) */
  int (*nsign)(const struct clipper *c, int i, int j);
  /* context for nsign */
  const tr_point *a, *b;
  const tr_point *const *t;
  int drop, s;
  /* segment-tet: the orientations by point number (tr_classify_segment_tet_o), and the
   * tet vertex that is the point a / b (-1: none) */
  tr_orient_fn o3;
  void *ud;
  int sa, sb;
} clipper;

/* A crossing that happens at an endpoint is that endpoint. */
static int norm_pos(const clipper *c, int i)
{
  if (i < 0)
    return i;
  if (c->ga[i] == 0)
    return POS_A;
  if (c->gb[i] == 0)
    return POS_B;
  return i;
}

/* Order along ab of two (normalised) positions: -1, 0, +1. Assumes a != b. */
static int cmp_pos(const clipper *c, int p, int q)
{
  if (p == q)
    return 0;
  if (p == POS_A)
    return -1;
  if (q == POS_A)
    return 1;
  if (p == POS_B)
    return 1;
  if (q == POS_B)
    return -1;
  /* both inner crossings: sign(t_p - t_q) = sign(N_pq) sign(D_p) sign(D_q), with
   * D > 0 for exiting (g(a) >= 0) and D < 0 for entering constraints */
  int dp = c->ga[p] < 0 ? -1 : 1, dq = c->ga[q] < 0 ? -1 : 1;
  return c->nsign(c, p, q) * dp * dq;
}

/* Mask of the facets position p lies on. */
static int zero_mask(const clipper *c, int p)
{
  int z = 0;
  for (int j = 0; j < c->m; j++) {
    if (p == POS_A)
      z |= (c->ga[j] == 0) << j;
    else if (p == POS_B)
      z |= (c->gb[j] == 0) << j;
    else if (j == p || (c->ga[j] == 0 && c->gb[j] == 0))
      z |= 1 << j;
    else if ((c->ga[j] < 0) != (c->gb[j] < 0) && norm_pos(c, j) >= 0 && cmp_pos(c, p, j) == 0)
      z |= 1 << j;
  }
  return z;
}

static int on_seg(int p) { return p == POS_A ? TR_SEG_A : p == POS_B ? TR_SEG_B : TR_SEG_IN; }

static int popcount4(int z) { return (z & 1) + ((z >> 1) & 1) + ((z >> 2) & 1) + ((z >> 3) & 1); }

/* The two codes of the vertices not in mask z (of m), as an ECode. */
static int ecode_outside(int z, int m)
{
  int v[2], n = 0;
  for (int i = 0; i < m && n < 2; i++)
    if (!(z & (1 << i)))
      v[n++] = i;
  return tr_ecode(v[0], v[1]);
}
static int first_outside(int z, int m)
{
  for (int i = 0; i < m; i++)
    if (!(z & (1 << i)))
      return i;
  return 0;
}

/* Type of a point on the facets z of a tet (m = 4) or triangle (m = 3). */
static tr_hit type_of(int z, int m, int pos)
{
  tr_hit h = {TR_DEG, 0, (uint8_t)on_seg(pos)};
  int k = popcount4(z);
  if (m == 4) {
    if (k == 0)
      h.type = TR_INT, h.code = 0;
    else if (k == 1)
      h.type = TR_FAC, h.code = (uint8_t)first_outside(~z & 15, 4); /* the facet in z */
    else if (k == 2)
      h.type = TR_EDG, h.code = (uint8_t)ecode_outside(z, 4);
    else
      h.type = TR_NOD, h.code = (uint8_t)first_outside(z, 4);
  } else {
    if (k == 0)
      h.type = TR_FAC, h.code = 3;
    else if (k == 1)
      h.type = TR_EDG, h.code = (uint8_t)ecode_outside(z, 3);
    else
      h.type = TR_NOD, h.code = (uint8_t)first_outside(z, 3);
  }
  return h;
}

static tr_isect clip(const clipper *c)
{
  tr_isect r = {0, {{0, 0, 0}, {0, 0, 0}}};
  for (int i = 0; i < c->m; i++)
    if (c->ga[i] < 0 && c->gb[i] < 0)
      return r;
  int start = POS_A, end = POS_B;
  for (int i = 0; i < c->m; i++) {
    if ((c->ga[i] < 0) == (c->gb[i] < 0))
      continue;
    int p = norm_pos(c, i);
    if (c->ga[i] < 0) { /* entering */
      if (cmp_pos(c, p, start) > 0)
        start = p;
    } else if (cmp_pos(c, p, end) < 0)
      end = p;
  }
  int o = cmp_pos(c, start, end);
  if (o > 0)
    return r;
  r.n = o == 0 ? 1 : 2;
  r.end[0] = type_of(zero_mask(c, start), c->m, start);
  if (r.n == 2)
    r.end[1] = type_of(zero_mask(c, end), c->m, end);
  return r;
}

/* ---------------- helpers ---------------- */

static int collinear(const tr_point *p, const tr_point *a, const tr_point *b)
{
  for (int k = 0; k < 3; k++)
    if (tr_orient2d_proj_p(a, b, p, k) != 0)
      return 0;
  return 1;
}

/* An axis along which a and b differ (-1 if a == b). */
static int diff_axis(const tr_point *a, const tr_point *b)
{
  for (int i = 0; i < 3; i++)
    if (tr_cmp_coord_p(a, b, i) != 0)
      return i;
  return -1;
}

/* A coordinate plane onto which triangle t0t1t2 projects without degenerating, and its
 * projected orientation sign; -1 for a degenerate (collinear) triangle. */
static int tri_axis(const tr_point *t0, const tr_point *t1, const tr_point *t2, int *s)
{
  for (int k = 0; k < 3; k++) {
    *s = tr_orient2d_proj_p(t0, t1, t2, k);
    if (*s != 0)
      return k;
  }
  return -1;
}

/* ---------------- point classifiers ---------------- */

tr_hit tr_classify_point_segment(const tr_point *p, const tr_point *a, const tr_point *b)
{
  tr_hit h = {TR_DEG, 0, 0};
  if (tr_equal_p(p, a)) {
    h.type = TR_NOD, h.code = 0;
    return h;
  }
  if (tr_equal_p(p, b)) {
    h.type = TR_NOD, h.code = 1;
    return h;
  }
  int i = diff_axis(a, b);
  if (i < 0 || !collinear(p, a, b))
    return h;
  /* on the line and distinct from a, b: strictly between iff coordinate i is */
  if (tr_cmp_coord_p(p, a, i) * tr_cmp_coord_p(p, b, i) < 0)
    h.type = TR_EDG, h.code = (uint8_t)tr_ecode(0, 1);
  return h;
}

/* p in the plane of t, projected on axis k where t has orientation sign s. */
static tr_hit point_triangle_2d(const tr_point *p, const tr_point *const t[3], int k, int s)
{
  tr_hit h = {TR_DEG, 0, 0};
  int z = 0;
  for (int i = 0; i < 3; i++) {
    int f = s * tr_orient2d_proj_p(t[(i + 1) % 3], t[(i + 2) % 3], p, k);
    if (f < 0)
      return h;
    z |= (f == 0) << i;
  }
  return type_of(z, 3, POS_A);
}

tr_hit tr_classify_point_triangle(const tr_point *p, const tr_point *t0, const tr_point *t1,
                                  const tr_point *t2)
{
  tr_hit h = {TR_DEG, 0, 0};
  const tr_point *t[3] = {t0, t1, t2};
  int s, k = tri_axis(t0, t1, t2, &s);
  if (k < 0 || tr_orient3d_p(t0, t1, t2, p) != 0)
    return h;
  h = point_triangle_2d(p, t, k, s);
  h.on_seg = 0;
  return h;
}

/* ---------------- segment-segment ---------------- */

static tr_hit hit(int type, int code, int seg)
{
  tr_hit h = {(uint8_t)type, (uint8_t)code, (uint8_t)seg};
  return h;
}

/* Where point p (one of a, b, c, d) lies on cd, given it is on the closed segment cd. */
static tr_hit collinear_end(const tr_point *p, const tr_point *a, const tr_point *b,
                            const tr_point *c, const tr_point *d)
{
  int seg = tr_equal_p(p, a) ? TR_SEG_A : tr_equal_p(p, b) ? TR_SEG_B : TR_SEG_IN;
  if (tr_equal_p(p, c))
    return hit(TR_NOD, 0, seg);
  if (tr_equal_p(p, d))
    return hit(TR_NOD, 1, seg);
  return hit(TR_EDG, tr_ecode(0, 1), seg);
}

tr_isect tr_classify_segment_segment(const tr_point *a, const tr_point *b, const tr_point *c,
                                     const tr_point *d)
{
  tr_isect r = {0, {{0, 0, 0}, {0, 0, 0}}};
  int iab = diff_axis(a, b), icd = diff_axis(c, d);
  if (iab < 0 || icd < 0) {
    /* degenerate segment(s): a point against a segment (or a point) */
    const tr_point *p = iab < 0 ? a : c;
    tr_hit h = iab < 0 ? tr_classify_point_segment(a, c, d) : tr_classify_point_segment(c, a, b);
    if (h.type == TR_DEG)
      return r;
    r.n = 1;
    r.end[0] = collinear_end(p, a, b, c, d);
    return r;
  }
  if (tr_orient3d_p(a, b, c, d) != 0)
    return r;
  int k = -1, oc = 0, od = 0;
  for (int j = 0; j < 3 && k < 0; j++)
    if (tr_orient2d_proj_p(a, b, c, j) != 0 || tr_orient2d_proj_p(a, b, d, j) != 0)
      k = j;
  if (k < 0) {
    /* all four on one line: overlap of two intervals along axis iab, oriented a -> b */
    int dir = tr_cmp_coord_p(b, a, iab);
    const tr_point *lo = c, *hi = d; /* lo comes first along ab */
    if (tr_cmp_coord_p(c, d, iab) * dir > 0)
      lo = d, hi = c;
    const tr_point *s = tr_cmp_coord_p(lo, a, iab) * dir > 0 ? lo : a;
    const tr_point *e = tr_cmp_coord_p(hi, b, iab) * dir < 0 ? hi : b;
    int o = tr_cmp_coord_p(s, e, iab) * dir;
    if (o > 0)
      return r;
    r.n = o == 0 ? 1 : 2;
    r.end[0] = collinear_end(s, a, b, c, d);
    if (r.n == 2)
      r.end[1] = collinear_end(e, a, b, c, d);
    return r;
  }
  /* coplanar, not all collinear: the projection on k is injective on their plane */
  oc = tr_orient2d_proj_p(a, b, c, k);
  od = tr_orient2d_proj_p(a, b, d, k);
  if (oc * od > 0)
    return r;
  int oa = tr_orient2d_proj_p(c, d, a, k), ob = tr_orient2d_proj_p(c, d, b, k);
  if (oa * ob > 0)
    return r;
  /* oc, od not both 0 (not collinear) and likewise oa, ob: one common point */
  r.n = 1;
  r.end[0] = hit(oc == 0 ? TR_NOD : od == 0 ? TR_NOD : TR_EDG,
                 oc == 0 ? 0 : od == 0 ? 1 : tr_ecode(0, 1),
                 oa == 0 ? TR_SEG_A : ob == 0 ? TR_SEG_B : TR_SEG_IN);
  return r;
}

/* ---------------- segment-triangle ---------------- */

static int nsign_tri(const clipper *c, int i, int j)
{
  if (j == (i + 1) % 3)
    return -c->s * tr_orient2d_proj_p(c->a, c->b, c->t[(i + 2) % 3], c->drop);
  return -nsign_tri(c, j, i);
}

tr_isect tr_classify_segment_triangle(const tr_point *a, const tr_point *b,
                                      const tr_point *t0, const tr_point *t1,
                                      const tr_point *t2)
{
  tr_isect r = {0, {{0, 0, 0}, {0, 0, 0}}};
  const tr_point *t[3] = {t0, t1, t2};
  int s, k = tri_axis(t0, t1, t2, &s);
  if (k < 0)
    return r; /* degenerate triangle: documented as no intersection */
  /* an end that is a corner of t is on its plane: no predicate (tr_pt_same) */
  int oa = tr_pt_same(a, t0) || tr_pt_same(a, t1) || tr_pt_same(a, t2)
               ? 0
               : tr_orient3d_p(t0, t1, t2, a);
  int ob = tr_pt_same(b, t0) || tr_pt_same(b, t1) || tr_pt_same(b, t2)
               ? 0
               : tr_orient3d_p(t0, t1, t2, b);
  if (oa * ob > 0)
    return r;
  if (oa != 0 && ob != 0) {
    /* transversal: the crossing point is inside iff the line ab passes on the same side
     * of the three directed edges (Pluecker signs); a zero puts it on that edge's line */
    int e[3], z = 0;
    for (int i = 0; i < 3; i++) {
      /* e[i]: edge opposite vertex i, i.e. t_{i+1} t_{i+2} */
      e[i] = tr_orient3d_p(a, b, t[(i + 1) % 3], t[(i + 2) % 3]);
      z |= (e[i] == 0) << i;
    }
    int pos = 0, neg = 0;
    for (int i = 0; i < 3; i++)
      pos |= e[i] > 0, neg |= e[i] < 0;
    if (pos && neg)
      return r;
    r.n = 1;
    r.end[0] = type_of(z, 3, 0);
    r.end[0].on_seg = TR_SEG_IN;
    return r;
  }
  if (oa == 0 && ob != 0) {
    tr_hit h = point_triangle_2d(a, t, k, s);
    if (h.type != TR_DEG)
      r.n = 1, r.end[0] = h, r.end[0].on_seg = TR_SEG_A;
    return r;
  }
  if (ob == 0 && oa != 0) {
    tr_hit h = point_triangle_2d(b, t, k, s);
    if (h.type != TR_DEG)
      r.n = 1, r.end[0] = h, r.end[0].on_seg = TR_SEG_B;
    return r;
  }
  /* coplanar */
  if (tr_equal_p(a, b)) {
    tr_hit h = point_triangle_2d(a, t, k, s);
    if (h.type != TR_DEG)
      r.n = 1, r.end[0] = h, r.end[0].on_seg = TR_SEG_A;
    return r;
  }
  clipper c = {3, {0}, {0}, nsign_tri, a, b, t, k, s, NULL, NULL, -1, -1};
  for (int i = 0; i < 3; i++) {
    c.ga[i] = s * tr_orient2d_proj_p(t[(i + 1) % 3], t[(i + 2) % 3], a, k);
    c.gb[i] = s * tr_orient2d_proj_p(t[(i + 1) % 3], t[(i + 2) % 3], b, k);
  }
  return clip(&c);
}

/* ---------------- segment-tet ---------------- */

/* parity of the permutation (i, j, k, l) of (0, 1, 2, 3): +1 even, -1 odd */
static int parity4(int i, int j, int k, int l)
{
  int v[4] = {i, j, k, l}, inv = 0;
  for (int x = 0; x < 4; x++)
    for (int y = x + 1; y < 4; y++)
      inv += v[x] > v[y];
  return inv % 2 ? -1 : 1;
}

static int nsign_tet(const clipper *c, int i, int j)
{
  int kl[2], n = 0;
  for (int v = 0; v < 4; v++)
    if (v != i && v != j)
      kl[n++] = v;
  if (kl[0] == c->sa || kl[0] == c->sb || kl[1] == c->sa || kl[1] == c->sb)
    return 0;
  return parity4(i, j, kl[0], kl[1]) * c->o3(c->ud, kl[0], kl[1], TR_PT_B, TR_PT_A);
}

/* g_i(x) for x = a or b: orientation of the tet with vertex i replaced by x (>= 0
 * inside); 0 without a predicate when x is another vertex of the tet */
static int g_tet(const clipper *c, int i, int x)
{
  int sx = x == TR_PT_A ? c->sa : c->sb;
  if (sx >= 0 && sx != i)
    return 0;
  int p[4] = {0, 1, 2, 3};
  p[i] = x;
  return c->o3(c->ud, p[0], p[1], p[2], p[3]);
}

/* The clip of ab by the tet once a != b is known. */
static tr_isect segment_tet(clipper *c)
{
  tr_isect r = {0, {{0, 0, 0}, {0, 0, 0}}};
  /* An end that is a vertex of the tet, with the other end strictly outside one of the
   * three facets through it: the segment meets the closed tet at that vertex or nowhere
   * (nowhere when the tet is inverted), which is what the clip below finds with all
   * eight g. Most tets of a vertex's star are such: a pipe's collection spends most of
   * its tests there (a third of the edge recovery on 252119.stl of the corpus). */
  for (int e = 0; e < 2; e++) {
    int s = e ? c->sb : c->sa, x = e ? TR_PT_A : TR_PT_B, self = e ? TR_PT_B : TR_PT_A;
    if (s < 0)
      continue;
    for (int i = 0; i < 4; i++) {
      if (i == s || g_tet(c, i, x) >= 0)
        continue;
      if (g_tet(c, s, self) < 0)
        return r;
      for (int j = 0; j < 4; j++) {
        c->ga[j] = e ? 1 : 0;
        c->gb[j] = e ? 0 : 1;
      }
      (e ? c->gb : c->ga)[s] = g_tet(c, s, self);
      int pos = e ? POS_B : POS_A;
      r.n = 1;
      r.end[0] = type_of(zero_mask(c, pos), 4, pos);
      return r;
    }
  }
  for (int i = 0; i < 4; i++) {
    c->ga[i] = g_tet(c, i, TR_PT_A);
    if (c->ga[i] < 0)
      c->gb[i] = g_tet(c, i, TR_PT_B);
  }
  /* early out: a constraint with both ends outside needs gb only where ga < 0 */
  for (int i = 0; i < 4; i++)
    if (c->ga[i] < 0 && c->gb[i] < 0)
      return r;
  for (int i = 0; i < 4; i++)
    if (c->ga[i] >= 0)
      c->gb[i] = g_tet(c, i, TR_PT_B);
  return clip(c);
}

/* The points of a point-based classification, by number. */
typedef struct pts6 {
  const tr_point *p[6];
} pts6;

static int o3_points(void *ud, int p, int q, int r, int s)
{
  const pts6 *x = ud;
  return tr_orient3d_p(x->p[p], x->p[q], x->p[r], x->p[s]);
}

tr_isect tr_classify_segment_tet(const tr_point *a, const tr_point *b, const tr_point *const t[4])
{
  pts6 x = {{t[0], t[1], t[2], t[3], a, b}};
  clipper c = {4, {0}, {0}, nsign_tet, a, b, t, 0, 1, o3_points, &x, -1, -1};
  for (int i = 0; i < 4; i++) {
    if (c.sa < 0 && tr_pt_same(t[i], a))
      c.sa = i;
    if (c.sb < 0 && tr_pt_same(t[i], b))
      c.sb = i;
  }
  if (tr_equal_p(a, b)) {
    tr_isect r = {0, {{0, 0, 0}, {0, 0, 0}}};
    for (int i = 0; i < 4; i++)
      if ((c.ga[i] = g_tet(&c, i, TR_PT_A)) < 0)
        return r;
    r.n = 1;
    r.end[0] = type_of(zero_mask(&c, POS_A), 4, POS_A);
    return r;
  }
  return segment_tet(&c);
}

tr_isect tr_classify_segment_tet_o(tr_orient_fn o3, void *ud, int sa, int sb)
{
  clipper c = {4, {0}, {0}, nsign_tet, NULL, NULL, NULL, 0, 1, o3, ud, sa, sb};
  return segment_tet(&c);
}
