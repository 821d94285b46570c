/* Unit tests of the removal of an interior point by the Delaunay retriangulation of its
 * star (src/suppress/starfill.c) on exact configurations: the Delaunay tetrahedralization
 * of integer points (a fixed linear congruential sequence). After every call the mesh
 * validator checks links, exact orientation and the exact volume (six times the box's,
 * unchanged); a removed point has no tet left and every tet keeps its region; a point
 * that stays leaves the mesh exactly as it was.
 *   delaunay     removing a vertex from a Delaunay mesh: its star's link is a subcomplex
 *                of the link vertices' Delaunay mesh, so every inner point goes without
 *                any expansion
 *   expanded     the mesh made non-Delaunay first (every third inner point removed by
 *                flips, flipout.c); then the stars that need an expansion are retried
 *                with every face beyond them a sub-face (the expansion must refuse:
 *                the point stays, the mesh unchanged), then without constraints
 *   by_dbl       on that mesh, a star refused at dbl = 1 and not by doubles is refused
 *                at dbl = 0 too (what lets the memo skip the dbl = 0 try) */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "suppress/suppress_int.h"

#include "tstar.h"
#include "tsup.h"

/* One call, then the checks of the file's header. Returns done. */
static int fill_one_by(struct tr_mesh *m, const sup_ctx *c, uint32_t p, int dbl, int rounds,
                       mpq_t vol, int *by_dbl)
{
  uint32_t n0 = 0, n1 = 0, *before = canon(m, &n0), t = TR_NONE;
  int done = -1;
  tr_status s = sup_star_fill(m, c, p, 7, dbl, rounds, &t, &done, by_dbl);
  EXPECT(s == TR_OK, "point %u: %s", p, tr_last_error());
  s = tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, vol);
  EXPECT(s == TR_OK, "after point %u (done %d): %s", p, done, tr_last_error());
  uint32_t *after = canon(m, &n1);
  if (done == 1) {
    EXPECT(m->v2t[p] == TR_NONE, "point %u removed but still has a tet", p);
    EXPECT(t != TR_NONE && tr_tet_is_real(m, t), "point %u: no new tet named", p);
    for (uint32_t i = 0; i < 4 * n1; i++)
      EXPECT(after[i] != p, "point %u removed but in tet %u", p, i / 4);
  } else {
    EXPECT(done == 0, "point %u: done = %d", p, done);
    EXPECT(before && after && n0 == n1 && !memcmp(before, after, 16 * (size_t)n0),
           "point %u stays but the mesh changed", p);
  }
  for (uint32_t k = 0; k < m->nt; k++)
    if (tr_tet_is_real(m, k))
      EXPECT(m->region[k] == 7, "point %u: tet %u has region %u", p, k, m->region[k]);
  free(before);
  free(after);
  return done;
}

static int fill_one(struct tr_mesh *m, const sup_ctx *c, uint32_t p, int dbl, int rounds,
                    mpq_t vol)
{
  return fill_one_by(m, c, p, dbl, rounds, vol, NULL);
}

/* The memo's shortcut (star.c, flipout.c): a star refused at dbl = 1 with by_dbl = 0 is
 * not tried at dbl = 0. On integer points every double is exact, so no refusal can come
 * from doubles (by_dbl must be 0), and each star refused at dbl = 1, with or without the
 * expansion, must be refused at dbl = 0 too, the mesh left as it was. */
static void by_dbl_case(uint32_t n, uint32_t seed)
{
  mpq_t vol;
  struct tr_mesh *m = box_mesh(n, seed, vol);
  if (!m)
    return;
  uint32_t k = 0, refused = 0;
  for (uint32_t p = 0; p < m->nv; p++) {
    if (m->v2t[p] == TR_NONE || tsup_hull_vertex(m, p) || k++ % 3)
      continue;
    int done = 0;
    EXPECT(sup_flip_out(m, NULL, p, 7, 0, &done) == TR_OK, "flips: %s", tr_last_error());
  }
  for (uint32_t p = 0; p < m->nv; p++) {
    if (m->v2t[p] == TR_NONE || tsup_hull_vertex(m, p))
      continue;
    for (int rounds = 0; rounds <= SUP_FILL_EXPAND; rounds += SUP_FILL_EXPAND) {
      sup_ctx c;
      tsup_constrain_all_but(&c, m, p, TR_NONE, NULL);
      int by_dbl = -1, done = fill_one_by(m, &c, p, 1, rounds, vol, &by_dbl);
      if (done == 0) {
        EXPECT(by_dbl == 0, "point %u: refused by doubles on integer points", p);
        done = fill_one_by(m, &c, p, 0, rounds, vol, &by_dbl);
        EXPECT(done == 0, "point %u: refused at dbl 1 (not by doubles), removed at dbl 0", p);
        refused++;
      }
      tsup_ctx_free(&c);
      if (done == 1)
        break;
    }
  }
  fprintf(stderr, "%u points (seed %u): %u refusals at dbl 1 not by doubles, refused at dbl 0 "
          "too\n", n, seed, refused);
  EXPECT(refused > 0, "no star was refused: a test of nothing");
  mpq_clear(vol);
  tr_mesh_destroy(m);
}

static void delaunay_case(uint32_t n, uint32_t seed, int dbl)
{
  mpq_t vol;
  struct tr_mesh *m = box_mesh(n, seed, vol);
  if (!m)
    return;
  uint32_t removed = 0, inner = 0;
  for (uint32_t p = 0; p < m->nv; p++) {
    if (m->v2t[p] == TR_NONE || tsup_hull_vertex(m, p))
      continue;
    inner++;
    removed += fill_one(m, NULL, p, dbl, 0, vol) == 1;
  }
  fprintf(stderr, "%u points (seed %u, dbl %d): %u of %u inner points removed\n", n, seed,
          dbl, removed, inner);
  EXPECT(inner >= n / 2 && removed == inner, "a Delaunay star was refused: %u of %u", removed,
         inner);
  mpq_clear(vol);
  tr_mesh_destroy(m);
}

static void expanded_case(uint32_t n, uint32_t seed)
{
  mpq_t vol;
  struct tr_mesh *m = box_mesh(n, seed, vol);
  if (!m)
    return;
  uint32_t flipped = 0, plain = 0, refused = 0, expanded = 0, stayed = 0, k = 0;
  for (uint32_t p = 0; p < m->nv; p++) {
    if (m->v2t[p] == TR_NONE || tsup_hull_vertex(m, p) || k++ % 3)
      continue;
    int done = 0;
    EXPECT(sup_flip_out(m, NULL, p, 7, 0, &done) == TR_OK, "flips: %s", tr_last_error());
    flipped += done == 1;
  }
  EXPECT(tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, vol) == TR_OK,
         "after the flips: %s", tr_last_error());
  for (uint32_t p = 0; p < m->nv; p++) {
    if (m->v2t[p] == TR_NONE || tsup_hull_vertex(m, p))
      continue;
    if (fill_one(m, NULL, p, 0, 0, vol) == 1) {
      plain++;
      continue;
    }
    sup_ctx c;
    tsup_constrain_all_but(&c, m, p, TR_NONE, NULL);
    int done = fill_one(m, &c, p, 0, SUP_FILL_EXPAND, vol);
    tsup_ctx_free(&c);
    EXPECT(done == 0, "point %u: expanded across a sub-face", p);
    refused++;
    done = fill_one(m, NULL, p, 0, SUP_FILL_EXPAND, vol);
    expanded += done == 1;
    stayed += done != 1;
  }
  fprintf(stderr,
          "%u points (seed %u): %u removed by flips first; then %u without expansion, %u "
          "with (refused when every face beyond the star is a sub-face: %u), %u stayed\n",
          n, seed, flipped, plain, expanded, refused, stayed);
  EXPECT(expanded > 0, "no star needed an expansion: a test of nothing");
  mpq_clear(vol);
  tr_mesh_destroy(m);
}

int main(int argc, char **argv)
{
  const char *c = argc > 1 ? argv[1] : "";
  if (!strcmp(c, "delaunay"))
    delaunay_case(120, 5, 0);
  else if (!strcmp(c, "delaunay_doubles"))
    delaunay_case(120, 6, 1);
  else if (!strcmp(c, "expanded"))
    expanded_case(200, 7);
  else if (!strcmp(c, "by_dbl"))
    by_dbl_case(200, 7);
  else {
    fprintf(stderr, "unknown case '%s'\n", c);
    return 2;
  }
  return failures != 0;
}
