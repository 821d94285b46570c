/* The mesh validator: checks the properties every stage must preserve and reports the
 * first violated one with where (tet, face, vertex) in tr_last_error(), returning
 * TR_ERR_INVALID_MESH. It never trusts a flag of the mesh: everything is recomputed with
 * exact predicates (tr_orient3d_p / exact rationals for Steiner points). */
#ifndef TR_MESH_CHECK_H
#define TR_MESH_CHECK_H

#include <gmp.h>

#include "mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

enum {
  /* tn symmetric, shared faces have the same 3 vertices in opposite orientation, codes
   * in range, no link to a free slot or to itself */
  TR_CHK_LINKS = 1u << 0,
  /* every Steiner coordinate a canonical rational, every real tet strictly positive
   * (exact); ghosts have TR_GHOST only in slot 3 */
  TR_CHK_ORIENT = 1u << 1,
  /* v2t[v] is a live tet containing v for every used vertex; with a dup_map, every kept
   * input point is used and every dropped one is unused; each face in at most two tets */
  TR_CHK_V2T = 1u << 2,
  /* V - E + F - T == 1 over the real tets (a triangulated ball) */
  TR_CHK_EULER = 1u << 3,
  /* perturbed Delaunay: across each interior face the opposite vertex is outside the
   * circumsphere (tr_insphere_sos < 0), and the hull is locally convex at ghost edges */
  TR_CHK_DELAUNAY = 1u << 4,
  TR_CHK_TOPOLOGY = TR_CHK_LINKS | TR_CHK_ORIENT | TR_CHK_V2T | TR_CHK_EULER,
  TR_CHK_ALL_DELAUNAY = TR_CHK_TOPOLOGY | TR_CHK_DELAUNAY
};

/* Checks the properties in `what` (TR_CHK_* bits, links are always checked first when
 * any other topological property is asked). If volume6 != NULL, also compares the exact
 * sum of 6 * volume of the real tets with it. */
tr_status tr_check_mesh(const struct tr_mesh *m, unsigned what, mpq_srcptr volume6);

/* out = exact sum over the real tets of det[b-a; c-a; d-a] (six times the volume). */
tr_status tr_mesh_volume6(const struct tr_mesh *m, mpq_t out);

#ifdef __cplusplus
}
#endif

#endif
