/* Input validation of a PLC (tr_plc_validate in include/tetrec.h). Split by concern:
 * validate.c   duplicates, zero area, manifoldness, orientation
 * selfint.c    exact detection of improperly intersecting triangles
 * nesting.c    which closed shells are cavities (inputs where every edge has 2 triangles)
 * cells.c      orientation and openness of any other surface, by its cells
 * report.c     the repair log kept in plc->report
 * defects.c    every defect at once, where validation stops at the first (defects.h) */
#ifndef TR_INPUT_VALIDATE_H
#define TR_INPUT_VALIDATE_H

#include <gmp.h>
#include <stdint.h>

#include "../core/plc.h"
#include "../core/status.h"

typedef struct tr_report {
  char *s;
  size_t n, cap;
  int lines[8];  /* lines written per kind, to cap the log */
  uint32_t dropped[8];
} tr_report;

enum { TR_REP_DUPV, TR_REP_DUPT, TR_REP_FLIP, TR_REP_SHELL };

/* Appends a line of kind `kind` (at most 10 per kind are kept; the rest are counted). */
void tr_report_add(tr_report *r, int kind, const char *fmt, ...) TR_PRINTF(3, 4);
/* Adds the "... and N more" lines and returns the text (owned by the caller). */
char *tr_report_finish(tr_report *r);

/* Fails with TR_ERR_SELF_INTERSECT naming the least pair (x, y), x < y, of triangles
 * that meet other than in a shared vertex or shared edge.
 * tri_orig (may be NULL) maps triangles to the numbers used in messages. */
tr_status tr_input_self_intersections(const struct tr_plc *plc, const uint32_t *tri_orig);
/* The same with a chosen broad phase, for the tests that compare them: AUTO is the grid,
 * or the sweep when the grid would be too large; GRID forces the grid; ALL_PAIRS tests
 * every pair whose boxes meet; REFERENCE too, each pair by the general narrow phase
 * alone (every side by orient3d, six segment-triangle classifications for pairs across
 * each other's planes, no interval test on the planes' line, selfint_line.h), the oracle
 * of the shortcuts. All give the same answer. */
enum { TR_SELFINT_AUTO, TR_SELFINT_GRID, TR_SELFINT_SWEEP, TR_SELFINT_ALL_PAIRS,
       TR_SELFINT_REFERENCE };
tr_status tr_input_self_intersections_by(const struct tr_plc *plc, const uint32_t *tri_orig,
                                         int method);
/* Collect-all variant (tetrec check-surface): every improper pair (x, y), x < y, as
 * (*pairs)[2i], (*pairs)[2i+1], *npairs pairs in increasing (x, y) order (free *pairs).
 * The same pairs for every method; TR_OK whether there are any or not. */
tr_status tr_input_self_intersection_pairs(const struct tr_plc *plc, int method,
                                           uint32_t **pairs, size_t *npairs);

/* out = 6 * the signed volume enclosed by the triangles (sum of det[a; b; c]), exact. */
tr_status tr_input_volume6(const struct tr_plc *plc, mpq_t out);

/* The same over the triangles tris[0..n). */
tr_status tr_input_volume6_of(const struct tr_plc *plc, const uint32_t *tris, uint32_t n,
                              mpq_t out);

/* out = 6 * the volume of the domain of any validated surface (internal facets, cracks,
 * cavities, several regions): the sum over the triangles that separate the domain from
 * the outside, oriented outward by the cell analysis of cells.c. For a union of closed
 * 2-manifold shells it equals tr_input_volume6. The surface must have no improper
 * intersections (tr_plc_validate checked). */
tr_status tr_input_domain_volume6(const struct tr_plc *plc, mpq_t out);

/* sides[t] for each triangle of a validated surface, in its current orientation: bit 0 =
 * the side its right-hand normal points to lies in the domain, bit 1 = the other side
 * does (0: outside on both sides, e.g. a facet between two cavities; 3: an internal
 * facet or a crack). What the outer coloring needs to decide a component bounded only
 * by internal facets. */
tr_status tr_input_side_domains(const struct tr_plc *plc, uint8_t *sides);

/* q = the centroid of triangle t of plc, exactly (q initialised). Ray casts start there:
 * unlike a vertex, it cannot lie on another triangle that does not cross t. */
struct tr_qpoint;
void tr_input_tri_centroid(const struct tr_plc *plc, uint32_t t, struct tr_qpoint *q);

/* Nesting of the closed shells (nesting.c). cavity[c] = 1 iff closed shell c is a cavity:
 * it lies directly inside a shell whose inside is in the domain, and either a hole point
 * of plc lies in it (and in none of the shells nested in it), or given[c] <= 0 (as read,
 * the majority of its triangles faced into it: -1; a tie: 0, the rule before inclusions
 * existed) and no region point of plc lies in it so. Any other shell nested in a domain
 * is an inclusion: its inside is a region of its own (plc->hole_cavity marks the hole
 * points that made a cavity). A shell at top level or directly inside a cavity bounds a
 * body.
 * Shell c's triangles are order[start[c] .. start[c+1]), consistently oriented; given[c]
 * is the sign of its enclosed volume as given. Each nested shell's kind is reported in
 * rep (tnum: triangle numbers for messages); *ncav / *nincl count them. Near-linear:
 * points are tested only against the shells whose box holds them. */
tr_status tr_input_shell_cavities(struct tr_plc *plc, const uint32_t *order,
                                  const uint32_t *start, const char *closed, uint32_t ncomp,
                                  const int8_t *given, const uint32_t *tnum, tr_report *rep,
                                  char *cavity, uint32_t *ncav, uint32_t *nincl);

/* Orients a surface with free edges (1 triangle) or edges of 3+ triangles by its cells
 * (cells.c): each triangle between the domain and the outside faces the outside;
 * internal facets and cracks keep their orientation. TR_ERR_OPEN if a triangle with a
 * free edge lies outside the domain, unless allow_open. Needs a surface without
 * improper intersections. flipped[t] is toggled for every triangle turned. */
tr_status tr_input_orient_cells(struct tr_plc *plc, const uint32_t *tnum, const uint32_t *orig,
                                int allow_open, char *flipped);

/* Points a and b of the double array ctx (3 per point) in lexicographic order, for
 * tr_sort_ids: -0.0 == 0.0, the same point, as validation merges them. */
int tr_cmp_point(const void *ctx, uint32_t a, uint32_t b);

/* Stable merge sort of ids by cmp(ctx, a, b) (<0, 0, >0). */
tr_status tr_sort_ids(uint32_t *ids, uint32_t n, int (*cmp)(const void *, uint32_t, uint32_t),
                      const void *ctx);

#endif
