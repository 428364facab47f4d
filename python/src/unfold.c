// Unfolding: a polyhedral surface cut into a net that folds back, a folded form developed into
// its crease pattern, and planar linkages straightened (Streinu).
#include "pyorikin.h"

#include <stdio.h>

// A surface from a file (OBJ, STL, FOLD) or from arrays (vertices (n, 3), faces as index lists).
static ori_mesh *read_surface(PyObject *path, PyObject *vertices, PyObject *faces, int hull, const char **source)
{
    ori_mesh *mesh = NULL;
    ori_error err;
    ori_status st;
    if (path != Py_None) {
        PyObject *b;
        if (!PyUnicode_FSConverter(path, &b)) return NULL;
        const char *p = PyBytes_AS_STRING(b);
        Py_BEGIN_ALLOW_THREADS
        st = ori_unfold_load_mesh(p, &mesh, &err);
        Py_END_ALLOW_THREADS
        if (st != ORI_OK) ori_py_raise(p, &err);
        Py_DECREF(b);
        *source = "<mesh file>";
        return mesh;
    }
    *source = hull ? "<hull>" : "<mesh>";
    PyArrayObject *v = (PyArrayObject *)PyArray_FROMANY(vertices, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY);
    if (!v || PyArray_DIM(v, 1) != 3 || PyArray_DIM(v, 0) > INT_MAX) {
        Py_XDECREF(v);
        PyErr_SetString(PyExc_ValueError, "vertices must be an (n, 3) array");
        return NULL;
    }
    int n = (int)PyArray_DIM(v, 0);
    if (hull) {
        st = ori_unfold_mesh_convex_hull(PyArray_DATA(v), n, &mesh, &err);
        Py_DECREF(v);
        if (st != ORI_OK) ori_py_raise(*source, &err);
        return mesh;
    }
    PyObject *seq = PySequence_Fast(faces, "faces must be a list of vertex index lists");
    if (!seq) {
        Py_DECREF(v);
        return NULL;
    }
    Py_ssize_t nf = PySequence_Fast_GET_SIZE(seq), total = 0;
    int *start = PyMem_Malloc(sizeof(int) * (size_t)(nf + 1));
    int *all = NULL;
    bool ok = start != NULL;
    for (Py_ssize_t f = 0; ok && f < nf; ++f) {
        Py_ssize_t k = PySequence_Size(PySequence_Fast_GET_ITEM(seq, f));
        if (k < 0) ok = false;
        total += k;
    }
    if (ok) all = PyMem_Malloc(sizeof(int) * (size_t)(total + 1));
    ok = ok && all;
    for (Py_ssize_t f = 0, at = 0; ok && f < nf; ++f) {
        int k;
        int *cyc = ori_py_int_list(PySequence_Fast_GET_ITEM(seq, f), &k, "faces[i]");
        if (!cyc) {
            ok = false;
            break;
        }
        start[f] = (int)at;
        memcpy(all + at, cyc, sizeof(int) * (size_t)k);
        at += k;
        PyMem_Free(cyc);
    }
    if (ok) {
        start[nf] = (int)total;
        for (Py_ssize_t i = 0; i < total; ++i)
            if (all[i] < 0 || all[i] >= n) {
                PyErr_Format(PyExc_ValueError, "faces: vertex %d does not exist (vertices 0 to %d)", all[i], n - 1);
                ok = false;
                break;
            }
    }
    if (ok) {
        st = ori_unfold_mesh_create(PyArray_DATA(v), n, start, all, (int)nf, &mesh, &err);
        if (st != ORI_OK) ori_py_raise(*source, &err);
    } else if (!PyErr_Occurred()) {
        PyErr_NoMemory();
    }
    PyMem_Free(start);
    PyMem_Free(all);
    Py_DECREF(seq);
    Py_DECREF(v);
    return mesh;
}

static PyObject *py_unfold(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"path", "vertices", "faces", "hull", "tries", "seed", "all", "develop", "tolerance_rad", NULL};
    PyObject *path = Py_None, *vertices = Py_None, *faces = Py_None;
    int hull = 0, all = 0, develop = 0;
    ori_unfold_def d = ori_default_unfold_def();
    double tol = 0.0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "|OOOpiIppd", kwlist, &path, &vertices, &faces, &hull, &d.tries, &d.seed, &all,
                                     &develop, &tol))
        return NULL;
    if (path == Py_None && vertices == Py_None) return PyErr_Format(PyExc_TypeError, "unfold needs a path or vertices");
    if (d.tries < 1) return PyErr_Format(PyExc_ValueError, "tries must be >= 1, got %d", d.tries);
    d.all = all;
    const char *source;
    ori_mesh *mesh = read_surface(path, vertices, faces, hull, &source);
    if (!mesh) return NULL;
    ori_unfold_net *net = NULL;
    ori_error err;
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = develop ? ori_unfold_develop(mesh, tol, &net, &err) : ori_unfold_solve(mesh, &d, &net, &err);
    Py_END_ALLOW_THREADS
    ori_unfold_mesh_destroy(mesh);
    if (st != ORI_OK) return ori_py_raise(source, &err);
    ori_unfold_result r = ori_unfold_net_result(net);
    const ori_pattern *np = ori_unfold_net_pattern(net);
    int V = ori_pattern_vertex_count(np), E = ori_pattern_edge_count(np);
    npy_intp vd[2] = {V, 3}, n1 = V, ne = E;
    PyObject *src = PyArray_SimpleNew(1, &n1, NPY_INT), *pos = PyArray_SimpleNew(2, vd, NPY_DOUBLE),
             *glue = PyArray_SimpleNew(1, &ne, NPY_INT);
    PyObject *pat = ori_py_pattern_new(ori_pattern_clone(np), NULL, NULL, develop ? "<developed>" : "<net>");
    PyObject *result = NULL;
    if (src && pos && glue && pat) {
        for (int v = 0; v < V; ++v) {
            ((int *)PyArray_DATA((PyArrayObject *)src))[v] = ori_unfold_net_vertex_source(net, v);
            ((ori_v3 *)PyArray_DATA((PyArrayObject *)pos))[v] = ori_unfold_net_vertex_position(net, v);
        }
        for (int e = 0; e < E; ++e) ((int *)PyArray_DATA((PyArrayObject *)glue))[e] = ori_unfold_net_glue(net, e);
        static const char *const orders[] = {"together", "leaves_first", "root_first"};
        PyObject *info = ori_py_dict(
            "pieces", PyLong_FromLong(r.pieces), "faces", PyLong_FromLong(r.faces), "input_faces",
            PyLong_FromLong(r.input_faces), "overlaps", PyLong_FromLong(r.overlaps), "tries", PyLong_FromLong(r.tries),
            "best_try", PyLong_FromLong(r.best_try), "refolded", PyBool_FromLong(r.refolded), "max_refold_error",
            r.max_refold_error < 0 ? Py_NewRef(Py_None) : PyFloat_FromDouble(r.max_refold_error), "motion_collides",
            PyBool_FromLong(r.motion_collides), "fold_order",
            r.fold_order == ORI_FOLD_ORDER_NONE ? Py_NewRef(Py_None) : PyUnicode_FromString(orders[r.fold_order]),
            "distinct_nets", r.distinct_nets < 0 ? Py_NewRef(Py_None) : PyLong_FromLong(r.distinct_nets), "spanning_trees",
            PyLong_FromLong(r.spanning_trees), "overlap_free_trees", PyLong_FromLong(r.overlap_free_trees), "cuts",
            PyLong_FromLong(r.cuts), "developed", PyBool_FromLong(r.developed), "fold_residual",
            r.fold_residual < 0 ? Py_NewRef(Py_None) : PyFloat_FromDouble(r.fold_residual), "vertex_source", Py_NewRef(src),
            "vertex_position", Py_NewRef(pos), "glue", Py_NewRef(glue), NULL);
        if (info) result = Py_BuildValue("(ON)", pat, info);
    }
    Py_XDECREF(src);
    Py_XDECREF(pos);
    Py_XDECREF(glue);
    Py_XDECREF(pat);
    ori_unfold_net_destroy(net);
    return result;
}

static PyObject *py_unfold_linkage(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"coords", "edges", "steps_per_event", "max_events", NULL};
    PyObject *cobj, *eobj;
    ori_linkage_def d = ori_default_linkage_def();
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|ii", kwlist, &cobj, &eobj, &d.steps_per_event, &d.max_events)) return NULL;
    PyArrayObject *c = (PyArrayObject *)PyArray_FROMANY(cobj, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY);
    PyArrayObject *e = c ? (PyArrayObject *)PyArray_FROMANY(eobj, NPY_INT, 2, 2, NPY_ARRAY_IN_ARRAY | NPY_ARRAY_FORCECAST) : NULL;
    if (!c || !e || PyArray_DIM(c, 1) != 2 || PyArray_DIM(e, 1) != 2 || PyArray_DIM(c, 0) > INT_MAX ||
        PyArray_DIM(e, 0) > INT_MAX) {
        Py_XDECREF(c);
        Py_XDECREF(e);
        PyErr_SetString(PyExc_ValueError, "a linkage is coords (n, 2) and edges (m, 2)");
        return NULL;
    }
    int n = (int)PyArray_DIM(c, 0), m = (int)PyArray_DIM(e, 0);
    const int *ev = PyArray_DATA(e);
    for (int i = 0; i < 2 * m; ++i)
        if (ev[i] < 0 || ev[i] >= n) {
            Py_DECREF(c);
            Py_DECREF(e);
            return ori_py_raise_value("<linkage>", "edges", "bar %d: vertex %d does not exist (vertices 0 to %d)", i / 2, ev[i],
                                      n - 1);
        }
    d.coords = PyArray_DATA(c);
    d.vertex_count = n;
    d.edges = ev;
    d.edge_count = m;
    ori_linkage_motion *mo = NULL;
    ori_error err;
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ori_linkage_unfold(&d, &mo, &err);
    Py_END_ALLOW_THREADS
    Py_DECREF(c);
    Py_DECREF(e);
    if (st != ORI_OK) return ori_py_raise("<linkage>", &err);
    int K = ori_linkage_motion_frame_count(mo);
    npy_intp dims[3] = {K, n, 2}, nk = K;
    PyObject *frames = PyArray_SimpleNew(3, dims, NPY_DOUBLE), *events = PyArray_SimpleNew(1, &nk, NPY_BOOL);
    PyObject *result = NULL;
    if (frames && events) {
        for (int k = 0; k < K; ++k) {
            memcpy((double *)PyArray_DATA((PyArrayObject *)frames) + (size_t)k * n * 2, ori_linkage_motion_frame(mo, k),
                   sizeof(ori_v2) * (size_t)n);
            ((npy_bool *)PyArray_DATA((PyArrayObject *)events))[k] = ori_linkage_motion_frame_is_event(mo, k);
        }
        ori_linkage_result r = ori_linkage_motion_result(mo);
        result = ori_py_dict("kind", PyUnicode_FromString(r.kind == ORI_LINKAGE_CHAIN ? "chain" : "polygon"), "frames",
                             Py_NewRef(frames), "events", Py_NewRef(events), "flips", PyLong_FromLong(r.flips),
                             "straightened", PyLong_FromLong(r.straightened), "final_ok", PyBool_FromLong(r.final_ok),
                             "max_length_error", PyFloat_FromDouble(r.max_length_error), "min_distance_change",
                             PyFloat_FromDouble(r.min_distance_change), NULL);
    }
    Py_XDECREF(frames);
    Py_XDECREF(events);
    ori_linkage_motion_destroy(mo);
    return result;
}

#define KW (PyCFunction)(void (*)(void))
PyMethodDef ori_py_unfold_functions[] = {
    {"unfold", KW py_unfold, METH_VARARGS | METH_KEYWORDS, "A surface to a net that folds back (or developed): (pattern, info)."},
    {"unfold_linkage", KW py_unfold_linkage, METH_VARARGS | METH_KEYWORDS, "Straighten or convexify a planar linkage."},
    {NULL, NULL, 0, NULL},
};
