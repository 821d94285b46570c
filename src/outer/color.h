/* Removal of outer tets by coloring, and region numbering (the seed paper's "Removal of
 * outer elements", with the FLAGE labels of flage.h as seeds).
 *
 * Rule. The constraint faces are the recovered sub-faces. The tets (ghosts included) are
 * split into components that are connected across non-constraint faces. A component that
 * holds a ghost tet touches the outside of the convex hull: OUTER. Any other component is
 * INNER iff at least one of its tets, seen from an adjacent sub-face oriented like its
 * input triangle (outward), is labelled INNER by FLAGE. Why "at least one" and not a
 * majority: a component bounded by an outer shell and by an internal facet (multi-region
 * input) gets OUTER votes from the internal facet's wrong side but INNER votes from its
 * own part of the outer shell, and it is inside; a component whose every adjacent
 * sub-face votes OUTER (e.g. the inside of a shell oriented inward, i.e. a cavity) is a
 * hole. Limits: a component enclosed only by internal facets that all happen to be
 * oriented away from it is classified OUTER (the input gives no outward direction for
 * it); tr_plc_validate orients a nested closed shell outward when it is an inclusion
 * (nested regions) and into itself when it is a cavity (src/input/nesting.c). Hole and
 * region points are applied afterwards (points.h).
 *
 * Regions: the INNER components get ids 1..k ordered by their lexicographically
 * smallest tet (sorted vertex ids), which does not depend on slot layout. */
#ifndef TR_OUTER_COLOR_H
#define TR_OUTER_COLOR_H

#include "mesh/mesh.h"
#include "recover_facets/recover_facets.h"

/* Sets TR_TF_OUTER on every outer tet (ghosts included), enables m->region and writes
 * 1..k into the inner tets (0 into outer ones). keep_hull != 0: every non-ghost
 * component is inner (open surfaces meshed within their convex hull). sides (may be
 * NULL; tr_input_side_domains of src/input/validate.h, per input triangle sub->tri[j]):
 * a component is inner iff the side of an adjacent sub-face it lies on is in the domain
 * (votes must agree, else TR_ERR_INTERNAL); this replaces the FLAGE vote rule above for
 * inputs with internal facets or cracks, and has none of its limits. *nregions = k.
 * TR_ERR_INTERNAL if a sub-face is not a face of the mesh. */
tr_status tr_outer_color(struct tr_mesh *m, const tr_subfaces *sub, int keep_hull,
                         const uint8_t *sides, uint32_t *nregions);
/* The same, and subtet[j] (sub->n entries, may be NULL) = the first real tet in slot
 * order that has sub-face j as a face, what tr_mesh_find_faces would answer: compaction
 * starts from it (tr_compact_in) instead of a second pass over every tet. hint (may be
 * NULL; nhint entries, nhint <= sub->n): hint[j] a tet that may have sub-face j as a
 * face (tr_recover_facets_ex's hint_out), checked; any value gives the same answer. */
tr_status tr_outer_color_ex(struct tr_mesh *m, const tr_subfaces *sub, int keep_hull,
                            const uint8_t *sides, uint32_t *nregions, uint32_t *subtet,
                            const uint32_t *hint, uint32_t nhint);

#endif
