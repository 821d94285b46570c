/* The distance of written Steiner doubles from their constraints (deviation.c). */
#ifndef TR_OUTPUT_DEVIATION_H
#define TR_OUTPUT_DEVIATION_H

#include "mesh/mesh.h"

struct tr_plc;
/* tr_mesh_double_deviation of include/tetrec.h. */
tr_status tr_mesh_double_deviation(const struct tr_mesh *m, const struct tr_plc *plc,
                                   double *dev, uint32_t *vertex);
/* For `tetrec check` on a mesh file with rounded Steiner points (whose exact constraint is
 * not known): the largest distance of points first..n-1 of xyz with on[v] != 0 (all of
 * them if on is NULL) from the nearest triangle of plc near them (in their grid cell),
 * over plc's bounding box diagonal, measured in doubles; *vertex = where (UINT32_MAX if
 * none). A lower bound of the deviation from the constraint each lies on, as long as on
 * names only points that lie on a constraint: an interior point of a refined mesh near
 * the surface would be taken for a large deviation. */
tr_status tr_plc_points_distance(const struct tr_plc *plc, const double *xyz, uint32_t first,
                                 uint32_t n, const uint8_t *on, double *dev, uint32_t *vertex);

#endif
