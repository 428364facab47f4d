// Hinge mechanics and Lorentz actuation along a fold or a sequence (actuate: ori_sizing_solve),
// and folding dynamics (simulate: ori_simulation_run), from the design fields of the pattern's
// FOLD document (edges_orikin:hinge, faces_orikin:panel, orikin:actuation). SI units.
#include "pyorikin.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

// The overrides of the design the CLI's actuation options give (act_load), None = the file's.
typedef struct design_opts {
    PyObject *field, *current_limit, *gravity, *damping, *meters_per_unit;
    const char *materials;
} design_opts;

static bool read_v3(PyObject *obj, ori_v3 *out, const char *what)
{
    PyArrayObject *a = ori_py_double_array(obj, 3, 0, what);
    if (!a) return false;
    const double *d = PyArray_DATA(a);
    *out = ori_v3_make(d[0], d[1], d[2]);
    Py_DECREF(a);
    return true;
}

// The design of a pattern with the overrides; NULL with an exception.
static ori_design *make_design(ori_py_pattern *pat, const design_opts *o, ori_materials **mats)
{
    const char *src = ori_py_pattern_source(pat);
    ori_error err;
    *mats = ori_materials_create();
    if (o->materials && ori_materials_load_file(*mats, o->materials, &err) != ORI_OK) {
        ori_py_raise(o->materials, &err);
        return NULL;
    }
    bool owned;
    ori_fold *doc = ori_py_pattern_doc(pat, &owned, &err);
    if (!doc) {
        ori_py_raise(src, &err);
        return NULL;
    }
    ori_design_def dd = ori_default_design_def();
    dd.doc = doc;
    dd.pattern = pat->p;
    dd.materials = *mats;
    if (o->meters_per_unit && o->meters_per_unit != Py_None) {
        dd.has_meters_per_unit = true;
        dd.meters_per_unit = PyFloat_AsDouble(o->meters_per_unit);
        if (PyErr_Occurred()) {
            if (owned) ori_fold_destroy(doc);
            return NULL;
        }
    }
    ori_design *d = NULL;
    ori_status st = ori_design_create(&dd, &d, &err);
    if (owned) ori_fold_destroy(doc);
    if (st != ORI_OK) {
        if (strcmp(err.field, "frame_unit") == 0 && !dd.has_meters_per_unit) { // as the CLI words it
            ori_error e = err;
            snprintf(e.message, sizeof e.message, "frame_unit: %.160s (meters_per_unit: the length of a unit in metres)",
                     err.message);
            e.field[0] = '\0';
            e.element = ORI_NULL_INDEX;
            ori_py_raise(src, &e);
        } else {
            ori_py_raise(src, &err);
        }
        return NULL;
    }
    ori_actuation a = ori_design_actuation(d);
    bool ok = true;
    if (o->field && o->field != Py_None) {
        ok = read_v3(o->field, &a.field_t, "field");
        a.has_field = true;
        a.schedule_count = 0; // a field given replaces the file's schedule
    }
    if (ok && o->current_limit && o->current_limit != Py_None) {
        a.has_current_limit = true;
        a.current_limit_a = PyFloat_AsDouble(o->current_limit);
        ok = !PyErr_Occurred();
    }
    if (ok && o->gravity && o->gravity != Py_None) {
        int g = PyObject_IsTrue(o->gravity);
        a.gravity_m_s2 = g ? ori_v3_make(0, 0, -9.80665) : ori_v3_make(0, 0, 0);
    }
    if (ok && o->damping && o->damping != Py_None) {
        a.damping_ratio = PyFloat_AsDouble(o->damping);
        ok = !PyErr_Occurred();
    }
    if (ok && ori_design_set_actuation(d, &a, &err) != ORI_OK) {
        ori_py_raise(src, &err);
        ok = false;
    }
    if (!ok) {
        ori_design_destroy(d);
        return NULL;
    }
    return d;
}

static PyObject *schedule_list(const ori_field_change *s, int n)
{
    PyObject *out = PyList_New(n);
    for (int i = 0; out && i < n; ++i) {
        PyObject *o = ori_py_dict("edge", s[i].edge == ORI_NULL_INDEX ? Py_NewRef(Py_None) : PyLong_FromLong(s[i].edge),
                                  "from_rad", PyFloat_FromDouble(s[i].from_rad), "field", ori_py_v3(s[i].field_t), "fold",
                                  PyLong_FromLong(s[i].fold), NULL);
        if (!o) {
            Py_CLEAR(out);
            break;
        }
        PyList_SET_ITEM(out, i, o);
    }
    return out;
}

static PyObject *mechanics_dict(const ori_hinge_mechanics *m)
{
    return ori_py_dict("stiffness_nm_rad", PyFloat_FromDouble(m->stiffness_nm_rad), "yield_moment_nm",
                       PyFloat_FromDouble(m->yield_moment_nm), "plastic_moment_nm", PyFloat_FromDouble(m->plastic_moment_nm),
                       "yield_rotation_rad", PyFloat_FromDouble(m->yield_rotation_rad), "has_wire",
                       PyBool_FromLong(m->has_wire), "wire_path_m", PyFloat_FromDouble(m->wire_path_m), "resistance_ohm",
                       PyFloat_FromDouble(m->resistance_ohm), "current_max_a",
                       m->has_current_density_max ? PyFloat_FromDouble(m->current_max_a) : Py_NewRef(Py_None), NULL);
}

#define DESIGN_KW "field", "current_limit", "gravity", "damping", "meters_per_unit", "materials"
#define DESIGN_ARGS(o) &o.field, &o.current_limit, &o.gravity, &o.damping, &o.meters_per_unit, &o.materials

// actuate(fold, schedule, reorientations, progress, **design): the sizing along a solved fold
// (a Motion with one driven crease) or a sequence run (a Record).
static PyObject *py_actuate(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"fold", "schedule", "reorientations", "progress", DESIGN_KW, NULL};
    PyObject *fold, *progress = Py_None;
    const char *schedule = "auto";
    int reorientations = -1;
    design_opts o = {NULL, NULL, NULL, NULL, NULL, NULL};
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|siOOOOOOz", kwlist, &fold, &schedule, &reorientations, &progress,
                                     DESIGN_ARGS(o)))
        return NULL;
    int driven = ORI_NULL_INDEX;
    const ori_sequence *seq = NULL;
    const ori_motion *mo = ori_py_motion_of(fold, &driven);
    const ori_record *rec = mo ? NULL : ori_py_record_of(fold, &seq);
    if (!mo && !rec)
        return PyErr_Format(PyExc_TypeError, "actuate needs a fold with one driven crease (a Motion) or a sequence (a Record)");
    ori_py_pattern *pat = mo ? ori_py_motion_pattern(fold) : ori_py_record_pattern(fold);
    ori_py_mechanism *mech = ori_py_pattern_mechanism(pat);
    if (!mech) return NULL;
    ori_py_progress pp;
    if (!ori_py_progress_init(&pp, progress)) return NULL;
    ori_sizing_def sd = ori_default_sizing_def();
    if (strcmp(schedule, "auto") == 0) sd.schedule = ORI_SCHEDULE_AUTO;
    else if (strcmp(schedule, "optimize") == 0) sd.schedule = ORI_SCHEDULE_OPTIMIZE;
    else if (strcmp(schedule, "fixed") == 0) sd.schedule = ORI_SCHEDULE_FIXED;
    else if (strcmp(schedule, "design") == 0) sd.schedule = ORI_SCHEDULE_DESIGN;
    else return PyErr_Format(PyExc_ValueError, "schedule is auto, optimize, fixed or design, got '%s'", schedule);
    if (reorientations >= 0) {
        sd.reorientations = reorientations;
        if (sd.schedule == ORI_SCHEDULE_AUTO) sd.schedule = ORI_SCHEDULE_OPTIMIZE; // as --reorientations N
    }
    ori_materials *mats = NULL;
    ori_design *design = make_design(pat, &o, &mats);
    if (!design) {
        ori_materials_destroy(mats);
        return NULL;
    }
    sd.design = design;
    sd.mechanism = mech->m;
    sd.motion = mo;
    sd.driven_edge = driven;
    sd.record = rec;
    sd.sequence = seq;
    sd.progress = ori_py_progress_fn;
    sd.progress_user = &pp;
    ori_sizing *z = NULL;
    ori_error err;
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ori_sizing_solve(&sd, &z, &err);
    Py_END_ALLOW_THREADS
    PyObject *result = NULL;
    if (st != ORI_OK) {
        ori_py_solve_failed(&pp, ori_py_pattern_source(pat), &err);
        goto done;
    }
    if (ori_py_progress_raise(&pp)) goto done;
    int H = ori_sizing_hinge_count(z), F = ori_sizing_frame_count(z);
    PyObject *hinges = PyList_New(H);
    npy_intp dims[2] = {H, F}, fdims[2] = {F, 3};
    static const char *const step_keys[] = {"angle_rad", "rate", "lorentz_moment_per_amp", "gravity_moment_nm",
                                            "required_moment_nm", "current_a", "power_w", "current_density_a_m2"};
    PyObject *steps[8] = {NULL};
    for (int k = 0; k < 8; ++k) steps[k] = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    PyObject *fields = PyArray_SimpleNew(2, fdims, NPY_DOUBLE), *drives = PyArray_SimpleNew(1, &fdims[0], NPY_DOUBLE);
    bool ok = hinges && fields && drives;
    for (int k = 0; k < 8; ++k) ok = ok && steps[k];
    for (int h = 0; ok && h < H; ++h) {
        ori_hinge_sizing s = ori_sizing_hinge(z, h);
        PyObject *d = ori_py_dict(
            "edge", PyLong_FromLong(s.edge), "mechanics", mechanics_dict(&s.mechanics), "travel_rad",
            PyFloat_FromDouble(s.travel_rad), "springback_rad", PyFloat_FromDouble(s.springback_rad), "plastic_rotation_rad",
            PyFloat_FromDouble(s.plastic_rotation_rad), "gravity_moment_max_nm", PyFloat_FromDouble(s.gravity_moment_max_nm),
            "gravity_ratio", PyFloat_FromDouble(s.gravity_ratio), "actuated", PyBool_FromLong(s.actuated),
            "current_needed_a", PyFloat_FromDouble(s.current_needed_a), "power_peak_w", PyFloat_FromDouble(s.power_peak_w),
            "current_density_peak_a_m2", PyFloat_FromDouble(s.current_density_peak_a_m2), "worst_frame",
            PyLong_FromLong(s.worst_frame), "feasible", PyBool_FromLong(s.feasible), "optimal_thickness_m",
            s.has_optimal_thickness ? PyFloat_FromDouble(s.optimal_thickness_m) : Py_NewRef(Py_None), "width_range_m",
            s.has_width_range ? Py_BuildValue("(dd)", s.width_min_m, s.width_max_m) : Py_NewRef(Py_None), NULL);
        if (!d) ok = false;
        else PyList_SET_ITEM(hinges, h, d);
        for (int f = 0; ok && f < F; ++f) {
            ori_sizing_step q = ori_sizing_step_at(z, h, f);
            double v[8] = {q.angle_rad, q.rate, q.lorentz_moment_per_amp, q.gravity_moment_nm,
                           q.required_moment_nm, q.current_a, q.power_w, q.current_density_a_m2};
            for (int k = 0; k < 8; ++k) ((double *)PyArray_DATA((PyArrayObject *)steps[k]))[(size_t)h * F + f] = v[k];
        }
    }
    for (int f = 0; ok && f < F; ++f) {
        ((ori_v3 *)PyArray_DATA((PyArrayObject *)fields))[f] = ori_sizing_frame_field(z, f);
        ((double *)PyArray_DATA((PyArrayObject *)drives))[f] = ori_sizing_frame_drive(z, f, NULL);
    }
    int ns = ori_sizing_schedule_count(z);
    ori_field_change sched[ORI_SCHEDULE_MAX];
    for (int i = 0; i < ns && i < ORI_SCHEDULE_MAX; ++i) sched[i] = ori_sizing_schedule_at(z, i);
    ori_sizing_summary sm = ori_sizing_summary_of(z);
    PyObject *stepd = ok ? PyDict_New() : NULL;
    for (int k = 0; stepd && k < 8; ++k)
        if (PyDict_SetItemString(stepd, step_keys[k], steps[k]) < 0) Py_CLEAR(stepd);
    if (ok && stepd)
        result = ori_py_dict(
            "feasible", PyBool_FromLong(sm.feasible), "worst_edge",
            sm.worst_edge == ORI_NULL_INDEX ? Py_NewRef(Py_None) : PyLong_FromLong(sm.worst_edge), "current_needed_a",
            PyFloat_FromDouble(sm.current_needed_a), "mechanism_current_a", PyFloat_FromDouble(sm.mechanism_current_a),
            "mechanism_worst_frame", PyLong_FromLong(sm.mechanism_worst_frame), "gravity_ratio_max",
            PyFloat_FromDouble(sm.gravity_ratio_max), "reorientations", PyLong_FromLong(sm.reorientations), "optimized",
            PyBool_FromLong(sm.optimized), "hinges", Py_NewRef(hinges), "schedule", schedule_list(sched, ns), "fields",
            Py_NewRef(fields), "drives_rad", Py_NewRef(drives), "steps", Py_NewRef(stepd), NULL);
    Py_XDECREF(stepd);
    Py_XDECREF(hinges);
    Py_XDECREF(fields);
    Py_XDECREF(drives);
    for (int k = 0; k < 8; ++k) Py_XDECREF(steps[k]);
done:
    ori_sizing_destroy(z);
    ori_design_destroy(design);
    ori_materials_destroy(mats);
    return result;
}

// A schedule from Python: a list of dicts {edge (None = the reference crease), from_rad, field, fold}.
static int read_schedule(PyObject *obj, ori_field_change *out)
{
    PyObject *seq = PySequence_Fast(obj, "schedule must be a list of {edge, from_rad, field, fold}");
    if (!seq) return -1;
    Py_ssize_t n = PySequence_Fast_GET_SIZE(seq);
    if (n > ORI_SCHEDULE_MAX) {
        Py_DECREF(seq);
        PyErr_Format(PyExc_ValueError, "a schedule has at most %d entries", ORI_SCHEDULE_MAX);
        return -1;
    }
    for (Py_ssize_t i = 0; i < n; ++i) {
        PyObject *d = PySequence_Fast_GET_ITEM(seq, i);
        PyObject *e = PyMapping_Check(d) ? PyMapping_GetItemString(d, "edge") : NULL;
        PyObject *f = e ? PyMapping_GetItemString(d, "from_rad") : NULL;
        PyObject *b = f ? PyMapping_GetItemString(d, "field") : NULL;
        PyObject *k = b ? PyMapping_GetItemString(d, "fold") : NULL;
        bool ok = k != NULL;
        if (ok) {
            out[i].edge = e == Py_None ? ORI_NULL_INDEX : (int)PyLong_AsLong(e);
            out[i].from_rad = PyFloat_AsDouble(f);
            out[i].fold = (int)PyLong_AsLong(k);
            ok = !PyErr_Occurred() && read_v3(b, &out[i].field_t, "schedule field");
        }
        Py_XDECREF(e);
        Py_XDECREF(f);
        Py_XDECREF(b);
        Py_XDECREF(k);
        if (!ok) {
            Py_DECREF(seq);
            if (!PyErr_Occurred() || PyErr_ExceptionMatches(PyExc_KeyError)) {
                PyErr_Clear();
                PyErr_SetString(PyExc_ValueError, "schedule entries are {edge, from_rad, field, fold}");
            }
            return -1;
        }
    }
    Py_DECREF(seq);
    return (int)n;
}

// simulate(pattern, fix, current, duration, ...): folding dynamics.
static PyObject *py_simulate(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"pattern", "fix", "current", "duration", "start", "coords", "targets", "schedule", "dt",
                             "pulse", "frames", "stops", "settle", "current_off_at_target", "auto_polarity", "progress",
                             DESIGN_KW, NULL};
    PyObject *pobj, *start = Py_None, *coords = Py_None, *targets = Py_None, *schedule = Py_None, *dt = Py_None,
                    *pulse = Py_None, *progress = Py_None;
    int fix, frames = 101, stops = 1, settle = 1, off_at_target = 1, auto_polarity = 1;
    double current, duration;
    design_opts o = {NULL, NULL, NULL, NULL, NULL, NULL};
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O!idd|OOOOOOippppOOOOOOz", kwlist, &ori_py_PatternType, &pobj, &fix,
                                     &current, &duration, &start, &coords, &targets, &schedule, &dt, &pulse, &frames, &stops,
                                     &settle, &off_at_target, &auto_polarity, &progress, DESIGN_ARGS(o)))
        return NULL;
    ori_py_pattern *pat = (ori_py_pattern *)pobj;
    const char *src = ori_py_pattern_source(pat);
    ori_py_mechanism *mech = ori_py_pattern_mechanism(pat);
    if (!mech || !ori_py_check_face(pat, "--fix", fix)) return NULL;
    ori_py_progress pp;
    if (!ori_py_progress_init(&pp, progress)) return NULL;
    const ori_mechanism *m = mech->m;
    int E = ori_mechanism_edge_count(m), V = ori_mechanism_vertex_count(m);
    ori_simulation_def d = ori_default_simulation_def();
    ori_field_change sched[ORI_SCHEDULE_MAX];
    if (schedule != Py_None) {
        int n = read_schedule(schedule, sched);
        if (n < 0) return NULL;
        d.schedule = sched;
        d.schedule_count = n;
    }
    ori_py_state s;
    if (!ori_py_state_read(&s, pat, start, coords)) return NULL;
    PyArrayObject *ta = NULL;
    ori_materials *mats = NULL;
    ori_design *design = NULL;
    ori_simulation *sim = NULL;
    PyObject *result = NULL;
    if (targets != Py_None && !(ta = ori_py_double_array(targets, E, 0, "targets"))) goto done;
    ori_error err;
    d.fixed_pose = ori_rigid_identity();
    if (s.positions && ori_mechanism_face_pose_from_coords(m, fix, s.positions, &d.fixed_pose, &err) != ORI_OK) {
        ori_py_raise(src, &err);
        goto done;
    }
    if (!(design = make_design(pat, &o, &mats))) goto done;
    d.design = design;
    d.mechanism = m;
    d.fixed_face = fix;
    d.start_angles_rad = s.angles;
    d.target_angles_rad = ta ? PyArray_DATA(ta) : NULL;
    d.current_a = current;
    d.auto_polarity = auto_polarity;
    d.duration_s = duration;
    if (dt != Py_None) {
        d.has_dt = true;
        d.dt_s = PyFloat_AsDouble(dt);
    }
    if (pulse != Py_None) {
        d.has_pulse = true;
        d.pulse_s = PyFloat_AsDouble(pulse);
    }
    if (PyErr_Occurred()) goto done;
    d.output_frames = frames;
    d.stops = stops;
    d.settle = settle;
    d.current_off_at_target = off_at_target;
    d.progress = ori_py_progress_fn;
    d.progress_user = &pp;
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ori_simulation_run(&d, &sim, &err);
    Py_END_ALLOW_THREADS
    if (st != ORI_OK) {
        ori_py_solve_failed(&pp, src, &err);
        goto done;
    }
    if (ori_py_progress_raise(&pp)) goto done;
    {
        npy_intp F = ori_simulation_frame_count(sim), ad[2] = {F, E}, vd[3] = {F, V, 3}, fd[2] = {F, 3}, ed[2] = {F, 2};
        PyObject *times = PyArray_SimpleNew(1, &F, NPY_DOUBLE), *angles = PyArray_SimpleNew(2, ad, NPY_DOUBLE),
                 *currents = PyArray_SimpleNew(2, ad, NPY_DOUBLE), *plastic = PyArray_SimpleNew(2, ad, NPY_DOUBLE),
                 *fields = PyArray_SimpleNew(2, fd, NPY_DOUBLE), *energy = PyArray_SimpleNew(2, ed, NPY_DOUBLE),
                 *resid = PyArray_SimpleNew(1, &F, NPY_DOUBLE), *verts = PyArray_SimpleNew(3, vd, NPY_DOUBLE);
        if (times && angles && currents && plastic && fields && energy && resid && verts) {
            for (npy_intp f = 0; f < F; ++f) {
                int k = (int)f;
                ((double *)PyArray_DATA((PyArrayObject *)times))[f] = ori_simulation_frame_time(sim, k);
                memcpy((double *)PyArray_DATA((PyArrayObject *)angles) + f * E, ori_simulation_frame_angles(sim, k),
                       sizeof(double) * (size_t)E);
                memcpy((double *)PyArray_DATA((PyArrayObject *)currents) + f * E, ori_simulation_frame_currents(sim, k),
                       sizeof(double) * (size_t)E);
                memcpy((double *)PyArray_DATA((PyArrayObject *)plastic) + f * E, ori_simulation_frame_plastic(sim, k),
                       sizeof(double) * (size_t)E);
                ((ori_v3 *)PyArray_DATA((PyArrayObject *)fields))[f] = ori_simulation_frame_field(sim, k);
                double *en = (double *)PyArray_DATA((PyArrayObject *)energy) + 2 * f;
                ori_simulation_frame_energy(sim, k, &en[0], &en[1]);
                ((double *)PyArray_DATA((PyArrayObject *)resid))[f] = ori_simulation_frame_residual(sim, k);
                ori_simulation_frame_vertices(sim, k, (ori_v3 *)PyArray_DATA((PyArrayObject *)verts) + f * V);
            }
            ori_simulation_summary sm = ori_simulation_summary_of(sim);
            result = ori_py_dict(
                "times", Py_NewRef(times), "angles", Py_NewRef(angles), "currents", Py_NewRef(currents), "plastic",
                Py_NewRef(plastic), "fields", Py_NewRef(fields), "energies", Py_NewRef(energy), "residuals",
                Py_NewRef(resid), "vertices", Py_NewRef(verts), "latched_rad", ori_py_doubles(ori_simulation_latched_angles(sim), E),
                "reached_target", PyBool_FromLong(sm.reached_target), "time_to_target_s",
                sm.reached_target ? PyFloat_FromDouble(sm.time_to_target_s) : Py_NewRef(Py_None), "peak_angular_velocity",
                PyFloat_FromDouble(sm.peak_angular_velocity), "energy_drift", PyFloat_FromDouble(sm.energy_drift),
                "max_residual", PyFloat_FromDouble(sm.max_residual), "steps", PyLong_FromLong(sm.steps), "explicit_steps",
                PyLong_FromLong(sm.explicit_steps), "dt_s", PyFloat_FromDouble(sm.dt_s), "energy_in_j",
                PyFloat_FromDouble(sm.energy_in_j), "dissipated_j", PyFloat_FromDouble(sm.dissipated_j), NULL);
        }
        Py_XDECREF(times);
        Py_XDECREF(angles);
        Py_XDECREF(currents);
        Py_XDECREF(plastic);
        Py_XDECREF(fields);
        Py_XDECREF(energy);
        Py_XDECREF(resid);
        Py_XDECREF(verts);
    }
done:
    ori_simulation_destroy(sim);
    ori_design_destroy(design);
    ori_materials_destroy(mats);
    Py_XDECREF(ta);
    ori_py_state_free(&s);
    return result;
}

// simulate_compliant(pattern, fix, current, auto_polarity, **design): the device on compliant
// panels, as `orikin simulate --model compliant`: the equilibria as the current ramps from 0 to
// current and off again. Angles in radians.
static PyObject *py_simulate_compliant(PyObject *mod, PyObject *args, PyObject *kw)
{
    (void)mod;
    static char *kwlist[] = {"pattern", "fix", "current", "auto_polarity", DESIGN_KW, NULL};
    PyObject *pobj;
    int fix, auto_polarity = 1;
    double current = 0.0;
    design_opts o = {NULL, NULL, NULL, NULL, NULL, NULL};
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O!i|dpOOOOOz", kwlist, &ori_py_PatternType, &pobj, &fix, &current,
                                     &auto_polarity, DESIGN_ARGS(o)))
        return NULL;
    ori_py_pattern *pat = (ori_py_pattern *)pobj;
    const char *src = ori_py_pattern_source(pat);
    if (!ori_py_check_face(pat, "--fix", fix)) return NULL;
    ori_materials *mats = NULL;
    ori_design *design = make_design(pat, &o, &mats);
    if (!design) {
        ori_materials_destroy(mats); // make_design leaves the table to its caller (found by fuzz_python)
        return NULL;
    }
    int E = ori_pattern_edge_count(pat->p);
    double *zeros = calloc((size_t)E + 1, sizeof(double));
    ori_actuation act = ori_design_actuation(design);
    ori_compliant_def d = ori_compliant_physical_def();
    d.design = design;
    d.fixed_face = fix;
    d.field_t = act.schedule_count > 0 ? act.schedule[0].field_t : act.field_t;
    d.current_a = current;
    d.auto_polarity = auto_polarity;
    d.gravity = -act.gravity_m_s2.z;
    d.target_angles_rad = zeros; // the hinges are made flat: the wires fold them
    d.keep_frames = true;
    ori_compliant *c = NULL;
    ori_error err;
    PyObject *result = NULL;
    ori_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ori_compliant_create(pat->p, &d, &c, &err);
    if (st == ORI_OK) st = ori_compliant_solve_static(c, &err);
    Py_END_ALLOW_THREADS
    if (st != ORI_OK) {
        ori_py_raise(src, &err);
        goto done;
    }
    double *loaded = malloc(sizeof(double) * ((size_t)E + 1)), *plastic = malloc(sizeof(double) * ((size_t)E + 1));
    double *currents = malloc(sizeof(double) * ((size_t)E + 1)), *latched = malloc(sizeof(double) * ((size_t)E + 1));
    for (int e = 0; e < E; ++e) {
        loaded[e] = ori_compliant_fold_angle(c, e);
        plastic[e] = ori_compliant_plastic_rotation(c, e);
        currents[e] = ori_compliant_wire_current(c, e);
    }
    double strain = ori_compliant_max_strain(c);
    int load_frames = ori_compliant_frame_count(c);
    Py_BEGIN_ALLOW_THREADS
    st = ori_compliant_set_fraction(c, 0.0, &err);
    if (st == ORI_OK) st = ori_compliant_solve_static(c, &err);
    Py_END_ALLOW_THREADS
    if (st != ORI_OK) {
        ori_py_raise(src, &err);
    } else {
        for (int e = 0; e < E; ++e) latched[e] = ori_compliant_fold_angle(c, e);
        int F = ori_compliant_frame_count(c);
        double *fr = malloc(sizeof(double) * (size_t)F), *ang = malloc(sizeof(double) * (size_t)F * (size_t)(E + 1));
        for (int k = 0; k < F; ++k) {
            fr[k] = ori_compliant_frame_fraction(c, k);
            memcpy(ang + (size_t)k * (size_t)E, ori_compliant_frame_angles(c, k), sizeof(double) * (size_t)E);
        }
        npy_intp dims[2] = {F, E};
        PyObject *angles = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
        if (angles) memcpy(PyArray_DATA((PyArrayObject *)angles), ang, sizeof(double) * (size_t)F * (size_t)E);
        if (angles)
            result = ori_py_dict("loaded_rad", ori_py_doubles(loaded, E), "plastic_rotation_rad", ori_py_doubles(plastic, E),
                                 "currents", ori_py_doubles(currents, E), "max_strain", PyFloat_FromDouble(strain),
                                 "latched_rad", ori_py_doubles(latched, E), "current_fractions", ori_py_doubles(fr, F),
                                 "current_on_frames", PyLong_FromLong(load_frames), "angles", angles, "wires",
                                 PyLong_FromLong(ori_compliant_wire_count(c)), "vertices",
                                 PyLong_FromLong(ori_compliant_vertex_count(c)), NULL);
        free(fr);
        free(ang);
    }
    free(loaded);
    free(plastic);
    free(currents);
    free(latched);
done:
    ori_compliant_destroy(c);
    free(zeros);
    ori_design_destroy(design);
    ori_materials_destroy(mats);
    return result;
}

#define KW (PyCFunction)(void (*)(void))
PyMethodDef ori_py_actuation_functions[] = {
    {"simulate_compliant", KW py_simulate_compliant, METH_VARARGS | METH_KEYWORDS,
     "The device on compliant panels: equilibria as the current ramps up and off."},
    {"actuate", KW py_actuate, METH_VARARGS | METH_KEYWORDS, "Size hinges and actuation along a fold or sequence."},
    {"simulate", KW py_simulate, METH_VARARGS | METH_KEYWORDS, "Folding dynamics of a pattern with a design."},
    {NULL, NULL, 0, NULL},
};
