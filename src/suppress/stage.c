/* The suppression stage in the pipeline: which steps run in which mode, and the counts. */
#include <stdio.h>

#include "pipeline/pipeline.h"
#include "suppress.h"

tr_status tr_pipeline_suppress(struct tr_mesh *m, tr_subfaces *sub, const struct tr_plc *plc,
                               const tr_options *opt, int keep_hull, unsigned pipe_flags,
                               tr_stats *stats)
{
  if (opt->keep_surface && (pipe_flags & TR_PIPE_KEEP_STEINER))
    return tr_error(TR_ERR_USAGE, "--keep-surface and --keep-steiner contradict each other");
  if (opt->keep_surface && keep_hull)
    return tr_error(TR_ERR_USAGE, "--keep-surface needs a closed surface: an open one is "
                    "meshed within its convex hull, whose faces are not input triangles");
  /* Open inputs meshed within their hull: the sub-faces are internal constraints, so
   * only the counts; the same with --keep-steiner. */
  unsigned flags = keep_hull || (pipe_flags & TR_PIPE_KEEP_STEINER) ? 0 : TR_SUP_DEFAULT;
  if (opt->keep_surface)
    flags = TR_SUP_REMOVE | TR_SUP_RELOCATE | TR_SUP_INTERIOR | TR_SUP_MERGE | TR_SUP_REQUIRE;
  tr_suppress_stats s;
  TR_CHECK(tr_suppress_steiner(m, sub, plc, flags, &s));
  stats->steiner_on_edges = s.on_edges;
  stats->steiner_on_facets = s.on_facets;
  stats->steiner_interior = s.interior;
  stats->steiner_removed = s.removed;
  stats->steiner_relocated = s.relocated;
  if (opt->verbose >= 2 && (s.removed || s.relocated))
    fprintf(stderr, "tetrec: %llu boundary Steiner points removed, %llu moved inside\n",
            (unsigned long long)s.removed, (unsigned long long)s.relocated);
  return TR_OK;
}
