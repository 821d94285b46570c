/* Cluster(F): the clusterels of a missing facet F = EFG (the seed paper's "Definition of
 * a clusterel"), collected and classified exactly.
 *
 * Precondition: E, F, G are mesh vertices and the three edges of EFG are mesh edges
 * (edge recovery ran first). Then no mesh edge or face crosses the boundary of the
 * triangle, which the classification relies on.
 *
 * A tet t is a clusterel iff
 *   CO_PLAN  one face of t lies in the closed triangle EFG (the paper: "tetrahedra with
 *            one facet coplanar with F"; the tets on both sides of such a face), or
 *   ONE_EDG .. FOU_EDG  1..4 edges of t cross the open triangle EFG at an interior point
 *            of the edge ("edges cutting through the missing facet").
 * For the crossing types, the intersection of t with the plane of EFG is a triangle or a
 * quad inside EFG; its corners are the clusterel's nodes, at most 4:
 *   NOD_MID  an edge of t crosses the plane at an interior point: codes[i] = its ECode;
 *   NOD_BEG / NOD_END  a vertex of t lies on the plane (inside the closed EFG): codes[i] =
 *            the ECode of the edge from that vertex to the first vertex of t (lowest code)
 *            strictly off the plane, and the node is that edge's start (lower code) or
 *            end;
 *   NOD_EXT  an edge crosses the plane outside EFG ("in the extension" of the facet). A
 *            clusterel never has one: its section by the plane is a convex polygon whose
 *            relative interior lies inside t, which no edge of EFG enters, so the polygon
 *            is inside EFG or disjoint from it. The value is kept for the vocabulary;
 *   NOD_NUL  unused slot.
 * nodes[i] is the mesh vertex of node i when it is a vertex of t, TR_NONE for a crossing
 * point not yet inserted. type = the number of NOD_MID nodes (CO_PLAN: 0 nodes, face =
 * FCode of the coplanar face). Nodes are listed MID first in ECode order, then the
 * on-plane vertices in code order.
 */
#ifndef TR_RECOVER_FACETS_CLUSTER_H
#define TR_RECOVER_FACETS_CLUSTER_H

#include "core/vtmap.h"
#include "mesh/mesh.h"
#include "recover_edges/edgeset.h"

enum { TR_CO_PLAN = 0, TR_ONE_EDG, TR_TWO_EDG, TR_THR_EDG, TR_FOU_EDG };
enum { TR_NOD_NUL = 0, TR_NOD_EXT, TR_NOD_BEG, TR_NOD_END, TR_NOD_MID };

typedef struct tr_clusterel {
  uint32_t iele;     /* the tet */
  uint8_t type;      /* TR_CO_PLAN .. TR_FOU_EDG */
  int8_t face;       /* CO_PLAN: FCode of the face in EFG's plane; else -1 */
  uint8_t nnodes;
  uint8_t codes[4];  /* ECodes, see above */
  uint8_t ntypes[4]; /* TR_NOD_* */
  uint32_t nodes[4]; /* mesh vertex or TR_NONE */
} tr_clusterel;

/* Classifies one tet against the triangle efg. *member = 0 when t is not a clusterel
 * (out is then unspecified). TR_ERR_INVALID_MESH if t is flat, or if its edges cross the
 * plane both inside and outside EFG or through EFG's boundary (the precondition is
 * violated). */
tr_status tr_clusterel_classify(const struct tr_mesh *m, uint32_t t, const tr_point *e,
                                const tr_point *f, const tr_point *g, tr_clusterel *out,
                                int *member);

/* Cluster(EFG): every clusterel, sorted by tet index. Found by a search through face
 * neighbours over the tets that touch the closed triangle, starting from Ball(e); ghost
 * tets are never clusterels. *out is malloc'ed (free() it; NULL when *n == 0). */
tr_status tr_cluster_collect(struct tr_mesh *m, uint32_t e, uint32_t f, uint32_t g,
                             tr_clusterel **out, uint32_t *n);

/* Exact answers of the collection by vertex ids (each vertex's side of the plane EFG and
 * membership in the closed triangle; each crossed edge's crossing point in or out), so
 * that collecting the same facet's cluster again after flips only evaluates what is
 * new. Valid for one facet while no point moves. Zero-initialise; free with
 * tr_cluster_memo_free. */
typedef struct tr_cluster_memo {
  tr_vtmap v;   /* vertex -> (side + 1) | in_closed << 2 */
  tr_edgeset e; /* edge {u, v} -> crossing_in_triangle + 1 */
} tr_cluster_memo;
void tr_cluster_memo_free(tr_cluster_memo *c);
/* The memo's answers one by one (e, f, g: the facet's points): the side of vertex v of
 * the plane efg (orient3d sign), and for an edge uv whose ends lie strictly on both sides
 * whether it crosses the triangle: 1 strictly inside, 0 outside, -1 on its boundary.
 * The facet flip driver measures its attempts with them, so they are evaluated once for
 * the measure and the collection together. */
int tr_cluster_side(const struct tr_mesh *m, uint32_t v, const tr_point *e, const tr_point *f,
                    const tr_point *g, tr_cluster_memo *mc);
int tr_cluster_crossing(const struct tr_mesh *m, uint32_t u, uint32_t v, const tr_point *e,
                        const tr_point *f, const tr_point *g, tr_cluster_memo *mc);
/* tr_cluster_collect with the answers taken from / added to mc (a memo of facet efg). */
tr_status tr_cluster_collect_memo(struct tr_mesh *m, uint32_t e, uint32_t f, uint32_t g,
                                  tr_clusterel **out, uint32_t *n, tr_cluster_memo *mc);

#endif
