/* Facet recovery on meshes (src/recover_facets/facet.c, recover_facets.c).
 *
 * Modes (argv[1]):
 *   swap32      hand-built bipyramid: the ring triangle is pierced by AB, whose shell has
 *               3 tets: recovered by Swap32 (2 tets); the same with Swap32 disabled goes
 *               through three ONE_EDG clusterels.
 *   cases       random Delaunay meshes: every triangle of mesh edges that is not a face
 *               is recovered alone on a fresh mesh; triangles with THR_EDG / FOU_EDG
 *               clusterels once per imposed S/Z pattern on the first such clusterel, so
 *               every Table 11 / 12 case runs on a mesh. Each run is checked: validator
 *               (links, positive tets, v2t, Euler), exact volume unchanged, every new
 *               point either exactly inside the open facet or (H) off its plane, and the
 *               facet exactly covered by mesh faces (brute force over all faces, exact
 *               area sum). Asserts every clusterel type and case was used.
 *   e2e         convex polyhedron (hull of random points) inside a cloud of other
 *               points: edges recovered with tr_recover_edge, then tr_recover_facets;
 *               every input triangle exactly covered by its listed sub-faces.
 *   lattice     the same on small integer coordinates: vertices exactly on facets and
 *               edges, coplanar faces.
 *   cavity K F  cavity retriangulation (cavity.h) on random clouds of kind K (0 integer
 *               grid, 1 grid moved by ulps, 2 nearly flat), after the flips (F = 1) or
 *               right after Swap32 (F = 0): see test_cavity.
 *   degenerate  a collinear input triangle: TR_ERR_UNSUPPORTED naming the facet.
 *   determinism the whole edges + facets run twice on one input: identical tets and
 *               sub-faces.
 * TETREC_FACET_TEST_SCALE in (0,1] scales the random modes down (sanitizer builds).
 */
#include <gmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "qgeom.h"
#include "recover_edges/pipe.h"
#include "recover_facets/cluster.h"
#include "recover_facets/facet.h"
#include "recover_facets/recover_facets.h"

static int fails;
#define CHECK(cond, ...)            \
  do {                              \
    if (!(cond)) {                  \
      fprintf(stderr, "FAIL: ");    \
      fprintf(stderr, __VA_ARGS__); \
      fputc('\n', stderr);          \
      fails++;                      \
    }                               \
  } while (0)

static double test_scale(void)
{
  const char *e = getenv("TETREC_FACET_TEST_SCALE");
  double x = e ? atof(e) : 1.0;
  return x > 0 && x <= 1 ? x : 1.0;
}

static int scaled(int n)
{
  int r = (int)(n * test_scale() + 0.5);
  return r < 1 ? 1 : r;
}

static int cmp_u64(const void *a, const void *b)
{
  uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
  return (x > y) - (x < y);
}

static uint64_t key2(uint32_t a, uint32_t b)
{
  return a < b ? ((uint64_t)a << 32) | b : ((uint64_t)b << 32) | a;
}

static uint64_t key3(uint32_t a, uint32_t b, uint32_t c)
{
  uint32_t t;
  if (a > b) { t = a; a = b; b = t; }
  if (b > c) { t = b; b = c; c = t; }
  if (a > b) { t = a; a = b; b = t; }
  return ((uint64_t)a << 42) | ((uint64_t)b << 21) | c;
}

static int has(const uint64_t *s, size_t n, uint64_t k)
{
  return bsearch(&k, s, n, sizeof k, cmp_u64) != NULL;
}

/* Sorted edge and face keys of the real tets. */
static void mesh_sets(const struct tr_mesh *m, uint64_t **edges, size_t *ne, uint64_t **faces,
                      size_t *nf)
{
  size_t cap = 6 * (size_t)m->nt + 1;
  *edges = malloc(cap * sizeof **edges);
  *faces = malloc(cap * sizeof **faces);
  *ne = *nf = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    for (int a = 0; a < 4; a++)
      for (int b = a + 1; b < 4; b++)
        (*edges)[(*ne)++] = key2(v[a], v[b]);
    for (int k = 0; k < 4; k++)
      (*faces)[(*nf)++] = key3(v[tr_face_vtx[k][0]], v[tr_face_vtx[k][1]], v[tr_face_vtx[k][2]]);
  }
  qsort(*edges, *ne, sizeof **edges, cmp_u64);
  qsort(*faces, *nf, sizeof **faces, cmp_u64);
}

/* out = doubled projected signed area of abc (axes drop+1, drop+2). */
static void parea(const struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t c, int drop, mpq_t out)
{
  tr_point p[3] = {tr_mesh_point(m, a), tr_mesh_point(m, b), tr_mesh_point(m, c)};
  mpq_t x[3], y[3], t;
  int i = (drop + 1) % 3, j = (drop + 2) % 3;
  for (int k = 0; k < 3; k++) {
    mpq_init(x[k]);
    mpq_init(y[k]);
    tr_point_get_q(&p[k], i, x[k]);
    tr_point_get_q(&p[k], j, y[k]);
  }
  mpq_init(t);
  for (int k = 1; k < 3; k++) {
    mpq_sub(x[k], x[k], x[0]);
    mpq_sub(y[k], y[k], y[0]);
  }
  mpq_mul(out, x[1], y[2]);
  mpq_mul(t, y[1], x[2]);
  mpq_sub(out, out, t);
  for (int k = 0; k < 3; k++) {
    mpq_clear(x[k]);
    mpq_clear(y[k]);
  }
  mpq_clear(t);
}

static int axis_of(const struct tr_mesh *m, uint32_t e, uint32_t f, uint32_t g)
{
  tr_point p[3] = {tr_mesh_point(m, e), tr_mesh_point(m, f), tr_mesh_point(m, g)};
  for (int d = 0; d < 3; d++)
    if (tr_orient2d_proj_p(&p[0], &p[1], &p[2], d))
      return d;
  return -1;
}

static int in_closed(const struct tr_mesh *m, uint32_t v, uint32_t e, uint32_t f, uint32_t g)
{
  tr_point p = tr_mesh_point(m, v), a = tr_mesh_point(m, e), b = tr_mesh_point(m, f),
           c = tr_mesh_point(m, g);
  return tr_classify_point_triangle(&p, &a, &b, &c).type != TR_DEG;
}

/* Brute force: the mesh faces inside the closed triangle efg cover it exactly (their
 * exact projected areas sum to its area; mesh faces never overlap). */
static int covered_brute(const struct tr_mesh *m, uint32_t e, uint32_t f, uint32_t g)
{
  int drop = axis_of(m, e, f, g);
  uint64_t *edges, *faces;
  size_t ne, nf;
  mesh_sets(m, &edges, &ne, &faces, &nf);
  mpq_t sum, a;
  mpq_init(sum);
  mpq_init(a);
  for (size_t i = 0; i < nf; i++) {
    if (i > 0 && faces[i] == faces[i - 1])
      continue;
    uint32_t w[3] = {(uint32_t)(faces[i] >> 42), (uint32_t)(faces[i] >> 21) & 0x1fffff,
                     (uint32_t)faces[i] & 0x1fffff};
    if (!in_closed(m, w[0], e, f, g) || !in_closed(m, w[1], e, f, g) ||
        !in_closed(m, w[2], e, f, g))
      continue;
    parea(m, w[0], w[1], w[2], drop, a);
    mpq_abs(a, a);
    mpq_add(sum, sum, a);
  }
  parea(m, e, f, g, drop, a);
  mpq_abs(a, a);
  int ok = mpq_equal(sum, a);
  mpq_clear(sum);
  mpq_clear(a);
  free(edges);
  free(faces);
  return ok;
}

/* One facet on a mesh, with every check of the "cases" mode. */
static void run_one(struct tr_mesh *m, uint32_t e, uint32_t f, uint32_t g,
                    const tr_facet_opts *o, tr_facet_detail *d, const char *what, int *outcome)
{
  mpq_t vol;
  mpq_init(vol);
  tr_mesh_volume6(m, vol);
  uint32_t nv0 = m->nv;
  uint64_t st0 = d->steiner, h0 = d->h_points;
  tr_status s = tr_recover_facet(m, 0, e, f, g, o, d, outcome, NULL);
  CHECK(s == TR_OK, "%s: recovery failed: %s", what, tr_last_error());
  if (s == TR_OK) {
    s = tr_check_mesh(m, TR_CHK_TOPOLOGY, vol);
    CHECK(s == TR_OK, "%s: validator (links, orientation, v2t, Euler, exact volume): %s",
          what, tr_last_error());
    uint64_t on = 0, off = 0;
    tr_point pe = tr_mesh_point(m, e), pf = tr_mesh_point(m, f), pg = tr_mesh_point(m, g);
    for (uint32_t v = nv0; v < m->nv; v++) {
      tr_point p = tr_mesh_point(m, v);
      if (tr_orient3d_p(&pe, &pf, &pg, &p) == 0) {
        CHECK(tr_classify_point_triangle(&p, &pe, &pf, &pg).type == TR_FAC,
              "%s: Steiner point %u on the plane but not inside the open facet", what, v);
        on++;
      } else {
        off++;
      }
    }
    CHECK(on == d->steiner - st0 && off == d->h_points - h0,
          "%s: %lu points on the facet, %lu off it; counted %lu Steiner, %lu H", what,
          (unsigned long)on, (unsigned long)off, (unsigned long)(d->steiner - st0),
          (unsigned long)(d->h_points - h0));
    CHECK(covered_brute(m, e, f, g), "%s: facet not exactly covered by mesh faces", what);
  }
  mpq_clear(vol);
}

static int test_swap32(void)
{
  /* ring C, D, E in z = 0 around the axis; A, B close enough that AB is Delaunay */
  const double xyz[] = {0, 0, 0.5, 0, 0, -0.5, 1, 0, 0, -1, 1, 0, -1, -1, 0};
  for (int noswap = 0; noswap < 2; noswap++) {
    struct tr_mesh *m = NULL;
    CHECK(tr_delaunay_build(xyz, 5, &m) == TR_OK, "swap32: delaunay: %s", tr_last_error());
    if (!m)
      return 1;
    CHECK(tr_mesh_count_real(m) == 3, "swap32: expected 3 tets around AB, got %u",
          tr_mesh_count_real(m));
    tr_facet_detail d = {0};
    tr_facet_opts o = {0};
    o.no_swap = noswap;
    int outcome = -1;
    run_one(m, 2, 3, 4, &o, &d, noswap ? "ONE_EDG x3 (Swap32 off)" : "Swap32", &outcome);
    if (!noswap) {
      CHECK(outcome == TR_FACET_BY_SWAP32 && d.swap32 == 1 && d.steiner == 0,
            "swap32: outcome %d, swaps %lu, points %lu", outcome, (unsigned long)d.swap32,
            (unsigned long)d.steiner);
      CHECK(tr_mesh_count_real(m) == 2, "swap32: %u tets after Swap32 (expected 2)",
            tr_mesh_count_real(m));
    } else {
      CHECK(outcome == TR_FACET_BY_CLUSTER && d.by_type[TR_ONE_EDG] == 3 && d.steiner == 1,
            "one_edg: outcome %d, ONE_EDG %lu, points %lu", outcome,
            (unsigned long)d.by_type[TR_ONE_EDG], (unsigned long)d.steiner);
      CHECK(tr_mesh_count_real(m) == 6, "one_edg: %u tets (expected 6)", tr_mesh_count_real(m));
    }
    printf("%s: outcome %d, %u tets, %lu points\n", noswap ? "Swap32 off" : "Swap32", outcome,
           tr_mesh_count_real(m), (unsigned long)d.steiner);
    tr_mesh_destroy(m);
  }
  return 0;
}

static void print_detail(const char *mode, const tr_facet_detail *d)
{
  printf("%s: clusterels ONE %lu TWO %lu (S %lu Z %lu) THR %lu FOU %lu; swap32 %lu; "
         "points %lu + H %lu\n  Table 11:", mode, (unsigned long)d->by_type[1],
         (unsigned long)d->by_type[2], (unsigned long)d->two_s, (unsigned long)d->two_z,
         (unsigned long)d->by_type[3], (unsigned long)d->by_type[4], (unsigned long)d->swap32,
         (unsigned long)d->steiner, (unsigned long)d->h_points);
  for (int i = 0; i < TR_NUM_THR_EDG; i++)
    printf(" %s %lu", tr_thr_edg_cases[i].name, (unsigned long)d->thr_case[i]);
  printf("\n  Table 12:");
  for (int i = 0; i < TR_NUM_FOU_EDG; i++)
    printf(" %s %lu", tr_fou_edg_cases[i].name, (unsigned long)d->fou_case[i]);
  printf("\n");
}

static int test_cases(void)
{
  tr_facet_detail d = {0};
  long runs = 0, tris = 0;
  int nseeds = scaled(8);
  for (int seed = 0; seed < nseeds; seed++) {
    uint64_t rs = 0x5eedf00dull + (uint64_t)seed * 0x9e3779b97f4a7c15ull;
    enum { N = 40 };
    double xyz[3 * N];
    for (int i = 0; i < 3 * N; i++)
      xyz[i] = (double)rng_range(&rs, 0, 40);
    struct tr_mesh *m = NULL;
    if (tr_delaunay_build(xyz, N, &m) != TR_OK) {
      CHECK(0, "cases: delaunay %d: %s", seed, tr_last_error());
      continue;
    }
    uint64_t *edges, *faces;
    size_t ne, nf;
    mesh_sets(m, &edges, &ne, &faces, &nf);
    int multi = 0, plain = 0, maxmulti = scaled(6), maxplain = scaled(10);
    for (size_t i = 0; i < ne && (multi < maxmulti || plain < maxplain); i++) {
      if (i > 0 && edges[i] == edges[i - 1])
        continue;
      uint32_t a = (uint32_t)(edges[i] >> 32), b = (uint32_t)edges[i];
      for (uint32_t c = b + 1; c < m->nv; c++) {
        if (!has(edges, ne, key2(a, c)) || !has(edges, ne, key2(b, c)) ||
            has(faces, nf, key3(a, b, c)) || axis_of(m, a, b, c) < 0)
          continue;
        tr_clusterel *cl = NULL;
        uint32_t ncl = 0;
        if (tr_cluster_collect(m, a, b, c, &cl, &ncl) != TR_OK)
          continue;
        int mt = 0;
        for (uint32_t k = 0; k < ncl; k++)
          mt = cl[k].type > mt ? cl[k].type : mt;
        free(cl);
        int npat = mt >= TR_THR_EDG ? 16 : 1;
        if (npat == 16 ? multi >= maxmulti : plain >= maxplain)
          continue;
        npat == 16 ? multi++ : plain++;
        tris++;
        for (int p = 0; p < npat; p++) {
          struct tr_mesh *w = NULL;
          if (tr_delaunay_build(xyz, N, &w) != TR_OK)
            continue;
          tr_facet_opts o = {0};
          o.no_swap = p & 1; /* both paths on Swap32 configurations */
          o.no_flips = 1;    /* this mode covers the clusterel tables */
          o.no_cavity = 1;
          o.force_on = npat == 16;
          o.force_first = p;
          char what[96];
          snprintf(what, sizeof what, "cases seed %d triangle %u %u %u pattern %d", seed, a, b,
                   c, p);
          int outcome;
          run_one(w, a, b, c, &o, &d, what, &outcome);
          CHECK(outcome != TR_FACET_PRESENT, "%s: a missing triangle reported present", what);
          runs++;
          tr_mesh_destroy(w);
        }
      }
    }
    free(edges);
    free(faces);
    tr_mesh_destroy(m);
  }
  printf("cases: %ld triangles, %ld recoveries\n", tris, runs);
  print_detail("cases", &d);
  for (int t = TR_ONE_EDG; t <= TR_FOU_EDG; t++)
    CHECK(d.by_type[t] > 0, "cases: clusterel type %d never decomposed", t);
  CHECK(d.two_s > 0 && d.two_z > 0, "cases: TWO_EDG S or Z never used");
  if (test_scale() == 1.0) {
    for (int i = 0; i < TR_NUM_THR_EDG; i++)
      CHECK(d.thr_case[i] > 0, "cases: Table 11 %s never used on a mesh", tr_thr_edg_cases[i].name);
    for (int i = 0; i < TR_NUM_FOU_EDG; i++)
      CHECK(d.fou_case[i] > 0, "cases: Table 12 %s never used on a mesh", tr_fou_edg_cases[i].name);
  }
  return 0;
}

/* Random point clouds of three kinds: integer grid points (cospherical and coplanar
 * ties everywhere), the same moved by 0-2 ulps per coordinate, and a nearly flat cloud
 * (z = k * 2^-30, near-coplanar tets around every facet). */
static void cloud(int kind, uint64_t *rs, double *xyz, int n)
{
  for (int i = 0; i < n; i++)
    for (int j = 0; j < 3; j++) {
      double x = (double)rng_range(rs, 0, 40);
      if (kind == 2 && j == 2)
        x = ldexp(x, -30);
      if (kind == 1)
        for (long k = rng_range(rs, 0, 2); k > 0; k--)
          x = nextafter(x, rng_range(rs, 0, 1) ? 100.0 : -100.0);
      xyz[3 * i + j] = x;
    }
}

/* Cavity retriangulation (cavity.h): every triangle of mesh edges that is not a face is
 * recovered alone on a fresh Delaunay mesh with the default path (Swap32, flips, cavity,
 * clusterels; flips_first = 0: Swap32, cavity, clusterels). Each run goes through the
 * checks of run_one. A facet the cavity recovered must have cost no vertex; recovered
 * again with the cavity off, it must go to the clusterels (the flips really failed on it)
 * and cost Steiner points. The cavity path must have been taken on every kind of cloud. */
static int test_cavity(int kind, int flips)
{
  static const char *kinds[] = {"grid", "ulps", "flat"};
  tr_facet_detail d = {0}, dc = {0};
  long count[5] = {0}, saved = 0;
  int nseeds = scaled(10);
  for (int seed = 0; seed < nseeds; seed++) {
    uint64_t rs = 0xca71f00dull + (uint64_t)seed * 0x9e3779b97f4a7c15ull + (uint64_t)kind;
    enum { N = 36 };
    double xyz[3 * N];
    cloud(kind, &rs, xyz, N);
    struct tr_mesh *m = NULL;
    if (tr_delaunay_build(xyz, N, &m) != TR_OK) {
      CHECK(0, "cavity %s: delaunay %d: %s", kinds[kind], seed, tr_last_error());
      continue;
    }
    uint64_t *edges, *faces;
    size_t ne, nf;
    mesh_sets(m, &edges, &ne, &faces, &nf);
    int tried = 0, maxtried = scaled(30);
    for (size_t i = 0; i < ne && tried < maxtried; i++) {
      if (i > 0 && edges[i] == edges[i - 1])
        continue;
      uint32_t a = (uint32_t)(edges[i] >> 32), b = (uint32_t)edges[i];
      for (uint32_t c = b + 1; c < m->nv && tried < maxtried; c++) {
        if (!has(edges, ne, key2(a, c)) || !has(edges, ne, key2(b, c)) ||
            has(faces, nf, key3(a, b, c)) || axis_of(m, a, b, c) < 0)
          continue;
        tried++;
        struct tr_mesh *w = NULL;
        if (tr_delaunay_build(xyz, N, &w) != TR_OK)
          continue;
        tr_facet_opts o = {0};
        o.no_flips = !flips;
        char what[96];
        snprintf(what, sizeof what, "cavity %s seed %d triangle %u %u %u", kinds[kind], seed, a,
                 b, c);
        int outcome = -1;
        uint32_t nv0 = w->nv;
        uint64_t rec0 = d.cavity.recovered;
        run_one(w, a, b, c, &o, &d, what, &outcome);
        if (outcome == TR_FACET_BY_CAVITY) {
          /* deterministic: the same input gives the same tets, slot for slot */
          struct tr_mesh *w2 = NULL;
          int out3 = -1;
          tr_facet_detail d3 = {0};
          if (tr_delaunay_build(xyz, N, &w2) == TR_OK &&
              tr_recover_facet(w2, 0, a, b, c, &o, &d3, &out3, NULL) == TR_OK)
            CHECK(out3 == outcome && w2->nt == w->nt &&
                  !memcmp(w2->tv, w->tv, 4 * sizeof *w->tv * (size_t)w->nt),
                  "%s: a second run gave other tets", what);
          else
            CHECK(0, "%s: second run failed: %s", what, tr_last_error());
          tr_mesh_destroy(w2);
        }
        tr_mesh_destroy(w);
        if (outcome < 0 || outcome > 4)
          continue;
        count[outcome]++;
        CHECK((outcome == TR_FACET_BY_CAVITY) == (d.cavity.recovered == rec0 + 1),
              "%s: outcome %d but cavity count %lu -> %lu", what, outcome,
              (unsigned long)rec0, (unsigned long)d.cavity.recovered);
        if (outcome != TR_FACET_BY_CAVITY)
          continue;
        /* the same facet without the cavity path */
        if (tr_delaunay_build(xyz, N, &w) != TR_OK)
          continue;
        CHECK(w->nv == nv0, "%s: vertices changed", what);
        o.no_cavity = 1;
        int out2 = -1;
        uint64_t st0 = dc.steiner;
        run_one(w, a, b, c, &o, &dc, what, &out2);
        CHECK(out2 == TR_FACET_BY_CLUSTER && dc.steiner > st0,
              "%s: without the cavity: outcome %d, %lu Steiner points", what, out2,
              (unsigned long)(dc.steiner - st0));
        saved += (long)(dc.steiner - st0 + dc.h_points);
        tr_mesh_destroy(w);
      }
    }
    free(edges);
    free(faces);
    tr_mesh_destroy(m);
  }
  printf("cavity %s (%s): outcomes: Swap32 %ld, flips %ld, cavity %ld, clusterels %ld; cavity "
         "tried %lu, recovered %lu, tets added by expansion %lu, failed on a boundary face "
         "%lu, otherwise %lu; the clusterels would have put %ld points on those facets\n",
         kinds[kind], flips ? "after flips" : "flips off", count[TR_FACET_BY_SWAP32],
         count[TR_FACET_BY_FLIPS], count[TR_FACET_BY_CAVITY], count[TR_FACET_BY_CLUSTER],
         (unsigned long)d.cavity.tried, (unsigned long)d.cavity.recovered,
         (unsigned long)d.cavity.expanded, (unsigned long)d.cavity.failed_boundary,
         (unsigned long)d.cavity.failed_other, saved);
  CHECK(count[TR_FACET_BY_CAVITY] > 0, "cavity %s: the cavity path was never taken",
        kinds[kind]);
  CHECK(d.steiner == (uint64_t)0 || count[TR_FACET_BY_CLUSTER] > 0,
        "cavity %s: Steiner points without a clusterel outcome", kinds[kind]);
  return 0;
}

/* The hull triangles of the first n1 points (their Delaunay mesh's ghost faces). */
static uint32_t hull_tris(const double *xyz, uint32_t n1, uint32_t **tris)
{
  struct tr_mesh *h = NULL;
  *tris = NULL;
  if (tr_delaunay_build(xyz, n1, &h) != TR_OK)
    return 0;
  uint32_t n = 0;
  *tris = malloc(3 * (size_t)h->nt * sizeof **tris);
  for (uint32_t t = 0; t < h->nt; t++)
    if (!tr_tet_is_free(h, t) && tr_tet_is_ghost(h, t)) {
      for (int q = 0; q < 3; q++)
        (*tris)[3 * n + q] = h->tv[4 * (size_t)t + (size_t)q];
      n++;
    }
  tr_mesh_destroy(h);
  return n;
}

static int test_e2e(int lattice)
{
  const char *mode = lattice ? "lattice" : "e2e";
  tr_facet_recovery_stats tot = {0};
  long ntri = 0, nsub = 0, edge_fail = 0, on_bnd = 0, in_face = 0;
  int nseeds = scaled(lattice ? 8 : 8);
  for (int seed = 0; seed < nseeds; seed++) {
    uint64_t rs = (lattice ? 0x1a77ull : 0xe2e0ull) + (uint64_t)seed * 0x9e3779b97f4a7c15ull;
#ifndef E2E_N1 /* hull points, all points; a bigger run: -DE2E_N1=.. -DE2E_N=.. */
#define E2E_N1 24
#define E2E_N 160
#endif
    enum { N1 = E2E_N1, N = E2E_N };
    double xyz[3 * N];
    long r1 = lattice ? 5 : 1000, r2 = lattice ? 7 : 1400;
    /* distinct points (vertex i = point i) */
    for (uint32_t i = 0; i < N; i++) {
      int dup;
      do {
        long r = i < N1 ? r1 : r2;
        for (int k = 0; k < 3; k++)
          xyz[3 * i + k] = (double)rng_range(&rs, -r, r);
        dup = 0;
        for (uint32_t j = 0; j < i && !dup; j++)
          dup = xyz[3 * j] == xyz[3 * i] && xyz[3 * j + 1] == xyz[3 * i + 1] &&
                xyz[3 * j + 2] == xyz[3 * i + 2];
      } while (dup);
    }
    uint32_t *tris;
    uint32_t nt = hull_tris(xyz, N1, &tris);
    struct tr_mesh *m = NULL;
    if (nt == 0 || tr_delaunay_build(xyz, N, &m) != TR_OK) {
      CHECK(0, "%s %d: delaunay failed: %s", mode, seed, tr_last_error());
      free(tris);
      continue;
    }
    uint64_t *ed = malloc(3 * (size_t)nt * sizeof *ed);
    for (uint32_t i = 0; i < nt; i++)
      for (int q = 0; q < 3; q++)
        ed[3 * i + q] = key2(tris[3 * i + q], tris[3 * i + (q + 1) % 3]);
    qsort(ed, 3 * (size_t)nt, sizeof *ed, cmp_u64);
    /* the unique edges, sorted, as the pipeline hands them to the edge stage; its chains
     * go to the facet stage, which keeps their pieces (TR_NONE-free pairs) */
    uint32_t *pairs = malloc(6 * (size_t)nt * sizeof *pairs), ne = 0;
    for (size_t i = 0; i < 3 * (size_t)nt; i++)
      if (i == 0 || ed[i] != ed[i - 1]) {
        pairs[2 * ne] = (uint32_t)(ed[i] >> 32);
        pairs[2 * ne + 1] = (uint32_t)ed[i];
        ne++;
      }
    free(ed);
    int ok = 1;
    tr_edge_chains chains = {0};
    tr_edge_recovery_stats es = {0};
    if (tr_recover_edges(m, pairs, ne, &chains, &es) != TR_OK) {
      /* edge recovery is another stage's job: counted, not a failure here */
      printf("%s %d: edge recovery failed (%s), mesh skipped\n", mode, seed, tr_last_error());
      edge_fail++;
      ok = 0;
    }
    free(pairs);
    if (ok) {
      mpq_t vol;
      mpq_init(vol);
      tr_mesh_volume6(m, vol);
      tr_subfaces sub = {0};
      tr_facet_recovery_stats st;
      tr_status s = tr_recover_facets(m, tris, nt, &chains, &sub, &st);
      CHECK(s == TR_OK, "%s %d: tr_recover_facets: %s", mode, seed, tr_last_error());
      if (s == TR_OK) {
        s = tr_check_mesh(m, TR_CHK_TOPOLOGY, vol);
        CHECK(s == TR_OK, "%s %d: validator after facet recovery: %s", mode, seed,
              tr_last_error());
        tot.missing_facets += st.missing_facets;
        tot.recovered_by_swap += st.recovered_by_swap;
        tot.points_added += st.points_added;
        ntri += nt;
        nsub += sub.n;
        /* every input triangle exactly covered by its sub-faces */
        uint64_t *edges, *faces;
        size_t ne, nf;
        mesh_sets(m, &edges, &ne, &faces, &nf);
        mpq_t sum, a;
        mpq_init(sum);
        mpq_init(a);
        uint32_t j = 0;
        for (uint32_t i = 0; i < nt; i++) {
          uint32_t e = tris[3 * i], f = tris[3 * i + 1], g = tris[3 * i + 2];
          int drop = axis_of(m, e, f, g);
          parea(m, e, f, g, drop, a);
          int sg = mpq_sgn(a);
          mpq_set_ui(sum, 0, 1);
          uint32_t j0 = j;
          for (; j < sub.n && sub.tri[j] == i; j++) {
            const uint32_t *w = sub.v + 3 * j;
            CHECK(has(faces, nf, key3(w[0], w[1], w[2])), "%s %d: sub-face %u of triangle %u "
                  "is not a mesh face", mode, seed, j, i);
            CHECK(in_closed(m, w[0], e, f, g) && in_closed(m, w[1], e, f, g) &&
                  in_closed(m, w[2], e, f, g), "%s %d: sub-face %u outside triangle %u", mode,
                  seed, j, i);
            CHECK(j == j0 || memcmp(w - 3, w, 3 * sizeof *w) != 0, "%s %d: sub-face listed twice",
                  mode, seed);
            for (int q = 0; q < 3; q++) { /* degenerate configurations met (a count) */
              tr_point p = tr_mesh_point(m, w[q]), pe = tr_mesh_point(m, e),
                       pf = tr_mesh_point(m, f), pg = tr_mesh_point(m, g);
              int ty = tr_classify_point_triangle(&p, &pe, &pf, &pg).type;
              on_bnd += ty == TR_EDG;
              in_face += ty == TR_FAC && w[q] < N;
            }
            mpq_t b;
            mpq_init(b);
            parea(m, w[0], w[1], w[2], drop, b);
            CHECK(mpq_sgn(b) == sg, "%s %d: sub-face %u not oriented like triangle %u", mode,
                  seed, j, i);
            mpq_add(sum, sum, b);
            mpq_clear(b);
          }
          CHECK(j > j0 && mpq_equal(sum, a), "%s %d: triangle %u (%u %u %u) not exactly "
                "covered by its %u sub-faces", mode, seed, i, e, f, g, j - j0);
        }
        CHECK(j == sub.n, "%s %d: sub-faces not sorted by triangle", mode, seed);
        mpq_clear(sum);
        mpq_clear(a);
        free(edges);
        free(faces);
      }
      tr_subfaces_free(&sub);
      mpq_clear(vol);
    }
    tr_edge_chains_free(&chains);
    free(tris);
    tr_mesh_destroy(m);
  }
  printf("%s: %ld triangles, %lu missing after edges, %lu by Swap32, %lu points added, %ld "
         "sub-faces; %ld meshes skipped (edge recovery failed)\n", mode, ntri,
         (unsigned long)tot.missing_facets, (unsigned long)tot.recovered_by_swap,
         (unsigned long)tot.points_added, nsub, edge_fail);
  printf("%s: sub-face corners on a facet's boundary edge (chain vertices) %ld, input points "
         "inside a facet %ld\n", mode, on_bnd, in_face);
  CHECK(on_bnd > 0, "%s: no facet with a chain vertex on its boundary exercised", mode);
  if (lattice)
    CHECK(in_face > 0, "%s: no input point inside a facet exercised", mode);
  CHECK(ntri > 0 && tot.missing_facets > 0, "%s: nothing exercised", mode);
  return 0;
}

/* Edges then facets of the hull of the first n1 points on the mesh of all n; exports the
 * final tets and sub-faces. 0 on success. */
static int pipeline_once(const double *xyz, uint32_t n1, uint32_t n, uint32_t **tets,
                         uint32_t *ntets, tr_subfaces *sub)
{
  uint32_t *tris;
  uint32_t nt = hull_tris(xyz, n1, &tris);
  struct tr_mesh *m = NULL;
  int bad = nt == 0 || tr_delaunay_build(xyz, n, &m) != TR_OK;
  for (uint32_t i = 0; i < 3 * nt && !bad; i++) {
    tr_edge_stats es = {0};
    bad = tr_recover_edge(m, tris[i], tris[i - i % 3 + (i + 1) % 3], &es) != TR_OK;
  }
  tr_facet_recovery_stats st;
  bad = bad || tr_recover_facets(m, tris, nt, NULL, sub, &st) != TR_OK ||
        tr_mesh_export_tets(m, tets, ntets) != TR_OK;
  free(tris);
  tr_mesh_destroy(m);
  return bad;
}

/* Same input, same output byte for byte: two runs of the same pipeline. */
static int test_determinism(void)
{
  enum { N1 = 24, N = 200 };
  double xyz[3 * N];
  uint64_t rs = 0xde7e;
  for (int i = 0; i < 3 * N; i++) /* a few duplicates are fine: hull ids stay < N1 */
    xyz[i] = (double)rng_range(&rs, i < 3 * N1 ? -1000 : -1400, i < 3 * N1 ? 1000 : 1400);
  uint32_t *t[2] = {NULL, NULL}, nt[2] = {0, 0};
  tr_subfaces sub[2] = {{0}, {0}};
  for (int r = 0; r < 2; r++)
    CHECK(pipeline_once(xyz, N1, N, &t[r], &nt[r], &sub[r]) == 0, "determinism: run %d failed: %s",
          r, tr_last_error());
  CHECK(nt[0] == nt[1] && !memcmp(t[0], t[1], 4 * (size_t)nt[0] * sizeof *t[0]),
        "determinism: the two runs give different tets");
  CHECK(sub[0].n == sub[1].n && sub[0].n > 0 &&
        !memcmp(sub[0].v, sub[1].v, 3 * (size_t)sub[0].n * sizeof *sub[0].v) &&
        !memcmp(sub[0].tri, sub[1].tri, (size_t)sub[0].n * sizeof *sub[0].tri),
        "determinism: the two runs give different sub-faces");
  printf("determinism: %u tets, %u sub-faces, identical in both runs\n", nt[0], sub[0].n);
  for (int r = 0; r < 2; r++) {
    free(t[r]);
    tr_subfaces_free(&sub[r]);
  }
  return 0;
}

static int test_degenerate(void)
{
  const double xyz[] = {0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4, 2, 0, 0, 1, 1, 1};
  struct tr_mesh *m = NULL;
  CHECK(tr_delaunay_build(xyz, 6, &m) == TR_OK, "degenerate: delaunay: %s", tr_last_error());
  if (!m)
    return 0;
  const uint32_t tris[] = {0, 1, 3, 0, 4, 1}; /* the second is collinear */
  tr_facet_recovery_stats st;
  tr_subfaces sub = {0};
  tr_status s = tr_recover_facets(m, tris, 2, NULL, &sub, &st);
  const char *msg = tr_last_error();
  printf("degenerate: status %d, message \"%s\"\n", (int)s, msg);
  CHECK(s == TR_ERR_UNSUPPORTED && strstr(msg, "facet 1 (0 4 1) is degenerate"),
        "degenerate: expected TR_ERR_UNSUPPORTED naming facet 1");
  tr_subfaces_free(&sub);
  tr_mesh_destroy(m);
  return 0;
}

int main(int argc, char **argv)
{
  const char *mode = argc > 1 ? argv[1] : "";
  if (!strcmp(mode, "swap32"))
    test_swap32();
  else if (!strcmp(mode, "cases"))
    test_cases();
  else if (!strcmp(mode, "e2e"))
    test_e2e(0);
  else if (!strcmp(mode, "lattice"))
    test_e2e(1);
  else if (!strcmp(mode, "cavity") && argc > 3)
    test_cavity(atoi(argv[2]), atoi(argv[3]));
  else if (!strcmp(mode, "degenerate"))
    test_degenerate();
  else if (!strcmp(mode, "determinism"))
    test_determinism();
  else {
    fprintf(stderr, "usage: %s swap32|cases|e2e|lattice|degenerate|determinism\n", argv[0]);
    return 2;
  }
  if (fails)
    fprintf(stderr, "%s: %d failure(s)\n", mode, fails);
  return fails ? 1 : 0;
}
