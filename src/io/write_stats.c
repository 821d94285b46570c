/* tr_stats as one JSON object (keys = the field names of tr_stats). */
#include <errno.h>
#include <math.h>
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
          "  \"total_seconds\": %.6f,\n  \"recovery_seconds\": %.6f,\n"
          "  \"peak_memory_bytes\": %llu,\n",
          (unsigned long long)s->surface_nodes, (unsigned long long)s->surface_facets,
          (unsigned long long)s->volume_nodes, (unsigned long long)s->volume_elements,
          (unsigned long long)s->missing_edges, (unsigned long long)s->edges_recovered_by_swap,
          (unsigned long long)s->points_added_for_edges, (unsigned long long)s->missing_facets,
          (unsigned long long)s->facets_recovered_by_swap,
          (unsigned long long)s->points_added_for_facets, (unsigned long long)s->surface_swaps,
          (unsigned long long)s->rounding_repairs,
          (unsigned long long)s->rounding_flips, s->total_seconds, s->recovery_seconds,
          (unsigned long long)s->peak_memory_bytes);
  /* the quality rows (src/refine/quality.h) */
  fprintf(f,
          "  \"points_added_for_quality\": %llu,\n  \"min_dihedral\": %.6f,\n"
          "  \"max_dihedral\": %.6f,\n  \"max_radius_edge\": %.6g,\n"
          "  \"tets_dihedral_below_5\": %llu,\n  \"tets_dihedral_below_10\": %llu,\n",
          (unsigned long long)s->points_added_for_quality, s->min_dihedral, s->max_dihedral,
          isfinite(s->max_radius_edge) ? s->max_radius_edge : 1e308,
          (unsigned long long)s->tets_dihedral_below_5,
          (unsigned long long)s->tets_dihedral_below_10);
  fprintf(f, "  \"dihedral_histogram\": [");
  for (size_t i = 0; i < sizeof s->dihedral_histogram / sizeof *s->dihedral_histogram; i++)
    fprintf(f, "%s%llu", i ? ", " : "", (unsigned long long)s->dihedral_histogram[i]);
  fprintf(f, "],\n  \"radius_edge_histogram\": [");
  for (size_t i = 0; i < sizeof s->radius_edge_histogram / sizeof *s->radius_edge_histogram; i++)
    fprintf(f, "%s%llu", i ? ", " : "", (unsigned long long)s->radius_edge_histogram[i]);
  fprintf(f, "]\n}\n");
  int bad = ferror(f);
  if (fclose(f) != 0 || bad)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return TR_OK;
}
