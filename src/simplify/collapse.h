/* Edge collapses inside the two-sided envelope (collapse.c). */
#ifndef TR_SIMPLIFY_COLLAPSE_H
#define TR_SIMPLIFY_COLLAPSE_H

#include <stdint.h>

#include "core/plc.h"

/* Triangles of plc (validated) whose smallest angle is under this are the ones worked
 * on, worst first. */
#define TR_SIMP_TARGET_ANGLE 30.0

/* Collapses edges of plc's surface (vertices keep their input doubles: a removed vertex
 * goes to a neighbour) within d of the input both ways. frozen[v] != 0: v stays (and
 * stays where it is). On return *tris / *ntris are the surviving triangles (3 ids of
 * plc's points each), *tri_of[i] the input triangle each came from (its marker and
 * source), into[v] the vertex v was collapsed into (v itself when it stays), all
 * malloc'ed; *ncollapse counts the collapses. */
tr_status tr_simp_collapse(const struct tr_plc *plc, double d, const uint8_t *frozen,
                           uint32_t **tris, uint32_t **tri_of, uint32_t *ntris,
                           uint32_t *into, uint64_t *ncollapse);

#endif
