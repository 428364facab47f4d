// libFuzzer target for the Python package's argument conversion (issue 27, item 6): the
// interpreter (Debian's libpython3, python3-embed) embedded, the extension's sources
// python/src/*.c compiled in with the fuzz sanitizers and registered as the built-in module
// orikin._orikin (PyImport_AppendInittab before Py_Initialize; fuzz/fuzz_python.py loads it
// under that dotted name, which the built-in importer does not find for a submodule by itself,
// and imports the pure-Python package from the source tree python/orikin on top of it).
//
// An input is up to three calls, decoded by fuzz/fuzz_python.py: a receiver (the extension
// module, the package, a Pattern loaded once from examples/patterns/open-corner.fold, a Motion,
// a Record and a Layers of it, the package's Pattern, or an object an earlier call of the input
// returned), one of its attributes (dir(), sorted, at start-up) and arguments built from the
// bytes: None, bools, ints (small, 32-bit, huge, negative), floats (NaN, ±inf, -0.0, ±1e308,
// denormals), str (lone surrogates, embedded NUL), bytes, nested and ragged lists and tuples,
// dicts with fuzzed keys, numpy arrays (float64, int32, object, complex, ...; 0-d, empty, the
// pattern's sizes, wrong shapes, non-contiguous, read-only), the example files (copies in a
// temporary directory), text of FOLD, sequence and composite files, progress callables (that
// continue, stop, raise, or are not callable). Keyword names are the real ones: the kwlist arrays
// of python/src/*.c, the stub _orikin.pyi and the package's signatures.
//
// Invariants: no crash, no sanitizer report; every call of the extension returns or raises
// TypeError, ValueError (InputError and UnicodeError among them), OverflowError, KeyError,
// IndexError, OSError or an orikin.Error; a SystemError anywhere in an exception's chain
// ("returned NULL without setting an exception", "returned a result with an exception set"),
// from the package too, is a finding; the library's counted allocations
// (_orikin._alloc_live_count) are back to their count before the input once its results are
// dropped (a reference the extension forgets to release keeps a library object alive). Nothing
// is written outside a temporary directory (removed at exit; left after a finding): every `path`
// parameter (all the writers' outputs, the extension's and the package's) gets one of its files
// or a name in it, other strings have no '/' (the FOLD and sequence texts are not
// directories), the example copies in it are restored after a call that may write.
//
// Bounded work (fuzz_python.py: INT_CAPS, FLOAT_CAPS, MIN_STEP, FORCED, SKIP): sizes and counts
// (rows, cols, sides, steps, frames, tries, budget, limit, threads, max_iterations, pixels, fps)
// are clamped small, positive steps are at least 0.05 rad (3° in the package) and dt at least
// 1 ms, fold spans at most 7 rad, durations at most 0.5; the package's compliant fold is off and
// simulate, animate and compliant_fold are not called (fuzz_simulate and fuzz_compliant fuzz
// those solvers).
//
// Memory: CPython's objects are allocated with malloc (PYMEM_ALLOCATOR_MALLOC) so that
// AddressSanitizer sees them. The interpreter lives as long as the process: Py_FinalizeEx per
// input is no option (numpy cannot be initialised twice in one process, and the start-up takes
// seconds under the sanitizers). CPython's start-up and imports leave blocks LeakSanitizer calls
// unreachable (code objects of numpy's modules, tuples of the import system); they are excluded
// by allocation time, not by stack: __lsan_disable() around Py_Initialize, the imports, the
// receivers and a warm-up of 200 generated inputs (the lazy imports and one-time caches), so
// that whatever an input allocates and loses is still reported. A suppressions file could not be
// narrow: Debian's libpython has no frame pointers, the fast unwinder stops after its first
// frame, and a pattern naming libpython would hide the extension's leaks too (every object is
// allocated in libpython). fuzz/run.sh runs this target with -detect_leaks=0 (libFuzzer's check
// after each new input scans the interpreter's whole heap: 10 inputs/s instead of 130), so the
// leak check is LeakSanitizer's at exit, for the whole run; leaked references to objects that
// hold library memory are caught per input by the counted allocator (above).
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#include <sanitizer/lsan_interface.h>
#include <stdio.h>
#include <stdlib.h>

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
PyMODINIT_FUNC PyInit__orikin(void); // python/src/module.c

static PyObject *run_fn, *cleanup_fn;

// At exit (libFuzzer's exit(), not the interpreter's): the temporary directory removed.
static void cleanup(void)
{
    if (!cleanup_fn) return;
    PyGILState_STATE g = PyGILState_Ensure();
    PyObject *r = PyObject_CallNoArgs(cleanup_fn);
    if (!r) PyErr_Clear();
    Py_XDECREF(r);
    PyGILState_Release(g);
}

static void fail(const char *what)
{
    fprintf(stderr, "fuzz_python: %s\n", what);
    if (PyErr_Occurred()) PyErr_Print();
    abort();
}

int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    // What the interpreter's start-up, the imports and the warm-up allocate is never a leak
    // report (the interpreter is not finalised); what an input allocates and loses is.
    __lsan_disable();
    PyPreConfig pre;
    PyPreConfig_InitPythonConfig(&pre);
    pre.allocator = PYMEM_ALLOCATOR_MALLOC;
    pre.utf8_mode = 1;
    if (PyStatus_Exception(Py_PreInitialize(&pre))) fail("Py_PreInitialize failed");
    if (PyImport_AppendInittab("orikin._orikin", PyInit__orikin) < 0) fail("PyImport_AppendInittab failed");
    PyConfig config;
    PyConfig_InitIsolatedConfig(&config); // no PYTHONPATH or user site: the same interpreter everywhere
    config.write_bytecode = 0;
    config.install_signal_handlers = 0; // libFuzzer's handlers stay
    PyStatus st = Py_InitializeFromConfig(&config);
    PyConfig_Clear(&config);
    if (PyStatus_Exception(st)) fail("Py_InitializeFromConfig failed");
    PyObject *path = PySys_GetObject("path"); // borrowed
    PyObject *dir = PyUnicode_FromString(ORI_SOURCE_DIR "/fuzz");
    if (!path || !dir || PyList_Insert(path, 0, dir) < 0) fail("sys.path");
    Py_DECREF(dir);
    PyObject *mod = PyImport_ImportModule("fuzz_python");
    if (!mod) fail("import fuzz_python (fuzz/fuzz_python.py)");
    PyObject *r = PyObject_CallMethod(mod, "setup", "s", ORI_SOURCE_DIR);
    if (!r) fail("fuzz_python.setup");
    int functions = 0, attributes = 0;
    if (!PyArg_ParseTuple(r, "ii", &functions, &attributes)) fail("fuzz_python.setup's counts");
    Py_DECREF(r);
    fprintf(stderr, "fuzz_python: %d functions of the extension, %d attributes of the receivers in all\n", functions,
            attributes);
    run_fn = PyObject_GetAttrString(mod, "run");
    cleanup_fn = PyObject_GetAttrString(mod, "cleanup");
    Py_DECREF(mod);
    if (!run_fn || !cleanup_fn) fail("fuzz_python.run, fuzz_python.cleanup");
    atexit(cleanup);
    __lsan_enable();
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    PyObject *b = PyBytes_FromStringAndSize((const char *)data, (Py_ssize_t)size);
    if (!b) fail("bytes");
    PyObject *r = PyObject_CallOneArg(run_fn, b);
    Py_DECREF(b);
    if (!r) fail("the decoder raised (a harness bug, or an exception that escaped the call)");
    if (r != Py_None) {
        fprintf(stderr, "fuzz_python: finding: %s\n", PyUnicode_Check(r) ? PyUnicode_AsUTF8(r) : "?");
        abort();
    }
    Py_DECREF(r);
    return 0;
}
