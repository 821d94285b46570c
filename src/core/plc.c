#include "plc.h"

#include <stdlib.h>
#include <string.h>

void tr_plc_clear(struct tr_plc *plc)
{
  free(plc->xyz);
  free(plc->tris);
  free(plc->tri_marker);
  free(plc->tri_source);
  free(plc->segs);
  free(plc->tets);
  free(plc->source);
  memset(plc, 0, sizeof *plc);
}
