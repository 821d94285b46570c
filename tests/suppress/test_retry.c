/* Unit test of what a retried interior point costs (src/suppress/flipout.c): the
 * suppression passes retry every point left while anything changed anywhere, and a
 * point whose flips get stuck on the same smaller star again skips that star's Delaunay
 * retriangulation, which failed on it before (sup_ctx.ftried). Skipping must change
 * nothing: on the Delaunay mesh of integer points made non-Delaunay (every third inner
 * point removed by flips first), every inner point is tried with the memo and every
 * face beyond its star a sub-face (no expansion), and each one that stays is tried again with it and then without it (every step redone): both end
 * as the first try did, the point still there and the mesh exactly as it was. After
 * every call the mesh validator checks links, exact orientation and the exact volume. */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "suppress/suppress_int.h"

#include "tstar.h"
#include "tsup.h"

/* One call, the validator, and whether the mesh is still `before` (up to slot order). */
static int flip_one(struct tr_mesh *m, const sup_ctx *c, uint32_t p, int dbl, mpq_t vol,
                    const uint32_t *before, uint32_t n0, int *same)
{
  int done = -1;
  tr_status s = sup_flip_out(m, c, p, 7, dbl, &done);
  EXPECT(s == TR_OK, "point %u: %s", p, tr_last_error());
  s = tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, vol);
  EXPECT(s == TR_OK, "after point %u (done %d): %s", p, done, tr_last_error());
  uint32_t n1 = 0, *after = canon(m, &n1);
  *same = before && after && n0 == n1 && !memcmp(before, after, 16 * (size_t)n0);
  free(after);
  return done;
}

/* both: each point that stays is then tried at dbl = 0 (--keep-surface's last try) and
 * at dbl = 1 again. The memo keeps one key per dbl: the dbl = 0 try must leave the dbl = 1
 * key as it was (with one slot for both, each try overwrote the other's key and under
 * --keep-surface no retry was ever skipped: 65395.stl ran 125 such retriangulations, none
 * skipped), and the dbl = 1 retry then ends as before. */
static void retry_case(uint32_t n, uint32_t seed, int both)
{
  mpq_t vol;
  struct tr_mesh *m = box_mesh(n, seed, vol);
  if (!m)
    return;
  uint32_t k = 0;
  for (uint32_t p = 0; p < m->nv; p++) {
    if (m->v2t[p] == TR_NONE || tsup_hull_vertex(m, p) || k++ % 3)
      continue;
    int done = 0;
    EXPECT(sup_flip_out(m, NULL, p, 7, 0, &done) == TR_OK, "flips: %s", tr_last_error());
  }
  uint32_t removed = 0, stayed = 0, memo = 0, kept_both = 0;
  for (uint32_t p = 0; p < m->nv; p++) {
    if (m->v2t[p] == TR_NONE || tsup_hull_vertex(m, p))
      continue;
    /* every face beyond p's star a sub-face: a retriangulation that needs an expansion
     * is refused, so that stars the flips get stuck on stay */
    sup_ctx c;
    tsup_constrain_all_but(&c, m, p, TR_NONE, NULL);
    c.ftried = calloc(2 * (size_t)m->nv, sizeof *c.ftried);
    EXPECT(c.ftried != NULL, "out of memory");
    uint32_t n0 = 0, *before = canon(m, &n0);
    int same = 0;
    if (c.ftried && flip_one(m, &c, p, 1, vol, before, n0, &same) == 1) {
      removed++;
      EXPECT(m->v2t[p] == TR_NONE, "point %u removed but still has a tet", p);
      free(before);
      free(c.ftried);
      tsup_ctx_free(&c);
      continue;
    }
    stayed++;
    EXPECT(same, "point %u stays but the mesh changed", p);
    memo += c.ftried[2 * (size_t)p + 1] != 0;
    int again = flip_one(m, &c, p, 1, vol, before, n0, &same);
    EXPECT(again == 0 && same, "point %u: the retry with the memo ended otherwise (done %d)",
           p, again);
    uint64_t *memo_of = c.ftried; /* the same sub-faces, no memo: every step redone */
    c.ftried = NULL;
    again = flip_one(m, &c, p, 1, vol, before, n0, &same);
    c.ftried = memo_of;
    EXPECT(again == 0 && same, "point %u: the full retry ended otherwise (done %d)", p, again);
    if (both && c.ftried[2 * (size_t)p + 1]) {
      uint64_t k1 = c.ftried[2 * (size_t)p + 1];
      again = flip_one(m, &c, p, 0, vol, before, n0, &same);
      if (again == 0) {
        EXPECT(same, "point %u stays at dbl 0 but the mesh changed", p);
        EXPECT(c.ftried[2 * (size_t)p + 1] == k1, "point %u: the dbl 0 try changed the dbl 1 key", p);
        kept_both += c.ftried[2 * (size_t)p] != 0;
        again = flip_one(m, &c, p, 1, vol, before, n0, &same);
        EXPECT(again == 0 && same && c.ftried[2 * (size_t)p + 1] == k1,
               "point %u: the dbl 1 retry after a dbl 0 try ended otherwise (done %d)", p, again);
      }
    }
    free(before);
    free(c.ftried);
    tsup_ctx_free(&c);
  }
  fprintf(stderr,
          "%u points (seed %u): %u removed, %u stayed, of which %u got stuck on a star "
          "whose retriangulation failed (skipped on the retry)\n",
          n, seed, removed, stayed, memo);
  EXPECT(memo > 0, "no retry skipped a retriangulation: a test of nothing");
  if (both) {
    fprintf(stderr, "%u of them kept a key for each dbl\n", kept_both);
    EXPECT(kept_both > 0, "no point kept a key for both dbl: a test of nothing");
  }
  mpq_clear(vol);
  tr_mesh_destroy(m);
}

int main(int argc, char **argv)
{
  const char *c = argc > 1 ? argv[1] : "";
  if (!strcmp(c, "stuck_star"))
    retry_case(argc > 2 ? (uint32_t)atoi(argv[2]) : 1000, argc > 3 ? (uint32_t)atoi(argv[3]) : 4,
               0);
  else if (!strcmp(c, "both_doubles"))
    retry_case(argc > 2 ? (uint32_t)atoi(argv[2]) : 1000, argc > 3 ? (uint32_t)atoi(argv[3]) : 4,
               1);
  else {
    fprintf(stderr, "unknown case '%s'\n", c);
    return 2;
  }
  return failures != 0;
}
