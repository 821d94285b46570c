/* Swap23 / Swap44 (see swap.h): label the mesh tets with the table's names, check the
 * new tets exactly, then let tr_dec_apply rebuild and relink. */
#include "recover_edges/swap.h"

#include <stdlib.h>

#include "recover_edges/decompose.h"
#include "recover_edges/edge_tables.h"

/* 1 iff every new tet of t is strictly positive under the binding ids. */
static int all_positive(const struct tr_mesh *m, const tr_dectable *t,
                        const uint32_t ids[TR_DV_COUNT])
{
  for (int r = 0; r < t->nnew; r++) {
    tr_point p[4];
    for (int i = 0; i < 4; i++)
      p[i] = tr_mesh_point(m, ids[t->tets[r].v[i]]);
    if (tr_orient3d_p(&p[0], &p[1], &p[2], &p[3]) <= 0)
      return 0;
  }
  return 1;
}

tr_status tr_swap23(struct tr_mesh *m, uint32_t t1, int k1, uint32_t out[3], int *done)
{
  *done = 0;
  uint32_t c = m->tn[4 * (size_t)t1 + (size_t)k1];
  if (c == TR_NONE || !tr_tet_is_real(m, t1) || !tr_tet_is_real(m, c >> 2))
    return TR_OK;
  uint32_t t2 = c >> 2;
  const uint32_t *v1 = m->tv + 4 * (size_t)t1;
  const uint8_t *f = tr_face_vtx[k1];
  uint32_t ids[TR_DV_COUNT];
  for (int i = 0; i < TR_DV_COUNT; i++)
    ids[i] = TR_NONE;
  /* (a,b,c) = face k1 with orient(a,b,c,vk) > 0, so (vk, a, c, b) is positive: that is
   * t1 = ACDE with C = a, D = c, E = b. */
  ids[TR_DV_A] = v1[k1];
  ids[TR_DV_C] = v1[f[0]];
  ids[TR_DV_D] = v1[f[2]];
  ids[TR_DV_E] = v1[f[1]];
  ids[TR_DV_B] = m->tv[4 * (size_t)t2 + (c & 3)];
  if (!all_positive(m, &tr_table3_swap23, ids))
    return TR_OK;
  uint32_t old[2] = {t1, t2};
  TR_CHECK(tr_dec_apply(m, &tr_table3_swap23, old, ids, NULL, 0, out));
  *done = 1;
  return TR_OK;
}

/* The vertex of t that is none of a, b, c. */
static uint32_t fourth(const struct tr_mesh *m, uint32_t t, uint32_t a, uint32_t b, uint32_t c)
{
  for (int k = 0; k < 4; k++) {
    uint32_t v = m->tv[4 * (size_t)t + (size_t)k];
    if (v != a && v != b && v != c)
      return v;
  }
  return TR_NONE;
}

tr_status tr_swap44(struct tr_mesh *m, uint32_t a, uint32_t b, uint32_t c, uint32_t d,
                    uint32_t out[4], int *done)
{
  *done = 0;
  tr_u32buf sh = {0};
  int closed = 0;
  tr_status s = tr_shell(m, c, d, TR_NONE, &sh, &closed);
  if (s != TR_OK) {
    tr_u32buf_free(&sh);
    return s;
  }
  uint32_t with_a[2], with_b[2];
  int na = 0, nb = 0, ok = closed && sh.n == 4;
  for (size_t i = 0; ok && i < sh.n; i++) {
    uint32_t t = sh.a[i];
    ok = tr_tet_is_real(m, t);
    if (ok && tr_ncode(m, t, a) >= 0 && na < 2)
      with_a[na++] = t;
    if (ok && tr_ncode(m, t, b) >= 0 && nb < 2)
      with_b[nb++] = t;
  }
  tr_u32buf_free(&sh);
  if (!ok || na != 2 || nb != 2)
    return TR_OK;
  /* Name C, D so that the tet with a and an even order (a,C,D,w) is t1 = ACDE. */
  uint32_t ids[TR_DV_COUNT], old[4];
  for (int i = 0; i < TR_DV_COUNT; i++)
    ids[i] = TR_NONE;
  ids[TR_DV_A] = a;
  ids[TR_DV_B] = b;
  ids[TR_DV_C] = c;
  ids[TR_DV_D] = d;
  uint32_t w0 = fourth(m, with_a[0], a, c, d), w1 = fourth(m, with_a[1], a, c, d);
  uint32_t p[4] = {a, c, d, w0};
  int e0 = tr_tet_even_order(m, with_a[0], p);
  if (e0 < 0)
    return TR_OK;
  if (e0) {
    old[0] = with_a[0];
    old[1] = with_a[1];
    ids[TR_DV_E] = w0;
    ids[TR_DV_F] = w1;
  } else {
    old[0] = with_a[1];
    old[1] = with_a[0];
    ids[TR_DV_E] = w1;
    ids[TR_DV_F] = w0;
  }
  /* t3 = BDCE, t4 = BCDF */
  old[2] = old[3] = TR_NONE;
  for (int i = 0; i < 2; i++) {
    uint32_t w = fourth(m, with_b[i], b, c, d);
    if (w == ids[TR_DV_E])
      old[2] = with_b[i];
    else if (w == ids[TR_DV_F])
      old[3] = with_b[i];
    else
      return TR_OK;
  }
  if (old[2] == TR_NONE || old[3] == TR_NONE)
    return TR_OK;
  tr_point pa = tr_mesh_point(m, a), pb = tr_mesh_point(m, b), pc = tr_mesh_point(m, c),
           pd = tr_mesh_point(m, d);
  if (tr_orient3d_p(&pa, &pb, &pc, &pd) != 0 || !all_positive(m, &tr_table4_swap44, ids))
    return TR_OK;
  TR_CHECK(tr_dec_apply(m, &tr_table4_swap44, old, ids, NULL, 0, out));
  *done = 1;
  return TR_OK;
}
