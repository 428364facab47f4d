// The compliant fold (include/orikin/compliant.h, docs/compliant.md): the bar-and-hinge model's
// static or explicit solve of a pattern, as `orikin fold --compliant` runs it (cli/fold_compliant.c),
// with its results as numpy arrays (copies: the model is freed before the call returns).
#include "pyorikin.h"

#include <math.h>

// A copy of frame-by-frame data: F × n doubles (or F × n × 3 when points).
static PyObject *frames_array(const ori_compliant *c, int F, int n, int what)
{
    npy_intp dims[3] = {F, n, 3};
    PyObject *arr = PyArray_SimpleNew(what == 0 ? 3 : 2, dims, NPY_DOUBLE);
    if (!arr) return NULL;
    double *out = PyArray_DATA((PyArrayObject *)arr);
    for (int k = 0; k < F; ++k) {
        if (what == 0) {
            const ori_v3 *x = ori_compliant_frame_positions(c, k);
            for (int v = 0; v < n; ++v) {
                out[((size_t)k * (size_t)n + (size_t)v) * 3 + 0] = x[v].x;
                out[((size_t)k * (size_t)n + (size_t)v) * 3 + 1] = x[v].y;
                out[((size_t)k * (size_t)n + (size_t)v) * 3 + 2] = x[v].z;
            }
        } else {
            const double *src = what == 1 ? ori_compliant_frame_angles(c, k) : ori_compliant_frame_strains(c, k);
            memcpy(out + (size_t)k * (size_t)n, src, sizeof(double) * (size_t)n);
        }
    }
    return arr;
}

// compliant_fold(pattern, fraction, dynamic, fix, physical, axial, facet, crease, damping, gravity,
// steps, keep_frames, tolerance, contacts, threads): the results as a dict (the CLI's --json keys; arrays in radians).
static PyObject *py_compliant_fold(PyObject *mod, PyObject *args, PyObject *kw)
{
    (void)mod;
    static char *kwlist[] = {"pattern", "fraction", "dynamic", "fix", "physical", "axial", "facet", "crease",
                             "damping", "gravity", "steps", "keep_frames", "tolerance", "contacts", "threads", NULL};
    PyObject *pobj, *axial = Py_None, *facet = Py_None, *crease = Py_None, *damping = Py_None;
    double fraction = 1.0, gravity = 0.0, tolerance = 1e-6;
    int dynamic = 0, fix = ORI_NULL_INDEX, physical = 0, steps = 1000000, keep = 0, check_contacts = 1, threads = 1;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O!|dpipOOOOdipdpi", kwlist, &ori_py_PatternType, &pobj, &fraction,
                                     &dynamic, &fix, &physical, &axial, &facet, &crease, &damping, &gravity, &steps,
                                     &keep, &tolerance, &check_contacts, &threads))
        return NULL;
    ori_py_pattern *pat = (ori_py_pattern *)pobj;
    const char *src = ori_py_pattern_source(pat);
    if (fix != ORI_NULL_INDEX && !ori_py_check_face(pat, "--fix", fix)) return NULL;
    ori_compliant_def d = physical ? ori_compliant_physical_def() : ori_default_compliant_def();
    if (axial != Py_None) d.axial_stiffness = PyFloat_AsDouble(axial);
    if (facet != Py_None) d.facet_stiffness = PyFloat_AsDouble(facet);
    if (crease != Py_None) d.crease_stiffness = d.crease_stiffness_per_m = PyFloat_AsDouble(crease);
    if (damping != Py_None) d.damping = PyFloat_AsDouble(damping);
    if (PyErr_Occurred()) return NULL;
    d.gravity = gravity;
    d.fraction = fraction;
    d.keep_frames = keep;
    d.fixed_face = fix;
    d.check_contacts = check_contacts;
    d.threads = threads;
    ori_compliant *c = NULL;
    ori_error err;
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ori_compliant_create(pat->p, &d, &c, &err);
    Py_END_ALLOW_THREADS
    if (st != ORI_OK) return ori_py_raise(src, &err);
    int done = 0;
    Py_BEGIN_ALLOW_THREADS
    st = dynamic ? ori_compliant_run_dynamic(c, steps, tolerance, &done, &err) : ori_compliant_solve_static(c, &err);
    Py_END_ALLOW_THREADS
    if (st != ORI_OK && st != ORI_ERR_NOT_CONVERGED) {
        ori_compliant_destroy(c);
        return ori_py_raise(src, &err);
    }
    int V = ori_compliant_vertex_count(c), E = ori_pattern_edge_count(pat->p), F = ori_compliant_frame_count(c);
    int NF = ori_pattern_face_count(pat->p);
    double *ang = PyMem_Malloc(sizeof(double) * (size_t)(E + NF + 1)), *str = PyMem_Malloc(sizeof(double) * (size_t)(E + 1));
    if (!ang || !str) {
        PyMem_Free(ang);
        PyMem_Free(str);
        ori_compliant_destroy(c);
        return PyErr_NoMemory();
    }
    for (int e = 0; e < E; ++e) {
        ang[e] = ori_compliant_fold_angle(c, e);
        str[e] = ori_compliant_edge_strain(c, e);
    }
    int it, fa, bt, ls;
    ori_compliant_stats(c, &it, &fa, &bt, &ls);
    npy_intp nf = F;
    PyObject *fracs = PyArray_SimpleNew(1, &nf, NPY_DOUBLE), *times = PyArray_SimpleNew(1, &nf, NPY_DOUBLE);
    double *fe = ang + E; // NF doubles after the angles
    for (int f = 0; f < NF; ++f) fe[f] = ori_compliant_face_energy(c, f);
    PyObject *face_energies = ori_py_doubles(fe, NF);
    for (int f = 0; f < NF; ++f) fe[f] = ori_compliant_face_strain(c, f);
    PyObject *face_strains = ori_py_doubles(fe, NF);
    PyObject *contacts = PyList_New(0);
    for (int k = 0; contacts && k < ori_compliant_contact_count(c); ++k) {
        int fa0, fb0, step;
        double fr;
        ori_compliant_contact(c, k, &fa0, &fb0, &step, &fr);
        PyObject *ct = ori_py_dict("faces", Py_BuildValue("(ii)", fa0, fb0), "step", PyLong_FromLong(step),
                                   "fraction", PyFloat_FromDouble(fr), NULL);
        if (!ct || PyList_Append(contacts, ct) < 0) Py_CLEAR(contacts);
        Py_XDECREF(ct);
    }
    if (fracs)
        for (int k = 0; k < F; ++k) ((double *)PyArray_DATA((PyArrayObject *)fracs))[k] = ori_compliant_frame_fraction(c, k);
    if (times)
        for (int k = 0; k < F; ++k) ((double *)PyArray_DATA((PyArrayObject *)times))[k] = ori_compliant_frame_time(c, k);
    bool reached = st == ORI_OK;
    PyObject *res = ori_py_dict(
        "solver", PyUnicode_FromString(dynamic ? "explicit" : "static"),
        "preset", PyUnicode_FromString(physical ? "physical" : "origami-simulator"),
        "reached", PyBool_FromLong(reached), "reached_fraction", PyFloat_FromDouble(ori_compliant_fraction(c)),
        "max_strain", PyFloat_FromDouble(ori_compliant_max_strain(c)), "energy", PyFloat_FromDouble(ori_compliant_energy(c)),
        "crease_error_deg", PyFloat_FromDouble(ori_compliant_crease_error(c) * 180.0 / ORI_PI),
        "gradient_norm", PyFloat_FromDouble(ori_compliant_gradient_norm(c)),
        "load_scale", PyFloat_FromDouble(ori_compliant_load_scale(c)), "vertices", PyLong_FromLong(V),
        "bars", PyLong_FromLong(ori_compliant_bar_count(c)), "hinges", PyLong_FromLong(ori_compliant_hinge_count(c)),
        "triangles", PyLong_FromLong(ori_compliant_triangle_count(c)),
        "steps", PyLong_FromLong(done), "time_step", PyFloat_FromDouble(ori_compliant_time_step(c)),
        "newton_iterations", PyLong_FromLong(it), "factorizations", PyLong_FromLong(fa),
        "backtracks", PyLong_FromLong(bt), "load_steps", PyLong_FromLong(ls),
        "fold_angles", ori_py_doubles(ang, E), "strains", ori_py_doubles(str, E),
        "positions", ori_py_points(ori_compliant_positions(c), V),
        "frame_fractions", fracs, "frame_times", times, "frame_positions", frames_array(c, F, V, 0),
        "frame_angles", frames_array(c, F, E, 1), "frame_strains", frames_array(c, F, E, 2),
        "face_energies", face_energies, "face_strains", face_strains, "contacts", contacts,
        "contacts_truncated", PyBool_FromLong(ori_compliant_contacts_truncated(c)),
        "reason", reached ? Py_NewRef(Py_None) : PyUnicode_FromString(err.message), NULL);
    PyMem_Free(ang);
    PyMem_Free(str);
    ori_compliant_destroy(c);
    return res;
}

#define KW (PyCFunction)(void (*)(void))

PyMethodDef ori_py_compliant_functions[] = {
    {"compliant_fold", KW py_compliant_fold, METH_VARARGS | METH_KEYWORDS,
     "The compliant (bar-and-hinge) fold of a pattern: a dict of the CLI's --json results, arrays as numpy."},
    {NULL, NULL, 0, NULL},
};
