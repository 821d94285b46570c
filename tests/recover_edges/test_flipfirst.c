/* Edge recovery by removing the crossings from the segment's ends (flipfirst.c).
 *
 * Usage: test_flipfirst lattice <npoints> <seed> <range> <depth> [tetgen]
 *        test_flipfirst prism <path of tests/data/twisted_star_prism.off>
 *
 * lattice: a Delaunay mesh of random integer points in [0, range)^3 (cospherical and
 *   coplanar sets), short random segments recovered one after the other by
 *   tr_pipe_flip_first at the given depth, the recovered ones protected. After every call
 *   the validator runs (links, exact orientation, v2t, Euler, exact volume unchanged);
 *   a segment reported recovered is a mesh edge; every protected edge is still one; and
 *   a segment left missing crosses no more faces and edges than before: every flip kept
 *   created nothing the segment crosses (the admission rule), also the flips of a
 *   removal that failed. Some segment must be recovered, else the test shows nothing.
 *   With "tetgen", edge removal only as TetGen's flips reach it (3-2, n-m on flat rings,
 *   the coplanar 4-4).
 *
 * retry: 16 lattice points in [0, 6)^3 (the smallest set found) and the segment 1-14 it
 *   misses. At depth 6 the search under TetGen's star rule leaves it missing; with
 *   TR_FLIPFIRST_RETRY the search without the rule, made where the rule cut a branch,
 *   recovers it. tr_recover_edges with 1-14 as the only input edge adds no Steiner point
 *   (one before the retry: the rule cut the only removal sequence it has). Every mesh
 *   through the validator with the exact volume.
 *
 * prism: a star-shaped prism (8 points, radii 1 and 0.7) whose top is turned by 0.1
 *   radians, sides and caps in fans: 16 of its edges are missing from the Delaunay mesh.
 *   The whole pipeline recovers every one by flips, with no Steiner point (one point
 *   was needed while the recovery kept only flips that shortened the pipe), and the mesh
 *   passes the mesh and exact conformity validators. */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "recover_edges/edgeset.h"
#include "recover_edges/pipe.h"
#include "recover_edges/recover_edges.h"
#include "../pipeline/tmesh.h"
#include "tdflip.h"
#include "trand.h"

/* The faces and edges the pipe's real pipels cross at an end, each once. */
static uint32_t crossings(const struct tr_mesh *m, const tr_pipe *p, tr_sxset *seen)
{
  uint32_t n = 0;
  tr_sxset_clear(seen);
  for (uint32_t i = 0; i < p->n; i++) {
    const tr_pipel *pl = &p->pl[i];
    const uint32_t *tv = m->tv + 4 * (size_t)pl->iEle;
    for (int e = 0; e < 2 && !pl->ghost; e++) {
      int ty = e ? (pl->type >> 2) & 3 : pl->type & 3, code = e ? pl->iCod2 : pl->iCod1;
      uint32_t key[3] = {TR_NONE, TR_NONE, TR_NONE};
      if (ty == TR_FAC)
        for (int q = 0; q < 3; q++)
          key[q] = tv[tr_face_vtx[code][q]];
      else if (ty == TR_EDG) {
        key[0] = tv[tr_ecode_start(code)];
        key[1] = tv[tr_ecode_end(code)];
      } else
        continue;
      n += tr_sxset_add(seen, key) == 1;
    }
  }
  return n;
}

static int lattice(uint32_t np, uint32_t range, int depth, int tetgen)
{
  double *x = malloc(sizeof *x * 3 * np);
  struct tr_mesh *m = NULL;
  if (!x)
    return 1;
  for (uint32_t i = 0; i < 3 * np; i++)
    x[i] = (double)(next_u32() % range);
  mpq_t vol;
  mpq_init(vol);
  if (tr_delaunay_build(x, np, &m) != TR_OK || tr_check_mesh(m, CHECKS, NULL) != TR_OK ||
      tr_mesh_volume6(m, vol) != TR_OK) {
    fprintf(stderr, "initial mesh: %s\n", tr_last_error());
    return 1;
  }
  tr_edgeset cons;
  tr_pipe p;
  tr_sxset seen = {0};
  memset(&cons, 0, sizeof cons);
  memset(&p, 0, sizeof p);
  int bad = 0, tried = 0, got = 0, fewer = 0;
  uint32_t seg[2 * 400];
  int nseg = 0;
  /* short segments, like a surface's edges: each from a point to one of a few near it */
  for (uint32_t i = 0; i < np && nseg < 400; i++) {
    uint32_t best = TR_NONE;
    double bd = 0;
    for (int k = 0; k < 8; k++) {
      uint32_t j = next_u32() % np;
      double d = 0;
      for (int c = 0; c < 3; c++)
        d += (x[3 * i + c] - x[3 * j + c]) * (x[3 * i + c] - x[3 * j + c]);
      if (j != i && d > 0 && (best == TR_NONE || d < bd)) {
        best = j;
        bd = d;
      }
    }
    if (best != TR_NONE) {
      seg[2 * nseg] = i;
      seg[2 * nseg + 1] = best;
      nseg++;
    }
  }
  for (int i = 0; i < nseg && !bad; i++) {
    uint32_t a = seg[2 * i], b = seg[2 * i + 1], via = TR_NONE;
    if (has_edge(m, a, b) || tr_edgeset_get(&cons, a, b) != TR_EDGESET_NONE)
      continue;
    if (tr_pipe_collect(m, a, b, &p, &via) != TR_OK || via != TR_NONE)
      continue; /* through a vertex: not a flip case */
    /* a segment crossing a protected edge cannot be recovered: not a flip case either */
    uint32_t c0 = crossings(m, &p, &seen);
    tried++;
    tr_edge_stats st;
    memset(&st, 0, sizeof st);
    int done = 0;
    tr_status s = tr_pipe_flip_first(m, a, b, &p, &cons, NULL, depth, 20000, tetgen, &st,
                                      &done);
    if (s != TR_OK) {
      fprintf(stderr, "segment %u-%u: %s\n", a, b, tr_last_error());
      bad++;
    } else if (tr_check_mesh(m, CHECKS, vol) != TR_OK) {
      fprintf(stderr, "segment %u-%u: %s\n", a, b, tr_last_error());
      bad++;
    } else if (done && !has_edge(m, a, b)) {
      fprintf(stderr, "segment %u-%u reported recovered but missing\n", a, b);
      bad++;
    } else if (done) {
      got++;
      if (tr_edgeset_put(&cons, a, b, (uint32_t)i) != TR_OK)
        bad++;
    } else {
      uint32_t c1 = crossings(m, &p, &seen);
      if (c1 > c0) {
        fprintf(stderr, "segment %u-%u left missing crosses %u simplices, %u before\n", a,
                b, c1, c0);
        bad++;
      }
      fewer += c1 < c0;
    }
    for (int k = 0; k < i && !bad; k++)
      if (tr_edgeset_get(&cons, seg[2 * k], seg[2 * k + 1]) != TR_EDGESET_NONE &&
          !has_edge(m, seg[2 * k], seg[2 * k + 1])) {
        fprintf(stderr, "protected edge %u-%u deleted by segment %u-%u\n", seg[2 * k],
                seg[2 * k + 1], a, b);
        bad++;
      }
  }
  fprintf(stderr, "%d missing segments, %d recovered by flips, %d left with fewer crossings\n",
          tried, got, fewer);
  if (!bad && got == 0) {
    fprintf(stderr, "no segment recovered: the test shows nothing\n");
    bad++;
  }
  tr_pipe_free(&p);
  tr_edgeset_free(&cons);
  tr_sxset_free(&seen);
  tr_mesh_destroy(m);
  mpq_clear(vol);
  free(x);
  return bad != 0;
}

static const double retry_pts[16][3] = {
  {2, 0, 3}, {1, 2, 0}, {5, 1, 4}, {4, 2, 4}, {1, 1, 4}, {2, 3, 1}, {4, 1, 5}, {1, 4, 5},
  {0, 5, 5}, {5, 3, 4}, {2, 1, 3}, {4, 4, 2}, {2, 4, 1}, {0, 2, 5}, {5, 5, 4}, {0, 5, 1},
};

/* The Delaunay mesh of retry_pts, through the validator; vol: its exact volume. */
static struct tr_mesh *retry_mesh(mpq_t vol)
{
  struct tr_mesh *m = NULL;
  EXPECT(tr_delaunay_build(&retry_pts[0][0], 16, &m) == TR_OK, "delaunay: %s",
         tr_last_error());
  if (m)
    EXPECT(tr_check_mesh(m, CHECKS, NULL) == TR_OK && tr_mesh_volume6(m, vol) == TR_OK,
           "initial mesh: %s", tr_last_error());
  return m;
}

/* tr_pipe_flip_first(1-14, depth 6, mode) on a fresh mesh: 1 if recovered, 0 if not,
 * -1 on an error or an invalid mesh. */
static int retry_search(unsigned mode)
{
  mpq_t vol;
  mpq_init(vol);
  struct tr_mesh *m = retry_mesh(vol);
  int r = -1;
  tr_pipe p;
  tr_edgeset cons;
  memset(&p, 0, sizeof p);
  memset(&cons, 0, sizeof cons);
  uint32_t via = TR_NONE;
  if (m && !has_edge(m, 1, 14) && tr_pipe_collect(m, 1, 14, &p, &via) == TR_OK &&
      via == TR_NONE) {
    tr_edge_stats st;
    memset(&st, 0, sizeof st);
    int done = 0;
    if (tr_pipe_flip_first(m, 1, 14, &p, &cons, NULL, 6, 20000, mode, &st, &done) == TR_OK &&
        tr_check_mesh(m, CHECKS, vol) == TR_OK)
      r = done && has_edge(m, 1, 14);
    EXPECT(r >= 0, "mode %u: %s", mode, tr_last_error());
    EXPECT(r < 0 || done == r, "mode %u: reported %d, the mesh says %d", mode, done, r);
  } else {
    EXPECT(0, "1-14 is not a missing segment through no vertex of the mesh");
  }
  tr_pipe_free(&p);
  tr_edgeset_free(&cons);
  tr_mesh_destroy(m);
  mpq_clear(vol);
  return r;
}

static int retry(void)
{
  EXPECT(retry_search(0) == 0, "under the star rule 1-14 was recovered: the case shows nothing");
  EXPECT(retry_search(TR_FLIPFIRST_RETRY) == 1, "the retry without the star rule left 1-14");
  mpq_t vol;
  mpq_init(vol);
  struct tr_mesh *m = retry_mesh(vol);
  const uint32_t e[2] = {1, 14};
  tr_edge_chains ch;
  tr_edge_recovery_stats st;
  memset(&ch, 0, sizeof ch);
  memset(&st, 0, sizeof st);
  if (m) {
    EXPECT(tr_recover_edges(m, e, 1, &ch, &st) == TR_OK, "recovery: %s", tr_last_error());
    EXPECT(tr_check_mesh(m, CHECKS, vol) == TR_OK, "after recovery: %s", tr_last_error());
    EXPECT(st.missing_edges == 1, "%llu edges missing, expected 1",
           (unsigned long long)st.missing_edges);
    EXPECT(st.points_added == 0 && m->nv == 16, "%llu Steiner points, expected none",
           (unsigned long long)st.points_added);
    EXPECT(has_edge(m, 1, 14), "1-14 is not a mesh edge after recovery");
  }
  tr_edge_chains_free(&ch);
  tr_mesh_destroy(m);
  mpq_clear(vol);
  return failures != 0;
}

static int prism(const char *path)
{
  tr_plc *plc = tm_read(path);
  tr_options opt = tm_options();
  tm_run r;
  if (tm_mesh(&r, "twisted star prism", plc, &opt, CHECKS & ~TR_CHK_EULER)) {
    EXPECT(r.st.missing_edges > 0, "no edge missing after Delaunay: the test shows nothing");
    EXPECT(r.st.points_added_for_edges == 0, "%llu Steiner points for edges, expected none",
           (unsigned long long)r.st.points_added_for_edges);
    EXPECT(r.st.steiner_on_edges + r.st.steiner_on_facets + r.st.steiner_interior == 0,
           "Steiner points left in the mesh");
    fprintf(stderr, "%llu edges missing after Delaunay, %llu Steiner points\n",
            (unsigned long long)r.st.missing_edges,
            (unsigned long long)r.st.points_added_for_edges);
  }
  tm_free(&r);
  tr_plc_destroy(plc);
  return failures != 0;
}

int main(int argc, char **argv)
{
  if ((argc == 6 || argc == 7) && !strcmp(argv[1], "lattice")) {
    rng = strtoull(argv[3], NULL, 10);
    return lattice((uint32_t)atoi(argv[2]), (uint32_t)atoi(argv[4]), atoi(argv[5]),
                   argc == 7 && !strcmp(argv[6], "tetgen"));
  }
  if (argc == 2 && !strcmp(argv[1], "retry"))
    return retry();
  if (argc == 3 && !strcmp(argv[1], "prism"))
    return prism(argv[2]);
  fprintf(stderr, "usage: test_flipfirst lattice N SEED RANGE DEPTH | retry | prism FILE\n");
  return 2;
}
