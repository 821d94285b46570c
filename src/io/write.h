/* The writers: one file per format, each taking a plain view of the mesh so that I/O does
 * not depend on the mesh store, and the dispatch by name (format.c). A writer includes
 * this header, put_number.h and, where it needs names, format_name.h: never a reader. */
#ifndef TR_IO_WRITE_H
#define TR_IO_WRITE_H

#include <stdint.h>

#include "../core/status.h"
#include "qpoint.h"

/* A mesh as the writers see it. exact: NULL, or per vertex NULL / the exact point
 * (written as num/den in --exact TetGen output). region, tri_marker may be NULL.
 * threads: how many threads the text writers may format on (blocks.h; 0 or 1: the calling
 * thread only); the file is the same for any value. */
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
  int threads;
};
/* Edges beside a view (check-surface's offending edges), written as lines by the .vtk and
 * .msh writers. */
struct tr_edge_view {
  uint32_t nedges;
  const uint32_t *edges;     /* 2 per edge */
  const int32_t *edge_marker;
};

/* `flags` of the writers that have a text and a binary form, and of the dispatch: the .msh
 * version (41 or 22) in the low byte, TR_WRITE_BINARY (include/tetrec.h) for the binary
 * form of .msh, .vtu and .vtk. */
#define TR_WRITE_VERSION(flags) ((flags) & 0xff)

/* OFF of the triangles (surface output for `tetrec convert`). */
tr_status tr_write_off(const struct tr_mesh_view *m, const char *path);
/* Binary STL of the triangles (surface output): coordinates rounded to float, as the
 * format stores them (write_stl.c). */
tr_status tr_write_stl(const struct tr_mesh_view *m, const char *path);
tr_status tr_write_medit(const struct tr_mesh_view *m, const char *path);
/* Binary Medit .meshb (write_meshb.c). */
tr_status tr_write_meshb(const struct tr_mesh_view *m, const char *path);
/* .vtu, ASCII, or with TR_WRITE_BINARY in flags raw appended binary data. */
tr_status tr_write_vtu(const struct tr_mesh_view *m, const char *path, int flags);
/* base = path without extension; writes base.node, base.ele, base.face. exact: write
 * exact rationals for vertices that have them. */
tr_status tr_write_tetgen(const struct tr_mesh_view *m, const char *base, int exact);
/* Legacy VTK (.vtk) unstructured grid, ASCII or with TR_WRITE_BINARY in flags binary
 * (big-endian): the tets with cell data "region", or the triangles with their markers when
 * there are no tets. */
tr_status tr_write_vtk(const struct tr_mesh_view *m, const char *path, int flags);
/* The same with edges (cells of VTK type 3 after the triangles; e may be NULL), ASCII. */
tr_status tr_write_vtk_edges(const struct tr_mesh_view *m, const struct tr_edge_view *e,
                             const char *path);
/* The same, ASCII or binary by flags. */
tr_status tr_write_vtk_flags(const struct tr_mesh_view *m, const struct tr_edge_view *e,
                             const char *path, int flags);
/* Gmsh .msh, version TR_WRITE_VERSION(flags) 41 (4.1) or 22 (2.2), ASCII or with
 * TR_WRITE_BINARY binary: tets with their region as physical tag, triangles with their
 * marker as physical tag (write_msh.c). */
tr_status tr_write_msh(const struct tr_mesh_view *m, const char *path, int flags);
/* The same with edges (elements of type 1, one curve entity per marker; e may be NULL). */
tr_status tr_write_msh_edges(const struct tr_mesh_view *m, const struct tr_edge_view *e,
                             const char *path, int flags);

/* Chooses the writer by tr_io_out_format (format.c): .mesh, .meshb, .vtu, .vtk, .msh, .off,
 * .stl, .node/.ele/.face (base taken from the name), or a TetGen base name. flags: as
 * above (msh version, TR_WRITE_BINARY). */
tr_status tr_write_mesh_view_as(const struct tr_mesh_view *m, const char *path, int exact,
                                int flags);
/* tr_write_mesh_view_as with .msh version 4.1, text. */
tr_status tr_write_mesh_view(const struct tr_mesh_view *m, const char *path, int exact);

/* tr_mesh_write_ex (include/tetrec.h) with the threads the text writers may use (the
 * public writers use one; the command passes --threads): write_mesh.c. */
tr_status tr_mesh_write_threads(const tr_mesh *mesh, const char *path, int exact, int flags,
                                int threads);
tr_status tr_plc_write_threads(const tr_plc *plc, const char *path, int flags, int threads);
/* Threads for an option value, as the Delaunay stage counts them: 0 every online core,
 * N > 0 at most N (64 at most). */
int tr_io_thread_count(int threads);

/* TR_ERR_IO unless every file that writing path creates (three for a TetGen name) can be
 * created; leaves no new file behind. */
tr_status tr_io_check_writable(const char *path);
/* The same for one file of any name. */
tr_status tr_io_check_file_writable(const char *file);

#endif
