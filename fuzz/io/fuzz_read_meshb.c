/* libFuzzer target: the binary Medit .meshb reader on arbitrary bytes. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  return tr_fuzz_run(tr_read_meshb_buf, data, size);
}
