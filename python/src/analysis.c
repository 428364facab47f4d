// Analyses of a pattern: local flat-foldability (check), regularisation, degrees of freedom and
// the layer orders (orikin._orikin.Layers).
#include "pyorikin.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static PyObject *mv_count(ori_mv_count c)
{
    // Exact; beyond 64 bits only "more than 2^64" is known.
    if (c.overflow) return Py_NewRef(Py_None);
    return PyLong_FromUnsignedLongLong(c.count);
}

static PyObject *truth(ori_flat_truth t)
{
    if (t == ORI_FLAT_UNDETERMINED) return Py_NewRef(Py_None);
    return PyBool_FromLong(t == ORI_FLAT_YES);
}

PyObject *ori_py_pattern_check(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"tolerance_rad", NULL};
    ori_py_pattern *pat = (ori_py_pattern *)self;
    double tol = 0.0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "|d", kwlist, &tol)) return NULL;
    if (!(tol >= 0.0)) return PyErr_Format(PyExc_ValueError, "tolerance must be an angle >= 0, got %g", tol);
    ori_flat_check_def d = ori_default_flat_check_def();
    d.tolerance_rad = tol;
    ori_flat_report *rep;
    Py_BEGIN_ALLOW_THREADS
    rep = ori_flat_check_pattern(pat->p, &d);
    Py_END_ALLOW_THREADS
    int nv = ori_flat_report_vertex_count(rep), nviol = ori_flat_report_violation_count(rep);
    PyObject *verts = PyList_New(nv), *viols = PyList_New(nviol);
    int cap = 8;
    int *edges = PyMem_Malloc(sizeof(int) * (size_t)cap);
    double *sectors = PyMem_Malloc(sizeof(double) * (size_t)cap);
    bool ok = verts && viols && edges && sectors;
    for (int i = 0; ok && i < nv; ++i) {
        ori_vertex_report r = ori_flat_report_vertex(rep, i);
        if (r.degree > cap) {
            cap = r.degree;
            PyMem_Free(edges);
            PyMem_Free(sectors);
            edges = PyMem_Malloc(sizeof(int) * (size_t)cap);
            sectors = PyMem_Malloc(sizeof(double) * (size_t)cap);
            if (!edges || !sectors) {
                ok = false;
                break;
            }
        }
        int n = ori_flat_report_vertex_creases(rep, i, edges, sectors, cap);
        PyObject *v = ori_py_dict(
            "vertex", PyLong_FromLong(r.vertex), "degree", PyLong_FromLong(r.degree), "creases", ori_py_ints(edges, n),
            "sectors_rad", ori_py_doubles(sectors, n), "mountains", PyLong_FromLong(r.mountains), "valleys",
            PyLong_FromLong(r.valleys), "unassigned", PyLong_FromLong(r.unassigned), "sector_sum_rad",
            PyFloat_FromDouble(r.sector_sum_rad), "kawasaki_rad", PyFloat_FromDouble(r.kawasaki_rad), "cone",
            PyBool_FromLong(r.cone), "kawasaki", PyBool_FromLong(r.kawasaki), "maekawa", truth(r.maekawa),
            "big_little_big", PyBool_FromLong(r.big_little_big), "mv_count", mv_count(r.mv_count), "assignment_valid",
            PyBool_FromLong(r.assignment_valid), "completions", mv_count(r.completions), "flat_foldable",
            PyBool_FromLong(r.flat_foldable), "within_tolerance", PyBool_FromLong(r.within_tolerance), "deviation_rad",
            PyFloat_FromDouble(r.deviation_rad), NULL);
        if (!v) ok = false;
        else PyList_SET_ITEM(verts, i, v);
    }
    for (int i = 0; ok && i < nviol; ++i) {
        ori_flat_violation v = ori_flat_report_violation(rep, i);
        PyObject *o = ori_py_dict("vertex", PyLong_FromLong(v.vertex), "rule", PyUnicode_FromString(ori_flat_rule_name(v.rule)),
                                  "edge", v.edge < 0 ? Py_NewRef(Py_None) : PyLong_FromLong(v.edge), "value",
                                  PyFloat_FromDouble(v.value), "detail", PyUnicode_FromString(v.detail), NULL);
        if (!o) ok = false;
        else PyList_SET_ITEM(viols, i, o);
    }
    PyMem_Free(edges);
    PyMem_Free(sectors);
    PyObject *result = NULL;
    if (ok)
        result = ori_py_dict("flat_foldable", PyBool_FromLong(ori_flat_report_flat_foldable(rep)), "interior_count",
                             PyLong_FromLong(ori_flat_report_interior_count(rep)), "failed_count",
                             PyLong_FromLong(ori_flat_report_failed_count(rep)), "within_count",
                             PyLong_FromLong(ori_flat_report_within_count(rep)), "max_deviation_rad",
                             PyFloat_FromDouble(ori_flat_report_max_deviation(rep)), "vertices", Py_NewRef(verts),
                             "violations", Py_NewRef(viols), NULL);
    Py_XDECREF(verts);
    Py_XDECREF(viols);
    ori_flat_report_destroy(rep);
    if (!ok && !PyErr_Occurred()) PyErr_NoMemory();
    return result;
}

PyObject *ori_py_pattern_regularize(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"rigid", "max_move_rel", "max_iterations", NULL};
    ori_py_pattern *pat = (ori_py_pattern *)self;
    ori_regularize_def d = ori_default_regularize_def();
    int rigid = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "|pdi", kwlist, &rigid, &d.max_move_rel, &d.max_iterations)) return NULL;
    d.rigid = rigid;
    if (!(d.max_move_rel > 0.0)) return PyErr_Format(PyExc_ValueError, "max_move must be positive, got %g", d.max_move_rel);
    if (d.max_iterations < 1) return PyErr_Format(PyExc_ValueError, "max_iterations must be >= 1, got %d", d.max_iterations);
    ori_pattern *out = NULL;
    ori_regularize_result r;
    ori_error err;
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ori_regularize(pat->p, &d, &out, &r, &err);
    Py_END_ALLOW_THREADS
    if (st != ORI_OK) return ori_py_raise(ori_py_pattern_source(pat), &err);
    PyObject *np = Py_NewRef(Py_None);
    if (out) {
        Py_DECREF(np);
        np = ori_py_pattern_new(out, NULL, pat->doc ? (PyObject *)pat : pat->templ, ori_py_pattern_source(pat));
        if (!np) return NULL;
    }
    PyObject *info = ori_py_dict(
        "converged", PyBool_FromLong(r.converged), "refused", PyBool_FromLong(r.refused), "odd_vertex",
        r.odd_vertex == ORI_NULL_INDEX ? Py_NewRef(Py_None) : PyLong_FromLong(r.odd_vertex), "interior_vertices",
        PyLong_FromLong(r.interior_vertices), "moved_vertices", PyLong_FromLong(r.moved_vertices), "iterations",
        PyLong_FromLong(r.iterations), "stopped", PyBool_FromLong(r.stopped), "max_move_rel", PyFloat_FromDouble(r.max_move_rel), "max_move_vertex",
        r.max_move_vertex == ORI_NULL_INDEX ? Py_NewRef(Py_None) : PyLong_FromLong(r.max_move_vertex), "rms_move_rel",
        PyFloat_FromDouble(r.rms_move_rel), "kawasaki_before_rad", PyFloat_FromDouble(r.kawasaki_before_rad),
        "kawasaki_after_rad", PyFloat_FromDouble(r.kawasaki_after_rad), "rigid_before", PyFloat_FromDouble(r.rigid_before),
        "rigid_after", PyFloat_FromDouble(r.rigid_after), "mode_vertices", PyLong_FromLong(r.mode_vertices),
        "crossing_edge", r.crossing_edge == ORI_NULL_INDEX ? Py_NewRef(Py_None) : PyLong_FromLong(r.crossing_edge),
        "crossing", PyUnicode_FromString(r.crossing), "against_edge",
        r.against_edge == ORI_NULL_INDEX ? Py_NewRef(Py_None) : PyLong_FromLong(r.against_edge), NULL);
    if (!info) {
        Py_DECREF(np);
        return NULL;
    }
    return Py_BuildValue("(NN)", np, info);
}

PyObject *ori_py_pattern_dof(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"angles", "lock", "probe", "budget", "progress", NULL};
    ori_py_pattern *pat = (ori_py_pattern *)self;
    PyObject *angles = Py_None, *locks = Py_None, *progress = Py_None;
    int probe = 1, budget = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "|OOpiO", kwlist, &angles, &locks, &probe, &budget, &progress)) return NULL;
    ori_py_mechanism *mech = ori_py_pattern_mechanism(pat);
    if (!mech) return NULL;
    ori_py_progress pp;
    if (!ori_py_progress_init(&pp, progress)) return NULL;
    ori_py_state s;
    if (!ori_py_state_read(&s, pat, angles, Py_None)) return NULL;
    int nl;
    int *lk = ori_py_int_list(locks, &nl, "lock");
    if (!lk) {
        ori_py_state_free(&s);
        return NULL;
    }
    for (int i = 0; i < nl; ++i)
        if (!ori_py_check_edge(pat, "--lock", lk[i])) {
            PyMem_Free(lk);
            ori_py_state_free(&s);
            return NULL;
        }
    ori_dof_def d = ori_default_dof_def();
    d.angles_rad = s.angles;
    d.locked_edges = lk;
    d.locked_count = nl;
    d.probe_generic = probe;
    d.probe_budget = budget;
    d.progress = ori_py_progress_fn;
    d.progress_user = &pp;
    ori_dof_result r;
    ori_error err;
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ori_mechanism_dof(mech->m, &d, &r, &err);
    Py_END_ALLOW_THREADS
    PyMem_Free(lk);
    ori_py_state_free(&s);
    if (st != ORI_OK) return ori_py_solve_failed(&pp, ori_py_pattern_source(pat), &err);
    if (ori_py_progress_raise(&pp)) return NULL;
    return ori_py_dict("grubler", PyLong_FromLong(r.grubler), "unknowns", PyLong_FromLong(r.unknowns), "equations",
                       PyLong_FromLong(r.equations), "rank", PyLong_FromLong(r.rank), "dof", PyLong_FromLong(r.dof),
                       "generic_dof", r.generic_dof < 0 ? Py_NewRef(Py_None) : PyLong_FromLong(r.generic_dof), "singular",
                       PyBool_FromLong(r.singular), "rigid", PyBool_FromLong(r.rigid), "undetermined",
                       PyBool_FromLong(r.undetermined), "probe_solves", PyLong_FromLong(r.probe_solves), "dense",
                       PyBool_FromLong(r.dense), "sigma_max", PyFloat_FromDouble(r.sigma_max), "sigma_cut",
                       PyFloat_FromDouble(r.sigma_cut), NULL);
}

// --- layers ------------------------------------------------------------------------------------

typedef struct ori_py_layers {
    PyObject_HEAD
    ori_layers *l;
    PyObject *pattern;
    bool busy; // count() runs without the GIL: the solver is not to be touched meanwhile
} ori_py_layers;

static bool layers_free(ori_py_layers *self)
{
    if (!self->busy) return true;
    PyErr_SetString(PyExc_RuntimeError, "this Layers object is counting in another thread");
    return false;
}

static void layers_dealloc(PyObject *obj)
{
    ori_py_layers *self = (ori_py_layers *)obj;
    ori_layers_destroy(self->l);
    Py_XDECREF(self->pattern);
    PyObject_Free(obj);
}

static const char *layers_source(const ori_py_layers *self) { return ori_py_pattern_source((ori_py_pattern *)self->pattern); }

// A decimal string handed out by the library as a Python int (exact, however large).
static PyObject *big(char *decimal)
{
    if (!decimal) return PyErr_NoMemory();
    PyObject *n = PyLong_FromString(decimal, NULL, 10);
    ori_buffer_free(decimal);
    return n;
}

PyObject *ori_py_pattern_layers(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"limit", "threads", "count", "progress", NULL};
    ori_py_pattern *pat = (ori_py_pattern *)self;
    PyObject *limit = Py_None, *progress = Py_None;
    int threads = 1, count = 1;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "|OipO", kwlist, &limit, &threads, &count, &progress)) return NULL;
    ori_layers_def d = ori_default_layers_def();
    if (limit != Py_None) {
        unsigned long long v = PyLong_AsUnsignedLongLong(limit);
        if (PyErr_Occurred()) return NULL;
        if (v == 0) return PyErr_Format(PyExc_ValueError, "limit must be a positive count, or None");
        d.limit = v;
    }
    if (threads < 1) return PyErr_Format(PyExc_ValueError, "threads must be >= 1, got %d", threads);
    d.threads = threads;
    ori_py_progress pp;
    if (!ori_py_progress_init(&pp, progress)) return NULL;
    d.progress = ori_py_progress_fn;
    d.progress_user = &pp;
    ori_py_layers *L = PyObject_New(ori_py_layers, &ori_py_LayersType);
    if (!L) return NULL;
    L->l = NULL;
    L->busy = false;
    L->pattern = Py_NewRef(self);
    ori_error err;
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ori_layers_create(pat->p, &d, &L->l, &err);
    if (st == ORI_OK && count) st = ori_layers_count(L->l, &err);
    Py_END_ALLOW_THREADS
    if (st != ORI_OK) {
        Py_DECREF(L);
        return ori_py_solve_failed(&pp, ori_py_pattern_source(pat), &err);
    }
    if (ori_py_progress_raise(&pp)) {
        Py_DECREF(L);
        return NULL;
    }
    return (PyObject *)L;
}

static PyObject *layers_count(PyObject *obj, PyObject *args, PyObject *kw)
{
    ori_py_layers *self = (ori_py_layers *)obj;
    if (!layers_free(self)) return NULL;
    ori_error err;
    ori_status st;
    self->busy = true;
    Py_BEGIN_ALLOW_THREADS
    st = ori_layers_count(self->l, &err);
    Py_END_ALLOW_THREADS
    self->busy = false;
    if (st != ORI_OK) return ori_py_raise(layers_source(self), &err);
    Py_RETURN_NONE;
}

static PyObject *layers_info(PyObject *obj, PyObject *args)
{
    ori_py_layers *self = (ori_py_layers *)obj;
    if (!layers_free(self)) return NULL;
    ori_layers_info i = ori_layers_get_info(self->l);
    PyObject *d = ori_py_dict(
        "faces", PyLong_FromLong(i.faces), "variables", PyLong_FromLong(i.variables), "taco_taco",
        PyLong_FromLongLong(i.taco_taco), "taco_tortilla", PyLong_FromLongLong(i.taco_tortilla), "tortilla_tortilla",
        PyLong_FromLongLong(i.tortilla_tortilla), "transitivity", PyLong_FromLongLong(i.transitivity), "points",
        PyLong_FromLong(i.points), "segments", PyLong_FromLong(i.segments), "cells", PyLong_FromLong(i.cells), "classes",
        PyLong_FromLong(i.classes), "fixed_variables", PyLong_FromLong(i.fixed_variables), "components",
        PyLong_FromLong(i.components), "counted", PyBool_FromLong(i.counted), "limited", PyBool_FromLong(i.limited),
        "satisfiable", PyBool_FromLong(i.satisfiable), NULL);
    return d;
}

static PyObject *layers_states(PyObject *obj, PyObject *args)
{
    ori_py_layers *self = (ori_py_layers *)obj;
    if (!layers_free(self)) return NULL;
    if (!ori_layers_get_info(self->l).counted) return PyErr_Format(PyExc_ValueError, "the states are not counted yet");
    return big(ori_layers_state_count(self->l));
}

static PyObject *layers_components(PyObject *obj, PyObject *args)
{
    ori_py_layers *self = (ori_py_layers *)obj;
    if (!layers_free(self)) return NULL;
    bool counted = ori_layers_get_info(self->l).counted;
    int n = ori_layers_component_count(self->l);
    PyObject *out = PyList_New(n);
    for (int c = 0; out && c < n; ++c) {
        PyObject *states = counted ? big(ori_layers_component_states(self->l, c)) : Py_NewRef(Py_None);
        PyObject *t = states ? Py_BuildValue("(Ni)", states, ori_layers_component_variables(self->l, c)) : NULL;
        if (!t) {
            Py_CLEAR(out);
            return NULL;
        }
        PyList_SET_ITEM(out, c, t);
    }
    return out;
}

static PyObject *layers_conflict(PyObject *obj, PyObject *args)
{
    ori_py_layers *self = (ori_py_layers *)obj;
    if (!layers_free(self)) return NULL;
    ori_layers_conflict c;
    if (!ori_layers_get_conflict(self->l, &c)) Py_RETURN_NONE;
    int n = ori_layers_conflict_faces(self->l, NULL, 0);
    int *faces = PyMem_Malloc(sizeof(int) * (size_t)(n + 1));
    if (!faces) return PyErr_NoMemory();
    ori_layers_conflict_faces(self->l, faces, n);
    PyObject *d = ori_py_dict("constraint", PyUnicode_FromString(ori_layers_constraint_name(c.constraint)), "faces",
                              ori_py_ints(c.faces, c.face_count), "vertex",
                              c.vertex == ORI_NULL_INDEX ? Py_NewRef(Py_None) : PyLong_FromLong(c.vertex), "component",
                              c.component < 0 ? Py_NewRef(Py_None) : PyLong_FromLong(c.component), "kawasaki_rad",
                              PyFloat_FromDouble(c.kawasaki_rad), "detail", PyUnicode_FromString(c.detail),
                              "involved_faces", ori_py_ints(faces, n), NULL);
    PyMem_Free(faces);
    return d;
}

static PyObject *layers_select(PyObject *obj, PyObject *args)
{
    ori_py_layers *self = (ori_py_layers *)obj;
    if (!layers_free(self)) return NULL;
    PyObject *k;
    if (!PyArg_ParseTuple(args, "O!", &PyLong_Type, &k)) return NULL;
    PyObject *s = PyObject_Str(k);
    if (!s) return NULL;
    ori_error err;
    ori_status st = ori_layers_select_state(self->l, PyUnicode_AsUTF8(s), &err);
    Py_DECREF(s);
    if (st == ORI_ERR_RANGE) return ori_py_raise_value(NULL, "--state", "%s", err.message); // as `orikin layers`
    if (st != ORI_OK) return ori_py_raise(layers_source(self), &err);
    Py_RETURN_NONE;
}

static PyObject *layers_face_orders(PyObject *obj, PyObject *args)
{
    ori_py_layers *self = (ori_py_layers *)obj;
    if (!layers_free(self)) return NULL;
    int n = ori_layers_face_orders(self->l, NULL, 0);
    npy_intp dims[2] = {n, 3};
    PyObject *arr = PyArray_SimpleNew(2, dims, NPY_INT);
    if (arr) ori_layers_face_orders(self->l, PyArray_DATA((PyArrayObject *)arr), n);
    return arr;
}

static PyObject *layers_folded(PyObject *obj, PyObject *args)
{
    ori_py_layers *self = (ori_py_layers *)obj;
    if (!layers_free(self)) return NULL;
    const ori_pattern *p = ((ori_py_pattern *)self->pattern)->p;
    npy_intp V = ori_pattern_vertex_count(p), F = ori_pattern_face_count(p), dims[2] = {V, 2};
    PyObject *xy = PyArray_SimpleNew(2, dims, NPY_DOUBLE), *flip = PyArray_SimpleNew(1, &F, NPY_BOOL);
    if (!xy || !flip) {
        Py_XDECREF(xy);
        Py_XDECREF(flip);
        return NULL;
    }
    double *o = PyArray_DATA((PyArrayObject *)xy);
    for (npy_intp v = 0; v < V; ++v) {
        ori_v2 q = ori_layers_folded_vertex(self->l, (int)v);
        o[2 * v] = q.x, o[2 * v + 1] = q.y;
    }
    npy_bool *fl = PyArray_DATA((PyArrayObject *)flip);
    for (npy_intp f = 0; f < F; ++f) fl[f] = ori_layers_face_flipped(self->l, (int)f);
    return Py_BuildValue("(NN)", xy, flip);
}

static PyObject *layers_svg(PyObject *obj, PyObject *args)
{
    ori_py_layers *self = (ori_py_layers *)obj;
    if (!layers_free(self)) return NULL;
    char *text = NULL;
    size_t size = 0;
    ori_error err;
    if (ori_layers_svg(self->l, ((ori_py_pattern *)self->pattern)->p, &text, &size, &err) != ORI_OK)
        return ori_py_raise(layers_source(self), &err);
    PyObject *s = PyUnicode_FromStringAndSize(text, (Py_ssize_t)size);
    ori_buffer_free(text);
    return s;
}

// The selected state as FOLD text: the pattern's document with the state appended as a
// foldedForm frame (as `orikin layers --state K -o OUT.fold`).
static PyObject *layers_to_fold_text(PyObject *obj, PyObject *args)
{
    ori_py_layers *self = (ori_py_layers *)obj;
    if (!layers_free(self)) return NULL;
    ori_py_pattern *pat = (ori_py_pattern *)self->pattern;
    PyObject *text = PyObject_CallMethod(self->pattern, "to_fold_text", NULL);
    if (!text) return NULL;
    Py_ssize_t n;
    const char *t = PyUnicode_AsUTF8AndSize(text, &n);
    ori_fold *doc = NULL;
    ori_error err;
    ori_status st = t ? ori_fold_load_string(t, (size_t)n, &doc, &err) : ORI_ERR_PARSE;
    Py_DECREF(text);
    if (!t) return NULL;
    if (st != ORI_OK) return ori_py_raise(layers_source(self), &err);
    if (ori_layers_append_frame(self->l, pat->p, doc, pat->frame, &err) < 0) {
        ori_fold_destroy(doc);
        return ori_py_raise(layers_source(self), &err);
    }
    char *out = ori_fold_to_string(doc);
    ori_fold_destroy(doc);
    PyObject *s = PyUnicode_FromString(out);
    ori_buffer_free(out);
    return s;
}

static PyMethodDef layers_methods[] = {
    {"count", (PyCFunction)(void (*)(void))layers_count, METH_VARARGS | METH_KEYWORDS, "Count the states (a no-op when counted)."},
    {"info", layers_info, METH_NOARGS, "Problem sizes and the verdict (a dict)."},
    {"states", layers_states, METH_NOARGS, "The number of flat-folded states (an exact int)."},
    {"components", layers_components, METH_NOARGS, "Per independent component: (states, variables)."},
    {"conflict", layers_conflict, METH_NOARGS, "Why there is no state (a dict), or None."},
    {"select", layers_select, METH_VARARGS, "select(k): choose state k (0 <= k < states)."},
    {"face_orders", layers_face_orders, METH_NOARGS, "FOLD faceOrders of the selected state, (n, 3)."},
    {"folded", layers_folded, METH_NOARGS, "(folded vertex positions (V, 2), faces flipped (F,))."},
    {"svg", layers_svg, METH_NOARGS, "The crease pattern and the selected state drawn as SVG text."},
    {"to_fold_text", layers_to_fold_text, METH_NOARGS, "The pattern's FOLD with the selected state appended."},
    {NULL, NULL, 0, NULL},
};

PyTypeObject ori_py_LayersType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "orikin._orikin.Layers",
    .tp_basicsize = sizeof(ori_py_layers),
    .tp_dealloc = layers_dealloc,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "The layer-order solver of a pattern (ori_layers): global flat-foldability.",
    .tp_methods = layers_methods,
};

PyMethodDef ori_py_analysis_functions[] = {{NULL, NULL, 0, NULL}};
