/* Mesh and surface arrays for the Python extension, copied from the public accessors of
 * include/tetrec.h into fresh numpy arrays. One exception: the public header has no
 * accessor for a PLC's triangle markers, segments or tets yet, so tetrec_py_plc_arrays
 * and tetrec_py_plc_extras read them from struct tr_plc (src/core/plc.h); the extension links the static library, so the
 * struct is the one it was built with. */
#define NO_IMPORT_ARRAY /* _tetrec.c imports the numpy C API */
#include "arrays.h"

#include <numpy/arrayobject.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"

static PyArrayObject *new_array(int nd, npy_intp rows, npy_intp cols, int type)
{
  npy_intp dims[2] = {rows, cols};
  return (PyArrayObject *)PyArray_SimpleNew(nd, dims, type);
}

/* A new array holding a copy of rows*cols items of src (zeros when src is NULL). */
static PyArrayObject *copy_array(const void *src, int nd, npy_intp rows, npy_intp cols,
                                 int type)
{
  PyArrayObject *a = new_array(nd, rows, cols, type);
  size_t bytes = a ? (size_t)PyArray_ITEMSIZE(a) * (size_t)PyArray_SIZE(a) : 0;
  if (bytes) {
    if (src)
      memcpy(PyArray_DATA(a), src, bytes);
    else
      memset(PyArray_DATA(a), 0, bytes);
  }
  return a;
}

PyObject *tetrec_py_mesh_arrays(const tr_mesh *mesh)
{
  npy_intp nv = tr_mesh_num_vertices(mesh), nt = tr_mesh_num_tets(mesh);
  npy_intp nf = tr_mesh_num_boundary_faces(mesh);
  PyArrayObject *a[6] = {
      copy_array(tr_mesh_points(mesh), 2, nv, 3, NPY_FLOAT64),
      copy_array(tr_mesh_tets(mesh), 2, nt, 4, NPY_UINT32),
      /* NULL only for a tr_delaunay mesh, which has one region */
      copy_array(tr_mesh_tet_regions(mesh), 1, nt, 0, NPY_INT32),
      copy_array(tr_mesh_boundary_faces(mesh), 2, nf, 3, NPY_UINT32),
      copy_array(tr_mesh_boundary_markers(mesh), 1, nf, 0, NPY_INT32),
      copy_array(tr_mesh_boundary_triangles(mesh), 1, nf, 0, NPY_UINT32)};
  for (int i = 0; i < 6; i++)
    if (!a[i]) {
      for (int j = 0; j < 6; j++)
        Py_XDECREF(a[j]);
      return NULL;
    }
  return Py_BuildValue("{sNsNsNsNsNsN}", "points", a[0], "tets", a[1], "regions", a[2],
                       "boundary_faces", a[3], "boundary_markers", a[4],
                       "boundary_triangles", a[5]);
}

PyObject *tetrec_py_mesh_exact_point(const tr_mesh *mesh, unsigned long v)
{
  if (v >= tr_mesh_num_vertices(mesh)) {
    PyErr_Format(PyExc_IndexError, "vertex %lu of a mesh with %u", v,
                 tr_mesh_num_vertices(mesh));
    return NULL;
  }
  char *text = NULL;
  tr_status st = tr_mesh_point_exact(mesh, (uint32_t)v, &text);
  if (st != TR_OK)
    return tetrec_py_raise(st);
  /* "x y z", each num/den or an integer */
  PyObject *s = PyUnicode_FromString(text);
  PyObject *parts = s ? PyUnicode_Split(s, NULL, -1) : NULL;
  if (parts && PyList_GET_SIZE(parts) != 3) {
    Py_CLEAR(parts);
    PyErr_Format(PyExc_RuntimeError, "tr_mesh_point_exact gave '%s' for vertex %lu", text, v);
  }
  tr_free(text);
  Py_XDECREF(s);
  PyObject *t = parts ? PyList_AsTuple(parts) : NULL;
  Py_XDECREF(parts);
  return t;
}

PyObject *tetrec_py_plc_arrays(const tr_plc *plc)
{
  npy_intp np = tr_plc_num_points(plc), nt = tr_plc_num_triangles(plc);
  PyArrayObject *pts = copy_array(tr_plc_points(plc), 2, np, 3, NPY_FLOAT64);
  PyArrayObject *tri = copy_array(tr_plc_triangles(plc), 2, nt, 3, NPY_UINT32);
  PyArrayObject *mark = copy_array(plc->tri_marker, 1, nt, 0, NPY_INT32);
  if (!pts || !tri || !mark) {
    Py_XDECREF(pts);
    Py_XDECREF(tri);
    Py_XDECREF(mark);
    return NULL;
  }
  return Py_BuildValue("(NNN)", pts, tri, mark);
}

void tetrec_py_plc_extras(const tr_plc *plc, unsigned long *nsegs, unsigned long *ntets)
{
  *nsegs = plc->nsegs;
  *ntets = plc->ntets;
}
