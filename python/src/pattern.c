// orikin._orikin.Pattern: a built crease pattern (or folded form) with the FOLD document it came
// from. Immutable: edits (crease, apply, assign, flip, remove) return a new pattern, so that a
// motion, a record or an array viewing them never sees its pattern change.
#include "pyorikin.h"

#include <math.h>
#include <stdio.h>

// --- the object ------------------------------------------------------------------------------

PyObject *ori_py_pattern_new(ori_pattern *p, ori_fold *doc, PyObject *templ, const char *source)
{
    ori_py_pattern *self = PyObject_New(ori_py_pattern, &ori_py_PatternType);
    if (!self) {
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
        return NULL;
    }
    self->p = p;
    self->doc = doc;
    self->templ = templ;
    Py_XINCREF(templ);
    self->mech = NULL;
    self->frame = 0;
    self->source = PyUnicode_FromString(source ? source : "<pattern>");
    if (!self->source) {
        Py_DECREF(self);
        return NULL;
    }
    return (PyObject *)self;
}

static void pattern_dealloc(PyObject *obj)
{
    ori_py_pattern *self = (ori_py_pattern *)obj;
    Py_XDECREF(self->mech);
    Py_XDECREF(self->templ);
    Py_XDECREF(self->source);
    ori_pattern_destroy(self->p);
    ori_fold_destroy(self->doc);
    PyObject_Free(obj);
}

const char *ori_py_pattern_source(const ori_py_pattern *pat)
{
    const char *s = pat->source ? PyUnicode_AsUTF8(pat->source) : NULL;
    if (!s) PyErr_Clear();
    return s ? s : "<pattern>";
}

static void mechanism_dealloc(PyObject *obj)
{
    ori_mechanism_destroy(((ori_py_mechanism *)obj)->m);
    PyObject_Free(obj);
}

PyTypeObject ori_py_MechanismType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "orikin._orikin.Mechanism",
    .tp_basicsize = sizeof(ori_py_mechanism),
    .tp_dealloc = mechanism_dealloc,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "The substituted mechanical system of a crease pattern (faces = bodies, creases = joints);\n"
              "motions and records hold it while they live.",
};

ori_py_mechanism *ori_py_pattern_mechanism(ori_py_pattern *pat)
{
    if (pat->mech) return (ori_py_mechanism *)pat->mech;
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = pat->p;
    ori_mechanism *m = NULL;
    ori_error err;
    if (ori_mechanism_create(&md, &m, &err) != ORI_OK) {
        ori_py_raise(ori_py_pattern_source(pat), &err);
        return NULL;
    }
    ori_py_mechanism *mo = PyObject_New(ori_py_mechanism, &ori_py_MechanismType);
    if (!mo) {
        ori_mechanism_destroy(m);
        return NULL;
    }
    mo->m = m;
    pat->mech = (PyObject *)mo;
    return mo;
}

bool ori_py_check_face(const ori_py_pattern *pat, const char *option, int face)
{
    int n = ori_pattern_face_count(pat->p);
    if (face >= 0 && face < n) return true;
    ori_py_raise_value(ori_py_pattern_source(pat), option, "no face %d (the pattern has faces 0 to %d)", face, n - 1);
    return false;
}

bool ori_py_check_edge(const ori_py_pattern *pat, const char *option, int edge)
{
    int n = ori_pattern_edge_count(pat->p);
    if (edge >= 0 && edge < n) return true;
    ori_py_raise_value(ori_py_pattern_source(pat), option, "no edge %d (the pattern has edges 0 to %d)", edge, n - 1);
    return false;
}

bool ori_py_state_read(ori_py_state *s, const ori_py_pattern *pat, PyObject *angles, PyObject *positions)
{
    memset(s, 0, sizeof *s);
    if (angles && angles != Py_None) {
        s->angles_arr = ori_py_double_array(angles, ori_pattern_edge_count(pat->p), 0, "angles");
        if (!s->angles_arr) return false;
        s->angles = PyArray_DATA(s->angles_arr);
        for (int e = 0; e < ori_pattern_edge_count(pat->p); ++e)
            if (!isfinite(s->angles[e])) {
                PyErr_Format(PyExc_ValueError, "angles[%d] is not finite", e);
                ori_py_state_free(s);
                return false;
            }
    }
    if (positions && positions != Py_None) {
        s->positions_arr = ori_py_double_array(positions, ori_pattern_vertex_count(pat->p), 3, "positions");
        if (!s->positions_arr) {
            ori_py_state_free(s);
            return false;
        }
        s->positions = PyArray_DATA(s->positions_arr);
    }
    return true;
}

void ori_py_state_free(ori_py_state *s)
{
    Py_CLEAR(s->angles_arr);
    Py_CLEAR(s->positions_arr);
    s->angles = NULL;
    s->positions = NULL;
}

// --- making patterns ---------------------------------------------------------------------------

static bool is_drawing(const char *path)
{
    ori_format f = ori_format_from_path(path);
    return f == ORI_FORMAT_SVG || f == ORI_FORMAT_OPX || f == ORI_FORMAT_CP;
}

// The pattern of a frame of a loaded document, as the CLI loads it (cli_load_pattern).
static PyObject *pattern_of_doc(ori_fold *doc, int frame, bool weld, const char *source)
{
    int frames = ori_fold_frame_count(doc);
    if (frame < 0 || frame >= frames) {
        ori_fold_destroy(doc);
        return ori_py_raise_value(source, "--frame", "frame %d does not exist (frames 0 to %d)", frame, frames - 1);
    }
    ori_build_def def = ori_default_build_def();
    def.weld = weld;
    def.planarize = true;
    ori_pattern *p = NULL;
    ori_error err;
    if (ori_fold_get_pattern(doc, frame, &def, &p, &err) != ORI_OK) {
        ori_fold_destroy(doc);
        if (frame == 0) return ori_py_raise(source, &err);
        char where[600];
        snprintf(where, sizeof where, "%s: frame %d", source, frame);
        return ori_py_raise(where, &err);
    }
    int from = ori_pattern_planarized_from(p);
    if (from > 0 && PyErr_WarnFormat(PyExc_UserWarning, 1,
                                     "%s: its edges cross or overlap: planarised %d edges into %d (edge numbers are "
                                     "the planarised ones)",
                                     source, from, ori_pattern_edge_count(p)) < 0) {
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
        return NULL;
    }
    // Frame 0 as loaded with the faces the pattern uses (traced when the file had none), so
    // that frames written later inherit faces_vertices (as the CLI's kinematics commands do).
    if (frame == 0 && ori_fold_set_pattern(doc, 0, p, &err) != ORI_OK) {
        ori_pattern_destroy(p);
        ori_fold_destroy(doc);
        return ori_py_raise(source, &err);
    }
    ori_py_pattern *pat = (ori_py_pattern *)ori_py_pattern_new(p, doc, NULL, source);
    if (pat) pat->frame = frame;
    return (PyObject *)pat;
}

static PyObject *py_load(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"path", "frame", "weld", NULL};
    PyObject *path_obj;
    int frame = 0, weld = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O&|ip", kwlist, PyUnicode_FSConverter, &path_obj, &frame, &weld))
        return NULL;
    const char *path = PyBytes_AS_STRING(path_obj);
    PyObject *result = NULL;
    ori_error err;
    if (is_drawing(path)) {
        if (frame != 0 || weld) {
            PyErr_Format(PyExc_ValueError, "%s applies to .fold input, not to %s", frame != 0 ? "frame" : "weld", path);
        } else {
            ori_pattern *p = NULL;
            ori_status st;
            Py_BEGIN_ALLOW_THREADS
            st = ori_import_file(path, ORI_FORMAT_UNKNOWN, NULL, &p, NULL, &err);
            Py_END_ALLOW_THREADS
            if (st != ORI_OK) {
                ori_py_raise(path, &err);
            } else {
                ori_fold *doc = ori_fold_create();
                ori_fold_set_custom(doc, 0, "frame_classes", "[\"creasePattern\"]", NULL);
                ori_fold_set_pattern(doc, 0, p, NULL);
                result = ori_py_pattern_new(p, doc, NULL, path);
            }
        }
    } else {
        ori_fold *doc = NULL;
        ori_status st;
        Py_BEGIN_ALLOW_THREADS
        st = ori_fold_load_file(path, &doc, &err);
        Py_END_ALLOW_THREADS
        if (st != ORI_OK) ori_py_raise(path, &err);
        else result = pattern_of_doc(doc, frame, weld, path);
    }
    Py_DECREF(path_obj);
    return result;
}

static PyObject *py_from_fold_text(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"text", "frame", "weld", "source", NULL};
    const char *text, *source = "<fold>";
    Py_ssize_t size;
    int frame = 0, weld = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "s#|ips", kwlist, &text, &size, &frame, &weld, &source)) return NULL;
    ori_fold *doc = NULL;
    ori_error err;
    if (ori_fold_load_string(text, (size_t)size, &doc, &err) != ORI_OK) return ori_py_raise(source, &err);
    return pattern_of_doc(doc, frame, weld, source);
}

static PyObject *py_from_arrays(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"vertices", "edges", "assignment", "faces", "fold_angles", "weld", "source", NULL};
    PyObject *vobj, *eobj, *aobj, *fobj = Py_None, *angobj = Py_None;
    int weld = 0;
    const char *source = "<arrays>";
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OOO|OOps", kwlist, &vobj, &eobj, &aobj, &fobj, &angobj, &weld, &source))
        return NULL;
    PyArrayObject *v = (PyArrayObject *)PyArray_FROMANY(vobj, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY);
    if (!v || (PyArray_DIM(v, 1) != 2 && PyArray_DIM(v, 1) != 3)) {
        Py_XDECREF(v);
        PyErr_SetString(PyExc_ValueError, "vertices must be an (n, 2) or (n, 3) array of coordinates");
        return NULL;
    }
    PyArrayObject *e = (PyArrayObject *)PyArray_FROMANY(eobj, NPY_INT, 2, 2, NPY_ARRAY_IN_ARRAY | NPY_ARRAY_FORCECAST);
    if (!e || PyArray_DIM(e, 1) != 2) {
        Py_DECREF(v);
        Py_XDECREF(e);
        PyErr_SetString(PyExc_ValueError, "edges must be an (m, 2) array of vertex indices");
        return NULL;
    }
    npy_intp nv = PyArray_DIM(v, 0), ne = PyArray_DIM(e, 0);
    PyArrayObject *ang = NULL;
    PyObject *asg = NULL, *faces = NULL, *result = NULL;
    ori_pattern *p = NULL;
    if (nv > INT_MAX / 2 || ne > INT_MAX / 2) {
        PyErr_SetString(PyExc_ValueError, "too many vertices or edges");
        goto done;
    }
    if (angobj != Py_None && !(ang = ori_py_double_array(angobj, ne, 0, "fold_angles"))) goto done;
    // The assignment: a string of FOLD letters, or a sequence of one-letter strings.
    if (PyUnicode_Check(aobj)) asg = PyUnicode_AsUTF8String(aobj);
    else {
        PyObject *joined = PyUnicode_Join(PyUnicode_FromString(""), aobj);
        if (joined) {
            asg = PyUnicode_AsUTF8String(joined);
            Py_DECREF(joined);
        }
    }
    if (!asg) {
        PyErr_Clear();
        PyErr_SetString(PyExc_TypeError, "assignment must be a string of FOLD letters (B, M, V, F, U, C, J), one per edge");
        goto done;
    }
    if (PyBytes_GET_SIZE(asg) != ne) {
        PyErr_Format(PyExc_ValueError, "assignment has %zd letters for %zd edges", (Py_ssize_t)PyBytes_GET_SIZE(asg),
                     (Py_ssize_t)ne);
        goto done;
    }
    ori_pattern_def pd = ori_default_pattern_def();
    pd.vertex_capacity = (int)nv;
    pd.edge_capacity = (int)ne;
    p = ori_pattern_create(&pd);
    bool is3d = PyArray_DIM(v, 1) == 3;
    bool lifted = false;
    const double *vc = PyArray_DATA(v);
    for (npy_intp i = 0; i < nv; ++i) {
        double z = is3d ? vc[3 * i + 2] : 0.0;
        const double *row = vc + (is3d ? 3 : 2) * i;
        if (!isfinite(row[0]) || !isfinite(row[1]) || !isfinite(z)) {
            ori_py_raise_value(source, "vertices", "vertex %zd has a coordinate that is not finite", (Py_ssize_t)i);
            goto done;
        }
        lifted |= z != 0.0;
        ori_pattern_add_vertex(p, ori_v3_make(row[0], row[1], z));
    }
    const int *ev = PyArray_DATA(e);
    const char *letters = PyBytes_AS_STRING(asg);
    for (npy_intp i = 0; i < ne; ++i) {
        ori_assignment a;
        if (!ori_assignment_from_char(letters[i], &a)) {
            ori_py_raise_value(source, "assignment", "edge %zd: '%c' is no FOLD assignment (B, M, V, F, U, C, J)",
                               (Py_ssize_t)i, letters[i]);
            goto done;
        }
        double th = ang ? ((const double *)PyArray_DATA(ang))[i] : 0.0;
        if (!(fabs(th) <= ORI_PI)) {
            ori_py_raise_value(source, "fold_angles", "edge %zd: %g rad is outside [-pi, pi]", (Py_ssize_t)i, th);
            goto done;
        }
        ori_pattern_add_edge(p, ev[2 * i], ev[2 * i + 1], a, th);
    }
    ori_pattern_set_has_fold_angles(p, ang != NULL);
    if (fobj != Py_None) {
        faces = PySequence_Fast(fobj, "faces must be a sequence of vertex cycles");
        if (!faces) goto done;
        for (Py_ssize_t f = 0; f < PySequence_Fast_GET_SIZE(faces); ++f) {
            int n;
            int *cyc = ori_py_int_list(PySequence_Fast_GET_ITEM(faces, f), &n, "faces[i]");
            if (!cyc) goto done;
            if (n < 3) {
                PyMem_Free(cyc);
                ori_py_raise_value(source, "faces", "face %zd has %d vertices (at least 3)", f, n);
                goto done;
            }
            ori_pattern_add_face(p, cyc, n);
            PyMem_Free(cyc);
        }
    }
    if (lifted) ori_pattern_set_folded_form(p, true);
    ori_build_def bd = ori_default_build_def();
    bd.weld = weld;
    bd.check_planarity = !lifted;
    ori_error err;
    if (ori_pattern_build(p, &bd, &err) != ORI_OK) {
        ori_py_raise(source, &err);
        goto done;
    }
    result = ori_py_pattern_new(p, NULL, NULL, source);
    p = NULL;
done:
    ori_pattern_destroy(p);
    Py_XDECREF(faces);
    Py_XDECREF(asg);
    Py_XDECREF(ang);
    Py_DECREF(v);
    Py_DECREF(e);
    return result;
}

static PyObject *py_sheet(PyObject *mod, PyObject *args)
{
    PyObject *poly;
    if (!PyArg_ParseTuple(args, "O", &poly)) return NULL;
    PyArrayObject *a = (PyArrayObject *)PyArray_FROMANY(poly, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY);
    if (!a || PyArray_DIM(a, 1) != 2 || PyArray_DIM(a, 0) < 3 || PyArray_DIM(a, 0) > INT_MAX) {
        Py_XDECREF(a);
        PyErr_SetString(PyExc_ValueError, "a sheet is a polygon: an (n, 2) array of n >= 3 corners");
        return NULL;
    }
    int n = (int)PyArray_DIM(a, 0);
    ori_pattern *p = NULL;
    ori_error err;
    ori_status st = ori_pattern_create_sheet((const ori_v2 *)PyArray_DATA(a), n, &p, &err);
    Py_DECREF(a);
    if (st != ORI_OK) return ori_py_raise("sheet", &err);
    return ori_py_pattern_new(p, NULL, NULL, "<sheet>");
}

static PyObject *py_generate(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"kind", "rows", "cols", "sides", "angle_rad", "width", "height", "twist_size",
                             "bistable_height", NULL};
    const char *kind;
    PyObject *o[8] = {NULL};
    if (!PyArg_ParseTupleAndKeywords(args, kw, "s|OOOOOOOO", kwlist, &kind, &o[0], &o[1], &o[2], &o[3], &o[4], &o[5],
                                     &o[6], &o[7]))
        return NULL;
    ori_tessellation t;
    if (!ori_tessellation_from_name(kind, &t)) {
        PyErr_Format(PyExc_ValueError, "unknown tessellation '%s' (miura, yoshimura, waterbomb, square-twist, kresling)",
                     kind);
        return NULL;
    }
    ori_generate_def d = ori_default_generate_def(t);
    int *ints[3] = {&d.rows, &d.cols, &d.sides};
    for (int i = 0; i < 3; ++i)
        if (o[i] && o[i] != Py_None) {
            long v = PyLong_AsLong(o[i]);
            if (v == -1 && PyErr_Occurred()) return NULL;
            if (v < INT_MIN || v > INT_MAX) return PyErr_Format(PyExc_OverflowError, "%s is too large", kwlist[i + 1]);
            *ints[i] = (int)v;
        }
    double *dbl[4] = {&d.angle_rad, &d.width, &d.height, &d.twist_size};
    for (int i = 0; i < 4; ++i)
        if (o[3 + i] && o[3 + i] != Py_None) {
            double v = PyFloat_AsDouble(o[3 + i]);
            if (v == -1.0 && PyErr_Occurred()) return NULL;
            *dbl[i] = v;
        }
    if (o[7] && o[7] != Py_None) d.bistable_height = PyObject_IsTrue(o[7]) == 1;
    ori_pattern *p = NULL;
    ori_edge_class *classes = NULL;
    ori_error err;
    ori_status st;
    char source[64];
    snprintf(source, sizeof source, "<generated %s>", ori_tessellation_name(t));
    Py_BEGIN_ALLOW_THREADS
    st = ori_generate(&d, &p, &classes, &err);
    Py_END_ALLOW_THREADS
    if (st != ORI_OK) return ori_py_raise(source, &err);
    // The edge classes as FOLD's "orikin:edges_class", as `orikin generate` writes them.
    int E = ori_pattern_edge_count(p);
    size_t cap = 16 + (size_t)E * 14;
    char *json = PyMem_Malloc(cap);
    if (!json) {
        ori_buffer_free(classes);
        ori_pattern_destroy(p);
        return PyErr_NoMemory();
    }
    size_t n = 0;
    json[n++] = '[';
    for (int e = 0; e < E; ++e) n += (size_t)snprintf(json + n, cap - n, "%s\"%s\"", e ? "," : "", ori_edge_class_name(classes[e]));
    json[n++] = ']';
    json[n] = '\0';
    ori_buffer_free(classes);
    ori_fold *doc = ori_fold_create();
    ori_fold_set_custom(doc, 0, "orikin:edges_class", json, NULL);
    ori_fold_set_pattern(doc, 0, p, NULL);
    PyMem_Free(json);
    return ori_py_pattern_new(p, doc, NULL, source);
}

// --- reading a pattern -------------------------------------------------------------------------

static PyObject *pattern_counts(PyObject *self, void *what)
{
    const ori_pattern *p = ((ori_py_pattern *)self)->p;
    switch ((int)(intptr_t)what) {
    case 0: return PyLong_FromLong(ori_pattern_vertex_count(p));
    case 1: return PyLong_FromLong(ori_pattern_edge_count(p));
    case 2: return PyLong_FromLong(ori_pattern_face_count(p));
    case 3: return PyBool_FromLong(ori_pattern_is_folded_form(p));
    case 4: return PyBool_FromLong(ori_pattern_has_fold_angles(p));
    case 5: return PyLong_FromLong(((ori_py_pattern *)self)->doc ? ori_fold_frame_count(((ori_py_pattern *)self)->doc) : 1);
    case 6: return PyLong_FromLong(ori_pattern_interior_vertex_count(p));
    case 7: return PyFloat_FromDouble(ori_pattern_diagonal(p));
    case 9: return PyLong_FromLong(((ori_py_pattern *)self)->frame);
    default: return Py_NewRef(((ori_py_pattern *)self)->source);
    }
}

static PyObject *pattern_vertices(PyObject *self, PyObject *args)
{
    const ori_pattern *p = ((ori_py_pattern *)self)->p;
    npy_intp dims[2] = {ori_pattern_vertex_count(p), 3};
    PyObject *arr = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    if (!arr) return NULL;
    ori_v3 *out = PyArray_DATA((PyArrayObject *)arr);
    for (npy_intp v = 0; v < dims[0]; ++v) out[v] = ori_pattern_vertex(p, (int)v);
    return arr;
}

static PyObject *pattern_edges(PyObject *self, PyObject *args)
{
    const ori_pattern *p = ((ori_py_pattern *)self)->p;
    npy_intp dims[2] = {ori_pattern_edge_count(p), 2};
    PyObject *arr = PyArray_SimpleNew(2, dims, NPY_INT);
    if (!arr) return NULL;
    int *out = PyArray_DATA((PyArrayObject *)arr);
    for (npy_intp e = 0; e < dims[0]; ++e) {
        ori_edge ed = ori_pattern_edge(p, (int)e);
        out[2 * e] = ed.v[0];
        out[2 * e + 1] = ed.v[1];
    }
    return arr;
}

static PyObject *pattern_assignment(PyObject *self, PyObject *args)
{
    const ori_pattern *p = ((ori_py_pattern *)self)->p;
    int E = ori_pattern_edge_count(p);
    PyObject *s = PyUnicode_New(E, 127);
    if (!s) return NULL;
    for (int e = 0; e < E; ++e) PyUnicode_WRITE(PyUnicode_1BYTE_KIND, PyUnicode_DATA(s), e, ori_assignment_to_char(ori_pattern_edge(p, e).assignment));
    return s;
}

static PyObject *pattern_fold_angles(PyObject *self, PyObject *args)
{
    const ori_pattern *p = ((ori_py_pattern *)self)->p;
    npy_intp E = ori_pattern_edge_count(p);
    PyObject *arr = PyArray_SimpleNew(1, &E, NPY_DOUBLE);
    if (!arr) return NULL;
    double *out = PyArray_DATA((PyArrayObject *)arr);
    for (npy_intp e = 0; e < E; ++e) out[e] = ori_pattern_edge(p, (int)e).fold_angle_rad;
    return arr;
}

static PyObject *pattern_targets(PyObject *self, PyObject *args)
{
    const ori_pattern *p = ((ori_py_pattern *)self)->p;
    npy_intp E = ori_pattern_edge_count(p);
    PyObject *arr = PyArray_SimpleNew(1, &E, NPY_DOUBLE);
    if (arr) ori_target_angles_default(p, PyArray_DATA((PyArrayObject *)arr));
    return arr;
}

static PyObject *pattern_faces(PyObject *self, PyObject *args)
{
    const ori_pattern *p = ((ori_py_pattern *)self)->p;
    int F = ori_pattern_face_count(p);
    PyObject *out = PyList_New(F);
    for (int f = 0; out && f < F; ++f) {
        int n = ori_pattern_face_size(p, f);
        int buf[64], *vs = n <= 64 ? buf : PyMem_Malloc(sizeof(int) * (size_t)n);
        if (!vs) {
            Py_CLEAR(out);
            return PyErr_NoMemory();
        }
        ori_pattern_face_vertices(p, f, vs, n);
        PyObject *cyc = PyList_New(n);
        for (int i = 0; cyc && i < n; ++i) PyList_SET_ITEM(cyc, i, PyLong_FromLong(vs[i]));
        if (vs != buf) PyMem_Free(vs);
        if (!cyc) {
            Py_CLEAR(out);
            return NULL;
        }
        PyList_SET_ITEM(out, f, cyc);
    }
    return out;
}

static PyObject *pattern_face_names(PyObject *self, PyObject *args)
{
    const ori_pattern *p = ((ori_py_pattern *)self)->p;
    int F = ori_pattern_face_count(p);
    PyObject *out = PyList_New(F);
    for (int f = 0; out && f < F; ++f) {
        const char *n = ori_pattern_face_name(p, f);
        PyList_SET_ITEM(out, f, n ? PyUnicode_FromString(n) : Py_NewRef(Py_None));
    }
    return out;
}

// A face named as the CLI names it (cli_spec_face): an index, a name or a point (x, y).
static PyObject *pattern_find_face(PyObject *self, PyObject *args)
{
    ori_py_pattern *pat = (ori_py_pattern *)self;
    PyObject *spec;
    const char *option = "--fix";
    if (!PyArg_ParseTuple(args, "O|s", &spec, &option)) return NULL;
    const char *src = ori_py_pattern_source(pat);
    if (PyLong_Check(spec)) {
        int overflow;
        long f = PyLong_AsLongAndOverflow(spec, &overflow);
        if (overflow || f < INT_MIN || f > INT_MAX) f = INT_MIN;
        if (!ori_py_check_face(pat, option, (int)f)) return NULL;
        return PyLong_FromLong(f);
    }
    if (PyUnicode_Check(spec)) {
        const char *name = PyUnicode_AsUTF8(spec);
        if (!name) return NULL;
        int f = ori_pattern_find_face_by_name(pat->p, name);
        if (f == ORI_NULL_INDEX && ori_pattern_find_tree_node(pat->p, name) != ORI_NULL_INDEX) // as cli_find_face_option
            return ori_py_raise_value(src, option, "%s is not a folding element any more (it was split; see orikin tree)",
                                      name);
        if (f == ORI_NULL_INDEX)
            return ori_py_raise_value(src, option, "no face named %s (see orikin info --faces %s)", name, src);
        return PyLong_FromLong(f);
    }
    ori_v2 x;
    if (!ori_py_read_v2(spec, &x, option)) {
        PyErr_Clear();
        return PyErr_Format(PyExc_TypeError, "%s: a face is an index, a name or a point (x, y)", option);
    }
    bool on_edge;
    int f = ori_pattern_find_face_at(pat->p, x, &on_edge);
    if (f != ORI_NULL_INDEX && on_edge)
        return ori_py_raise_value(src, option, "(%g, %g) lies on an edge of face %d: give a point inside a face", x.x, x.y, f);
    if (f == ORI_NULL_INDEX)
        return ori_py_raise_value(src, option, "no face contains (%g, %g) (see orikin info --faces)", x.x, x.y);
    return PyLong_FromLong(f);
}

// A crease named as the CLI names it (cli_spec_edge): an index or a point (x, y) on it.
static PyObject *pattern_find_edge(PyObject *self, PyObject *args)
{
    ori_py_pattern *pat = (ori_py_pattern *)self;
    PyObject *spec;
    const char *option = "--drive";
    if (!PyArg_ParseTuple(args, "O|s", &spec, &option)) return NULL;
    if (PyLong_Check(spec)) {
        int overflow;
        long e = PyLong_AsLongAndOverflow(spec, &overflow);
        if (overflow || e < INT_MIN || e > INT_MAX) e = INT_MIN;
        if (!ori_py_check_edge(pat, option, (int)e)) return NULL;
        return PyLong_FromLong(e);
    }
    ori_v2 x;
    if (PyUnicode_Check(spec) || !ori_py_read_v2(spec, &x, option)) {
        PyErr_Clear();
        return PyErr_Format(PyExc_TypeError, "%s: a crease is an index or a point (x, y) on it", option);
    }
    int e = ori_pattern_find_edge_at(pat->p, x);
    if (e == ORI_NULL_INDEX)
        return ori_py_raise_value(ori_py_pattern_source(pat), option,
                                  "no crease passes through (%g, %g) (see orikin info --edges)", x.x, x.y);
    return PyLong_FromLong(e);
}

static PyObject *pattern_center_face(PyObject *self, PyObject *args)
{
    return PyLong_FromLong(ori_pattern_center_face(((ori_py_pattern *)self)->p));
}

// The state of a frame of the pattern's file as the CLI's fold starts from it (cli_kin_load):
// (angles, coordinates, folded): a folded frame's edges_foldAngle, else the flat state, and its
// vertices (3D for a folded frame).
// With as_drawn, a crease-pattern frame's angles are its own edges_foldAngle (the state render,
// export and collide pose, cli/state_args.c) instead of the flat start.
static PyObject *pattern_frame_state(PyObject *self, PyObject *args)
{
    ori_py_pattern *pat = (ori_py_pattern *)self;
    int frame, as_drawn = 0;
    if (!PyArg_ParseTuple(args, "i|p", &frame, &as_drawn)) return NULL;
    const char *src = ori_py_pattern_source(pat);
    int frames = pat->doc ? ori_fold_frame_count(pat->doc) : 1;
    if (frame < 0 || frame >= frames)
        return ori_py_raise_value(src, "--frame", "frame %d does not exist (frames 0 to %d)", frame, frames - 1);
    ori_pattern *other = NULL;
    const ori_pattern *state = pat->p;
    if (frame != pat->frame) {
        ori_build_def bd = ori_default_build_def();
        bd.check_planarity = false;
        ori_error err;
        if (ori_fold_get_pattern(pat->doc, frame, &bd, &other, &err) != ORI_OK) {
            char where[600];
            snprintf(where, sizeof where, "%s: frame %d", src, frame);
            return ori_py_raise(where, &err);
        }
        if (ori_pattern_edge_count(other) != ori_pattern_edge_count(pat->p) ||
            ori_pattern_vertex_count(other) != ori_pattern_vertex_count(pat->p)) {
            ori_pattern_destroy(other);
            ori_error e;
            ori_error_clear(&e);
            e.status = ORI_ERR_TOPOLOGY;
            snprintf(e.message, sizeof e.message,
                     "frame %d has different vertices or edges from frame 0: not a state of the same pattern", frame);
            return ori_py_raise(src, &e);
        }
        state = other;
    }
    bool folded = ori_pattern_is_folded_form(state) || ori_pattern_is_3d(state);
    npy_intp E = ori_pattern_edge_count(state), V = ori_pattern_vertex_count(state);
    PyObject *angles = PyArray_ZEROS(1, &E, NPY_DOUBLE, 0);
    npy_intp dims[2] = {V, 3};
    PyObject *coords = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    if (angles && coords) {
        double *a = PyArray_DATA((PyArrayObject *)angles);
        for (npy_intp e = 0; (folded || as_drawn) && e < E; ++e) a[e] = ori_pattern_edge(state, (int)e).fold_angle_rad;
        ori_v3 *c = PyArray_DATA((PyArrayObject *)coords);
        for (npy_intp v = 0; v < V; ++v) c[v] = ori_pattern_vertex(state, (int)v);
    }
    bool is3d = ori_pattern_is_3d(state);
    ori_pattern_destroy(other);
    if (!angles || !coords) {
        Py_XDECREF(angles);
        Py_XDECREF(coords);
        return NULL;
    }
    return Py_BuildValue("(NNO)", angles, coords, is3d ? Py_True : Py_False);
}

// --- writing -----------------------------------------------------------------------------------

// The FOLD text of a pattern: its document (as loaded, the pattern set into its frame), a
// template's document with this pattern in frame 0, or a new document.
static char *fold_text(ori_py_pattern *pat, ori_error *err)
{
    if (pat->doc) return ori_fold_to_string(pat->doc);
    if (pat->templ) {
        ori_py_pattern *t = (ori_py_pattern *)pat->templ;
        char *base = fold_text(t, err);
        if (!base) return NULL;
        ori_fold *doc = NULL;
        ori_status st = ori_fold_load_string(base, strlen(base), &doc, err);
        ori_buffer_free(base);
        if (st != ORI_OK) return NULL;
        if (ori_fold_set_pattern(doc, 0, pat->p, err) != ORI_OK) {
            ori_fold_destroy(doc);
            return NULL;
        }
        char *text = ori_fold_to_string(doc);
        ori_fold_destroy(doc);
        return text;
    }
    return ori_pattern_to_fold_text(pat->p, NULL, 0, NULL);
}

ori_fold *ori_py_pattern_doc(ori_py_pattern *pat, bool *owned, ori_error *err)
{
    *owned = false;
    ori_error_clear(err);
    if (pat->doc) return pat->doc;
    char *text = fold_text(pat, err);
    if (!text) return NULL;
    ori_fold *doc = NULL;
    ori_status st = ori_fold_load_string(text, strlen(text), &doc, err);
    ori_buffer_free(text);
    if (st != ORI_OK) return NULL;
    *owned = true;
    return doc;
}

static PyObject *pattern_to_fold_text(PyObject *self, PyObject *args)
{
    ori_error err;
    ori_error_clear(&err);
    char *text = fold_text((ori_py_pattern *)self, &err);
    if (!text) return ori_py_raise(ori_py_pattern_source((ori_py_pattern *)self), &err);
    PyObject *s = PyUnicode_FromString(text);
    ori_buffer_free(text);
    return s;
}

// with_states(positions, angles, titles, custom): the pattern's FOLD text with K folded states
// appended as foldedForm frames inheriting from its frame (ori_fold_append_state, as the CLI's
// -o OUT.fold writes a motion), and top-level custom fields {key: JSON text}.
static PyObject *pattern_with_states(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"positions", "angles", "titles", "custom", NULL};
    ori_py_pattern *pat = (ori_py_pattern *)self;
    PyObject *pobj, *aobj, *titles = Py_None, *custom = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|OO", kwlist, &pobj, &aobj, &titles, &custom)) return NULL;
    int V = ori_pattern_vertex_count(pat->p), E = ori_pattern_edge_count(pat->p);
    PyArrayObject *pa = (PyArrayObject *)PyArray_FROMANY(pobj, NPY_DOUBLE, 3, 3, NPY_ARRAY_IN_ARRAY);
    PyArrayObject *aa = pa ? (PyArrayObject *)PyArray_FROMANY(aobj, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY) : NULL;
    if (!aa || PyArray_DIM(pa, 1) != V || PyArray_DIM(pa, 2) != 3 || PyArray_DIM(aa, 0) != PyArray_DIM(pa, 0) ||
        PyArray_DIM(aa, 1) != E || PyArray_DIM(pa, 0) > INT_MAX) {
        Py_XDECREF(pa);
        Py_XDECREF(aa);
        return PyErr_Format(PyExc_ValueError, "states need positions (K, %d, 3) and angles (K, %d)", V, E);
    }
    int K = (int)PyArray_DIM(pa, 0);
    ori_error err;
    bool owned;
    PyObject *result = NULL;
    ori_fold *base = ori_py_pattern_doc(pat, &owned, &err);
    char *text = base ? ori_fold_to_string(base) : NULL;
    if (owned) ori_fold_destroy(base);
    ori_fold *doc = NULL;
    if (!text || ori_fold_load_string(text, strlen(text), &doc, &err) != ORI_OK) {
        ori_buffer_free(text);
        ori_py_raise(ori_py_pattern_source(pat), &err);
        goto done;
    }
    ori_buffer_free(text);
    for (int k = 0; k < K; ++k) {
        const char *title = NULL;
        PyObject *t = titles != Py_None ? PySequence_GetItem(titles, k) : NULL;
        if (t && PyUnicode_Check(t)) title = PyUnicode_AsUTF8(t);
        PyErr_Clear();
        ori_fold_append_state(doc, pat->frame, V, (const ori_v3 *)PyArray_DATA(pa) + (size_t)k * V, E,
                              (const double *)PyArray_DATA(aa) + (size_t)k * E, title);
        Py_XDECREF(t);
    }
    if (custom != Py_None) {
        PyObject *key, *value;
        Py_ssize_t pos = 0;
        if (!PyDict_Check(custom)) {
            PyErr_SetString(PyExc_TypeError, "custom must be a dict of FOLD keys to JSON text");
            goto done;
        }
        while (PyDict_Next(custom, &pos, &key, &value)) {
            const char *k = PyUnicode_AsUTF8(key), *v = PyUnicode_AsUTF8(value);
            if (!k || !v) goto done;
            if (ori_fold_set_custom(doc, 0, k, v, &err) != ORI_OK) {
                ori_py_raise(k, &err);
                goto done;
            }
        }
    }
    char *out = ori_fold_to_string(doc);
    result = PyUnicode_FromString(out);
    ori_buffer_free(out);
done:
    ori_fold_destroy(doc);
    Py_DECREF(pa);
    Py_DECREF(aa);
    return result;
}

// Write FOLD (the document), or a drawing (SVG, CP, OPX) by the extension.
static PyObject *pattern_save(PyObject *self, PyObject *args)
{
    ori_py_pattern *pat = (ori_py_pattern *)self;
    PyObject *path_obj;
    if (!PyArg_ParseTuple(args, "O&", PyUnicode_FSConverter, &path_obj)) return NULL;
    const char *path = PyBytes_AS_STRING(path_obj);
    ori_error err;
    ori_status st;
    if (is_drawing(path)) {
        st = ori_export_file(pat->p, ORI_FORMAT_UNKNOWN, NULL, path, &err);
    } else {
        ori_error_clear(&err);
        char *text = fold_text(pat, &err);
        st = text ? ori_file_write_atomic(path, text, strlen(text), &err) : err.status;
        ori_buffer_free(text);
    }
    PyObject *r = st == ORI_OK ? Py_NewRef(Py_None) : ori_py_raise(path, &err);
    Py_DECREF(path_obj);
    return r;
}

// --- edits: each returns a new pattern ---------------------------------------------------------

static PyObject *derived(ori_py_pattern *pat, ori_pattern *p)
{
    PyObject *t = pat->doc ? (PyObject *)pat : pat->templ;
    return ori_py_pattern_new(p, NULL, t, ori_py_pattern_source(pat));
}

static bool read_assignment(PyObject *obj, ori_assignment *a)
{
    const char *s = PyUnicode_Check(obj) ? PyUnicode_AsUTF8(obj) : NULL;
    if (!s || strlen(s) != 1 || !ori_assignment_from_char(s[0], a)) {
        PyErr_Clear();
        PyErr_SetString(PyExc_ValueError, "assignment must be one FOLD letter: 'M', 'V', 'F' or 'U' for a crease");
        return false;
    }
    return true;
}

static PyObject *apply_result(const ori_apply_result *r)
{
    return ori_py_dict("segments", PyLong_FromLong(r->segments), "faces_split", PyLong_FromLong(r->faces_split),
                       "vertices_added", PyLong_FromLong(r->vertices_added), "edges_added", PyLong_FromLong(r->edges_added),
                       "first_edge", PyLong_FromLong(r->first_edge), NULL);
}

// crease(a, b, infinite, assignment, angle_rad, face): the crease through a→b applied (a clone).
// Without an assignment the crease is unassigned (U), as `orikin crease` makes it.
static PyObject *pattern_crease(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"a", "b", "infinite", "assignment", "angle_rad", "face", NULL};
    ori_py_pattern *pat = (ori_py_pattern *)self;
    PyObject *ao, *bo, *asg = NULL; // optional: not written by PyArg_Parse* when omitted
    int infinite = 1, face = ORI_NULL_INDEX;
    double angle = 0.0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|pOdi", kwlist, &ao, &bo, &infinite, &asg, &angle, &face)) return NULL;
    ori_crease c;
    c.assignment = ORI_ASSIGN_UNASSIGNED;
    if (!ori_py_read_v2(ao, &c.a, "a") || !ori_py_read_v2(bo, &c.b, "b") || (asg && !read_assignment(asg, &c.assignment)))
        return NULL;
    c.infinite = infinite;
    c.fold_angle_rad = angle;
    if (face != ORI_NULL_INDEX && !ori_py_check_face(pat, "--face", face)) return NULL;
    ori_pattern *p = ori_pattern_clone(pat->p);
    ori_apply_result r;
    ori_error err;
    if (ori_pattern_apply_crease(p, &c, face, &r, &err) != ORI_OK) {
        ori_pattern_destroy(p);
        return ori_py_raise(ori_py_pattern_source(pat), &err);
    }
    PyObject *np = derived(pat, p);
    if (!np) return NULL;
    return Py_BuildValue("(NN)", np, apply_result(&r));
}

// apply(composite, face, assignment): a built-in composite by name or a composite file.
static PyObject *pattern_apply(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"composite", "face", "assignment", NULL};
    ori_py_pattern *pat = (ori_py_pattern *)self;
    const char *name;
    int face = ORI_NULL_INDEX;
    PyObject *asg = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "s|iO", kwlist, &name, &face, &asg)) return NULL;
    ori_assignment a, *ap = NULL;
    if (asg != Py_None) {
        if (!read_assignment(asg, &a)) return NULL;
        ap = &a;
    }
    if (face != ORI_NULL_INDEX && !ori_py_check_face(pat, "--face", face)) return NULL;
    ori_composite *c = NULL;
    ori_error err;
    ori_status st = ori_composite_builtin(name, &c, &err);
    if (st == ORI_ERR_NOT_FOUND) st = ori_composite_load_file(name, &c, &err);
    if (st != ORI_OK) return ori_py_raise(name, &err);
    ori_pattern *p = ori_pattern_clone(pat->p);
    ori_apply_result r;
    st = ori_pattern_apply_composite(p, c, face, ap, &r, &err);
    ori_composite_destroy(c);
    if (st != ORI_OK) {
        ori_pattern_destroy(p);
        return ori_py_raise(ori_py_pattern_source(pat), &err);
    }
    PyObject *np = derived(pat, p);
    if (!np) return NULL;
    return Py_BuildValue("(NN)", np, apply_result(&r));
}

// edit(kind, edge, assignment, a, b): assign, flip, remove or move a crease (a clone).
static PyObject *pattern_edit(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"kind", "edge", "assignment", "a", "b", NULL};
    ori_py_pattern *pat = (ori_py_pattern *)self;
    const char *kind;
    int edge;
    PyObject *asg = Py_None, *ao = Py_None, *bo = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "si|OOO", kwlist, &kind, &edge, &asg, &ao, &bo)) return NULL;
    char option[16];
    snprintf(option, sizeof option, "--%s", kind);
    if (!ori_py_check_edge(pat, option, edge)) return NULL;
    ori_pattern *p = ori_pattern_clone(pat->p);
    ori_error err;
    ori_status st;
    if (strcmp(kind, "assign") == 0) {
        ori_assignment a;
        if (!read_assignment(asg, &a)) {
            ori_pattern_destroy(p);
            return NULL;
        }
        st = ori_pattern_assign_crease(p, edge, a, &err);
    } else if (strcmp(kind, "flip") == 0) {
        st = ori_pattern_flip_crease(p, edge, &err);
    } else if (strcmp(kind, "remove") == 0) {
        st = ori_pattern_remove_crease(p, edge, NULL, &err);
    } else if (strcmp(kind, "move") == 0) {
        ori_v2 a, b;
        if (!ori_py_read_v2(ao, &a, "a") || !ori_py_read_v2(bo, &b, "b")) {
            ori_pattern_destroy(p);
            return NULL;
        }
        st = ori_pattern_move_crease(p, edge, a, b, NULL, NULL, &err);
    } else {
        ori_pattern_destroy(p);
        return PyErr_Format(PyExc_ValueError, "unknown edit '%s' (assign, flip, remove, move)", kind);
    }
    if (st != ORI_OK) {
        ori_pattern_destroy(p);
        return ori_py_raise(ori_py_pattern_source(pat), &err);
    }
    return derived(pat, p);
}

static PyObject *pattern_grubler(PyObject *self, PyObject *args)
{
    ori_py_mechanism *m = ori_py_pattern_mechanism((ori_py_pattern *)self);
    return m ? PyLong_FromLong(ori_mechanism_grubler(m->m)) : NULL;
}

// --- the type --------------------------------------------------------------------------------

static PyGetSetDef pattern_getset[] = {
    {"vertex_count", pattern_counts, NULL, "Number of vertices (FOLD vertices_coords).", (void *)0},
    {"edge_count", pattern_counts, NULL, "Number of edges (FOLD edges_vertices).", (void *)1},
    {"face_count", pattern_counts, NULL, "Number of faces (given, or traced from the planar graph).", (void *)2},
    {"is_folded_form", pattern_counts, NULL, "True for a folded form (3D or flagged foldedForm), not a flat sheet.", (void *)3},
    {"has_fold_angles", pattern_counts, NULL, "True when the edges carry fold angles (FOLD edges_foldAngle).", (void *)4},
    {"frame_count", pattern_counts, NULL, "Frames of the FOLD file the pattern came from (1 + file_frames).", (void *)5},
    {"interior_vertex_count", pattern_counts, NULL, "Vertices the paper surrounds (the ones checked and looped).", (void *)6},
    {"diagonal", pattern_counts, NULL, "Bounding-box diagonal: the length scale of every relative tolerance.", (void *)7},
    {"source", pattern_counts, NULL, "Where the pattern came from: the path, or '<arrays>', '<fold>', ...", (void *)8},
    {"frame", pattern_counts, NULL, "The frame of its FOLD file the pattern is (0: the top level).", (void *)9},
    {NULL, NULL, NULL, NULL, NULL},
};

#define KW (PyCFunction)(void (*)(void))
static PyMethodDef pattern_methods[] = {
    {"vertices", pattern_vertices, METH_NOARGS, "Vertex coordinates, (V, 3) (a copy; z = 0 on a flat sheet)."},
    {"edges", pattern_edges, METH_NOARGS, "Edge endpoints, (E, 2) vertex indices (a copy)."},
    {"assignment", pattern_assignment, METH_NOARGS, "Edge assignments as a string of FOLD letters."},
    {"fold_angles", pattern_fold_angles, METH_NOARGS, "Edge fold angles in radians (a copy)."},
    {"targets", pattern_targets, METH_NOARGS, "Target angles of a fold toward the targets (radians; ori_target_angles_default)."},
    {"faces", pattern_faces, METH_NOARGS, "Faces as lists of vertex indices (counter-clockwise)."},
    {"face_names", pattern_face_names, METH_NOARGS, "Face names (Obj12 ...) or None."},
    {"find_face", pattern_find_face, METH_VARARGS, "find_face(spec, option): a face by index, name or point."},
    {"find_edge", pattern_find_edge, METH_VARARGS, "find_edge(spec, option): a crease by index or point."},
    {"center_face", pattern_center_face, METH_NOARGS, "The face a fold fixes when none is named."},
    {"frame_state", pattern_frame_state, METH_VARARGS, "frame_state(k, as_drawn): (angles_rad, coords, is_3d) of frame k."},
    {"to_fold_text", pattern_to_fold_text, METH_NOARGS, "The pattern as FOLD text."},
    {"save", pattern_save, METH_VARARGS, "save(path): FOLD, or SVG / CP / OPX by the extension."},
    {"with_states", KW pattern_with_states, METH_VARARGS | METH_KEYWORDS, "FOLD text with folded states appended."},
    {"crease", KW pattern_crease, METH_VARARGS | METH_KEYWORDS, "crease(a, b, ...): (new pattern, what it did)."},
    {"apply", KW pattern_apply, METH_VARARGS | METH_KEYWORDS, "apply(composite, face, assignment): (new pattern, what it did)."},
    {"edit", KW pattern_edit, METH_VARARGS | METH_KEYWORDS, "edit(kind, edge, ...): a new pattern."},
    {"grubler", pattern_grubler, METH_NOARGS, "Grubler-Kutzbach mobility of the mechanism."},
    {"fold", KW ori_py_pattern_fold, METH_VARARGS | METH_KEYWORDS, "A single-drive fold (ori_motion_solve)."},
    {"target_fold", KW ori_py_pattern_target_fold, METH_VARARGS | METH_KEYWORDS, "A fold toward the targets."},
    {"drives_fold", KW ori_py_pattern_drives_fold, METH_VARARGS | METH_KEYWORDS, "Several drives together."},
    {"lock_set", KW ori_py_pattern_lock_set, METH_VARARGS | METH_KEYWORDS, "A lock set leaving one DOF per drive."},
    {"symmetry", ori_py_pattern_symmetry, METH_NOARGS, "(orbits, groups, order) of the flat pattern's symmetries."},
    {"pose", KW ori_py_pattern_pose, METH_VARARGS | METH_KEYWORDS, "Pose fold angles: (angles, positions)."},
    {"check", KW ori_py_pattern_check, METH_VARARGS | METH_KEYWORDS, "Local flat-foldability report."},
    {"regularize", KW ori_py_pattern_regularize, METH_VARARGS | METH_KEYWORDS, "The nearest exact pattern."},
    {"layers", KW ori_py_pattern_layers, METH_VARARGS | METH_KEYWORDS, "The layer-order solver."},
    {"dof", KW ori_py_pattern_dof, METH_VARARGS | METH_KEYWORDS, "Degrees of freedom at a state."},
    {"sequence", KW ori_py_pattern_sequence, METH_VARARGS | METH_KEYWORDS, "Run a fold sequence (JSON text)."},
    {NULL, NULL, 0, NULL},
};

PyTypeObject ori_py_PatternType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "orikin._orikin.Pattern",
    .tp_basicsize = sizeof(ori_py_pattern),
    .tp_dealloc = pattern_dealloc,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "A built crease pattern and its FOLD document (the library's ori_pattern, ori_fold).",
    .tp_methods = pattern_methods,
    .tp_getset = pattern_getset,
};

PyMethodDef ori_py_pattern_functions[] = {
    {"load", KW py_load, METH_VARARGS | METH_KEYWORDS, "load(path, frame=0, weld=False): a pattern from a file."},
    {"from_fold_text", KW py_from_fold_text, METH_VARARGS | METH_KEYWORDS, "A pattern from FOLD text."},
    {"from_arrays", KW py_from_arrays, METH_VARARGS | METH_KEYWORDS, "A pattern from numpy arrays."},
    {"sheet", py_sheet, METH_VARARGS, "sheet(polygon): a blank sheet."},
    {"generate", KW py_generate, METH_VARARGS | METH_KEYWORDS, "A generated tessellation."},
    {NULL, NULL, 0, NULL},
};
