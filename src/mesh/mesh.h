/* The mesh store: tetrahedra in flat uint32_t arrays, HXT style.
 *
 *   tv[4*t + k]  vertex k of tet t (k = its NCode). tv[4*t] == TR_NONE: t is free.
 *   tn[4*t + k]  neighbour across face k (the face opposite vertex k, FCode = k),
 *                encoded as 4*t' + k' where k' is the face of t' shared with t;
 *                TR_NONE when there is none. So NEIG(t,k) = tn[4t+k] >> 2 and the
 *                shared face's code in the neighbour comes for free as tn[4t+k] & 3.
 *
 * Orientation (one convention, see include/tetrec.h): tet (v0,v1,v2,v3) is positive iff
 * tr_orient3d(v0,v1,v2,v3) > 0. The vertices of face k listed in tr_face_vtx[k] order
 * (a,b,c) satisfy orient3d(a,b,c,vk) > 0: seen from vk they turn clockwise, i.e. their
 * right-hand normal points into the tet.
 *
 * Convex hull: the Delaunay stage uses ghost tets: tets with vertex TR_GHOST in slot 3
 * (see delaunay/), so every real tet has 4 neighbours; ghost tets are skipped by
 * iterators that say so and removed by outer removal.
 */
#ifndef TR_MESH_H
#define TR_MESH_H

#include <stdint.h>

#include "../../predicates/qpoint.h"
#include "../core/status.h"

#define TR_NONE UINT32_MAX

/* tr_face_vtx[k] = the three vertex codes of face k, ordered as explained above. */
extern const uint8_t tr_face_vtx[4][3];

#endif
