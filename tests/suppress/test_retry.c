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
static int flip_one(struct tr_mesh *m, const sup_ctx *c, uint32_t p, mpq_t vol,
                    const uint32_t *before, uint32_t n0, int *same)
{
  int done = -1;
  tr_status s = sup_flip_out(m, c, p, 7, 1, &done);
  EXPECT(s == TR_OK, "point %u: %s", p, tr_last_error());
  s = tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, vol);
  EXPECT(s == TR_OK, "after point %u (done %d): %s", p, done, tr_last_error());
  uint32_t n1 = 0, *after = canon(m, &n1);
  *same = before && after && n0 == n1 && !memcmp(before, after, 16 * (size_t)n0);
  free(after);
  return done;
}

static void retry_case(uint32_t n, uint32_t seed)
{
  struct tr_mesh *m = mesh_of(n, seed);
  if (!m)
    return;
  mpq_t vol;
  mpq_init(vol);
  mpq_set_ui(vol, 6 * 64 * 64 * 64, 1);
  uint32_t k = 0;
  for (uint32_t p = 0; p < m->nv; p++) {
    if (m->v2t[p] == TR_NONE || tsup_hull_vertex(m, p) || k++ % 3)
      continue;
    int done = 0;
    EXPECT(sup_flip_out(m, NULL, p, 7, 0, &done) == TR_OK, "flips: %s", tr_last_error());
  }
  uint32_t removed = 0, stayed = 0, memo = 0;
  for (uint32_t p = 0; p < m->nv; p++) {
    if (m->v2t[p] == TR_NONE || tsup_hull_vertex(m, p))
      continue;
    /* every face beyond p's star a sub-face: a retriangulation that needs an expansion
     * is refused, so that stars the flips get stuck on stay */
    sup_ctx c;
    tsup_constrain_all_but(&c, m, p, TR_NONE, NULL);
    c.ftried = calloc(m->nv, sizeof *c.ftried);
    EXPECT(c.ftried != NULL, "out of memory");
    uint32_t n0 = 0, *before = canon(m, &n0);
    int same = 0;
    if (c.ftried && flip_one(m, &c, p, vol, before, n0, &same) == 1) {
      removed++;
      EXPECT(m->v2t[p] == TR_NONE, "point %u removed but still has a tet", p);
      free(before);
      free(c.ftried);
      tsup_ctx_free(&c);
      continue;
    }
    stayed++;
    EXPECT(same, "point %u stays but the mesh changed", p);
    memo += c.ftried[p] != 0;
    int again = flip_one(m, &c, p, vol, before, n0, &same);
    EXPECT(again == 0 && same, "point %u: the retry with the memo ended otherwise (done %d)",
           p, again);
    uint64_t *memo_of = c.ftried; /* the same sub-faces, no memo: every step redone */
    c.ftried = NULL;
    again = flip_one(m, &c, p, vol, before, n0, &same);
    c.ftried = memo_of;
    EXPECT(again == 0 && same, "point %u: the full retry ended otherwise (done %d)", p, again);
    free(before);
    free(c.ftried);
    tsup_ctx_free(&c);
  }
  fprintf(stderr,
          "%u points (seed %u): %u removed, %u stayed, of which %u got stuck on a star "
          "whose retriangulation failed (skipped on the retry)\n",
          n, seed, removed, stayed, memo);
  EXPECT(memo > 0, "no retry skipped a retriangulation: a test of nothing");
  mpq_clear(vol);
  tr_mesh_destroy(m);
}

int main(int argc, char **argv)
{
  const char *c = argc > 1 ? argv[1] : "";
  if (!strcmp(c, "stuck_star"))
    retry_case(argc > 2 ? (uint32_t)atoi(argv[2]) : 1000, argc > 3 ? (uint32_t)atoi(argv[3]) : 4);
  else {
    fprintf(stderr, "unknown case '%s'\n", c);
    return 2;
  }
  return failures != 0;
}
