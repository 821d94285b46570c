/* Two counting-sort passes (by the larger id, then stably by the smaller): linear time,
 * and the same order as the merge sort it replaces, so outputs do not change. The keys
 * are taken once, triangle by triangle, into two flat arrays, with both passes' counts in
 * the same loop: both passes then stream them instead of reading the triangles through
 * the slot order. */
#include "core/edgesort.h"

#include <stdlib.h>

tr_status tr_edge_slots_sorted(const uint32_t *tris, uint32_t ntris, uint32_t nv,
                               uint32_t *slots)
{
  uint32_t ne = 3 * ntris;
  if (ne == 0)
    return TR_OK;
  /* both passes' counts, taken in the one loop that reads the triangles */
  uint32_t *cnt = calloc(2 * ((size_t)nv + 1), sizeof *cnt), *tmp = malloc(sizeof *tmp * ne);
  uint32_t *lo = malloc(sizeof *lo * ne), *hi = malloc(sizeof *hi * ne);
  if (!cnt || !tmp || !lo || !hi) {
    free(cnt);
    free(tmp);
    free(lo);
    free(hi);
    return tr_error(TR_ERR_NOMEM, "out of memory sorting %u triangle edges", ne);
  }
  uint32_t *clo = cnt, *chi = cnt + (size_t)nv + 1;
  /* slot 3t+k: the edge tris[3t+k] -> tris[3t+(k+1)%3] */
  for (uint32_t t = 0; t < ntris; t++) {
    const uint32_t *v = tris + 3 * (size_t)t;
    for (int k = 0; k < 3; k++) {
      uint32_t a = v[k], b = v[k == 2 ? 0 : k + 1];
      uint32_t l = a < b ? a : b, h = a < b ? b : a;
      lo[3 * (size_t)t + (size_t)k] = l;
      hi[3 * (size_t)t + (size_t)k] = h;
      clo[l + 1]++;
      chi[h + 1]++;
    }
  }
  for (uint32_t i = 1; i <= nv; i++) {
    clo[i] += clo[i - 1];
    chi[i] += chi[i - 1];
  }
  /* pass 0: slots in index order -> tmp by hi */
  for (uint32_t i = 0; i < ne; i++)
    tmp[chi[hi[i]]++] = i;
  /* pass 1: tmp -> slots, stably by lo */
  for (uint32_t i = 0; i < ne; i++) {
    uint32_t s = tmp[i];
    slots[clo[lo[s]]++] = s;
  }
  free(cnt);
  free(tmp);
  free(lo);
  free(hi);
  return TR_OK;
}
