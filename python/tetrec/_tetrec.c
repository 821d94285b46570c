/* _tetrec: the C extension under the tetrec Python package. It converts numpy arrays to
 * the C API's flat arrays, runs the pipeline with the GIL released, and turns every
 * tr_status into a tetrec.Error carrying the status name and tr_last_error(). The
 * user-facing signatures and checks live in _mesh.py; this layer is kept thin. */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <numpy/arrayobject.h>

#include <math.h>
#include <string.h>

#include "arrays.h"
#include "tetrec.h"

static PyObject *Error; /* tetrec.Error */

/* Builds tetrec.Error(message) with .status (tr_status_name), .code and .message. */
static PyObject *make_error(int code, const char *message)
{
  PyObject *exc = PyObject_CallFunction(Error, "s", message);
  if (!exc)
    return NULL;
  PyObject *name = PyUnicode_FromString(tr_status_name((tr_status)code));
  PyObject *num = PyLong_FromLong(code);
  PyObject *msg = PyUnicode_FromString(message);
  int bad = !name || !num || !msg || PyObject_SetAttrString(exc, "status", name) < 0 ||
            PyObject_SetAttrString(exc, "code", num) < 0 ||
            PyObject_SetAttrString(exc, "message", msg) < 0;
  Py_XDECREF(name);
  Py_XDECREF(num);
  Py_XDECREF(msg);
  if (bad) {
    Py_DECREF(exc);
    return NULL;
  }
  return exc;
}

PyObject *tetrec_py_raise(tr_status st)
{
  PyObject *exc = make_error((int)st, tr_last_error());
  if (exc) {
    PyErr_SetObject(Error, exc);
    Py_DECREF(exc);
  }
  return NULL;
}

/* ---- the mesh handle ---- */
typedef struct {
  PyObject_HEAD
  tr_mesh *mesh;
} CMesh;

static void cmesh_dealloc(CMesh *self)
{
  tr_mesh_destroy(self->mesh);
  Py_TYPE(self)->tp_free((PyObject *)self);
}

static PyObject *cmesh_write(CMesh *self, PyObject *args)
{
  PyObject *path_obj;
  int exact = 0;
  if (!PyArg_ParseTuple(args, "O&p", PyUnicode_FSConverter, &path_obj, &exact))
    return NULL;
  const char *path = PyBytes_AS_STRING(path_obj);
  tr_status st;
  Py_BEGIN_ALLOW_THREADS
  st = tr_mesh_write(self->mesh, path, exact);
  Py_END_ALLOW_THREADS
  Py_DECREF(path_obj);
  if (st != TR_OK)
    return tetrec_py_raise(st);
  Py_RETURN_NONE;
}

/* A dict of fresh numpy arrays (copies: the Python Mesh outlives nothing it points at). */
static PyObject *cmesh_arrays(CMesh *self, PyObject *Py_UNUSED(ignored))
{
  return tetrec_py_mesh_arrays(self->mesh);
}

static PyObject *cmesh_exact_point(CMesh *self, PyObject *args)
{
  unsigned long v;
  if (!PyArg_ParseTuple(args, "k", &v))
    return NULL;
  return tetrec_py_mesh_exact_point(self->mesh, v);
}

static PyMethodDef cmesh_methods[] = {
    {"write", (PyCFunction)cmesh_write, METH_VARARGS,
     "write(path, exact): tr_mesh_write; the extension picks the format."},
    {"arrays", (PyCFunction)cmesh_arrays, METH_NOARGS,
     "arrays() -> dict of numpy arrays (copies): points, tets, regions, boundary_faces, "
     "boundary_markers, boundary_triangles."},
    {"exact_point", (PyCFunction)cmesh_exact_point, METH_VARARGS,
     "exact_point(v) -> (x, y, z), each an exact rational as text, num/den or num."},
    {NULL, NULL, 0, NULL}};

static PyTypeObject CMeshType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "tetrec._tetrec.CMesh",
    .tp_basicsize = sizeof(CMesh),
    .tp_dealloc = (destructor)cmesh_dealloc,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "A tetrec mesh (tr_mesh) owned by Python.",
    .tp_methods = cmesh_methods,
};

/* tr_options.progress: runs on the thread that called tr_mesh_plc, which released the
 * GIL; it takes the GIL back to look for a pending KeyboardInterrupt and to call the
 * user's progress(stage, fraction). A signal, an exception or a true return cancels
 * the run (TR_ERR_CANCELLED); the exception is kept and raised afterwards. */
typedef struct {
  PyObject *callback; /* or NULL */
  PyObject *exc_type, *exc_value, *exc_tb;
} progress_state;

static int progress_hook(void *user, const char *stage, double fraction)
{
  progress_state *ps = user;
  PyGILState_STATE g = PyGILState_Ensure();
  int stop = 0;
  if (!ps->exc_type) {
    if (PyErr_CheckSignals() < 0) {
      stop = 1;
    } else if (ps->callback) {
      PyObject *r = PyObject_CallFunction(ps->callback, "sd", stage, fraction);
      stop = !r || PyObject_IsTrue(r) != 0;
      Py_XDECREF(r);
    }
    if (PyErr_Occurred())
      PyErr_Fetch(&ps->exc_type, &ps->exc_value, &ps->exc_tb);
  } else {
    stop = 1;
  }
  PyGILState_Release(g);
  return stop;
}

/* ---- options ---- */
/* Every key of `opts` is an option the caller set to a non-default value. Each one this
 * build of the C library supports is copied into tr_options; any other raises
 * NotImplementedError, so no option is ever dropped. To wire a new option: handle its
 * key here and add its name to SUPPORTED_OPTIONS below. */
static const char *const SUPPORTED_OPTIONS[] = {
    "smooth", "verbose", "round_budget", "progress", "keep_surface", "keep_steiner", "quality",
    "max_volume", "optimize", "keep_edges", "subface_quality", "refine_budget",
    "spacing_radii", "refine_partial", "holes", "regions", "threads", "sizing", "resolve",
    "surface_tolerance", "exact", NULL};

/* A positive finite float, or -1 with a Python error set. */
static double positive(PyObject *value, const char *name)
{
  double x = PyFloat_AsDouble(value);
  if (x == -1.0 && PyErr_Occurred())
    return -1;
  if (!(x > 0) || !isfinite(x)) {
    PyErr_Format(PyExc_ValueError, "%s must be a positive finite number", name);
    return -1;
  }
  return x;
}

static int set_options(PyObject *opts, tr_options *opt, progress_state *ps)
{
  tr_options_default(opt);
  opt->verbose = 0;
  opt->progress = progress_hook;
  opt->progress_user = ps;
  if (opts == Py_None)
    return 0;
  if (!PyDict_Check(opts)) {
    PyErr_SetString(PyExc_TypeError, "options must be a dict");
    return -1;
  }
  PyObject *key, *value;
  Py_ssize_t pos = 0;
  while (PyDict_Next(opts, &pos, &key, &value)) {
    const char *k = PyUnicode_Check(key) ? PyUnicode_AsUTF8(key) : NULL;
    if (!k) {
      PyErr_SetString(PyExc_TypeError, "option names must be strings");
      return -1;
    }
    if (!strcmp(k, "smooth") || !strcmp(k, "verbose")) {
      long x = PyLong_AsLong(value);
      if (x == -1 && PyErr_Occurred())
        return -1;
      if (x < 0 || x > 2) {
        PyErr_Format(PyExc_ValueError, "%s must be 0, 1 or 2, not %ld", k, x);
        return -1;
      }
      if (k[0] == 's')
        opt->smooth = (int)x;
      else
        opt->verbose = (int)x;
    } else if (!strcmp(k, "progress")) {
      if (!PyCallable_Check(value)) {
        PyErr_SetString(PyExc_TypeError, "progress must be callable(stage, fraction)");
        return -1;
      }
      ps->callback = value;
    } else if (!strcmp(k, "round_budget")) {
      unsigned long long x = PyLong_AsUnsignedLongLong(value);
      if (x == (unsigned long long)-1 && PyErr_Occurred())
        return -1;
      if (x == 0) {
        PyErr_SetString(PyExc_ValueError, "round_budget must be positive");
        return -1;
      }
      opt->round_budget = (uint64_t)x;
    } else if (!strcmp(k, "resolve")) {
      /* 1: the solid by winding number, 2: with its internal facets (tr_options.resolve) */
      long x = PyLong_AsLong(value);
      if (x == -1 && PyErr_Occurred())
        return -1;
      if (x < 1 || x > 2) {
        PyErr_Format(PyExc_ValueError, "resolve is 1 or 2 here, not %ld", x);
        return -1;
      }
      opt->resolve = (int)x;
    } else if (!strcmp(k, "surface_tolerance")) {
      /* a fraction of the bounding box diagonal (tr_options.surface_tolerance) */
      if ((opt->surface_tolerance = positive(value, "surface_tolerance")) < 0)
        return -1;
    } else if (!strcmp(k, "threads")) {
      long x = PyLong_AsLong(value);
      if (x == -1 && PyErr_Occurred())
        return -1;
      if (x < 0 || x > 1024) {
        PyErr_Format(PyExc_ValueError, "threads must be 0 (every core) to 1024, not %ld", x);
        return -1;
      }
      opt->threads = (int)x;
    } else if (!strcmp(k, "keep_surface") || !strcmp(k, "keep_steiner") ||
               !strcmp(k, "keep_edges") || !strcmp(k, "spacing_radii") ||
               !strcmp(k, "refine_partial") || !strcmp(k, "exact")) {
      int x = PyObject_IsTrue(value);
      if (x < 0)
        return -1;
      if (!strcmp(k, "keep_surface"))
        opt->keep_surface = x;
      else if (!strcmp(k, "keep_edges"))
        opt->keep_edges = x;
      else if (!strcmp(k, "spacing_radii"))
        opt->refine_spacing_radii = x;
      else if (!strcmp(k, "refine_partial"))
        opt->refine_partial = x;
      else if (!strcmp(k, "exact")) /* the exact mesh, unrounded (tr_options.keep_exact) */
        opt->keep_exact = x;
      else
        opt->keep_steiner = x;
    } else if (!strcmp(k, "quality")) {
      /* R, or (R, D) with D a minimum dihedral angle in degrees that sliver removal
       * works towards (tr_options.quality_min_dihedral) */
      PyObject *r = value, *d = NULL;
      if (PyTuple_Check(value) || PyList_Check(value)) {
        if (PySequence_Size(value) != 2) {
          PyErr_SetString(PyExc_ValueError, "quality is R or (R, D)");
          return -1;
        }
        r = PySequence_GetItem(value, 0);
        d = PySequence_GetItem(value, 1);
        Py_XDECREF(r); /* borrowed from here on: value keeps them alive */
        Py_XDECREF(d);
        if (!r || !d)
          return -1;
      }
      if ((opt->quality_ratio = positive(r, "quality")) < 0)
        return -1;
      if (d) {
        opt->quality_min_dihedral = PyFloat_AsDouble(d);
        if (opt->quality_min_dihedral == -1.0 && PyErr_Occurred())
          return -1;
      }
    } else if (!strcmp(k, "optimize")) {
      /* the sliver removal level; the library refuses one out of 0..3 */
      long x = PyLong_AsLong(value);
      if (x == -1 && PyErr_Occurred())
        return -1;
      if (x < 0 || x > 3) {
        PyErr_SetString(PyExc_ValueError, "optimize is 0, 1, 2 or 3");
        return -1;
      }
      opt->optimize = (int)x;
    } else if (!strcmp(k, "subface_quality")) {
      /* the library refuses S < 1 (TR_ERR_USAGE) like the CLI's --subface-quality */
      if ((opt->quality_subface_ratio = positive(value, "subface_quality")) < 0)
        return -1;
    } else if (!strcmp(k, "refine_budget")) {
      unsigned long long x = PyLong_AsUnsignedLongLong(value);
      if (x == (unsigned long long)-1 && PyErr_Occurred())
        return -1;
      if (x == 0) {
        PyErr_SetString(PyExc_ValueError, "refine_budget must be positive");
        return -1;
      }
      opt->refine_budget = (uint64_t)x;
    } else if (!strcmp(k, "max_volume")) {
      if ((opt->max_volume = positive(value, "max_volume")) < 0)
        return -1;
    } else if (!strcmp(k, "sizing")) {
      /* a C-contiguous float64 array (_mesh.py makes it), one value per point: the library
       * checks the count and the values; the options dict keeps the array alive for the
       * call, so its buffer is only borrowed */
      Py_buffer view;
      if (PyObject_GetBuffer(value, &view, PyBUF_C_CONTIGUOUS | PyBUF_FORMAT) < 0)
        return -1;
      int ok = view.itemsize == sizeof(double) && view.format && !strcmp(view.format, "d") &&
               (size_t)view.len / sizeof(double) <= UINT32_MAX;
      opt->sizing = (const double *)view.buf;
      opt->nsizing = (uint32_t)((size_t)view.len / sizeof(double));
      PyBuffer_Release(&view);
      if (!ok) {
        PyErr_SetString(PyExc_TypeError, "sizing must be a contiguous float64 array");
        return -1;
      }
    } else if (!strcmp(k, "holes") || !strcmp(k, "regions")) {
      /* added to the PLC by py_tetrahedralize (add_points) */
    } else {
      PyErr_Format(PyExc_NotImplementedError,
                   "tetrahedralize(%s=...): the tetrec C library (version %s) has no such "
                   "option yet",
                   k, TETREC_VERSION_STRING);
      return -1;
    }
  }
  return 0;
}

static PyObject *stats_dict(const tr_stats *s)
{
  PyObject *d = Py_BuildValue(
      "{sKsKsKsKsKsKsKsKsKsKsKsKsKsdsdsK}", "surface_nodes", (unsigned long long)s->surface_nodes,
      "surface_facets", (unsigned long long)s->surface_facets, "volume_nodes",
      (unsigned long long)s->volume_nodes, "volume_elements",
      (unsigned long long)s->volume_elements, "missing_edges",
      (unsigned long long)s->missing_edges, "edges_recovered_by_swap",
      (unsigned long long)s->edges_recovered_by_swap, "points_added_for_edges",
      (unsigned long long)s->points_added_for_edges, "missing_facets",
      (unsigned long long)s->missing_facets, "facets_recovered_by_swap",
      (unsigned long long)s->facets_recovered_by_swap, "points_added_for_facets",
      (unsigned long long)s->points_added_for_facets, "surface_swaps",
      (unsigned long long)s->surface_swaps, "rounding_repairs",
      (unsigned long long)s->rounding_repairs, "rounding_flips",
      (unsigned long long)s->rounding_flips, "total_seconds", s->total_seconds,
      "recovery_seconds", s->recovery_seconds, "peak_memory_bytes",
      (unsigned long long)s->peak_memory_bytes);
  PyObject *stages = d ? PyDict_New() : NULL;
  for (int k = 0; stages && k < TR_STAGE_COUNT; k++) {
    PyObject *x = PyFloat_FromDouble(s->stage_seconds[k]);
    if (!x || PyDict_SetItemString(stages, tr_stage_name(k), x) < 0)
      Py_CLEAR(stages);
    Py_XDECREF(x);
  }
  if (!stages || PyDict_SetItemString(d, "stage_seconds", stages) < 0) {
    Py_XDECREF(stages);
    Py_XDECREF(d);
    return NULL;
  }
  Py_DECREF(stages);
  /* the rows added after the paper's Table 14: counts, then measures */
  const struct {
    const char *name;
    uint64_t value;
  } counts[] = {{"facets_recovered_by_cavity", s->facets_recovered_by_cavity},
                {"steiner_on_edges", s->steiner_on_edges},
                {"steiner_on_facets", s->steiner_on_facets},
                {"steiner_interior", s->steiner_interior},
                {"steiner_removed", s->steiner_removed},
                {"steiner_relocated", s->steiner_relocated},
                {"hole_points", s->hole_points},
                {"region_points", s->region_points},
                {"cavities", s->cavities},
                {"inclusions", s->inclusions},
                {"points_added_for_quality", s->points_added_for_quality},
                {"tets_dihedral_below_5", s->tets_dihedral_below_5},
                {"tets_dihedral_below_10", s->tets_dihedral_below_10},
                {"points_added_for_sliver", s->points_added_for_sliver},
                {"sliver_flips", s->sliver_flips},
                {"sliver_points_smoothed", s->sliver_points_smoothed},
                {"input_edges_merged", s->input_edges_merged},
                {"refine_budget_reached", s->refine_budget_reached},
                {"tets_over_bounds", s->tets_over_bounds},
                {"tets_dihedral_below_10_on_thin_input", s->tets_dihedral_below_10_on_thin_input},
                {"thin_input_triangles", s->thin_input_triangles},
                {"surface_collapses", s->surface_collapses},
                {"surface_flips", s->surface_flips}};
  const struct {
    const char *name;
    double value;
  } reals[] = {{"min_dihedral", s->min_dihedral},
               {"max_dihedral", s->max_dihedral},
               {"max_radius_edge", s->max_radius_edge},
               {"double_deviation", s->double_deviation},
               {"bytes_per_tet", s->bytes_per_tet},
               {"surface_tolerance_bound", s->surface_tolerance_bound},
               {"surface_tolerance_seconds", s->surface_tolerance_seconds}};
  size_t nc = sizeof counts / sizeof *counts, nr = sizeof reals / sizeof *reals;
  for (size_t i = 0; i < nc + nr; i++) {
    PyObject *x = i < nc ? PyLong_FromUnsignedLongLong((unsigned long long)counts[i].value)
                         : PyFloat_FromDouble(reals[i - nc].value);
    if (!x || PyDict_SetItemString(d, i < nc ? counts[i].name : reals[i - nc].name, x) < 0) {
      Py_XDECREF(x);
      Py_DECREF(d);
      return NULL;
    }
    Py_DECREF(x);
  }
  return d;
}

/* The arrays _mesh.py hands over are already C-contiguous with the exact dtypes; this
 * checks it again rather than trusting it, since a wrong stride would read garbage. */
static PyArrayObject *as_array(PyObject *obj, int type, npy_intp cols, const char *what)
{
  if (!PyArray_Check(obj) || PyArray_TYPE((PyArrayObject *)obj) != type ||
      !PyArray_IS_C_CONTIGUOUS((PyArrayObject *)obj) ||
      PyArray_NDIM((PyArrayObject *)obj) != (cols ? 2 : 1) ||
      (cols && PyArray_DIM((PyArrayObject *)obj, 1) != cols)) {
    PyErr_Format(PyExc_TypeError, "%s: expected a C-contiguous array of the right dtype/shape",
                 what);
    return NULL;
  }
  if (PyArray_DIM((PyArrayObject *)obj, 0) > (npy_intp)UINT32_MAX - 1) {
    PyErr_Format(PyExc_ValueError, "%s: more than 2^32-2 rows", what);
    return NULL;
  }
  return (PyArrayObject *)obj;
}

static PyObject *new_cmesh(tr_mesh *mesh)
{
  CMesh *h = PyObject_New(CMesh, &CMeshType);
  if (!h) {
    tr_mesh_destroy(mesh);
    return NULL;
  }
  h->mesh = mesh;
  return (PyObject *)h;
}

/* A PLC from the arrays _mesh.py prepared; NULL with an exception set on failure. */
static tr_plc *build_plc(PyObject *pts_obj, PyObject *tri_obj, PyObject *mark_obj)
{
  PyArrayObject *pts = as_array(pts_obj, NPY_FLOAT64, 3, "points");
  PyArrayObject *tri = pts ? as_array(tri_obj, NPY_UINT32, 3, "triangles") : NULL;
  if (!tri)
    return NULL;
  PyArrayObject *mark = NULL;
  if (mark_obj != Py_None) {
    if (!(mark = as_array(mark_obj, NPY_INT32, 0, "markers")))
      return NULL;
    if (PyArray_DIM(mark, 0) != PyArray_DIM(tri, 0)) {
      PyErr_SetString(PyExc_ValueError, "markers: one per triangle");
      return NULL;
    }
  }
  tr_plc *plc = NULL;
  tr_status st = tr_plc_create(&plc);
  if (st == TR_OK)
    st = tr_plc_set(plc, (const double *)PyArray_DATA(pts), (uint32_t)PyArray_DIM(pts, 0),
                    (const uint32_t *)PyArray_DATA(tri), (uint32_t)PyArray_DIM(tri, 0),
                    mark ? (const int32_t *)PyArray_DATA(mark) : NULL);
  if (st != TR_OK) {
    tr_plc_destroy(plc);
    tetrec_py_raise(st);
    return NULL;
  }
  return plc;
}

/* Hole points (rows x y z, width 3) or region points (rows x y z attribute max_volume,
 * width 5) into plc; rows NULL: none. -1 with a Python error set on failure. */
static int add_points(tr_plc *plc, PyObject *rows, int width)
{
  if (!rows || rows == Py_None)
    return 0;
  PyArrayObject *a =
      (PyArrayObject *)PyArray_FROMANY(rows, NPY_FLOAT64, 2, 2, NPY_ARRAY_IN_ARRAY);
  if (!a)
    return -1;
  if (PyArray_DIM(a, 1) != width) {
    PyErr_Format(PyExc_ValueError, "%s: rows of %d numbers (%s)",
                 width == 3 ? "holes" : "regions", width,
                 width == 3 ? "x, y, z" : "x, y, z, attribute, max_volume");
    Py_DECREF(a);
    return -1;
  }
  const double *x = (const double *)PyArray_DATA(a);
  tr_status st = TR_OK;
  for (npy_intp i = 0; i < PyArray_DIM(a, 0) && st == TR_OK; i++) {
    const double *r = x + (size_t)width * (size_t)i;
    if (width == 3)
      st = tr_plc_add_hole(plc, r[0], r[1], r[2]);
    else if (!(r[3] >= -2147483648.0 && r[3] <= 2147483647.0) || r[3] != floor(r[3])) {
      Py_DECREF(a);
      PyErr_Format(PyExc_ValueError, "regions: attribute %g is not a 32-bit integer", r[3]);
      return -1;
    } else
      st = tr_plc_add_region(plc, r[0], r[1], r[2], (int32_t)r[3], r[4]);
  }
  Py_DECREF(a);
  if (st != TR_OK) {
    tetrec_py_raise(st);
    return -1;
  }
  return 0;
}

/* tetrahedralize(points float64 (n,3), triangles uint32 (m,3), markers int32 (m,) or None,
 * options dict or None) -> (CMesh, stats dict) */
static PyObject *py_tetrahedralize(PyObject *Py_UNUSED(mod), PyObject *args)
{
  PyObject *pts_obj, *tri_obj, *mark_obj, *opts;
  if (!PyArg_ParseTuple(args, "OOOO", &pts_obj, &tri_obj, &mark_obj, &opts))
    return NULL;
  tr_options opt;
  progress_state ps = {NULL, NULL, NULL, NULL};
  if (set_options(opts, &opt, &ps) < 0)
    return NULL;
  tr_plc *plc = build_plc(pts_obj, tri_obj, mark_obj);
  if (!plc)
    return NULL;
  if (opts != Py_None && (add_points(plc, PyDict_GetItemString(opts, "holes"), 3) < 0 ||
                          add_points(plc, PyDict_GetItemString(opts, "regions"), 5) < 0)) {
    tr_plc_destroy(plc);
    return NULL;
  }
  tr_mesh *mesh = NULL;
  tr_stats stats;
  memset(&stats, 0, sizeof stats);
  stats.size = sizeof stats;
  tr_status st;
  Py_BEGIN_ALLOW_THREADS
  st = tr_mesh_plc(plc, &opt, &mesh, &stats);
  Py_END_ALLOW_THREADS
  tr_plc_destroy(plc);
  if (ps.exc_type) {
    tr_mesh_destroy(mesh);
    PyErr_Restore(ps.exc_type, ps.exc_value, ps.exc_tb);
    return NULL;
  }
  if (st != TR_OK)
    return tetrec_py_raise(st);
  PyObject *h = new_cmesh(mesh);
  PyObject *sd = h ? stats_dict(&stats) : NULL;
  if (!sd) {
    Py_XDECREF(h);
    return NULL;
  }
  return Py_BuildValue("(NN)", h, sd);
}

/* validate(points, triangles, markers or None) -> (points, triangles, markers, report):
 * the surface after tr_plc_validate's repairs, i.e. the one tr_mesh_plc meshes. */
static PyObject *py_validate(PyObject *Py_UNUSED(mod), PyObject *args)
{
  PyObject *pts_obj, *tri_obj, *mark_obj;
  if (!PyArg_ParseTuple(args, "OOO", &pts_obj, &tri_obj, &mark_obj))
    return NULL;
  tr_plc *plc = build_plc(pts_obj, tri_obj, mark_obj);
  if (!plc)
    return NULL;
  tr_status st;
  Py_BEGIN_ALLOW_THREADS
  st = tr_plc_validate(plc, NULL);
  Py_END_ALLOW_THREADS
  if (st != TR_OK) {
    tr_plc_destroy(plc);
    return tetrec_py_raise(st);
  }
  PyObject *arrays = tetrec_py_plc_arrays(plc);
  PyObject *res = arrays ? Py_BuildValue("(OOOs)", PyTuple_GET_ITEM(arrays, 0),
                                         PyTuple_GET_ITEM(arrays, 1),
                                         PyTuple_GET_ITEM(arrays, 2), tr_plc_report(plc))
                         : NULL;
  Py_XDECREF(arrays);
  tr_plc_destroy(plc);
  return res;
}

/* "" or "N polygon(s) that cannot be triangulated in their plane read as fans: " and the
 * first reasons, joined by "; ". */
static PyObject *fan_notes(const tr_plc *plc)
{
  uint32_t n = tr_plc_num_fans(plc);
  if (!n)
    return PyUnicode_FromString("");
  PyObject *notes = PyUnicode_FromString(tr_plc_fan_notes(plc));
  if (!notes)
    return NULL;
  PyObject *lines = PyUnicode_Splitlines(notes, 0);
  Py_DECREF(notes);
  PyObject *sep = lines ? PyUnicode_FromString("; ") : NULL;
  PyObject *joined = sep ? PyUnicode_Join(sep, lines) : NULL;
  Py_XDECREF(lines);
  Py_XDECREF(sep);
  if (!joined)
    return NULL;
  PyObject *res = PyUnicode_FromFormat("%lu polygon(s) that cannot be triangulated in their "
                                       "plane read as fans of their loops (at most ten named): %U",
                                       (unsigned long)n, joined);
  Py_DECREF(joined);
  return res;
}

/* read(path, resolve) -> (points (n,3) float64, triangles (m,3) uint32, markers (m,)
 * int32, segments, tets, fans): segments and tets count what the file held beside its
 * surface (segments on no triangle, volume tets), which a Surface cannot carry; fans is
 * "" or, with resolve, what tr_plc_fan_notes says of the polygons read as fans. */
static PyObject *py_read(PyObject *Py_UNUSED(mod), PyObject *args)
{
  PyObject *path_obj;
  int resolve = 0;
  if (!PyArg_ParseTuple(args, "O&p", PyUnicode_FSConverter, &path_obj, &resolve))
    return NULL;
  tr_plc *plc = NULL;
  tr_status st;
  tr_options opt;
  tr_options_default(&opt);
  opt.resolve = resolve;
  opt.threads = 1;
  Py_BEGIN_ALLOW_THREADS
  st = tr_plc_read_options(PyBytes_AS_STRING(path_obj), &opt, &plc);
  Py_END_ALLOW_THREADS
  Py_DECREF(path_obj);
  if (st != TR_OK)
    return tetrec_py_raise(st);
  PyObject *arrays = tetrec_py_plc_arrays(plc);
  unsigned long extra[2];
  tetrec_py_plc_extras(plc, &extra[0], &extra[1]);
  PyObject *fans = fan_notes(plc);
  tr_plc_destroy(plc);
  if (!arrays || !fans) {
    Py_XDECREF(arrays);
    Py_XDECREF(fans);
    return NULL;
  }
  PyObject *res = Py_BuildValue("(OOOkkN)", PyTuple_GET_ITEM(arrays, 0),
                                PyTuple_GET_ITEM(arrays, 1), PyTuple_GET_ITEM(arrays, 2),
                                extra[0], extra[1], fans);
  Py_DECREF(arrays);
  return res;
}

static PyObject *py_status_name(PyObject *Py_UNUSED(mod), PyObject *args)
{
  int code;
  if (!PyArg_ParseTuple(args, "i", &code))
    return NULL;
  return PyUnicode_FromString(tr_status_name((tr_status)code));
}

/* error(code, message) -> a tetrec.Error instance, for errors the Python layer finds
 * itself (the same classification as the C library's). */
static PyObject *py_error(PyObject *Py_UNUSED(mod), PyObject *args)
{
  int code;
  const char *msg;
  if (!PyArg_ParseTuple(args, "is", &code, &msg))
    return NULL;
  return make_error(code, msg);
}

static PyMethodDef module_methods[] = {
    {"tetrahedralize", py_tetrahedralize, METH_VARARGS,
     "tetrahedralize(points, triangles, markers, options) -> (CMesh, stats)"},
    {"read", py_read, METH_VARARGS,
     "read(path, resolve) -> (points, triangles, markers, segments, tets, fans)"},
    {"validate", py_validate, METH_VARARGS,
     "validate(points, triangles, markers) -> (points, triangles, markers, report)"},
    {"status_name", py_status_name, METH_VARARGS, "status_name(code) -> 'TR_ERR_...'"},
    {"error", py_error, METH_VARARGS, "error(code, message) -> tetrec.Error"},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef module_def = {PyModuleDef_HEAD_INIT, "_tetrec",
                                        "C extension of the tetrec package.", -1,
                                        module_methods, NULL, NULL, NULL, NULL};

/* The library's version as "major.minor.patch" (tr_version: the library linked in). */
static PyObject *c_version(void)
{
  int v[3];
  tr_version(&v[0], &v[1], &v[2]);
  return PyUnicode_FromFormat("%d.%d.%d", v[0], v[1], v[2]);
}

PyMODINIT_FUNC PyInit__tetrec(void)
{
  import_array();
  if (PyType_Ready(&CMeshType) < 0)
    return NULL;
  PyObject *m = PyModule_Create(&module_def);
  if (!m)
    return NULL;
  Error = PyErr_NewExceptionWithDoc(
      "tetrec.Error",
      "A failure reported by the tetrec C library: .status is the tr_status name "
      "('TR_ERR_OPEN', ...), .code its number, .message tr_last_error().",
      NULL, NULL);
  Py_ssize_t nsup = 0;
  while (SUPPORTED_OPTIONS[nsup])
    nsup++;
  PyObject *supported = PyTuple_New(nsup);
  for (Py_ssize_t i = 0; supported && i < nsup; i++) {
    PyObject *s = PyUnicode_FromString(SUPPORTED_OPTIONS[i]);
    if (!s)
      Py_CLEAR(supported);
    else
      PyTuple_SET_ITEM(supported, i, s);
  }
  /* The static pointer keeps its own reference for make_error. */
  Py_XINCREF(Error);
  if (!Error || !supported || PyModule_AddObject(m, "Error", Error) < 0 ||
      PyModule_AddObject(m, "SUPPORTED_OPTIONS", supported) < 0 ||
      PyModule_AddObject(m, "C_VERSION", c_version()) < 0) {
    Py_DECREF(m);
    return NULL;
  }
  Py_INCREF(&CMeshType);
  if (PyModule_AddObject(m, "CMesh", (PyObject *)&CMeshType) < 0) {
    Py_DECREF(m);
    return NULL;
  }
  return m;
}
