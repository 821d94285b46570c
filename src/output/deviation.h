/* The distance of written Steiner doubles from their constraints (deviation.c). */
#ifndef TR_OUTPUT_DEVIATION_H
#define TR_OUTPUT_DEVIATION_H

#include "mesh/mesh.h"

struct tr_plc;
/* tr_mesh_double_deviation of include/tetrec.h. */
tr_status tr_mesh_double_deviation(const struct tr_mesh *m, const struct tr_plc *plc,
                                   double *dev, uint32_t *vertex);

#endif
