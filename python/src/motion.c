// orikin._orikin.Motion: a solved fold — one driven crease (ori_motion) or several degrees of
// freedom (ori_multifold: toward the targets, several drives) — with the fold it was solved
// with, views of its frames, the state between frames and its self-collision check.
#include "pyorikin.h"

#include <math.h>
#include <stdio.h>

typedef struct ori_py_motion {
    PyObject_HEAD
    PyObject *weakrefs; // views' owners are checked for lifetime by weak references (tests)
    ori_motion *mo;    // a single-drive fold, or NULL
    ori_multifold *mf; // a fold with several degrees of freedom, or NULL
    PyObject *mech, *pattern;
    bool targets;      // mf: toward the targets (else several drives)
    // The fold as solved (for at() and the collision check).
    ori_motion_def def;
    double *start;     // start angles (edge_count) or NULL (flat)
    int *locks;
    int nlocks;
    // The self-collision check (collide()): frames shown are those before the first contact.
    bool checked;
    ori_collision_event ev;
    double clearance;
} ori_py_motion;

static void motion_dealloc(PyObject *obj)
{
    ori_py_motion *self = (ori_py_motion *)obj;
    if (self->weakrefs) PyObject_ClearWeakRefs(obj);
    ori_motion_destroy(self->mo); // before the mechanism it refers to
    ori_multifold_destroy(self->mf);
    PyMem_Free(self->start);
    PyMem_Free(self->locks);
    Py_XDECREF(self->mech);
    Py_XDECREF(self->pattern);
    PyObject_Free(obj);
}

static int motion_frames(const ori_py_motion *self)
{
    return self->mo ? ori_motion_frame_count(self->mo) : ori_multifold_frame_count(self->mf);
}

// Frames before the first contact when the check found one, else all.
static int shown_frames(const ori_py_motion *self)
{
    int n = motion_frames(self);
    return self->checked && self->ev.collides && self->ev.frame < n ? self->ev.frame : n;
}

static const ori_mechanism *mech_of(const ori_py_motion *self) { return ((ori_py_mechanism *)self->mech)->m; }

// A new Motion holding the pattern, its mechanism, the def and copies of start and locks.
static ori_py_motion *motion_new(ori_py_pattern *pat, ori_py_mechanism *mech, const ori_motion_def *def,
                                 const double *start, const int *locks, int nlocks)
{
    ori_py_motion *self = PyObject_New(ori_py_motion, &ori_py_MotionType);
    if (!self) return NULL;
    self->weakrefs = NULL;
    self->mo = NULL;
    self->mf = NULL;
    self->pattern = Py_NewRef((PyObject *)pat);
    self->mech = Py_NewRef((PyObject *)mech);
    self->targets = false;
    self->def = *def;
    self->checked = false;
    memset(&self->ev, 0, sizeof self->ev);
    self->clearance = 0.0;
    int E = ori_mechanism_edge_count(mech->m);
    self->start = start ? PyMem_Malloc(sizeof(double) * (size_t)(E + 1)) : NULL;
    self->locks = PyMem_Malloc(sizeof(int) * (size_t)(nlocks + 1));
    self->nlocks = nlocks;
    if ((start && !self->start) || !self->locks) {
        Py_DECREF(self);
        PyErr_NoMemory();
        return NULL;
    }
    if (start) memcpy(self->start, start, sizeof(double) * (size_t)E);
    if (nlocks) memcpy(self->locks, locks, sizeof(int) * (size_t)nlocks);
    self->def.start_angles_rad = self->start;
    self->def.locked_edges = self->locks;
    self->def.locked_count = nlocks;
    self->def.progress = NULL;
    self->def.progress_user = NULL;
    return self;
}

// --- the common inputs of a fold -------------------------------------------------------------------

typedef struct fold_inputs {
    ori_py_mechanism *mech;
    PyArrayObject *start_arr;
    const double *start;
    ori_rigid pose;
    int *locks, nlocks;
    int *group; // symmetry groups (edge_count) or NULL
    PyArrayObject *group_arr;
} fold_inputs;

static void fold_inputs_free(fold_inputs *in)
{
    Py_CLEAR(in->start_arr);
    Py_CLEAR(in->group_arr);
    PyMem_Free(in->locks);
    in->locks = NULL;
}

// fix (checked), start angles (radians) and the coordinates that place the fixed face (a 3D
// start frame), locks (checked) and groups.
static bool fold_inputs_read(fold_inputs *in, ori_py_pattern *pat, int fix, PyObject *start, PyObject *coords,
                             PyObject *locks, PyObject *group)
{
    memset(in, 0, sizeof *in);
    in->pose = ori_rigid_identity();
    in->mech = ori_py_pattern_mechanism(pat);
    if (!in->mech) return false;
    const ori_mechanism *m = in->mech->m;
    int E = ori_mechanism_edge_count(m), V = ori_mechanism_vertex_count(m);
    if (!ori_py_check_face(pat, "--fix", fix)) return false;
    if (start && start != Py_None) {
        in->start_arr = ori_py_double_array(start, E, 0, "start angles");
        if (!in->start_arr) return false;
        in->start = PyArray_DATA(in->start_arr);
    }
    if (coords && coords != Py_None) {
        PyArrayObject *c = ori_py_double_array(coords, V, 3, "start coordinates");
        if (!c) {
            fold_inputs_free(in);
            return false;
        }
        ori_error err;
        ori_status st = ori_mechanism_face_pose_from_coords(m, fix, PyArray_DATA(c), &in->pose, &err);
        Py_DECREF(c);
        if (st != ORI_OK) {
            fold_inputs_free(in);
            ori_py_raise(ori_py_pattern_source(pat), &err);
            return false;
        }
    }
    in->locks = ori_py_int_list(locks, &in->nlocks, "lock");
    if (!in->locks) {
        fold_inputs_free(in);
        return false;
    }
    for (int i = 0; i < in->nlocks; ++i)
        if (!ori_py_check_edge(pat, "--lock", in->locks[i])) {
            fold_inputs_free(in);
            return false;
        }
    if (group && group != Py_None) {
        in->group_arr = (PyArrayObject *)PyArray_FROMANY(group, NPY_INT, 1, 1, NPY_ARRAY_IN_ARRAY | NPY_ARRAY_FORCECAST);
        if (!in->group_arr || PyArray_DIM(in->group_arr, 0) != E) {
            fold_inputs_free(in);
            PyErr_Format(PyExc_ValueError, "group must hold %d integers (one per edge)", E);
            return false;
        }
        in->group = PyArray_DATA(in->group_arr);
    }
    return true;
}

static bool read_solver(const char *s, ori_solver *out)
{
    if (strcmp(s, "auto") == 0) *out = ORI_SOLVER_AUTO;
    else if (strcmp(s, "analytic") == 0) *out = ORI_SOLVER_ANALYTIC;
    else if (strcmp(s, "numeric") == 0) *out = ORI_SOLVER_NUMERIC;
    else {
        PyErr_Format(PyExc_ValueError, "solver is auto, analytic or numeric, got '%s'", s);
        return false;
    }
    return true;
}

static bool read_linear(const char *s, ori_linear *out)
{
    if (strcmp(s, "auto") == 0) *out = ORI_LINEAR_AUTO;
    else if (strcmp(s, "dense") == 0) *out = ORI_LINEAR_DENSE;
    else if (strcmp(s, "sparse") == 0) *out = ORI_LINEAR_SPARSE;
    else if (strcmp(s, "sweep") == 0) *out = ORI_LINEAR_SWEEP;
    else {
        PyErr_Format(PyExc_ValueError, "linear is auto, dense, sparse or sweep, got '%s'", s);
        return false;
    }
    return true;
}

// --- the folds ------------------------------------------------------------------------------------

// The Motion of a fold with several degrees of freedom from face fix (the caller solves into mf).
static ori_py_motion *multifold_motion(ori_py_pattern *pat, const fold_inputs *in, int fix)
{
    ori_motion_def md = ori_default_motion_def();
    md.fixed_face = fix;
    md.fixed_pose = in->pose;
    return motion_new(pat, in->mech, &md, in->start, in->locks, in->nlocks);
}

// The Motion once its solve returned st: itself, or NULL after raising (the Motion released).
static PyObject *solved(ori_py_motion *mo, ori_status st, ori_py_progress *pp, ori_py_pattern *pat, const ori_error *err)
{
    if (st != ORI_OK) {
        Py_DECREF(mo);
        return ori_py_solve_failed(pp, ori_py_pattern_source(pat), err);
    }
    if (ori_py_progress_raise(pp)) { // a callback that raised after the solve's last check
        Py_DECREF(mo);
        return NULL;
    }
    return (PyObject *)mo;
}

PyObject *ori_py_pattern_fold(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"fix", "drive", "to_rad", "step_rad", "from_rad", "lock", "solver", "linear", "start",
                             "coords", "last_frame_only", "progress", NULL};
    ori_py_pattern *pat = (ori_py_pattern *)self;
    int fix, drive, last_only = 0;
    double to, step;
    PyObject *from = Py_None, *locks = Py_None, *start = Py_None, *coords = Py_None, *progress = Py_None;
    const char *solver = "auto", *linear = "auto";
    if (!PyArg_ParseTupleAndKeywords(args, kw, "iidd|OOssOOpO", kwlist, &fix, &drive, &to, &step, &from, &locks, &solver,
                                     &linear, &start, &coords, &last_only, &progress))
        return NULL;
    ori_motion_def d = ori_default_motion_def();
    if (!read_solver(solver, &d.solver) || !read_linear(linear, &d.linear)) return NULL;
    ori_py_progress pp;
    if (!ori_py_progress_init(&pp, progress)) return NULL;
    fold_inputs in;
    if (!fold_inputs_read(&in, pat, fix, start, coords, locks, NULL)) return NULL;
    if (!ori_py_check_edge(pat, "--drive", drive)) {
        fold_inputs_free(&in);
        return NULL;
    }
    d.fixed_face = fix;
    d.fixed_pose = in.pose;
    d.start_angles_rad = in.start;
    d.driven_edge = drive;
    d.has_from = from != Py_None;
    if (d.has_from) {
        d.from_rad = PyFloat_AsDouble(from);
        if (d.from_rad == -1.0 && PyErr_Occurred()) {
            fold_inputs_free(&in);
            return NULL;
        }
    }
    d.to_rad = to;
    d.step_rad = step;
    d.locked_edges = in.locks;
    d.locked_count = in.nlocks;
    d.last_frame_only = last_only;
    d.progress = ori_py_progress_fn;
    d.progress_user = &pp;
    ori_py_motion *mo = motion_new(pat, in.mech, &d, in.start, in.locks, in.nlocks);
    if (!mo) {
        fold_inputs_free(&in);
        return NULL;
    }
    ori_error err;
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ori_motion_solve(in.mech->m, &d, &mo->mo, &err);
    Py_END_ALLOW_THREADS
    fold_inputs_free(&in);
    return solved(mo, st, &pp, pat, &err);
}

PyObject *ori_py_pattern_target_fold(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"fix", "fraction", "step_rad", "lock", "group", "start", "coords", "targets", "progress",
                             NULL};
    ori_py_pattern *pat = (ori_py_pattern *)self;
    int fix;
    double fraction, step;
    PyObject *locks = Py_None, *group = Py_None, *start = Py_None, *coords = Py_None, *targets = Py_None,
             *progress = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "idd|OOOOOO", kwlist, &fix, &fraction, &step, &locks, &group, &start,
                                     &coords, &targets, &progress))
        return NULL;
    ori_py_progress pp;
    if (!ori_py_progress_init(&pp, progress)) return NULL;
    fold_inputs in;
    if (!fold_inputs_read(&in, pat, fix, start, coords, locks, group)) return NULL;
    PyArrayObject *tarr = NULL;
    if (targets != Py_None &&
        !(tarr = ori_py_double_array(targets, ori_mechanism_edge_count(in.mech->m), 0, "targets"))) {
        fold_inputs_free(&in);
        return NULL;
    }
    ori_target_fold_def d = ori_default_target_fold_def();
    d.fixed_face = fix;
    d.fixed_pose = in.pose;
    d.start_angles_rad = in.start;
    d.target_angles_rad = tarr ? PyArray_DATA(tarr) : NULL;
    d.fraction = fraction;
    d.step_rad = step;
    d.locked_edges = in.locks;
    d.locked_count = in.nlocks;
    d.edge_group = in.group;
    d.progress = ori_py_progress_fn;
    d.progress_user = &pp;
    ori_py_motion *mo = multifold_motion(pat, &in, fix);
    if (!mo) {
        Py_XDECREF(tarr);
        fold_inputs_free(&in);
        return NULL;
    }
    mo->targets = true;
    ori_error err;
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ori_target_fold_solve(in.mech->m, &d, &mo->mf, &err);
    Py_END_ALLOW_THREADS
    Py_XDECREF(tarr);
    fold_inputs_free(&in);
    return solved(mo, st, &pp, pat, &err);
}

PyObject *ori_py_pattern_drives_fold(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"fix", "drives", "to_rad", "step_rad", "lock", "group", "start", "coords", "progress", NULL};
    ori_py_pattern *pat = (ori_py_pattern *)self;
    int fix;
    double step;
    PyObject *drives, *to, *locks = Py_None, *group = Py_None, *start = Py_None, *coords = Py_None, *progress = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "iOOd|OOOOO", kwlist, &fix, &drives, &to, &step, &locks, &group, &start,
                                     &coords, &progress))
        return NULL;
    ori_py_progress pp;
    if (!ori_py_progress_init(&pp, progress)) return NULL;
    fold_inputs in;
    if (!fold_inputs_read(&in, pat, fix, start, coords, locks, group)) return NULL;
    int nd;
    int *dv = ori_py_int_list(drives, &nd, "drive");
    PyArrayObject *ta = dv ? ori_py_double_array(to, nd, 0, "to") : NULL;
    PyObject *result = NULL;
    if (!ta) goto done;
    for (int i = 0; i < nd; ++i)
        if (!ori_py_check_edge(pat, "--drive", dv[i])) goto done;
    ori_drives_fold_def d = ori_default_drives_fold_def();
    d.fixed_face = fix;
    d.fixed_pose = in.pose;
    d.start_angles_rad = in.start;
    d.driven_edges = dv;
    d.to_rad = PyArray_DATA(ta);
    d.driven_count = nd;
    d.step_rad = step;
    d.locked_edges = in.locks;
    d.locked_count = in.nlocks;
    d.edge_group = in.group;
    d.progress = ori_py_progress_fn;
    d.progress_user = &pp;
    ori_py_motion *mo = multifold_motion(pat, &in, fix);
    if (!mo) goto done;
    ori_error err;
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ori_drives_fold_solve(in.mech->m, &d, &mo->mf, &err);
    Py_END_ALLOW_THREADS
    result = solved(mo, st, &pp, pat, &err);
done:
    Py_XDECREF(ta);
    PyMem_Free(dv);
    fold_inputs_free(&in);
    return result;
}

PyObject *ori_py_pattern_lock_set(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"drives", "lock", "group", "start", "progress", NULL};
    ori_py_pattern *pat = (ori_py_pattern *)self;
    PyObject *drives, *locks = Py_None, *group = Py_None, *start = Py_None, *progress = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|OOOO", kwlist, &drives, &locks, &group, &start, &progress)) return NULL;
    ori_py_progress pp;
    if (!ori_py_progress_init(&pp, progress)) return NULL;
    fold_inputs in;
    if (!fold_inputs_read(&in, pat, ori_pattern_face_count(pat->p) > 0 ? 0 : -1, start, Py_None, locks, group))
        return NULL;
    int nd;
    int *dv = ori_py_int_list(drives, &nd, "drive");
    PyObject *result = NULL;
    int E = ori_mechanism_edge_count(in.mech->m);
    int *out = dv ? PyMem_Malloc(sizeof(int) * (size_t)(E + 1)) : NULL;
    if (!out) goto done;
    for (int i = 0; i < nd; ++i)
        if (!ori_py_check_edge(pat, "--drive", dv[i])) goto done;
    ori_error err;
    int n;
    Py_BEGIN_ALLOW_THREADS
    n = ori_mechanism_lock_set_progress(in.mech->m, in.start, dv, nd, in.locks, in.nlocks, in.group, out, E + 1,
                                        ori_py_progress_fn, &pp, &err);
    Py_END_ALLOW_THREADS
    if (n < 0) ori_py_solve_failed(&pp, ori_py_pattern_source(pat), &err);
    else if (!ori_py_progress_raise(&pp)) {
        result = PyList_New(n);
        for (int i = 0; result && i < n; ++i) PyList_SET_ITEM(result, i, PyLong_FromLong(out[i]));
    }
done:
    PyMem_Free(out);
    PyMem_Free(dv);
    fold_inputs_free(&in);
    return result;
}

PyObject *ori_py_pattern_symmetry(PyObject *self, PyObject *args)
{
    ori_py_mechanism *mech = ori_py_pattern_mechanism((ori_py_pattern *)self);
    if (!mech) return NULL;
    npy_intp E = ori_mechanism_edge_count(mech->m);
    PyObject *orbits = PyArray_SimpleNew(1, &E, NPY_INT);
    if (!orbits) return NULL;
    int groups = ori_mechanism_symmetry_orbits(mech->m, PyArray_DATA((PyArrayObject *)orbits));
    int order = ori_mechanism_symmetries(mech->m, NULL, 0);
    return Py_BuildValue("(Nii)", orbits, groups, order);
}

// pose(angles, fix, coords): the state the angles give, closed onto the loop-closure manifold
// and posed (ori_mechanism_pose_state): (closed angles, positions).
PyObject *ori_py_pattern_pose(PyObject *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"angles", "fix", "coords", NULL};
    ori_py_pattern *pat = (ori_py_pattern *)self;
    PyObject *angles, *coords = Py_None;
    int fix;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "Oi|O", kwlist, &angles, &fix, &coords)) return NULL;
    if (angles == Py_None) { // a fold's start may be None (the flat state), the state posed may not
        PyErr_SetString(PyExc_ValueError, "angles must be a 1-D array of numbers");
        return NULL;
    }
    fold_inputs in;
    if (!fold_inputs_read(&in, pat, fix, angles, coords, Py_None, Py_None)) return NULL;
    npy_intp E = ori_mechanism_edge_count(in.mech->m), dims[2] = {ori_mechanism_vertex_count(in.mech->m), 3};
    PyObject *closed = PyArray_SimpleNew(1, &E, NPY_DOUBLE), *pos = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    PyObject *result = NULL;
    if (closed && pos) {
        ori_error err;
        ori_status st;
        Py_BEGIN_ALLOW_THREADS
        st = ori_mechanism_pose_state(in.mech->m, in.start, fix, in.pose, PyArray_DATA((PyArrayObject *)closed),
                                      PyArray_DATA((PyArrayObject *)pos), NULL, &err);
        Py_END_ALLOW_THREADS
        if (st != ORI_OK) ori_py_raise(ori_py_pattern_source(pat), &err);
        else result = Py_BuildValue("(OO)", closed, pos);
    }
    Py_XDECREF(closed);
    Py_XDECREF(pos);
    fold_inputs_free(&in);
    return result;
}

// --- reading a motion -------------------------------------------------------------------------------

static PyObject *motion_angles(PyObject *obj, PyObject *args)
{
    ori_py_motion *self = (ori_py_motion *)obj;
    int stride = 0, E = ori_mechanism_edge_count(mech_of(self));
    const double *a = self->mo ? ori_motion_angles(self->mo, &stride) : ori_multifold_angles(self->mf, &stride);
    static const double none = 0.0;
    npy_intp dims[2] = {shown_frames(self), E}, strides[2] = {(npy_intp)(sizeof(double) * (size_t)stride), sizeof(double)};
    return ori_py_view(obj, NPY_DOUBLE, 2, dims, strides, a ? a : &none);
}

static PyObject *motion_vertices(PyObject *obj, PyObject *args)
{
    ori_py_motion *self = (ori_py_motion *)obj;
    int V = ori_mechanism_vertex_count(mech_of(self));
    // Computed once, with the GIL held (ori_motion_vertices is not safe against a concurrent first call).
    const ori_v3 *v = self->mo ? ori_motion_vertices(self->mo) : ori_multifold_vertices(self->mf);
    static const ori_v3 none = {0.0, 0.0, 0.0};
    npy_intp dims[3] = {shown_frames(self), V, 3};
    return ori_py_view(obj, NPY_DOUBLE, 3, dims, NULL, v ? v : &none);
}

// Per frame shown: the driven crease's angle or the progress (which 0), the residual (1).
static PyObject *motion_column(ori_py_motion *self, int which)
{
    npy_intp n = shown_frames(self);
    PyObject *arr = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    if (!arr) return NULL;
    double *out = PyArray_DATA((PyArrayObject *)arr);
    for (npy_intp k = 0; k < n; ++k) {
        int f = (int)k;
        if (self->mo) out[k] = which ? ori_motion_frame_residual(self->mo, f) : ori_motion_frame_drive(self->mo, f);
        else out[k] = which ? ori_multifold_frame_residual(self->mf, f) : ori_multifold_frame_progress(self->mf, f);
    }
    return arr;
}

static PyObject *motion_drives(PyObject *obj, PyObject *args) { return motion_column((ori_py_motion *)obj, 0); }

static PyObject *motion_residuals(PyObject *obj, PyObject *args) { return motion_column((ori_py_motion *)obj, 1); }

static bool frame_index(const ori_py_motion *self, int *k)
{
    int n = shown_frames(self);
    if (*k < 0) *k += n;
    if (*k < 0 || *k >= n) {
        PyErr_Format(PyExc_IndexError, "frame %d is out of range (the motion has %d frames)", *k, n);
        return false;
    }
    return true;
}

static PyObject *motion_face_poses(PyObject *obj, PyObject *args)
{
    ori_py_motion *self = (ori_py_motion *)obj;
    int k;
    if (!PyArg_ParseTuple(args, "i", &k) || !frame_index(self, &k)) return NULL;
    const ori_mechanism *m = mech_of(self);
    npy_intp dims[3] = {ori_mechanism_face_count(m), 3, 4};
    PyObject *arr = PyArray_SimpleNew(3, dims, NPY_DOUBLE);
    ori_rigid *g = PyMem_Malloc(sizeof(ori_rigid) * (size_t)(dims[0] + 1));
    if (!arr || !g) {
        Py_XDECREF(arr);
        PyMem_Free(g);
        return PyErr_NoMemory();
    }
    const double *a = self->mo ? ori_motion_frame_angles(self->mo, k) : ori_multifold_frame_angles(self->mf, k);
    ori_mechanism_face_poses(m, a, self->def.fixed_face, self->def.fixed_pose, g);
    double *out = PyArray_DATA((PyArrayObject *)arr);
    for (npy_intp f = 0; f < dims[0]; ++f) {
        double *o = out + 12 * f;
        double t[3] = {g[f].t.x, g[f].t.y, g[f].t.z};
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 3; ++c) o[4 * r + c] = g[f].r.m[r][c];
            o[4 * r + 3] = t[r];
        }
    }
    PyMem_Free(g);
    return arr;
}

static PyObject *motion_info(PyObject *obj, PyObject *args)
{
    ori_py_motion *self = (ori_py_motion *)obj;
    const char *reason = self->mo ? ori_motion_reason(self->mo) : ori_multifold_reason(self->mf);
    const char *verdict = self->mo ? ori_motion_verdict_name(ori_motion_verdict_of(self->mo))
                                   : ori_multifold_verdict_name(ori_multifold_verdict_of(self->mf));
    bool valid = self->mo ? ori_motion_verdict_of(self->mo) == ORI_MOTION_VALID
                          : ori_multifold_verdict_of(self->mf) == ORI_MULTIFOLD_REACHED;
    PyObject *d = ori_py_dict("kind", PyUnicode_FromString(self->mo ? "drive" : self->targets ? "targets" : "drives"),
                              "verdict", PyUnicode_FromString(verdict), "valid", PyBool_FromLong(valid), "reason",
                              reason ? PyUnicode_FromString(reason) : Py_NewRef(Py_None), "frames",
                              PyLong_FromLong(motion_frames(self)), "fixed_face", PyLong_FromLong(self->def.fixed_face),
                              "locked", ori_py_ints(self->locks, self->nlocks), NULL);
    if (!d) return NULL;
    bool ok = true;
    if (self->mo) {
        ori_motion_stats st = ori_motion_stats_of(self->mo);
        const char *solver = st.analytic ? "closed-form spherical 4R"
                             : st.sweep  ? "continuation, sweep (block substitution along the loops; CHOLMOD fallback)"
                             : st.sparse ? "continuation, sparse (CHOLMOD)"
                                         : "continuation, dense (LAPACK)";
        PyObject *stats = ori_py_dict("analytic", PyBool_FromLong(st.analytic), "sparse", PyBool_FromLong(st.sparse),
                                      "sweep", PyBool_FromLong(st.sweep), "steps", PyLong_FromLong(st.steps),
                                      "rejected_steps", PyLong_FromLong(st.rejected_steps), "newton_iterations",
                                      PyLong_FromLong(st.newton_iterations), "factorizations",
                                      PyLong_FromLong(st.factorizations), "max_residual",
                                      PyFloat_FromDouble(st.max_residual), NULL);
        ok = stats && PyDict_SetItemString(d, "stats", stats) == 0;
        Py_XDECREF(stats);
        PyObject *more = ori_py_dict("solver", PyUnicode_FromString(solver), "drive", PyLong_FromLong(self->def.driven_edge),
                                     "dof", PyLong_FromLong(ori_motion_dof(self->mo)), "rigidly_foldable",
                                     PyBool_FromLong(ori_motion_verdict_of(self->mo) != ORI_MOTION_NOT_RIGIDLY_FOLDABLE),
                                     NULL);
        ok = ok && more && PyDict_Update(d, more) == 0;
        Py_XDECREF(more);
        // Creases folding against their assignment.
        int nv = ori_motion_violation_count(self->mo);
        PyObject *viol = PyList_New(nv);
        for (int i = 0; viol && i < nv; ++i) {
            ori_crease_violation v = ori_motion_violation(self->mo, i);
            char as[2] = {ori_assignment_to_char(v.assignment), 0};
            PyList_SET_ITEM(viol, i, ori_py_dict("edge", PyLong_FromLong(v.edge), "assignment", PyUnicode_FromString(as),
                                                 "angle_rad", PyFloat_FromDouble(v.angle_rad), "drive_rad",
                                                 PyFloat_FromDouble(v.drive_rad), NULL));
        }
        ok = ok && viol && PyDict_SetItemString(d, "violations", viol) == 0;
        Py_XDECREF(viol);
        ori_motion_block b;
        PyObject *blk = Py_NewRef(Py_None);
        if (ori_motion_block_of(self->mo, &b)) {
            Py_DECREF(blk);
            blk = ori_py_dict("kind", PyUnicode_FromString(b.kind == ORI_BLOCK_CREASE_LIMIT ? "crease_limit" : b.kind == ORI_BLOCK_STEP_LIMIT ? "step_limit" : "singular"),
                              "drive_rad", PyFloat_FromDouble(b.drive_rad), "edge",
                              b.edge == ORI_NULL_INDEX ? Py_NewRef(Py_None) : PyLong_FromLong(b.edge), "edge_angle_rad",
                              PyFloat_FromDouble(b.edge_angle_rad), "singular_edges",
                              ori_py_ints(b.singular_edges, b.singular_count < 32 ? b.singular_count : 32), NULL);
        }
        ok = ok && blk && PyDict_SetItemString(d, "blocked", blk) == 0;
        Py_XDECREF(blk);
        ori_vertex_split s;
        PyObject *split = Py_NewRef(Py_None);
        if (ori_motion_split(self->mo, &s)) {
            Py_DECREF(split);
            split = ori_py_dict("vertex", PyLong_FromLong(s.vertex), "frame_a", ori_py_ints(s.frame_a, 2), "frame_b",
                                ori_py_ints(s.frame_b, s.frame_b_count), "surrounding",
                                ori_py_ints(s.surrounding, s.surrounding_count), "d", ori_py_v3(s.d), NULL);
        }
        ok = ok && split && PyDict_SetItemString(d, "split", split) == 0;
        Py_XDECREF(split);
    } else {
        int steps, rejected, newton;
        ori_multifold_stats(self->mf, &steps, &rejected, &newton);
        int se = ori_multifold_stop_edge(self->mf);
        npy_intp E = ori_mechanism_edge_count(mech_of(self));
        PyObject *more = ori_py_dict(
            "stop_edge", se == ORI_NULL_INDEX ? Py_NewRef(Py_None) : PyLong_FromLong(se), "extra_dof",
            PyLong_FromLong(ori_multifold_extra_dof(self->mf)), "held_at_180", PyLong_FromLong(ori_multifold_held_count(self->mf)),
            "goal_rad", ori_py_doubles(ori_multifold_goal(self->mf), E), "stats",
            ori_py_dict("steps", PyLong_FromLong(steps), "rejected_steps", PyLong_FromLong(rejected), "newton_iterations",
                        PyLong_FromLong(newton), NULL),
            NULL);
        ok = more && PyDict_Update(d, more) == 0;
        Py_XDECREF(more);
    }
    if (!ok) {
        Py_DECREF(d);
        return NULL;
    }
    return d;
}

static PyObject *motion_end_effector(PyObject *obj, PyObject *args)
{
    ori_py_motion *self = (ori_py_motion *)obj;
    int k;
    if (!PyArg_ParseTuple(args, "i", &k) || !frame_index(self, &k)) return NULL;
    ori_v3 a, b;
    if (!self->mo || !ori_motion_frame_end_effector(self->mo, k, &a, &b)) Py_RETURN_NONE;
    return Py_BuildValue("(NN)", ori_py_v3(a), ori_py_v3(b));
}

static PyObject *motion_other_branch(PyObject *obj, PyObject *args)
{
    ori_py_motion *self = (ori_py_motion *)obj;
    int k;
    if (!PyArg_ParseTuple(args, "i", &k) || !frame_index(self, &k)) return NULL;
    if (!self->mo) Py_RETURN_NONE;
    npy_intp E = ori_mechanism_edge_count(mech_of(self));
    PyObject *arr = PyArray_SimpleNew(1, &E, NPY_DOUBLE);
    if (!arr) return NULL;
    if (!ori_motion_frame_other_branch(self->mo, k, PyArray_DATA((PyArrayObject *)arr))) {
        Py_DECREF(arr);
        Py_RETURN_NONE;
    }
    return arr;
}

// at(t): the exact state at fraction t (0 … 1) of the motion from its first to its last frame:
// a single drive is solved again from the frame before (as ori_record_at restores a sequence),
// several degrees of freedom are interpolated in the progress and closed (ori_multifold_at).
// Returns (angles, positions, drive or progress).
static PyObject *motion_at(PyObject *obj, PyObject *args)
{
    ori_py_motion *self = (ori_py_motion *)obj;
    double t;
    if (!PyArg_ParseTuple(args, "d", &t)) return NULL;
    int n = shown_frames(self);
    if (n == 0) return PyErr_Format(PyExc_ValueError, "the motion has no frames");
    if (!(t >= 0.0 && t <= 1.0)) return PyErr_Format(PyExc_ValueError, "t = %g is outside [0, 1]", t);
    const ori_mechanism *m = mech_of(self);
    npy_intp E = ori_mechanism_edge_count(m), dims[2] = {ori_mechanism_vertex_count(m), 3};
    PyObject *angles = PyArray_SimpleNew(1, &E, NPY_DOUBLE), *pos = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    if (!angles || !pos) goto fail;
    double *a = PyArray_DATA((PyArrayObject *)angles);
    ori_v3 *p = PyArray_DATA((PyArrayObject *)pos);
    ori_error err;
    ori_status st = ORI_OK;
    double x;
    if (self->mf) {
        double x0 = ori_multifold_frame_progress(self->mf, 0), x1 = ori_multifold_frame_progress(self->mf, n - 1);
        x = t == 1.0 ? x1 : x0 + t * (x1 - x0);
        Py_BEGIN_ALLOW_THREADS
        st = ori_multifold_at(self->mf, self->locks, self->nlocks, x, a, p, &err);
        Py_END_ALLOW_THREADS
    } else {
        double x0 = ori_motion_frame_drive(self->mo, 0), x1 = ori_motion_frame_drive(self->mo, n - 1);
        x = t == 1.0 ? x1 : x0 + t * (x1 - x0);
        // The last frame at or before x along the motion's direction.
        int k = 0;
        double dir = x1 >= x0 ? 1.0 : -1.0;
        while (k + 1 < n && dir * (ori_motion_frame_drive(self->mo, k + 1) - x) <= 0.0) k++;
        const double *ak = ori_motion_frame_angles(self->mo, k);
        if (ori_motion_frame_drive(self->mo, k) == x) {
            memcpy(a, ak, sizeof(double) * (size_t)E);
            ori_motion_frame_vertices(self->mo, k, p);
        } else {
            ori_motion_def d = self->def;
            d.start_angles_rad = ak;
            d.has_from = false;
            d.to_rad = x;
            d.step_rad = fabs(x - ori_motion_frame_drive(self->mo, k));
            d.last_frame_only = true;
            d.fixed_pose = ori_motion_fixed_pose(self->mo);
            ori_motion *mo = NULL;
            Py_BEGIN_ALLOW_THREADS
            st = ori_motion_solve(m, &d, &mo, &err);
            Py_END_ALLOW_THREADS
            if (st == ORI_OK) {
                int nf = ori_motion_frame_count(mo);
                if (nf == 0 || ori_motion_verdict_of(mo) != ORI_MOTION_VALID) {
                    ori_error_clear(&err);
                    err.status = st = ORI_ERR_NOT_CONVERGED;
                    snprintf(err.message, sizeof err.message, "the motion could not be restored at t = %g", t);
                } else {
                    memcpy(a, ori_motion_frame_angles(mo, nf - 1), sizeof(double) * (size_t)E);
                    ori_motion_frame_vertices(mo, nf - 1, p);
                }
            }
            ori_motion_destroy(mo);
        }
    }
    if (st != ORI_OK) {
        ori_py_raise(ori_py_pattern_source((ori_py_pattern *)self->pattern), &err);
        goto fail;
    }
    return Py_BuildValue("(NNd)", angles, pos, x);
fail:
    Py_XDECREF(angles);
    Py_XDECREF(pos);
    return NULL;
}

// collide(clearance, progress): check the motion frame by frame for self-collision (as
// `orikin fold` does); afterwards the motion shows the frames before the first contact.
// Returns the first contact as a dict, or None.
static PyObject *motion_collide(PyObject *obj, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"clearance", "progress", NULL};
    ori_py_motion *self = (ori_py_motion *)obj;
    double clearance = 0.0;
    PyObject *progress = Py_None;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "|dO", kwlist, &clearance, &progress)) return NULL;
    ori_py_progress pp;
    if (!ori_py_progress_init(&pp, progress)) return NULL;
    ori_py_pattern *pat = (ori_py_pattern *)self->pattern;
    const char *src = ori_py_pattern_source(pat);
    ori_collider *c = ori_py_collider(pat, clearance);
    if (!c) return NULL;
    ori_error err;
    ori_collision_motion_def check = ori_default_collision_motion_def();
    check.progress = ori_py_progress_fn;
    check.progress_user = &pp;
    ori_collision_event ev;
    ori_status st;
    const ori_mechanism *m = mech_of(self);
    ori_motion_def d = self->def;
    Py_BEGIN_ALLOW_THREADS
    if (self->mo) st = ori_collision_check_motion(c, m, &d, self->mo, &check, &ev, &err);
    else st = ori_collision_check_multifold(c, self->mf, self->locks, self->nlocks, &check, &ev, &err);
    Py_END_ALLOW_THREADS
    ori_collider_destroy(c);
    if (st != ORI_OK) return ori_py_solve_failed(&pp, src, &err);
    if (ori_py_progress_raise(&pp)) return NULL;
    self->checked = true;
    self->ev = ev;
    self->clearance = clearance;
    if (!ev.collides) Py_RETURN_NONE;
    return ori_py_event_dict(&ev, self->mf != NULL);
}

// lock_suggestion(): the lock set that leaves this single-drive fold one degree of freedom
// (what an underdetermined fold's hint names, as the CLI's): a list, or an exception.
static PyObject *motion_lock_suggestion(PyObject *obj, PyObject *args)
{
    ori_py_motion *self = (ori_py_motion *)obj;
    if (!self->mo) return PyErr_Format(PyExc_ValueError, "a lock suggestion is for a fold with one driven crease");
    const ori_mechanism *m = mech_of(self);
    int cap = ori_mechanism_edge_count(m) + 1;
    int *out = PyMem_Malloc(sizeof(int) * (size_t)cap);
    if (!out) return PyErr_NoMemory();
    ori_error err;
    int n;
    Py_BEGIN_ALLOW_THREADS
    n = ori_mechanism_lock_set(m, self->start, &self->def.driven_edge, 1, self->locks, self->nlocks, NULL, out, cap, &err);
    Py_END_ALLOW_THREADS
    PyObject *r = NULL;
    if (n < 0) ori_py_raise(ori_py_pattern_source((ori_py_pattern *)self->pattern), &err);
    else r = ori_py_ints(out, n);
    PyMem_Free(out);
    return r;
}

static PyObject *motion_counts(PyObject *obj, void *what)
{
    ori_py_motion *self = (ori_py_motion *)obj;
    switch ((int)(intptr_t)what) {
    case 0: return PyLong_FromLong(shown_frames(self));
    case 1: return PyLong_FromLong(motion_frames(self));
    case 2: return Py_NewRef(self->pattern);
    default: return PyBool_FromLong(self->checked);
    }
}

static PyGetSetDef motion_getset[] = {
    {"frame_count", motion_counts, NULL, "Frames shown: all, or those before the first contact once collide() found one.", (void *)0},
    {"solved_frames", motion_counts, NULL, "Frames the solver produced.", (void *)1},
    {"pattern", motion_counts, NULL, "The crease pattern folded.", (void *)2},
    {"checked", motion_counts, NULL, "True once collide() ran.", (void *)3},
    {NULL, NULL, NULL, NULL, NULL},
};

#define KW (PyCFunction)(void (*)(void))
static PyMethodDef motion_methods[] = {
    {"angles", motion_angles, METH_NOARGS, "(frames, E) fold angles in radians: a read-only view of the library's block."},
    {"vertices", motion_vertices, METH_NOARGS, "(frames, V, 3) world positions: a read-only view (computed once)."},
    {"drives", motion_drives, METH_NOARGS, "Per frame: the driven crease's angle (radians) or the progress (0 to 1)."},
    {"residuals", motion_residuals, METH_NOARGS, "Per frame: the loop-closure residual."},
    {"face_poses", motion_face_poses, METH_VARARGS, "face_poses(k): (F, 3, 4) rigid poses [R | t] of frame k."},
    {"info", motion_info, METH_NOARGS, "Verdict, reason, statistics, split, blocked, violations (a dict)."},
    {"end_effector", motion_end_effector, METH_VARARGS, "end_effector(k): (in Frame A, in Frame B) or None."},
    {"other_branch", motion_other_branch, METH_VARARGS, "other_branch(k): the other closed-form branch or None."},
    {"at", motion_at, METH_VARARGS, "at(t): (angles, positions, drive) at fraction t of the motion."},
    {"collide", KW motion_collide, METH_VARARGS | METH_KEYWORDS, "collide(clearance, progress): the first contact or None."},
    {"lock_suggestion", motion_lock_suggestion, METH_NOARGS, "The lock set leaving one degree of freedom (a list)."},
    {NULL, NULL, 0, NULL},
};

PyTypeObject ori_py_MotionType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "orikin._orikin.Motion",
    .tp_basicsize = sizeof(ori_py_motion),
    .tp_weaklistoffset = offsetof(ori_py_motion, weakrefs),
    .tp_dealloc = motion_dealloc,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "A solved fold (ori_motion or ori_multifold) with the pattern and mechanism it refers to.",
    .tp_methods = motion_methods,
    .tp_getset = motion_getset,
};

const ori_motion *ori_py_motion_of(PyObject *obj, int *driven_edge)
{
    if (!PyObject_TypeCheck(obj, &ori_py_MotionType)) return NULL;
    ori_py_motion *self = (ori_py_motion *)obj;
    if (driven_edge) *driven_edge = self->def.driven_edge;
    return self->mo;
}

ori_py_pattern *ori_py_motion_pattern(PyObject *obj) { return (ori_py_pattern *)((ori_py_motion *)obj)->pattern; }

PyMethodDef ori_py_motion_functions[] = {{NULL, NULL, 0, NULL}};
