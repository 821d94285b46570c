/* Two counting-sort passes (by the larger id, then stably by the smaller): linear time,
 * and the same order as the merge sort it replaces, so outputs do not change. The keys
 * are taken once, triangle by triangle, into two flat arrays: both passes then stream
 * them instead of reading the triangles through the slot order (smoothing sorts once per
 * pass, so this runs many times on some surfaces). */
#include "core/edgesort.h"

#include <stdlib.h>

tr_status tr_edge_slots_sorted(const uint32_t *tris, uint32_t ntris, uint32_t nv,
                               uint32_t *slots)
{
  uint32_t ne = 3 * ntris;
  if (ne == 0)
    return TR_OK;
  uint32_t *cnt = calloc((size_t)nv + 1, sizeof *cnt), *tmp = malloc(sizeof *tmp * ne);
  uint32_t *lo = malloc(sizeof *lo * ne), *hi = malloc(sizeof *hi * ne);
  if (!cnt || !tmp || !lo || !hi) {
    free(cnt);
    free(tmp);
    free(lo);
    free(hi);
    return tr_error(TR_ERR_NOMEM, "out of memory sorting %u triangle edges", ne);
  }
  /* slot 3t+k: the edge tris[3t+k] -> tris[3t+(k+1)%3] */
  for (uint32_t t = 0; t < ntris; t++) {
    const uint32_t *v = tris + 3 * (size_t)t;
    for (int k = 0; k < 3; k++) {
      uint32_t a = v[k], b = v[k == 2 ? 0 : k + 1];
      lo[3 * (size_t)t + (size_t)k] = a < b ? a : b;
      hi[3 * (size_t)t + (size_t)k] = a < b ? b : a;
    }
  }
  /* pass 0: slots in index order -> tmp by hi */
  for (uint32_t i = 0; i < ne; i++)
    cnt[hi[i] + 1]++;
  for (uint32_t i = 1; i <= nv; i++)
    cnt[i] += cnt[i - 1];
  for (uint32_t i = 0; i < ne; i++)
    tmp[cnt[hi[i]]++] = i;
  /* pass 1: tmp -> slots, stably by lo */
  for (uint32_t i = 0; i <= nv; i++)
    cnt[i] = 0;
  for (uint32_t i = 0; i < ne; i++)
    cnt[lo[i] + 1]++;
  for (uint32_t i = 1; i <= nv; i++)
    cnt[i] += cnt[i - 1];
  for (uint32_t i = 0; i < ne; i++) {
    uint32_t s = tmp[i];
    slots[cnt[lo[s]]++] = s;
  }
  free(cnt);
  free(tmp);
  free(lo);
  free(hi);
  return TR_OK;
}
