/* Tet shape measures and the mesh quality summary (quality.h). */
#include "refine/quality.h"

#include <math.h>
#include <string.h>

#include "core/box.h"

static void sub3(const double *a, const double *b, double *o)
{
  o[0] = a[0] - b[0];
  o[1] = a[1] - b[1];
  o[2] = a[2] - b[2];
}
static double dot3(const double *a, const double *b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static void cross3(const double *a, const double *b, double *o)
{
  o[0] = a[1] * b[2] - a[2] * b[1];
  o[1] = a[2] * b[0] - a[0] * b[2];
  o[2] = a[0] * b[1] - a[1] * b[0];
}

/* The measures are invariant under scaling; their double formulas, products of degree 2
 * to 4 of coordinate differences, are not: a tet 1e200 across overflows them (every angle
 * came out 180 and every ratio inf), one 1e-200 across underflows them. A tet whose half
 * extent lies in [2^-SHAPE_SAFE, 2^SHAPE_SAFE) is measured as given (degree 4 stays within
 * 2^(+-4 SHAPE_SAFE), inside the normal range), any other on its coordinates times 2^-e,
 * its half extent then in [1/2, 1): multiplying by a power of two is exact, so the
 * figures are those of the same tet at unit size, and the common case pays a bounding box
 * and no libm call. Returns e (0: as given) and points *q at the coordinates to use. */
#define SHAPE_SAFE 240

static int shape_frame(const double *const p[4], double buf[4][3], const double *q[4])
{
  double lo[3], hi[3];
  for (int k = 0; k < 3; k++) {
    lo[k] = hi[k] = p[0][k];
    for (int i = 1; i < 4; i++) {
      lo[k] = p[i][k] < lo[k] ? p[i][k] : lo[k];
      hi[k] = p[i][k] > hi[k] ? p[i][k] : hi[k];
    }
  }
  double half = tr_box_half_extent(lo, hi);
  for (int i = 0; i < 4; i++)
    q[i] = p[i];
  /* the range first: the common case then makes no libm call (ilogb); with the second
   * framing of every measure gone (the cosines on the frame taken once), this function
   * went from 11.8% to 5.6% of the instructions of anchor.off under --quality 1.414 */
  if (half >= 0x1p-240 && half < 0x1p240) /* 2^-SHAPE_SAFE, 2^SHAPE_SAFE */
    return 0;
  int e = tr_frame_exp(half); /* 0: flat or not finite, nothing to scale */
  if (!e)
    return 0;
  for (int i = 0; i < 4; i++) {
    for (int k = 0; k < 3; k++)
      buf[i][k] = ldexp(p[i][k], -e);
    q[i] = buf[i];
  }
  return e;
}

/* shape_frame's answer without its bounding box, from the differences u, v, w = b - a,
 * c - a, d - a that the measures take anyway: 1 when shape_frame would return 0 (measure
 * as given), 0 when it must be asked. Every |difference| under 2^236 (NaN and inf fail)
 * bounds each axis's extent by 2^237, and one over 2^-236 makes an extent over it (the
 * roundings are monotone and the thresholds doubles), so the half extent is inside
 * [2^-SHAPE_SAFE, 2^SHAPE_SAFE) with room for the rounding of 0.5 hi - 0.5 lo. The box
 * was a fifth of tr_tet_min_cos, the sliver stage's most called measure. */
static int frame_as_given(const double u[3], const double v[3], const double w[3])
{
  const double *d[3] = {u, v, w};
  double big = 0;
  for (int i = 0; i < 3; i++)
    for (int k = 0; k < 3; k++) {
      double x = fabs(d[i][k]);
      if (!(x < 0x1p236))
        return 0;
      big = x > big ? x : big;
    }
  return big > 0x1p-236;
}

/* The faces' normals of a tet (p: coordinates shape_frame gave): n[k] = (y - x) x (z - x)
 * for face k's vertices x y z in tr_face_vtx's order, as constants (with the mesh's tables,
 * another unit, the compiler could unroll nothing). n[1], n[2] and n[3] are the cross
 * products v x w, w x u and u x v of u, v, w = b - a, c - a, d - a, the very operations
 * the volume and the circumcentre take: those callers reuse them (tet_shape,
 * tr_tet_min_cos) instead of making them twice. */
static const uint8_t face_of[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

static void face_normal(const double *const p[4], int k, double n[3])
{
  const double *x = p[face_of[k][0]], *y = p[face_of[k][1]], *z = p[face_of[k][2]];
  double e1[3], e2[3];
  sub3(y, x, e1);
  sub3(z, x, e2);
  cross3(e1, e2, n);
}

/* cs[e] = the cosine of the angle between the normals n (face_normal) of the two faces
 * at edge e (ECode order), clamped to [-1, 1]; 1 where a face has no normal. The
 * dihedral angle at e is pi minus its arccosine. */
static void normal_cosines(const double n[4][3], double cs[6])
{
  /* per edge of tr_edge_vtx, the two faces through it (those opposite the other two
   * vertices), as constants: the search for them was a tenth of this function, the
   * hottest of the sliver stage (tests/refine: dihedral_at_edge_matches_geometry) */
  static const uint8_t ef[6][2] = {{2, 3}, {1, 3}, {1, 2}, {0, 3}, {0, 2}, {0, 1}};
  double len[4];
  for (int k = 0; k < 4; k++)
    len[k] = sqrt(dot3(n[k], n[k]));
  for (int e = 0; e < 6; e++) {
    int k = ef[e][0], l = ef[e][1];
    double c = len[k] > 0 && len[l] > 0 ? dot3(n[k], n[l]) / (len[k] * len[l]) : 1;
    /* clamped to [-1, 1], NaN to 1 (as fmax(-1, fmin(1, c))), without the libm calls
     * (libm's fmin was 4.7% of couplingdown --quality 1.414) */
    cs[e] = c >= 1 || c != c ? 1 : c <= -1 ? -1 : c;
  }
}

/* The smallest of normal_cosines' six, the same double, without clamping each: a cosine
 * the clamp takes to 1 (at least 1, NaN, or a face without a normal) never lowers a
 * minimum that starts at 1, and one at most -1 leaves -1 after the final clamp either way.
 * The per-cosine clamp's branches were a third of normal_cosines. */
static double min_normal_cos(const double n[4][3])
{
  static const uint8_t ef[6][2] = {{2, 3}, {1, 3}, {1, 2}, {0, 3}, {0, 2}, {0, 1}};
  double len[4], lo = 1;
  for (int k = 0; k < 4; k++)
    len[k] = sqrt(dot3(n[k], n[k]));
  if (len[0] > 0 && len[1] > 0 && len[2] > 0 && len[3] > 0) {
    for (int e = 0; e < 6; e++) {
      int k = ef[e][0], l = ef[e][1];
      double c = dot3(n[k], n[l]) / (len[k] * len[l]);
      lo = c < lo ? c : lo;
    }
  } else {
    for (int e = 0; e < 6; e++) {
      int k = ef[e][0], l = ef[e][1];
      if (len[k] > 0 && len[l] > 0) {
        double c = dot3(n[k], n[l]) / (len[k] * len[l]);
        lo = c < lo ? c : lo;
      }
    }
  }
  return lo <= -1 ? -1 : lo;
}

/* tr_tet_shape, and *lo_cos (when not NULL) = the smallest of its tet's normal_cosines:
 * tr_tet_min_dihedral's figures on one frame (it took tr_tet_shape's and then
 * tr_tet_min_cos's, a bounding box and a volume twice); cs_out (when not NULL) = the six
 * cosines themselves (tr_quality_measure took them with a second frame and four more
 * normals, the same doubles) */
static int tet_shape(const double *a0, const double *b0, const double *c0, const double *d0,
                     double *ratio, double *volume, double dih[6], double cc[3],
                     double *lo_cos, double cs_out[6])
{
  const double *p0[4] = {a0, b0, c0, d0}, *p[4] = {a0, b0, c0, d0};
  double buf[4][3], u[3], v[3], w[3];
  sub3(b0, a0, u);
  sub3(c0, a0, v);
  sub3(d0, a0, w);
  int fe = 0;
  if (!frame_as_given(u, v, w) && (fe = shape_frame(p0, buf, p)) != 0) {
    sub3(p[1], p[0], u); /* on the frame */
    sub3(p[2], p[0], v);
    sub3(p[3], p[0], w);
  }
  double vw[3], wu[3], uv[3];
  cross3(v, w, vw);
  cross3(w, u, wu);
  cross3(u, v, uv);
  double det = dot3(u, vw);
  *volume = fe ? ldexp(det / 6, 3 * fe) : det / 6;
  /* circumcentre: a + (|u|^2 v x w + |v|^2 w x u + |w|^2 u x v) / (2 det) */
  double uu = dot3(u, u), vv = dot3(v, v), ww = dot3(w, w), o[3];
  for (int i = 0; i < 3; i++)
    o[i] = (uu * vw[i] + vv * wu[i] + ww * uv[i]) / (2 * det);
  double R = sqrt(dot3(o, o)), emin = INFINITY;
  for (int e = 0; e < 6; e++) {
    double x[3];
    sub3(p[tr_edge_vtx[e][1]], p[tr_edge_vtx[e][0]], x);
    double xx = dot3(x, x);
    emin = xx < emin ? xx : emin; /* fmin without the libm call (never NaN: emin starts at
                                     inf, and a NaN xx leaves it as fmin does) */
  }
  *ratio = det != 0 ? R / sqrt(emin) : INFINITY;
  int finite = isfinite(o[0]) && isfinite(o[1]) && isfinite(o[2]);
  for (int i = 0; i < 3 && fe; i++)
    o[i] = ldexp(o[i], fe);
  if (cc)
    for (int i = 0; i < 3; i++) {
      cc[i] = a0[i] + o[i];
      finite = finite && isfinite(cc[i]);
    }
  if (dih || lo_cos || cs_out) {
    double cs[6], lo = 1, n[4][3];
    face_normal(p, 0, n[0]);
    memcpy(n[1], vw, sizeof vw); /* face_normal(p, 1), (2) and (3): the same operations */
    memcpy(n[2], wu, sizeof wu);
    memcpy(n[3], uv, sizeof uv);
    if (dih || cs_out) {
      normal_cosines(n, cs);
      for (int e = 0; e < 6 && dih; e++)
        dih[e] = tr_dihedral_of_cos(cs[e]);
      for (int e = 0; e < 6; e++)
        lo = cs[e] < lo ? cs[e] : lo; /* as tr_tet_min_cos */
    } else
      lo = min_normal_cos(n);
    if (lo_cos)
      *lo_cos = lo;
    if (cs_out)
      memcpy(cs_out, cs, sizeof cs);
  }
  return finite;
}

int tr_tet_shape(const double *a0, const double *b0, const double *c0, const double *d0,
                 double *ratio, double *volume, double dih[6], double cc[3])
{
  return tet_shape(a0, b0, c0, d0, ratio, volume, dih, cc, NULL, NULL);
}

double tr_tet_min_cos(const double *a, const double *b, const double *c, const double *d,
                      double *volume)
{
  const double *p0[4] = {a, b, c, d}, *p[4] = {a, b, c, d};
  double buf[4][3], u[3], v[3], w[3], n[4][3];
  sub3(b, a, u);
  sub3(c, a, v);
  sub3(d, a, w);
  int fe = 0;
  if (frame_as_given(u, v, w)) {
    /* face_normal's operations: faces 1, 2 and 3 are v x w, w x u and u x v */
    double e1[3], e2[3];
    sub3(d, b, e1);
    sub3(c, b, e2);
    cross3(e1, e2, n[0]);
    cross3(v, w, n[1]);
    cross3(w, u, n[2]);
    cross3(u, v, n[3]);
  } else {
    fe = shape_frame(p0, buf, p);
    for (int k = 0; k < 4; k++)
      face_normal(p, k, n[k]);
    sub3(p[1], p[0], u);
  }
  /* the volume as tr_tet_shape computes it, the same operations in the same order; v x w
   * is face 1's normal */
  *volume = fe ? ldexp(dot3(u, n[1]) / 6, 3 * fe) : dot3(u, n[1]) / 6;
  return min_normal_cos(n);
}

double tr_dihedral_of_cos(double lo)
{
  return 180.0 - acos(lo) * (180.0 / 3.14159265358979323846);
}

/* the guard of tr_quality_measure's cosines (TR_QUALITY_COS_GUARD, below): f(c) = 180 -
 * acos(c) 180/pi rises at least 180/pi per unit of cosine, so a cosine 1e-9 under that of
 * d has an angle at least 5.7e-8 degrees under d, and the roundings of cos, acos and the
 * products err by under 1e-13 degrees (where the slope is steep, near 0 and 180 degrees,
 * the guard's gap in degrees grows with it) */
double tr_dihedral_cos_below(double degrees)
{
  if (!(degrees > 0))
    return -INFINITY;
  /* the sliver flips ask again and again about the same angle (a ring's best so far):
   * the last answer, per thread, spares the cosine (1.5 million calls on 37384.stl) */
  static _Thread_local double last_deg = -1, last_cos;
  if (degrees == last_deg)
    return last_cos;
  last_cos = -cos(degrees * (3.14159265358979323846 / 180.0)) - 1e-9;
  last_deg = degrees;
  return last_cos;
}

double tr_tet_min_dihedral(const double *a, const double *b, const double *c, const double *d,
                           double *ratio, double *volume)
{
  double lo;
  tet_shape(a, b, c, d, ratio, volume, NULL, NULL, &lo, NULL);
  /* the smallest angle has the smallest cosine of the normals' angle: one acos, the
   * same double as the smallest of the six (acos is correctly rounded, so monotone) */
  return tr_dihedral_of_cos(lo);
}

uint64_t tr_quality_count_below(const struct tr_mesh *m, double degrees)
{
  uint64_t n = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t) || (m->flags[t] & TR_TF_OUTER))
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    double ratio, vol;
    n += tr_tet_min_dihedral(m->xyz + 3 * (size_t)v[0], m->xyz + 3 * (size_t)v[1],
                             m->xyz + 3 * (size_t)v[2], m->xyz + 3 * (size_t)v[3], &ratio,
                             &vol) < degrees;
  }
  return n;
}

/* The summary without an arccosine per dihedral angle (six per tet were most of its
 * time), giving the very same figures. The angle of a cosine c, f(c) = 180 - acos(c) *
 * 180/pi, increases with c; the angles that decide something are the histogram's bin edges
 * (10 k degrees), 5 and 10 degrees (per tet, its smallest angle) and the extremes. A
 * cosine farther than TR_QUALITY_COS_GUARD from the cosine of an edge falls on the same
 * side of it as its computed angle: acos and the arithmetic after it err by under 1e-13
 * degrees, and f's slope is at least 180/pi per unit of cosine, so the guard leaves a
 * margin of five orders of magnitude. Cosines inside a guard band take the angle itself,
 * as before; so do the candidates for the extremes (every cosine within the guard of the
 * smallest / largest one seen so far: an angle skipped lies beyond the guard from a cosine
 * whose angle was taken, so it is no extreme). */
#define TR_QUALITY_COS_GUARD 1e-9

/* edge[k] ~ the cosine of angle 10 (k + 1), k < TR_QUALITY_DIH_BINS - 1; c5, c10: of 5
 * and 10 degrees */
typedef struct cos_edges {
  double edge[TR_QUALITY_DIH_BINS - 1], c5, c10;
} cos_edges;

static void cos_edges_init(cos_edges *e)
{
  const double pi = 3.14159265358979323846;
  for (int k = 0; k < TR_QUALITY_DIH_BINS - 1; k++)
    e->edge[k] = cos((180.0 - 10.0 * (k + 1)) * (pi / 180.0));
  e->c5 = cos(175.0 * (pi / 180.0));
  e->c10 = cos(170.0 * (pi / 180.0));
}

static int near_cos(double c, double edge)
{
  return fabs(c - edge) <= TR_QUALITY_COS_GUARD;
}

static int dih_bin(double dih)
{
  int b = (int)(dih / 10);
  return b < 0 ? 0 : b >= TR_QUALITY_DIH_BINS ? TR_QUALITY_DIH_BINS - 1 : b;
}

/* The bin of cosine c: the edges below it, or, inside a guard band, the bin of its
 * angle. The edges ascend, so their count is a binary search; written as conditional
 * adds of a halving step (five, for 17 edges), which compile to conditional moves: a
 * branching search was mispredicted half the time, and counting all 17 cost 3x more. */
_Static_assert(TR_QUALITY_DIH_BINS - 1 <= 31, "cos_bin's steps from 16 reach 31 edges");
static int cos_bin(const cos_edges *e, double c)
{
  int n = 0;
  for (int step = 16; step; step >>= 1) {
    int k = n + step;
    n = k <= TR_QUALITY_DIH_BINS - 1 && e->edge[k - 1] < c ? k : n;
  }
  if ((n > 0 && near_cos(c, e->edge[n - 1])) ||
      (n < TR_QUALITY_DIH_BINS - 1 && near_cos(c, e->edge[n])))
    return dih_bin(tr_dihedral_of_cos(c));
  return n;
}

/* 1 iff the smallest of the angles of cs[0..6) is under the angle whose cosine is ce
 * (degrees: that angle; ce: a guard-free cosine of it). */
static int any_under(const double cs[6], double lo_cos, double ce, double degrees)
{
  if (!near_cos(lo_cos, ce))
    return lo_cos < ce;
  for (int e = 0; e < 6; e++)
    if (tr_dihedral_of_cos(cs[e]) < degrees)
      return 1;
  return 0;
}

void tr_quality_measure(const struct tr_mesh *m, tr_quality *q)
{
  memset(q, 0, sizeof *q);
  q->min_dihedral = 180;
  static const double rb[TR_QUALITY_RATIO_BINS - 1] = {1, 1.414, 2, 4, 10, 100};
  cos_edges ce;
  cos_edges_init(&ce);
  double lo_seen = INFINITY, hi_seen = -INFINITY; /* extreme cosines whose angles were taken */
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t) || (m->flags[t] & TR_TF_OUTER))
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    const double *p[4] = {m->xyz + 3 * (size_t)v[0], m->xyz + 3 * (size_t)v[1],
                          m->xyz + 3 * (size_t)v[2], m->xyz + 3 * (size_t)v[3]};
    double ratio, vol, cs[6];
    tet_shape(p[0], p[1], p[2], p[3], &ratio, &vol, NULL, NULL, NULL, cs);
    q->ntets++;
    double lc = cs[0], hc = cs[0];
    for (int e = 0; e < 6; e++) {
      lc = cs[e] < lc ? cs[e] : lc;
      hc = cs[e] > hc ? cs[e] : hc;
      q->dihedral_hist[cos_bin(&ce, cs[e])]++;
    }
    /* an angle already taken (the same cosine) is not taken again */
    for (int e = 0; e < 6; e++) {
      if (cs[e] <= lo_seen + TR_QUALITY_COS_GUARD && cs[e] != lo_seen)
        q->min_dihedral = fmin(q->min_dihedral, tr_dihedral_of_cos(cs[e]));
      if (cs[e] >= hi_seen - TR_QUALITY_COS_GUARD && cs[e] != hi_seen)
        q->max_dihedral = fmax(q->max_dihedral, tr_dihedral_of_cos(cs[e]));
    }
    lo_seen = lc < lo_seen ? lc : lo_seen;
    hi_seen = hc > hi_seen ? hc : hi_seen;
    q->below5 += any_under(cs, lc, ce.c5, 5);
    q->below10 += any_under(cs, lc, ce.c10, 10);
    if (!(ratio <= q->max_radius_edge))
      q->max_radius_edge = ratio;
    int b = 0;
    while (b < TR_QUALITY_RATIO_BINS - 1 && !(ratio < rb[b]))
      b++;
    q->ratio_hist[b]++;
  }
  if (!q->ntets)
    q->min_dihedral = 0;
}

void tr_quality_print(FILE *f, const char *prefix, const tr_quality *q)
{
  fprintf(f,
          "%squality: %llu tets, dihedral min %.3f max %.3f deg, %llu (%.2f%%) under 5 deg, "
          "%llu (%.2f%%) under 10 deg, max radius-edge %.4g\n",
          prefix, (unsigned long long)q->ntets, q->min_dihedral, q->max_dihedral,
          (unsigned long long)q->below5, q->ntets ? 100.0 * (double)q->below5 / (double)q->ntets : 0,
          (unsigned long long)q->below10,
          q->ntets ? 100.0 * (double)q->below10 / (double)q->ntets : 0, q->max_radius_edge);
  fprintf(f, "%s  dihedral histogram (10 deg bins):", prefix);
  for (int i = 0; i < TR_QUALITY_DIH_BINS; i++)
    fprintf(f, " %llu", (unsigned long long)q->dihedral_hist[i]);
  fprintf(f, "\n%s  radius-edge histogram (<1 <1.414 <2 <4 <10 <100 >=100):", prefix);
  for (int i = 0; i < TR_QUALITY_RATIO_BINS; i++)
    fprintf(f, " %llu", (unsigned long long)q->ratio_hist[i]);
  fprintf(f, "\n");
}
