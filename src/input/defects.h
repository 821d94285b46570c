/* Every defect of a surface at once (defects.c), where tr_plc_validate stops at the
 * first: what `tetrec check-surface` lists and what `tetrec resolve` tests its rounded
 * surface for (src/cli/check_surface.c, src/resolve/snap.c). */
#ifndef TR_INPUT_DEFECTS_H
#define TR_INPUT_DEFECTS_H

#include <stddef.h>
#include <stdint.h>

#include "../core/plc.h"
#include "../core/status.h"

/* Triangle numbers are the PLC's; vertex numbers in edges are representatives (below). */
typedef struct tr_surface_defects {
  uint32_t nzero, *zero;   /* zero-area triangles, increasing */
  uint32_t ndup, *dup;     /* 2 per duplicate: (copy, first copy); grouped by vertex set
                              in increasing order of its sorted triple, each group's
                              copies increasing */
  uint32_t nedges;         /* edges of one triangle or of three or more, in increasing
                              (a, b) order */
  uint32_t *edge;          /* 2 per edge: a < b */
  uint32_t *edge_start;    /* nedges + 1 offsets: edge k's triangles, increasing, are */
  uint32_t *edge_tri;      /* edge_tri[edge_start[k] .. edge_start[k + 1]) */
  uint32_t nopen, nnonmanifold; /* of those edges, with one triangle / three or more */
  size_t npairs;           /* improper pairs (x, y), x < y, in increasing order: */
  uint32_t *pairs;         /* pairs[2i], pairs[2i + 1] */
} tr_surface_defects;

/* *d = the defects of plc's triangles (segments and points on none play no part).
 * Vertices with exactly equal coordinates are one vertex, the least index of them, so
 * that coincident copies are read neither as open edges nor as intersections. Then, each
 * step on what the one before left:
 *  - zero-area triangles (exact: collinear or repeated corners), left out of the rest;
 *  - duplicate triangles, the same three vertices in either orientation: only the first
 *    copy goes on, so that a repeated triangle is not also read as non-manifold edges;
 *  - the edge census: open and non-manifold edges;
 *  - every pair of triangles that meet other than in a shared vertex or a shared edge
 *    (tr_input_self_intersection_pairs).
 * TR_OK whatever is found; free with tr_surface_defects_free (also after a failure). */
tr_status tr_surface_defects_find(const struct tr_plc *plc, tr_surface_defects *d);
void tr_surface_defects_free(tr_surface_defects *d);

#endif
