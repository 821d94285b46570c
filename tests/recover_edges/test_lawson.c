/* Lawson flips around a midpoint (src/recover_edges/lawson.h) on Delaunay meshes of
 * random points, every result through the validator (links, exact orientation, v2t,
 * Euler, exact volume unchanged).
 * Usage: test_lawson delaunay <seed> | guarded <seed>
 *
 * delaunay: segments between random vertex pairs that are not mesh edges are split at
 *   their exact midpoint (tr_pipe_split_mid, a rational point when the ends are
 *   integers' halves apart) and Lawson flips run around it, without a guard. Joe's
 *   theorem: one point inserted into a Delaunay mesh followed by the flips gives a
 *   Delaunay mesh again, so after every split every face of the whole mesh must be
 *   locally Delaunay. The split alone must have broken that at least once (else the test
 *   would prove nothing).
 * guarded: the same with a guard protecting a fixed third of the edges. After the flips
 *   every protected edge present before them is still there, and every link face of the
 *   new point that is not locally Delaunay is unflippable: the 2-3 flip and every 3-2 flip
 *   through it are refused. The guard must have blocked at least one flip. */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "recover_edges/lawson.h"
#include "recover_edges/pipe.h"
#include "tmesh.h"
#include "trand.h"

static uint64_t refusals; /* protected edges the guard was asked about */
static int protect(void *ud, const uint32_t *v, int nv)
{
  (void)ud;
  if (nv != 2)
    return 0;
  uint32_t a = v[0] < v[1] ? v[0] : v[1], b = v[0] ^ v[1] ^ a;
  int yes = (a * 7u + b * 13u) % 3u == 0;
  refusals += yes;
  return yes;
}

/* Number of faces of real tets that are not locally Delaunay. */
static uint32_t bad_faces(const struct tr_mesh *m)
{
  uint32_t n = 0;
  for (uint32_t t = 0; t < m->nt; t++)
    for (int k = 0; k < 4 && tr_tet_is_real(m, t); k++)
      n += !tr_lawson_face_ok(m, t, k);
  return n;
}

/* The protected edges of the mesh (pairs, each once). */
static tr_status protected_edges(struct tr_mesh *m, tr_u32buf *out)
{
  out->n = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    for (int e = 0; e < 6; e++) {
      uint32_t v[2] = {m->tv[4 * t + tr_edge_vtx[e][0]], m->tv[4 * t + tr_edge_vtx[e][1]]};
      if (v[0] > v[1] || !protect(NULL, v, 2))
        continue; /* each edge once per tet is enough: duplicates are harmless */
      TR_CHECK(tr_u32buf_push(out, v[0]));
      TR_CHECK(tr_u32buf_push(out, v[1]));
    }
  }
  return TR_OK;
}

/* 1 iff a flip of link face k of t (opposite p) is possible under the guard: tried for
 * real (the caller fails the test on a 1, so the changed mesh does not matter). */
static int flippable(struct tr_mesh *m, uint32_t t, int k)
{
  int done;
  if (tr_flip23(m, t, k, protect, NULL, NULL, &done) != TR_OK || done)
    return 1;
  for (int j = 0; j < 4; j++) {
    if (j == k)
      continue;
    uint32_t e[2], ne = 0;
    for (int i = 0; i < 4; i++)
      if (i != j && i != k)
        e[ne++] = m->tv[4 * t + i];
    /* a 3-2 flip only: shell of exactly three real tets */
    tr_u32buf sh = {0};
    int closed, real3 = 0;
    if (tr_shell(m, e[0], e[1], t, &sh, &closed) == TR_OK && closed && sh.n == 3)
      real3 = tr_tet_is_real(m, sh.a[0]) && tr_tet_is_real(m, sh.a[1]) &&
              tr_tet_is_real(m, sh.a[2]);
    tr_u32buf_free(&sh);
    if (real3 && (tr_flip_remove_edge(m, e[0], e[1], t, protect, NULL, NULL, &done) != TR_OK ||
                  done))
      return 1;
  }
  return 0;
}

static int run(uint64_t seed, int guarded)
{
  rng = seed;
  const uint32_t np = 300;
  double *xyz = malloc(3 * (size_t)np * sizeof *xyz);
  for (uint32_t i = 0; i < 3 * np; i++)
    xyz[i] = (double)(next_u32() % 1000000);
  struct tr_mesh *m;
  tr_status s = tr_delaunay_build(xyz, np, &m);
  free(xyz);
  if (s != TR_OK)
    FAIL("delaunay: %s", tr_last_error());
  mpq_t vol;
  mpq_init(vol);
  CK(tr_mesh_volume6(m, vol));
  if (bad_faces(m))
    FAIL("the Delaunay mesh has non-Delaunay faces");
  tr_pipe pipe = {0};
  tr_lawson L = {0};
  tr_lawson_stats st = {0};
  tr_u32buf prot = {0}, ball = {0};
  uint32_t splits = 0, broken = 0;
  uint64_t lawson_refusals = 0;
  while (splits < 40) {
    uint32_t a = next_u32() % np, b = next_u32() % np, via, mid;
    int yes, ok;
    if (a == b || m->v2t[a] == TR_NONE || m->v2t[b] == TR_NONE)
      continue;
    CK(tr_mesh_has_edge(m, a, b, &yes));
    if (yes)
      continue;
    CK(tr_pipe_collect(m, a, b, &pipe, &via));
    if (via != TR_NONE)
      continue;
    CK(tr_pipe_split_mid(m, a, b, &pipe, NULL, NULL, &mid, &ok));
    if (!ok)
      FAIL("split of %u-%u refused", a, b);
    splits++;
    if (guarded) {
      CK(protected_edges(m, &prot));
    } else {
      broken += bad_faces(m) > 0;
    }
    uint64_t capped = st.capped;
    uint64_t r0 = refusals;
    CK(tr_lawson_vertex(m, mid, guarded ? protect : NULL, NULL, &L, &st));
    lawson_refusals += refusals - r0;
    if (st.capped != capped)
      FAIL("split %u: the flip budget was hit", splits);
    if (validate(m, vol, "after Lawson"))
      return 1;
    if (!guarded) {
      uint32_t nb = bad_faces(m);
      if (nb)
        FAIL("split %u (midpoint of %u-%u): %u faces not locally Delaunay after the flips",
             splits, a, b, nb);
      continue;
    }
    for (size_t i = 0; i < prot.n; i += 2) {
      CK(tr_mesh_has_edge(m, prot.a[i], prot.a[i + 1], &yes));
      if (!yes)
        FAIL("split %u: protected edge %u-%u deleted", splits, prot.a[i], prot.a[i + 1]);
    }
    CK(tr_ball(m, mid, 0, &ball));
    for (size_t i = 0; i < ball.n; i++) {
      uint32_t t = ball.a[i];
      int k = tr_ncode(m, t, mid);
      if (!tr_lawson_face_ok(m, t, k) && flippable(m, t, k))
        FAIL("split %u: a flippable non-Delaunay link face of %u was left", splits, mid);
    }
  }
  printf("%s seed %llu: %u midpoint splits (%u broke the Delaunay property); faces tested "
         "%llu, flips 2-3 %llu, 3-2 %llu, blocked %llu (guard refusals %llu)\n",
         guarded ? "guarded" : "delaunay", (unsigned long long)seed, splits, broken,
         (unsigned long long)st.tested, (unsigned long long)st.flip23,
         (unsigned long long)st.flip32, (unsigned long long)st.blocked,
         (unsigned long long)lawson_refusals);
  if (!guarded && (broken == 0 || st.flip23 + st.flip32 == 0))
    FAIL("no split broke the Delaunay property: the test proves nothing");
  if (guarded && (st.blocked == 0 || lawson_refusals == 0))
    FAIL("the guard never refused a flip: the test proves nothing");
  tr_pipe_free(&pipe);
  tr_lawson_free(&L);
  tr_u32buf_free(&prot);
  tr_u32buf_free(&ball);
  mpq_clear(vol);
  tr_mesh_destroy(m);
  return 0;
}

int main(int argc, char **argv)
{
  if (argc == 3 && (!strcmp(argv[1], "delaunay") || !strcmp(argv[1], "guarded")))
    return run((uint64_t)atoll(argv[2]), !strcmp(argv[1], "guarded"));
  fprintf(stderr, "usage: test_lawson delaunay|guarded <seed>\n");
  return 2;
}
