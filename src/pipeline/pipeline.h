/* The `tetrec mesh` pipeline (tr_mesh_plc in include/tetrec.h), split by concern:
 *   mesh_plc.c  orchestration, timing, statistics
 *   stages.c    input edges, the two recovery stages (or the exact "nothing missing"
 *               fallback when the library is built without them)
 *   compact.c   the output mesh: inner tets only, dense deterministic numbering
 * Smoothing (src/smooth, on by default, `--no-smooth` / tr_options.smooth = 0 turns it
 * off) replaces input edges interior to a coplanar region of one marker by Delaunay
 * diagonals: the surface as a point set is unchanged, but the recovered edges are those of
 * the smoothed PLC (returned by tr_mesh_plc_ex), not necessarily the caller's. */
#ifndef TR_PIPELINE_H
#define TR_PIPELINE_H

#include <stdint.h>

#include "core/plc.h"
#include "mesh/mesh.h"
#include "recover_edges/recover_edges.h"
#include "recover_facets/recover_facets.h"

/* tr_mesh_plc, and *used (may be NULL) receives the PLC actually meshed: validated
 * (duplicates merged, orientation repaired) and smoothed. The output mesh's first
 * vertices are used's points that appear in a tet, in order. The caller destroys it. */
tr_status tr_mesh_plc_ex(const tr_plc *plc, const tr_options *opt, tr_mesh **out,
                         tr_stats *stats, tr_plc **used);

/* tr_mesh_plc_ex with flags (TR_PIPE_*). The output's Steiner points keep their exact
 * positions (vq); their doubles (xyz, what the writers print) are the nearest doubles,
 * moved where needed so that every tet is strictly positive in doubles
 * (src/output/round.h; stats->rounding_repairs counts the points off their nearest
 * double). When no such doubles are found the call fails with TR_ERR_INVALID_MESH. With
 * TR_PIPE_KEEP_EXACT there is no repair: the doubles are the nearest ones (or the one
 * next to it that refinement admitted a point at), and when that leaves a tet flat or
 * inverted a warning is printed (the exact points are valid). */
enum {
  TR_PIPE_KEEP_EXACT = 1u << 0, /* the caller writes exact coordinates (--exact .node;
                                   set by tr_options.keep_exact) */
  TR_PIPE_KEEP_STEINER = 1u << 1, /* the recovery's Steiner points as they are, no
                                     suppression (src/suppress; --keep-steiner) */
  TR_PIPE_NO_QUALITY = 1u << 2 /* the caller shows no quality figures (the CLI without
                                  --stats): unless a note about a dihedral target or
                                  refinement needs them, the stats' dihedral, radius-edge
                                  and thin-input fields are not measured and stay 0 */
};
tr_status tr_mesh_plc_flags(const tr_plc *plc, const tr_options *opt, tr_mesh **out,
                            tr_stats *stats, tr_plc **used, unsigned flags);

/* The unique undirected edges of the triangles and segments, a < b, sorted; *nopen =
 * number of edges with exactly one triangle, *nmulti = with three or more (segments do
 * not count). */
tr_status tr_pipeline_edges(const struct tr_plc *plc, uint32_t **edges, uint32_t *n,
                            uint32_t *nopen, uint32_t *nmulti);

/* Edge then facet recovery on m (vertex ids = plc point ids). Fills sub, the stats rows
 * and *vkind, *vindex (tr_pipeline_origins; NULL when the build has no recovery stages,
 * so every vertex is an input vertex); secs[0], secs[1] = time of each stage. Reports
 * both stages to opt->progress (TR_ERR_CANCELLED when it asks to stop). opt->recovery
 * picks the steps (1: the paper's only; 2: no facet flips). subhint (may be NULL):
 * *subhint = the sub-faces' tet hints for tr_outer_color_ex (tr_recover_facets_ex's
 * hint_out; NULL: none), freed by the caller. */
tr_status tr_pipeline_recover(struct tr_mesh *m, const struct tr_plc *plc,
                              const uint32_t *edges, uint32_t ne, tr_subfaces *sub,
                              tr_stats *stats, double secs[2], const tr_options *opt,
                              uint8_t **vkind, uint32_t **vindex, uint32_t **subhint);
/* opt->progress(user, tr_stage_name(stage), fraction) if set; TR_ERR_CANCELLED with a
 * message naming the stage when it returns non-zero. */
tr_status tr_pipeline_progress(const tr_options *opt, int stage, double fraction);

/* The origin of every vertex of m (enum tr_vertex_origin, indices in m's numbering and
 * the PLC's): input points are the first npoints vertices, a Steiner point on an edge
 * chain is on that input edge, one on a sub-face of triangle k (and on no chain) is on
 * triangle k, any other is interior. malloc'ed arrays of m->nv entries. */
tr_status tr_pipeline_origins(const struct tr_mesh *m, uint32_t npoints,
                              const tr_edge_chains *chains, const tr_subfaces *sub,
                              uint8_t **kind, uint32_t **index);
/* The origins of the vertices nv0.. that a stage after the recovery added (quality
 * refinement): on a sub-face, on an edge of its input triangle (decided exactly; the
 * index into edges, ne sorted unique pairs) or inside it; else interior. *kind and
 * *index grow to m->nv entries; nothing when *kind is NULL. */
tr_status tr_pipeline_origins_extend(const struct tr_mesh *m, const struct tr_plc *plc,
                                     const tr_subfaces *sub, const uint32_t *edges,
                                     uint32_t ne, uint32_t nv0, uint8_t **kind,
                                     uint32_t **index);
/* Frees sub's arrays (works whether or not the facet stage is built). */
void tr_pipeline_subfaces_free(tr_subfaces *sub);

/* What the compact mesh carries besides its tets (its tr_mesh_attrs): the sub-faces
 * with their triangles' markers, the vertex origins (may be NULL: all input) and the
 * input edges, all in m's numbering; compaction renumbers them. */
typedef struct tr_compact_in {
  const tr_subfaces *sub;
  const int32_t *tri_marker; /* per input triangle, may be NULL (all 0) */
  const uint8_t *vkind;
  const uint32_t *vindex;
  const uint32_t *edges;
  uint32_t nedges;
  /* NULL, or nsubtet candidates: subtet[f] a tet that had sub-face f when the outer
   * removal ran (tr_outer_color_ex); each is checked, and the tets are searched again
   * when one no longer has its face or sub changed size */
  const uint32_t *subtet;
  uint32_t nsubtet;
} tr_compact_in;
/* A new store holding the non-outer real tets of m, vertices renumbered densely in
 * increasing old id (input points first, Steiner points in creation order), tets in slot
 * order, neighbours and regions kept, and attrs built from in (NULL: none). Steiner
 * points are moved out of m. */
tr_status tr_pipeline_compact(struct tr_mesh *m, const tr_compact_in *in,
                              struct tr_mesh **out);
/* Gives the Steiner points tr_pipeline_compact moved from m into res back to m (m not
 * changed since), so that m can be edited and compacted again; res keeps none. */
tr_status tr_pipeline_uncompact_steiner(struct tr_mesh *m, struct tr_mesh *res);

/* Boundary Steiner points taken off the surface after outer removal (src/suppress) unless
 * flags has TR_PIPE_KEEP_STEINER, the Steiner counts by location into stats; under
 * opt->keep_surface every one must go. */
tr_status tr_pipeline_suppress(struct tr_mesh *m, tr_subfaces *sub, const struct tr_plc *plc,
                               const tr_options *opt, int keep_hull, unsigned flags,
                               tr_stats *stats);

/* Monotonic clock in seconds. */
double tr_pipeline_now(void);

#endif
