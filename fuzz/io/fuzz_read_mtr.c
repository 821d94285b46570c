/* libFuzzer target: the .mtr reader (a size per point) on arbitrary bytes, with any count
 * and with the count of a fixed input of 8 points. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  if (size > 1 << 16)
    return 0;
  double *h = NULL;
  uint32_t n = 0;
  if (tr_read_mtr_buf((const char *)data, size, "fuzz", UINT32_MAX, &h, &n) == TR_OK)
    for (uint32_t i = 0; i < n; i++)
      if (!(h[i] >= 0))
        abort(); /* the reader promises values >= 0 */
  free(h);
  h = NULL;
  tr_read_mtr_buf((const char *)data, size, "fuzz", 8, &h, &n);
  free(h);
  return 0;
}
