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

/* OFF of the triangles (surface output for `tetrec convert`). */
tr_status tr_write_off(const struct tr_mesh_view *m, const char *path);
tr_status tr_write_medit(const struct tr_mesh_view *m, const char *path);
tr_status tr_write_vtu(const struct tr_mesh_view *m, const char *path);
/* base = path without extension; writes base.node, base.ele, base.face. exact: write
 * exact rationals for vertices that have them. */
tr_status tr_write_tetgen(const struct tr_mesh_view *m, const char *base, int exact);
/* Chooses by extension: .mesh, .vtu, .node/.ele/.face (base taken from the name), or no
 * extension = TetGen files with that base. */
tr_status tr_write_mesh_view(const struct tr_mesh_view *m, const char *path, int exact);

/* One line of n integers in decimal, separated by single spaces, then '\n': what
 * fprintf("%lld ...") writes, without its format parsing, which was most of the time of
 * writing the element lists. */
void tr_io_put_ints(FILE *f, const int64_t *x, int n);

/* 1 iff path ends with ext (ASCII case-insensitive, ext includes the dot). */
int tr_io_has_ext(const char *path, const char *ext);

#endif
