// The design-search step (SPEC item 22): add a crease to a pattern and judge the result — rigid
// foldability (a fold toward the targets from the flat sheet, every crease as assigned), the
// degrees of freedom (rank of the loop-closure Jacobian, generic probe) and self-collision
// along that fold — in one call without the GIL, the inner loop of a gym environment
// (orikin.DesignEnv).
#include "pyorikin.h"

#include <math.h>
#include <stdio.h>

// What one step found (filled without the GIL).
typedef struct step_out {
    bool applied;
    ori_error err;            // why the crease or a check failed
    ori_apply_result apply;
    int folds;                // M, V and U creases
    int dof, flat_dof;        // generic DOF (−1: undetermined), DOF at the flat state
    bool dof_ok;
    const char *verdict;
    double progress;          // how far the fold toward the targets got (0 … 1)
    int frames;
    int against;              // creases folding against their assignment
    int against_edge;         // the first of them
    bool collides;
    ori_collision_event ev;
    bool checked;
} step_out;

typedef struct step_in {
    ori_crease crease;
    int face;
    int fix;                  // ORI_NULL_INDEX: the face at the sheet's centre
    double fraction, step_rad, clearance;
    int max_steps;            // of the fold toward the targets (≤ 0: the library's bound)
    int probe_budget;         // of the DOF probe at the flat sheet when the fold does not move
    bool collisions, probe;
} step_in;

// The DOF at a state (radians per edge, NULL = flat): the rank count, and with a probe budget the
// generic count near a singular state; false with out->err set when the analysis fails.
static bool dof_at(const ori_mechanism *m, const double *angles, int probe_budget, ori_dof_result *r, ori_error *err)
{
    ori_dof_def dd = ori_default_dof_def();
    dd.angles_rad = angles;
    dd.probe_generic = probe_budget > 0;
    dd.probe_budget = probe_budget;
    return ori_mechanism_dof(m, &dd, r, err) == ORI_OK;
}

static void judge(ori_pattern *p, const step_in *in, step_out *out)
{
    for (int a = ORI_ASSIGN_MOUNTAIN; a <= ORI_ASSIGN_UNASSIGNED; ++a)
        if (ori_assignment_is_fold((ori_assignment)a)) out->folds += ori_pattern_count_assignment(p, (ori_assignment)a);
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = p;
    ori_mechanism *m = NULL;
    if (ori_mechanism_create(&md, &m, &out->err) != ORI_OK) return;
    ori_dof_result flat;
    if (!dof_at(m, NULL, 0, &flat, &out->err)) {
        ori_mechanism_destroy(m);
        return;
    }
    out->flat_dof = flat.dof;
    if (out->folds == 0) { // a sheet without creases folds trivially (nothing moves)
        out->dof_ok = true;
        out->dof = 0;
        out->verdict = "reached";
        out->progress = 1.0;
        ori_mechanism_destroy(m);
        return;
    }
    ori_target_fold_def td = ori_default_target_fold_def();
    td.fixed_face = in->fix == ORI_NULL_INDEX ? ori_pattern_center_face(p) : in->fix;
    td.fraction = in->fraction;
    td.step_rad = in->step_rad;
    td.max_steps = in->max_steps;
    ori_multifold *mf = NULL;
    if (ori_target_fold_solve(m, &td, &mf, &out->err) != ORI_OK) {
        ori_mechanism_destroy(m);
        return;
    }
    out->verdict = ori_multifold_verdict_name(ori_multifold_verdict_of(mf));
    out->frames = ori_multifold_frame_count(mf);
    out->progress = out->frames ? ori_multifold_frame_progress(mf, out->frames - 1) : 0.0;
    // The degrees of freedom: along the motion when the fold moves (a state half way, away from
    // the flat sheet's singularity: the rank count is the generic one there), else the generic
    // probe at the flat sheet (its budget bounded: a rigid vertex is proved in a few solves).
    ori_dof_result r;
    bool moved = out->frames >= 2 && out->progress > 0.0;
    if (moved && dof_at(m, ori_multifold_frame_angles(mf, out->frames / 2), 0, &r, &out->err)) {
        out->dof_ok = true;
        out->dof = r.dof;
    } else if (!moved && !in->probe) {
        out->dof_ok = true;
        out->dof = flat.dof;
    } else if (!moved && dof_at(m, NULL, in->probe_budget, &r, &out->err)) {
        out->dof_ok = true;
        // A regular state needs no probe: its DOF is the generic one.
        out->dof = r.generic_dof >= 0 ? r.generic_dof : r.undetermined ? -1 : r.dof;
    }
    out->against_edge = ORI_NULL_INDEX;
    int E = ori_pattern_edge_count(p);
    for (int e = 0; e < E; ++e) { // as the CLI's modes report them (fold_modes.c)
        ori_assignment as = ori_pattern_edge(p, e).assignment;
        int sg = as == ORI_ASSIGN_VALLEY ? 1 : as == ORI_ASSIGN_MOUNTAIN ? -1 : 0;
        bool bad = false;
        for (int f = 0; sg && f < out->frames && !bad; ++f) {
            double x = ori_multifold_frame_angles(mf, f)[e];
            bad = x * sg < 0.0 && fabs(x) > ORI_TOL_FOLD_SIGN_RAD;
        }
        if (bad && out->against++ == 0) out->against_edge = e;
    }
    if (in->collisions && out->frames > 1) {
        ori_collider_def cd = ori_default_collider_def();
        cd.pattern = p;
        cd.clearance = in->clearance;
        ori_collider *c = NULL;
        ori_error cerr;
        if (ori_collider_create(&cd, &c, &cerr) == ORI_OK) {
            ori_collision_motion_def check = ori_default_collision_motion_def();
            if (ori_collision_check_multifold(c, mf, NULL, 0, &check, &out->ev, &cerr) == ORI_OK) {
                out->checked = true;
                out->collides = out->ev.collides;
            }
        }
        ori_collider_destroy(c);
    }
    ori_multifold_destroy(mf);
    ori_mechanism_destroy(m);
}

// design_step(pattern, a, b, assignment, face, infinite, fix, fraction, step_rad, collisions,
// clearance, probe, max_steps, probe_budget): (the new pattern or None when the crease was not
// applied, what was found).
static PyObject *py_design_step(PyObject *mod, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"pattern", "a", "b", "assignment", "face", "infinite", "fix", "fraction", "step_rad",
                             "collisions", "clearance", "probe", "max_steps", "probe_budget", NULL};
    PyObject *pobj, *ao, *bo;
    const char *asg = "V";
    step_in in = {.face = ORI_NULL_INDEX, .fix = ORI_NULL_INDEX, .fraction = 1.0, .step_rad = ORI_PI / 18,
                  .clearance = 0.0, .max_steps = 0, .probe_budget = 32, .collisions = true, .probe = true};
    int infinite = 1, collisions = 1, probe = 1;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O!OO|sipiddpdpii", kwlist, &ori_py_PatternType, &pobj, &ao, &bo, &asg,
                                     &in.face, &infinite, &in.fix, &in.fraction, &in.step_rad, &collisions, &in.clearance,
                                     &probe, &in.max_steps, &in.probe_budget))
        return NULL;
    ori_py_pattern *pat = (ori_py_pattern *)pobj;
    in.collisions = collisions;
    in.probe = probe;
    in.crease.infinite = infinite;
    in.crease.fold_angle_rad = 0.0;
    if (!ori_py_read_v2(ao, &in.crease.a, "a") || !ori_py_read_v2(bo, &in.crease.b, "b")) return NULL;
    if (strlen(asg) != 1 || !ori_assignment_from_char(asg[0], &in.crease.assignment) ||
        !(ori_assignment_is_fold(in.crease.assignment) || in.crease.assignment == ORI_ASSIGN_FLAT))
        return PyErr_Format(PyExc_ValueError, "assignment must be 'M', 'V', 'F' or 'U', got '%s'", asg);
    if (in.face != ORI_NULL_INDEX && !ori_py_check_face(pat, "--face", in.face)) return NULL;
    if (!(in.fraction >= 0.0 && in.fraction <= 1.0))
        return PyErr_Format(PyExc_ValueError, "percent must be from 0 to 100, got %g", 100.0 * in.fraction);
    if (!(in.step_rad > 0.0)) return PyErr_Format(PyExc_ValueError, "step must be a positive angle");
    step_out out;
    memset(&out, 0, sizeof out);
    ori_error_clear(&out.err);
    out.dof = out.flat_dof = -1;
    ori_pattern *p = ori_pattern_clone(pat->p);
    Py_BEGIN_ALLOW_THREADS
    out.applied = ori_pattern_apply_crease(p, &in.crease, in.face, &out.apply, &out.err) == ORI_OK;
    if (out.applied) {
        if (in.fix != ORI_NULL_INDEX && in.fix >= ori_pattern_face_count(p)) in.fix = ORI_NULL_INDEX;
        judge(p, &in, &out);
    }
    Py_END_ALLOW_THREADS
    char msg[512] = "";
    if (out.err.status != ORI_OK) ori_error_format(&out.err, msg, sizeof msg);
    PyObject *np = Py_NewRef(Py_None);
    if (out.applied) {
        Py_DECREF(np);
        np = ori_py_pattern_new(p, NULL, pat->doc ? (PyObject *)pat : pat->templ, ori_py_pattern_source(pat));
        if (!np) return NULL;
    } else {
        ori_pattern_destroy(p);
    }
    // Rigidly foldable: the mechanism has a motion (generic DOF ≥ 1; a step of 1e-7 before a
    // singular stop is no motion) and the fold toward the targets takes it, every crease as assigned.
    bool moves = out.dof_ok && out.dof >= 0 ? out.dof > 0 : true;
    bool rigid = out.applied && out.verdict && moves && out.frames >= 2 && out.progress > 0.0 && out.against == 0;
    if (out.applied && out.folds == 0) rigid = true;
    PyObject *edges = PyList_New(out.applied ? out.apply.edges_added : 0);
    for (int i = 0; edges && out.applied && i < out.apply.edges_added; ++i)
        PyList_SET_ITEM(edges, i, PyLong_FromLong(out.apply.first_edge + i));
    PyObject *collision = Py_NewRef(Py_None);
    if (out.collides) {
        Py_DECREF(collision);
        collision = ori_py_dict("frame", PyLong_FromLong(out.ev.frame), "progress", PyFloat_FromDouble(out.ev.drive_rad),
                                "faces", Py_BuildValue("(ii)", out.ev.contact.face_a, out.ev.contact.face_b), "point",
                                ori_py_v3(out.ev.contact.point), NULL);
    }
    PyObject *info = ori_py_dict(
        "applied", PyBool_FromLong(out.applied), "error", msg[0] ? PyUnicode_FromString(msg) : Py_NewRef(Py_None), "edges",
        edges, "creases", PyLong_FromLong(out.folds), "rigid_foldable", PyBool_FromLong(rigid), "dof",
        out.dof_ok && out.dof >= 0 ? PyLong_FromLong(out.dof) : Py_NewRef(Py_None), "flat_dof",
        out.dof_ok ? PyLong_FromLong(out.flat_dof) : Py_NewRef(Py_None), "verdict",
        out.verdict ? PyUnicode_FromString(out.verdict) : Py_NewRef(Py_None), "progress", PyFloat_FromDouble(out.progress),
        "against_assignment", PyLong_FromLong(out.against), "against_edge",
        out.against ? PyLong_FromLong(out.against_edge) : Py_NewRef(Py_None), "collides", PyBool_FromLong(out.collides),
        "collision_checked", PyBool_FromLong(out.checked), "collision", collision, NULL);
    if (!info) {
        Py_DECREF(np);
        return NULL;
    }
    return Py_BuildValue("(NN)", np, info);
}

#define KW (PyCFunction)(void (*)(void))
PyMethodDef ori_py_design_functions[] = {
    {"design_step", KW py_design_step, METH_VARARGS | METH_KEYWORDS,
     "Add a crease and judge the pattern: (new pattern or None, rigid foldability, DOF, collision)."},
    {NULL, NULL, 0, NULL},
};
