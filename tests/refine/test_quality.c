/* The quality measures of src/refine/quality.h against their definitions: one arccosine
 * per dihedral angle, measured independently of tr_tet_shape, on random, flat and lattice
 * tets and on Delaunay meshes of such points (the refinement runs are test_refine.c's). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "mesh/mesh.h"
#include "refine/quality.h"
#include "../pipeline/texpect.h"

/* The next of the LCG *r's doubles in [0, 1), 53 random bits. */
static double unit(uint64_t *r)
{
  *r = *r * 6364136223846793005ull + 1442695040888963407ull;
  return (double)(*r >> 11) * 0x1p-53;
}

/* Four points of the unit cube from *r. */
static void random_tet(uint64_t *r, double p[4][3])
{
  for (int i = 0; i < 4; i++)
    for (int k = 0; k < 3; k++)
      p[i][k] = unit(r);
}

/* tr_tet_shape's dih[e] is the interior dihedral angle at edge e (tr_edge_vtx order),
 * measured independently: the angle between the other two vertices' offsets from the
 * edge line, on random tets. */
static void dihedral_at_edge_matches_geometry(void)
{
  uint64_t r = 777;
  for (int it = 0; it < 5000; it++) {
    double p[4][3];
    random_tet(&r, p);
    double ratio, vol, dih[6];
    tr_tet_shape(p[0], p[1], p[2], p[3], &ratio, &vol, dih, NULL);
    for (int e = 0; e < 6; e++) {
      int i = tr_edge_vtx[e][0], j = tr_edge_vtx[e][1], o[2], no = 0;
      for (int s = 0; s < 4; s++)
        if (s != i && s != j)
          o[no++] = s;
      double d[3], dd = 0, w[2][3];
      for (int k = 0; k < 3; k++) {
        d[k] = p[j][k] - p[i][k];
        dd += d[k] * d[k];
      }
      for (int h = 0; h < 2; h++) {
        double t = 0;
        for (int k = 0; k < 3; k++)
          t += (p[o[h]][k] - p[i][k]) * d[k];
        for (int k = 0; k < 3; k++)
          w[h][k] = p[o[h]][k] - p[i][k] - t / dd * d[k];
      }
      double c = 0, l0 = 0, l1 = 0;
      for (int k = 0; k < 3; k++) {
        c += w[0][k] * w[1][k];
        l0 += w[0][k] * w[0][k];
        l1 += w[1][k] * w[1][k];
      }
      double want = acos(c / sqrt(l0 * l1)) * (180.0 / 3.14159265358979323846);
      if (!(l0 > 1e-6 && l1 > 1e-6))
        continue; /* a vertex nearly on the edge line: no well-defined reference */
      EXPECT(fabs(dih[e] - want) < 1e-6, "tet %d edge %d: %.12g vs %.12g degrees", it, e,
             dih[e], want);
    }
  }
}

/* tr_tet_min_dihedral is the smallest of tr_tet_shape's six angles, the same double, on
 * regular, random, sliver-like and flat tets (its one arccosine rests on acos being
 * monotone). */
static void min_dihedral_equals_smallest_of_six(void)
{
  uint64_t r = 12345;
  for (int it = 0; it < 20000; it++) {
    double p[4][3];
    random_tet(&r, p);
    if (it % 3 == 1) /* nearly flat: d close to the plane abc */
      for (int k = 0; k < 3; k++)
        p[3][k] = (p[0][k] + p[1][k] + p[2][k]) / 3 + (it % 2 ? 1e-9 : 0);
    double ratio, vol, dih[6], r2, v2;
    tr_tet_shape(p[0], p[1], p[2], p[3], &ratio, &vol, dih, NULL);
    double lo = dih[0];
    for (int e = 1; e < 6; e++)
      lo = fmin(lo, dih[e]);
    double m = tr_tet_min_dihedral(p[0], p[1], p[2], p[3], &r2, &v2);
    EXPECT(m == lo || (isnan(m) && isnan(lo)), "tet %d: %.17g vs the six's smallest %.17g", it,
           m, lo);
    EXPECT((r2 == ratio || (isnan(r2) && isnan(ratio))) && v2 == vol, "tet %d: ratio/volume", it);
  }
}

/* The smallest cosine and the volume by their definition, each face's normal made on its
 * own from its three vertices (y - x) x (z - x), faces in tr_face_vtx's order, the
 * cosine at edge e that of the normals of the two faces through it (those opposite the
 * edge's other two vertices), clamped to [-1, 1], 1 where a normal is zero; the volume
 * (b - a) . ((c - a) x (d - a)) / 6. */
static double min_cos_by_faces(const double p[4][3], double *volume)
{
  double n[4][3], len[4];
  for (int k = 0; k < 4; k++) {
    const double *x = p[tr_face_vtx[k][0]], *y = p[tr_face_vtx[k][1]], *z = p[tr_face_vtx[k][2]];
    double e1[3] = {y[0] - x[0], y[1] - x[1], y[2] - x[2]};
    double e2[3] = {z[0] - x[0], z[1] - x[1], z[2] - x[2]};
    n[k][0] = e1[1] * e2[2] - e1[2] * e2[1];
    n[k][1] = e1[2] * e2[0] - e1[0] * e2[2];
    n[k][2] = e1[0] * e2[1] - e1[1] * e2[0];
    len[k] = sqrt(n[k][0] * n[k][0] + n[k][1] * n[k][1] + n[k][2] * n[k][2]);
  }
  double lo = 1;
  for (int e = 0; e < 6; e++) {
    int f[2], nf = 0;
    for (int k = 0; k < 4; k++)
      if (k != tr_edge_vtx[e][0] && k != tr_edge_vtx[e][1])
        f[nf++] = k; /* the face opposite vertex k holds the edge */
    const double *a = n[f[0]], *b = n[f[1]];
    double c = len[f[0]] > 0 && len[f[1]] > 0
                   ? (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (len[f[0]] * len[f[1]])
                   : 1;
    c = c >= 1 || c != c ? 1 : c <= -1 ? -1 : c;
    lo = c < lo ? c : lo;
  }
  double u[3], v[3], w[3];
  for (int k = 0; k < 3; k++) {
    u[k] = p[1][k] - p[0][k];
    v[k] = p[2][k] - p[0][k];
    w[k] = p[3][k] - p[0][k];
  }
  *volume = (u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2]) +
             u[2] * (v[0] * w[1] - v[1] * w[0])) / 6;
  return lo;
}

/* The measures share the face normals that the volume and the circumcentre also take
 * (quality.c: v x w, w x u and u x v are the normals of faces 1, 2 and 3): tr_tet_min_cos,
 * tr_tet_min_dihedral and tr_tet_shape give, bit for bit, the smallest cosine (its angle)
 * and the volume of each face's normal made on its own, on random, nearly flat and flat
 * tets and tets with two vertices the same. */
static void measures_equal_the_per_face_definition(void)
{
  uint64_t r = 9001;
  for (int it = 0; it < 20000; it++) {
    double p[4][3];
    random_tet(&r, p);
    if (it % 4 == 1) /* nearly flat, or flat: d close to or on the plane of abc */
      for (int k = 0; k < 3; k++)
        p[3][k] = (p[0][k] + p[1][k] + p[2][k]) / 3 + (it % 8 == 1 ? 1e-9 : 0);
    if (it % 4 == 2) /* a zero normal on two faces */
      memcpy(p[2], p[1], sizeof p[1]);
    double want_vol, want = min_cos_by_faces(p, &want_vol);
    double vol, ratio, vol2, dih[6], r2, v3;
    double lo = tr_tet_min_cos(p[0], p[1], p[2], p[3], &vol);
    EXPECT(lo == want && vol == want_vol, "tet %d: min cosine %.17g vs %.17g, volume %.17g vs "
           "%.17g", it, lo, want, vol, want_vol);
    tr_tet_shape(p[0], p[1], p[2], p[3], &ratio, &vol2, dih, NULL);
    double m = tr_tet_min_dihedral(p[0], p[1], p[2], p[3], &r2, &v3);
    double six = dih[0];
    for (int e = 1; e < 6; e++)
      six = fmin(six, dih[e]);
    double angle = tr_dihedral_of_cos(want);
    EXPECT(vol2 == want_vol && v3 == want_vol && (m == angle || (isnan(m) && isnan(angle))) &&
               (six == angle || (isnan(six) && isnan(angle))),
           "tet %d: tr_tet_shape / tr_tet_min_dihedral %.17g, %.17g vs %.17g degrees", it, six,
           m, angle);
  }
}

/* A tet scaled by a power of two has the same figures, bit for bit (the volume scaled
 * with it), on both sides of the frame's range (half extents 2^-240 and 2^240), on both
 * sides of the differences' shortcut to it (2^-236 and 2^236) and far outside it: whether
 * a tet is measured as given or in its frame, and by tr_tet_shape,
 * tr_tet_min_cos or tr_tet_min_dihedral (which measures on one frame what the other two
 * measure on theirs), the sliver stage ranks it the same. */
static void measures_invariant_under_power_of_two_scaling(void)
{
  static const int ks[] = {-900, -300, -241, -240, -239, -237, -236, -235, 0,
                           234,  235,  236,  237,  238,  239,  240,  241,  300, 900};
  uint64_t r = 4242;
  for (int it = 0; it < 2000; it++) {
    double p[4][3];
    random_tet(&r, p);
    double ratio0, vol0, dih0[6], w0;
    tr_tet_shape(p[0], p[1], p[2], p[3], &ratio0, &vol0, dih0, NULL);
    double lo0 = tr_tet_min_cos(p[0], p[1], p[2], p[3], &w0);
    for (size_t j = 0; j < sizeof ks / sizeof *ks; j++) {
      double q[4][3];
      for (int i = 0; i < 4; i++)
        for (int k = 0; k < 3; k++)
          q[i][k] = ldexp(p[i][k], ks[j]);
      double ratio, vol, dih[6], w, r2, v2;
      tr_tet_shape(q[0], q[1], q[2], q[3], &ratio, &vol, dih, NULL);
      double lo = tr_tet_min_cos(q[0], q[1], q[2], q[3], &w);
      double m = tr_tet_min_dihedral(q[0], q[1], q[2], q[3], &r2, &v2);
      EXPECT(ratio == ratio0 && r2 == ratio0, "tet %d at 2^%d: ratio %.17g, %.17g vs %.17g",
             it, ks[j], ratio, r2, ratio0);
      EXPECT(!memcmp(dih, dih0, sizeof dih) && lo == lo0 && m == tr_dihedral_of_cos(lo0),
             "tet %d at 2^%d: angles", it, ks[j]);
      if (3 * abs(ks[j]) < 1000) /* the volume itself within doubles */
        EXPECT(vol == ldexp(vol0, 3 * ks[j]) && w == vol && v2 == vol,
               "tet %d at 2^%d: volume %.17g vs %.17g", it, ks[j], vol, ldexp(vol0, 3 * ks[j]));
    }
  }
}

/* The quality summary by its definition: tr_tet_shape's six angles of every live real tet,
 * one arccosine each (what tr_quality_measure computed before it compared cosines). */
static void quality_by_angles(const tr_mesh *m, tr_quality *q)
{
  memset(q, 0, sizeof *q);
  q->min_dihedral = 180;
  static const double rb[TR_QUALITY_RATIO_BINS - 1] = {1, 1.414, 2, 4, 10, 100};
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t) || (m->flags[t] & TR_TF_OUTER))
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    double ratio, vol, dih[6];
    tr_tet_shape(m->xyz + 3 * (size_t)v[0], m->xyz + 3 * (size_t)v[1], m->xyz + 3 * (size_t)v[2],
                 m->xyz + 3 * (size_t)v[3], &ratio, &vol, dih, NULL);
    q->ntets++;
    double lo = 180, hi = 0;
    for (int e = 0; e < 6; e++) {
      lo = fmin(lo, dih[e]);
      hi = fmax(hi, dih[e]);
      int b = (int)(dih[e] / 10);
      q->dihedral_hist[b < 0 ? 0 : b >= TR_QUALITY_DIH_BINS ? TR_QUALITY_DIH_BINS - 1 : b]++;
    }
    q->min_dihedral = fmin(q->min_dihedral, lo);
    q->max_dihedral = fmax(q->max_dihedral, hi);
    q->below5 += lo < 5;
    q->below10 += lo < 10;
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

/* tr_quality_measure (cosines against precomputed bin edges, an arccosine only near an
 * edge or an extreme) gives exactly the figures of one arccosine per angle: on a lattice
 * (angles of exactly 45, 60, 90, 120, 135 degrees: cosines on the bin edges and ties for
 * the extremes), on random points and on points close to a plane (slivers, angles near 0
 * and 180 degrees). */
static void quality_summary_equals_per_angle_definition(void)
{
  uint64_t r = 987654321;
  for (int set = 0; set < 6; set++) {
    double x[3 * 400];
    uint32_t n = 0;
    if (set == 0) {
      for (int i = 0; i < 6; i++)
        for (int j = 0; j < 6; j++)
          for (int k = 0; k < 6; k++) {
            x[3 * n] = i;
            x[3 * n + 1] = j;
            x[3 * n + 2] = k;
            n++;
          }
    } else {
      for (n = 0; n < 400; n++)
        for (int k = 0; k < 3; k++) {
          double u = unit(&r);
          x[3 * n + (uint32_t)k] = k == 2 && set >= 3 ? u * (set == 3 ? 1e-3 : set == 4 ? 1e-7 : 1e-12)
                                                      : u;
        }
    }
    tr_mesh *m = NULL;
    if (tr_delaunay_build(x, n, &m) != TR_OK) {
      EXPECT(0, "set %d: Delaunay failed: %s", set, tr_last_error());
      continue;
    }
    tr_quality a, b;
    tr_quality_measure(m, &a);
    quality_by_angles(m, &b);
    EXPECT(a.ntets == b.ntets && a.ntets > 0, "set %d: %llu vs %llu tets", set,
           (unsigned long long)a.ntets, (unsigned long long)b.ntets);
    EXPECT(a.min_dihedral == b.min_dihedral && a.max_dihedral == b.max_dihedral,
           "set %d: dihedral min %.17g max %.17g, by the angles %.17g %.17g", set,
           a.min_dihedral, a.max_dihedral, b.min_dihedral, b.max_dihedral);
    EXPECT(a.below5 == b.below5 && a.below10 == b.below10,
           "set %d: under 5 / 10 degrees %llu %llu, by the angles %llu %llu", set,
           (unsigned long long)a.below5, (unsigned long long)a.below10,
           (unsigned long long)b.below5, (unsigned long long)b.below10);
    EXPECT(a.max_radius_edge == b.max_radius_edge, "set %d: max radius-edge", set);
    for (int k = 0; k < TR_QUALITY_DIH_BINS; k++)
      EXPECT(a.dihedral_hist[k] == b.dihedral_hist[k], "set %d: dihedral bin %d: %llu vs %llu",
             set, k, (unsigned long long)a.dihedral_hist[k],
             (unsigned long long)b.dihedral_hist[k]);
    for (int k = 0; k < TR_QUALITY_RATIO_BINS; k++)
      EXPECT(a.ratio_hist[k] == b.ratio_hist[k], "set %d: ratio bin %d", set, k);
    if (set == 0) /* the lattice has angles on bin edges: the fallback was exercised */
      EXPECT(b.dihedral_hist[4] + b.dihedral_hist[6] + b.dihedral_hist[9] > 0,
             "lattice: no angle of 45, 60 or 90 degrees");
    tr_mesh_destroy(m);
  }
}

/* tr_dihedral_cos_below(d) is a safe screen: every cosine under it has an angle under d,
 * on random bounds and cosines, on the bounds' own cosines moved by a few ulps and by the
 * guard's width (where the screen must not claim what only the arccosine decides), near 0
 * and 180 degrees where an angle moves fastest with its cosine, and for d <= 0. */
static void cos_below_screens_only_angles_under_the_bound(void)
{
  uint64_t r = 4242;
  long screened = 0;
  for (int it = 0; it < 200000; it++) {
    double d = it % 4 == 0 ? 180 * unit(&r) : it % 4 == 1 ? 1e-3 * unit(&r)
             : it % 4 == 2 ? 180 - 1e-3 * unit(&r) : 5 + 10 * unit(&r);
    double cb = tr_dihedral_cos_below(d), c0 = -cos(d * (3.14159265358979323846 / 180.0));
    double c;
    switch (it % 5) {
    case 0: c = 2 * unit(&r) - 1; break;
    case 1: c = nextafter(cb, -2); break;
    case 2: c = c0 - 2e-9 * unit(&r); break;
    case 3: c = nextafter(nextafter(c0, -2), -2); break;
    default: c = c0 - 1e-9 * (1 - 1e-6); break;
    }
    c = c < -1 ? -1 : c > 1 ? 1 : c;
    if (!(c < cb))
      continue;
    screened++;
    EXPECT(tr_dihedral_of_cos(c) < d, "bound %.17g degrees, cosine %.17g: angle %.17g", d, c,
           tr_dihedral_of_cos(c));
  }
  EXPECT(screened > 50000, "only %ld cosines screened", screened);
  EXPECT(tr_dihedral_cos_below(0) == -INFINITY && tr_dihedral_cos_below(-1) == -INFINITY &&
             tr_dihedral_cos_below(NAN) == -INFINITY,
         "a bound of 0 degrees or less screens no cosine");
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"min_dihedral", min_dihedral_equals_smallest_of_six, NULL},
      {"quality_summary", quality_summary_equals_per_angle_definition, NULL},
      {"dihedral_at_edge", dihedral_at_edge_matches_geometry, NULL},
      {"cos_below", cos_below_screens_only_angles_under_the_bound, NULL},
      {"scale_invariant", measures_invariant_under_power_of_two_scaling, NULL},
      {"per_face", measures_equal_the_per_face_definition, NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
