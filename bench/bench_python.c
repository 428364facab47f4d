// Python binding scenario: what the `orikin` package costs over the C API, measured side by side
// in one process. The benchmark embeds the interpreter (Debian's libpython, the one the package
// is built for), imports the package from the build tree and bench/bench_python.py, and times
// (1) the 100 × 100 Miura fold of bench_miura.c (5° → 175° in 100 output steps from the 5°
// state, every frame kept): ori_motion_solve called from C, then Pattern.fold(...) called from
// Python with its result read through the view motion.angles, rounds alternating, medians of wall
// and CPU time (goal: the binding within 5 % of the C call); (2) design-search steps per second
// (DesignEnv.step on a 4 × 4 sheet, random creases through its grid points; goal ≥ 1000 / s),
// with the share spent inside the library's step. Skipped when the package is not built.
#ifdef ORI_BENCH_PYTHON
#  define PY_SSIZE_T_CLEAN
#  include <Python.h>
#endif

#ifndef _POSIX_C_SOURCE // (Python.h defines it)
#  define _POSIX_C_SOURCE 200809L
#endif
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include <cblas.h>

#include "bench.h"

#ifdef ORI_BENCH_PYTHON

#define ROUNDS 5
#define MIURA_N 100
#define DESIGN_SECONDS 2.0

static int py_fail(const char *what)
{
    printf("   python: %s failed:\n", what);
    fflush(stdout);
    PyErr_Print();
    return 1;
}

// The C side: the same pattern (the generator's, as the package makes it), its mechanism, the
// 5° state, the def of the measured fold.
typedef struct c_fold {
    ori_pattern *p;
    ori_mechanism *m;
    ori_motion *start;
    ori_motion_def d;
} c_fold;

static int c_setup(c_fold *c, int v0, int v1)
{
    ori_generate_def g = ori_default_generate_def(ORI_TESS_MIURA);
    g.rows = g.cols = MIURA_N;
    g.width = 1.0;
    g.height = sqrt(1.25);
    g.angle_rad = atan2(1.0, 0.5);
    ori_error err;
    if (ori_generate(&g, &c->p, NULL, &err) != ORI_OK) return 1;
    ori_mechanism_def md = ori_default_mechanism_def();
    md.pattern = c->p;
    if (ori_mechanism_create(&md, &c->m, &err) != ORI_OK) return 1;
    int drive = ori_pattern_find_edge(c->p, v0, v1);
    double sg = ori_pattern_edge(c->p, drive).assignment == ORI_ASSIGN_VALLEY ? 1.0 : -1.0;
    c->d = ori_default_motion_def();
    c->d.driven_edge = drive;
    c->d.to_rad = sg * ori_deg_to_rad(5.0);
    c->d.step_rad = ori_deg_to_rad(5.0);
    if (ori_motion_solve(c->m, &c->d, &c->start, &err) != ORI_OK) return 1;
    c->d.start_angles_rad = ori_motion_frame_angles(c->start, ori_motion_frame_count(c->start) - 1);
    c->d.to_rad = sg * ori_deg_to_rad(175.0);
    c->d.step_rad = ori_deg_to_rad(1.7);
    return 0;
}

static int run(void)
{
    openblas_set_num_threads(1); // one core, as bench_miura and the CLI
    Py_InitializeEx(0);
    int bad = 0;
    PyObject *sys_path = PySys_GetObject("path"); // borrowed
    PyObject *dirs[2] = {PyUnicode_FromString(ORI_BENCH_PYTHONPATH), PyUnicode_FromString(ORI_BENCH_DIR)};
    for (int i = 0; i < 2; ++i) {
        PyList_Insert(sys_path, 0, dirs[i]);
        Py_DECREF(dirs[i]);
    }
    PyObject *mod = PyImport_ImportModule("bench_python");
    if (!mod) return py_fail("import orikin (and bench/bench_python.py)");
    // (1) the Miura fold.
    PyObject *fold = PyObject_CallMethod(mod, "MiuraFold", "i", MIURA_N);
    if (!fold) return py_fail("MiuraFold");
    PyObject *ev = PyObject_CallMethod(fold, "edge_vertices", NULL);
    c_fold c = {0};
    if (!ev || c_setup(&c, (int)PyLong_AsLong(PyList_GetItem(ev, 0)), (int)PyLong_AsLong(PyList_GetItem(ev, 1)))) {
        printf("   C set-up failed\n");
        return 1;
    }
    Py_DECREF(ev);
    PyObject *warm = PyObject_CallMethod(fold, "fold", NULL); // the pattern's mechanism made once, as in C
    if (!warm) return py_fail("the first fold");
    Py_DECREF(warm);
    double cw[ROUNDS], cc[ROUNDS], pw[ROUNDS], pc[ROUNDS], c_last = 0.0, p_last = 0.0, p_res = 0.0;
    int c_frames = 0, p_frames = 0;
    for (int r = 0; r < ROUNDS; ++r) {
        for (int side = 0; side < 2; ++side) {
            bool py = (side + r) % 2 == 1; // alternate which goes first
            double t0 = bench_now(), u0 = bench_cpu_now();
            if (py) {
                PyObject *res = PyObject_CallMethod(fold, "fold", NULL);
                if (!res) return py_fail("Pattern.fold");
                p_frames = (int)PyLong_AsLong(PyTuple_GetItem(res, 0));
                p_last = PyFloat_AsDouble(PyTuple_GetItem(res, 1));
                p_res = PyFloat_AsDouble(PyTuple_GetItem(res, 2));
                Py_DECREF(res); // (the motion was freed when fold() returned: inside the time, as below)
                pw[r] = bench_now() - t0, pc[r] = bench_cpu_now() - u0;
            } else {
                ori_motion *mo = NULL;
                ori_error err;
                if (ori_motion_solve(c.m, &c.d, &mo, &err) != ORI_OK) return 1;
                c_frames = ori_motion_frame_count(mo);
                c_last = ori_motion_frame_angles(mo, c_frames - 1)[c.d.driven_edge];
                ori_motion_destroy(mo);
                cw[r] = bench_now() - t0, cc[r] = bench_cpu_now() - u0;
            }
        }
    }
    double mcw = bench_median(cw, ROUNDS), mcc = bench_median(cc, ROUNDS), mpw = bench_median(pw, ROUNDS), mpc = bench_median(pc, ROUNDS);
    printf("   %dx%d Miura 5->175 deg (%d frames kept): C API %.3f s wall (%.3f s CPU), Python %.3f s wall (%.3f s CPU), "
           "median of %d alternating rounds\n",
           MIURA_N, MIURA_N, c_frames, mcw, mcc, mpw, mpc, ROUNDS);
    printf("   binding overhead: %+.1f %% wall, %+.1f %% CPU (goal <= 5 %%); the same motion: %d vs %d frames, last drive "
           "%.17g vs %.17g rad, max residual %.1e\n",
           100.0 * (mpw - mcw) / mcw, 100.0 * (mpc - mcc) / mcc, c_frames, p_frames, c_last, p_last, p_res);
    bad |= c_frames != p_frames || fabs(c_last - p_last) > 1e-12;
    Py_DECREF(fold);
    ori_motion_destroy(c.start);
    ori_mechanism_destroy(c.m);
    ori_pattern_destroy(c.p);
    // (2) design-search steps.
    PyObject *ds = PyObject_CallMethod(mod, "design_steps", "d", DESIGN_SECONDS);
    if (!ds) return py_fail("design_steps");
    long steps = PyLong_AsLong(PyTuple_GetItem(ds, 0));
    double secs = PyFloat_AsDouble(PyTuple_GetItem(ds, 1)), cpu = PyFloat_AsDouble(PyTuple_GetItem(ds, 2)),
           lib = PyFloat_AsDouble(PyTuple_GetItem(ds, 3));
    printf("   design search (DesignEnv.step, 4x4 sheet, random creases, <= 6 per episode): %ld steps in %.2f s wall "
           "(%.2f s CPU) = %.0f steps/s wall, %.0f per CPU second (goal >= 1000), %.0f %% of the wall time in the "
           "library's step\n",
           steps, secs, cpu, steps / secs, steps / cpu, 100.0 * lib / secs);
    Py_DECREF(ds);
    Py_DECREF(mod);
    if (Py_FinalizeEx() < 0) bad = 1;
    return bad;
}

#else

static int run(void)
{
    printf("   skipped: the Python package is not built (python3-dev and python3-numpy: make deps)\n");
    return 0;
}

#endif

const bench_scenario bench_python = {
    "python",
    "the Python binding against the C API: a 100x100 Miura fold side by side, design-search steps per second",
    run,
};
