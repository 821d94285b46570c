/* tr_stats as one JSON object (keys = the field names of tr_stats), after the status of
 * the run and its message ("" on success). */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "io.h"

tr_status tr_stats_write_json(const tr_stats *s, const char *path)
{
  return tr_stats_write_json_status(s, TR_OK, "", path);
}

tr_status tr_stats_write_json_status(const tr_stats *s, tr_status status, const char *message,
                                     const char *path)
{
  FILE *f = fopen(path, "w");
  if (!f)
    return tr_error(TR_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
  /* the message as a JSON string: quotes, backslashes and control bytes escaped */
  fprintf(f, "{\n  \"status\": \"%s\",\n  \"message\": \"", tr_status_name(status));
  for (const unsigned char *c = (const unsigned char *)(message ? message : ""); *c; c++)
    if (*c == '"' || *c == '\\')
      fprintf(f, "\\%c", *c);
    else if (*c < 0x20)
      fprintf(f, "\\u%04x", *c);
    else
      fputc(*c, f);
  fprintf(f,
          "\",\n  \"surface_nodes\": %llu,\n  \"surface_facets\": %llu,\n"
          "  \"volume_nodes\": %llu,\n  \"volume_elements\": %llu,\n"
          "  \"missing_edges\": %llu,\n  \"edges_recovered_by_swap\": %llu,\n"
          "  \"points_added_for_edges\": %llu,\n  \"missing_facets\": %llu,\n"
          "  \"facets_recovered_by_swap\": %llu,\n  \"points_added_for_facets\": %llu,\n"
          "  \"surface_swaps\": %llu,\n  \"rounding_repairs\": %llu,\n  \"rounding_flips\": %llu,\n"
          "  \"total_seconds\": %.6f,\n  \"recovery_seconds\": %.6f,\n"
          "  \"peak_memory_bytes\": %llu,\n  \"double_deviation\": %.17g\n}\n",
          (unsigned long long)s->surface_nodes, (unsigned long long)s->surface_facets,
          (unsigned long long)s->volume_nodes, (unsigned long long)s->volume_elements,
          (unsigned long long)s->missing_edges, (unsigned long long)s->edges_recovered_by_swap,
          (unsigned long long)s->points_added_for_edges, (unsigned long long)s->missing_facets,
          (unsigned long long)s->facets_recovered_by_swap,
          (unsigned long long)s->points_added_for_facets, (unsigned long long)s->surface_swaps,
          (unsigned long long)s->rounding_repairs,
          (unsigned long long)s->rounding_flips, s->total_seconds, s->recovery_seconds,
          (unsigned long long)s->peak_memory_bytes, s->double_deviation);
  int bad = ferror(f);
  if (fclose(f) != 0 || bad)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return TR_OK;
}
