/* File formats by name: the one place that maps an extension to a format, for reading and
 * for writing, so that readers, writers and the dispatch all ask here and none asks
 * another. Nothing in it reads or writes a file. */
#ifndef TR_IO_FORMAT_NAME_H
#define TR_IO_FORMAT_NAME_H

#include "../core/status.h"

/* 1 iff path ends with ext (ASCII case-insensitive, ext includes the dot). */
int tr_io_has_ext(const char *path, const char *ext);
/* The extension of path (from the last '.' of its last component, with the dot) when it
 * has a letter in it; NULL otherwise: "out" and "cube.1" are TetGen base names. */
const char *tr_io_extension(const char *path);

/* Output format of a name: the extension when it has a letter, else a TetGen base name. */
enum tr_out_format {
  TR_OUT_UNKNOWN, TR_OUT_MEDIT, TR_OUT_VTU, TR_OUT_VTK, TR_OUT_MSH, TR_OUT_TETGEN, TR_OUT_OFF,
  TR_OUT_MESHB, TR_OUT_STL
};
enum tr_out_format tr_io_out_format(const char *path);
/* TR_ERR_USAGE naming the supported extensions unless path names a format tetrec writes
 * (surface != 0: the surface-only formats .off and .stl too). */
tr_status tr_io_check_out_name(const char *path, int surface);
/* TR_ERR_USAGE unless the format of path has a binary form tetrec writes (.msh, .vtu, .vtk;
 * and .meshb, .stl, which are binary anyway): asked when --binary is given. */
tr_status tr_io_check_binary_name(const char *path);

/* Input format of a name. */
enum tr_in_format {
  TR_IN_UNKNOWN, TR_IN_OFF, TR_IN_STL, TR_IN_OBJ, TR_IN_PLY, TR_IN_MEDIT, TR_IN_MESHB,
  TR_IN_NODE, TR_IN_POLY, TR_IN_SMESH, TR_IN_ELE, TR_IN_MSH
};
enum tr_in_format tr_io_in_format(const char *path);
/* The error for a name tr_io_in_format does not know (TR_ERR_USAGE, the list). */
tr_status tr_io_unknown_input(const char *path);

#endif
