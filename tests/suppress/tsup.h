/* Shared by the unit tests that drive suppression's internals on a whole mesh
 * (test_starfill.c, test_merge.c): a suppression context whose sub-faces are every face of
 * the mesh but the ones on the points under test, its release, and whether a vertex is on
 * the convex hull (a ghost tet in its ball). */
#ifndef TR_TESTS_SUPPRESS_TSUP_H
#define TR_TESTS_SUPPRESS_TSUP_H

#include <stdlib.h>
#include <string.h>

#include "suppress/suppress_int.h"

#include "../pipeline/texpect.h"

/* Every face of the mesh on neither p nor q (q may be TR_NONE), each once, as a sub-face
 * of pseudo input triangle 0; with faces non-NULL their sorted vertex triples too. */
static void tsup_constrain_all_but(sup_ctx *c, struct tr_mesh *m, uint32_t p, uint32_t q,
                                   tr_u32buf *faces)
{
  memset(c, 0, sizeof *c);
  c->m = m;
  c->nv = m->nv;
  c->head = malloc(sizeof *c->head * m->nv);
  EXPECT(c->head != NULL, "out of memory");
  for (uint32_t v = 0; v < m->nv; v++)
    c->head[v] = TR_NONE;
  if (faces)
    faces->n = 0;
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!tr_tet_is_real(m, t))
      continue;
    for (int k = 0; k < 4; k++) {
      const uint32_t *tv = m->tv + 4 * (size_t)t;
      uint32_t f[3];
      for (int a = 0; a < 3; a++)
        f[a] = tv[tr_face_vtx[k][a]];
      if (f[0] == p || f[1] == p || f[2] == p || f[0] == q || f[1] == q || f[2] == q)
        continue;
      uint32_t nb = TR_NEIG(m, t, k);
      if (nb != TR_NONE && tr_tet_is_real(m, nb) && nb < t)
        continue; /* each face once */
      EXPECT(sup_add(c, f[0], f[1], f[2], 0) == TR_OK, "sup_add");
      if (faces) {
        tr_sort3(f);
        for (int a = 0; a < 3; a++)
          EXPECT(tr_u32buf_push(faces, f[a]) == TR_OK, "push");
      }
    }
  }
}

static void tsup_ctx_free(sup_ctx *c)
{
  free(c->head);
  free(c->v);
  free(c->tri);
  free(c->lnext);
  free(c->lsub);
}

static int tsup_hull_vertex(struct tr_mesh *m, uint32_t p)
{
  tr_u32buf ball = {0};
  int hull = tr_ball(m, p, 1, &ball) != TR_OK;
  for (size_t i = 0; i < ball.n; i++)
    hull |= !tr_tet_is_real(m, ball.a[i]);
  tr_u32buf_free(&ball);
  return hull;
}

#endif
