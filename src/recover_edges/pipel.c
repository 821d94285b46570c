/* Pipel decomposition: case selection, relabeling, DType rule (see pipel.h). */
#include "recover_edges/pipel.h"

#include "classify.h"
#include "recover_edges/dtype.h"
#include "recover_edges/edge_tables.h"

int tr_pipel_case(uint8_t type)
{
  int a = type & 3, b = (type >> 2) & 3;
  int lo = a < b ? a : b, hi = a < b ? b : a;
  if (hi == TR_NOD)
    return lo == TR_DEG || lo == TR_NOD ? 0 : -1;
  if (hi == TR_EDG)
    return lo == TR_EDG ? 2 : 1; /* EDG with NOD or DEG: Case 1 */
  if (hi == TR_FAC) {
    if (lo == TR_NOD)
      return 3;
    if (lo == TR_EDG)
      return 4;
    if (lo == TR_FAC)
      return 5;
  }
  return -1; /* DEG_DEG, FAC_DEG: a segment cannot meet a tet like that */
}

/* 1 iff some tet of pl's dectets has both vertices u and v. */
static int dec_has_edge(const struct tr_mesh *m, const tr_pipel *pl, uint32_t u, uint32_t v)
{
  for (int i = 0; i < pl->nTets; i++)
    if (tr_ncode(m, pl->dectets[i], u) >= 0 && tr_ncode(m, pl->dectets[i], v) >= 0)
      return 1;
  return 0;
}

tr_status tr_pipel_decompose(struct tr_mesh *m, tr_pipel *pipe, uint32_t npipe, tr_pipel *pl)
{
  int cs = tr_pipel_case(pl->type);
  if (cs <= 0)
    return tr_error(TR_ERR_INTERNAL, "pipel %u: type 0x%x cannot be decomposed", pl->iEle,
                    pl->type & 15);
  if (pl->nTets)
    return tr_error(TR_ERR_INTERNAL, "pipel %u decomposed twice", pl->iEle);
  /* the Steiner points and their carriers (local codes of iEle) */
  uint8_t car[2][4], ncar[2];
  uint32_t sid[2];
  int nst = 0, prefer = -1, edges[2], nedges = 0;
  for (int e = 0; e < 2; e++) {
    int ty = e ? (pl->type >> 2) & 3 : pl->type & 3;
    int code = e ? pl->iCod2 : pl->iCod1;
    uint32_t node = e ? pl->iNod2 : pl->iNod1;
    if (ty == TR_NOD) {
      prefer = code;
    } else if (ty == TR_EDG) {
      car[nst][0] = (uint8_t)tr_ecode_start(code);
      car[nst][1] = (uint8_t)tr_ecode_end(code);
      ncar[nst] = 2;
      sid[nst++] = node;
      edges[nedges++] = code;
    } else if (ty == TR_FAC) {
      for (int k = 0, q = 0; k < 4; k++)
        if (k != code)
          car[nst][q++] = (uint8_t)k;
      ncar[nst] = 3;
      sid[nst++] = node;
    }
  }
  const tr_dectable *t = NULL;
  switch (cs) {
  case 1: t = &tr_table5_case1; break;
  case 2: {
    int s0 = tr_ecode_start(edges[0]), e0 = tr_ecode_end(edges[0]);
    int s1 = tr_ecode_start(edges[1]), e1 = tr_ecode_end(edges[1]);
    int share = s0 == s1 || s0 == e1 || e0 == s1 || e0 == e1;
    t = share ? &tr_table6_case2_2s : &tr_table6_case2_1;
    break;
  }
  case 3: t = &tr_table7_case3; break;
  case 4: t = &tr_table8_case4; break;
  default: t = &tr_table9_case5; break;
  }
  uint32_t ids[TR_DV_COUNT];
  if (!tr_dec_match(t, m->tv + 4 * (size_t)pl->iEle, nst, (const uint8_t(*)[4])car, ncar, sid,
                    prefer, ids))
    return tr_error(TR_ERR_INTERNAL, "pipel %u (type 0x%x): %s does not fit its codes",
                    pl->iEle, pl->type & 15, t->name);
  uint8_t dbits = 0;
  if (t == &tr_table6_case2_2s) {
    /* Steps 1-3 for the face ABD (opposite C), which holds both cut edges */
    int kc = tr_ncode(m, pl->iEle, ids[TR_DV_C]);
    uint32_t nb = m->tn[4 * (size_t)pl->iEle + (size_t)kc];
    const tr_pipel *np = nb == TR_NONE ? NULL : tr_pipe_find(pipe, npipe, nb >> 2);
    int dtype = TR_DTYPE_S; /* Step 3 */
    if (np && np->nTets) { /* Step 2 */
      if (dec_has_edge(m, np, ids[TR_DV_A], ids[TR_DV_P2]))
        dtype = TR_DTYPE_Z;
      else if (!dec_has_edge(m, np, ids[TR_DV_B], ids[TR_DV_P1]))
        return tr_error(TR_ERR_INTERNAL,
                        "pipel %u: neighbour pipel %u split the shared face with neither "
                        "diagonal", pl->iEle, np->iEle);
    }
    if (dtype == TR_DTYPE_Z) {
      t = &tr_table6_case2_2z;
      dbits = (uint8_t)(1u << (4 + kc));
    }
  }
  uint32_t old = pl->iEle;
  TR_CHECK(tr_dec_apply(m, t, &old, ids, pipe, npipe, pl->dectets));
  pl->nTets = t->nnew;
  pl->type = (uint8_t)((pl->type & 15) | dbits);
  return TR_OK;
}
