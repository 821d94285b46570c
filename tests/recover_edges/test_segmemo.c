/* The parked segment memos of edge recovery (segmemo.h's tr_segmemo_store): pass 1 parks
 * the memo of every sub-segment it leaves missing and its next flip level and pass 2 take
 * it back, so a parked memo must answer exactly as a fresh classification does on the
 * mesh as it is then, after other segments' flips replaced tets around it.
 *
 * Usage: test_segmemo park <seed>
 *
 * A Delaunay mesh of 300 random integer points in [0, 6)^3 (cospherical and coplanar
 * sets: many exact zeros). The first missing segment ab (not through a vertex) gets its
 * pipe collected through a memo, which is parked; flips then recover other missing
 * segments (tr_pipe_flip_first, depth 4), changing tets next to ab. The memo taken back
 * holds the same number of classifications as the one parked; for every real tet of the
 * mesh then, its answer (count, end types and codes) equals tr_segmemo_classify_ids; a
 * second take of ab gets an empty memo; parking an empty memo stores nothing; the store
 * counts its entries. The mesh passes the validator after the flips. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "recover_edges/edgeset.h"
#include "recover_edges/pipe.h"
#include "../pipeline/texpect.h"
#include "tdflip.h"
#include "trand.h"

static int same(tr_isect x, tr_isect y)
{
  if (x.n != y.n)
    return 0;
  for (int e = 0; e < x.n; e++)
    if (x.end[e].type != y.end[e].type || x.end[e].code != y.end[e].code)
      return 0;
  return 1;
}

static int park(void)
{
  const uint32_t np = 300;
  double x[3 * 300];
  for (uint32_t i = 0; i < 3 * np; i++)
    x[i] = (double)(next_u32() % 6);
  struct tr_mesh *m = NULL;
  if (tr_delaunay_build(x, np, &m) != TR_OK) {
    fprintf(stderr, "initial mesh: %s\n", tr_last_error());
    return 1;
  }
  tr_pipe p;
  memset(&p, 0, sizeof p);
  tr_edgeset cons;
  memset(&cons, 0, sizeof cons);
  tr_segmemo_store store;
  memset(&store, 0, sizeof store);
  tr_segmemo g;
  tr_segmemo_init(&g, m, 0, 0);
  /* the first missing segment from a point to one of the next ones, not through a vertex */
  uint32_t a = TR_NONE, b = TR_NONE, via = TR_NONE;
  for (uint32_t i = 0; i < np && a == TR_NONE; i++)
    for (uint32_t j = i + 1; j < np && j < i + 8 && a == TR_NONE; j++) {
      if (has_edge(m, i, j))
        continue;
      tr_segmemo_take(&store, &g, m, i, j);
      if (tr_pipe_collect_memo(m, i, j, &p, &via, &g) == TR_OK && via == TR_NONE && p.n > 2) {
        a = i;
        b = j;
      }
    }
  EXPECT(a != TR_NONE, "no missing segment: the test shows nothing");
  uint32_t held = g.map.n;
  EXPECT(held > p.n, "the memo holds %u classifications for a pipe of %u", held, p.n);
  tr_segmemo_park(&store, &g);
  EXPECT(g.map.n == 0 && store.entries == held, "parked: memo left with %u, store counts %llu",
         g.map.n, (unsigned long long)store.entries);
  /* an empty memo is not stored */
  tr_segmemo e;
  tr_segmemo_init(&e, m, b, a);
  tr_segmemo_park(&store, &e);
  EXPECT(store.entries == held && store.n == 1, "an empty memo was stored");
  /* flips elsewhere: every later missing segment that does not pass through a vertex */
  uint32_t recovered = 0, flipped = 0;
  for (uint32_t i = 0; i < np; i++) {
    uint32_t j = (i + 1 + next_u32() % 7) % np;
    if (j == i || (i == a && j == b) || has_edge(m, i, j))
      continue;
    if (tr_pipe_collect(m, i, j, &p, &via) != TR_OK || via != TR_NONE)
      continue;
    tr_edge_stats st;
    memset(&st, 0, sizeof st);
    int done = 0;
    EXPECT(tr_pipe_flip_first(m, i, j, &p, &cons, NULL, 4, 20000, 0, &st, &done) == TR_OK,
           "flips for %u-%u: %s", i, j, tr_last_error());
    flipped += st.flip23 + st.flip32 + st.flip44 + st.flipn + st.flip_hull;
    if (done) {
      recovered++;
      EXPECT(tr_edgeset_put(&cons, i, j, i) == TR_OK, "out of memory");
    }
  }
  EXPECT(flipped > 0, "no flip was made: the test shows nothing");
  EXPECT(tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T | TR_CHK_EULER, NULL) ==
             TR_OK, "mesh after the flips: %s", tr_last_error());
  tr_segmemo_take(&store, &g, m, a, b);
  EXPECT(g.a == a && g.b == b && g.map.n == held && store.entries == 0,
         "taken back: %u classifications of %u-%u, %u parked; store counts %llu", g.map.n, g.a,
         g.b, held, (unsigned long long)store.entries);
  uint32_t checked = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    const uint32_t *v = m->tv + 4 * (size_t)t;
    tr_isect got = tr_segmemo_classify(&g, m, v), want = tr_segmemo_classify_ids(m, a, b, v);
    EXPECT(same(got, want), "tet %u (%u %u %u %u): the parked memo answers differently", t,
           v[0], v[1], v[2], v[3]);
    checked++;
  }
  tr_segmemo_take(&store, &g, m, a, b);
  EXPECT(g.map.n == 0, "a second take of %u-%u got %u classifications", a, b, g.map.n);
  fprintf(stderr, "segment %u-%u: %u classifications parked; %u flips elsewhere, %u segments "
                  "recovered; %u tets checked\n", a, b, held, flipped, recovered, checked);
  tr_segmemo_free(&g);
  tr_segmemo_store_free(&store);
  tr_edgeset_free(&cons);
  tr_pipe_free(&p);
  tr_mesh_destroy(m);
  return failures != 0;
}

int main(int argc, char **argv)
{
  if (argc == 3 && !strcmp(argv[1], "park")) {
    rng = strtoull(argv[2], NULL, 10);
    return park();
  }
  fprintf(stderr, "usage: test_segmemo park <seed>\n");
  return 2;
}
