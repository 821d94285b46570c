/* Hole and region points applied after the coloring (color.h), on the mesh whose inner
 * cells carry region ids 1..*nregions.
 *
 * A hole point empties the cell that contains it: its tets become outer (TR_TF_OUTER,
 * region 0). A region point gives the tets of its cell its attribute as region id (the
 * int32 attribute's bits in the uint32 region array); the cells without one keep the
 * coloring's order, renumbered 1..k over the cells left (so the ids of a mesh without
 * region points are unchanged by hole points other than those emptied). Errors
 * (TR_ERR_INPUT, naming the point): a hole or region point on an input triangle, a
 * region point outside the domain or in an emptied cell, two region points with
 * different attributes in one cell. Warnings on stderr (verbose >= 1): a hole point
 * outside every shell (it removes nothing; one in a cavity the surface leaves empty
 * anyway is not warned about), a region's positive maximum volume (stored,
 * not supported: there is no refinement). verbose >= 2 says which region each point hit.
 * *nregions becomes the number of inner cells left. Exact: the points are located with
 * exact orient3d, also among rational Steiner points. Cost: one pass over the input
 * triangles and one over the inner tets, each asking a grid of the points for the ones in
 * its box (thousands of points cost about as much as one). */
#ifndef TR_OUTER_POINTS_H
#define TR_OUTER_POINTS_H

#include "core/plc.h"
#include "mesh/mesh.h"

tr_status tr_outer_points(struct tr_mesh *m, const struct tr_plc *plc, int verbose,
                          uint32_t *nregions);

#endif
