/* Suppression of Steiner points on the boundary (issue 16), after outer removal.
 *
 * Edge and facet recovery split input edges and triangles; a user who shares the surface
 * mesh between volumes needs it unsplit (TetGen's -Y). For a Steiner point p whose star
 * lies in one region and whose only constraint faces are boundary sub-faces (so p is on
 * an input edge or triangle of the domain's boundary, not on an internal facet or a
 * crack):
 *   1. un-split: in each input triangle, the sub-faces around p form a planar fan;
 *      its polygon is triangulated without p by ear clipping (exact orient2d in the
 *      triangle's plane). With p on an input edge and one sub-face on each side, the two
 *      sub-faces merge back into one.
 *   2. the star of p is then a polyhedral ball bounded by its link faces and the merged
 *      triangles. Full removal: a boundary vertex v that sees every boundary face not
 *      incident to it strictly positively (exact orient3d of each new tet) replaces the
 *      star by its cone: p disappears.
 *   3. relocation (if allowed): a double point q that sees every boundary face strictly
 *      positively replaces p: p becomes an interior Steiner point whose coordinates are
 *      doubles, so rounding never moves it. Candidates, each checked exactly: p moved
 *      along the sum of the merged triangles' inner normals by steps halving down to
 *      p's resolution (for a step small enough this is in the kernel, since p sees every
 *      link face strictly and the sum points into each surface plane's inner side),
 *      points between p and the centroid of its link, projections into the kernel
 *      (relax), the star tets' centroids.
 * New tets must also be positive with every Steiner point at its nearest double (what
 * rounding can repair is the vertices' rounding, not the shape); under --keep-surface a
 * last try asks only the exact test and leaves the rest to the rounding repair.
 * Otherwise p stays. An interior point (TR_SUP_INTERIOR) whose star no vertex sees is
 * removed by the Delaunay retriangulation of its star, expanded across non-constraint
 * faces (starfill.c), else by flips that only delete simplices on p (flipout.c). No
 * tolerance decides anything.
 *
 * The outer tets are taken out of the working mesh first (their faces on the domain side
 * become mesh boundary, neighbour TR_NONE): they are discarded by compaction anyway and
 * keeping them would mean retriangulating the outside too. Sub-faces (sub) stay in the
 * format of recover_facets.h, sorted by input triangle then rotated vertex ids.
 *
 * Inputs with segments or meshed within their convex hull (allow_open) are left alone:
 * their sub-faces are internal constraints. */
#ifndef TR_SUPPRESS_H
#define TR_SUPPRESS_H

#include <stdint.h>

#include "core/plc.h"
#include "mesh/mesh.h"
#include "recover_facets/recover_facets.h"

enum {
  TR_SUP_REMOVE = 1u << 0,   /* try full removal */
  TR_SUP_RELOCATE = 1u << 1, /* try relocation into the interior */
  TR_SUP_REQUIRE = 1u << 2,  /* every boundary Steiner point must go (--keep-surface) */
  TR_SUP_CHECK = 1u << 3,    /* tests: the mesh validator and the exact conformity
                                validator after every change (closed PLCs only) */
  TR_SUP_INTERIOR = 1u << 4, /* full removal of interior Steiner points too (those the
                                recovery put inside and those relocated), last round: a
                                cone from a star vertex, else flips down to a 4-1 flip */
  TR_SUP_MERGE = 1u << 5     /* with TR_SUP_INTERIOR: after the removal rounds, two
                                neighbouring interior points that cannot go one by one
                                become one (merge.c) */
};
/* What the default mode runs. On CGAL's 84 sample models recovery adds 4,434 Steiner
 * points, all on input edges; full removal alone leaves 1,797 (on edges); removal, then
 * relocation of the rest, then removal again leaves 1,363, of which 4 on the surface;
 * with the removal of interior points in the last round 1,137 (4 on edges): fewer points
 * in all and far fewer on the surface, for 2% more CPU. An interior point no cone takes
 * out is then removed by flips (flipout.c): 509 left (4 on edges), the same CPU; a second
 * removal / relocation round and interior removal after it: 454 (1 on an edge), and
 * --keep-surface meshes all 84 (80 with three rounds); an interior point the flips
 * cannot remove moved into its kernel first, and the removal rounds repeated while they
 * remove something: 358 (none on the surface; 589 under --keep-surface). The star
 * retriangulation (starfill.c) before the flips and on the star they get stuck on: 339;
 * with edge recovery's deeper flips on short pipes (fewer points to remove): 315.
 * Merging the interior points left two into one after all that (merge.c, in a round of
 * its own, at doubles only): 278 (cheese 175 -> 142); under --keep-surface cheese 238
 * -> 190, turbine 82 -> 72, anchor 29 -> 28, rotor_small 21 -> 20. */
#define TR_SUP_DEFAULT (TR_SUP_REMOVE | TR_SUP_RELOCATE | TR_SUP_INTERIOR | TR_SUP_MERGE)

typedef struct tr_suppress_stats {
  uint64_t on_edges, on_facets, interior; /* Steiner points left, by where they lie */
  uint64_t removed, relocated;
} tr_suppress_stats;

/* m: the working mesh after tr_outer_color; sub: its sub-faces (updated); plc: the meshed
 * PLC (vertex ids = plc point ids). flags: TR_SUP_*; 0 only counts. With TR_SUP_REQUIRE a
 * boundary Steiner point that cannot be suppressed is TR_ERR_UNSUPPORTED naming the input
 * edge or triangle and the point. The counts are those of the Steiner points left in the
 * domain's tets. */
tr_status tr_suppress_steiner(struct tr_mesh *m, tr_subfaces *sub, const tr_plc *plc,
                              unsigned flags, tr_suppress_stats *st);

/* ---- steps, exposed for the unit tests ---- */
/* The plane of input triangle tri: *drop = the axis the exact 2D tests drop, *sign such
 * that sign * tr_orient2d_proj_p(a,b,c,drop) > 0 for the triangle itself. */
tr_status tr_sup_plane(const tr_plc *plc, uint32_t tri, int *drop, int *sign);
/* Triangulates the simple polygon poly[0..n) (counter-clockwise in that plane, every
 * vertex in it, 3 <= n <= TR_SUP_MAX_POLY) by ear clipping: out gets 3*(n-2) vertex ids,
 * each triangle counter-clockwise. An ear is strictly convex and holds no other polygon
 * vertex in its closed triangle. TR_ERR_INTERNAL if no ear is found (not simple). */
#define TR_SUP_MAX_POLY 64
tr_status tr_sup_triangulate(const struct tr_mesh *m, int drop, int sign, const uint32_t *poly,
                             uint32_t n, uint32_t *out);

#endif
