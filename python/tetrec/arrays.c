/* Mesh and surface arrays for the Python extension, read from the library's own
 * structs (src/mesh/mesh.h, src/core/plc.h): the public header has counts but no array
 * accessors yet. The extension links the static library, so the structs are the ones
 * it was built with. Once include/tetrec.h has tr_mesh_points & co., this file reads
 * those instead and stops including internal headers.
 *
 * The boundary faces are the ones tr_mesh_write writes (src/io/write_mesh.c): a face of
 * a kept tet whose neighbour is missing, a ghost, outside, or in another region (listed
 * once, from the lower tet), oriented with its normal out of its tet. */
#define NO_IMPORT_ARRAY
#include "arrays.h"

#include <numpy/arrayobject.h>
#include <stdlib.h>
#include <string.h>

#include "core/plc.h"
#include "mesh/mesh.h"

static int keep(const struct tr_mesh *m, uint32_t t)
{
  return tr_tet_is_real(m, t) && !(m->flags && (m->flags[t] & TR_TF_OUTER));
}

static int boundary(const struct tr_mesh *m, uint32_t t, int k)
{
  uint32_t o = TR_NEIG(m, t, k);
  return o == TR_NONE || !keep(m, o) || (m->region && m->region[o] != m->region[t] && o > t);
}

static PyArrayObject *new_array(int nd, npy_intp rows, npy_intp cols, int type)
{
  npy_intp dims[2] = {rows, cols};
  return (PyArrayObject *)PyArray_SimpleNew(nd, dims, type);
}

/* Steals the arrays' references; NULL (exception set) if any is NULL. */
static PyObject *mesh_dict(PyArrayObject *pts, PyArrayObject *tets, PyArrayObject *reg,
                           PyArrayObject *faces, PyArrayObject *mark)
{
  if (!pts || !tets || !reg || !faces || !mark) {
    Py_XDECREF(pts);
    Py_XDECREF(tets);
    Py_XDECREF(reg);
    Py_XDECREF(faces);
    Py_XDECREF(mark);
    return NULL;
  }
  return Py_BuildValue("{sNsNsNsNsN}", "points", pts, "tets", tets, "regions", reg,
                       "boundary_faces", faces, "boundary_markers", mark);
}

PyObject *tetrec_py_mesh_arrays(const tr_mesh *mesh)
{
  const struct tr_mesh *m = mesh;
  npy_intp nt = 0, nf = 0;
  for (uint32_t t = 0; t < m->nt; t++)
    if (keep(m, t)) {
      nt++;
      for (int k = 0; k < 4; k++)
        nf += boundary(m, t, k);
    }
  PyArrayObject *pts = new_array(2, m->nv, 3, NPY_FLOAT64);
  PyArrayObject *tets = new_array(2, nt, 4, NPY_UINT32);
  PyArrayObject *reg = new_array(1, nt, 0, NPY_INT32);
  PyArrayObject *faces = new_array(2, nf, 3, NPY_UINT32);
  PyArrayObject *mark = new_array(1, nf, 0, NPY_INT32);
  if (!pts || !tets || !reg || !faces || !mark)
    return mesh_dict(pts, tets, reg, faces, mark);
  if (m->nv)
    memcpy(PyArray_DATA(pts), m->xyz, sizeof(double) * 3 * (size_t)m->nv);
  uint32_t *tv = PyArray_DATA(tets), *fv = PyArray_DATA(faces);
  int32_t *rv = PyArray_DATA(reg), *mv = PyArray_DATA(mark);
  for (uint32_t t = 0; t < m->nt; t++) {
    if (!keep(m, t))
      continue;
    memcpy(tv, m->tv + 4 * (size_t)t, 4 * sizeof *tv);
    tv += 4;
    *rv++ = m->region ? (int32_t)m->region[t] : 0;
    for (int k = 0; k < 4; k++)
      if (boundary(m, t, k)) {
        /* tr_face_vtx order has the normal pointing into the tet: reverse it. */
        fv[0] = m->tv[4 * (size_t)t + tr_face_vtx[k][0]];
        fv[1] = m->tv[4 * (size_t)t + tr_face_vtx[k][2]];
        fv[2] = m->tv[4 * (size_t)t + tr_face_vtx[k][1]];
        fv += 3;
        /* The store keeps no input markers; tr_mesh_write writes 1 for every face. */
        *mv++ = 1;
      }
  }
  return mesh_dict(pts, tets, reg, faces, mark);
}

static PyObject *mpq_text(const mpq_t q)
{
  char *s = mpq_get_str(NULL, 10, q);
  if (!s)
    return PyErr_NoMemory();
  PyObject *r = PyUnicode_FromString(s);
  void (*freefunc)(void *, size_t);
  mp_get_memory_functions(NULL, NULL, &freefunc);
  freefunc(s, strlen(s) + 1);
  return r;
}

PyObject *tetrec_py_mesh_exact_point(const tr_mesh *mesh, unsigned long v)
{
  const struct tr_mesh *m = mesh;
  if (v >= m->nv) {
    PyErr_Format(PyExc_IndexError, "vertex %lu of a mesh with %u", v, m->nv);
    return NULL;
  }
  PyObject *c[3] = {NULL, NULL, NULL};
  const tr_qpoint *q = m->vq ? m->vq[v] : NULL;
  for (int k = 0; k < 3; k++) {
    if (q) {
      c[k] = mpq_text(q->c[k]);
    } else {
      mpq_t x;
      mpq_init(x);
      mpq_set_d(x, m->xyz[3 * (size_t)v + k]);
      c[k] = mpq_text(x);
      mpq_clear(x);
    }
    if (!c[k]) {
      Py_XDECREF(c[0]);
      Py_XDECREF(c[1]);
      return NULL;
    }
  }
  return Py_BuildValue("(NNN)", c[0], c[1], c[2]);
}

PyObject *tetrec_py_plc_arrays(const tr_plc *plc)
{
  uint32_t np = tr_plc_num_points(plc), nt = tr_plc_num_triangles(plc);
  PyArrayObject *pts = new_array(2, np, 3, NPY_FLOAT64);
  PyArrayObject *tri = new_array(2, nt, 3, NPY_UINT32);
  PyArrayObject *mark = new_array(1, nt, 0, NPY_INT32);
  if (!pts || !tri || !mark) {
    Py_XDECREF(pts);
    Py_XDECREF(tri);
    Py_XDECREF(mark);
    return NULL;
  }
  if (np)
    memcpy(PyArray_DATA(pts), tr_plc_points(plc), sizeof(double) * 3 * (size_t)np);
  if (nt)
    memcpy(PyArray_DATA(tri), tr_plc_triangles(plc), sizeof(uint32_t) * 3 * (size_t)nt);
  int32_t *mv = PyArray_DATA(mark);
  for (uint32_t i = 0; i < nt; i++)
    mv[i] = plc->tri_marker ? plc->tri_marker[i] : 0;
  return Py_BuildValue("(NNN)", pts, tri, mark);
}
