/* The refinement stage's entry points for the pipeline (src/pipeline/mesh_plc.c) and the
 * CLI: option checks, the stage with its default budget, the quality rows of tr_stats. */
#ifndef TR_REFINE_STAGE_H
#define TR_REFINE_STAGE_H

#include "refine/refine.h"

/* TR_ERR_USAGE for a bound out of range, TR_ERR_UNSUPPORTED for a dihedral target. */
tr_status tr_refine_check_options(const tr_options *opt);
/* tr_refine with the options' bounds and budget (default: tr_refine_default_budget on the
 * domain's volume); *points = points added, *merged = input edges inside merged planar
 * facets (core/facets.h; 0 with opt->keep_edges), *budget_reached = 1 when the point
 * budget ended it under opt->refine_partial (without it, reaching the budget is
 * TR_ERR_NOMEM). keep_hull (open input in its hull): refused. */
tr_status tr_refine_stage(struct tr_mesh *m, const struct tr_plc *plc, tr_subfaces *sub,
                          const tr_options *opt, int keep_hull, uint64_t *points,
                          uint64_t *merged, uint64_t *budget_reached);
/* m's tets whose radius-edge ratio is over opt->quality_ratio (ratio), whose volume is over
 * its bound (volume: opt->max_volume, plc's region points' unless plc is NULL), and either
 * (either), all in doubles, in one pass. */
typedef struct tr_refine_over {
  uint64_t ratio, volume, either;
} tr_refine_over;
tr_status tr_refine_count_over(const struct tr_mesh *m, const struct tr_plc *plc,
                               const tr_options *opt, tr_refine_over *over);
/* The per-region volume bounds of plc's region points as tr_refine_params wants them
 * (ids sorted, distinct, the smallest bound of a repeated id; malloc'ed); *least is lowered
 * to the smallest (it is the caller's global bound, or 0 for none). */
tr_status tr_refine_region_bounds(const struct tr_plc *plc, uint32_t **ids, double **bounds,
                                  uint32_t *n, double *least);
/* The shape rows of s (min/max dihedral, histograms, ...) measured on m's doubles. */
void tr_quality_stats(const struct tr_mesh *m, tr_stats *s);

#endif
