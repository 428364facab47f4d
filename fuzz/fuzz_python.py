"""The decoder of the libFuzzer target fuzz_python (fuzz/fuzz_python.c, which embeds the
interpreter and compiles python/src/*.c in as the built-in module orikin._orikin).

setup(source_dir) runs once: it registers the built-in extension as orikin._orikin, imports the
package from the source tree (python/orikin, whose `from . import _orikin` then finds the
in-process module), copies the example inputs into a temporary directory (the working
directory's paths are the only ones given to a `path` parameter), builds the receivers (the extension module, the pure-Python package,
a Pattern loaded from examples/patterns/open-corner.fold, a Motion, a Record and a Layers of it,
the package's own Pattern) and lists each receiver's attributes (dir(), sorted) and each
callable's parameter names (the kwlist arrays of python/src/*.c, the package's signatures).

run(data) decodes one input into up to three calls (receiver, attribute, positional and keyword
arguments; a later call may use an earlier call's result as receiver or argument) and returns
None, or a one-line description of a finding, which the C side prints before abort().
"""

import gc
import glob
import importlib.machinery
import importlib.util
import inspect
import math
import os
import re
import shutil
import struct
import sys
import tempfile
import warnings

import numpy as np

# Work bounds: numbers given to these parameters (by keyword, or by position when the
# callable's parameter list is known) are clamped into [lo, hi]; NaN, infinities and the
# negative values that the validation must refuse pass through unchanged except where noted.
INT_CAPS = {
    "rows": (-2, 6), "cols": (-2, 6), "sides": (-2, 12), "tries": (-2, 4), "max_iterations": (-2, 40),
    "budget": (-2, 64), "probe_budget": (-2, 64), "max_steps": (-2, 6), "limit": (-2, 1000), "threads": (-2, 2),
    "reorientations": (-2, 3), "steps_per_event": (-2, 16), "max_events": (-2, 16), "frames": (-2, 12),
    "steps": (-2, 40), "width": (-2, 64), "height": (-2, 64), "fps": (-2, 20), "k": (-4, 64), "frame": (-4, 64),
}
FLOAT_CAPS = {  # finite values clamped; inf and nan kept (the library must refuse them)
    "to_rad": (-7.0, 7.0), "from_rad": (-7.0, 7.0), "angle_rad": (-7.0, 7.0), "to": (-400.0, 400.0),
    "from_": (-400.0, 400.0), "duration": (-1.0, 0.5), "settle": (-1.0, 1.0), "hold": (-1.0, 1.0),
    "fps": (-1.0, 20.0), "width": (-64.0, 64.0), "height": (-64.0, 64.0), "steps": (-2.0, 40.0),
    "fraction": (-2.0, 2.0),
}
# Smallest positive value of a step-like parameter (a positive step below it is raised to it):
# a fold's frame count is its span over its step, a simulation's steps its duration over dt.
MIN_STEP = {"step_rad": 0.05, "step": 3.0, "dt": 1e-3, "tolerance": 1e-9, "tolerance_rad": 1e-9}
# Parameters whose value is forced: no compliant (bar-and-hinge) solve from the package's fold
# (it has its own target, fuzz_compliant).
FORCED = {"compliant": False, "dynamic": False}
# Attributes never called: the package's own long runs, which fuzz_simulate, fuzz_compliant and
# the CLI targets cover (names of the extension itself are all called, with the caps above).
SKIP = {"simulate", "animate", "compliant_fold"}
# Calls that may write files (paths are all inside the temporary directory; it is reset after).
# Methods that change their receiver (a base receiver is made again after them, so that every
# input starts from the same objects).
MUTATORS = {"collide", "select", "count"}
WRITERS = {"save", "render", "export_mesh", "export", "animate", "with_states", "to_fold"}
MAX_ELEMENTS = 256
MAX_CALLS = 3
WARM_UP = 200

EXPECTED = (TypeError, ValueError, OverflowError, KeyError, IndexError, OSError)

S = None  # the state made by setup()


class Reader:
    def __init__(self, data):
        self.d = data
        self.i = 0

    def u8(self):
        if self.i >= len(self.d):
            return 0
        self.i += 1
        return self.d[self.i - 1]

    def take(self, n):
        b = self.d[self.i:self.i + n]
        self.i += len(b)
        return b

    def pick(self, seq):
        return seq[self.u8() % len(seq)] if seq else None


class State:
    pass


def _kwlists(src):
    """{(owner, name): [parameter names]} from the kwlist arrays and method tables of python/src."""
    texts = {f: open(f, encoding="utf-8").read() for f in sorted(glob.glob(os.path.join(src, "python/src/*.c")))}
    macros = {}
    for t in texts.values():
        for m in re.finditer(r'#define\s+(\w+)\s+((?:"\w+"\s*,?\s*(?:\\\n\s*)?)+)', t):
            macros[m.group(1)] = re.findall(r'"(\w+)"', m.group(2))
    funcs = {}
    for t in texts.values():
        for m in re.finditer(r'(\w+)\(PyObject \*\w+, PyObject \*args, PyObject \*kw\w*\)\s*\{[^{}]*?'
                             r'static char \*kwlist\[\] = \{(.*?)\};', t, re.S):
            names = []
            for tok in re.findall(r'"\w+"|\b[A-Z_]+\b', m.group(2)):
                names += [tok[1:-1]] if tok.startswith('"') else macros.get(tok, [])
            funcs[m.group(1)] = names
    table = {}
    for t in texts.values():
        for m in re.finditer(r'\{"(\w+)",\s*(?:KW\s*|\(PyCFunction\)\(void \(\*\)\(void\)\)\s*)?(\w+),', t):
            cfunc = m.group(2)
            owner = ("Motion" if cfunc.startswith("motion_") else "Record" if cfunc.startswith("record_") else
                     "Layers" if cfunc.startswith("layers_") else
                     "Pattern" if cfunc.startswith(("pattern_", "ori_py_pattern_")) else "module")
            if cfunc in funcs:
                table[(owner, m.group(1))] = funcs[cfunc]
    words = set()
    for t in texts.values():
        words.update(w for w in re.findall(r'"([A-Za-z_][\w-]{0,23})"', t))
    return table, sorted(words)


def _stub_names(src):
    """{(owner, name): [parameter names]} from the stub python/orikin/_orikin.pyi (positional-only
    methods such as find_face(spec, option) have no kwlist)."""
    import ast
    tree = ast.parse(open(os.path.join(src, "python/orikin/_orikin.pyi"), encoding="utf-8").read())
    out = {}
    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            out[("module", node.name)] = [a.arg for a in node.args.args + node.args.kwonlyargs]
        elif isinstance(node, ast.ClassDef):
            for f in node.body:
                if isinstance(f, ast.FunctionDef):
                    out[(node.name, f.name)] = [a.arg for a in f.args.args[1:] + f.args.kwonlyargs]
    return out


def _build_bases():
    c = S.ext
    pat = c.load(S.fixed[0])  # open-corner.fold
    pat.grubler()  # its mechanism, made on first use, made now
    motion = pat.fold(4, 12, math.radians(90.0), math.radians(10.0), lock=[11])
    with open(S.seq_text_path, encoding="utf-8") as f:
        record = pat.sequence(f.read())
    layers = c.load(S.flat_path).layers()
    wpat = S.pkg.Pattern.load(S.fixed[0])
    S.bases = [("module", c), ("package", S.pkg), ("Pattern", pat), ("Motion", motion), ("Record", record),
               ("Layers", layers), ("package.Pattern", wpat)]


def _attrs(obj):
    names = []
    for n in sorted(dir(obj)):
        if n.startswith("__") or n in SKIP:
            continue
        a = getattr(type(obj), n, None) if not isinstance(obj, type(sys)) else getattr(obj, n, None)
        if isinstance(obj, type(sys)) and (inspect.ismodule(a) or (isinstance(a, type) and issubclass(a, BaseException))):
            continue
        names.append(n)
    return names


def _reset_dir():
    for n in os.listdir(S.tmp):
        p = os.path.join(S.tmp, n)
        if n in S.fixed_names:
            continue
        if os.path.isdir(p) and not os.path.islink(p):
            shutil.rmtree(p, ignore_errors=True)
        else:
            os.unlink(p)
    for src, dst in S.copies:
        same = False
        if os.path.isfile(dst) and not os.path.islink(dst):
            with open(src, "rb") as f, open(dst, "rb") as g:
                same = f.read() == g.read()
        if not same:
            if os.path.isdir(dst) and not os.path.islink(dst):
                shutil.rmtree(dst, ignore_errors=True)
            elif os.path.lexists(dst):
                os.unlink(dst)
            shutil.copyfile(src, dst)


def setup(src):
    global S
    S = State()
    warnings.simplefilter("ignore")
    sys.dont_write_bytecode = True
    spec = importlib.machinery.ModuleSpec("orikin._orikin", importlib.machinery.BuiltinImporter, origin="built-in")
    S.ext = importlib.util.module_from_spec(spec)
    sys.modules["orikin._orikin"] = S.ext
    sys.path.insert(0, os.path.join(src, "python"))
    import orikin
    if orikin._api._c is not S.ext or not orikin.__file__.startswith(os.path.join(src, "python")):
        raise RuntimeError("fuzz_python: the package did not take the in-process extension")
    S.pkg = orikin
    S.trace = os.environ.get("FUZZ_PYTHON_TRACE") == "1"
    S.tmp = tempfile.mkdtemp(prefix="fuzz_python-")
    inputs = (sorted(glob.glob(os.path.join(src, "examples/patterns/*.fold"))) +
              sorted(glob.glob(os.path.join(src, "examples/*.seq.json"))) +
              sorted(glob.glob(os.path.join(src, "examples/composites/*.json")))[:2] +
              sorted(glob.glob(os.path.join(src, "tests/data/formats/*.svg")))[:1] +
              sorted(glob.glob(os.path.join(src, "tests/data/formats/*.cp")))[:1])
    # open-corner.fold first (the base Pattern), then the others in name order
    inputs.sort(key=lambda p: (os.path.basename(p) != "open-corner.fold", p))
    S.copies = [(p, os.path.join(S.tmp, os.path.basename(p))) for p in inputs]
    for a, b in S.copies:
        shutil.copyfile(a, b)
    S.fixed = [b for _, b in S.copies]
    S.fixed_names = {os.path.basename(b) for b in S.fixed}
    S.seq_text_path = next(b for b in S.fixed if b.endswith("open-corner.seq.json"))
    S.flat_path = next(b for b in S.fixed if b.endswith("degree4-vertex.fold"))
    exts = ["fold", "svg", "pdf", "png", "cp", "opx", "obj", "stl", "ply", "gltf", "glb", "gif", "json", "txt", ""]
    S.paths = S.fixed + [os.path.join(S.tmp, "out." + e) for e in exts] + [
        os.path.join(S.tmp, "missing", "none.fold"), os.path.join(S.tmp, "none.fold"), S.tmp]
    S.texts = []
    for p in S.fixed:
        with open(p, encoding="utf-8", errors="surrogateescape") as f:
            S.texts.append(f.read())
    S.kw, S.words = _kwlists(src)
    for k, v in _stub_names(src).items():
        S.kw.setdefault(k, v)
    _build_bases()
    S.attrs = {}
    for owner, obj in S.bases:
        S.attrs[owner] = _attrs(obj)
        for n in S.attrs[owner]:
            if owner.startswith("package"):
                try:
                    sig = inspect.signature(getattr(obj, n))
                    S.kw[(owner, n)] = [p for p in sig.parameters if p not in ("self", "cls")]
                except (TypeError, ValueError):
                    pass
    S.kwpool = sorted({n for v in S.kw.values() for n in v})
    S.shapes = [0, 1, 2, 3, 4, S.bases[2][1].vertex_count, S.bases[2][1].edge_count, S.bases[2][1].face_count]
    del obj  # (the loop's last receiver)
    S.live0 = None
    _rebuild()
    # Warm-up (with LeakSanitizer off, fuzz_python.c): inputs from a fixed generator, so that
    # the interpreter's and numpy's one-time caches and lazy imports are made before the leak
    # checks start.
    import random
    gen = random.Random(27)
    if os.environ.get("FUZZ_PYTHON_PROFILE") == "1":  # where the time of the warm-up goes
        import cProfile
        import pstats
        prof = cProfile.Profile()
        prof.enable()
        for i in range(WARM_UP):
            run(bytes(gen.getrandbits(8) for _ in range(8 + i % 192)))
        prof.disable()
        pstats.Stats(prof, stream=sys.stderr).sort_stats("cumulative").print_stats(40)
    for i in range(WARM_UP):
        f = run(bytes(gen.getrandbits(8) for _ in range(8 + i % 192)))
        if f:
            raise RuntimeError("fuzz_python: warm-up input %d: %s" % (i, f))
    return len(S.attrs["module"]), sum(len(v) for v in S.attrs.values())


# --- values ------------------------------------------------------------------------------------

SMALL_FLOATS = [math.nan, math.inf, -math.inf, -0.0, 0.0, 1e308, -1e308, 5e-324, 1e-300, 0.5, 1.0, -1.0, 2.0,
                math.pi, math.pi / 2, 90.0, 180.0, 1e9]
HUGE_INTS = [2**31, -2**31 - 1, 2**31 - 1, 2**63, -2**63 - 1, 2**64, 10**30, -10**30, 2**1000]
DTYPES = [np.float64, np.int32, np.int64, object, np.bool_, np.float32, np.complex128, np.uint8]


def _str(r):
    raw = r.take(r.u8() % 24)
    s = raw.decode("utf-8", errors="surrogateescape")  # lone surrogates for the undecodable bytes
    return s.replace("/", "_")  # no directory in it (a relative name is never written: every `path` is one of S.paths)


def _bytes(r):
    return r.take(r.u8() % 24).replace(b"/", b"_")


def _callable(r):
    k = r.u8() % 5

    def stop(fraction):
        raise ValueError("fuzz: stopped")
    return [lambda f: True, lambda f: False, stop, lambda f: None, 42][k]


def _array(r, depth, results):
    dt = r.pick(DTYPES)
    nd = r.u8() % 4
    shape = tuple(r.pick(S.shapes) for _ in range(nd))
    n = int(np.prod(shape)) if shape else 1
    if n > MAX_ELEMENTS:
        shape, n = (r.u8() % 8,), None
        n = shape[0]
    fill = r.u8() % 4
    if dt is object:
        flat = [value(r, depth + 1, None, results) for _ in range(min(n, 8))] + [0.0] * max(0, n - 8)
        a = np.empty(n, dtype=object)
        a[:] = flat if n else []
    elif fill == 0:
        a = np.zeros(n, dtype=dt)
    elif fill == 1:
        a = np.arange(n).astype(dt)
    else:
        vals = [r.pick(SMALL_FLOATS) if fill == 2 else (r.u8() - 128) / 8.0 for _ in range(n)]
        with np.errstate(all="ignore"):
            a = np.array(vals, dtype=np.float64).astype(dt)
    a = a.reshape(shape)
    if r.u8() % 4 == 0 and a.ndim >= 1:
        # non-contiguous: every other entry of an array twice as long, or a transposed copy
        if a.ndim >= 2 and r.u8() % 2:
            a = np.asfortranarray(a).T.T if r.u8() % 2 else np.ascontiguousarray(a.T).T
        else:
            b = np.repeat(a, 2, axis=0)
            a = b[::2]
    if r.u8() % 8 == 0:
        a.setflags(write=False)
    return a


_NONE = object()
INT_NAMES = {"fix", "drive", "face", "edge", "frame", "k", "rows", "cols", "sides", "axiom", "limit", "threads",
             "budget", "seed", "tries", "max_iterations", "max_steps", "probe_budget", "steps", "frames", "stops",
             "reorientations", "steps_per_event", "max_events", "keep_frames", "size"}
FLOAT_NAMES = {"fraction", "clearance", "current", "duration", "thickness", "tolerance", "t", "gravity", "fps",
               "hold", "width", "height", "step", "to", "from_", "angle", "max_move_rel", "max_move", "damping",
               "axial", "facet", "crease", "twist_size", "dt", "settle", "pulse", "current_limit",
               "meters_per_unit", "percent", "ratio"}
ARRAY_E = {"angles", "start", "targets", "fold_angles", "state"}
ARRAY_V3 = {"positions", "coords", "vertices"}


def _typed(r, name, hint):
    """A value of the type parameter `name` takes, near its valid range (_NONE: no rule)."""
    p = S.bases[2][1] if S.bases else None
    e = p.edge_count if p else 4
    v = p.vertex_count if p else 4
    if name in INT_NAMES:
        return (r.u8() % 40) - 4 if hint & 4 else r.u8() % max(e, 1)
    if name in FLOAT_NAMES or name.endswith("_rad"):
        return r.pick(SMALL_FLOATS) if hint & 4 else (r.u8() - 128) / 32.0
    if name in ("lock", "drives", "group", "edges" if hint & 8 else "lock"):
        return [r.u8() % max(e, 1) for _ in range(r.u8() % 4)]
    if name in ("a", "b", "p1", "p2"):
        return ((r.u8() - 64) / 64.0, (r.u8() - 64) / 64.0)
    if name in ("l1", "l2"):
        return (((r.u8() - 64) / 64.0, (r.u8() - 64) / 64.0), ((r.u8() - 64) / 64.0, (r.u8() - 64) / 64.0))
    if name == "polygon":
        return [((r.u8() - 64) / 32.0, (r.u8() - 64) / 32.0) for _ in range(r.u8() % 7)]
    if name in ARRAY_E:
        n = e if hint & 8 else r.u8() % 8
        return np.array([(r.u8() - 128) / 40.0 for _ in range(n)])
    if name in ARRAY_V3:
        n = v if hint & 8 else r.u8() % 8
        return np.array([[(r.u8() - 128) / 64.0 for _ in range(3)] for _ in range(n)]).reshape(n, 3)
    if name in ("assignment", "kind", "solver", "linear", "format", "view", "schedule", "camera", "option"):
        return r.pick(S.words)
    if name in ("infinite", "weld", "rigid", "count", "probe", "loop", "last_frame_only", "as_drawn", "physical",
                "all", "develop", "hull", "collisions", "bistable_height", "perspective", "labels", "grid"):
        return bool(hint & 4)
    return _NONE


def value(r, depth=0, name=None, results=()):
    """A value for parameter `name` (None when not known)."""
    if name in FORCED:
        return FORCED[name]
    hint = r.u8()
    if name is not None and (name == "path" or name.endswith("_path")):
        # Every writer's output is a `path` (the extension's, the package's): always inside the
        # temporary directory, or not a path at all.
        k = hint % 4
        if k < 2:
            return r.pick(S.paths)
        if k == 2:
            return os.path.join(S.tmp, _str(r)) if hint & 4 else os.fsencode(os.path.join(S.tmp, "")) + _bytes(r)
        return r.pick([None, 0, -1, 1.5, [], (S.tmp,), {}])
    if name is not None and hint % 4 != 3:
        typed = _typed(r, name, hint)
        if typed is not _NONE:
            return clamp(name, typed)
    if name is not None and hint % 3 == 0:
        if name in ("pattern",):
            return S.bases[2][1]
        if name in ("fold",):
            return S.bases[3 + hint % 2][1]
        if name == "composite":
            return r.pick(S.paths)
        if name == "progress":
            return _callable(r)
        if name in ("text", "folds"):
            return r.pick(S.texts)
    k = r.u8() % (22 if depth < 3 else 12)
    if k == 0:
        v = None
    elif k == 1:
        v = bool(r.u8() & 1)
    elif k == 2:
        v = (r.u8() % 80) - 8
    elif k == 3:
        v = struct.unpack("<i", r.take(4).ljust(4, b"\0"))[0]
    elif k == 4:
        v = r.pick(HUGE_INTS)
    elif k == 5:
        v = r.pick(SMALL_FLOATS)
    elif k == 6:
        v = struct.unpack("<d", r.take(8).ljust(8, b"\0"))[0]
    elif k == 7:
        v = (r.u8() - 128) / 16.0
    elif k == 8:
        v = _str(r)
    elif k == 9:
        v = r.pick(S.words)
    elif k == 10:
        v = r.pick(S.paths)
    elif k == 11:
        v = _bytes(r)
    elif k in (12, 13):
        v = [value(r, depth + 1, None, results) for _ in range(r.u8() % 6)]
        v = v if k == 12 else tuple(v)
    elif k == 14:
        v = {}
        for _ in range(r.u8() % 4):
            key = r.pick(S.kwpool) if r.u8() % 2 else value(r, 3, None, results)
            try:
                v[key] = value(r, depth + 1, None, results)
            except TypeError:  # unhashable key
                pass
    elif k == 15:
        v = _array(r, depth, results)
    elif k == 16:
        v = S.bases[2 + r.u8() % 5][1]
    elif k == 17:
        v = r.pick(list(results)) if results else S.bases[2][1]
    elif k == 18:
        v = ((r.u8() - 64) / 32.0, (r.u8() - 64) / 32.0)
    elif k == 19:
        v = r.pick(S.texts)
    elif k == 20:
        v = _callable(r)
    else:  # a point list, a list of ints (locks, drives), a list of points (polygons)
        n = r.u8() % 6
        v = [r.u8() % 24 for _ in range(n)] if hint & 1 else [((r.u8() - 64) / 32.0, (r.u8() - 64) / 32.0) for _ in range(n)]
    return clamp(name, v)


def clamp(name, v):
    if name is None or isinstance(v, bool):
        return v
    if isinstance(v, int):
        if name in INT_CAPS:
            lo, hi = INT_CAPS[name]
            return max(lo, min(hi, v))
        if name in FLOAT_CAPS:
            lo, hi = FLOAT_CAPS[name]
            return int(max(lo, min(hi, v)))
    if isinstance(v, float):
        if name in FLOAT_CAPS and math.isfinite(v):
            lo, hi = FLOAT_CAPS[name]
            v = max(lo, min(hi, v))
        if name in INT_CAPS and math.isfinite(v):
            lo, hi = INT_CAPS[name]
            v = max(float(lo), min(float(hi), v))
        if name in MIN_STEP and 0.0 < v < MIN_STEP[name]:
            v = MIN_STEP[name]
    if isinstance(v, np.ndarray) and name in MIN_STEP | FLOAT_CAPS | INT_CAPS:
        return v.size and v.flat[0]  # no arrays of work sizes: their first entry (clamped again)
    return v


# --- one input ---------------------------------------------------------------------------------

def _classify(exc, owner):
    """None for an acceptable exception, else the finding."""
    chain, e = [], exc
    while e is not None and len(chain) < 8:
        chain.append(e)
        e = e.__cause__ or e.__context__
    for e in chain:
        if isinstance(e, SystemError):
            return "SystemError: %s" % e
    if owner.startswith("package"):
        return None  # the pure-Python layer may raise what Python raises; only the extension is held to the list
    if isinstance(exc, EXPECTED) or isinstance(exc, S.ext.Error):
        return None
    return "%s: %s" % (type(exc).__name__, exc)


def run(data):
    finding, wrote, touched = _calls(Reader(data))
    # (the calls' locals, which hold the receivers and results, are gone here)
    if wrote:
        _reset_dir()
    if finding:
        return finding
    return _check_live(touched)


def _calls(r):
    results = []
    wrote = False
    touched = False
    finding = None
    for _ in range(1 + r.u8() % MAX_CALLS):
        if r.i >= len(r.d) and results:
            break
        receivers = S.bases + [(type(x).__name__, x) for x in results if type(x).__module__.startswith("orikin")]
        owner, obj = receivers[r.u8() % len(receivers)]
        names = S.attrs.get(owner)
        if names is None:
            names = S.attrs[owner] = _attrs(obj)
        if not names:
            continue
        name = r.pick(names)
        touched = touched or (name in MUTATORS and any(obj is b for _, b in S.bases[2:]))
        params = S.kw.get((owner, name)) or S.kw.get(("module" if owner == "module" else owner.split(".")[-1], name)) or []
        try:
            attr = getattr(obj, name)
        except EXPECTED:
            continue
        except BaseException as e:
            finding = _classify(e, owner)
            break
        if not callable(attr) or isinstance(attr, type):
            results.append(attr)
            continue
        flags = r.u8()
        nargs = flags % 5
        args = [value(r, 0, params[i] if i < len(params) else None, results) for i in range(nargs)]
        kwargs = {}
        for _ in range((flags >> 3) % 4):
            sel = r.u8()
            if sel % 8 < 6 and params:
                key = params[(sel >> 3) % len(params)]
            elif sel % 8 < 7:
                key = r.pick(S.kwpool)
            else:
                key = _str(r)
            kwargs[key] = value(r, 0, key, results)
        for key in list(kwargs):
            if key in FORCED:
                kwargs[key] = FORCED[key]
        wrote = wrote or name in WRITERS
        if S.trace:
            sys.stderr.write("fuzz_python: %s.%s(*%r, **%r)\n" % (owner, name, args, kwargs)[:2000])
        try:
            out = attr(*args, **kwargs)
        except BaseException as e:
            finding = _classify(e, owner)
            if finding:
                finding = "%s.%s(%d args, keywords %s): %s" % (owner, name, len(args), sorted(map(repr, kwargs)), finding)
                break
            continue
        results.append(out)
        if isinstance(out, tuple):
            results.extend(x for x in out if type(x).__module__.startswith("orikin"))
    return finding, wrote, touched


def cleanup():
    """Remove the temporary directory (fuzz_python.c calls it at exit)."""
    if S is not None:
        shutil.rmtree(S.tmp, ignore_errors=True)


def _rebuild():
    """Make the receivers again; their library allocations dropped, the count must be the one
    without them that setup() measured."""
    S.bases = None
    gc.collect()
    live = S.ext._alloc_live_count()
    if S.live0 is not None and live != S.live0:
        return "library allocations without the receivers: %d, were %d (a leaked reference)" % (live, S.live0)
    S.live0 = live
    _build_bases()
    S.live = S.ext._alloc_live_count()
    return None


def _check_live(touched):
    """The library's counted allocations are back where they were: a reference the extension
    forgot to release keeps its object, and the object's library memory, alive. A receiver that
    changed (a collide() that trimmed a Motion, a computed cache) is made again."""
    if touched:
        return _rebuild()
    live = S.ext._alloc_live_count()
    if live != S.live:
        gc.collect()
        live = S.ext._alloc_live_count()
        if live != S.live:
            return _rebuild()
    return None
