/* The simplification proper (improve.c): the operations of edit.h applied to the
 * triangles under TR_SIMP_TARGET_ANGLE, worst first, inside the two-sided envelope. */
#ifndef TR_SIMPLIFY_IMPROVE_H
#define TR_SIMPLIFY_IMPROVE_H

#include <stdint.h>

#include "core/plc.h"

/* Triangles of plc (validated) whose smallest angle is under this are the ones worked
 * on, worst first. */
#define TR_SIMP_TARGET_ANGLE 30.0
/* largest angle between the normals of the two triangles a flip makes (flip.c) */
#define TR_SIMP_FLIP_FOLD_DEG 5.0

typedef struct tr_simp_result {
  uint32_t *tris, *tri_of, ntris; /* surviving triangles (3 point ids each) and the
                                   * input triangle each came from (marker, source) */
  uint64_t collapses, flips;
} tr_simp_result;

/* Improves plc's surface within d of the input both ways: edge collapses (a removed
 * point goes to a neighbour: into[v] is where v went, v itself when it stays; every
 * point keeps its input doubles) and flips. Points with frozen[v] != 0 stay and no
 * operation touches them. *res is filled (malloc'ed; tr_simp_result_free). */
tr_status tr_simp_improve(const struct tr_plc *plc, double d, const uint8_t *frozen,
                          uint32_t *into, tr_simp_result *res);
void tr_simp_result_free(tr_simp_result *res);

#endif
