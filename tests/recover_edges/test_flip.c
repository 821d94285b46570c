/* General flips (src/recover_edges/flip.h) on exact hand-built configurations, every
 * result through the validator (links, strict positivity, v2t, Euler, exact volume):
 * edge removal for shells of 3..7 tets (and its undo), a ring no triangulation fits
 * (refused, mesh unchanged), protected edges and faces, the 2-2 hull flip on every face of
 * a cube (ghosts stay consistent), and a missing input edge recovered by the flips of the
 * edge driver without a Steiner point.
 * Usage: test_flip ring N | ring_invalid | protected | hull_cube | flip23 | recover N |
 *        edge_tet | sxset | blocked23 | shell_kept | tetgen44 */
#include <gmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "mesh/mesh.h"
#include "recover_edges/flip.h"
#include "recover_edges/recover_edges.h"
#include "tmesh.h"

#define PI 3.14159265358979323846

/* The shell of AB (vertices 0, 1) with ring vertices 2..n+1: tets {A,B,r_i,r_i+1} made
 * positive, glued. z[i]: height of ring vertex i (radius 1, regular angles). */
static tr_status build_shell(int n, const double *z, double ha, double hb, struct tr_mesh **out)
{
  struct tr_mesh *m;
  TR_CHECK(tr_mesh_create(32, 32, &m));
  double a[3] = {0, 0, ha}, b[3] = {0, 0, hb};
  uint32_t id;
  TR_CHECK(tr_mesh_add_vertex(m, a, &id));
  TR_CHECK(tr_mesh_add_vertex(m, b, &id));
  for (int i = 0; i < n; i++) {
    double p[3] = {cos(2 * PI * i / n), sin(2 * PI * i / n), z ? z[i] : 0};
    TR_CHECK(tr_mesh_add_vertex(m, p, &id));
  }
  for (int i = 0; i < n; i++) {
    uint32_t x = 2 + (uint32_t)i, y = 2 + (uint32_t)((i + 1) % n), t;
    tr_point p[4] = {tr_mesh_point(m, 0), tr_mesh_point(m, 1), tr_mesh_point(m, x),
                     tr_mesh_point(m, y)};
    if (tr_orient3d_p(&p[0], &p[1], &p[2], &p[3]) > 0)
      TR_CHECK(tr_tet_new(m, 0, 1, x, y, &t));
    else
      TR_CHECK(tr_tet_new(m, 1, 0, x, y, &t));
  }
  glue_all(m);
  *out = m;
  return TR_OK;
}

/* The exact volume of m into vol (initialised here), and m through the validator. */
static int measured(struct tr_mesh *m, mpq_t vol, const char *what)
{
  mpq_init(vol);
  if (tr_mesh_volume6(m, vol) != TR_OK) {
    fprintf(stderr, "%s: volume: %s\n", what, tr_last_error());
    return 1;
  }
  return validate(m, vol, what);
}

static int test_ring(int n)
{
  /* a slightly wavy ring: non-planar, still removable */
  double z[16];
  for (int i = 0; i < n; i++)
    z[i] = (i % 2 ? 0.125 : -0.0625);
  struct tr_mesh *m;
  CK(build_shell(n, z, 1, -1, &m));
  mpq_t vol;
  if (measured(m, vol, "shell"))
    return 1;
  tr_flip_rec rec;
  int done;
  CK(tr_flip_remove_edge(m, 0, 1, TR_NONE, NULL, NULL, &rec, &done));
  if (!done)
    FAIL("ring %d: edge removal refused", n);
  if (has_edge(m, 0, 1) || tr_mesh_count_real(m) != (uint32_t)(2 * n - 4))
    FAIL("ring %d: AB still there or %u tets (expected %d)", n, tr_mesh_count_real(m),
         2 * n - 4);
  if (validate(m, vol, "after removal"))
    return 1;
  CK(tr_flip_undo(m, &rec));
  if (!has_edge(m, 0, 1) || tr_mesh_count_real(m) != (uint32_t)n)
    FAIL("ring %d: undo did not restore the shell", n);
  if (validate(m, vol, "after undo"))
    return 1;
  printf("ring %d: removed into %d tets, undone, valid\n", n, 2 * n - 4);
  mpq_clear(vol);
  tr_mesh_destroy(m);
  return 0;
}

/* Ring vertices alternately far above A and far below B: every diagonal of the 4-ring
 * leaves A or B on the wrong side of a triangle, so no triangulation fits. */
static int test_ring_invalid(void)
{
  double z[4] = {3, -3, 3, -3};
  struct tr_mesh *m;
  CK(build_shell(4, z, 1, -1, &m));
  mpq_t vol;
  if (measured(m, vol, "invalid ring shell"))
    return 1;
  uint32_t before[16];
  memcpy(before, m->tv, sizeof before);
  int done;
  CK(tr_flip_remove_edge(m, 0, 1, TR_NONE, NULL, NULL, NULL, &done));
  if (done || memcmp(before, m->tv, sizeof before) != 0 || !has_edge(m, 0, 1))
    FAIL("ring_invalid: removal accepted or mesh changed");
  if (validate(m, vol, "after refusal"))
    return 1;
  printf("ring_invalid: refused, mesh unchanged\n");
  mpq_clear(vol);
  tr_mesh_destroy(m);
  return 0;
}

static int guard_edge01(void *ud, const uint32_t *v, int nv)
{
  (void)ud;
  return nv == 2 && ((v[0] == 0 && v[1] == 1) || (v[0] == 1 && v[1] == 0));
}

static int guard_any_face(void *ud, const uint32_t *v, int nv)
{
  (void)ud;
  (void)v;
  return nv == 3;
}

static int test_protected(void)
{
  struct tr_mesh *m;
  CK(build_shell(5, NULL, 1, -1, &m));
  int done;
  CK(tr_flip_remove_edge(m, 0, 1, TR_NONE, guard_edge01, NULL, NULL, &done));
  if (done || !has_edge(m, 0, 1))
    FAIL("protected: a protected edge was removed");
  CK(tr_flip_remove_edge(m, 0, 1, TR_NONE, guard_any_face, NULL, NULL, &done));
  if (done)
    FAIL("protected: removal deleted protected faces");
  /* flip32 then try Swap23 back on the face with every face protected */
  CK(tr_flip_remove_edge(m, 0, 1, TR_NONE, NULL, NULL, NULL, &done));
  if (!done)
    FAIL("protected: unprotected removal refused");
  for (uint32_t t = 0; t < m->nt; t++)
    for (int k = 0; k < 4 && !tr_tet_is_free(m, t); k++) {
      CK(tr_flip23(m, t, k, guard_any_face, NULL, NULL, &done));
      if (done)
        FAIL("protected: Swap23 deleted a protected face");
    }
  if (tr_check_mesh(m, CHECKS, NULL) != TR_OK)
    FAIL("protected: validator: %s", tr_last_error());
  printf("protected: edge and faces kept\n");
  tr_mesh_destroy(m);
  return 0;
}

/* Two tets glued on a face the segment between their apexes pierces: Swap23, valid;
 * moved apex (segment misses the face): refused. */
static int test_flip23(void)
{
  for (int bad = 0; bad < 2; bad++) {
    struct tr_mesh *m;
    CK(tr_mesh_create(8, 8, &m));
    double p[5][3] = {{1, 1, -3}, {2, 1, 4}, {4, 0, 0}, {0, 4, 0}, {0, 0, 0}};
    if (bad)
      p[1][0] = 9;
    uint32_t id, t1, t2;
    for (int i = 0; i < 5; i++)
      CK(tr_mesh_add_vertex(m, p[i], &id));
    CK(tr_tet_new(m, 0, 2, 3, 4, &t1));
    CK(tr_tet_new(m, 1, 3, 2, 4, &t2));
    glue_all(m);
    mpq_t vol;
    mpq_init(vol);
    CK(tr_mesh_volume6(m, vol));
    int done;
    tr_flip_rec rec;
    CK(tr_flip23(m, t1, 0, NULL, NULL, &rec, &done));
    if (done == bad || (!bad && (!has_edge(m, 0, 1) || tr_mesh_count_real(m) != 3)))
      FAIL("flip23 (%s): done = %d", bad ? "non-convex" : "convex", done);
    if (validate(m, vol, "flip23"))
      return 1;
    if (done) {
      CK(tr_flip_undo(m, &rec));
      if (has_edge(m, 0, 1) || validate(m, vol, "flip23 undo"))
        FAIL("flip23: undo failed");
    }
    mpq_clear(vol);
    tr_mesh_destroy(m);
  }
  printf("flip23: convex pair flipped and undone, non-convex pair refused\n");
  return 0;
}

/* The Delaunay mesh of a cube: each face is two hull triangles; flipping its diagonal is
 * a 2-2 hull flip. Every face once, validator (ghost links included) after each. */
static int test_hull_cube(void)
{
  double x[24];
  for (int i = 0; i < 8; i++) {
    x[3 * i] = i & 1;
    x[3 * i + 1] = (i >> 1) & 1;
    x[3 * i + 2] = (i >> 2) & 1;
  }
  struct tr_mesh *m;
  CK(tr_delaunay_build(x, 8, &m));
  mpq_t vol;
  mpq_init(vol);
  CK(tr_mesh_volume6(m, vol));
  int flipped = 0;
  /* the 12 face diagonals: pairs differing in exactly two coordinates */
  for (uint32_t a = 0; a < 8; a++)
    for (uint32_t b = a + 1; b < 8; b++) {
      uint32_t d = a ^ b;
      if (__builtin_popcount(d) != 2 || !has_edge(m, a, b))
        continue;
      int done;
      tr_flip_rec rec;
      CK(tr_flip_remove_edge(m, a, b, TR_NONE, NULL, NULL, &rec, &done));
      if (!done) {
        /* legitimate: the cube is cospherical, some shells have only flat fillings */
        if (validate(m, vol, "hull flip refused"))
          return 1;
        continue;
      }
      if (!rec.hull)
        FAIL("hull_cube: %u-%u removal not reported as a hull flip", a, b);
      uint32_t c = TR_NONE, e = TR_NONE; /* the other diagonal of that face */
      for (uint32_t v = 0; v < 8; v++) {
        uint32_t fixed = 7u & ~d;
        if (v != a && v != b && (v & fixed) == (a & fixed))
          c == TR_NONE ? (c = v) : (e = v);
      }
      if (has_edge(m, a, b) || !has_edge(m, c, e))
        FAIL("hull_cube: after flipping %u-%u the diagonal %u-%u is missing", a, b, c, e);
      if (validate(m, vol, "hull flip"))
        return 1;
      flipped++;
    }
  if (flipped < 1)
    FAIL("hull_cube: no face diagonal flipped");
  printf("hull_cube: %d hull 2-2 flips, mesh valid\n", flipped);
  tr_mesh_destroy(m);
  /* Square pyramids (one or two apexes): the base diagonal is a hull edge with coplanar
   * hull faces; its removal must always succeed and give the other diagonal. */
  for (int two = 0; two < 2; two++) {
    double y[18] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1, 0.25, 0.75, 0.5};
    CK(tr_delaunay_build(y, two ? 6 : 5, &m));
    CK(tr_mesh_volume6(m, vol));
    uint32_t a = has_edge(m, 0, 2) ? 0 : 1, b = a + 2;
    int done;
    tr_flip_rec rec;
    CK(tr_flip_remove_edge(m, a, b, TR_NONE, NULL, NULL, &rec, &done));
    if (!done || !rec.hull || has_edge(m, a, b) || !has_edge(m, (a + 1) % 4, (a + 3) % 4))
      FAIL("pyramid %d: base diagonal %u-%u not flipped on the hull", two, a, b);
    if (validate(m, vol, "pyramid hull flip"))
      return 1;
    CK(tr_flip_undo(m, &rec));
    if (!has_edge(m, a, b) || validate(m, vol, "pyramid undo"))
      FAIL("pyramid %d: undo failed", two);
    tr_mesh_destroy(m);
  }
  printf("pyramids: base diagonal flipped on the hull and undone, valid\n");
  mpq_clear(vol);
  return 0;
}

/* Remove AB from an n-shell, then ask the edge driver for AB: it must come back by
 * flips alone (no Steiner point). */
static int test_recover(int n)
{
  double x[3 * 18];
  x[0] = 0, x[1] = 0, x[2] = 1, x[3] = 0, x[4] = 0, x[5] = -1;
  for (int i = 0; i < n; i++) {
    x[6 + 3 * i] = cos(2 * PI * i / n);
    x[7 + 3 * i] = sin(2 * PI * i / n);
    x[8 + 3 * i] = i % 2 ? 0.125 : -0.0625;
  }
  struct tr_mesh *m;
  CK(tr_delaunay_build(x, (uint32_t)(2 + n), &m));
  mpq_t vol;
  mpq_init(vol);
  CK(tr_mesh_volume6(m, vol));
  int done = 1;
  if (has_edge(m, 0, 1))
    CK(tr_flip_remove_edge(m, 0, 1, TR_NONE, NULL, NULL, NULL, &done));
  if (!done || has_edge(m, 0, 1))
    FAIL("recover %d: could not set up a mesh without AB", n);
  uint32_t edges[2] = {0, 1};
  tr_edge_chains ch;
  tr_edge_recovery_stats st;
  CK(tr_recover_edges(m, edges, 1, &ch, &st));
  if (!has_edge(m, 0, 1) || st.points_added != 0 || st.recovered_by_swap != 1)
    FAIL("recover %d: AB %s, %llu Steiner points", n, has_edge(m, 0, 1) ? "present" : "missing",
         (unsigned long long)st.points_added);
  if (validate(m, vol, "recover"))
    return 1;
  printf("recover %d: AB back by flips (swap23 %llu, flip23 %llu, 3/4/n-removals %llu/%llu/%llu)\n",
         n, (unsigned long long)st.swap23, (unsigned long long)st.flip23,
         (unsigned long long)st.flip32, (unsigned long long)st.flip44,
         (unsigned long long)st.flipn);
  tr_edge_chains_free(&ch);
  mpq_clear(vol);
  tr_mesh_destroy(m);
  return 0;
}

/* The Delaunay mesh of np points on a grid of 2001^3 in [-1, 1]^3 (xorshift, fixed seed):
 * exact coincidences and coplanar sets among random ones. */
static tr_status random_dt(uint32_t np, struct tr_mesh **m)
{
  double *x = malloc(sizeof *x * 3 * np);
  if (!x)
    return TR_ERR_NOMEM;
  unsigned long long r = 88172645463325252ull;
  for (uint32_t i = 0; i < 3 * np; i++) {
    r ^= r << 13, r ^= r >> 7, r ^= r << 17;
    x[i] = (double)(r % 2001) / 1000.0 - 1.0;
  }
  tr_status st = tr_delaunay_build(x, np, m);
  free(x);
  return st;
}

/* tr_flip_edge_tet (the early-exit search of the flip drivers) gives exactly the tet that
 * scanning the whole of tr_ball(a, 1) gives: the first with vertex b, ghosts included,
 * TR_NONE when ab is not an edge. Checked for every vertex pair of a random Delaunay mesh
 * (hull edges included), so the flips start their shells where they did before. */
static int test_edge_tet(void)
{
  enum { NP = 60 };
  struct tr_mesh *m;
  CK(random_dt(NP, &m));
  mpq_t vol;
  mpq_init(vol);
  CK(tr_mesh_volume6(m, vol));
  tr_u32buf ball = {0};
  int edges = 0;
  for (uint32_t a = 0; a < NP; a++) {
    CK(tr_ball(m, a, 1, &ball));
    for (uint32_t b = 0; b < NP; b++) {
      if (b == a)
        continue;
      uint32_t want = TR_NONE, got;
      for (size_t i = 0; i < ball.n && want == TR_NONE; i++)
        if (tr_ncode(m, ball.a[i], b) >= 0)
          want = ball.a[i];
      CK(tr_flip_edge_tet(m, a, b, &got));
      if (got != want)
        FAIL("edge_tet %u-%u: %u, the ball scan gives %u", a, b, got, want);
      edges += want != TR_NONE;
    }
  }
  tr_u32buf_free(&ball);
  for (uint32_t t = 0; t < m->nt; t++)
    if (m->flags[t] & TR_TF_MARK)
      FAIL("edge_tet: scratch mark left on tet %u", t);
  if (edges < 2 * NP)
    FAIL("edge_tet: only %d directed edges found", edges);
  if (validate(m, vol, "edge_tet")) /* the searches leave the mesh as it was */
    return 1;
  printf("edge_tet: %d directed edges and every non-edge agree with the ball scan\n", edges);
  mpq_clear(vol);
  tr_mesh_destroy(m);
  return 0;
}

/* tr_sxset: each edge / triangle is added once whatever the vertex order, edges and
 * triangles on the same vertices are different, growth keeps every key, clear empties. */
static int test_sxset(void)
{
  tr_sxset s = {0};
  int added = 0;
  for (int round = 0; round < 2; round++) {
    for (uint32_t i = 0; i < 500; i++) {
      uint32_t f[3] = {i, i + 7, 3 * i + 1}, g[3] = {3 * i + 1, i, i + 7};
      uint32_t e[3] = {i + 7, i, TR_NONE};
      int r1 = tr_sxset_add(&s, f), r2 = tr_sxset_add(&s, g), r3 = tr_sxset_add(&s, e);
      if (r1 != 1 || r2 != 0 || r3 != 1)
        FAIL("sxset round %d key %u: add gave %d %d %d, want 1 0 1", round, i, r1, r2, r3);
      added += r1 + r3;
    }
    for (uint32_t i = 0; i < 500; i++) {
      uint32_t f[3] = {i + 7, 3 * i + 1, i}, e[3] = {i, i + 7, TR_NONE};
      if (tr_sxset_add(&s, f) != 0 || tr_sxset_add(&s, e) != 0)
        FAIL("sxset round %d key %u: lost after growth", round, i);
    }
    if (s.map.n != 1000)
      FAIL("sxset round %d: %u keys, want 1000", round, s.map.n);
    tr_sxset_clear(&s);
  }
  tr_sxset_free(&s);
  printf("sxset: %d distinct simplices added over two rounds\n", added);
  return 0;
}

/* tr_flip23_jb (the flip searches' Swap23 after tr_flip23_blockers) decides as
 * tr_flip23_j does: on every interior face of a random Delaunay mesh, one or two blockers
 * mean the Swap23 is refused (counted as one try, mesh unchanged), none that it is made,
 * three never happen between two valid tets. Made flips are undone; validator at the end
 * (the mesh is the one it started as). */
static int test_blocked23(void)
{
  enum { NP = 60 };
  double x[3 * NP];
  unsigned long long r = 2463534242ull;
  for (int i = 0; i < 3 * NP; i++) {
    r ^= r << 13, r ^= r >> 7, r ^= r << 17;
    x[i] = (double)(r % 2001) / 1000.0 - 1.0;
  }
  struct tr_mesh *m;
  CK(tr_delaunay_build(x, NP, &m));
  mpq_t vol;
  mpq_init(vol);
  CK(tr_mesh_volume6(m, vol));
  int count[4] = {0, 0, 0, 0};
  for (uint32_t t = 0; t < m->nt; t++)
    for (int k = 0; k < 4; k++) {
      if (tr_tet_is_free(m, t) || !tr_tet_is_real(m, t))
        continue;
      uint32_t c = m->tn[4 * (size_t)t + (size_t)k];
      if (c == TR_NONE || !tr_tet_is_real(m, c >> 2) || (c >> 2) < t)
        continue; /* each interior face once */
      uint32_t be[3][2], before[8];
      memcpy(before, m->tv + 4 * (size_t)t, 4 * sizeof *before);
      memcpy(before + 4, m->tv + 4 * (size_t)(c >> 2), 4 * sizeof *before);
      int nb = tr_flip23_blockers(m, t, k, be), want, got;
      tr_flip_journal j;
      memset(&j, 0, sizeof j);
      CK(tr_flip23_j(m, t, k, NULL, NULL, &j, &want));
      if (want)
        CK(tr_flip_journal_undo(m, &j, 0));
      j.tries = 0;
      CK(tr_flip23_jb(m, t, k, nb, NULL, NULL, &j, &got));
      if (nb == 3 || got != want || got != (nb == 0) || j.tries != 1 || j.n != (uint32_t)got)
        FAIL("blocked23: tet %u face %d: %d blockers, Swap23 %d, with them %d (%u tries)", t,
             k, nb, want, got, j.tries);
      if (got)
        CK(tr_flip_journal_undo(m, &j, 0));
      tr_flip_journal_free(&j);
      if (memcmp(m->tv + 4 * (size_t)t, before, 4 * sizeof *before) ||
          memcmp(m->tv + 4 * (size_t)(c >> 2), before + 4, 4 * sizeof *before))
        FAIL("blocked23: tet %u face %d: the pair is not as it was", t, k);
      count[nb]++;
    }
  if (!count[0] || !count[1] || !count[2])
    FAIL("blocked23: faces with 0/1/2 blockers %d/%d/%d: a kind is not shown", count[0],
         count[1], count[2]);
  if (validate(m, vol, "blocked23"))
    return 1;
  printf("blocked23: %d faces flippable, %d / %d with one / two blockers refused alike\n",
         count[0], count[1], count[2]);
  mpq_clear(vol);
  tr_mesh_destroy(m);
  return 0;
}

/* tr_flip_remove_edge_nm takes Shell(ab) from tr_flip_edge_tet's tet after its plain
 * removal of ab failed; when that removal found its tet the same way and changed
 * nothing, the shell it left in the journal's scratch is used instead. That is the same
 * list, in the same order, for every interior edge of a random Delaunay mesh whose
 * removal fails (those that succeed are undone, the mesh stays valid). */
static int test_shell_kept(void)
{
  enum { NP = 60 };
  struct tr_mesh *m;
  CK(random_dt(NP, &m));
  mpq_t vol;
  mpq_init(vol);
  CK(tr_mesh_volume6(m, vol));
  tr_sxset seen = {0};
  tr_u32buf sh = {0};
  int same = 0, removed = 0;
  for (uint32_t t = 0; t < m->nt; t++)
    for (int e = 0; e < 16 && !tr_tet_is_free(m, t) && tr_tet_is_real(m, t); e++) {
      if ((e & 3) >= (e >> 2))
        continue; /* the six edges (slot e & 3, slot e >> 2), each once */
      uint32_t a = m->tv[4 * (size_t)t + (size_t)(e & 3)],
               b = m->tv[4 * (size_t)t + (size_t)(e >> 2)], key[3] = {a, b, TR_NONE};
      if (tr_sxset_add(&seen, key) != 1)
        continue;
      tr_flip_journal j;
      memset(&j, 0, sizeof j);
      int done, closed = 0;
      CK(tr_flip_remove_edge_nm(m, a, b, TR_NONE, 1, NULL, NULL, &j, &done));
      if (done) {
        removed++;
        CK(tr_flip_journal_undo(m, &j, 0));
      } else {
        uint32_t t1;
        CK(tr_flip_edge_tet(m, a, b, &t1));
        CK(tr_shell(m, a, b, t1, &sh, &closed));
        if (closed) {
          if (j.n || sh.n != j.shell.n || memcmp(sh.a, j.shell.a, sh.n * sizeof *sh.a))
            FAIL("shell_kept: edge %u-%u: the removal left %zu shell tets, the shell has "
                 "%zu (or a flip was kept)", a, b, j.shell.n, sh.n);
          same++;
        }
      }
      tr_flip_journal_free(&j);
    }
  if (!same || !removed)
    FAIL("shell_kept: %d shells compared, %d edges removed: a case is not shown", same,
         removed);
  if (validate(m, vol, "shell_kept"))
    return 1;
  printf("shell_kept: %d failed removals left the edge's shell, %d removals undone\n", same,
         removed);
  tr_u32buf_free(&sh);
  tr_sxset_free(&seen);
  mpq_clear(vol);
  tr_mesh_destroy(m);
  return 0;
}

/* The edge removal that TetGen's flips reach (journal tetgen_flips, the flip levels
 * below the last): a flat ring, and the 4-4 flip, a shell of four tets whose edge ab and
 * two opposite ring vertices are coplanar (TetGen makes it as a Swap23 through a flat tet
 * and a 3-2). Here a wavy 4-ring around A = (0,0,1), B = (0,0,-1): A, B, r0, r2 lie in
 * y = 0 and A, B, r1, r3 in x = 0, the ring is not flat. Moving A off both planes leaves
 * a 4-shell that only the general removal takes (TetGen reaches it by a Swap23 and a 3-2,
 * the recursion's job). */
static int test_tetgen44(void)
{
  double z[4] = {-0.0625, 0.125, -0.0625, 0.125};
  for (int moved = 0; moved < 2; moved++) {
    for (int mode = 0; mode < 2; mode++) {
      struct tr_mesh *m;
      CK(build_shell(4, z, 1, -1, &m));
      /* cos and sin of multiples of pi/2 are not exactly 0: put the ring on the axes */
      static const double axis[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
      for (int i = 0; i < 4; i++) {
        m->xyz[3 * (2 + i)] = axis[i][0];
        m->xyz[3 * (2 + i) + 1] = axis[i][1];
      }
      if (moved) {
        m->xyz[0] += 0.125; /* A off x = 0 and y = 0; the four tets stay positive */
        m->xyz[1] += 0.0625;
      }
      mpq_t vol;
      if (measured(m, vol, "4-shell"))
        return 1;
      tr_flip_journal j;
      memset(&j, 0, sizeof j);
      j.tetgen_flips = mode;
      int done;
      CK(tr_flip_remove_edge_nm(m, 0, 1, TR_NONE, 1, NULL, NULL, &j, &done));
      int want = !(moved && mode);
      if (done != want)
        FAIL("tetgen44: A %s, %s flips: removal %s", moved ? "moved" : "on the axis",
             mode ? "TetGen's" : "general", done ? "made" : "refused");
      if (done) {
        if (has_edge(m, 0, 1) || tr_mesh_count_real(m) != 4)
          FAIL("tetgen44: AB still there or %u tets", tr_mesh_count_real(m));
        if (!moved && !has_edge(m, 2, 4) && !has_edge(m, 3, 5))
          FAIL("tetgen44: the new edge is not a diagonal coplanar with AB");
      } else if (!has_edge(m, 0, 1) || tr_mesh_count_real(m) != 4 || j.n != 0) {
        FAIL("tetgen44: a refused removal changed the mesh");
      }
      if (validate(m, vol, done ? "after the 4-4" : "after refusal"))
        return 1;
      tr_flip_journal_free(&j);
      mpq_clear(vol);
      tr_mesh_destroy(m);
    }
  }
  printf("tetgen44: the coplanar 4-4 is one of TetGen's flips, the other 4-shell is not\n");
  return 0;
}

int main(int argc, char **argv)
{
  if (argc < 2)
    return 2;
  const char *w = argv[1];
  int n = argc > 2 ? atoi(argv[2]) : 0;
  if (!strcmp(w, "ring") && n >= 3 && n <= 12)
    return test_ring(n);
  if (!strcmp(w, "ring_invalid"))
    return test_ring_invalid();
  if (!strcmp(w, "protected"))
    return test_protected();
  if (!strcmp(w, "flip23"))
    return test_flip23();
  if (!strcmp(w, "hull_cube"))
    return test_hull_cube();
  if (!strcmp(w, "recover") && n >= 3 && n <= 12)
    return test_recover(n);
  if (!strcmp(w, "edge_tet"))
    return test_edge_tet();
  if (!strcmp(w, "sxset"))
    return test_sxset();
  if (!strcmp(w, "blocked23"))
    return test_blocked23();
  if (!strcmp(w, "shell_kept"))
    return test_shell_kept();
  if (!strcmp(w, "tetgen44"))
    return test_tetgen44();
  fprintf(stderr, "unknown test %s\n", w);
  return 2;
}
