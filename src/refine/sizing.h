/* A size field for refinement (tr_options.sizing, the command's --sizing): a target edge
 * length per input point, interpolated linearly over the Delaunay tetrahedralization of
 * the input points (the background mesh, built once and read only). Doubles throughout:
 * a size only chooses which tets and pieces get points, never connectivity. */
#ifndef TR_REFINE_SIZING_H
#define TR_REFINE_SIZING_H

#include <stdint.h>

#include "core/plc.h"
#include "mesh/mesh.h"

typedef struct tr_sizing {
  struct tr_mesh *bg; /* Delaunay of the input points, ghosts kept */
  const double *h;    /* per input point (the background's vertex ids): >= 0, 0 none */
} tr_sizing;

/* The field of plc->vsize (not NULL) over plc's points; threads as for the Delaunay
 * stage (the same mesh for any number). */
tr_status tr_sizing_build(const struct tr_plc *plc, int threads, tr_sizing *s);
void tr_sizing_free(tr_sizing *s);
/* The size at p: linear over the background tet that holds p (found by a visibility walk
 * from *hint, which is updated; any value is a valid hint), clamped to the nearest hull
 * tet outside the hull; 0 when a vertex of that tet has none. */
double tr_sizing_at(const tr_sizing *s, const double p[3], uint32_t *hint);
/* The integral of h^-3 over a tet of volume vol on whose vertices the linear h takes
 * h[0..3] (all > 0): the points a field asks for are about proportional to it. */
double tr_sizing_inverse_cube(double vol, const double h[4]);

#endif
