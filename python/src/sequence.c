// orikin._orikin.Record: a fold sequence run on a pattern (the folding manager): the recorded
// states as views, any instant restored exactly, the self-collision check of the whole motion.
#include "pyorikin.h"

#include <math.h>
#include <stdio.h>

typedef struct ori_py_record {
    PyObject_HEAD
    PyObject *weakrefs; // views' owners are checked for lifetime by weak references (tests)
    ori_record *r;
    ori_sequence *seq;
    PyObject *mech, *pattern;
    bool checked;
    ori_collision_event ev;
} ori_py_record;

static void record_dealloc(PyObject *obj)
{
    ori_py_record *self = (ori_py_record *)obj;
    if (self->weakrefs) PyObject_ClearWeakRefs(obj);
    ori_record_destroy(self->r); // before its mechanism
    ori_sequence_destroy(self->seq);
    Py_XDECREF(self->mech);
    Py_XDECREF(self->pattern);
    PyObject_Free(obj);
}

static const char *record_source(const ori_py_record *self) { return ori_py_pattern_source((ori_py_pattern *)self->pattern); }

static int shown_frames(const ori_py_record *self)
{
    int n = ori_record_frame_count(self->r);
    return self->checked && self->ev.collides && self->ev.frame < n ? self->ev.frame : n;
}

// sequence(text, start, coords, progress): parse the sequence JSON, resolve its names against the
// pattern and run it from the start state (the first fold's face placed by coords when 3D).
PyObject *ori_py_pattern_sequence(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"text", "start", "coords", "source", "progress", NULL};
    ori_py_pattern *pat = (ori_py_pattern *)self;
    const char *text, *source = NULL;
    Py_ssize_t size;
    PyObject *start = Py_None, *coords = Py_None, *progress = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "s#|OOzO", kwlist, &text, &size, &start, &coords, &source, &progress))
        return NULL;
    if (!source) source = ori_py_pattern_source(pat);
    ori_py_mechanism *mech = ori_py_pattern_mechanism(pat);
    if (!mech) return NULL;
    ori_py_progress pp;
    if (!ori_py_progress_init(&pp, progress)) return NULL;
    ori_py_state s;
    if (!ori_py_state_read(&s, pat, start, coords)) return NULL;
    ori_py_record *rec = PyObject_New(ori_py_record, &ori_py_RecordType);
    if (!rec) {
        ori_py_state_free(&s);
        return NULL;
    }
    rec->weakrefs = NULL;
    rec->r = NULL;
    rec->seq = NULL;
    rec->mech = Py_NewRef((PyObject *)mech);
    rec->pattern = Py_NewRef(self);
    rec->checked = false;
    memset(&rec->ev, 0, sizeof rec->ev);
    ori_error err;
    PyObject *result = NULL;
    if (ori_sequence_parse(text, (size_t)size, &rec->seq, &err) != ORI_OK ||
        ori_sequence_resolve(rec->seq, pat->p, &err) != ORI_OK) {
        ori_py_raise(source, &err);
        goto done;
    }
    ori_sequence_fold first = ori_sequence_fold_at(rec->seq, 0);
    int faces = ori_mechanism_face_count(mech->m);
    if (first.fixed_face < 0 || first.fixed_face >= faces) { // as `orikin sequence` says it
        ori_error e;
        ori_error_clear(&e);
        e.status = ORI_ERR_RANGE;
        snprintf(e.message, sizeof e.message, "folds 0: fix: face %d does not exist (%d faces)", first.fixed_face, faces);
        ori_py_raise(source, &e);
        goto done;
    }
    ori_rigid pose = ori_rigid_identity();
    if (s.positions && ori_mechanism_face_pose_from_coords(mech->m, first.fixed_face, s.positions, &pose, &err) != ORI_OK) {
        ori_py_raise(source, &err);
        goto done;
    }
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ori_sequence_run_progress(rec->seq, mech->m, s.angles, pose, ori_py_progress_fn, &pp, &rec->r, &err);
    Py_END_ALLOW_THREADS
    if (st != ORI_OK) {
        ori_py_solve_failed(&pp, source, &err);
        goto done;
    }
    if (ori_py_progress_raise(&pp)) goto done;
    result = Py_NewRef((PyObject *)rec);
done:
    Py_DECREF(rec);
    ori_py_state_free(&s);
    return result;
}

static PyObject *record_angles(PyObject *obj, PyObject *args)
{
    ori_py_record *self = (ori_py_record *)obj;
    int stride = 0, E = ori_mechanism_edge_count(((ori_py_mechanism *)self->mech)->m);
    const double *a = ori_record_angles(self->r, &stride);
    static const double none = 0.0;
    npy_intp dims[2] = {shown_frames(self), E}, strides[2] = {(npy_intp)(sizeof(double) * (size_t)stride), sizeof(double)};
    return ori_py_view(obj, NPY_DOUBLE, 2, dims, strides, a ? a : &none);
}

static PyObject *record_vertices(PyObject *obj, PyObject *args)
{
    ori_py_record *self = (ori_py_record *)obj;
    int V = ori_mechanism_vertex_count(((ori_py_mechanism *)self->mech)->m);
    const ori_v3 *v = ori_record_vertices(self->r);
    static const ori_v3 none = {0.0, 0.0, 0.0};
    npy_intp dims[3] = {shown_frames(self), V, 3};
    return ori_py_view(obj, NPY_DOUBLE, 3, dims, NULL, v ? v : &none);
}

// Per recorded state: 0 times, 1 drives, 2 residuals (floats); 3 folds (ints).
static PyObject *record_column(PyObject *obj, void *which)
{
    ori_py_record *self = (ori_py_record *)obj;
    npy_intp n = shown_frames(self);
    int w = (int)(intptr_t)which;
    PyObject *arr = PyArray_SimpleNew(1, &n, w == 3 ? NPY_INT : NPY_DOUBLE);
    if (!arr) return NULL;
    void *out = PyArray_DATA((PyArrayObject *)arr);
    for (npy_intp k = 0; k < n; ++k) {
        if (w == 3) ((int *)out)[k] = ori_record_frame_fold(self->r, (int)k);
        else
            ((double *)out)[k] = w == 0   ? ori_record_frame_time(self->r, (int)k)
                                 : w == 1 ? ori_record_frame_drive(self->r, (int)k)
                                          : ori_record_frame_residual(self->r, (int)k);
    }
    return arr;
}

static PyObject *record_info(PyObject *obj, PyObject *args)
{
    ori_py_record *self = (ori_py_record *)obj;
    const ori_record *r = self->r;
    int nf = ori_sequence_fold_count(self->seq);
    PyObject *folds = PyList_New(nf);
    for (int i = 0; folds && i < nf; ++i) {
        ori_sequence_fold f = ori_sequence_fold_at(self->seq, i);
        PyObject *o = ori_py_dict("name", PyUnicode_FromString(f.name), "fix", PyLong_FromLong(f.fixed_face), "targets",
                                  PyBool_FromLong(f.targets), "drive",
                                  f.targets ? Py_NewRef(Py_None) : PyLong_FromLong(f.driven_edge), "to_rad",
                                  f.targets ? Py_NewRef(Py_None) : PyFloat_FromDouble(f.to_rad), "fraction",
                                  f.targets ? PyFloat_FromDouble(f.fraction) : Py_NewRef(Py_None), "step_rad",
                                  PyFloat_FromDouble(f.step_rad), "lock", ori_py_ints(f.locked, f.locked_count), NULL);
        if (!o) {
            Py_CLEAR(folds);
            return NULL;
        }
        PyList_SET_ITEM(folds, i, o);
    }
    const char *reason = ori_record_reason(r);
    int failed = ori_record_failed_fold(r);
    return ori_py_dict("verdict", PyUnicode_FromString(ori_motion_verdict_name(ori_record_verdict(r))), "valid",
                       PyBool_FromLong(ori_record_verdict(r) == ORI_MOTION_VALID), "reason",
                       reason ? PyUnicode_FromString(reason) : Py_NewRef(Py_None), "failed_fold",
                       failed == ORI_NULL_INDEX ? Py_NewRef(Py_None) : PyLong_FromLong(failed), "completed_folds",
                       PyLong_FromLong(ori_record_completed_folds(r)), "partial_frames",
                       PyLong_FromLong(ori_record_partial_frames(r)), "duration", PyFloat_FromDouble(ori_record_duration(r)),
                       "frames", PyLong_FromLong(ori_record_frame_count(r)), "folds", folds, NULL);
}

// at(t): (angles, positions, drive, fold) at sequence time t, solved exactly (ori_record_at).
static PyObject *record_at(PyObject *obj, PyObject *args)
{
    ori_py_record *self = (ori_py_record *)obj;
    double t;
    if (!PyArg_ParseTuple(args, "d", &t)) return NULL;
    const ori_mechanism *m = ((ori_py_mechanism *)self->mech)->m;
    npy_intp E = ori_mechanism_edge_count(m), dims[2] = {ori_mechanism_vertex_count(m), 3};
    PyObject *angles = PyArray_SimpleNew(1, &E, NPY_DOUBLE), *pos = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    if (!angles || !pos) {
        Py_XDECREF(angles);
        Py_XDECREF(pos);
        return NULL;
    }
    double drive, residual;
    int fold;
    ori_error err;
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ori_record_at(self->r, t, PyArray_DATA((PyArrayObject *)angles), PyArray_DATA((PyArrayObject *)pos), &drive, &fold,
                       &residual, &err);
    Py_END_ALLOW_THREADS
    if (st != ORI_OK) {
        Py_DECREF(angles);
        Py_DECREF(pos);
        if (st == ORI_ERR_RANGE) return ori_py_raise_value(NULL, "--at", "%s", err.message); // as `orikin sequence`
        return ori_py_raise(record_source(self), &err);
    }
    return Py_BuildValue("(NNdi)", angles, pos, drive, fold);
}

static PyObject *record_collide(PyObject *obj, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"clearance", "progress", NULL};
    ori_py_record *self = (ori_py_record *)obj;
    double clearance = 0.0;
    PyObject *progress = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "|dO", kwlist, &clearance, &progress)) return NULL;
    ori_py_progress pp;
    if (!ori_py_progress_init(&pp, progress)) return NULL;
    const char *src = record_source(self);
    ori_collider *c = ori_py_collider((ori_py_pattern *)self->pattern, clearance);
    if (!c) return NULL;
    ori_error err;
    ori_collision_motion_def check = ori_default_collision_motion_def();
    check.progress = ori_py_progress_fn;
    check.progress_user = &pp;
    ori_collision_event ev;
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ori_collision_check_record(c, self->r, &check, &ev, &err);
    Py_END_ALLOW_THREADS
    ori_collider_destroy(c);
    if (st != ORI_OK) return ori_py_solve_failed(&pp, src, &err);
    if (ori_py_progress_raise(&pp)) return NULL;
    self->checked = true;
    self->ev = ev;
    if (!ev.collides) Py_RETURN_NONE;
    return ori_py_event_dict(&ev, false);
}

static PyObject *record_frames(PyObject *obj, void *what)
{
    ori_py_record *self = (ori_py_record *)obj;
    if (what) return Py_NewRef(self->pattern);
    return PyLong_FromLong(shown_frames(self));
}

static PyObject *record_to_json(PyObject *obj, PyObject *args)
{
    char *text = ori_sequence_to_json(((ori_py_record *)obj)->seq);
    if (!text) return PyErr_NoMemory();
    PyObject *s = PyUnicode_FromString(text);
    ori_buffer_free(text);
    return s;
}

static PyGetSetDef record_getset[] = {
    {"frame_count", record_frames, NULL, "Recorded states shown (those before the first contact once collide() found one).", NULL},
    {"pattern", record_frames, NULL, "The crease pattern folded.", (void *)1},
    {"times", record_column, NULL, "Sequence time T of every state (a copy).", (void *)0},
    {"drives", record_column, NULL, "Driven crease angle (radians) or progress of every state (a copy).", (void *)1},
    {"residuals", record_column, NULL, "Loop-closure residual of every state (a copy).", (void *)2},
    {"folds", record_column, NULL, "Fold (0-based) every state belongs to (a copy).", (void *)3},
    {NULL, NULL, NULL, NULL, NULL},
};

static PyMethodDef record_methods[] = {
    {"angles", record_angles, METH_NOARGS, "(states, E) fold angles in radians: a read-only view of the record."},
    {"vertices", record_vertices, METH_NOARGS, "(states, V, 3) world positions: a read-only view of the record."},
    {"info", record_info, METH_NOARGS, "Verdict, reason, failed fold, the folds (a dict)."},
    {"at", record_at, METH_VARARGS, "at(t): (angles, positions, drive, fold) at sequence time t."},
    {"collide", (PyCFunction)(void (*)(void))record_collide, METH_VARARGS | METH_KEYWORDS, "The first contact, or None."},
    {"to_json", record_to_json, METH_NOARGS, "The sequence as JSON text (degrees)."},
    {NULL, NULL, 0, NULL},
};

PyTypeObject ori_py_RecordType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "orikin._orikin.Record",
    .tp_basicsize = sizeof(ori_py_record),
    .tp_weaklistoffset = offsetof(ori_py_record, weakrefs),
    .tp_dealloc = record_dealloc,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "A fold sequence run on a pattern (ori_record): the motion record.",
    .tp_methods = record_methods,
    .tp_getset = record_getset,
};

const ori_record *ori_py_record_of(PyObject *obj, const ori_sequence **seq)
{
    if (!PyObject_TypeCheck(obj, &ori_py_RecordType)) return NULL;
    ori_py_record *self = (ori_py_record *)obj;
    if (seq) *seq = self->seq;
    return self->r;
}

ori_py_pattern *ori_py_record_pattern(PyObject *obj) { return (ori_py_pattern *)((ori_py_record *)obj)->pattern; }

// sequence_file(path): (its text, the pattern path as written, the start frame), read and parsed
// by the library (ori_sequence_load_file: the CLI's messages, with the JSON line and column).
static PyObject *py_sequence_file(PyObject *mod, PyObject *args)
{
    PyObject *path_obj;
    if (!PyArg_ParseTuple(args, "O&", PyUnicode_FSConverter, &path_obj)) return NULL;
    const char *path = PyBytes_AS_STRING(path_obj);
    ori_sequence *seq = NULL;
    ori_error err;
    PyObject *r = NULL;
    if (ori_sequence_load_file(path, &seq, &err) != ORI_OK) {
        ori_py_raise(path, &err);
    } else {
        char *text = ori_sequence_to_json(seq);
        r = text ? Py_BuildValue("(ssi)", text, ori_sequence_pattern_path(seq), ori_sequence_frame(seq)) : PyErr_NoMemory();
        ori_buffer_free(text);
    }
    ori_sequence_destroy(seq);
    Py_DECREF(path_obj);
    return r;
}

PyMethodDef ori_py_sequence_functions[] = {
    {"sequence_file", py_sequence_file, METH_VARARGS, "sequence_file(path): (JSON text, pattern path, frame)."},
    {NULL, NULL, 0, NULL},
};
