/* Unit tests of merging two interior Steiner points into one (src/suppress/merge.c) on
 * exact configurations: the Delaunay tetrahedralization of integer points (tstar.h), made
 * non-Delaunay first by removing every third inner point by flips (flipout.c), every inner
 * point then a Steiner point. For each inner point p in id order and its smallest
 * Steiner neighbour q, every face on neither p nor q is made a constraint (a sub-face),
 * and p is merged with its neighbours. After every call the mesh validator checks links,
 * exact orientation and the exact volume (six times the box's), every constraint face is
 * still a face of the mesh, a point that is gone has no tet, and a merge that is refused
 * (a constraint inside the union of the stars, no kernel point) leaves the mesh exactly
 * as it was.
 *   exact    new tets exactly positive
 *   doubles  positive with every vertex at its double too */
#include <gmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh/check.h"
#include "suppress/suppress_int.h"

#include "tstar.h"
#include "tsup.h"

/* The checks of the file's header after a call on p (and q) that reported done. */
static void check(struct tr_mesh *m, const char *what, uint32_t p, uint32_t q, int done,
                  const tr_u32buf *faces, const uint32_t *before, uint32_t n0, mpq_t vol)
{
  tr_status s = tr_check_mesh(m, TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T, vol);
  EXPECT(s == TR_OK, "%s of %u (done %d): %s", what, p, done, tr_last_error());
  for (size_t i = 0; i < faces->n; i += 3) {
    uint32_t t = TR_NONE;
    EXPECT(tr_ball_find(m, faces->a[i], faces->a[i + 1], faces->a[i + 2], &t) == TR_OK &&
               t != TR_NONE,
           "%s of %u: constraint face (%u,%u,%u) is gone", what, p, faces->a[i],
           faces->a[i + 1], faces->a[i + 2]);
  }
  uint32_t n1 = 0, *after = canon(m, &n1);
  if (done) {
    int gone = m->v2t[p] == TR_NONE || m->v2t[q] == TR_NONE;
    EXPECT(gone, "%s of %u reported done but %u and %u have tets", what, p, p, q);
    for (uint32_t i = 0; after && i < 4 * n1; i++)
      EXPECT((after[i] != p || m->v2t[p] != TR_NONE) && (after[i] != q || m->v2t[q] != TR_NONE),
             "%s of %u: a removed point is in tet %u", what, p, i / 4);
  } else {
    EXPECT(before && after && n0 == n1 && !memcmp(before, after, 16 * (size_t)n0),
           "%s of %u failed but the mesh changed", what, p);
  }
  for (uint32_t k = 0; k < m->nt; k++)
    if (tr_tet_is_real(m, k))
      EXPECT(m->region[k] == 7, "%s of %u: tet %u has region %u", what, p, k, m->region[k]);
  free(after);
}

static void merge_case(uint32_t n, uint32_t seed, int dbl)
{
  mpq_t vol;
  struct tr_mesh *m = box_mesh(n, seed, vol);
  if (!m)
    return;
  uint32_t k = 0;
  for (uint32_t p = 0; p < m->nv; p++) {
    int done = 0;
    if (m->v2t[p] == TR_NONE || tsup_hull_vertex(m, p) || k++ % 3)
      continue;
    EXPECT(sup_flip_out(m, NULL, p, 7, 0, &done) == TR_OK, "flips: %s", tr_last_error());
  }
  /* the inner points become Steiner points, at their doubles exactly */
  m->vq = calloc(m->cap_v, sizeof *m->vq);
  EXPECT(m->vq != NULL, "out of memory");
  for (uint32_t v = 0; m->vq && v < m->nv; v++) {
    if (m->v2t[v] == TR_NONE || tsup_hull_vertex(m, v))
      continue;
    m->vq[v] = malloc(sizeof *m->vq[v]);
    EXPECT(m->vq[v] != NULL, "out of memory");
    tr_qpoint_init(m->vq[v]);
    tr_qpoint_set_d(m->vq[v], m->xyz + 3 * (size_t)v);
  }
  uint32_t merged = 0, stayed = 0, pairs = 0;
  tr_u32buf ball = {0}, faces = {0};
  for (uint32_t p = 0; p < m->nv && m->vq; p++) {
    if (!m->vq[p] || m->v2t[p] == TR_NONE)
      continue;
    /* q: p's smallest Steiner neighbour */
    uint32_t q = TR_NONE;
    EXPECT(tr_ball(m, p, 1, &ball) == TR_OK, "ball");
    for (size_t i = 0; i < ball.n; i++)
      for (int a = 0; a < 4; a++) {
        uint32_t v = m->tv[4 * (size_t)ball.a[i] + a];
        if (v != p && v < m->nv && m->vq[v] && (q == TR_NONE || v < q))
          q = v;
      }
    if (q == TR_NONE)
      continue;
    pairs++;
    sup_ctx c;
    tsup_constrain_all_but(&c, m, p, q, &faces);
    uint32_t n0 = 0, *before = canon(m, &n0);
    int done = 0;
    EXPECT(sup_merge(m, &c, p, 7, dbl, &done) == TR_OK, "merge: %s", tr_last_error());
    check(m, "merge", p, q, done, &faces, before, n0, vol);
    merged += done == 1;
    stayed += done != 1;
    free(before);
    tsup_ctx_free(&c);
  }
  fprintf(stderr,
          "%u points (seed %u, dbl %d): %u points with a Steiner neighbour; %u merged into "
          "it, %u refused\n",
          n, seed, dbl, pairs, merged, stayed);
  EXPECT(merged > 0 && stayed > 0, "every merge %s: a test of nothing",
         merged ? "succeeded" : "refused");
  tr_u32buf_free(&ball);
  tr_u32buf_free(&faces);
  mpq_clear(vol);
  tr_mesh_destroy(m);
}

int main(int argc, char **argv)
{
  const char *c = argc > 1 ? argv[1] : "";
  if (!strcmp(c, "exact"))
    merge_case(200, 7, 0);
  else if (!strcmp(c, "doubles"))
    merge_case(200, 8, 1);
  else {
    fprintf(stderr, "unknown case '%s'\n", c);
    return 2;
  }
  return failures != 0;
}
