/* Two counting-sort passes (by the larger id, then stably by the smaller): linear time,
 * and the same order as the merge sort it replaces, so outputs do not change. */
#include "core/edgesort.h"

#include <stdlib.h>

static void edge_key(const uint32_t *tris, uint32_t s, uint32_t *lo, uint32_t *hi)
{
  uint32_t a = tris[s], b = tris[3 * (s / 3) + (s % 3 + 1) % 3];
  *lo = a < b ? a : b;
  *hi = a < b ? b : a;
}

tr_status tr_edge_slots_sorted(const uint32_t *tris, uint32_t ntris, uint32_t nv,
                               uint32_t *slots)
{
  uint32_t ne = 3 * ntris;
  if (ne == 0)
    return TR_OK;
  uint32_t *cnt = calloc((size_t)nv + 1, sizeof *cnt), *tmp = malloc(sizeof *tmp * ne);
  if (!cnt || !tmp) {
    free(cnt);
    free(tmp);
    return tr_error(TR_ERR_NOMEM, "out of memory sorting %u triangle edges", ne);
  }
  uint32_t lo, hi;
  for (int pass = 0; pass < 2; pass++) {
    /* pass 0: slots in index order -> tmp by hi; pass 1: tmp -> slots by lo */
    const uint32_t *src = pass ? tmp : NULL;
    uint32_t *dst = pass ? slots : tmp;
    for (uint32_t i = 0; i <= nv; i++)
      cnt[i] = 0;
    for (uint32_t i = 0; i < ne; i++) {
      edge_key(tris, i, &lo, &hi);
      cnt[(pass ? lo : hi) + 1]++;
    }
    for (uint32_t i = 1; i <= nv; i++)
      cnt[i] += cnt[i - 1];
    for (uint32_t i = 0; i < ne; i++) {
      uint32_t s = src ? src[i] : i;
      edge_key(tris, s, &lo, &hi);
      dst[cnt[pass ? lo : hi]++] = s;
    }
  }
  free(cnt);
  free(tmp);
  return TR_OK;
}
