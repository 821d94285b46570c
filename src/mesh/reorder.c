/* Tet slots renumbered: the live tets in a given order, free slots dropped. The sliver
 * stage sorts them so along a Hilbert curve (src/sliver/order.c). */
#include "mesh.h"

#include <stdlib.h>
#include <string.h>

tr_status tr_mesh_permute_tets(struct tr_mesh *m, const uint32_t *order, uint32_t n)
{
  uint32_t *newid = malloc(sizeof *newid * ((size_t)m->nt + 1));
  uint32_t *tv = malloc(sizeof *tv * 4 * (size_t)m->cap_t);
  uint32_t *tn = malloc(sizeof *tn * 4 * (size_t)m->cap_t);
  uint8_t *fl = malloc((size_t)m->cap_t + 1);
  uint32_t *rg = m->region ? malloc(sizeof *rg * (size_t)m->cap_t) : NULL;
  if (!newid || !tv || !tn || !fl || (m->region && !rg)) {
    free(newid), free(tv), free(tn), free(fl), free(rg);
    return tr_error(TR_ERR_NOMEM, "out of memory renumbering %u tets", n);
  }
  for (uint32_t t = 0; t < m->nt; t++)
    newid[t] = TR_NONE;
  for (uint32_t i = 0; i < n; i++)
    newid[order[i]] = i;
  for (uint32_t i = 0; i < n; i++) {
    const uint32_t t = order[i];
    memcpy(tv + 4 * (size_t)i, m->tv + 4 * (size_t)t, 4 * sizeof *tv);
    for (int a = 0; a < 4; a++) {
      const uint32_t c = m->tn[4 * (size_t)t + a];
      tn[4 * (size_t)i + a] = c == TR_NONE ? TR_NONE : 4 * newid[c >> 2] + (c & 3);
    }
    fl[i] = m->flags[t];
    if (rg)
      rg[i] = m->region[t];
  }
  for (uint32_t v = 0; v < m->nv; v++)
    if (m->v2t[v] != TR_NONE)
      m->v2t[v] = m->v2t[v] < m->nt ? newid[m->v2t[v]] : TR_NONE;
  free(m->tv), free(m->tn), free(m->flags), free(m->region);
  m->tv = tv;
  m->tn = tn;
  m->flags = fl;
  m->region = rg;
  m->nt = n;
  m->free_head = TR_NONE;
  m->nfree = 0;
  free(newid);
  return TR_OK;
}
