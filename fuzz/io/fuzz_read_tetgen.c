/* libFuzzer target: the TetGen readers. The first byte picks .node / .poly / .smesh /
 * .node+.ele; for .poly, .smesh and .ele a NUL byte in the rest splits the main file from
 * its companion .node file. */
#include "fuzz_common.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
  if (size < 1 || size > 1 << 16)
    return 0;
  int kind = data[0] % 4;
  const char *buf = (const char *)data + 1;
  size_t len = size - 1;
  const char *nul = memchr(buf, '\0', len);
  const char *node = nul ? nul + 1 : NULL;
  size_t node_len = nul ? len - (size_t)(nul + 1 - buf) : 0;
  size_t main_len = nul ? (size_t)(nul - buf) : len;
  struct tr_plc plc;
  memset(&plc, 0, sizeof plc);
  tr_status s;
  if (kind == 3) {
    /* .ele needs points: the part after the NUL is the .node */
    s = tr_read_tetgen_buf(TR_TETGEN_NODE, node ? node : "", node_len, "fuzz.node", NULL, 0,
                           NULL, &plc);
    if (s == TR_OK)
      s = tr_read_ele_buf(buf, main_len, "fuzz.ele", &plc);
  } else {
    static const enum tr_tetgen_kind k[3] = {TR_TETGEN_NODE, TR_TETGEN_POLY, TR_TETGEN_SMESH};
    s = tr_read_tetgen_buf(k[kind], buf, main_len, "fuzz", node, node_len, "fuzz.node", &plc);
  }
  if (s == TR_OK && plc.ntris) {
    tr_options o;
    tr_options_default(&o);
    o.allow_open = 1;
    (void)tr_plc_validate(&plc, &o);
  }
  tr_plc_clear(&plc);
  return 0;
}
