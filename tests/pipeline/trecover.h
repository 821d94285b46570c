/* The tests that look at the mesh between stages (tests/pipeline, tests/suppress) drive
 * the pipeline as tr_mesh_plc does, without smoothing: validation, the input's edges,
 * Delaunay, then edge and facet recovery (tr_pipeline_recover). One helper, so that a
 * change of those stages' calls is made once for every such test. */
#ifndef TR_TESTS_PIPELINE_TRECOVER_H
#define TR_TESTS_PIPELINE_TRECOVER_H

#include <string.h>

#include "core/plc.h"
#include "delaunay/delaunay.h"
#include "input/validate.h"
#include "pipeline/pipeline.h"

typedef struct {
  struct tr_mesh *m;
  tr_subfaces sub; /* the recovered facets' sub-faces */
  uint32_t *edges, ne, nopen, nmulti;
  uint8_t *vkind;
  uint32_t *vindex;
  uint32_t *hint; /* the sub-faces' tet hints for tr_outer_color_ex (NULL: none) */
  tr_stats st;
} trec_run;

/* Validates plc (NULL options) and runs the stages up to facet recovery into *r, which
 * trec_free releases whatever the outcome. Stops at the first failing stage. */
static inline tr_status trec_to_recovery(tr_plc *plc, trec_run *r)
{
  memset(r, 0, sizeof *r);
  tr_options opt;
  tr_options_default(&opt);
  double secs[2];
  tr_status s = tr_plc_validate(plc, NULL);
  if (s == TR_OK)
    s = tr_pipeline_edges(plc, &r->edges, &r->ne, &r->nopen, &r->nmulti);
  if (s == TR_OK)
    s = tr_delaunay_build(plc->xyz, plc->npoints, &r->m);
  if (s == TR_OK)
    s = tr_pipeline_recover(r->m, plc, r->edges, r->ne, &r->sub, &r->st, secs, &opt,
                            &r->vkind, &r->vindex, &r->hint);
  return s;
}

static inline void trec_free(trec_run *r)
{
  tr_pipeline_subfaces_free(&r->sub);
  free(r->edges);
  free(r->vkind);
  free(r->vindex);
  free(r->hint);
  tr_mesh_destroy(r->m);
  memset(r, 0, sizeof *r);
}

#endif
