/* What every reader produces before triangulation: points, facets made of loops
 * (polygons; the first loop of a facet is its outer boundary unless hole points say
 * otherwise), hole points per facet (TetGen .poly), and tets for volume formats.
 * tr_soup_to_plc() triangulates the polygons exactly and fills a tr_plc. Keeping this
 * step shared means every format gets the same polygon handling and messages. */
#ifndef TR_IO_SOUP_H
#define TR_IO_SOUP_H

#include <stdint.h>

#include "../core/plc.h"
#include "../core/status.h"
#include "lex.h"

/* The largest element count any array may reach; indices stay below UINT32_MAX so that
 * UINT32_MAX can keep meaning "none" elsewhere. */
#define TR_IO_MAX_COUNT (UINT32_MAX / 8u)

typedef struct tr_u32vec {
  uint32_t *a;
  uint32_t n, cap;
} tr_u32vec;

tr_status tr_u32vec_push(tr_u32vec *v, uint32_t x);
tr_status tr_u32vec_reserve(tr_u32vec *v, uint32_t n);
void tr_u32vec_free(tr_u32vec *v);

typedef struct tr_soup {
  const char *name;
  uint32_t npoints, cap_points;
  double *xyz;
  tr_u32vec facet_loop;   /* first loop of each facet */
  tr_u32vec facet_hole;   /* first hole point of each facet */
  tr_u32vec facet_line;   /* source line of each facet, for messages */
  tr_u32vec facet_marker; /* boundary marker (int32 stored as uint32) */
  tr_u32vec loop_first;   /* first index of each loop in idx */
  tr_u32vec idx;          /* 0-based vertex indices of all loops */
  uint32_t nholes, cap_holes;
  double *holes;          /* 3 per hole point */
  tr_u32vec tets;         /* 4 per tet */
} tr_soup;

void tr_soup_init(tr_soup *s, const char *name);
void tr_soup_free(tr_soup *s);
tr_status tr_soup_reserve_points(tr_soup *s, uint32_t n);
tr_status tr_soup_add_point(tr_soup *s, const double p[3]);
tr_status tr_soup_begin_facet(tr_soup *s, int32_t marker, unsigned long line);
tr_status tr_soup_begin_loop(tr_soup *s);
tr_status tr_soup_add_index(tr_soup *s, uint32_t v);
tr_status tr_soup_add_hole(tr_soup *s, const double p[3]);
static inline uint32_t tr_soup_nfacets(const tr_soup *s) { return s->facet_loop.n; }

/* Checks indices, triangulates every facet, and moves the result into plc (which must
 * be zeroed or cleared). plc->tri_source[t] = the facet (0-based) triangle t came from. */
tr_status tr_soup_to_plc(tr_soup *s, struct tr_plc *plc);

/* The whole of a line-oriented text reader (OFF, OBJ, Medit): tokenise buf with the given
 * comment character, let `parse` fill a soup, then triangulate it into plc. */
typedef tr_status (*tr_soup_parse_fn)(tr_lex *lx, tr_soup *s);
tr_status tr_soup_read_text(const char *buf, size_t len, const char *name, char comment,
                            tr_soup_parse_fn parse, struct tr_plc *plc);

/* Exact triangulation of one planar facet given as loops of vertex indices into xyz.
 * Loops after the first are holes if a hole point lies inside them, or if there are no
 * hole points and they lie inside the first loop (the OFF/OBJ convention has no holes,
 * only .poly uses hole points). Triangles keep the orientation of the first loop and are
 * appended to out (3 indices each). `what` names the facet in messages. The ear-clipped
 * triangulation is then flipped towards max-min angle (polyflip.h): on a non-planar
 * polygon that chooses which surface the polygon stands for, as any triangulation does. */
tr_status tr_triangulate_facet(const double *xyz, const uint32_t *idx, const uint32_t *loop_first,
                               uint32_t nloops, uint32_t nidx, const double *holes,
                               uint32_t nholes, tr_u32vec *out, const char *what);

#endif
