/* Exact conformity of a tet mesh to its input PLC (used by the pipeline tests, the model
 * runs and `tetrec check`). The mesh must hold only the domain's tets (as tr_mesh_plc
 * outputs them: no ghosts kept, outer tets removed); tets flagged TR_TF_OUTER and ghosts
 * are ignored. Checks, in this order, and reports the first violation with where:
 *  1. every tet strictly positive (exact);
 *  2. every vertex of an input triangle or segment is a mesh vertex (equal coordinates);
 *  3. every input edge (triangle edges and segments) is a chain of collinear mesh edges,
 *     except the inner edges of merged planar facets (below);
 *  4. every input triangle is exactly covered: the mesh faces lying in it (all three
 *     vertices in the closed triangle, exact) have a total projected area equal to its
 *     own, exactly (mpq); and every boundary face of the mesh (no tet behind it, or a tet
 *     of another region) lies in some input triangle or merged facet;
 *     a merged planar facet (core/facets.h: exactly coplanar neighbours across a manifold
 *     edge, same marker, opposite sides; refinement works on these) is checked as one
 *     polygon instead: its boundary edges are chains (3.), its inner edges need not be,
 *     and the mesh faces lying in its plane with their three vertices in its closed
 *     triangles and their exact centroid in the closed union of its triangles have a
 *     total projected area equal to the facet's (the sum of its triangles', mpq). The
 *     mesh being a tetrahedralization and the facet's boundary made of mesh edges, no
 *     such face crosses the boundary and none overlap: this is exact coverage. A
 *     triangle merged with none is checked alone as above;
 *  5. the exact sum of 6 * volume of the tets equals volume6, or when volume6 is NULL:
 *     when every input edge has exactly two triangles, the sum of det over the input
 *     triangles (the volume the surface encloses; a cavity shell oriented inward counts
 *     negatively); otherwise (internal facets, cracks) the domain volume of the input's
 *     cell analysis (tr_input_domain_volume6), except under TR_CONF_OPEN (no volume
 *     check: the domain is the convex hull); the cell analysis too when the validated
 *     input has inclusions or hole points, whose triangle sum is not the domain's volume. */
#ifndef TR_MESH_CONFORM_H
#define TR_MESH_CONFORM_H

#include <gmp.h>

#include "core/plc.h"
#include "mesh.h"

enum {
  /* the input was open and meshed within its convex hull (tr_options.allow_open): mesh
   * boundary faces need not lie in an input triangle */
  TR_CONF_OPEN = 1u << 0,
  /* no merged facets: every input edge a chain, every triangle covered on its own (the
   * promise of tr_options.keep_edges, and of meshes made without refinement) */
  TR_CONF_KEEP_EDGES = 1u << 1
};

tr_status tr_check_conformity(const struct tr_mesh *m, const struct tr_plc *plc,
                              mpq_srcptr volume6, unsigned flags);

#endif
