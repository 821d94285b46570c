/* Flips that take away tets flat in doubles, before the rounding repair (issue 7).
 *
 * A tet can be strictly positive exactly and flat or inverted once its Steiner points are
 * at their nearest doubles. The repair of round.h moves doubles; it cannot help a tet
 * whose shape, not its vertices' rounding, is the problem: a sliver whose four vertices
 * lie on one facet that is bumpy below the resolution of doubles (coordinates moved by
 * ulps, zeros moved to subnormals) has a volume no double position of a Steiner point
 * can keep positive. Such a tet is often not needed: the face under it has a better
 * apex a few tets away. This pass runs on the exact mesh after outer removal and, for
 * each kept tet that is not strictly positive on the doubles m->xyz (round.h), tries
 * flips that
 *   - keep the mesh exactly valid: every new tet strictly positive on the exact points;
 *   - keep it conforming: no sub-face is flipped away (so no sub-segment of an input
 *     edge on a triangle either), no edge lying on an input segment is removed, and all
 *     tets of a flip are kept tets of one region;
 *   - strictly lower the number of its tets that are not positive in doubles.
 * The flips are Swap23 on each face of the tet and edge removal on each of its edges
 * whose shell has 3 to TR_FLATFLIP_MAX_SHELL tets (the ring triangulated as a fan from
 * each ring vertex in turn; 3 tets: Swap32). The first flip that helps is taken (faces
 * before edges, in code order; fans by fewest tets left flat, then ring order). Passes
 * over the tets in slot order repeat until one takes no flip; each flip lowers the total
 * number of flat tets, so this ends, and the result depends only on the mesh.
 *
 * A flip makes fewer, larger tets (3-2, edge removal): after the passes (and with any
 * volume bound of refinement, -a or region points, flips or not: the last net under the
 * stages before), a tet over its bound is split in four at its centroid, an interior
 * double, when its new tets are positive exactly and in doubles (the passes repeat; each
 * split quarters the volume).
 *
 * The exact points never change, so the mesh stays exactly conforming and the --exact
 * output is the same mesh as the double one. */
#ifndef TR_OUTPUT_FLATFLIP_H
#define TR_OUTPUT_FLATFLIP_H

#include <stdint.h>

#include "core/plc.h"
#include "mesh/mesh.h"
#include "recover_facets/recover_facets.h"

#define TR_FLATFLIP_MAX_SHELL 6

/* m: the working mesh after tr_outer_color (regions enabled); sub: its sub-faces; plc:
 * the meshed PLC (its segments are constraints too, its region points' maximum volumes
 * bounds); max_volume: the bound on every tet (0: none); split_over 0: no tet is split for
 * a bound (refinement stopped at its point budget, tr_options.refine_partial, and the
 * bounds are not met anyway). *nflips = flips taken. */
tr_status tr_round_flip_flat(struct tr_mesh *m, const tr_subfaces *sub, const tr_plc *plc,
                             double max_volume, int split_over, uint64_t *nflips);

/* After the rounding repair failed on the compact copy: each kept tet of m still flat in
 * doubles gets a new vertex at its centroid (a double) joined to a cavity grown from it
 * until the centroid sees every face of its boundary strictly, exactly and in doubles
 * (flatflip.c, try_insert). Only run on that failure, so every mesh the repair handles
 * stays as it was. *ninserted = vertices added. */
tr_status tr_round_insert_flat(struct tr_mesh *m, const tr_subfaces *sub, const tr_plc *plc,
                               uint64_t *ninserted);

#endif
