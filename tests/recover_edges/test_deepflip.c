/* The pipel-count flip search of flipseg.c: depth 4 on a short pipe before a Steiner
 * point (recover_edges.c), and deeper levels with a flip budget (tr_pipe_try_flips_budget).
 * Usage: test_deepflip <npoints> <seed> [coordinate range, default 1000] [depth D, default
 *        4] [flip budget, default 0 = none]
 *        test_deepflip faceedge <npoints> <seed> <range>
 *
 * Two Delaunay meshes of the same random integer points, lattice points in a small range
 * (degenerate: cospherical and coplanar sets, the cases where depth 4 pays; the build is
 * deterministic, so the two are the same mesh). Segments are short, like a surface's
 * edges. In each, the segments that are not mesh edges (and pass through no vertex) are
 * recovered by flips alone, one after the other, the recovered ones protected: in the
 * first mesh with depth 3 (what pass 1 does), then, where that fails, each depth from 4
 * to D-1 in turn; in the second the same and then depth D. After every call the validator
 * runs (links, exact orientation, v2t, Euler, exact volume unchanged); a segment reported
 * recovered is a mesh edge, and every protected edge is still one. Depth D must recover
 * some segment that depths 3..D-1 could not, else the test shows nothing (the two meshes
 * are not compared segment by segment: they diverge once one has more).
 *
 * faceedge: segments whose pipe is three tets, ab crossing two faces, where the Swap23 of
 * both faces is refused (tried, and undone if made); tr_pipe_try_flips must recover some
 * of them (by removing an edge of a crossed face), validator after each. */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "recover_edges/edgeset.h"
#include "recover_edges/pipe.h"
#include "tdflip.h"
#include "trand.h"

static int failures;

/* Recovers the segments seg[0..2n) by flips, depth 3, then 4 .. maxd where that fails;
 * returns how many, or -1 on a failure; *extra: how many depth maxd recovered. */
static int run(struct tr_mesh *m, const uint32_t *seg, int n, int maxd, uint32_t budget,
               mpq_t vol, int *extra)
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
    for (int d = 4; d <= maxd && s == TR_OK && !done; d++) {
      s = tr_pipe_try_flips_budget(m, a, b, &p, &cons, NULL, d, budget, &st, &done);
      if (d == maxd)
        *extra += done;
    }
    if (s != TR_OK) {
      fprintf(stderr, "segment %u-%u: %s\n", a, b, tr_last_error());
      failures++;
    } else if (tr_check_mesh(m, CHECKS, vol) != TR_OK) {
      fprintf(stderr, "segment %u-%u (depth %d): %s\n", a, b, maxd, tr_last_error());
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

/* 1 iff the Swap23 of face k of t is refused (when it is made, it is undone). */
static int swap23_refused(struct tr_mesh *m, uint32_t t, int k)
{
  tr_flip_rec rec;
  int done = 0;
  if (tr_flip23(m, t, k, NULL, NULL, &rec, &done) != TR_OK) {
    failures++;
    return 0;
  }
  if (done && tr_flip_undo(m, &rec) != TR_OK)
    failures++;
  return !done;
}

static int faceedge(uint32_t np, uint32_t range)
{
  double *x = malloc(sizeof *x * 3 * np);
  struct tr_mesh *m = NULL;
  if (!x)
    return 1;
  for (uint32_t i = 0; i < 3 * np; i++)
    x[i] = (double)(next_u32() % range);
  if (tr_delaunay_build(x, np, &m) != TR_OK) {
    fprintf(stderr, "delaunay: %s\n", tr_last_error());
    return 1;
  }
  mpq_t vol;
  mpq_init(vol);
  if (tr_check_mesh(m, CHECKS, NULL) != TR_OK || tr_mesh_volume6(m, vol) != TR_OK) {
    fprintf(stderr, "initial mesh: %s\n", tr_last_error());
    return 1;
  }
  tr_edgeset cons;
  tr_pipe p;
  memset(&cons, 0, sizeof cons);
  memset(&p, 0, sizeof p);
  int cases = 0, got = 0;
  for (uint32_t a = 0; a < np && !failures; a++)
    for (uint32_t b = a + 1; b < np && !failures; b++) {
      uint32_t via = TR_NONE;
      if (has_edge(m, a, b) || tr_pipe_collect(m, a, b, &p, &via) != TR_OK || via != TR_NONE)
        continue;
      /* three real tets: a's (NOD_FAC), the middle one (FAC_FAC), b's (FAC_NOD) */
      uint32_t nreal = 0, nfac = 0;
      for (uint32_t i = 0; i < p.n; i++)
        if (!p.pl[i].ghost) {
          nreal++;
          int ty = p.pl[i].type & 15;
          nfac += ty == TR_PIPEL_TYPE(TR_NOD, TR_FAC) || ty == TR_PIPEL_TYPE(TR_FAC, TR_NOD);
        }
      if (nreal != 3 || nfac != 2)
        continue;
      int refused = 1;
      for (uint32_t i = 0; i < p.n && refused; i++)
        if (!p.pl[i].ghost && (p.pl[i].type & 15) == TR_PIPEL_TYPE(TR_NOD, TR_FAC))
          refused = swap23_refused(m, p.pl[i].iEle, p.pl[i].iCod2);
        else if (!p.pl[i].ghost && (p.pl[i].type & 15) == TR_PIPEL_TYPE(TR_FAC, TR_NOD))
          refused = swap23_refused(m, p.pl[i].iEle, p.pl[i].iCod1);
      if (!refused || failures)
        continue;
      if (tr_pipe_collect(m, a, b, &p, &via) != TR_OK)
        failures++;
      cases++;
      tr_edge_stats st;
      memset(&st, 0, sizeof st);
      int done = 0;
      if (!failures && tr_pipe_try_flips(m, a, b, &p, &cons, NULL, &st, &done) != TR_OK) {
        fprintf(stderr, "segment %u-%u: %s\n", a, b, tr_last_error());
        failures++;
      } else if (tr_check_mesh(m, CHECKS, vol) != TR_OK) {
        fprintf(stderr, "segment %u-%u: %s\n", a, b, tr_last_error());
        failures++;
      } else if (done && !has_edge(m, a, b)) {
        fprintf(stderr, "segment %u-%u reported recovered but missing\n", a, b);
        failures++;
      } else if (done) {
        got++;
        if (tr_edgeset_put(&cons, a, b, 0) != TR_OK)
          failures++;
      }
    }
  printf("%u points: %d segments through two faces whose Swap23 is refused, %d recovered by "
         "flips\n", np, cases, got);
  if (!failures && got == 0) {
    fprintf(stderr, "no such segment recovered: a test of nothing\n");
    failures++;
  }
  tr_pipe_free(&p);
  tr_edgeset_free(&cons);
  mpq_clear(vol);
  tr_mesh_destroy(m);
  free(x);
  return failures != 0;
}

int main(int argc, char **argv)
{
  if (argc == 5 && strcmp(argv[1], "faceedge") == 0) {
    rng = (uint64_t)atoll(argv[3]);
    return faceedge((uint32_t)atoi(argv[2]), (uint32_t)atoi(argv[4]));
  }
  if (argc < 3)
    return 2;
  uint32_t np = (uint32_t)atoi(argv[1]), range = argc > 3 ? (uint32_t)atoi(argv[3]) : 1000;
  int maxd = argc > 4 ? atoi(argv[4]) : 4;
  uint32_t budget = argc > 5 ? (uint32_t)atoi(argv[5]) : 0;
  if (maxd < 4)
    return 2;
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
  int r3 = run(m3, seg, nseg, maxd - 1, budget, vol, &e3);
  int r4 = run(m4, seg, nseg, maxd, budget, vol, &e4);
  printf("%u points, %d segments: depths 3..%d recover %d; depths 3..%d recover %d (%d by "
         "depth %d)\n",
         np, nseg, maxd - 1, r3, maxd, r4, e4, maxd);
  if (!failures && e4 == 0) {
    fprintf(stderr, "depth %d recovered nothing depths 3..%d could not: a test of nothing\n",
            maxd, maxd - 1);
    failures++;
  }
  mpq_clear(vol);
  tr_mesh_destroy(m3);
  tr_mesh_destroy(m4);
  free(x);
  free(seg);
  return failures != 0;
}
