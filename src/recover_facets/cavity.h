/* Missing-facet recovery by cavity retriangulation (Si & Gaertner 2005; the approach of
 * TetGen 1.5): no Steiner point, tried after the flips and before the clusterels.
 *
 * The cavity of a missing facet F = EFG is the union C of its crossing clusterels (the
 * tets whose interior meets the open triangle; cluster.h). Every vertex of C lies on one
 * closed side of F's plane or on F's boundary, no face of C's boundary crosses the plane
 * (such a face would cross F, so the tet behind it would be a clusterel too), so F's
 * plane cuts C into an upper cavity C+ and a lower cavity C-, glued along the region
 * R = C n plane, a polygon inside F whose corners lie on F's boundary.
 *
 * Each side is retriangulated as the Delaunay tetrahedralization of its vertices (the
 * vertices of C on that closed side: R's corners and every vertex strictly on the side,
 * interior ones included, so no vertex is lost), built here by a small exact
 * Bowyer-Watson (exact insphere, a cospherical point is not in conflict: the result is a
 * Delaunay tetrahedralization, the one of this insertion order, ids ascending). Its tets
 * inside the cavity are taken by a flood fill from the cavity's boundary faces, which
 * must all be faces of the Delaunay mesh; where one is not, the tet behind it (on the
 * same closed side, touching the plane only at R's corners) joins the cavity and the
 * side is rebuilt (Si's cavity expansion, at most TR_CAVITY_EXPAND rounds). Both sides
 * must triangulate R the same way (they do unless R's corners are cocircular), every
 * protected edge and face (the guard) inside the cavity must survive, and the new tets
 * must fill exactly the old region (tr_mesh_replace checks it). When any of this fails
 * the mesh is left as it was and the caller goes on with the clusterels.
 *
 * Where it succeeds, F is the union of the faces of R's triangulation and of the faces
 * of F that were present already.
 */
#ifndef TR_RECOVER_FACETS_CAVITY_H
#define TR_RECOVER_FACETS_CAVITY_H

#include "mesh/mesh.h"
#include "recover_edges/flip.h"
#include "recover_facets/cluster.h"

/* Expansion rounds, and the most vertices a side may have (the Bowyer-Watson here is a
 * brute-force one, quadratic in them; a larger cavity goes to the clusterels). */
#define TR_CAVITY_EXPAND 8
#define TR_CAVITY_MAX_VERTICES 192

typedef struct tr_cavity_stats {
  uint64_t tried;       /* facets tried */
  uint64_t recovered;   /* retriangulated: the facet is present, no Steiner point */
  uint64_t expanded;    /* tets added to cavities by expansion (over all facets) */
  uint64_t failed_boundary; /* a boundary face stayed missing after the last expansion,
                               or could not be expanded across */
  uint64_t failed_other;    /* too big, R triangulated differently, a protected edge or
                               face lost, or the replacement refused */
} tr_cavity_stats;

/* Tries the retriangulation of facet efg (idx names it in messages) whose cluster is
 * cl[0..ncl) (current). *done = 1 if the mesh was changed (then the facet is present).
 * guard / ud: the protected edges and faces (may be NULL). A refusal is *done = 0 with
 * TR_OK; only out of memory is an error. */
tr_status tr_facet_cavity(struct tr_mesh *m, uint32_t idx, uint32_t e, uint32_t f, uint32_t g,
                          const tr_clusterel *cl, uint32_t ncl, tr_flip_guard guard, void *ud,
                          tr_cavity_stats *st, int *done);

#endif
