/* The arrays of a mesh and of a surface as numpy arrays, for _tetrec.c. Kept apart so
 * that where they come from (public accessors or the library's structs) is one file. */
#ifndef TETREC_PY_ARRAYS_H
#define TETREC_PY_ARRAYS_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include "tetrec.h"

/* Raises tetrec.Error for st with tr_last_error(); returns NULL. */
PyObject *tetrec_py_raise(tr_status st);

/* dict: points (n,3) float64, tets (m,4) uint32, regions (m,) int32,
 * boundary_faces (f,3) uint32, boundary_markers (f,) int32, boundary_triangles (f,)
 * uint32; NULL with an exception set. */
PyObject *tetrec_py_mesh_arrays(const tr_mesh *mesh);
/* (x, y, z) as exact decimal strings "num/den" or "num"; IndexError past the end. */
PyObject *tetrec_py_mesh_exact_point(const tr_mesh *mesh, unsigned long v);
/* (points (n,3) float64, triangles (m,3) uint32, markers (m,) int32) of a surface. */
PyObject *tetrec_py_plc_arrays(const tr_plc *plc);
/* How many segments (on no triangle) and volume tets a PLC read from a file holds. */
void tetrec_py_plc_extras(const tr_plc *plc, unsigned long *nsegs, unsigned long *ntets);

#endif
