/* Library identity and the small public helpers that belong to no stage. */
#include <stdlib.h>

#include "qpoint.h"
#include "tetrec.h"

/* TR_VERSION_* come from meson.build's project version (src/core/meson.build), so the
 * library reports what it was built as even when a program compiled against an older
 * header loads it. */
void tr_version(int *major, int *minor, int *patch)
{
  if (major)
    *major = TR_VERSION_MAJOR;
  if (minor)
    *minor = TR_VERSION_MINOR;
  if (patch)
    *patch = TR_VERSION_PATCH;
}

void tr_free(void *p) { free(p); }

void tr_thread_cleanup(void) { tr_exact_scratch_free(); }

_Static_assert(TR_STAGE_COUNT <= TR_STAGE_SLOTS, "tr_stats.stage_seconds has no room");

const char *tr_stage_name(int stage)
{
  static const char *const names[TR_STAGE_COUNT] = {
      "reading", "validation", "self_intersection", "nesting", "smoothing", "delaunay",
      "edge_recovery", "facet_recovery", "coloring", "suppression", "refinement", "rounding",
      "statistics", "writing"};
  return stage >= 0 && stage < TR_STAGE_COUNT ? names[stage] : NULL;
}
