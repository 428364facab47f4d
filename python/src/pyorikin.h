// orikin._orikin: the CPython extension under the Python package `orikin` (python/orikin). It
// holds the library's objects (pattern, mechanism, motion, record, layers) as Python objects,
// hands out numpy arrays that view the library's memory (read-only, the owner as their base),
// turns ori_error into the package's exceptions with the CLI's one-line message, releases the
// GIL around long solves and runs progress callbacks. The Python layer (orikin/_api.py) makes
// the user-facing classes from these primitives; docs/python.md describes both.
//
// Files: module.c (module, exceptions, views, progress), pattern.c (Pattern), motion.c
// (Mechanism, Motion and the folds), analysis.c (check, regularize, layers, dof), state.c
// (render, export, collide, animate), sequence.c (Record), actuation.c (actuate, simulate),
// unfold.c (unfold, develop, linkage), design.c (the design-search step), compliant.c (the
// compliant bar-and-hinge fold).
#ifndef ORI_PY_ORIKIN_H
#define ORI_PY_ORIKIN_H

#define PY_SSIZE_T_CLEAN
#include <Python.h>

#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#define PY_ARRAY_UNIQUE_SYMBOL ori_py_numpy_api
#ifndef ORI_PY_MODULE_C
#  define NO_IMPORT_ARRAY
#endif
#include <numpy/arrayobject.h>

#include <orikin/orikin.h>

// --- errors ---------------------------------------------------------------------------------

// The package's exceptions (module.c creates them): Error, InputError(Error, ValueError),
// SolveError(Error, RuntimeError), Cancelled(Error).
extern PyObject *ori_py_Error, *ori_py_InputError, *ori_py_SolveError, *ori_py_Cancelled;

// Raise the exception of a library failure with the CLI's line "SOURCE: <ori_error_format>"
// (source NULL: the formatted error alone) and attributes status, element, field, line, column.
// Returns NULL.
PyObject *ori_py_raise(const char *source, const ori_error *error);
// Raise InputError with the CLI's line for a value the pattern does not have:
// "SOURCE: OPTION: <message>" (cli_value_fail's text), attribute option. Returns NULL.
PyObject *ori_py_raise_value(const char *source, const char *option, const char *fmt, ...);

// --- progress and cancellation -----------------------------------------------------------------

// The state of a solve run without the GIL: the Python callback (may be NULL) and the exception
// it (or a signal such as KeyboardInterrupt) raised, re-raised after the solve.
typedef struct ori_py_progress {
    PyObject *callback;
    PyObject *exc_type, *exc_value, *exc_tb;
    bool called;
} ori_py_progress;

// Initialise from a callable or None (borrowed); false with TypeError set for anything else.
bool ori_py_progress_init(ori_py_progress *pp, PyObject *callback);
// The ori_progress_fn: takes the GIL, checks signals, calls the callback with the fraction;
// False (or an exception) cancels.
bool ori_py_progress_fn(double fraction, void *user);
// After the solve: when the callback or a signal stopped it, restore that exception and return
// true (the caller returns NULL); else false.
bool ori_py_progress_raise(ori_py_progress *pp);
// Raise for a failed solve: the stashed exception when the callback stopped it, else the
// library's (ori_py_raise). Returns NULL.
PyObject *ori_py_solve_failed(ori_py_progress *pp, const char *source, const ori_error *error);

// --- numpy -----------------------------------------------------------------------------------

// A read-only array viewing data (nd dims; strides in bytes, NULL = C-contiguous) kept alive by
// owner (a new reference is taken). Writing to it is refused; the flag cannot be set back.
PyObject *ori_py_view(PyObject *owner, int type, int nd, const npy_intp *dims, const npy_intp *strides,
                      const void *data);
// A new array (an owned copy) of doubles: 1-D of n, or n × 3 for points.
PyObject *ori_py_doubles(const double *v, npy_intp n);
PyObject *ori_py_points(const ori_v3 *v, npy_intp n);
PyObject *ori_py_ints(const int *v, npy_intp n);
// A C-contiguous float64 array of obj with n entries (or n × cols when cols > 0); NULL with
// ValueError naming what (e.g. "angles") when the shape does not match. New reference.
PyArrayObject *ori_py_double_array(PyObject *obj, npy_intp n, int cols, const char *what);
// A list of ints (any integer sequence) into a malloc'd array (*count set); NULL with an exception.
// None gives an empty list (a non-NULL pointer, *count = 0).
int *ori_py_int_list(PyObject *obj, int *count, const char *what);

// --- objects -----------------------------------------------------------------------------------

// A crease pattern: the library pattern (built), the FOLD document it came from (or NULL), a
// template pattern whose document fields it keeps when written (or NULL), where it came from
// (for messages), its edge classes (generated patterns) and its mechanism (made on first use).
typedef struct ori_py_pattern {
    PyObject_HEAD
    ori_pattern *p;
    ori_fold *doc;
    PyObject *templ;  // ori_py_pattern or NULL
    PyObject *source; // str
    PyObject *mech;   // ori_py_mechanism or NULL
    int frame;        // the frame of doc the pattern is
} ori_py_pattern;

typedef struct ori_py_mechanism {
    PyObject_HEAD
    ori_mechanism *m;
} ori_py_mechanism;

extern PyTypeObject ori_py_PatternType, ori_py_MechanismType, ori_py_MotionType, ori_py_RecordType,
    ori_py_LayersType;

// A new Pattern object taking p (built) and doc (either may own; doc may be NULL); source is
// borrowed and copied. NULL (p and doc destroyed) on failure.
PyObject *ori_py_pattern_new(ori_pattern *p, ori_fold *doc, PyObject *templ, const char *source);
// The pattern's FOLD document: its own (borrowed, *owned false) or one made from its FOLD text
// (*owned true: destroy it). NULL with *err set on failure.
ori_fold *ori_py_pattern_doc(ori_py_pattern *pat, bool *owned, ori_error *err);
// The source text of a pattern (for messages).
const char *ori_py_pattern_source(const ori_py_pattern *pat);
// The pattern's mechanism (a borrowed reference, made on first use), or NULL with the library's
// exception (a folded form, faces not connected).
ori_py_mechanism *ori_py_pattern_mechanism(ori_py_pattern *pat);
// Check a face / edge index against the pattern: false after raising the CLI's message
// ("SOURCE: --fix: no face 9 (the pattern has faces 0 to 4)").
bool ori_py_check_face(const ori_py_pattern *pat, const char *option, int face);
bool ori_py_check_edge(const ori_py_pattern *pat, const char *option, int edge);

// A state passed in from Python: edge angles (radians, edge_count) and world positions
// (vertex_count × 3), either NULL; arrays kept for the call.
typedef struct ori_py_state {
    PyArrayObject *angles_arr, *positions_arr;
    const double *angles;
    const ori_v3 *positions;
} ori_py_state;
// Read optional angles and positions (None or arrays of the pattern's sizes); false with an exception.
bool ori_py_state_read(ori_py_state *s, const ori_py_pattern *pat, PyObject *angles, PyObject *positions);
void ori_py_state_free(ori_py_state *s);

// The library objects behind a Motion (NULL for a fold with several degrees of freedom; its
// driven crease in *driven_edge) and a Record (its sequence in *seq); borrowed. Both false/NULL
// when obj is not of that type (no exception set).
const ori_motion *ori_py_motion_of(PyObject *obj, int *driven_edge);
const ori_record *ori_py_record_of(PyObject *obj, const ori_sequence **seq);
// The pattern a Motion or Record folded (borrowed).
ori_py_pattern *ori_py_motion_pattern(PyObject *obj);
ori_py_pattern *ori_py_record_pattern(PyObject *obj);

// A collision checker of the pattern's faces (NULL after raising: a negative clearance is the
// CLI's --clearance message), a contact and the first contact along a motion as dicts
// (progress: the event's parameter is the progress of a fold with several degrees of freedom).
ori_collider *ori_py_collider(const ori_py_pattern *pat, double clearance);
PyObject *ori_py_contact_dict(const ori_contact *contact);
PyObject *ori_py_event_dict(const ori_collision_event *event, bool progress);

// Module-level functions by file (each returns a PyMethodDef table ending with a NULL entry).
extern PyMethodDef ori_py_pattern_functions[], ori_py_motion_functions[], ori_py_analysis_functions[],
    ori_py_state_functions[], ori_py_sequence_functions[], ori_py_actuation_functions[], ori_py_unfold_functions[],
    ori_py_design_functions[], ori_py_compliant_functions[];

// Pattern methods defined in other files (pattern.c lists them in the type).
PyObject *ori_py_pattern_fold(PyObject *self, PyObject *args, PyObject *kw);
PyObject *ori_py_pattern_target_fold(PyObject *self, PyObject *args, PyObject *kw);
PyObject *ori_py_pattern_drives_fold(PyObject *self, PyObject *args, PyObject *kw);
PyObject *ori_py_pattern_lock_set(PyObject *self, PyObject *args, PyObject *kw);
PyObject *ori_py_pattern_symmetry(PyObject *self, PyObject *args);
PyObject *ori_py_pattern_pose(PyObject *self, PyObject *args, PyObject *kw);
PyObject *ori_py_pattern_check(PyObject *self, PyObject *args, PyObject *kw);
PyObject *ori_py_pattern_regularize(PyObject *self, PyObject *args, PyObject *kw);
PyObject *ori_py_pattern_layers(PyObject *self, PyObject *args, PyObject *kw);
PyObject *ori_py_pattern_dof(PyObject *self, PyObject *args, PyObject *kw);
PyObject *ori_py_pattern_sequence(PyObject *self, PyObject *args, PyObject *kw);

// Small helpers.
PyObject *ori_py_v3(ori_v3 v);                 // (x, y, z) tuple
bool ori_py_read_v2(PyObject *obj, ori_v2 *out, const char *what); // a 2-sequence of numbers
// Build a dict from "key", value pairs ending with NULL; values are new references (stolen).
PyObject *ori_py_dict(const char *key, ...);

#endif
