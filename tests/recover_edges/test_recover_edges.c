/* End-to-end tests of the edge recovery stage (tr_recover_edges).
 * Usage: test_recover_edges <mode> [args]
 *
 * spheres <seed> <meshes>: the big test. Each mesh: three nested random convex
 *   polyhedra (points on spheres of radius 1, 2, 3; their hull edges are the input edges,
 *   non-crossing by construction) plus random points filling the cube around them, so
 *   many hull edges are not Delaunay edges. Validator and chain checks after each mesh's
 *   whole stage; the counters are printed. TETREC_EDGE_TEST_SCALE (default 1) scales the
 *   number of meshes (for sanitizer builds).
 * grid <n> <nseg> <seed> <incremental>: an n^3 integer grid with segments along lattice
 *   directions (through grid vertices, inside grid faces and planes, across edges),
 *   pairwise non-crossing (T-junctions allowed). incremental = 1: the stage is re-run
 *   after each new segment and the validator runs after every run.
 * crossing: two crossing input edges must give TR_ERR_SELF_INTERSECT naming an edge.
 * badinput: unsorted / degenerate / out of range edges give TR_ERR_INPUT.
 * equal_doubles: an edge between two Steiner points with the same nearest doubles.
 */
#include <gmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "classify.h"
#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "recover_edges/pipe.h"
#include "recover_edges/recover_edges.h"
#include "tedges.h"
#include "trand.h"

static const unsigned CHECKS = TR_CHK_TOPOLOGY;
/* recovery switches: zero (the default pipeline) except in the coverage mode */
static tr_edge_recovery_opts g_opt;

static const char *const KIND[TR_EDGE_PIPEL_KINDS] = {
    "case1(T5)", "case2-I(T6)", "case2-II-S(T6)", "case2-II-Z(T6)",
    "case3(T7)", "case4(T8)",   "case5(T9)"};

static double next_unit(void) { return (next_u32() + 0.5) / 2147483648.0; } /* (0,1) */

static int fail(const char *what, tr_status s)
{
  fprintf(stderr, "FAIL %s: %s: %s\n", what, tr_status_name(s), tr_last_error());
  return 1;
}

/* Every chain: from a to b, consecutive vertices are mesh edges, interior vertices lie
 * exactly in the open segment (TR_EDG) strictly ordered along it. Every Steiner point
 * added is inside exactly one chain (count). brute: also no mesh vertex on a segment is
 * missing from its chain (O(nv) per edge). */
static int check_chains(struct tr_mesh *m, const uint32_t *edges, uint32_t n,
                        const tr_edge_chains *ch, uint32_t nv_before,
                        const tr_edge_recovery_stats *st, int brute, const char *what)
{
  if (ch->n != n || ch->start[0] != 0) {
    fprintf(stderr, "FAIL %s: chains: n = %u for %u edges\n", what, ch->n, n);
    return 1;
  }
  if (m->nv - nv_before != st->points_added) {
    fprintf(stderr, "FAIL %s: %u vertices added, stats say %llu\n", what, m->nv - nv_before,
            (unsigned long long)st->points_added);
    return 1;
  }
  uint64_t steiner_in_chains = 0;
  for (uint32_t i = 0; i < n; i++) {
    uint32_t a = edges[2 * i], b = edges[2 * i + 1];
    const uint32_t *v = ch->v + ch->start[i];
    uint32_t len = ch->start[i + 1] - ch->start[i];
    if (len < 2 || v[0] != a || v[len - 1] != b) {
      fprintf(stderr, "FAIL %s: chain %u (%u-%u) has wrong ends or length %u\n", what, i, a, b,
              len);
      return 1;
    }
    if (tr_edge_chains_find(ch, edges, a, b) != i || tr_edge_chains_find(ch, edges, b, a) != i) {
      fprintf(stderr, "FAIL %s: tr_edge_chains_find(%u,%u) != %u\n", what, a, b, i);
      return 1;
    }
    tr_point pa = tr_mesh_point(m, a), pb = tr_mesh_point(m, b);
    int axis = tr_pipe_long_axis(&pa, &pb), dir = axis < 0 ? 0 : tr_cmp_coord_p(&pa, &pb, axis);
    for (uint32_t k = 0; k + 1 < len; k++) {
      int yes;
      if (tr_mesh_has_edge(m, v[k], v[k + 1], &yes) != TR_OK || !yes) {
        fprintf(stderr, "FAIL %s: chain %u (%u-%u): piece %u-%u is not a mesh edge\n", what,
                i, a, b, v[k], v[k + 1]);
        return 1;
      }
      tr_point p = tr_mesh_point(m, v[k]), q = tr_mesh_point(m, v[k + 1]);
      if (dir == 0 || tr_cmp_coord_p(&p, &q, axis) != dir) {
        fprintf(stderr, "FAIL %s: chain %u (%u-%u): %u, %u not strictly ordered\n", what, i,
                a, b, v[k], v[k + 1]);
        return 1;
      }
      if (k > 0) {
        if (tr_classify_point_segment(&p, &pa, &pb).type != TR_EDG) {
          fprintf(stderr, "FAIL %s: chain %u (%u-%u): vertex %u not exactly inside it\n",
                  what, i, a, b, v[k]);
          return 1;
        }
        steiner_in_chains += v[k] >= nv_before;
      }
    }
    if (brute) {
      uint32_t on = 0;
      for (uint32_t w = 0; w < m->nv; w++) {
        if (m->v2t[w] == TR_NONE)
          continue;
        tr_point pw = tr_mesh_point(m, w);
        on += tr_classify_point_segment(&pw, &pa, &pb).type == TR_EDG;
      }
      if (on != len - 2) {
        fprintf(stderr, "FAIL %s: chain %u (%u-%u) has %u inner vertices, %u lie on it\n",
                what, i, a, b, len - 2, on);
        return 1;
      }
    }
  }
  if (steiner_in_chains != st->points_added) {
    fprintf(stderr, "FAIL %s: %llu Steiner points in chains, %llu added\n", what,
            (unsigned long long)steiner_in_chains, (unsigned long long)st->points_added);
    return 1;
  }
  if (st->recovered_by_swap + st->through_vertices + st->recovered_by_steiner !=
      st->missing_edges) {
    fprintf(stderr, "FAIL %s: missing edges not accounted for\n", what);
    return 1;
  }
  return 0;
}

static void add_stats(tr_edge_recovery_stats *t, const tr_edge_recovery_stats *s)
{
  uint64_t *x = (uint64_t *)t;
  const uint64_t *y = (const uint64_t *)s;
  for (size_t i = 0; i < sizeof *t / sizeof(uint64_t); i++)
    x[i] += y[i];
}

static void print_stats(const char *what, uint64_t nedges, const tr_edge_recovery_stats *s)
{
  double miss = s->missing_edges ? (double)s->missing_edges : 1;
  printf("%s: %llu input edges, %llu missing; by swap %llu (%.1f%%), through vertices only "
         "%llu, with Steiner points %llu; Steiner points %llu (%.3f per missing edge); "
         "swap23 %llu, swap44 %llu, splits at vertices %llu, ghosts split %llu\n",
         what, (unsigned long long)nedges, (unsigned long long)s->missing_edges,
         (unsigned long long)s->recovered_by_swap, 100.0 * (double)s->recovered_by_swap / miss,
         (unsigned long long)s->through_vertices, (unsigned long long)s->recovered_by_steiner,
         (unsigned long long)s->points_added, (double)s->points_added / miss,
         (unsigned long long)s->swap23, (unsigned long long)s->swap44,
         (unsigned long long)s->split_at_vertex, (unsigned long long)s->ghosts_split);
  printf("%s: midpoint splits %llu, Lawson flips around them 2-3 %llu, 3-2 %llu, 4-4 %llu\n",
         what, (unsigned long long)s->midpoints, (unsigned long long)s->lawson_flip23,
         (unsigned long long)s->lawson_flip32, (unsigned long long)s->lawson_flip44);
  printf("%s: pipels decomposed per case:", what);
  for (int k = 0; k < TR_EDGE_PIPEL_KINDS; k++)
    printf(" %s %llu", KIND[k], (unsigned long long)s->pipels[k]);
  printf("\n%s: per raw type:", what);
  static const char *const T[4] = {"DEG", "NOD", "EDG", "FAC"};
  for (int k = 0; k < 16; k++)
    if (s->pipels_raw[k])
      printf(" %s_%s %llu", T[k & 3], T[k >> 2], (unsigned long long)s->pipels_raw[k]);
  printf("\n");
}

/* Runs the stage on m with the validator and the chain checks after it. */
static int run_stage(struct tr_mesh *m, const uint32_t *edges, uint32_t n, int brute,
                     int volume, const char *what, tr_edge_recovery_stats *st)
{
  mpq_t vol;
  mpq_init(vol);
  /* the exact volume sum over rational Steiner tets dominates the big test's time */
  tr_status s = volume ? tr_mesh_volume6(m, vol) : TR_OK;
  uint32_t nv0 = m->nv;
  tr_edge_chains ch;
  int bad = 0;
  if (s == TR_OK)
    s = tr_recover_edges_ex(m, edges, n, &g_opt, &ch, st);
  if (s != TR_OK) {
    bad = fail(what, s);
  } else {
    if ((s = tr_check_mesh(m, CHECKS, volume ? vol : NULL)) != TR_OK)
      bad = fail(what, s);
    else
      bad = check_chains(m, edges, n, &ch, nv0, st, brute, what);
    tr_edge_chains_free(&ch);
  }
  mpq_clear(vol);
  return bad;
}

/* Hull edges of the Delaunay mesh of pts (from its ghost tets), offset by base. */
static int hull_edges(const double *pts, uint32_t np, uint32_t base, uint32_t **e, uint32_t *ne,
                      uint32_t *cap)
{
  struct tr_mesh *h;
  tr_status s = tr_delaunay_build(pts, np, &h);
  if (s != TR_OK)
    return fail("hull", s);
  for (uint32_t t = 0; t < h->nt; t++) {
    if (tr_tet_is_free(h, t) || !tr_tet_is_ghost(h, t))
      continue;
    for (int k = 0; k < 3; k++) {
      if (*ne + 1 > *cap) {
        *cap = 2 * *cap + 64;
        *e = realloc(*e, 2 * (size_t)*cap * sizeof **e);
      }
      (*e)[2 * *ne] = base + h->tv[4 * (size_t)t + (size_t)k];
      (*e)[2 * *ne + 1] = base + h->tv[4 * (size_t)t + (size_t)(k + 1) % 3];
      ++*ne;
    }
  }
  tr_mesh_destroy(h);
  return 0;
}

static double test_scale(void)
{
  const char *e = getenv("TETREC_EDGE_TEST_SCALE");
  double x = e ? atof(e) : 1.0;
  return x > 0 && x <= 1 ? x : 1.0;
}

enum { SPHERES = 3, PER_SPHERE = 300, FILL = 1500 };

static int test_spheres(uint64_t seed, int meshes)
{
  meshes = (int)(meshes * test_scale() + 0.5);
  if (meshes < 1)
    meshes = 1;
  tr_edge_recovery_stats tot;
  memset(&tot, 0, sizeof tot);
  uint64_t total_edges = 0;
  uint32_t np = SPHERES * PER_SPHERE + FILL;
  double *xyz = malloc(3 * (size_t)np * sizeof *xyz);
  uint32_t *e = NULL, ne, cap = 0;
  for (int mi = 0; mi < meshes; mi++) {
    rng = seed * 1000003u + (uint64_t)mi;
    ne = 0;
    for (int sp = 0; sp < SPHERES; sp++) {
      double r = sp + 1.0;
      for (uint32_t j = 0; j < PER_SPHERE; j++) {
        double x, y, z, l;
        do {
          x = 2 * next_unit() - 1;
          y = 2 * next_unit() - 1;
          z = 2 * next_unit() - 1;
          l = x * x + y * y + z * z;
        } while (l > 1 || l < 0.01);
        double g = 1.0 / sqrt(l);
        double *p = xyz + 3 * ((size_t)sp * PER_SPHERE + j);
        p[0] = r * x * g;
        p[1] = r * y * g;
        p[2] = r * z * g;
      }
      if (hull_edges(xyz + 3 * (size_t)sp * PER_SPHERE, PER_SPHERE, (uint32_t)sp * PER_SPHERE,
                     &e, &ne, &cap))
        return 1;
    }
    /* fill: half uniform in the cube, half close to the spheres (shells of width 0.2),
     * which is what makes hull edges non-Delaunay */
    for (uint32_t j = 0; j < FILL; j++) {
      double *p = xyz + 3 * ((size_t)SPHERES * PER_SPHERE + j);
      for (int k = 0; k < 3; k++)
        p[k] = 7.0 * next_unit() - 3.5;
      if (j % 4) {
        double l = p[0] * p[0] + p[1] * p[1] + p[2] * p[2], g = 1.0 / sqrt(l);
        double r = 1.0 + (double)(next_u32() % SPHERES) + 0.2 * next_unit() - 0.1;
        for (int k = 0; k < 3; k++)
          p[k] *= r * g;
      }
    }
    ne = sort_edges(e, ne);
    struct tr_mesh *m;
    tr_status s = tr_delaunay_build(xyz, np, &m);
    if (s != TR_OK)
      return fail("delaunay", s);
    char what[64];
    snprintf(what, sizeof what, "spheres seed %llu mesh %d", (unsigned long long)seed, mi);
    tr_edge_recovery_stats st;
    int bad = run_stage(m, e, ne, 0, mi == 0, what, &st);
    tr_mesh_destroy(m);
    if (bad)
      return 1;
    add_stats(&tot, &st);
    total_edges += ne;
  }
  free(xyz);
  free(e);
  if (!tot.swap23 || tot.missing_edges == 0) {
    fprintf(stderr, "FAIL spheres: no missing edge or no Swap23 (%llu missing)\n",
            (unsigned long long)tot.missing_edges);
    return 1;
  }
  char what[64];
  snprintf(what, sizeof what, "spheres seed %llu, %d meshes", (unsigned long long)seed, meshes);
  print_stats(what, total_edges, &tot);
  return 0;
}

/* 1 iff segment ab may join the PLC with segments seg[0..n): no crossing, no collinear
 * overlap; touching at an endpoint of either (shared end, T-junction) is allowed. */
static int compatible(struct tr_mesh *m, uint32_t a, uint32_t b, const uint32_t *seg, uint32_t n)
{
  tr_point pa = tr_mesh_point(m, a), pb = tr_mesh_point(m, b);
  for (uint32_t j = 0; j < n; j++) {
    if ((seg[2 * j] == a && seg[2 * j + 1] == b) || (seg[2 * j] == b && seg[2 * j + 1] == a))
      return 0;
    tr_point pc = tr_mesh_point(m, seg[2 * j]), pd = tr_mesh_point(m, seg[2 * j + 1]);
    tr_isect x = tr_classify_segment_segment(&pa, &pb, &pc, &pd);
    if (x.n == 2)
      return 0;
    if (x.n == 1 && x.end[0].type == TR_EDG && x.end[0].on_seg == TR_SEG_IN)
      return 0;
  }
  return 1;
}

static int test_grid(int n, uint32_t nseg, uint64_t seed, int incremental,
                     tr_edge_recovery_stats *out)
{
  static const int DIR[][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, -1, 0},
                               {0, 1, 1}, {1, 0, -1}, {1, 1, 1}, {1, -1, 1}, {1, 2, 0},
                               {2, 1, 1}, {1, 2, 3}, {0, 1, 2}, {2, -1, 1}, {1, 1, 2}};
  const int ndir = (int)(sizeof DIR / sizeof DIR[0]);
  rng = seed;
  uint32_t np = (uint32_t)(n * n * n);
  double *xyz = malloc(3 * (size_t)np * sizeof *xyz);
  for (uint32_t i = 0; i < np; i++) {
    xyz[3 * i] = (double)(i % (uint32_t)n);
    xyz[3 * i + 1] = (double)(i / (uint32_t)n % (uint32_t)n);
    xyz[3 * i + 2] = (double)(i / (uint32_t)(n * n));
  }
  struct tr_mesh *m;
  tr_status s = tr_delaunay_build(xyz, np, &m);
  free(xyz);
  if (s != TR_OK)
    return fail("delaunay", s);
  uint32_t *seg = malloc(2 * (size_t)nseg * sizeof *seg), *sorted = NULL;
  uint32_t ns = 0;
  for (int tries = 0; ns < nseg && tries < 100000; tries++) {
    int p[3], d[3], len = 1 + (int)(next_u32() % (uint32_t)(n - 1));
    const int *dd = DIR[next_u32() % (uint32_t)ndir];
    for (int k = 0; k < 3; k++) {
      p[k] = (int)(next_u32() % (uint32_t)n);
      d[k] = p[k] + len * dd[k];
    }
    if (d[0] < 0 || d[1] < 0 || d[2] < 0 || d[0] >= n || d[1] >= n || d[2] >= n)
      continue;
    uint32_t a = (uint32_t)(p[0] + n * p[1] + n * n * p[2]);
    uint32_t b = (uint32_t)(d[0] + n * d[1] + n * n * d[2]);
    if (compatible(m, a, b, seg, ns)) {
      seg[2 * ns] = a;
      seg[2 * ns + 1] = b;
      ns++;
    }
  }
  sorted = malloc(2 * (size_t)ns * sizeof *sorted);
  tr_edge_recovery_stats tot, st;
  memset(&tot, 0, sizeof tot);
  char what[96];
  int bad = 0;
  /* incremental: the stage again after each new segment (the earlier ones are chains by
   * then), validator and exhaustive chain checks after every run */
  for (uint32_t k = incremental ? 1 : ns; k <= ns && !bad; k++) {
    memcpy(sorted, seg, 2 * (size_t)k * sizeof *seg);
    uint32_t nk = sort_edges(sorted, k);
    snprintf(what, sizeof what, "grid %d^3 seed %llu, %u segments", n,
             (unsigned long long)seed, k);
    bad = run_stage(m, sorted, nk, 1, 1, what, &st);
    add_stats(&tot, &st);
  }
  if (!bad)
    print_stats(what, ns, &tot);
  if (out)
    add_stats(out, &tot);
  free(seg);
  free(sorted);
  tr_mesh_destroy(m);
  return bad;
}

/* Crossing input edges are an invalid PLC: the stage must stop with a message naming
 * the edge, not corrupt the mesh or crash. */
static int expect_crossing(const double *xyz, uint32_t np, const uint32_t *e, uint32_t ne,
                           const char *what)
{
  struct tr_mesh *m;
  tr_status s = tr_delaunay_build(xyz, np, &m);
  if (s != TR_OK)
    return fail("delaunay", s);
  tr_edge_chains ch;
  tr_edge_recovery_stats st;
  s = tr_recover_edges(m, e, ne, &ch, &st);
  int bad = s != TR_ERR_SELF_INTERSECT || !strstr(tr_last_error(), "input edge") ||
            ch.start != NULL;
  if (bad)
    fprintf(stderr, "FAIL %s: got %s: %s\n", what, tr_status_name(s), tr_last_error());
  else
    printf("%s refused: %s\n", what, tr_last_error());
  tr_mesh_destroy(m);
  return bad;
}

static int test_crossing(void)
{
  /* crossing at (2,2,2), which the first edge's Steiner points happen to include */
  static const double a[] = {0, 0, 0, 4, 0, 0, 0, 4, 0, 4, 4, 0, 0, 0, 4, 4, 0, 4, 0, 4, 4,
                             4, 4, 4, 1, 1, 1, 3, 3, 3, 1, 3, 3, 3, 1, 1,
                             2, 2.1, 1.9, 1.9, 2, 2.1, 2.1, 1.9, 2, 2.05, 2.05, 2.2, 1.8, 2.1,
                             2.1};
  static const uint32_t ea[] = {8, 9, 10, 11};
  /* the two diagonals of a square: one is a Delaunay edge, the other crosses it (its
   * Swap44 must be refused, then its cut edge is the constraint) */
  static const double b[] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0, 1, 1, 1, 1, 1, -1};
  static const uint32_t eb[] = {0, 2, 1, 3};
  int bad = expect_crossing(a, (uint32_t)(sizeof a / sizeof a[0] / 3), ea, 2,
                            "edges crossing at a Steiner point");
  bad |= expect_crossing(b, 6, eb, 2, "edges crossing at an edge interior");
  return bad;
}

static int test_badinput(void)
{
  double xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  struct tr_mesh *m;
  tr_status s = tr_delaunay_build(xyz, 5, &m);
  if (s != TR_OK)
    return fail("delaunay", s);
  static const uint32_t cases[][4] = {{1, 0, 2, 3}, {0, 0, 1, 2}, {0, 1, 0, 9},
                                      {2, 3, 0, 1}, {0, 1, 0, 1}};
  int bad = 0;
  for (int i = 0; i < 5; i++) {
    tr_edge_chains ch;
    tr_edge_recovery_stats st;
    s = tr_recover_edges(m, cases[i], 2, &ch, &st);
    if (s != TR_ERR_INPUT || ch.start != NULL) {
      fprintf(stderr, "FAIL bad input %d accepted: %s\n", i, tr_status_name(s));
      bad = 1;
    }
  }
  if (!bad)
    printf("5 malformed edge lists refused with TR_ERR_INPUT\n");
  tr_mesh_destroy(m);
  return bad;
}

/* The requirement that no case of Table 2 is left to an untested path: degenerate
 * grids (all at once, validator + exhaustive chains) must together decompose pipels of
 * every kind, split hull faces, split at vertices and use Swap44. (Swap23 is the common
 * swap of the random meshes: the spheres mode requires it.) */
static int test_coverage(void)
{
  /* the paper's path: these counters are about its tables */
  g_opt.no_flips = g_opt.no_midpoints = 1;
  tr_edge_recovery_stats tot;
  memset(&tot, 0, sizeof tot);
  static const uint64_t seeds[] = {1, 2, 3};
  for (int i = 0; i < 3; i++)
    if (test_grid(5, 30, seeds[i], 0, &tot))
      return 1;
  int bad = 0;
  for (int k = 0; k < TR_EDGE_PIPEL_KINDS; k++)
    if (!tot.pipels[k]) {
      fprintf(stderr, "FAIL coverage: no pipel of kind %s decomposed\n", KIND[k]);
      bad = 1;
    }
  if (!tot.swap44 || !tot.ghosts_split || !tot.split_at_vertex || !tot.through_vertices) {
    fprintf(stderr, "FAIL coverage: swap44 %llu ghosts split %llu splits at vertices %llu\n",
            (unsigned long long)tot.swap44, (unsigned long long)tot.ghosts_split,
            (unsigned long long)tot.split_at_vertex);
    bad = 1;
  }
  if (!bad)
    print_stats("coverage (3 grids)", 90, &tot);
  return bad;
}

/* Inserts the exact point q (taken) strictly inside the hull of the tiny mesh m: every
 * real tet whose closure holds it is replaced by the cone from it over its faces that do
 * not (brute force over the slots). */
static int insert_point(struct tr_mesh *m, tr_qpoint *q, uint32_t *id)
{
  tr_point pq = tr_pt_q(q);
  uint32_t old[64], newv[4 * 4 * 64], nold = 0, nnew = 0;
  for (uint32_t t = 0; t < m->nt && nold < 64; t++) {
    if (tr_tet_is_free(m, t) || tr_tet_is_ghost(m, t))
      continue;
    const uint32_t *tv = m->tv + 4 * (size_t)t;
    int on[4], out = 0;
    for (int k = 0; k < 4 && !out; k++) {
      const uint8_t *f = tr_face_vtx[k];
      tr_point a = tr_mesh_point(m, tv[f[0]]), b = tr_mesh_point(m, tv[f[1]]),
               c = tr_mesh_point(m, tv[f[2]]);
      int o = tr_orient3d_p(&a, &b, &c, &pq);
      out = o < 0;
      on[k] = o == 0;
    }
    if (out)
      continue;
    old[nold++] = t;
    for (int k = 0; k < 4; k++) {
      if (on[k])
        continue;
      for (int j = 0; j < 4; j++)
        newv[4 * nnew + (uint32_t)j] = j == k ? m->nv : tv[j];
      nnew++;
    }
  }
  tr_status s = tr_mesh_add_steiner(m, q, id);
  if (s == TR_OK)
    s = tr_mesh_replace(m, old, nold, newv, nnew, NULL);
  return s != TR_OK ? fail("insert a Steiner point", s) : 0;
}

/* Two Steiner points whose nearest doubles are the same point and whose x is exactly
 * equal (the walk's old axis): p and q on the line x = y = 1/2 at z = 1 -+ 2^-70, on
 * either side of the square's Delaunay diagonal, which segment pq crosses. Recovering pq
 * and walking its chain need an axis where p and q differ exactly; each recovery path
 * (defaults, flips off with midpoint splits, the paper's pipels) through the validator
 * and the exhaustive chain checks. */
static int test_equal_doubles(void)
{
  static const double xyz[] = {0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0.4, 0.45, 0, 0.6, 0.55, 2};
  static const tr_edge_recovery_opts opts[3] = {{0, 0, 0, NULL, 0}, {1, 0, 1, NULL, 0}, {1, 1, 0, NULL, 0}};
  static const char *const names[3] = {"equal doubles, defaults",
                                       "equal doubles, no flips and no Lawson flips",
                                       "equal doubles, no flips and no midpoint splits"};
  int bad = 0;
  for (int r = 0; r < 3 && !bad; r++) {
    struct tr_mesh *m;
    tr_status s = tr_delaunay_build(xyz, 6, &m);
    if (s != TR_OK)
      return fail("delaunay", s);
    uint32_t e[2];
    for (int i = 0; i < 2 && !bad; i++) {
      tr_qpoint *q = malloc(sizeof *q);
      tr_qpoint_init(q);
      mpq_set_ui(q->c[0], 1, 2);
      mpq_set_ui(q->c[1], 1, 2);
      mpq_set_ui(q->c[2], 1, 1);
      mpq_t eps;
      mpq_init(eps);
      mpq_set_ui(eps, 1, 1);
      mpq_div_2exp(eps, eps, 70);
      if (i)
        mpq_add(q->c[2], q->c[2], eps);
      else
        mpq_sub(q->c[2], q->c[2], eps);
      mpq_clear(eps);
      tr_qpoint_update(q);
      bad = insert_point(m, q, &e[i]);
    }
    tr_point p0 = tr_mesh_point(m, e[0]), p1 = tr_mesh_point(m, e[1]);
    if (!bad && (p0.d[0] != p1.d[0] || p0.d[1] != p1.d[1] || p0.d[2] != p1.d[2] ||
                 tr_cmp_coord_p(&p0, &p1, 0) != 0 || tr_cmp_coord_p(&p0, &p1, 2) >= 0)) {
      fprintf(stderr, "FAIL %s: the two points do not have the same doubles\n", names[r]);
      bad = 1;
    }
    int yes = 1;
    if (!bad && (tr_mesh_has_edge(m, e[0], e[1], &yes) != TR_OK || yes)) {
      fprintf(stderr, "FAIL %s: pq is already a mesh edge\n", names[r]);
      bad = 1;
    }
    g_opt = opts[r];
    tr_edge_recovery_stats st;
    if (!bad && !(bad = run_stage(m, e, 1, 1, 1, names[r], &st)))
      printf("%s: recovered, %llu Steiner points\n", names[r],
             (unsigned long long)st.points_added);
    tr_mesh_destroy(m);
  }
  return bad;
}

int main(int argc, char **argv)
{
  /* a trailing "nolawson": the same run with the Lawson flips off (tr_recover_edges_ex) */
  if (argc >= 3 && !strcmp(argv[argc - 1], "nolawson")) {
    g_opt.no_lawson = 1;
    argc--;
  }
  /* a trailing "budget=N": at most N flip attempts per search (tr_edge_recovery_opts) */
  if (argc >= 3 && !strncmp(argv[argc - 1], "budget=", 7)) {
    g_opt.flip_budget = (uint32_t)atoi(argv[argc - 1] + 7);
    if (!g_opt.flip_budget)
      return 2;
    argc--;
  }
  if (argc == 6 && !strcmp(argv[1], "grid"))
    return test_grid(atoi(argv[2]), (uint32_t)atoi(argv[3]), (uint64_t)atoll(argv[4]),
                     atoi(argv[5]), NULL);
  if (argc == 2 && !strcmp(argv[1], "coverage"))
    return test_coverage();
  if (argc == 2 && !strcmp(argv[1], "crossing"))
    return test_crossing();
  if (argc == 2 && !strcmp(argv[1], "badinput"))
    return test_badinput();
  if (argc == 2 && !strcmp(argv[1], "equal_doubles"))
    return test_equal_doubles();
  if (argc == 4 && !strcmp(argv[1], "spheres"))
    return test_spheres((uint64_t)atoll(argv[2]), atoi(argv[3]));
  fprintf(stderr, "usage: test_recover_edges spheres <seed> <meshes> | grid <n> <nseg> "
                  "<seed> <incremental> | crossing | badinput | equal_doubles [nolawson] "
                  "[budget=N]\n");
  return 2;
}
