/* Input validation of a PLC (tr_plc_validate in include/tetrec.h). Split by concern:
 * validate.c   duplicates, zero area, manifoldness, orientation
 * selfint.c    exact detection of improperly intersecting triangles
 * report.c     the repair log kept in plc->report */
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

/* Fails with TR_ERR_SELF_INTERSECT naming the first pair (lowest triangle numbers in
 * sweep order) of triangles that meet other than in a shared vertex or shared edge.
 * tri_orig (may be NULL) maps triangles to the numbers used in messages. */
tr_status tr_input_self_intersections(const struct tr_plc *plc, const uint32_t *tri_orig);

/* out = 6 * the signed volume enclosed by the triangles (sum of det[a; b; c]), exact. */
tr_status tr_input_volume6(const struct tr_plc *plc, mpq_t out);

/* cavity[c] = 1 iff closed shell c lies inside an odd number of other closed shells.
 * Shell c's triangles are order[start[c] .. start[c+1]). */
tr_status tr_input_shell_cavities(const struct tr_plc *plc, const uint32_t *order,
                                  const uint32_t *start, const char *closed, uint32_t ncomp,
                                  char *cavity);

/* Stable merge sort of ids by cmp(ctx, a, b) (<0, 0, >0). */
tr_status tr_sort_ids(uint32_t *ids, uint32_t n, int (*cmp)(const void *, uint32_t, uint32_t),
                      const void *ctx);

#endif
