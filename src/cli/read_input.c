/* Reading the input surface for every command: `tr_plc_read_fans` (with --resolve, a
 * polygon that cannot be triangulated in its plane is read as a fan of its loop), and a
 * warning naming each polygon read so: nothing the user gave changes silently. */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "io/io.h"

tr_status tr_cli_read_input(const tr_cli_args *a, int threads, tr_plc **out)
{
  TR_CHECK(tr_plc_read_fans(a->in, out, threads, a->resolve != 0));
  uint32_t n = tr_plc_num_fans(*out);
  if (!n || a->quiet)
    return TR_OK;
  const char *r = tr_plc_fan_notes(*out);
  while (*r) {
    const char *nl = strchr(r, '\n');
    int len = nl ? (int)(nl - r) : (int)strlen(r);
    fprintf(stderr, "tetrec: warning: %.*s: read as the fan of its loop from its first corner "
            "(--resolve)\n", len, r);
    r += len + (nl ? 1 : 0);
  }
  if (n > TR_PLC_FAN_NOTES)
    fprintf(stderr, "tetrec: warning: %s: %u more polygons that cannot be triangulated in "
            "their plane read as fans (the first %d are named above)\n", a->in,
            n - TR_PLC_FAN_NOTES, TR_PLC_FAN_NOTES);
  return TR_OK;
}
