/* File readers and writers. One file per format; every reader has a from-memory entry
 * point (used by tr_io_read_file after loading the file, and by the fuzzers). The writers
 * are declared in write.h, the names of formats in format_name.h, the number formatting
 * in put_number.h; this header gathers them for the rest of tetrec.
 *
 * Readers fill a tr_plc (which must be zeroed or cleared first); on failure the plc is
 * left cleared and tr_last_error() says "file:line: what is wrong". `name` is the file
 * name used in messages. Polygons are triangulated exactly (see polytri.c). */
#ifndef TR_IO_IO_H
#define TR_IO_IO_H

#include <stddef.h>
#include <stdio.h>
#include <stdint.h>

#include "../core/plc.h"
#include "../core/status.h"
#include "qpoint.h"
#include "format_name.h"
#include "put_number.h"
#include "write.h"

tr_status tr_read_off_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc);
tr_status tr_read_stl_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc);
tr_status tr_read_obj_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc);
tr_status tr_read_ply_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc);
/* Medit .mesh: Vertices, Triangles (the surface input, with their refs as markers),
 * Tetrahedra (kept in plc->tets for `tetrec check`). */
tr_status tr_read_medit_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc);
/* Gmsh .msh 4.1 or 2.2, ASCII or binary (little-endian; a big-endian file is refused):
 * triangles (and quadrangles, as polygons) with the physical tag of their entity (4.1) or
 * their first tag (2.2) as marker, tetrahedra into plc->tets; points and lines are
 * skipped (triangle edges and corners carry no more geometry), any other element type is
 * an error (read_msh.c). */
tr_status tr_read_msh_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc);
/* Binary Medit .meshb, versions 1 to 4, little-endian: what tr_read_medit_buf reads from
 * the text form (read_meshb.c). */
tr_status tr_read_meshb_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc);

/* Exact reading of a TetGen .node buffer: *out = *npoints entries (free each with
 * tr_qpoint_clear + free, then the array), NULL for a point whose three coordinates are doubles, else its exact point;
 * *exact_file = the file starts with tetrec's "# tetrec exact rationals" line or has a
 * num/den coordinate. */
tr_status tr_read_node_exact_buf(const char *buf, size_t len, const char *name,
                                 tr_qpoint ***out, uint32_t *npoints, int *exact_file);

/* TetGen formats. .node alone gives points only. For .poly/.smesh, node_buf may hold the
 * companion .node file used when the .poly declares 0 points (NULL if none). */
enum tr_tetgen_kind { TR_TETGEN_NODE, TR_TETGEN_POLY, TR_TETGEN_SMESH, TR_TETGEN_ELE };
tr_status tr_read_tetgen_buf(enum tr_tetgen_kind kind, const char *buf, size_t len,
                             const char *name, const char *node_buf, size_t node_len,
                             const char *node_name, struct tr_plc *plc);
/* The same with `threads` threads for the point list of a .node file (and of the .node
 * next to a .poly/.smesh without points): the same points, read in parallel when the file
 * is large and every point is one line (read_tetgen.c). */
tr_status tr_read_tetgen_buf_threads(enum tr_tetgen_kind kind, const char *buf, size_t len,
                                     const char *name, const char *node_buf, size_t node_len,
                                     const char *node_name, struct tr_plc *plc, int threads);
/* .ele on top of already-read points: appends plc->tets. */
tr_status tr_read_ele_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc);

/* TetGen .mtr: one target edge length per point (read_mtr.c). npoints: the count the file
 * must announce (UINT32_MAX: any); *out = *count values (malloc'ed), each >= 0. A count
 * that does not match, a negative value or NaN/Inf is TR_ERR_INPUT, a malformed file
 * TR_ERR_PARSE, more than one value per point TR_ERR_UNSUPPORTED, all with file:line. */
tr_status tr_read_mtr_buf(const char *buf, size_t len, const char *name, uint32_t npoints,
                          double **out, uint32_t *count);
tr_status tr_read_mtr_file(const char *path, uint32_t npoints, double **out);

/* Loads a whole file (binary-safe, NUL-terminated for convenience). */
tr_status tr_io_load(const char *path, char **buf, size_t *len);
/* Reads any supported file chosen by its extension (tr_io_in_format: .off .stl .obj .ply
 * .mesh .meshb .msh .node .poly .smesh; .ele reads the .node next to it plus the tets). */
tr_status tr_io_read_file(const char *path, struct tr_plc *plc);
/* The same with `threads` threads where a reader has a parallel form (a TetGen point
 * list), and tr_plc_read (include/tetrec.h) with them: the command passes --threads. */
tr_status tr_io_read_file_threads(const char *path, struct tr_plc *plc, int threads);
tr_status tr_plc_read_threads(const char *path, tr_plc **out, int threads);
/* The same; fans != 0 sets tr_plc.read_fans (--resolve): a one-loop polygon that cannot
 * be triangulated in its plane is read as a fan, counted in nfans and named in fan_notes. */
tr_status tr_plc_read_fans(const char *path, tr_plc **out, int threads, int fans);

/* A polygon of the input that is not planar (polytri.c): plc triangles first_tri ..
 * first_tri + ntris - 1 came from input facet `facet`; deviation = the largest distance
 * of one of its vertices from the plane of its largest triangle, relative = deviation /
 * the diagonal of its bounding box. */
typedef struct tr_nonplanar {
  uint32_t facet, first_tri, ntris;
  double deviation, relative;
} tr_nonplanar;
/* Every non-planar polygon of a plc as read (before tr_plc_validate, which may reorder
 * triangles): the triangles of one input facet (plc->tri_source) not all in one plane,
 * decided exactly (orient3d). *out (free) has *n entries, in facet order. */
tr_status tr_plc_nonplanar(const struct tr_plc *plc, tr_nonplanar **out, uint32_t *n);

#endif
