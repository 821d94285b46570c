/* libFuzzer target: the binary sections of the .msh reader. Arbitrary bytes rarely make a
 * valid binary header, so the target writes one: the first input byte picks format 4.1
 * (even) or 2.2 (odd), and the rest of the input follows "$MeshFormat\n4.1 1 8\n<int 1>\n
 * $EndMeshFormat\n" as the file's sections. fuzz_read_msh covers the header itself. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  static const char h41[] = "$MeshFormat\n4.1 1 8\n\x01\0\0\0\n$EndMeshFormat\n";
  static const char h22[] = "$MeshFormat\n2.2 1 8\n\x01\0\0\0\n$EndMeshFormat\n";
  if (size < 1 || size > 1 << 16)
    return 0;
  size_t hn = sizeof h41 - 1, n = hn + size - 1;
  /* exactly n bytes, so that ASan sees any read past the end */
  uint8_t *buf = malloc(n);
  if (!buf)
    return 0;
  memcpy(buf, data[0] & 1 ? h22 : h41, hn);
  memcpy(buf + hn, data + 1, size - 1);
  tr_fuzz_run(tr_read_msh_buf, buf, n);
  free(buf);
  return 0;
}
