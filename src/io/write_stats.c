/* tr_stats as one JSON object: the status of the run and its message ("" on success),
 * then one key per field of tr_stats, named as the field (stage_seconds as an object
 * keyed by tr_stage_name). The fields are listed once, in the tables below, so a new
 * field is one line. */
#include <errno.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "../core/status.h"

typedef struct {
  const char *name;
  size_t off;
} field;

#define FIELD(f) {#f, offsetof(tr_stats, f)}
/* uint64_t fields */
static const field counts[] = {
    FIELD(surface_nodes), FIELD(surface_facets), FIELD(volume_nodes), FIELD(volume_elements),
    FIELD(missing_edges), FIELD(edges_recovered_by_swap), FIELD(points_added_for_edges),
    FIELD(missing_facets), FIELD(facets_recovered_by_swap), FIELD(points_added_for_facets),
    FIELD(facets_recovered_by_cavity), FIELD(surface_swaps), FIELD(rounding_repairs),
    FIELD(rounding_flips), FIELD(hole_points), FIELD(region_points), FIELD(cavities),
    FIELD(inclusions), FIELD(steiner_on_edges), FIELD(steiner_on_facets), FIELD(steiner_interior),
    FIELD(steiner_removed), FIELD(steiner_relocated), FIELD(peak_memory_bytes),
    FIELD(points_added_for_quality), FIELD(tets_dihedral_below_5), FIELD(tets_dihedral_below_10),
    FIELD(points_added_for_sliver), FIELD(sliver_flips), FIELD(sliver_points_smoothed),
    FIELD(input_edges_merged), FIELD(refine_budget_reached), FIELD(tets_over_bounds),
    FIELD(tets_dihedral_below_10_on_thin_input), FIELD(thin_input_triangles),
    FIELD(surface_collapses), FIELD(surface_flips)};
/* double fields */
static const field reals[] = {FIELD(total_seconds), FIELD(recovery_seconds),
                              FIELD(double_deviation), FIELD(min_dihedral),
                              FIELD(max_dihedral), FIELD(max_radius_edge),
                              FIELD(bytes_per_tet), FIELD(surface_tolerance_bound),
                              FIELD(surface_tolerance_seconds)};
#undef FIELD

/* The message as a JSON string: quotes, backslashes and control bytes escaped. */
static void put_string(FILE *f, const char *text)
{
  fputc('"', f);
  for (const unsigned char *c = (const unsigned char *)(text ? text : ""); *c; c++)
    if (*c == '"' || *c == '\\')
      fprintf(f, "\\%c", *c);
    else if (*c < 0x20)
      fprintf(f, "\\u%04x", *c);
    else
      fputc(*c, f);
  fputc('"', f);
}

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
  fprintf(f, "{\n  \"status\": \"%s\",\n  \"message\": ", tr_status_name(status));
  put_string(f, message);
  const char *base = (const char *)s;
  for (size_t i = 0; i < sizeof counts / sizeof *counts; i++) {
    uint64_t v;
    memcpy(&v, base + counts[i].off, sizeof v);
    fprintf(f, ",\n  \"%s\": %llu", counts[i].name, (unsigned long long)v);
  }
  /* %.17g: doubles read back exactly */
  for (size_t i = 0; i < sizeof reals / sizeof *reals; i++) {
    double v;
    memcpy(&v, base + reals[i].off, sizeof v);
    /* JSON has no infinity: a flat tet's radius-edge ratio is written as 1e308 */
    fprintf(f, ",\n  \"%s\": %.17g", reals[i].name, isfinite(v) ? v : 1e308);
  }
  /* the quality histograms (src/refine/quality.h) */
  fprintf(f, ",\n  \"dihedral_histogram\": [");
  for (size_t i = 0; i < sizeof s->dihedral_histogram / sizeof *s->dihedral_histogram; i++)
    fprintf(f, "%s%llu", i ? ", " : "", (unsigned long long)s->dihedral_histogram[i]);
  fprintf(f, "],\n  \"radius_edge_histogram\": [");
  for (size_t i = 0; i < sizeof s->radius_edge_histogram / sizeof *s->radius_edge_histogram; i++)
    fprintf(f, "%s%llu", i ? ", " : "", (unsigned long long)s->radius_edge_histogram[i]);
  fprintf(f, "]");
  /* one key per stage, named as `tetrec -v` prints them (tr_stage_name) */
  fprintf(f, ",\n  \"stage_seconds\": {");
  for (int k = 0; k < TR_STAGE_COUNT; k++)
    fprintf(f, "%s\n    \"%s\": %.6f", k ? "," : "", tr_stage_name(k), s->stage_seconds[k]);
  fprintf(f, "\n  }\n}\n");
  int bad = ferror(f);
  if (fclose(f) != 0 || bad)
    return tr_error(TR_ERR_IO, "%s: write failed", path);
  return TR_OK;
}
