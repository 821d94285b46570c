/* Cluster(F) collection on Delaunay meshes of random and lattice points, for every triangle
 * EFG whose three edges are mesh edges (missing facets and mesh faces alike):
 *  - the search finds exactly the tets the classifier accepts among all tets;
 *  - each clusterel's type, codes and node types agree with an independent exact
 *    recount in rational arithmetic (crossing points constructed, tested against the
 *    triangle with barycentric signs);
 *  - the sections of the clusterels by the plane (polygons of the crossing ones, the
 *    coplanar faces once each) cover EFG exactly: their areas add up to EFG's;
 *  - the scratch marks are cleared and a second run gives the same bytes. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "qgeom.h"
#include "recover_facets/cluster.h"
#include "recover_facets/dtype.h"
#include "verify.h"

static int fails;
static long type_count[5], ntri_missing, ntri_face, ndecomposed;
static int decompose_mode; /* also decompose every THR_EDG / FOU_EDG clusterel */

#define CHECK(cond, ...)            \
  do {                              \
    if (!(cond)) {                  \
      fprintf(stderr, "FAIL: ");    \
      fprintf(stderr, __VA_ARGS__); \
      fputc('\n', stderr);          \
      fails++;                      \
    }                               \
  } while (0)

static int cmp_u64(const void *a, const void *b)
{
  uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
  return (x > y) - (x < y);
}
static uint64_t key2(uint32_t a, uint32_t b)
{
  return a < b ? (uint64_t)a << 32 | b : (uint64_t)b << 32 | a;
}
static uint64_t key3(uint32_t a, uint32_t b, uint32_t c)
{
  uint32_t t;
  if (a > b) t = a, a = b, b = t;
  if (b > c) t = b, b = c, c = t;
  if (a > b) t = a, a = b, b = t;
  return (uint64_t)a << 42 | (uint64_t)b << 21 | c;
}
static int has(const uint64_t *s, size_t n, uint64_t k)
{
  return bsearch(&k, s, n, sizeof k, cmp_u64) != NULL;
}

static void point_q(const struct tr_mesh *m, uint32_t v, qv *out)
{
  for (int i = 0; i < 3; i++)
    mpq_set_d(out->c[i], m->xyz[3 * (size_t)v + i]);
}

/* Side of x w.r.t. the plane with normal n through e. */
static int side(const qv *n, const qv *e, const qv *x)
{
  qv d;
  qv_init(&d);
  qv_sub(&d, x, e);
  mpq_t s;
  mpq_init(s);
  qv_dot(s, n, &d);
  int r = mpq_sgn(s);
  mpq_clear(s);
  qv_clear(&d);
  return r;
}

/* For x in the plane of triangle t (normal n): 1 inside the open triangle, 0 on its
 * boundary, -1 outside. */
static int in_tri(const qv *x, const qv t[3], const qv *n)
{
  int pos = 0, zero = 0;
  qv u, w, c;
  qv_init(&u), qv_init(&w), qv_init(&c);
  mpq_t s;
  mpq_init(s);
  for (int i = 0; i < 3; i++) {
    qv_sub(&u, &t[(i + 1) % 3], &t[i]);
    qv_sub(&w, x, &t[i]);
    qv_cross(&c, &u, &w);
    qv_dot(s, &c, n);
    pos += mpq_sgn(s) > 0;
    zero += mpq_sgn(s) == 0;
  }
  mpq_clear(s);
  qv_clear(&u), qv_clear(&w), qv_clear(&c);
  return pos == 3 ? 1 : pos + zero == 3 ? 0 : -1;
}

/* |(b-a) x (c-a) . n| */
static void tri_area(mpq_t out, const qv *a, const qv *b, const qv *c, const qv *n)
{
  qv u, v;
  qv_init(&u), qv_init(&v);
  qv_sub(&u, b, a);
  qv_sub(&v, c, a);
  qv_cross(&u, &u, &v);
  qv_dot(out, &u, n);
  mpq_abs(out, out);
  qv_clear(&u), qv_clear(&v);
}

/* The plane crossing of segment ab (a, b on opposite sides). */
static void crossing(qv *out, const qv *a, const qv *b, const qv *n, const qv *e)
{
  mpq_t fa, fb, t;
  mpq_init(fa), mpq_init(fb), mpq_init(t);
  qv d;
  qv_init(&d);
  qv_sub(&d, a, e);
  qv_dot(fa, n, &d);
  qv_sub(&d, b, e);
  qv_dot(fb, n, &d);
  mpq_sub(t, fa, fb);
  mpq_div(t, fa, t);
  qv_lerp(out, a, b, t);
  qv_clear(&d);
  mpq_clear(fa), mpq_clear(fb), mpq_clear(t);
}

/* Decomposes clusterel c of triangle T (normal nrm) with every S/Z requirement on its
 * cut faces: tr_cluster_match picks a case and an even relabeling; the case's table is
 * instantiated on the real points (A..D = the tet's vertices through perm, P_i = the exact
 * crossings of the carrier edges, H by the library's rule) and verified like the tables
 * themselves, including the S/Z type of every face on the real coordinates. */
static void decompose(const struct tr_mesh *m, const tr_clusterel *c, const qv T[3],
                      const qv *nrm, const char *what)
{
  const uint32_t *tv = m->tv + 4 * (size_t)c->iele;
  int nfree = 0, cutface[4];
  for (int k = 0; k < 4; k++) { /* faces with two cut edges get a requirement */
    int n = 0;
    for (int i = 0; i < c->nnodes; i++) {
      int a = c->codes[i] & 3, b = c->codes[i] >> 2;
      n += a != k && b != k;
    }
    cutface[k] = n == 2;
    nfree += cutface[k];
  }
  config cf;
  config_init(&cf);
  char w2[160];
  for (int pat = 0; pat <= (1 << nfree); pat++) {
    int8_t want[4];
    int bit = 0;
    for (int k = 0; k < 4; k++) /* pat == 2^nfree: everything free */
      want[k] = !cutface[k] || pat == (1 << nfree) ? TR_DTYPE_ANY : (int8_t)((pat >> bit++) & 1);
    const tr_cluster_case *cs;
    uint8_t perm[4];
    if (tr_cluster_match(c->type, c->codes, want, &cs, perm) != TR_OK) {
      CHECK(0, "%s tet %u: no case: %s", what, c->iele, tr_last_error());
      continue;
    }
    for (int x = 0; x < 4; x++) {
      point_q(m, tv[perm[x]], &cf.p[x]);
      CHECK(want[perm[x]] == TR_DTYPE_ANY || want[perm[x]] == cs->dtype[x],
            "%s tet %u: case %s ignores the requirement on face %d", what, c->iele, cs->name,
            perm[x]);
    }
    for (int i = 0; i < cs->table->nsteiner; i++) {
      const tr_dsteiner *st = &cs->table->steiner[i];
      if (st->ncar == 2)
        crossing(&cf.p[st->name], &cf.p[st->car[0]], &cf.p[st->car[1]], nrm, &T[0]);
    }
    cf.npoly = c->type;
    for (int i = 0; i < c->type; i++)
      cf.poly[i] = (uint8_t)(TR_DV_P1 + i);
    snprintf(w2, sizeof w2, "%s tet %u case %s pattern %d", what, c->iele, cs->name, pat);
    CHECK(place_h(&cf, cs) == 0, "%s: H not placed", w2);
    fails += verify(cs->table, &cf, cs->dtype, w2);
    ndecomposed++;
  }
  config_clear(&cf);
}

static void check_triangle(struct tr_mesh *m, uint32_t e, uint32_t f, uint32_t g, int is_face,
                           const char *what)
{
  tr_clusterel *cl = NULL, *cl2 = NULL;
  uint32_t n = 0, n2 = 0;
  tr_status st = tr_cluster_collect(m, e, f, g, &cl, &n);
  CHECK(st == TR_OK, "%s: collect failed: %s", what, tr_last_error());
  if (st != TR_OK)
    return;
  st = tr_cluster_collect(m, e, f, g, &cl2, &n2);
  int same = st == TR_OK && n == n2;
  for (uint32_t i = 0; same && i < n; i++) {
    same &= cl[i].iele == cl2[i].iele && cl[i].type == cl2[i].type &&
            cl[i].face == cl2[i].face && cl[i].nnodes == cl2[i].nnodes;
    for (int q = 0; q < 4; q++)
      same &= cl[i].codes[q] == cl2[i].codes[q] && cl[i].ntypes[q] == cl2[i].ntypes[q] &&
              cl[i].nodes[q] == cl2[i].nodes[q];
  }
  CHECK(same, "%s: second run differs", what);
  free(cl2);
  for (uint32_t t = 0; t < m->nt; t++)
    CHECK(!(m->flags[t] & TR_TF_MARK), "%s: mark left on tet %u", what, t);

  /* The search found exactly the members among all tets. */
  tr_point pe = tr_mesh_point(m, e), pf = tr_mesh_point(m, f), pg = tr_mesh_point(m, g);
  uint32_t k = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    tr_clusterel c;
    int member = 0;
    CHECK(tr_clusterel_classify(m, t, &pe, &pf, &pg, &c, &member) == TR_OK,
          "%s: classify tet %u: %s", what, t, tr_last_error());
    if (!member)
      continue;
    CHECK(k < n && cl[k].iele == t, "%s: clusterel %u missed by the search", what, t);
    if (k < n && cl[k].iele == t)
      k++;
  }
  CHECK(k == n, "%s: search returned %u clusterels, classifier accepts %u", what, n, k);

  /* Independent recount and the area identity. */
  qv T[3], nrm, u, v, P[4], X[4];
  for (int i = 0; i < 3; i++)
    qv_init(&T[i]);
  qv_init(&nrm), qv_init(&u), qv_init(&v);
  for (int i = 0; i < 4; i++)
    qv_init(&P[i]), qv_init(&X[i]);
  point_q(m, e, &T[0]), point_q(m, f, &T[1]), point_q(m, g, &T[2]);
  qv_sub(&u, &T[1], &T[0]);
  qv_sub(&v, &T[2], &T[0]);
  qv_cross(&nrm, &u, &v);
  mpq_t want, got, a, b;
  mpq_init(want), mpq_init(got), mpq_init(a), mpq_init(b);
  tri_area(want, &T[0], &T[1], &T[2], &nrm);
  uint64_t *cofaces = malloc((n + 1) * sizeof *cofaces);
  size_t ncof = 0;
  for (uint32_t i = 0; i < n; i++) {
    const tr_clusterel *c = &cl[i];
    const uint32_t *tv = m->tv + 4 * (size_t)c->iele;
    int s[4];
    for (int q = 0; q < 4; q++) {
      point_q(m, tv[q], &P[q]);
      s[q] = side(&nrm, &T[0], &P[q]);
    }
    type_count[c->type]++;
    if (c->type == TR_CO_PLAN) {
      CHECK(c->face >= 0 && c->face < 4 && s[c->face] != 0 && c->nnodes == 0,
            "%s: CO_PLAN tet %u malformed", what, c->iele);
      int inside = 1;
      uint32_t fv[3];
      int m3 = 0;
      for (int q = 0; q < 4; q++)
        if (q != c->face) {
          inside &= s[q] == 0 && in_tri(&P[q], T, &nrm) >= 0;
          fv[m3++] = tv[q];
        }
      CHECK(inside, "%s: CO_PLAN face of tet %u not in the closed triangle", what, c->iele);
      cofaces[ncof++] = key3(fv[0], fv[1], fv[2]);
      continue;
    }
    /* Recount the crossing edges and the on-plane vertices. */
    int nmid = 0, nx = 0, ok = 1;
    for (int p = 0; p < 4; p++)
      for (int q = p + 1; q < 4; q++) {
        if (s[p] * s[q] >= 0)
          continue;
        crossing(&X[nx < 4 ? nx : 3], &P[p], &P[q], &nrm, &T[0]);
        if (in_tri(&X[nx < 4 ? nx : 3], T, &nrm) != 1)
          continue;
        int listed = 0;
        for (int r = 0; r < c->nnodes; r++)
          listed |= c->ntypes[r] == TR_NOD_MID && c->codes[r] == (p | q << 2);
        ok &= listed;
        nmid++;
        nx++;
      }
    for (int p = 0; p < 4; p++) {
      if (s[p] != 0)
        continue;
      int listed = 0;
      for (int r = 0; r < c->nnodes; r++) {
        int st0 = c->codes[r] & 3, en = c->codes[r] >> 2;
        listed |= (c->ntypes[r] == TR_NOD_BEG && st0 == p && c->nodes[r] == tv[p] &&
                   s[en] != 0) ||
                  (c->ntypes[r] == TR_NOD_END && en == p && c->nodes[r] == tv[p] &&
                   s[st0] != 0);
      }
      ok &= listed;
      if (nx < 4)
        qv_set(&X[nx], &P[p]);
      nx++;
    }
    if (decompose_mode && c->type >= TR_THR_EDG)
      decompose(m, c, T, &nrm, what);
    CHECK(ok && nmid == c->type && nx == c->nnodes && nx >= 3 && nx <= 4,
          "%s: tet %u: type %d with %d nodes, recount %d crossing edges, %d nodes", what,
          c->iele, c->type, c->nnodes, nmid, nx);
    if (nx < 3 || nx > 4)
      continue;
    /* Section polygon area: a triangle, or a convex quad whose correct cyclic order has
     * the largest shoelace area of the three orders. */
    if (nx == 3) {
      tri_area(a, &X[0], &X[1], &X[2], &nrm);
    } else {
      static const int ord[3][4] = {{0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 1, 3}};
      mpq_set_ui(a, 0, 1);
      for (int o = 0; o < 3; o++) {
        /* Shoelace as a fan from X[ord0] with signed terms. */
        mpq_t sgn, tt;
        mpq_init(sgn), mpq_init(tt);
        for (int r = 1; r < 3; r++) {
          qv_sub(&u, &X[ord[o][r]], &X[ord[o][0]]);
          qv_sub(&v, &X[ord[o][r + 1]], &X[ord[o][0]]);
          qv_cross(&u, &u, &v);
          qv_dot(tt, &u, &nrm);
          mpq_add(sgn, sgn, tt);
        }
        mpq_abs(sgn, sgn);
        if (mpq_cmp(sgn, a) > 0)
          mpq_set(a, sgn);
        mpq_clear(sgn), mpq_clear(tt);
      }
    }
    mpq_add(got, got, a);
  }
  qsort(cofaces, ncof, sizeof *cofaces, cmp_u64);
  for (size_t i = 0; i < ncof; i++) {
    if (i > 0 && cofaces[i] == cofaces[i - 1])
      continue;
    uint32_t x0 = (uint32_t)(cofaces[i] >> 42), x1 = (uint32_t)(cofaces[i] >> 21) & 0x1fffff,
             x2 = (uint32_t)cofaces[i] & 0x1fffff;
    point_q(m, x0, &P[0]), point_q(m, x1, &P[1]), point_q(m, x2, &P[2]);
    tri_area(b, &P[0], &P[1], &P[2], &nrm);
    mpq_add(got, got, b);
  }
  CHECK(mpq_equal(want, got), "%s: sections of the %u clusterels do not cover the triangle "
        "exactly", what, n);
  if (is_face)
    for (uint32_t i = 0; i < n; i++)
      CHECK(cl[i].type == TR_CO_PLAN, "%s: a mesh face has a crossing clusterel", what);
  free(cofaces);
  mpq_clear(want), mpq_clear(got), mpq_clear(a), mpq_clear(b);
  for (int i = 0; i < 3; i++)
    qv_clear(&T[i]);
  qv_clear(&nrm), qv_clear(&u), qv_clear(&v);
  for (int i = 0; i < 4; i++)
    qv_clear(&P[i]), qv_clear(&X[i]);
  free(cl);
}

/* Every triangle with three mesh edges (up to max_tris of them), checked. */
static void check_mesh(struct tr_mesh *m, int max_tris, const char *name)
{
  size_t ne = 0, nf = 0, cap = 6 * (size_t)m->nt + 1;
  uint64_t *edges = malloc(cap * sizeof *edges), *faces = malloc(cap * sizeof *faces);
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    for (int a = 0; a < 4; a++)
      for (int b = a + 1; b < 4; b++)
        edges[ne++] = key2(v[a], v[b]);
    for (int k = 0; k < 4 && nf + 4 < cap; k++) {
      uint32_t w[3];
      int q = 0;
      for (int i = 0; i < 4; i++)
        if (i != k)
          w[q++] = v[i];
      faces[nf++] = key3(w[0], w[1], w[2]);
    }
  }
  qsort(edges, ne, sizeof *edges, cmp_u64);
  qsort(faces, nf, sizeof *faces, cmp_u64);
  int done = 0;
  char what[96];
  for (size_t i = 0; i < ne && done < max_tris; i++) {
    if (i > 0 && edges[i] == edges[i - 1])
      continue;
    uint32_t a = (uint32_t)(edges[i] >> 32), b = (uint32_t)edges[i];
    for (uint32_t c = b + 1; c < m->nv && done < max_tris; c++) {
      if (!has(edges, ne, key2(a, c)) || !has(edges, ne, key2(b, c)))
        continue;
      int is_face = has(faces, nf, key3(a, b, c));
      qv p[3], u, w, x;
      for (int q = 0; q < 3; q++)
        qv_init(&p[q]);
      qv_init(&u), qv_init(&w), qv_init(&x);
      point_q(m, a, &p[0]), point_q(m, b, &p[1]), point_q(m, c, &p[2]);
      qv_sub(&u, &p[1], &p[0]);
      qv_sub(&w, &p[2], &p[0]);
      qv_cross(&x, &u, &w);
      int flat = !mpq_sgn(x.c[0]) && !mpq_sgn(x.c[1]) && !mpq_sgn(x.c[2]);
      for (int q = 0; q < 3; q++)
        qv_clear(&p[q]);
      qv_clear(&u), qv_clear(&w), qv_clear(&x);
      if (flat)
        continue;
      snprintf(what, sizeof what, "%s triangle %u %u %u%s", name, a, b, c,
               is_face ? " (face)" : " (missing)");
      check_triangle(m, a, b, c, is_face, what);
      is_face ? ntri_face++ : ntri_missing++;
      done++;
    }
  }
  free(edges);
  free(faces);
}

int main(int argc, char **argv)
{
  const char *mode = argc > 1 ? argv[1] : "random";
  decompose_mode = !strcmp(mode, "decompose");
  if (!strcmp(mode, "random") || decompose_mode) {
    for (int seed = 0; seed < 6; seed++) {
      uint64_t rs = 0xdeadbeefcafef00dull + (uint64_t)seed * 0x9e3779b97f4a7c15ull;
      enum { N = 50 };
      double xyz[3 * N];
      for (int i = 0; i < 3 * N; i++)
        xyz[i] = (double)rng_range(&rs, 0, 40);
      struct tr_mesh *m = NULL;
      tr_status st = tr_delaunay_build(xyz, N, &m);
      CHECK(st == TR_OK, "delaunay of random set %d: %s", seed, tr_last_error());
      if (st != TR_OK)
        continue;
      char name[32];
      snprintf(name, sizeof name, "random set %d", seed);
      check_mesh(m, 400, name);
      tr_mesh_destroy(m);
    }
  } else if (!strcmp(mode, "lattice")) {
    /* Points on a small integer lattice (duplicates included): many coplanar and
     * collinear points, mesh vertices on the facets' planes, coplanar faces. */
    for (int seed = 0; seed < 6; seed++) {
      uint64_t rs = 0x0123456789abcdefull + (uint64_t)seed * 0x9e3779b97f4a7c15ull;
      enum { N = 60 };
      double xyz[3 * N];
      for (int i = 0; i < 3 * N; i++)
        xyz[i] = (double)rng_range(&rs, 0, 4);
      struct tr_mesh *m = NULL;
      tr_status st = tr_delaunay_build(xyz, N, &m);
      CHECK(st == TR_OK, "delaunay of lattice set %d: %s", seed, tr_last_error());
      if (st != TR_OK)
        continue;
      char name[32];
      snprintf(name, sizeof name, "lattice set %d", seed);
      check_mesh(m, 400, name);
      tr_mesh_destroy(m);
    }
  } else {
    fprintf(stderr, "usage: %s random|lattice|decompose\n", argv[0]);
    return 2;
  }
  printf("%s: %ld missing triangles, %ld mesh faces; clusterels CO_PLAN %ld ONE %ld TWO %ld "
         "THR %ld FOU %ld; %ld decompositions verified\n", mode, ntri_missing, ntri_face,
         type_count[0], type_count[1], type_count[2], type_count[3], type_count[4],
         ndecomposed);
  if (decompose_mode)
    CHECK(ndecomposed > 500, "decompose: only %ld decompositions", ndecomposed);
  CHECK(ntri_missing > 0 && ntri_face > 0, "%s: no missing triangle or no face exercised",
        mode);
  if (!strcmp(mode, "random") || decompose_mode)
    CHECK(type_count[TR_THR_EDG] > 0 && type_count[TR_FOU_EDG] > 0,
          "random: THR_EDG and FOU_EDG clusterels not exercised");
  else
    CHECK(type_count[TR_ONE_EDG] > 0 && type_count[TR_TWO_EDG] > 0 && type_count[0] > 0,
          "lattice: ONE_EDG / TWO_EDG / CO_PLAN clusterels not exercised");
  if (fails) {
    fprintf(stderr, "%s: %d failure(s)\n", mode, fails);
    return 1;
  }
  return 0;
}
