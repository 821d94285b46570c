/* File readers and writers. One file per format; every reader has a from-memory entry
 * point (used by tr_io_read_file after loading the file, and by the fuzzers), every
 * writer takes a plain view of the mesh so that I/O does not depend on the mesh store.
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

tr_status tr_read_off_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc);
tr_status tr_read_stl_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc);
tr_status tr_read_obj_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc);
tr_status tr_read_ply_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc);
/* Medit .mesh: Vertices, Triangles (the surface input, with their refs as markers),
 * Tetrahedra (kept in plc->tets for `tetrec check`). */
tr_status tr_read_medit_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc);
/* Gmsh .msh 4.1 or 2.2, ASCII (binary is refused): triangles (and quadrangles, as
 * polygons) with the physical tag of their entity (4.1) or their first tag (2.2) as
 * marker, tetrahedra into plc->tets; points and lines are skipped (triangle edges and
 * corners carry no more geometry), any other element type is an error (read_msh.c). */
tr_status tr_read_msh_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc);

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
/* .ele on top of already-read points: appends plc->tets. */
tr_status tr_read_ele_buf(const char *buf, size_t len, const char *name, struct tr_plc *plc);

/* Loads a whole file (binary-safe, NUL-terminated for convenience). */
tr_status tr_io_load(const char *path, char **buf, size_t *len);
/* Reads any supported file chosen by its extension (.off .stl .obj .ply .mesh .node .poly
 * .smesh; .ele reads the .node next to it plus the tets). */
tr_status tr_io_read_file(const char *path, struct tr_plc *plc);

/* A mesh as the writers see it. exact: NULL, or per vertex NULL / the exact point
 * (written as num/den in --exact TetGen output). region, tri_marker may be NULL. */
struct tr_mesh_view {
  uint32_t nverts;
  const double *xyz;
  const tr_qpoint *const *exact;
  uint32_t ntets;
  const uint32_t *tets;
  const int32_t *region;
  uint32_t ntris;
  const uint32_t *tris;
  const int32_t *tri_marker;
};
/* Edges beside a view (check-surface's offending edges), written as lines by the .vtk and
 * .msh writers. */
struct tr_edge_view {
  uint32_t nedges;
  const uint32_t *edges;     /* 2 per edge */
  const int32_t *edge_marker;
};

/* OFF of the triangles (surface output for `tetrec convert`). */
tr_status tr_write_off(const struct tr_mesh_view *m, const char *path);
tr_status tr_write_medit(const struct tr_mesh_view *m, const char *path);
tr_status tr_write_vtu(const struct tr_mesh_view *m, const char *path);
/* base = path without extension; writes base.node, base.ele, base.face. exact: write
 * exact rationals for vertices that have them. */
tr_status tr_write_tetgen(const struct tr_mesh_view *m, const char *base, int exact);
/* Legacy VTK (.vtk), ASCII unstructured grid: the tets with cell data "region", or the
 * triangles with their markers when there are no tets. */
tr_status tr_write_vtk(const struct tr_mesh_view *m, const char *path);
/* The same with edges (cells of VTK type 3 after the triangles; e may be NULL). */
tr_status tr_write_vtk_edges(const struct tr_mesh_view *m, const struct tr_edge_view *e,
                             const char *path);
/* Gmsh .msh, ASCII, version 41 (4.1) or 22 (2.2): tets with their region as physical tag,
 * triangles with their marker as physical tag (write_msh.c). */
tr_status tr_write_msh(const struct tr_mesh_view *m, const char *path, int version);
/* The same with edges (elements of type 1, one curve entity per marker; e may be NULL). */
tr_status tr_write_msh_edges(const struct tr_mesh_view *m, const struct tr_edge_view *e,
                             const char *path, int version);

/* Output format of a name (format.c): the extension after the last dot of the last path
 * component when it has a letter, else a TetGen base name ("out", "cube.1"). */
enum tr_out_format {
  TR_OUT_UNKNOWN, TR_OUT_MEDIT, TR_OUT_VTU, TR_OUT_VTK, TR_OUT_MSH, TR_OUT_TETGEN, TR_OUT_OFF
};
enum tr_out_format tr_io_out_format(const char *path);
/* TR_ERR_USAGE naming the supported extensions unless path names a format tetrec writes
 * (surface != 0: .off too). */
tr_status tr_io_check_out_name(const char *path, int surface);
/* TR_ERR_IO unless every file that writing path creates (three for a TetGen name) can be
 * created; leaves no new file behind. */
tr_status tr_io_check_writable(const char *path);
/* The same for one file of any name. */
tr_status tr_io_check_file_writable(const char *file);

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
/* Chooses by tr_io_out_format: .mesh, .vtu, .vtk, .msh (msh_version 41 or 22), .off,
 * .node/.ele/.face (base taken from the name), or a TetGen base name. */
tr_status tr_write_mesh_view_as(const struct tr_mesh_view *m, const char *path, int exact,
                                int msh_version);
/* tr_write_mesh_view_as with .msh version 4.1. */
tr_status tr_write_mesh_view(const struct tr_mesh_view *m, const char *path, int exact);

/* One line of n integers in decimal, separated by single spaces, then '\n': what
 * fprintf("%lld ...") writes, without its format parsing, which was most of the time of
 * writing the element lists. */
void tr_io_put_ints(FILE *f, const int64_t *x, int n);
/* x as printf("%.17g") writes it, byte for byte (so it reads back to the same double),
 * into out (at least 32 bytes), NUL-terminated; returns the length. */
int tr_io_fmt_double(char *out, double x);
/* "lead x y z" then tail (at most 16 bytes; lead < 0: none): the doubles as %.17g. */
void tr_io_put_xyz(FILE *f, int64_t lead, const double x[3], const char *tail);

/* 1 iff path ends with ext (ASCII case-insensitive, ext includes the dot). */
int tr_io_has_ext(const char *path, const char *ext);

#endif
