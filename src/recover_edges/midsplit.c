/* Splitting a missing sub-segment at its exact midpoint (tr_pipe_split_mid, pipe.h).
 *
 * The midpoint M of ab lies in the closure of some pipels of Pipe(ab) (inside one tet, on
 * a face, or on an edge; on a hull face also in the ghost tet of that face): every tet
 * whose closure holds M is a pipel, because ab meets it at M, which is not a vertex. Those
 * tets are replaced by the cone from M over their faces that do not contain M (the tet
 * with vertex k replaced by M, for each face k not through M): strictly positive by
 * construction, and tr_mesh_replace checks that they fill the same region. Ghost tets
 * keep TR_GHOST in slot 3 (their hull face always holds M, so slot 3 is never replaced).
 */
#include <stdlib.h>

#include "classify.h"
#include "recover_edges/pipe.h"

/* Bit k set iff face k of real tet tv holds p; -1 if p is outside the tet. */
static int faces_through(const struct tr_mesh *m, const uint32_t *tv, const tr_point *p)
{
  int mask = 0;
  for (int k = 0; k < 4; k++) {
    const uint8_t *f = tr_face_vtx[k];
    tr_point a = tr_mesh_point(m, tv[f[0]]), b = tr_mesh_point(m, tv[f[1]]),
             c = tr_mesh_point(m, tv[f[2]]);
    int o = tr_orient3d_p(&a, &b, &c, p);
    if (o < 0)
      return -1;
    if (o == 0)
      mask |= 1 << k;
  }
  return mask;
}

tr_status tr_pipe_split_mid(struct tr_mesh *m, uint32_t a, uint32_t b, const tr_pipe *p,
                            uint32_t *mid, int *done)
{
  *done = 0;
  *mid = TR_NONE;
  tr_qpoint *q = malloc(sizeof *q);
  if (!q)
    return tr_error(TR_ERR_NOMEM, "out of memory for a midpoint");
  tr_qpoint_init(q);
  tr_point pa = tr_mesh_point(m, a), pb = tr_mesh_point(m, b);
  mpq_t x, y;
  mpq_init(x);
  mpq_init(y);
  for (int i = 0; i < 3; i++) {
    tr_point_get_q(&pa, i, x);
    tr_point_get_q(&pb, i, y);
    mpq_add(x, x, y);
    mpq_div_2exp(q->c[i], x, 1);
  }
  mpq_clear(x);
  mpq_clear(y);
  tr_qpoint_update(q);
  tr_point pm = tr_pt_q(q);
  uint32_t id = m->nv; /* the id M gets if the split goes ahead */
  tr_u32buf old = {0}, newv = {0};
  tr_status s = TR_OK;
  for (uint32_t i = 0; i < p->n && s == TR_OK; i++) {
    uint32_t t = p->pl[i].iEle;
    const uint32_t *tv = m->tv + 4 * (size_t)t;
    int skip[4] = {0, 0, 0, 0};
    if (p->pl[i].ghost) {
      tr_point h0 = tr_mesh_point(m, tv[0]), h1 = tr_mesh_point(m, tv[1]),
               h2 = tr_mesh_point(m, tv[2]);
      if (tr_orient3d_p(&h0, &h1, &h2, &pm) != 0 ||
          tr_classify_point_triangle(&pm, &h0, &h1, &h2).type == TR_DEG)
        continue;
      skip[3] = 1;
      /* face k < 3 is (hull edge opposite k, GHOST): it holds M iff M is on that edge */
      for (int k = 0; k < 3; k++) {
        tr_point u = tr_mesh_point(m, tv[(k + 1) % 3]), w = tr_mesh_point(m, tv[(k + 2) % 3]);
        skip[k] = tr_classify_point_segment(&pm, &u, &w).type == TR_EDG;
      }
    } else {
      int mask = faces_through(m, tv, &pm);
      if (mask < 0)
        continue;
      for (int k = 0; k < 4; k++)
        skip[k] = (mask >> k) & 1;
    }
    s = tr_u32buf_push(&old, t);
    for (int k = 0; k < 4 && s == TR_OK; k++) {
      if (skip[k])
        continue;
      for (int j = 0; j < 4 && s == TR_OK; j++)
        s = tr_u32buf_push(&newv, j == k ? id : tv[j]);
    }
  }
  if (s == TR_OK && old.n > 0) {
    if ((s = tr_mesh_add_constructed(m, q, &id)) == TR_OK) {
      q = NULL;
      s = tr_mesh_replace(m, old.a, (uint32_t)old.n, newv.a, (uint32_t)(newv.n / 4), NULL);
      if (s == TR_OK) {
        *done = 1;
        *mid = id;
      } else {
        /* unused: take the vertex back so the store has no orphan */
        tr_qpoint_clear(m->vq[id]);
        free(m->vq[id]);
        m->vq[id] = NULL;
        m->nv--;
        s = TR_OK;
      }
    }
  }
  if (q) {
    tr_qpoint_clear(q);
    free(q);
  }
  tr_u32buf_free(&old);
  tr_u32buf_free(&newv);
  return s;
}
