// orikin._orikin: module set-up, the exceptions, numpy views, progress callbacks.
#define ORI_PY_MODULE_C
#include "pyorikin.h"

#include <stdarg.h>
#include <stdio.h>

PyObject *ori_py_Error, *ori_py_InputError, *ori_py_SolveError, *ori_py_Cancelled;

// --- errors ---------------------------------------------------------------------------------

// Raise cls(message) with the attributes of the error (NULL error: none but option).
static PyObject *raise_with(PyObject *cls, const char *message, const ori_error *error, const char *option)
{
    PyObject *exc = PyObject_CallFunction(cls, "s", message);
    if (!exc) return NULL;
    PyObject *status = PyUnicode_FromString(error ? ori_status_name(error->status) : "ERR_RANGE");
    PyObject *element = error && error->element != ORI_NULL_INDEX ? PyLong_FromLong(error->element) : Py_NewRef(Py_None);
    PyObject *field = error && error->field[0] ? PyUnicode_FromString(error->field) : Py_NewRef(Py_None);
    PyObject *line = error && error->line > 0 ? PyLong_FromLong(error->line) : Py_NewRef(Py_None);
    PyObject *column = error && error->column > 0 ? PyLong_FromLong(error->column) : Py_NewRef(Py_None);
    PyObject *opt = option ? PyUnicode_FromString(option) : Py_NewRef(Py_None);
    PyObject *msg = PyUnicode_FromString(error ? error->message : message);
    bool ok = status && element && field && line && column && opt && msg &&
              PyObject_SetAttrString(exc, "status", status) == 0 && PyObject_SetAttrString(exc, "element", element) == 0 &&
              PyObject_SetAttrString(exc, "field", field) == 0 && PyObject_SetAttrString(exc, "line", line) == 0 &&
              PyObject_SetAttrString(exc, "column", column) == 0 && PyObject_SetAttrString(exc, "option", opt) == 0 &&
              PyObject_SetAttrString(exc, "reason", msg) == 0;
    Py_XDECREF(status);
    Py_XDECREF(element);
    Py_XDECREF(field);
    Py_XDECREF(line);
    Py_XDECREF(column);
    Py_XDECREF(opt);
    Py_XDECREF(msg);
    if (ok) PyErr_SetObject(cls, exc);
    Py_DECREF(exc);
    return NULL;
}

PyObject *ori_py_raise(const char *source, const ori_error *error)
{
    if (error->status == ORI_ERR_NOMEM) return PyErr_NoMemory();
    char buf[512], line[1024];
    ori_error_format(error, buf, sizeof buf);
    if (source) snprintf(line, sizeof line, "%s: %s", source, buf);
    else snprintf(line, sizeof line, "%s", buf);
    PyObject *cls = ori_py_InputError;
    if (error->status == ORI_ERR_NOT_CONVERGED || error->status == ORI_ERR_INTERNAL) cls = ori_py_SolveError;
    else if (error->status == ORI_ERR_LIMIT && strcmp(error->message, "cancelled") == 0) cls = ori_py_Cancelled;
    return raise_with(cls, line, error, NULL);
}

PyObject *ori_py_raise_value(const char *source, const char *option, const char *fmt, ...)
{
    char msg[512], line[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (source) snprintf(line, sizeof line, "%s: %s: %s", source, option, msg);
    else snprintf(line, sizeof line, "%s: %s", option, msg);
    ori_error e;
    ori_error_clear(&e);
    e.status = ORI_ERR_RANGE;
    snprintf(e.message, sizeof e.message, "%.255s", msg);
    return raise_with(ori_py_InputError, line, &e, option);
}

// --- progress --------------------------------------------------------------------------------

bool ori_py_progress_init(ori_py_progress *pp, PyObject *callback)
{
    memset(pp, 0, sizeof *pp);
    if (callback && callback != Py_None) {
        if (!PyCallable_Check(callback)) {
            PyErr_SetString(PyExc_TypeError, "progress must be a callable taking the fraction done (0 to 1), or None");
            return false;
        }
        pp->callback = callback;
    }
    return true;
}

bool ori_py_progress_fn(double fraction, void *user)
{
    ori_py_progress *pp = user;
    if (pp->exc_type) return false;
    PyGILState_STATE g = PyGILState_Ensure();
    bool go = true;
    pp->called = true;
    if (PyErr_CheckSignals() < 0) {
        go = false;
    } else if (pp->callback) {
        PyObject *r = PyObject_CallFunction(pp->callback, "d", fraction);
        if (!r) go = false;
        else go = r == Py_None || PyObject_IsTrue(r) == 1;
        Py_XDECREF(r);
    }
    if (PyErr_Occurred()) PyErr_Fetch(&pp->exc_type, &pp->exc_value, &pp->exc_tb);
    PyGILState_Release(g);
    return go;
}

bool ori_py_progress_raise(ori_py_progress *pp)
{
    if (!pp->exc_type) return false;
    PyErr_Restore(pp->exc_type, pp->exc_value, pp->exc_tb);
    pp->exc_type = pp->exc_value = pp->exc_tb = NULL;
    return true;
}

PyObject *ori_py_solve_failed(ori_py_progress *pp, const char *source, const ori_error *error)
{
    if (pp && ori_py_progress_raise(pp)) return NULL;
    return ori_py_raise(source, error);
}

// --- numpy -------------------------------------------------------------------------------------

PyObject *ori_py_view(PyObject *owner, int type, int nd, const npy_intp *dims, const npy_intp *strides,
                      const void *data)
{
    PyArray_Descr *descr = PyArray_DescrFromType(type);
    if (!descr) return NULL;
    // Without NPY_ARRAY_WRITEABLE: numpy refuses writes, and since the base owns no writable
    // buffer it refuses `flags.writeable = True` too.
    PyObject *arr = PyArray_NewFromDescr(&PyArray_Type, descr, nd, (npy_intp *)dims, (npy_intp *)strides,
                                         (void *)data, NPY_ARRAY_ALIGNED, NULL);
    if (!arr) return NULL;
    Py_INCREF(owner);
    if (PyArray_SetBaseObject((PyArrayObject *)arr, owner) < 0) {
        Py_DECREF(arr);
        return NULL;
    }
    return arr;
}

PyObject *ori_py_doubles(const double *v, npy_intp n)
{
    PyObject *arr = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    if (arr && n > 0) memcpy(PyArray_DATA((PyArrayObject *)arr), v, sizeof(double) * (size_t)n);
    return arr;
}

PyObject *ori_py_points(const ori_v3 *v, npy_intp n)
{
    npy_intp dims[2] = {n, 3};
    PyObject *arr = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    if (arr && n > 0) memcpy(PyArray_DATA((PyArrayObject *)arr), v, sizeof(ori_v3) * (size_t)n);
    return arr;
}

PyObject *ori_py_ints(const int *v, npy_intp n)
{
    PyObject *arr = PyArray_SimpleNew(1, &n, NPY_INT);
    if (arr && n > 0) memcpy(PyArray_DATA((PyArrayObject *)arr), v, sizeof(int) * (size_t)n);
    return arr;
}

PyArrayObject *ori_py_double_array(PyObject *obj, npy_intp n, int cols, const char *what)
{
    PyArrayObject *a = (PyArrayObject *)PyArray_FROMANY(obj, NPY_DOUBLE, cols > 0 ? 2 : 1, cols > 0 ? 2 : 1,
                                                        NPY_ARRAY_IN_ARRAY);
    if (!a) {
        PyErr_Format(PyExc_ValueError, "%s must be %s of numbers", what, cols > 0 ? "a 2-D array" : "a 1-D array");
        return NULL;
    }
    bool ok = PyArray_DIM(a, 0) == n && (cols <= 0 || PyArray_DIM(a, 1) == cols);
    if (!ok) {
        if (cols > 0)
            PyErr_Format(PyExc_ValueError, "%s must have shape (%zd, %d), got (%zd, %zd)", what, (Py_ssize_t)n, cols,
                         (Py_ssize_t)PyArray_DIM(a, 0), (Py_ssize_t)PyArray_DIM(a, 1));
        else
            PyErr_Format(PyExc_ValueError, "%s must have %zd entries, got %zd", what, (Py_ssize_t)n,
                         (Py_ssize_t)PyArray_DIM(a, 0));
        Py_DECREF(a);
        return NULL;
    }
    return a;
}

int *ori_py_int_list(PyObject *obj, int *count, const char *what)
{
    *count = 0;
    if (!obj || obj == Py_None) return PyMem_Malloc(sizeof(int));
    PyObject *seq = PySequence_Fast(obj, what);
    if (!seq) return NULL;
    Py_ssize_t n = PySequence_Fast_GET_SIZE(seq);
    if (n > INT_MAX - 1) {
        Py_DECREF(seq);
        PyErr_Format(PyExc_ValueError, "%s: too many entries", what);
        return NULL;
    }
    int *out = PyMem_Malloc(sizeof(int) * (size_t)(n + 1));
    if (!out) {
        Py_DECREF(seq);
        PyErr_NoMemory();
        return NULL;
    }
    for (Py_ssize_t i = 0; i < n; ++i) {
        long v = PyLong_AsLong(PySequence_Fast_GET_ITEM(seq, i));
        if ((v == -1 && PyErr_Occurred()) || v < INT_MIN || v > INT_MAX) {
            PyErr_Clear();
            PyErr_Format(PyExc_TypeError, "%s must hold integers (FOLD indices)", what);
            PyMem_Free(out);
            Py_DECREF(seq);
            return NULL;
        }
        out[i] = (int)v;
    }
    Py_DECREF(seq);
    *count = (int)n;
    return out;
}

PyObject *ori_py_v3(ori_v3 v) { return Py_BuildValue("(ddd)", v.x, v.y, v.z); }

bool ori_py_read_v2(PyObject *obj, ori_v2 *out, const char *what)
{
    if (!PySequence_Check(obj) || PySequence_Size(obj) != 2) {
        PyErr_Clear();
        PyErr_Format(PyExc_TypeError, "%s must be a point (x, y)", what);
        return false;
    }
    double c[2];
    for (int i = 0; i < 2; ++i) {
        PyObject *x = PySequence_GetItem(obj, i);
        c[i] = x ? PyFloat_AsDouble(x) : -1.0;
        Py_XDECREF(x);
        if (PyErr_Occurred()) {
            PyErr_Clear();
            PyErr_Format(PyExc_TypeError, "%s must be a point (x, y) of numbers", what);
            return false;
        }
    }
    *out = ori_v2_make(c[0], c[1]);
    return true;
}

PyObject *ori_py_dict(const char *key, ...)
{
    PyObject *d = PyDict_New();
    va_list ap;
    va_start(ap, key);
    bool ok = d != NULL;
    for (const char *k = key; k; k = va_arg(ap, const char *)) {
        PyObject *v = va_arg(ap, PyObject *);
        if (!v) ok = false;
        if (ok && PyDict_SetItemString(d, k, v) < 0) ok = false;
        Py_XDECREF(v);
    }
    va_end(ap);
    if (!ok) {
        Py_XDECREF(d);
        if (!PyErr_Occurred()) PyErr_NoMemory();
        return NULL;
    }
    return d;
}

// --- collisions ---------------------------------------------------------------------------------

ori_collider *ori_py_collider(const ori_py_pattern *pat, double clearance)
{
    const char *src = ori_py_pattern_source(pat);
    ori_collider_def cd = ori_default_collider_def();
    cd.pattern = pat->p;
    cd.clearance = clearance;
    ori_collider *c = NULL;
    ori_error err;
    if (ori_collider_create(&cd, &c, &err) == ORI_OK) return c;
    if (err.status == ORI_ERR_RANGE) // as the CLI words it (collide_args.c)
        ori_py_raise_value(src, "--clearance", "must be a length >= 0, got %g", clearance);
    else ori_py_raise(src, &err);
    return NULL;
}

static const char *contact_kind_name(ori_contact_kind k)
{
    return k == ORI_CONTACT_PENETRATING ? "penetrating" : k == ORI_CONTACT_NEAR ? "near" : "touching";
}

PyObject *ori_py_contact_dict(const ori_contact *c)
{
    return ori_py_dict("faces", Py_BuildValue("(ii)", c->face_a, c->face_b), "kind",
                       PyUnicode_FromString(contact_kind_name(c->kind)), "adjacent", PyBool_FromLong(c->adjacent),
                       "stacked", PyBool_FromLong(c->stacked), "collides", PyBool_FromLong(c->collides), "distance",
                       PyFloat_FromDouble(c->distance), "point", ori_py_v3(c->point), NULL);
}

PyObject *ori_py_event_dict(const ori_collision_event *ev, bool progress)
{
    PyObject *d = ori_py_contact_dict(&ev->contact);
    PyObject *more = ori_py_dict("frame", PyLong_FromLong(ev->frame), "fold", PyLong_FromLong(ev->fold), "step",
                                 PyLong_FromLong(ev->step), progress ? "progress" : "drive_rad",
                                 PyFloat_FromDouble(ev->drive_rad), "time", PyFloat_FromDouble(ev->time), NULL);
    if (!d || !more || PyDict_Update(d, more) < 0) Py_CLEAR(d);
    Py_XDECREF(more);
    return d;
}

// --- module functions ----------------------------------------------------------------------------

static PyObject *py_version(PyObject *self, PyObject *args) { return PyUnicode_FromString(ori_version_string()); }

static PyObject *py_alloc_live_count(PyObject *self, PyObject *args) { return PyLong_FromLongLong(ori_alloc_live_count()); }

static PyObject *py_alloc_live_bytes(PyObject *self, PyObject *args) { return PyLong_FromLongLong(ori_alloc_live_bytes()); }

static bool read_line(PyObject *obj, ori_line *out, const char *what)
{
    // A line is ((px, py), (dx, dy)): a point on it and a direction.
    if (!PySequence_Check(obj) || PySequence_Size(obj) != 2) {
        PyErr_Clear();
        PyErr_Format(PyExc_TypeError, "%s must be a line ((x, y), (dx, dy)): a point and a direction", what);
        return false;
    }
    PyObject *a = PySequence_GetItem(obj, 0), *b = PySequence_GetItem(obj, 1);
    ori_v2 p, d;
    bool ok = a && b && ori_py_read_v2(a, &p, what) && ori_py_read_v2(b, &d, what);
    Py_XDECREF(a);
    Py_XDECREF(b);
    if (ok) out->point = p, out->dir = d;
    return ok;
}

static PyObject *py_axiom(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"axiom", "p1", "p2", "l1", "l2", NULL};
    int n;
    PyObject *p1 = NULL, *p2 = NULL, *l1 = NULL, *l2 = NULL;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "i|OOOO", kwlist, &n, &p1, &p2, &l1, &l2)) return NULL;
    if (n < 1 || n > 7) {
        PyErr_Format(PyExc_ValueError, "axiom must be 1 to 7, got %d", n);
        return NULL;
    }
    // Which inputs each axiom reads (ori_axiom_solve): points p1, p2 and lines l1, l2.
    static const char needs[8][5] = {"", "pp", "pp", "ll", "pl", "ppl", "plpl", "pll"};
    ori_axiom_input in;
    memset(&in, 0, sizeof in);
    in.axiom = n;
    PyObject *given[4] = {p1, p2, l1, l2};
    bool want[4] = {false, false, false, false};
    int np = 0, nl = 0;
    for (const char *c = needs[n]; *c; ++c) {
        if (*c == 'p') want[np++] = true;
        else want[2 + nl++] = true;
    }
    static const char *names[4] = {"p1", "p2", "l1", "l2"};
    for (int i = 0; i < 4; ++i) {
        if (want[i] && (!given[i] || given[i] == Py_None)) {
            PyErr_Format(PyExc_TypeError, "axiom %d needs %s", n, names[i]);
            return NULL;
        }
        if (!want[i] && given[i] && given[i] != Py_None) {
            PyErr_Format(PyExc_TypeError, "axiom %d takes no %s", n, names[i]);
            return NULL;
        }
    }
    if (want[0] && !ori_py_read_v2(p1, &in.p1, "p1")) return NULL;
    if (want[1] && !ori_py_read_v2(p2, &in.p2, "p2")) return NULL;
    if (want[2] && !read_line(l1, &in.l1, "l1")) return NULL;
    if (want[3] && !read_line(l2, &in.l2, "l2")) return NULL;
    ori_line_set s = ori_axiom_solve(&in);
    PyObject *out = PyList_New(s.count);
    for (int i = 0; out && i < s.count; ++i) {
        PyObject *l = Py_BuildValue("((dd)(dd))", s.lines[i].point.x, s.lines[i].point.y, s.lines[i].dir.x,
                                    s.lines[i].dir.y);
        if (!l) {
            Py_CLEAR(out);
            break;
        }
        PyList_SET_ITEM(out, i, l);
    }
    return out;
}

static PyMethodDef module_functions[] = {
    {"version", py_version, METH_NOARGS, "The library's version string, e.g. '0.1.0'."},
    {"_alloc_live_count", py_alloc_live_count, METH_NOARGS,
     "Number of library allocations currently live (the counted allocator; tests check it returns to its start)."},
    {"_alloc_live_bytes", py_alloc_live_bytes, METH_NOARGS, "Bytes the library currently holds."},
    {"_axiom", (PyCFunction)(void (*)(void))py_axiom, METH_VARARGS | METH_KEYWORDS,
     "_axiom(n, p1, p2, l1, l2): every fold line of Huzita-Hatori axiom n as ((x, y), (dx, dy))."},
    {NULL, NULL, 0, NULL},
};

// An ORI_ASSERT that fails is a bug in the binding (it validates every input first): say where
// on stderr, then the library aborts.
static void assert_hook(const char *condition, const char *file, int line)
{
    fprintf(stderr, "orikin: internal assertion failed: %s (%s:%d)\n", condition, file, line);
    fflush(stderr);
}

static struct PyModuleDef module_def = {
    PyModuleDef_HEAD_INIT, "orikin._orikin",
    "The C extension of the orikin package: the library's objects and numpy views of their arrays.\n"
    "Use the package (import orikin); this module's names are its building blocks.",
    -1, NULL, NULL, NULL, NULL, NULL,
};

static int add_exception(PyObject *m, const char *name, PyObject **out, PyObject *bases, const char *doc)
{
    char full[64];
    snprintf(full, sizeof full, "orikin.%s", name);
    *out = PyErr_NewExceptionWithDoc(full, doc, bases, NULL);
    if (!*out) return -1;
    Py_INCREF(*out);
    return PyModule_AddObject(m, name, *out);
}

PyMODINIT_FUNC PyInit__orikin(void);
PyMODINIT_FUNC PyInit__orikin(void)
{
    import_array();
    PyTypeObject *types[] = {&ori_py_PatternType, &ori_py_MechanismType, &ori_py_MotionType, &ori_py_RecordType,
                             &ori_py_LayersType};
    for (size_t i = 0; i < sizeof types / sizeof *types; ++i)
        if (PyType_Ready(types[i]) < 0) return NULL;
    PyObject *m = PyModule_Create(&module_def);
    if (!m) return NULL;
    PyMethodDef *tables[] = {module_functions,           ori_py_pattern_functions, ori_py_motion_functions,
                             ori_py_analysis_functions,  ori_py_state_functions,   ori_py_sequence_functions,
                             ori_py_actuation_functions, ori_py_unfold_functions,  ori_py_design_functions,
                             ori_py_compliant_functions};
    for (size_t i = 0; i < sizeof tables / sizeof *tables; ++i)
        if (PyModule_AddFunctions(m, tables[i]) < 0) goto fail;
    for (size_t i = 0; i < sizeof types / sizeof *types; ++i) {
        const char *dot = strrchr(types[i]->tp_name, '.');
        Py_INCREF(types[i]);
        if (PyModule_AddObject(m, dot ? dot + 1 : types[i]->tp_name, (PyObject *)types[i]) < 0) goto fail;
    }
    if (add_exception(m, "Error", &ori_py_Error, NULL,
                      "Base of orikin's exceptions: the library's one-line message (str(e), as the CLI prints it\n"
                      "after 'orikin COMMAND: ') and where: status ('ERR_RANGE'), element (the FOLD index or None),\n"
                      "field ('edges_vertices' or None), line and column (JSON input, or None), option (the\n"
                      "argument the message names, or None) and reason (the message without its place).") < 0)
        goto fail;
    PyObject *bases = PyTuple_Pack(2, ori_py_Error, PyExc_ValueError);
    int rc = bases ? add_exception(m, "InputError", &ori_py_InputError, bases,
                                   "Bad input: a file that does not load, an index or value the pattern does not have.")
                   : -1;
    Py_XDECREF(bases);
    if (rc < 0) goto fail;
    bases = PyTuple_Pack(2, ori_py_Error, PyExc_RuntimeError);
    rc = bases ? add_exception(m, "SolveError", &ori_py_SolveError, bases,
                               "A solver that did not converge or failed internally (the CLI's exit code 4).")
               : -1;
    Py_XDECREF(bases);
    if (rc < 0) goto fail;
    if (add_exception(m, "Cancelled", &ori_py_Cancelled, ori_py_Error,
                      "A long operation stopped because its progress callback returned False.") < 0)
        goto fail;
    ori_set_assert_hook(assert_hook);
    return m;
fail:
    Py_DECREF(m);
    return NULL;
}
