/* The deeper flip search that edge recovery tries on a short pipe before a Steiner point
 * (tr_pipe_try_flips_depth, depth 4 of recover_edges.c).
 * Usage: test_deepflip <npoints> <seed> [coordinate range, default 1000]
 *
 * Two Delaunay meshes of the same random integer points, lattice points in a small range
 * (degenerate: cospherical and coplanar sets, the cases where depth 4 pays; the build is
 * deterministic, so the two are the same mesh). Segments are short, like a surface's
 * edges. In each, the segments that are not mesh edges (and pass through no vertex) are
 * recovered by flips alone, one after the other, the recovered ones protected: in the first mesh with depth 3 (what pass 1 does),
 * in the second with depth 3 and then, where that fails, depth 4. After every call the
 * validator runs (links, exact orientation, v2t, Euler, exact volume unchanged); a
 * segment reported recovered is a mesh edge, and every protected edge is still one. Depth
 * 4 must recover some segment that depth 3 could not, else the test shows nothing (the
 * two meshes are not compared segment by segment: they diverge once one has more). */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "recover_edges/edgeset.h"
#include "recover_edges/pipe.h"

static const unsigned CHECKS = TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T | TR_CHK_EULER;
static int failures;

static uint64_t rng;
static uint32_t next_u32(void)
{
  rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
  return (uint32_t)(rng >> 33);
}

static int has_edge(struct tr_mesh *m, uint32_t a, uint32_t b)
{
  int yes = 0;
  return tr_mesh_has_edge(m, a, b, &yes) == TR_OK && yes;
}

/* Recovers the segments seg[0..2n) by flips; returns how many, or -1 on a failure. */
static int run(struct tr_mesh *m, const uint32_t *seg, int n, int deep, mpq_t vol, int *extra)
{
  tr_edgeset cons;
  tr_pipe p;
  memset(&cons, 0, sizeof cons);
  memset(&p, 0, sizeof p);
  int got = 0;
  *extra = 0;
  for (int i = 0; i < n && !failures; i++) {
    uint32_t a = seg[2 * i], b = seg[2 * i + 1], via = TR_NONE;
    if (has_edge(m, a, b))
      continue;
    if (tr_pipe_collect(m, a, b, &p, &via) != TR_OK || via != TR_NONE)
      continue; /* through a vertex: not a flip case */
    tr_edge_stats st;
    memset(&st, 0, sizeof st);
    int done = 0;
    tr_status s = tr_pipe_try_flips(m, a, b, &p, &cons, NULL, &st, &done);
    if (s == TR_OK && !done && deep) {
      s = tr_pipe_try_flips_depth(m, a, b, &p, &cons, NULL, 4, &st, &done);
      *extra += done;
    }
    if (s != TR_OK) {
      fprintf(stderr, "segment %u-%u: %s\n", a, b, tr_last_error());
      failures++;
    } else if (tr_check_mesh(m, CHECKS, vol) != TR_OK) {
      fprintf(stderr, "segment %u-%u (deep %d): %s\n", a, b, deep, tr_last_error());
      failures++;
    } else if (done && !has_edge(m, a, b)) {
      fprintf(stderr, "segment %u-%u reported recovered but missing\n", a, b);
      failures++;
    } else if (done) {
      got++;
      if (tr_edgeset_put(&cons, a, b, (uint32_t)i) != TR_OK)
        failures++;
    }
    for (int k = 0; k < i && !failures; k++)
      if (tr_edgeset_get(&cons, seg[2 * k], seg[2 * k + 1]) != TR_EDGESET_NONE &&
          !has_edge(m, seg[2 * k], seg[2 * k + 1])) {
        fprintf(stderr, "protected edge %u-%u deleted by segment %u-%u\n", seg[2 * k],
                seg[2 * k + 1], a, b);
        failures++;
      }
  }
  tr_pipe_free(&p);
  tr_edgeset_free(&cons);
  return failures ? -1 : got;
}

int main(int argc, char **argv)
{
  if (argc < 3)
    return 2;
  uint32_t np = (uint32_t)atoi(argv[1]), range = argc > 3 ? (uint32_t)atoi(argv[3]) : 1000;
  rng = (uint64_t)atoll(argv[2]);
  double *x = malloc(sizeof *x * 3 * np);
  if (!x)
    return 1;
  for (uint32_t i = 0; i < 3 * np; i++)
    x[i] = (double)(next_u32() % range);
  struct tr_mesh *m3 = NULL, *m4 = NULL;
  if (tr_delaunay_build(x, np, &m3) != TR_OK || tr_delaunay_build(x, np, &m4) != TR_OK) {
    fprintf(stderr, "delaunay: %s\n", tr_last_error());
    return 1;
  }
  /* short segments, like a surface's edges: from a random vertex a, a walk of `hops`
   * random face crossings from one of its tets; b a vertex of the tet reached that is not
   * a's neighbour */
  int nseg = 0, cap = 400;
  uint32_t *seg = malloc(sizeof *seg * 2 * (size_t)cap);
  for (int tries = 0; tries < 20 * cap && nseg < cap && seg; tries++) {
    uint32_t a = next_u32() % np, t = m3->v2t[a];
    int hops = 2 + (int)(next_u32() % 3);
    for (int h = 0; h < hops && t != TR_NONE; h++) {
      uint32_t nb = m3->tn[4 * (size_t)t + next_u32() % 4];
      t = nb == TR_NONE ? TR_NONE : nb >> 2;
    }
    if (t == TR_NONE || !tr_tet_is_real(m3, t))
      continue;
    uint32_t b = m3->tv[4 * (size_t)t + next_u32() % 4];
    if (b == a || has_edge(m3, a, b))
      continue;
    seg[2 * nseg] = a;
    seg[2 * nseg++ + 1] = b;
  }
  mpq_t vol;
  mpq_init(vol);
  if (tr_check_mesh(m3, CHECKS, NULL) != TR_OK || tr_mesh_volume6(m3, vol) != TR_OK) {
    fprintf(stderr, "initial mesh: %s\n", tr_last_error());
    return 1;
  }
  int e3, e4;
  int r3 = run(m3, seg, nseg, 0, vol, &e3);
  int r4 = run(m4, seg, nseg, 1, vol, &e4);
  printf("%u points, %d segments: depth 3 recovers %d; depth 3 then 4 recovers %d (%d by "
         "depth 4)\n",
         np, nseg, r3, r4, e4);
  if (!failures && e4 == 0) {
    fprintf(stderr, "depth 4 recovered nothing depth 3 could not: a test of nothing\n");
    failures++;
  }
  mpq_clear(vol);
  tr_mesh_destroy(m3);
  tr_mesh_destroy(m4);
  free(x);
  free(seg);
  return failures != 0;
}
