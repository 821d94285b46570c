/* Recovery of ONE missing facet (the paper's "RECOVERY OF MISSING FACETS" for one input
 * triangle F = EFG), and the exact presence test shared with tr_subfaces.
 *
 * Presence test (documented choice: a boundary-closure argument, double-checked by an
 * exact area sum). After edge recovery no mesh edge or face crosses the boundary of F.
 * If no tet of Cluster(F) is a crossing clusterel (ONE_EDG..FOU_EDG), no tet's interior
 * meets the open triangle: a tet whose interior met it would have vertices strictly on
 * both sides of F's plane, so an edge crossing the plane at a point of its section
 * polygon, which lies inside F (cluster.h) and not on F's boundary. Then F is covered by
 * mesh faces, edges and vertices, i.e. F is the union of the coplanar faces of the
 * CO_PLAN clusterels. After a recovery changed the mesh, the sum of their exact
 * (projected, rational) areas must also equal F's area (an inequality is reported as an
 * internal error, never ignored); for facets already present it is not recomputed.
 *
 * Recovery: Swap32 (Table 10) when the only crossing tets are the three around one edge
 * AB whose ring is EFG; then general flips (flipfacet.h: edge removal of the crossing
 * edges, Swap23 on the cut faces, kept only while they lower the crossing count); what
 * still crosses after them is retriangulated without Steiner points where cavity.h can
 * (off with no_cavity); else every crossing clusterel is decomposed (ONE_EDG: Table 5
 * (pipel Case 1), TWO_EDG: Table 6 II-S/II-Z (pipel Case 2), THR_EDG: Table 11, FOU_EDG:
 * Table 12 + SZZS) with one exact Steiner point per crossed mesh edge (shared by every
 * clusterel around that edge) and the extra point H where the case needs it. The S/Z
 * choice follows the paper's Steps 1-3 in tet-index order: a face whose diagonal a
 * decomposed neighbour already chose imposes the matching type, a free face takes
 * whatever tr_cluster_match prefers. All clusterels are replaced in one tr_mesh_replace
 * call, which glues every sub-face to its partner by vertex set: this is the Phi linking
 * of the paper, and it refuses (leaving the tets unchanged) if two sides disagree.
 */
#ifndef TR_RECOVER_FACETS_FACET_H
#define TR_RECOVER_FACETS_FACET_H

#include "mesh/mesh.h"
#include "recover_facets/cluster_tables.h"
#include "recover_facets/cavity.h"
#include "recover_facets/flipfacet.h"

/* Test hooks; zero-initialise for normal use (force_first = 0 means "off" only when
 * force_on is 0). */
typedef struct tr_facet_opts {
  int no_swap;   /* skip Swap32, the flips and the cavity retriangulation, so the
                    clusterel path runs on Swap32 configurations */
  int force_on;  /* decompose the first clusterel of the highest type >= THR_EDG first,
                    imposing force_first on it */
  int force_first; /* bit k set: that clusterel's free two-cut face k (local code) gets
                      Z-type, clear: S-type */
  tr_flip_guard guard; /* what the flips must not delete (NULL: nothing protected) */
  void *guard_ud;
  int no_flips;  /* skip the general flips only (Swap32 still runs) */
  int no_cavity; /* skip the cavity retriangulation (cavity.h) */
  const uint32_t *hint; /* NULL, or per facet index a tet that had the facet as a face
                           when the stage began (tr_mesh_find_faces; TR_NONE: it had
                           none). Checked before use: a later flip may have replaced it. */
} tr_facet_opts;

/* Counters per decision, for tests and reports. */
typedef struct tr_facet_detail {
  uint64_t by_type[5];                /* crossing clusterels decomposed, by TR_*_EDG */
  uint64_t thr_case[TR_NUM_THR_EDG];  /* Table 11 cases used (tr_thr_edg_cases order) */
  uint64_t fou_case[TR_NUM_FOU_EDG];  /* Table 12 cases used (tr_fou_edg_cases order) */
  uint64_t two_s, two_z;              /* Table 6 II-S / II-Z used for TWO_EDG */
  uint64_t swap32;                    /* facets recovered by Swap32 */
  uint64_t steiner;                   /* points on facets */
  uint64_t h_points;                  /* extra points H */
  uint64_t by_flips;                  /* facets recovered by general flips */
  tr_facet_flip_stats flips;          /* the flips themselves */
  tr_cavity_stats cavity;             /* cavity retriangulation (cavity.h) */
} tr_facet_detail;

enum { TR_FACET_PRESENT = 0, TR_FACET_BY_SWAP32 = 1, TR_FACET_BY_CLUSTER = 2,
       TR_FACET_BY_FLIPS = 3, TR_FACET_BY_CAVITY = 4 };

/* Recovers input triangle number idx = (e, f, g) (idx only names it in messages).
 * *outcome = TR_FACET_*. opt may be NULL. d is added to (may be NULL). If faces != NULL,
 * F's faces afterwards are appended to it as tr_facet_faces does.
 * TR_ERR_UNSUPPORTED for a degenerate triangle (repeated or collinear corners). */
tr_status tr_recover_facet(struct tr_mesh *m, uint32_t idx, uint32_t e, uint32_t f, uint32_t g,
                           const tr_facet_opts *opt, tr_facet_detail *d, int *outcome,
                           tr_u32buf *faces);

/* The presence test above. *present = 1 iff F is the union of mesh faces; then, if
 * faces != NULL, the faces are appended to it (3 ids each, right-hand normal in the
 * direction of efg's, rotated to start at their smallest id, sorted). */
tr_status tr_facet_faces(struct tr_mesh *m, uint32_t idx, uint32_t e, uint32_t f, uint32_t g,
                         int *present, tr_u32buf *faces);

struct tr_clusterel;
/* The same on an already collected Cluster(F); area_check = 0 skips the exact area sum
 * (the boundary-closure argument alone; tr_recover_facet uses that for facets that were
 * already present, and always checks the area after it changed the mesh). */
tr_status tr_facet_faces_of_cluster(struct tr_mesh *m, uint32_t idx, uint32_t e, uint32_t f,
                                    uint32_t g, const struct tr_clusterel *cl, uint32_t ncl,
                                    int area_check, int *present, tr_u32buf *faces);

#endif
