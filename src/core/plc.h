/* The input piecewise linear complex after reading: points, triangles (polygons already
 * triangulated in their plane), optional segments. Readers fill it; input/ validates it;
 * the pipeline consumes it. */
#ifndef TR_CORE_PLC_H
#define TR_CORE_PLC_H

#include <stdint.h>

#include "tetrec.h"
#include "qpoint.h"

/* How many fanned polygons tr_plc.fan_notes names. */
#define TR_PLC_FAN_NOTES 10

/* Values of tr_plc.hole_cavity. */
enum { TR_HOLE_EMPTIED = 1, TR_HOLE_IN_CAVITY = 2 };

struct tr_plc {
  uint32_t npoints;
  double *xyz;           /* 3 * npoints */
  uint32_t ntris;
  uint32_t *tris;        /* 3 * ntris, 0-based */
  int32_t *tri_marker;   /* ntris boundary markers (0 when the format has none) */
  uint32_t *tri_source;  /* ntris: index of the input element (polygon / facet) each
                            triangle came from, for messages; NULL = identity */
  uint32_t nsegs;
  uint32_t *segs;        /* 2 * nsegs, input segments not on any triangle (may be 0) */
  uint32_t ntets;        /* only Medit/TetGen volume inputs: tets read (for `check`) */
  uint32_t *tets;        /* 4 * ntets */
  /* Volume hole points and region points (tr_plc_add_hole / tr_plc_add_region, the hole
   * and region sections of .poly / .smesh). They are coordinates, not point indices, so
   * tr_plc_set keeps them. A hole point empties the cell of the domain it lies in; a
   * region point gives its cell an attribute (src/outer/points.c) and a maximum tet
   * volume, stored for refinement (not implemented: a positive one is warned about). */
  uint32_t nholes;
  double *holes;         /* 3 * nholes */
  uint32_t nregions;
  double *region_xyz;    /* 3 * nregions */
  int32_t *region_attr;  /* nregions */
  double *region_maxvol; /* nregions, <= 0: no constraint */
  uint32_t ncavities, ninclusions; /* nested shells by kind, from tr_plc_validate */
  uint8_t *hole_cavity;  /* NULL or nholes, from tr_plc_validate: TR_HOLE_EMPTIED = the
                            hole point emptied a cell of the domain (a nested shell made a
                            cavity, or a cell of the cell analysis); TR_HOLE_IN_CAVITY = it
                            lies in a cavity the surface leaves empty anyway; either way it
                            lies outside by design. 0: outside every shell, or in the
                            domain (the outer stage tells which) */
  char *source;          /* file name for messages, or NULL */
  char *report;          /* repairs made by tr_plc_validate, one per line, or NULL */
  double validate_seconds[3]; /* the last tr_plc_validate: whole, of which
                                 self-intersection, and nesting (shells, cells) */
  double *vsize;         /* NULL, or npoints target edge lengths (tr_options.sizing, the
                            command's --sizing), >= 0, 0 none: carried through the merges of
                            tr_plc_validate (the smaller of duplicates' values) */
  /* Exact points (--resolve's new vertices that are no doubles, src/resolve/surface.c):
   * NULL, or npoints entries, the exact point of point i or NULL when it is the double
   * xyz[3i..]; an exact point's xyz is its nearest double. They are the last nxq points,
   * so the Delaunay stage triangulates the doubles before it and inserts them after
   * (src/delaunay/qinsert.c). Stages that read a triangle's corners read tr_plc_point. */
  tr_qpoint **xq;
  uint32_t nxq;
  uint8_t *tri_inner;    /* with xq: NULL, or ntris, 1 for an internal facet (--resolve-
                            internal: the solid on both sides), else the solid lies behind
                            the triangle; what the cell analysis finds in doubles otherwise */
  /* Polygons that cannot be triangulated in their plane (self-overlapping, or all
   * corners collinear). read_fans, set before reading: such a polygon of one loop and no
   * hole points becomes the fan of its loop from its first corner, for --resolve, whose
   * winding number counts any surface that the loop bounds (a planar self-overlapping
   * loop covers each point of its plane as often as its fan does), instead of an error.
   * nfans of them were fanned, the input facets fan_facet[0..nfans-1] in increasing
   * order; fan_notes: the first TR_PLC_FAN_NOTES of the reasons, one per line (NULL if
   * none). */
  uint8_t read_fans;
  uint32_t nfans;
  uint32_t *fan_facet;
  char *fan_notes;
  uint8_t validated;     /* 1 + allow_open of the last successful tr_plc_validate, 0 if
                            none: the struct is opaque and every setter builds a new one,
                            so a validated PLC stays valid and the pipeline skips a second
                            validation (its repairs are idempotent anyway) */
};

/* Point v as an exact point (its rational when it has one, else its double). */
static inline tr_point tr_plc_point(const struct tr_plc *plc, uint32_t v)
{
  if (plc->xq && plc->xq[v])
    return tr_pt_q(plc->xq[v]);
  return tr_pt_d(plc->xyz + 3 * (size_t)v);
}

/* dst->xq = copies of src's exact points, and its tri_inner (dst has src's points and
 * triangles). */
tr_status tr_plc_copy_exact(struct tr_plc *dst, const struct tr_plc *src);

/* *out = a new PLC with in's points, triangles, markers, sources, segments, exact points,
 * hole and region points, sizes, file name and validation state (not its report). */
tr_status tr_plc_copy(const struct tr_plc *in, struct tr_plc **out);

/* Frees the arrays and zeroes the struct (not the struct itself). */
void tr_plc_clear(struct tr_plc *plc);

/* Appends src's hole and region points to dst's; copies its counts of nested shells. */
tr_status tr_plc_copy_points(struct tr_plc *dst, const struct tr_plc *src);

#endif
