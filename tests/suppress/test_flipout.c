/* Unit tests of the removal of an interior point by flips (src/suppress/flipout.c) on
 * exact configurations: the Delaunay tetrahedralization of integer points (a fixed
 * linear congruential sequence), whose inner vertices are removed one after the other.
 * After every call the mesh validator checks links, exact orientation and the exact
 * volume (six times the hull's, unchanged); a removed point has no tet left and every
 * tet keeps its region; a point that stays (a hull vertex, or a star the flips cannot
 * empty) leaves the mesh exactly as it was. */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "delaunay/delaunay.h"
#include "mesh/check.h"
#include "suppress/suppress_int.h"

#include "tstar.h"

static int cone_exists(struct tr_mesh *m, uint32_t p)
{
  tr_u32buf ball = {0};
  int found = 0;
  if (tr_ball(m, p, 1, &ball) != TR_OK)
    return 0;
  for (size_t i = 0; i < ball.n; i++)
    if (!tr_tet_is_real(m, ball.a[i]))
      found = 1; /* a hull vertex: not asked */
  for (size_t i = 0; i < ball.n && !found; i++)
    for (int a = 0; a < 4 && !found; a++) {
      uint32_t v = m->tv[4 * (size_t)ball.a[i] + a];
      if (v == p)
        continue;
      int all = 1;
      for (size_t j = 0; j < ball.n && all; j++) {
        const uint32_t *tv = m->tv + 4 * (size_t)ball.a[j];
        int k = tr_ncode(m, ball.a[j], p);
        uint32_t f[3];
        for (int b = 0; b < 3; b++)
          f[b] = tv[tr_face_vtx[k][b]];
        if (f[0] == v || f[1] == v || f[2] == v)
          continue;
        /* the link face seen from p's side, so from v iff v is on p's side */
        uint32_t w[4] = {tv[0], tv[1], tv[2], tv[3]};
        w[k] = v;
        tr_point q[4];
        for (int b = 0; b < 4; b++)
          q[b] = tr_mesh_point(m, w[b]);
        all = tr_orient3d_p(&q[0], &q[1], &q[2], &q[3]) > 0;
      }
      found = all;
    }
  tr_u32buf_free(&ball);
  return found;
}

static void remove_all(uint32_t n, uint32_t seed, int dbl)
{
  mpq_t vol;
  struct tr_mesh *m = box_mesh(n, seed, vol);
  if (!m)
    return;
  uint32_t removed = 0, stayed = 0, without_cone = 0;
  for (uint32_t p = 0; p < m->nv; p++) {
    if (m->v2t[p] == TR_NONE)
      continue;
    int cone = cone_exists(m, p), done = -1;
    uint32_t n0 = 0, n1 = 0, *before = canon(m, &n0);
    tr_status s = sup_flip_out(m, NULL, p, 7, dbl, &done);
    EXPECT(s == TR_OK, "point %u: %s", p, tr_last_error());
    s = tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, vol);
    EXPECT(s == TR_OK, "after point %u (done %d): %s", p, done, tr_last_error());
    uint32_t *after = canon(m, &n1);
    if (done == 1) {
      removed++;
      without_cone += !cone;
      EXPECT(m->v2t[p] == TR_NONE, "point %u removed but still has a tet", p);
      for (uint32_t i = 0; i < 4 * n1; i++)
        EXPECT(after[i] != p, "point %u removed but in tet %u", p, i / 4);
    } else {
      stayed++;
      EXPECT(done == 0, "point %u: done = %d", p, done);
      EXPECT(before && after && n0 == n1 && !memcmp(before, after, 16 * (size_t)n0),
             "point %u stays but the mesh changed", p);
    }
    for (uint32_t t = 0; t < m->nt; t++)
      if (tr_tet_is_real(m, t))
        EXPECT(m->region[t] == 7, "point %u: tet %u has region %u", p, t, m->region[t]);
    free(before);
    free(after);
  }
  fprintf(stderr, "%u points (seed %u, dbl %d): %u removed (%u without a cone), %u stayed\n", n,
          seed, dbl, removed, without_cone, stayed);
  /* the 8 corners are hull vertices: they stay; most inner points go */
  EXPECT(stayed >= 8 && removed >= (n - 8) / 2, "too few removals: %u of %u", removed, n - 8);
  EXPECT(without_cone > 0, "no point needed the flips: a test of nothing");
  mpq_clear(vol);
  tr_mesh_destroy(m);
}

int main(int argc, char **argv)
{
  const char *c = argc > 1 ? argv[1] : "";
  if (!strcmp(c, "exact"))
    remove_all(80, 1, 0);
  else if (!strcmp(c, "doubles"))
    remove_all(80, 2, 1);
  else if (!strcmp(c, "dense"))
    remove_all(300, 3, 1);
  else {
    fprintf(stderr, "unknown case '%s'\n", c);
    return 2;
  }
  return failures != 0;
}
