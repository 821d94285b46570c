/* The tets under 10 degrees that stand on thin input triangles (src/refine/thin.c,
 * tr_stats.tets_dihedral_below_10_on_thin_input and thin_input_triangles), against a
 * count by definition: the input triangles' corners by arccosine, every boundary face of
 * the output scanned for each edge of each tet under 10 degrees. Every mesh goes through
 * the mesh validator and the exact conformity validator (tmesh.h). */
#include <math.h>

#include <stdint.h>
#include <string.h>

#include "core/facets.h"
#include "refine/quality.h"
#include "refine/refine_impl.h" /* rf_cos_angle */
#include "../pipeline/tmesh.h"

/* The smallest corner of input triangle t of plc, degrees, by arccosine. */
static double corner_by_acos(const tr_plc *plc, uint32_t t)
{
  double lo = 180;
  for (int k = 0; k < 3; k++) {
    const double *o = plc->xyz + 3 * (size_t)plc->tris[3 * (size_t)t + (size_t)k],
                 *p = plc->xyz + 3 * (size_t)plc->tris[3 * (size_t)t + (size_t)(k + 1) % 3],
                 *q = plc->xyz + 3 * (size_t)plc->tris[3 * (size_t)t + (size_t)(k + 2) % 3];
    double dot = 0, a = 0, b = 0;
    for (int i = 0; i < 3; i++) {
      dot += (p[i] - o[i]) * (q[i] - o[i]);
      a += (p[i] - o[i]) * (p[i] - o[i]);
      b += (q[i] - o[i]) * (q[i] - o[i]);
    }
    lo = fmin(lo, acos(dot / sqrt(a * b)) * (180 / 3.14159265358979323846));
  }
  return lo;
}

/* Does edge (u, v) belong to boundary face f? */
static int face_has_edge(const uint32_t *f, uint32_t u, uint32_t v)
{
  int n = 0;
  for (int i = 0; i < 3; i++)
    n += f[i] == u || f[i] == v;
  return n == 2;
}

/* Meshes plc under opt and compares the stats with the count by definition; `merged`:
 * the triangles in merged facets (no thin one counts there). Returns the number of tets
 * under 10 degrees on thin triangles. */
static uint64_t check_counts(const char *name, const tr_plc *plc, const tr_options *opt,
                             const uint8_t *merged)
{
  tm_run r;
  tr_mesh *m = tm_mesh(&r, name, plc, opt, TR_CHK_TOPOLOGY);
  uint64_t on = 0;
  if (!m) {
    tm_free(&r);
    return 0;
  }
  const struct tr_mesh_attrs *a = m->attrs;
  uint64_t thin = 0, below = 0;
  uint8_t is_thin[64] = {0};
  EXPECT(r.used->ntris <= 64, "%s: test too large", name);
  for (uint32_t t = 0; t < r.used->ntris && t < 64; t++) {
    is_thin[t] = !(merged && merged[t]) && corner_by_acos(r.used, t) < 10;
    thin += is_thin[t];
  }
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t) || (m->flags[t] & TR_TF_OUTER))
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    double ratio, vol;
    if (!(tr_tet_min_dihedral(m->xyz + 3 * (size_t)v[0], m->xyz + 3 * (size_t)v[1],
                              m->xyz + 3 * (size_t)v[2], m->xyz + 3 * (size_t)v[3], &ratio,
                              &vol) < 10))
      continue;
    below++;
    int found = 0;
    for (int e = 0; e < 6 && !found; e++)
      for (uint32_t f = 0; f < a->nfaces && !found; f++)
        found = is_thin[a->face_tri[f]] &&
                face_has_edge(a->faces + 3 * (size_t)f, v[tr_edge_vtx[e][0]], v[tr_edge_vtx[e][1]]);
    on += (uint64_t)found;
  }
  EXPECT(r.st.tets_dihedral_below_10 == below, "%s: %llu tets under 10 degrees, %llu by "
         "definition", name, (unsigned long long)r.st.tets_dihedral_below_10,
         (unsigned long long)below);
  /* the stats skip the count when no tet is under 10 degrees */
  EXPECT(r.st.thin_input_triangles == (below ? thin : 0), "%s: %llu thin input triangles, %llu "
         "by definition", name, (unsigned long long)r.st.thin_input_triangles,
         (unsigned long long)thin);
  EXPECT(r.st.tets_dihedral_below_10_on_thin_input == on, "%s: %llu tets under 10 degrees on "
         "thin triangles, %llu by definition", name,
         (unsigned long long)r.st.tets_dihedral_below_10_on_thin_input, (unsigned long long)on);
  fprintf(stderr, "%s: %u tets, %llu under 10 degrees, %llu of them on the %llu thin "
          "triangles\n", name, tr_mesh_num_tets(m), (unsigned long long)below,
          (unsigned long long)on, (unsigned long long)thin);
  tm_free(&r);
  return on;
}

/* The prism over the triangle (0,0), (10,0), (10,0.875) (a 5-degree corner), 2 high: its
 * two end facets are single thin triangles, its sides exactly planar rectangles (merged).
 * Refined without sliver removal, tets under 10 degrees are left on the ends, and each is
 * counted as the definition counts it. */
static void prism_with_thin_ends(void)
{
  const double x[18] = {0, 0, 0, 10, 0, 0, 10, 0.875, 0, 0, 0, 2, 10, 0, 2, 10, 0.875, 2};
  static const uint32_t t[24] = {0, 2, 1, 3, 4, 5, 0, 1, 4, 0, 4, 3,
                                 1, 2, 5, 1, 5, 4, 2, 0, 3, 2, 3, 5};
  static const uint8_t merged[8] = {0, 0, 1, 1, 1, 1, 1, 1};
  tr_plc *plc = tm_plc(x, 6, t, 8);
  tr_options opt = tm_refinement(1.414, 0);
  uint64_t on = check_counts("thin_prism", plc, &opt, merged);
  EXPECT(on > 0, "thin_prism: no tet under 10 degrees on the thin ends: the case shows "
         "nothing");
  opt.optimize = 2; /* and after sliver removal (the default) */
  check_counts("thin_prism_O2", plc, &opt, merged);
  tr_plc_destroy(plc);
}

/* A box split into 1 x 1 x 20 (its long sides' triangles have a corner of 2.9 degrees).
 * Exactly planar sides merge by default: no triangle is thin there. With every input edge
 * kept, the long sides' 8 triangles are thin, and the count follows the definition. */
static void merged_thin_triangles_do_not_count(void)
{
  const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 20};
  tr_plc *plc = tm_box(lo, hi);
  tr_options opt = tm_refinement(1.414, 0);
  uint8_t all[12];
  memset(all, 1, sizeof all);
  tm_run r;
  tr_mesh *m = tm_mesh(&r, "long_box", plc, &opt, TR_CHK_TOPOLOGY);
  if (m)
    EXPECT(r.st.thin_input_triangles == 0 && r.st.tets_dihedral_below_10_on_thin_input == 0,
           "long_box: %llu thin triangles, %llu tets on them, merged facets have none",
           (unsigned long long)r.st.thin_input_triangles,
           (unsigned long long)r.st.tets_dihedral_below_10_on_thin_input);
  tm_free(&r);
  check_counts("long_box_merged", plc, &opt, all);
  opt.keep_edges = 1;
  check_counts("long_box_keep_edges", plc, &opt, NULL);
  tr_plc_destroy(plc);
}

/* A unit cube has no thin triangle: nothing is counted. */
static void cube_has_no_thin_triangle(void)
{
  const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  tr_plc *plc = tm_box(lo, hi);
  tr_options opt = tm_refinement(1.414, 0);
  opt.keep_edges = 1;
  EXPECT(check_counts("cube", plc, &opt, NULL) == 0, "cube: tets counted on thin triangles");
  tr_plc_destroy(plc);
}

/* The corner measure's definition: each difference vector scaled by ldexp to its largest
 * component's binade, then the cosine. */
static double cos_by_ldexp(const double *o, const double *p, const double *q)
{
  double a[3], b[3], ma = 0, mb = 0;
  for (int i = 0; i < 3; i++) {
    a[i] = p[i] - o[i];
    b[i] = q[i] - o[i];
    ma = fmax(ma, fabs(a[i]));
    mb = fmax(mb, fabs(b[i]));
  }
  int ea = 0, eb = 0;
  if (ma > 0 && isfinite(ma))
    frexp(ma, &ea);
  if (mb > 0 && isfinite(mb))
    frexp(mb, &eb);
  for (int i = 0; i < 3; i++) {
    a[i] = ldexp(a[i], -ea);
    b[i] = ldexp(b[i], -eb);
  }
  double n = sqrt((a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) * (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
  return n > 0 ? (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / n : 1;
}

static uint64_t rng = 0x9e3779b97f4a7c15u;
static double unif(void)
{
  rng ^= rng << 13;
  rng ^= rng >> 7;
  rng ^= rng << 17;
  return (double)(rng >> 11) * 0x1p-53;
}

/* Case n of the cosine tests: a triangle at scale 2^e (returned), e in [-1074, 1006), its
 * components spread up to 2^59 apart in size, some zero; x1 = x0 in every 97th case. */
static int draw_triangle(int n, double x[3][3])
{
  int e = (int)(unif() * 2080) - 1074, spread = (int)(unif() * 60);
  for (int k = 0; k < 3; k++)
    for (int i = 0; i < 3; i++) {
      double m = unif() - 0.5;
      x[k][i] = ldexp(m, e - (unif() < 0.3 ? spread : 0));
      if (unif() < 0.05)
        x[k][i] = 0;
    }
  if (n % 97 == 0)
    memcpy(x[1], x[0], sizeof x[0]);
  return e;
}

/* rf_cos_angle scales by one power of two per vector, not by ldexp per component: the same
 * double bit for bit, over scales from 2^-1074 to 2^1000, components far apart in size
 * (subnormal products), zero and equal points. */
static void cos_angle_equals_definition(void)
{
  int bad = 0, subnormal = 0;
  for (int n = 0; n < 200000 && bad < 5; n++) {
    double x[3][3];
    int e = draw_triangle(n, x);
    double got = rf_cos_angle(x[0], x[1], x[2]), want = cos_by_ldexp(x[0], x[1], x[2]);
    subnormal += fabs(x[1][0] - x[0][0]) < 0x1p-1022 && x[1][0] != x[0][0];
    if (memcmp(&got, &want, sizeof got) && !(isnan(got) && isnan(want))) {
      bad++;
      EXPECT(0, "case %d (scale 2^%d): rf_cos_angle %a, by ldexp %a", n, e, got, want);
    }
  }
  EXPECT(subnormal > 1000, "subnormal differences exercised: %d", subnormal);
}

/* rf_tri_cos_angles shares the edge vectors between the three corners: each cosine the
 * same double as rf_cos_angle at that corner, bit for bit but for the sign of a zero, on
 * the triangles of cos_angle_equals_definition and right angles with zero products. */
static void tri_cos_angles_equal_cos_angle(void)
{
  int bad = 0, zero = 0;
  for (int n = 0; n < 200000 && bad < 5; n++) {
    double x[3][3];
    int e = draw_triangle(n, x);
    if (n % 89 == 0) /* a right angle at x0 with zero products: signed zeros */
      for (int i = 0; i < 3; i++) {
        x[1][i] = i == 0 ? x[0][i] + 1 : x[0][i];
        x[2][i] = i == 1 ? x[0][i] - 1 : x[0][i];
      }
    double c[3];
    rf_tri_cos_angles(x[0], x[1], x[2], c);
    for (int k = 0; k < 3; k++) {
      double want = rf_cos_angle(x[k], x[(k + 1) % 3], x[(k + 2) % 3]);
      zero += want == 0;
      if (memcmp(&c[k], &want, sizeof want) && !(c[k] == 0 && want == 0) &&
          !(isnan(c[k]) && isnan(want))) {
        bad++;
        EXPECT(0, "case %d corner %d (scale 2^%d): rf_tri_cos_angles %a, rf_cos_angle %a", n,
               k, e, c[k], want);
      }
    }
  }
  EXPECT(zero > 1000, "zero cosines exercised: %d", zero);
}

/* The thin triangles by their definition, as thin.c counted them before it skipped
 * arccosines and built the facets only for a thin corner: every triangle's three
 * rf_cos_angle and the arccosine of the largest, a triangle of a merged facet excluded. */
static void thin_by_definition(const tr_plc *plc, const tr_facets *fc, double corner,
                               uint8_t *thin, tr_quality_thin *out)
{
  out->triangles = out->below_on_thin = 0;
  out->thinnest = out->thinnest_vertex = UINT32_MAX;
  out->thinnest_angle = 180;
  for (uint32_t t = 0; t < plc->ntris; t++) {
    const uint32_t *T = plc->tris + 3 * (size_t)t;
    double hi = -1;
    uint32_t at = T[0];
    for (int k = 0; k < 3; k++) {
      double c = rf_cos_angle(plc->xyz + 3 * (size_t)T[k], plc->xyz + 3 * (size_t)T[(k + 1) % 3],
                              plc->xyz + 3 * (size_t)T[(k + 2) % 3]);
      if (c > hi) {
        hi = c;
        at = T[k];
      }
    }
    double lo = acos(fmin(hi, 1)) * (180 / 3.14159265358979323846);
    thin[t] = tr_facets_size(fc, fc->group[t]) == 1 && lo < corner;
    if (!thin[t])
      continue;
    out->triangles++;
    if (lo < out->thinnest_angle) {
      out->thinnest_angle = lo;
      out->thinnest = t;
      out->thinnest_vertex = at;
    }
  }
}

static int same_thin(const tr_quality_thin *a, const tr_quality_thin *b)
{
  return a->triangles == b->triangles && a->thinnest == b->thinnest &&
         a->thinnest_vertex == b->thinnest_vertex &&
         !memcmp(&a->thinnest_angle, &b->thinnest_angle, sizeof a->thinnest_angle);
}

/* tr_plc_thin_triangles (the corners first, the facets only for a thin one) and
 * tr_facets_thin_triangles (no arccosine far from the corner) against the definition on
 * random surfaces: points of a 3x3x3 grid (coplanar neighbours merge, collinear corners of
 * 0 and 180 degrees) and fans whose corner at the origin lies within 1e-5 degrees of the
 * limit, for limits 0, 10, 60, 179.5 and 180, with and without kept edges. */
static void lazy_thin_triangles_equal_the_definition(void)
{
  enum { NP = 27 + 3 * 64, NT = 400 };
  static double xyz[3 * NP];
  static uint32_t tris[3 * NT];
  uint64_t seen_thin = 0, seen_merged = 0, rounds = 0;
  for (int round = 0; round < 40; round++) {
    for (int i = 0; i < 27; i++) {
      xyz[3 * i] = i % 3;
      xyz[3 * i + 1] = i / 3 % 3;
      xyz[3 * i + 2] = i / 9;
    }
    double corner = (double[]){0, 10, 60, 179.5, 180}[round % 5];
    /* fans at the origin: corner +- up to 1e-5 degrees, at a random scale */
    for (int f = 0; f < 64; f++) {
      double deg = corner + (unif() - 0.5) * 2e-5, r = ldexp(1, (int)(unif() * 40) - 20);
      double th = deg * (3.14159265358979323846 / 180);
      double *o = xyz + 3 * (27 + 3 * f);
      o[0] = o[1] = o[2] = 5 * r;
      o[3] = o[0] + 2 * r, o[4] = o[1], o[5] = o[2];
      o[6] = o[0] + 3 * r * cos(th), o[7] = o[1] + 3 * r * sin(th), o[8] = o[2];
    }
    uint32_t nt = 0;
    for (int f = 0; f < 64; f++, nt++)
      for (int k = 0; k < 3; k++)
        tris[3 * nt + k] = 27 + 3 * (uint32_t)f + (uint32_t)k;
    while (nt < NT) {
      uint32_t a = (uint32_t)(unif() * 27), b = (uint32_t)(unif() * 27),
               c = (uint32_t)(unif() * 27);
      if (a == b || b == c || a == c)
        continue;
      tris[3 * nt] = a, tris[3 * nt + 1] = b, tris[3 * nt + 2] = c;
      nt++;
    }
    tr_plc plc = {0};
    plc.npoints = NP;
    plc.xyz = xyz;
    plc.ntris = nt;
    plc.tris = tris;
    int keep = round / 5 % 2;
    tr_facets fc;
    EXPECT(tr_facets_build(&plc, keep, &fc) == TR_OK, "facets: %s", tr_last_error());
    static uint8_t want_thin[NT], got_thin[NT], got2_thin[NT];
    tr_quality_thin want, got, got2;
    thin_by_definition(&plc, &fc, corner, want_thin, &want);
    tr_facets_thin_triangles(&plc, &fc, corner, got_thin, &got);
    EXPECT(tr_plc_thin_triangles(&plc, keep, corner, got2_thin, &got2) == TR_OK, "thin: %s",
           tr_last_error());
    EXPECT(same_thin(&got, &want) && !memcmp(got_thin, want_thin, nt),
           "round %d (corner %g): facets path %llu thin, thinnest %u at %a; definition %llu, "
           "%u at %a", round, corner, (unsigned long long)got.triangles, got.thinnest,
           got.thinnest_angle, (unsigned long long)want.triangles, want.thinnest,
           want.thinnest_angle);
    EXPECT(same_thin(&got2, &want) && !memcmp(got2_thin, want_thin, nt),
           "round %d (corner %g): plc path %llu thin, thinnest %u at %a; definition %llu, "
           "%u at %a", round, corner, (unsigned long long)got2.triangles, got2.thinnest,
           got2.thinnest_angle, (unsigned long long)want.triangles, want.thinnest,
           want.thinnest_angle);
    seen_thin += want.triangles;
    seen_merged += fc.nmerged;
    tr_facets_free(&fc);
    rounds++;
  }
  EXPECT(seen_thin > 500 && seen_merged > 20, "thin triangles %llu, merged facets %llu",
         (unsigned long long)seen_thin, (unsigned long long)seen_merged);
}

int main(int argc, char **argv)
{
  static const texpect_case cases[] = {
      {"thin_prism", prism_with_thin_ends, NULL},
      {"merged", merged_thin_triangles_do_not_count, NULL},
      {"cube", cube_has_no_thin_triangle, NULL},
      {"cos_angle", cos_angle_equals_definition, NULL},
      {"tri_cos", tri_cos_angles_equal_cos_angle, NULL},
      {"lazy", lazy_thin_triangles_equal_the_definition, NULL},
  };
  return texpect_main(argc, argv, cases, sizeof cases / sizeof *cases);
}
