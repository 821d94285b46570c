/* tr_stats as one JSON object (keys = the field names of tr_stats; stage_seconds as an
 * object keyed by tr_stage_name). */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "io.h"

tr_status tr_stats_write_json(const tr_stats *s, const char *path)
{
  FILE *f = fopen(path, "w");
  if (!f)
    return tr_error(TR_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
  fprintf(f,
          "{\n  \"surface_nodes\": %llu,\n  \"surface_facets\": %llu,\n"
          "  \"volume_nodes\": %llu,\n  \"volume_elements\": %llu,\n"
          "  \"missing_edges\": %llu,\n  \"edges_recovered_by_swap\": %llu,\n"
          "  \"points_added_for_edges\": %llu,\n  \"missing_facets\": %llu,\n"
          "  \"facets_recovered_by_swap\": %llu,\n  \"points_added_for_facets\": %llu,\n"
          "  \"surface_swaps\": %llu,\n  \"rounding_repairs\": %llu,\n  \"rounding_flips\": %llu,\n"
          "  \"hole_points\": %llu,\n  \"region_points\": %llu,\n  \"cavities\": %llu,\n"
          "  \"inclusions\": %llu,\n"
          "  \"total_seconds\": %.6f,\n  \"recovery_seconds\": %.6f,\n"
          "  \"peak_memory_bytes\": %llu,\n  \"stage_seconds\": {",
          (unsigned long long)s->surface_nodes, (unsigned long long)s->surface_facets,
          (unsigned long long)s->volume_nodes, (unsigned long long)s->volume_elements,
          (unsigned long long)s->missing_edges, (unsigned long long)s->edges_recovered_by_swap,
          (unsigned long long)s->points_added_for_edges, (unsigned long long)s->missing_facets,
          (unsigned long long)s->facets_recovered_by_swap,
          (unsigned long long)s->points_added_for_facets, (unsigned long long)s->surface_swaps,
          (unsigned long long)s->rounding_repairs,
          (unsigned long long)s->rounding_flips, (unsigned long long)s->hole_points,
          (unsigned long long)s->region_points, (unsigned long long)s->cavities,
          (unsigned long long)s->inclusions, s->total_seconds, s->recovery_seconds,
          (unsigned long long)s->peak_memory_bytes);
  /* one key per stage, named as `tetrec -v` prints them (tr_stage_name) */
  for (int k = 0; k < TR_STAGE_COUNT; k++)
    fprintf(f, "%s\n    \"%s\": %.6f", k ? "," : "", tr_stage_name(k), s->stage_seconds[k]);
  fprintf(f, "\n  },\n  \"facets_recovered_by_cavity\": %llu,\n"
          "  \"steiner_on_edges\": %llu,\n  \"steiner_on_facets\": %llu,\n"
          "  \"steiner_interior\": %llu,\n  \"steiner_removed\": %llu,\n"
          "  \"steiner_relocated\": %llu\n}\n",
          (unsigned long long)s->facets_recovered_by_cavity,
          (unsigned long long)s->steiner_on_edges, (unsigned long long)s->steiner_on_facets,
          (unsigned long long)s->steiner_interior, (unsigned long long)s->steiner_removed,
          (unsigned long long)s->steiner_relocated);
  int bad = ferror(f);
  if (fclose(f) != 0 || bad)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return TR_OK;
}
