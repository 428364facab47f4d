"""The orikin package's classes over the C extension (orikin._orikin).

Units: angles you pass are degrees, as on the command line and in FOLD files (positive =
valley, negative = mountain); arrays the library hands out are radians, as it stores them
(``motion.angles`` is a view of the library's memory and cannot convert; ``motion.angles_deg``
is a converted copy). Lengths are the pattern's units; actuation is SI.
"""

from __future__ import annotations

import json
import math
import os
from typing import Any, Callable, Iterable, Optional, Sequence, Union

import numpy as np

from . import _orikin as _c

Error = _c.Error
InputError = _c.InputError
SolveError = _c.SolveError
Cancelled = _c.Cancelled

Progress = Optional[Callable[[float], Any]]


def _usage(message: str, option: Optional[str] = None) -> InputError:
    """An InputError for an argument out of range, with the CLI's text (its usage errors)."""
    e = InputError(message)
    e.status, e.element, e.field, e.line, e.column = "ERR_RANGE", None, None, None, None
    e.option, e.reason = option, message
    return e


class Report:
    """A result record: fields as attributes (``r.flat_foldable``) and as keys (``r["dof"]``)."""

    __slots__ = ("_d",)

    def __init__(self, d: dict):
        object.__setattr__(self, "_d", d)

    def __getattr__(self, name: str):
        try:
            return self._d[name]
        except KeyError:
            raise AttributeError(f"{type(self).__name__} has no field {name!r}") from None

    def __setattr__(self, name, value):
        raise AttributeError(f"{type(self).__name__} is read-only")

    def __getitem__(self, key: str):
        return self._d[key]

    def __contains__(self, key: str) -> bool:
        return key in self._d

    def keys(self):
        """The field names."""
        return self._d.keys()

    def as_dict(self) -> dict:
        """The fields as a plain dict (nested reports too)."""
        def plain(v):
            if isinstance(v, Report):
                return v.as_dict()
            if isinstance(v, list):
                return [plain(x) for x in v]
            return v
        return {k: plain(v) for k, v in self._d.items()}

    def __repr__(self) -> str:
        shown = ", ".join(f"{k}={v!r}" for k, v in self._d.items() if not isinstance(v, (list, np.ndarray, dict)))
        return f"{type(self).__name__}({shown})"


class CheckReport(Report):
    """Local flat-foldability of every interior vertex (`orikin check`): flat_foldable,
    interior_count, failed_count, within_count, max_deviation_rad, vertices (VertexReport per
    interior vertex: kawasaki, maekawa (None when undetermined), big_little_big, mv_count (Hull's
    C, None beyond 2^64), assignment_valid, completions, flat_foldable, within_tolerance,
    deviation_rad, creases, sectors_rad ...) and violations (vertex, rule, edge, value, detail)."""


class VertexReport(Report):
    """One interior vertex of a CheckReport."""


class Violation(Report):
    """One broken rule at one vertex: vertex, rule ('kawasaki', 'maekawa', 'big_little_big',
    'assignment', 'cone'), edge, value, detail (a sentence)."""


class DofReport(Report):
    """Degrees of freedom at a state (`orikin dof`): grubler, unknowns, equations, rank, dof
    (infinitesimal), generic_dof (at a nearby regular state; None when not probed or
    undetermined), singular, rigid, undetermined, probe_solves, dense, sigma_max, sigma_cut."""


class Regularization(Report):
    """What `regularize` did: pattern (the exact pattern, or None when not converged, refused or
    the moves made edges cross), converged, refused, max_move_rel, moved_vertices,
    kawasaki_before_rad / kawasaki_after_rad, rigid_before / rigid_after, crossing, ..."""


class Collision(Report):
    """Self-collision of one state (`orikin collide`): collides, penetrating, touching, near,
    min_clearance, clearance_faces, witness, tolerance, contacts (Contact: faces, kind
    ('penetrating', 'touching', 'near'), adjacent, stacked, collides, distance, point)."""


class Contact(Report):
    """A pair of faces in contact."""


class CollisionEvent(Report):
    """The first collision along a motion: frame (the first colliding frame; frames before it
    are clean), faces, kind, point, drive_rad (single drive) or progress, time, fold (sequences)."""


class Actuation(Report):
    """Hinge sizing and Lorentz actuation along a fold or sequence (`orikin actuate`): feasible,
    current_needed_a, worst_edge, mechanism_current_a, gravity_ratio_max, reorientations,
    schedule (the field schedule used), hinges (per hinge: mechanics, current_needed_a,
    springback_rad, optimal_thickness_m, width_range_m, feasible ...), fields (frames, 3),
    drives_rad, steps (dict of (hinges, frames) arrays: current_a, required_moment_nm, ...)."""


class Simulation(Report):
    """Folding dynamics (`orikin simulate`): times (s), angles (frames, E) rad, currents,
    plastic, fields, energies (kinetic, total), vertices (frames, V, 3), latched_rad (after the
    currents stop), reached_target, time_to_target_s, peak_angular_velocity, energy_drift, ..."""


class CompliantSimulation(Report):
    """The device on compliant panels (`orikin simulate --model compliant`): loaded_rad (fold
    angles under the full current), plastic_rotation_rad, currents (signed, A), max_strain,
    latched_rad (the current off), current_fractions and angles (one row per load step, the
    first current_on_frames with the current ramping up, then down), wires, vertices."""


class Net(Report):
    """An unfolding (`orikin unfold`): pattern (the net as a crease pattern), pieces, faces,
    overlaps, refolded, max_refold_error, fold_order, distinct_nets, cuts, developed,
    vertex_source, vertex_position, glue ..."""


class LinkageMotion(Report):
    """A planar linkage straightened or convexified (`orikin unfold-linkage`): kind ('chain' or
    'polygon'), frames (K, n, 2), events, flips, straightened, final_ok, max_length_error,
    min_distance_change."""


class StepResult(Report):
    """One design-search step (DesignEnv.step): applied (the crease was added), error (why not),
    edges (the new edges), creases (M, V and U creases now), rigid_foldable (the mechanism has a
    motion and the fold toward the targets from the flat sheet takes it, every crease as
    assigned), progress (how far it got, 0 to 1), verdict (of that fold), dof (the degrees of
    freedom along that motion; None when undetermined), flat_dof (the infinitesimal count at the
    flat sheet), against_assignment, against_edge, collides (along that fold),
    collision (where), reward (the environment's), pattern (the observation), terminated,
    truncated."""

    def astuple(self) -> tuple:
        """(observation, reward, terminated, truncated, info) as a gym environment's step returns them."""
        return self.pattern, self.reward, self.terminated, self.truncated, self.as_dict()


# --- naming faces and creases -----------------------------------------------------------------

def _point(spec) -> Optional[tuple]:
    """A point (x, y) from '@x,y' (the CLI's form) or a pair with a float in it; else None."""
    if isinstance(spec, str) and spec.startswith("@"):
        try:
            x, y = (float(v) for v in spec[1:].split(","))
        except ValueError:
            raise TypeError(f"'{spec}': a point is @x,y") from None
        return (x, y)
    if isinstance(spec, (tuple, list, np.ndarray)) and len(spec) == 2 and any(
            isinstance(v, (float, np.floating)) for v in spec):
        return (float(spec[0]), float(spec[1]))
    return None


def _edge_list(spec) -> list:
    """A crease or several: an index, a point, '3,@0.5,1,9' (the CLI's list), or a sequence."""
    if spec is None:
        return []
    if isinstance(spec, (int, np.integer)) or _point(spec) is not None:
        return [spec]
    if isinstance(spec, str):
        items, parts = [], spec.split(",")
        i = 0
        while i < len(parts):
            if parts[i].startswith("@") and i + 1 < len(parts):
                items.append(parts[i] + "," + parts[i + 1])
                i += 2
            else:
                items.append(int(parts[i]))
                i += 1
        return items
    return list(spec)


def _check_angle(value: float, option: str) -> float:
    if not (abs(value) <= 180.0):
        raise _usage(f"{option} {value:g} is outside [-180, 180] degrees", option)
    return math.radians(value)


# --- the pattern ---------------------------------------------------------------------------------

class Pattern:
    """A crease pattern (or a folded form) and the FOLD document it came from.

    Patterns are immutable: crease(), apply(), assign(), flip(), remove(), move() and
    regularize() return new ones, so a motion never sees its pattern change. Indices are FOLD
    indices. Make one with Pattern.load, Pattern.from_arrays, Pattern.from_fold, Pattern.sheet
    or orikin.generate.
    """

    __slots__ = ("_p",)

    def __init__(self, _p: _c.Pattern):
        if not isinstance(_p, _c.Pattern):
            raise TypeError("make a Pattern with Pattern.load, from_arrays, from_fold, sheet or orikin.generate")
        self._p = _p

    # --- making ---------------------------------------------------------------------------------

    @classmethod
    def load(cls, path: Union[str, os.PathLike], *, frame: int = 0, weld: bool = False) -> "Pattern":
        """Read a crease pattern: FOLD (frame N of it; weld merges vertices closer than the
        length tolerance), or a drawing (.svg in Origami Simulator's colours, ORIPA .opx, .cp).
        Raises InputError with the line `orikin` prints for the same file (after 'orikin CMD: ')."""
        return cls(_c.load(path, frame, weld))

    @classmethod
    def from_fold(cls, fold: Union[dict, str], *, frame: int = 0, weld: bool = False) -> "Pattern":
        """A pattern from a FOLD document: a dict (as json.load gives) or its JSON text. Unknown
        fields are kept and come back in to_fold()."""
        text = fold if isinstance(fold, str) else json.dumps(fold)
        return cls(_c.from_fold_text(text, frame, weld))

    @classmethod
    def from_arrays(cls, vertices, edges, assignment, faces=None, *, fold_angles=None, weld: bool = False) -> "Pattern":
        """A pattern from arrays: vertices (V, 2) or (V, 3) coordinates (z != 0: a folded form),
        edges (E, 2) vertex indices, assignment one FOLD letter per edge ('MVB...' or a list),
        faces (vertex cycles, counter-clockwise; None: traced from the planar graph) and
        fold_angles (E degrees; None: no edges_foldAngle). Validated as a FOLD file is: an error
        names the FOLD index ('edges_vertices 3: ...')."""
        angles = None if fold_angles is None else np.radians(np.asarray(fold_angles, dtype=float))
        if not isinstance(assignment, str):
            assignment = "".join(assignment)
        return cls(_c.from_arrays(vertices, edges, assignment, faces, angles, weld))

    @classmethod
    def sheet(cls, polygon) -> "Pattern":
        """A blank sheet: a simple polygon (n, 2) of corners, one face named Obj1 (`orikin new`)."""
        return cls(_c.sheet(np.asarray(polygon, dtype=float)))

    @classmethod
    def square(cls, size: float = 1.0) -> "Pattern":
        """A blank square sheet of side size with its lower-left corner at the origin."""
        return cls.sheet([(0.0, 0.0), (size, 0.0), (size, size), (0.0, size)])

    # --- reading --------------------------------------------------------------------------------

    vertex_count = property(lambda self: self._p.vertex_count, doc="Number of vertices.")
    edge_count = property(lambda self: self._p.edge_count, doc="Number of edges.")
    face_count = property(lambda self: self._p.face_count, doc="Number of faces.")
    frame_count = property(lambda self: self._p.frame_count, doc="Frames of the FOLD file it came from.")
    is_folded_form = property(lambda self: self._p.is_folded_form, doc="A folded form rather than a flat sheet.")
    has_fold_angles = property(lambda self: self._p.has_fold_angles, doc="The edges carry fold angles (edges_foldAngle).")
    interior_vertex_count = property(lambda self: self._p.interior_vertex_count, doc="Vertices the paper surrounds.")
    diagonal = property(lambda self: self._p.diagonal, doc="Bounding-box diagonal (the length scale of tolerances).")
    source = property(lambda self: self._p.source, doc="The file it came from (or '<arrays>', '<fold>', ...).")

    @property
    def vertices(self) -> np.ndarray:
        """(V, 3) coordinates (a copy)."""
        return self._p.vertices()

    @property
    def edges(self) -> np.ndarray:
        """(E, 2) vertex indices (a copy)."""
        return self._p.edges()

    @property
    def assignment(self) -> str:
        """One FOLD letter per edge: B, M, V, F, U, C, J."""
        return self._p.assignment()

    @property
    def fold_angles(self) -> np.ndarray:
        """Fold angle per edge in degrees (FOLD edges_foldAngle; a copy)."""
        return np.degrees(self._p.fold_angles())

    @property
    def targets(self) -> np.ndarray:
        """The 100 % goal of fold(percent=...) in degrees: a crease's fold angle where it has
        one, else +180 valley, -180 mountain, 0 other edges."""
        return np.degrees(self._p.targets())

    @property
    def faces(self) -> list:
        """Faces as lists of vertex indices (counter-clockwise from the front)."""
        return self._p.faces()

    @property
    def face_names(self) -> list:
        """Face names (Obj1, Obj12 ... the crease history), None where a face has none."""
        return self._p.face_names()

    def face(self, spec, option: str = "--fix") -> int:
        """The face an index, a name ('Obj12') or a point ((x, y) or '@x,y') names, as the CLI
        resolves --fix; InputError with the CLI's message when the pattern has none."""
        p = _point(spec)
        return self._p.find_face(p if p is not None else spec, option)

    def edge(self, spec, option: str = "--drive") -> int:
        """The crease an index or a point on it ((x, y) or '@x,y') names."""
        p = _point(spec)
        return self._p.find_edge(p if p is not None else spec, option)

    def center_face(self) -> int:
        """The face a fold fixes when none is named: the one at the sheet's centre."""
        return self._p.center_face()

    def grubler(self) -> int:
        """Grübler–Kutzbach mobility of the mechanism (wrong when overconstrained: -1 for the open corner)."""
        return self._p.grubler()

    def to_fold(self) -> dict:
        """The pattern as a FOLD dict (its file's fields kept; angles in degrees)."""
        return json.loads(self._p.to_fold_text())

    def save(self, path: Union[str, os.PathLike]) -> None:
        """Write FOLD, or by the extension SVG / CP / OPX; atomically (temporary file, rename)."""
        self._p.save(path)

    def __repr__(self) -> str:
        return (f"<orikin.Pattern {self.source}: {self.vertex_count} vertices, {self.edge_count} edges, "
                f"{self.face_count} faces>")

    # --- authoring ------------------------------------------------------------------------------

    def crease(self, a=None, b=None, *, line=None, assignment: str = "V", angle: float = 0.0, face=None,
               segment: bool = False) -> "Pattern":
        """A new pattern with a crease through a and b (or line=((x, y), (dx, dy)), e.g. from
        orikin.axiom) clipped to face (index, name or point; None: every face it crosses), like
        a perforation: each face it crosses splits and its parts are named N1 (left of a->b),
        N2. segment=True creases only the segment ab. angle: its fold angle in degrees."""
        if line is not None:
            (px, py), (dx, dy) = line
            a, b = (px, py), (px + dx, py + dy)
        if a is None or b is None:
            raise TypeError("crease needs two points a, b (or line=)")
        f = -1 if face is None else self.face(face, "--face")
        p, _ = self._p.crease(a, b, not segment, assignment, math.radians(angle), f)
        return Pattern(p)

    def apply(self, composite: str, *, face=None, assignment: Optional[str] = None) -> "Pattern":
        """A new pattern with a composite of the crease collection ('diagonal-left',
        'diagonal-right', 'middle-h', 'middle-v', or a composite JSON file) on a face."""
        f = -1 if face is None else self.face(face, "--face")
        p, _ = self._p.apply(composite, f, assignment)
        return Pattern(p)

    def assign(self, edge, assignment: str) -> "Pattern":
        """A new pattern with crease edge re-assigned ('M', 'V', 'F', 'U')."""
        return Pattern(self._p.edit("assign", self.edge(edge, "--assign"), assignment))

    def flip(self, edge) -> "Pattern":
        """A new pattern with mountain edge made a valley (or back), its angle negated."""
        return Pattern(self._p.edit("flip", self.edge(edge, "--flip")))

    def remove(self, edge) -> "Pattern":
        """A new pattern without crease edge (its faces merge)."""
        return Pattern(self._p.edit("remove", self.edge(edge, "--remove")))

    def move(self, edge, a, b) -> "Pattern":
        """A new pattern with crease edge moved onto the segment ab."""
        return Pattern(self._p.edit("move", self.edge(edge, "--move"), None, a, b))

    # --- analysis -------------------------------------------------------------------------------

    def check(self, tolerance: float = 0.0) -> CheckReport:
        """Local flat-foldability of every interior vertex (`orikin check`): Kawasaki, Maekawa,
        big-little-big, Hull's count of valid M/V assignments and the exact test. tolerance
        (degrees, 0 to 1): a vertex that misses only by rounding within it passes 'within
        tolerance' (a rounded drawing)."""
        if not (0.0 <= tolerance <= 1.0):
            raise _usage(f"--tolerance needs an angle in degrees in [0, 1], got '{tolerance:g}'", "--tolerance")
        d = self._p.check(math.radians(tolerance))
        d["vertices"] = [VertexReport(v) for v in d["vertices"]]
        d["violations"] = [Violation(v) for v in d["violations"]]
        return CheckReport(d)

    def regularize(self, rigid: bool = False, *, max_move: Optional[float] = None,
                   max_iterations: int = 100) -> Regularization:
        """The nearest exact pattern (`orikin regularize`): vertices moved the least so that
        Kawasaki holds exactly and, with rigid=True, so that the pattern folds rigidly from the
        flat sheet. max_move: refuse beyond this fraction of the sheet's diagonal."""
        kw = {"rigid": rigid, "max_iterations": max_iterations}
        if max_move is not None:
            kw["max_move_rel"] = max_move
        p, d = self._p.regularize(**kw)
        d["pattern"] = None if p is None else Pattern(p)
        return Regularization(d)

    def layers(self, *, limit: Optional[int] = None, threads: int = 1, progress: Progress = None) -> "Layers":
        """Global flat-foldability (`orikin layers`): every flat-folded state (layer order) of
        the pattern, counted exactly (Flat-Folder's model), or the conflict when there is none."""
        return Layers(self._p.layers(limit=limit, threads=threads, count=True, progress=progress), self)

    def dof(self, state=None, *, lock=None, probe: bool = True, budget: int = 0, progress: Progress = None) -> DofReport:
        """Degrees of freedom (`orikin dof`) at the flat sheet or a state (a State, or fold
        angles in degrees): the rank of the loop-closure Jacobian, and with probe the DOF at a
        nearby regular state (the flat sheet is singular)."""
        angles = None
        if isinstance(state, State):
            angles = state.angles
        elif state is not None:
            angles = np.radians(np.asarray(state, dtype=float))
        locks = [self.edge(e, "--lock") for e in _edge_list(lock)]
        return DofReport(self._p.dof(angles, locks, probe, budget, progress))

    def symmetry(self) -> tuple:
        """(orbits, groups, order): per edge the smallest edge a symmetry maps it to, the number
        of orbits holding a crease, and the order of the flat pattern's symmetry group."""
        return self._p.symmetry()

    # --- kinematics -----------------------------------------------------------------------------

    def _start(self, frame: int, start) -> tuple:
        """Start angles (radians) and the coordinates placing the fixed face, as the CLI's
        --frame N: a folded frame's angles and 3D pose; a State; angles in degrees."""
        if start is not None:
            if isinstance(start, State):
                return np.ascontiguousarray(start.angles), np.ascontiguousarray(start.positions)
            return np.radians(np.asarray(start, dtype=float)), None
        if frame == 0 and self._p.frame_count >= 1 and not self.is_folded_form:
            return None, None
        angles, coords, is3d = self._p.frame_state(frame)
        return angles, coords if is3d else None

    def fold(self, fix=None, drive=None, to=None, *, from_: Optional[float] = None, step: float = 10.0,
             lock=None, frame: int = 0, start=None, solver: str = "auto", linear: str = "auto",
             percent: Optional[float] = None, ratio=None, symmetric: bool = False, collisions: bool = True,
             clearance: float = 0.0, progress: Progress = None, compliant: bool = False, dynamic: bool = False,
             preset: str = "origami-simulator", axial: Optional[float] = None, facet: Optional[float] = None,
             crease: Optional[float] = None, damping: Optional[float] = None, gravity: float = 0.0,
             steps: int = 1000000, threads: int = 1, all_frames: bool = False) -> Union["Motion", "CompliantFold"]:
        """Fold rigidly: fix a face, lock creases, drive a crease (`orikin fold`).

        Treat the crease pattern as a mechanism (faces = rigid bodies, creases = revolute
        joints), hold face `fix` fixed and the locked creases at their current angle, and turn
        crease `drive` from its current angle (or `from_`) to `to` degrees (positive = valley,
        negative = mountain). Every step is an exact solution of the loop-closure equations
        (residual below 1e-10). Starting from the flat sheet, the branch is the one the MV
        assignment admits; the fold is invalid when every motion folds some crease against its
        assignment (the crease and the angle it would reach are named), and not rigidly
        foldable when no motion exists. A single vertex with four moving creases is solved in
        closed form and split into the thesis' Frame A, Frame B and surrounding; other patterns
        by numeric continuation. Every step is checked for self-collision (collide): a motion
        that collides stops at the last clean step, with the first contact located to 1e-6 deg
        (verdict 'collision'). A motion stops (verdict 'blocked') where a moving crease reaches
        +-180 deg or at a singular point (motion.blocked names the creases that can move there);
        no crease ever leaves [-180, 180] deg. From the flat sheet the branch is found once, a
        fixed 1 deg out: the verdict depends on neither `step` nor how small `to` is.
        Exceptions are orikin.InputError for what the CLI exits 2 or 3 on (an index the pattern
        does not have: the same message), orikin.SolveError for exit 4; a negative verdict is a
        result (motion.valid is False), as the CLI's exit 1.

        Arguments (the CLI's options):
          fix       face held fixed: FOLD index, name ('Obj12') or a point (x, y) / '@x,y' (the
                    face there); default: the face at the centre of the sheet's bounding box
                    (motion.fix_default tells)
          drive     driven crease: FOLD index or a point on it; several (a list) drive them
                    together (the mode 'drives' below)
          to        final angle of the driven crease in degrees, -180 to 180 (a list for several)
          from_     output from this angle (reached first, silently); default: the current one
          step      output spacing in degrees (> 0); default 10
          lock      creases held at their current angle: indices and points mixed
                    ([3, (0.5, 1.0), 9] or the CLI's '3,@0.5,1,9'); or 'auto' (below)
          frame     start from the fold angles (and 3D pose) of frame N of the file; default 0
          start     start from a State (motion.at(t), a sequence instant: angles and pose) or
                    fold angles in degrees, instead of a frame
          solver    'auto' (default), 'analytic' (single vertex only) or 'numeric'
          linear    the numeric solver's linear algebra: 'auto', 'dense', 'sparse' or 'sweep'
          collisions  check every step for self-collision (default True; False: --no-collisions)
          clearance   faces sharing no vertex closer than this length collide too (>= 0)
          progress  called with the fraction done (0 to 1) while the solve runs (the GIL is
                    released); returning False cancels: orikin.Cancelled. Ctrl-C cancels too.

        Patterns with several degrees of freedom (docs/kinematics.md §16):
          percent   fold every crease toward its target (edges_foldAngle or SVG opacity; +-180
                    by assignment where absent), by projecting onto the rigid motions: percent of the way
                    (0-100) along the motion toward the 100 % targets (progress
                    1 - D/D0, D the distance to the targets; Origami Simulator's slider, the CLI's
                    --percent); motion.creases tells how far each got
          drive=[e1, e2, ...], to=[a1, a2, ...]   drive several creases together (the rest solved)
          ratio     with one `to` A: crease ei goes to ratio[i] x A degrees
          lock='auto'  lock the creases a rank-revealing QR of the Jacobian leaves over (one
                    degree of freedom per drive); an underdetermined fold's motion.hint says such a set
          symmetric keep creases that the pattern's symmetries map onto each other at equal angles
          (these modes check every step for self-collision as the ordinary fold does)

        Compliant folding (compliant=True, the CLI's --compliant; docs/compliant.md): fold with
        a bar-and-hinge model (Origami Simulator's: faces triangulated, bars on every edge and
        diagonal, creases driven to `percent` % of their targets, facet hinges resisting panel
        bending), so that patterns that are not rigidly foldable fold too, bending a little.
        Returns a CompliantFold (fold_angles, strains, positions, face_energies, contacts as
        numpy arrays and lists; .info() is the CLI's --json), not a Motion. Takes fix, percent
        (default 100) and:
          dynamic   the explicit solver (damped Verlet, stable time step) for at most `steps`
                    steps, instead of the static one (Newton with load steps, |grad E| <= 1e-10
                    of the load)
          preset    'origami-simulator' (default: axial 20, facet 0.2, crease 0.7, damping
                    0.45) or 'physical' (SI: 1 um silicon panels; lengths in metres)
          axial, facet, crease, damping   the stiffnesses of the preset, replaced
          gravity   acceleration along -z (model units or m/s^2); default 0
          steps     the explicit solver's step bound (> 0)
          threads   the explicit solver's threads (1 to 64; large sheets only share them)
          all_frames  keep one frame per load step, or with dynamic the time history (the CLI's --all-frames)
        A fold that does not reach its fraction is a result (fold.reached False, fold.reason:
        the CLI's exit 1, or 5 for dynamic); bad stiffnesses are orikin.InputError with the
        CLI's message.

        From the command line's other options: --json is the Motion itself (motion.info(),
        .angles, .frames ...), -o OUT.fold is motion.to_fold() / motion.save(path), --weld and
        the drawing options (--tolerance, --gaps, --keep-*) belong to Pattern.load, and --force
        (the CLI's output guard) has no counterpart: nothing is written unless asked.

        Example (the CLI's):
            p = orikin.Pattern.load("examples/patterns/open-corner.fold")
            m = p.fold(fix=4, drive=12, lock=[11], to=90)
            np.degrees(m.angles[-1, [8, 9]])   # the thesis' 35.26 and 60 degrees
        """
        if compliant:
            rigid_only = (("--drive", drive is not None), ("--to", to is not None), ("--from", from_ is not None),
                          ("--step", step != 10.0), ("--lock", lock is not None), ("--frame", frame != 0),
                          ("--start", start is not None), ("--solver", solver != "auto"), ("--linear", linear != "auto"),
                          ("--ratio", ratio is not None), ("--symmetric", bool(symmetric)),
                          ("--no-collisions", not collisions), ("--clearance", clearance != 0.0))
            for name, given in rigid_only:
                if given:
                    raise _usage(f"unknown option '{name}' with --compliant (see orikin fold -h)", name)
            return self._compliant_fold(fix, 100.0 if percent is None else percent, dynamic, preset, axial, facet,
                                        crease, damping, gravity, steps, all_frames, threads)
        for name, given in (("--dynamic", dynamic), ("--preset", preset != "origami-simulator"),
                            ("--axial", axial is not None), ("--facet", facet is not None),
                            ("--crease", crease is not None), ("--damping", damping is not None),
                            ("--gravity", gravity != 0.0), ("--steps", steps != 1000000), ("--threads", threads != 1),
                            ("--all-frames", all_frames)):
            if given:
                raise _usage(f"{name} is an option of the compliant fold: add --compliant", name)
        if fix is None:
            fix_index, fix_default = self.center_face(), True
        else:
            fix_index, fix_default = self.face(fix, "--fix"), False
        drives = _edge_list(drive)
        several_to = isinstance(to, (list, tuple, np.ndarray))
        lock_auto = isinstance(lock, str) and lock == "auto"
        modes = percent is not None or symmetric or ratio is not None or lock_auto or len(drives) > 1 or several_to
        if modes:
            for name, given in (("--from", from_ is not None), ("--solver", solver != "auto"),
                                ("--linear", linear != "auto")):
                if given:
                    raise _usage(f"{name} applies to a single drive, not with --percent, several drives, --ratio, "
                                 "--symmetric or --lock auto", name)
        locks = [] if lock_auto else _unique([self.edge(e, "--lock") for e in _edge_list(lock)])
        if not (step > 0):
            raise _usage(f"--step must be a positive angle in degrees, got {step:g}", "--step")
        start_angles, coords = self._start(frame, start)
        if lock_auto and len(drives) == 1 and not several_to and percent is None and ratio is None and not symmetric:
            # One drive with lock='auto': the lock set, then the ordinary fold (as the CLI).
            locks = [int(e) for e in self._p.lock_set([self.edge(drives[0], "--drive")], lock=[], start=start_angles,
                                                      progress=progress)]
            if not locks:
                raise _usage("--lock auto: nothing to lock, the drive leaves no freedom", "--lock")
            modes = False
        if not modes:
            if not drives:
                raise _usage("missing --drive EDGE", "--drive")
            if to is None:
                raise _usage("missing --to DEG", "--to")
            to_rad = _check_angle(float(to), "--to")
            from_rad = None if from_ is None else _check_angle(float(from_), "--from")
            m = self._p.fold(fix_index, self.edge(drives[0], "--drive"), to_rad, math.radians(step), from_rad,
                             locks, solver, linear, start_angles, coords, False, progress)
            motion = Motion(m, self, fix_default)
        else:
            group = self._p.symmetry()[0] if symmetric else None
            if percent is not None:
                if drives or to is not None or ratio is not None:
                    raise _usage("--percent folds every crease toward its target: no --drive, --to or --ratio with it",
                                 "--percent")
                if lock_auto:
                    raise _usage("--lock auto applies to drives: --percent needs no lock set", "--lock")
                if not (0.0 <= percent <= 100.0):
                    raise _usage(f"--percent needs a number from 0 to 100, got '{percent:g}'", "--percent")
                m = self._p.target_fold(fix_index, percent / 100.0, math.radians(step), lock=locks, group=group,
                                        start=start_angles, coords=coords, progress=progress)
            else:
                if not drives:
                    raise _usage("missing --drive EDGE (or --percent P)", "--drive")
                if to is None:
                    raise _usage("missing --to DEG", "--to")
                tos = [float(t) for t in (to if several_to else [to])]
                if ratio is not None:
                    ratio = [float(r) for r in ratio]
                    if len(tos) != 1:
                        raise _usage("--ratio takes one --to angle (crease Ei goes to Ri x that angle)", "--ratio")
                    if len(ratio) != len(drives):
                        raise _usage(f"--ratio has {len(ratio)} values for {len(drives)} driven creases", "--ratio")
                    tos = [r * tos[0] for r in ratio]
                elif len(tos) != len(drives):
                    raise _usage(f"--to has {len(tos)} angles for {len(drives)} driven creases", "--to")
                to_rad = [_check_angle(t, "--to") for t in tos]
                edges = [self.edge(e, "--drive") for e in drives]
                if lock_auto:
                    locks = self._p.lock_set(edges, lock=[], group=group, start=start_angles, progress=progress)
                m = self._p.drives_fold(fix_index, edges, np.array(to_rad), math.radians(step), lock=locks, group=group,
                                        start=start_angles, coords=coords, progress=progress)
            motion = Motion(m, self, fix_default, percent=percent, lock_auto=lock_auto, symmetric=symmetric)
        if collisions:
            motion.collide(clearance)
        return motion

    def _compliant_fold(self, fix, percent, dynamic, preset, axial, facet, crease, damping, gravity, steps,
                        all_frames, threads=1) -> "CompliantFold":
        """Pattern.fold(compliant=True): the CLI's checks (cli/fold_compliant.c), then the solve."""
        if not (0.0 <= percent <= 100.0):
            raise _usage(f"--percent needs a number from 0 to 100, got '{percent:g}'", "--percent")
        if preset not in ("origami-simulator", "physical"):
            raise _usage(f"--preset is origami-simulator or physical, got '{preset}'", "--preset")
        for name, value, zero_ok in (("--axial", axial, False), ("--facet", facet, True), ("--crease", crease, True),
                                     ("--damping", damping, True)):
            if value is not None and not (math.isfinite(value) and (value > 0 or (zero_ok and value == 0))):
                raise _usage(f"{name} needs a number {'>= 0' if zero_ok else '> 0'}, got '{value:g}'", name)
        if not math.isfinite(gravity):
            raise _usage(f"--gravity needs a number, got '{gravity:g}'", "--gravity")
        if int(steps) != steps or steps <= 0:
            raise _usage(f"--steps needs a positive integer, got '{steps}'", "--steps")
        if int(threads) != threads or not (1 <= threads <= 64):
            raise _usage(f"--threads needs an integer from 1 to 64, got '{threads}'", "--threads")
        fix_index = -1 if fix is None else self.face(fix, "--fix")
        d = _c.compliant_fold(self._p, percent / 100.0, bool(dynamic), fix_index, preset == "physical",
                              None if axial is None else float(axial), None if facet is None else float(facet),
                              None if crease is None else float(crease), None if damping is None else float(damping),
                              float(gravity), int(steps), bool(all_frames), threads=int(threads))
        d["percent"] = float(percent)
        return CompliantFold(d, self)

    def state(self, angles=None, *, fix=None, frame: Optional[int] = None) -> "State":
        """A posed state: fold angles in degrees (closed exactly onto the loop-closure manifold
        when they nearly close, then posed with face fix, default the centre face, where the flat
        sheet has it); or, without angles, frame N of the file (default the pattern's own) as
        `orikin render --frame N` shows it: a folded form's coordinates, a crease pattern posed
        from its edges_foldAngle (face 0 in place), the flat sheet when it has none."""
        if angles is None:
            k = self._p.frame if frame is None else frame
            a, coords, is3d = self._p.frame_state(k, True)
            label = f"frame {k}"
            if is3d or self.is_folded_form or not np.any(a):
                return State(self, a if self.has_fold_angles or is3d else None, coords, label=label)
            try:
                closed, pos = self._p.pose(a, 0)
            except InputError as e:
                if e.status != "ERR_ARGUMENT":
                    raise
                raise _usage(f"{self.source}: frame {k}: its edges_foldAngle are not a folded state (the loops around "
                             "the vertices do not close): fold it with fix, drive and to") from None
            return State(self, closed, pos, label=label)
        fix_index = self.center_face() if fix is None else self.face(fix, "--fix")
        closed, pos = self._p.pose(np.radians(np.asarray(angles, dtype=float)), fix_index)
        return State(self, closed, pos)

    def sequence(self, folds, *, frame: int = 0, collisions: bool = True, clearance: float = 0.0,
                 progress: Progress = None) -> "Record":
        """Run a fold sequence (`orikin sequence`, the folding manager): folds as the SEQ.json
        file lists them ([{"fix": F, "drive": E, "to": DEG, "step": DEG, "lock": [...]}, or
        {"fix": F, "percent": P}], degrees; faces by index, name or "@x,y"), each from the
        geometry the previous one left. The record restores any instant exactly (record.at(t))."""
        doc = {"pattern": self.source, "folds": list(folds)}
        start, coords = self._start(frame, None)
        r = self._p.sequence(json.dumps(doc), start, coords, None, progress)
        record = Record(r, self)
        if collisions:
            record.collide(clearance)
        return record

    def simulate(self, *, fix=None, current: float = 0.0, duration: Optional[float] = None, start=None, targets=None,
                 schedule=None, dt: Optional[float] = None, pulse: Optional[float] = None, frames: int = 101,
                 stops: bool = True, settle: bool = True, current_off_at_target: bool = True,
                 auto_polarity: bool = True, field=None, current_limit=None, gravity=None, damping=None,
                 meters_per_unit=None, materials=None, progress: Progress = None,
                 model: str = "rigid") -> Union[Simulation, "CompliantSimulation"]:
        """Folding dynamics with closed loops (`orikin simulate`): panels with mass, hinge
        moments, Lorentz actuation (current in A through every wire), gravity and damping,
        integrated for duration seconds from the flat sheet (or start: a State). The design comes
        from the FOLD fields (edges_orikin:hinge, faces_orikin:panel, orikin:actuation); field,
        current_limit, gravity, damping and meters_per_unit override them. schedule: the field
        schedule ([{edge, from_rad, field, fold}], e.g. Motion.actuate().schedule, which is what
        the CLI optimises first); None: the file's. targets in degrees (None: +-180 by assignment).

        model='compliant' (the CLI's --model compliant; docs/compliant.md): the panels bend and
        stretch in the bar-and-hinge model with the file's panels, layered hinges and wires, and
        the equilibria are followed as the current ramps from 0 to current and off again. It
        takes fix, current, auto_polarity and the design overrides (field, current_limit, gravity,
        meters_per_unit, materials) and returns a CompliantSimulation; the time options
        (duration, dt, pulse, frames, stops, settle, damping, start, targets, schedule) are the
        rigid model's."""
        if model not in ("rigid", "compliant"):
            raise _usage(f"--model is rigid or compliant, got '{model}'", "--model")
        fix_index = self.center_face() if fix is None else self.face(fix, "--fix")
        if model == "compliant":
            timed = (("--duration", duration is not None), ("--dt", dt is not None), ("--pulse", pulse is not None),
                     ("--frames", frames != 101), ("--no-stops", not stops), ("settle", not settle),
                     ("current_off_at_target", not current_off_at_target), ("--damping", damping is not None),
                     ("--frame", start is not None), ("targets", targets is not None), ("schedule", schedule is not None))
            for name, given in timed:
                if given:
                    raise _usage("--model compliant follows the equilibria as the current ramps up and off: "
                                 f"{name} is the rigid model's", name)
            d = _c.simulate_compliant(self._p, fix_index, float(current), bool(auto_polarity), field=field,
                                      current_limit=current_limit, gravity=gravity, meters_per_unit=meters_per_unit,
                                      materials=None if materials is None else os.fspath(materials))
            return CompliantSimulation(d)
        if duration is None:
            raise _usage("missing --duration S", "--duration")
        start_angles, coords = (None, None)
        if start is not None:
            start_angles, coords = self._start(0, start)
        tg = None if targets is None else np.radians(np.asarray(targets, dtype=float))
        d = _c.simulate(self._p, fix_index, current, duration, start_angles, coords, tg, schedule, dt, pulse, frames,
                        stops, settle, current_off_at_target, auto_polarity, progress, field, current_limit, gravity,
                        damping, meters_per_unit, None if materials is None else os.fspath(materials))
        return Simulation(d)

    # --- pictures and meshes of the pattern itself -------------------------------------------

    def render(self, path=None, **options):
        """Draw the crease pattern (view 'cp', default) or the sheet in 3D: see State.render."""
        options.setdefault("view", "3d" if self.is_folded_form else "cp")
        return self.state().render(path, **options)

    def collide(self, clearance: float = 0.0) -> Collision:
        """Self-collision of the pattern's own coordinates (a folded form): see State.collide."""
        return self.state().collide(clearance)


def _unique(items: list) -> list:
    seen, out = set(), []
    for x in items:
        if x not in seen:
            seen.add(x)
            out.append(x)
    return out


# --- states --------------------------------------------------------------------------------------

_DRAW_KEYS = ("view", "camera", "yaw", "pitch", "roll", "size", "perspective", "edges", "grid", "labels", "shading",
              "front", "back", "background", "texture", "face_orders")


def _draw_kwargs(options: dict) -> dict:
    """The drawing options (render, animate) in the extension's terms (radians, width/height)."""
    unknown = set(options) - set(_DRAW_KEYS) - {"format"}
    if unknown:
        raise TypeError(f"unknown drawing option(s): {', '.join(sorted(unknown))}")
    kw = {}
    for k in ("view", "camera", "perspective", "edges", "grid", "labels", "shading", "front", "back", "background",
              "face_orders"):
        if k in options and options[k] is not None:
            kw[k] = options[k]
    for k in ("yaw", "pitch", "roll"):
        if options.get(k) is not None:
            kw[k + "_rad"] = math.radians(options[k])
    if options.get("size") is not None:
        kw["width"], kw["height"] = (int(v) for v in options["size"])
    tex = options.get("texture")
    if tex is not None and not isinstance(tex, bytes):
        with open(tex, "rb") as f:
            tex = f.read()
    if tex is not None:
        kw["texture"] = tex
    return kw


class State:
    """One state of a pattern: fold angles (radians, per edge; None for a folded form without
    them) and world vertex positions (V, 3). From motion.at(t), motion.frame(k), record.at(t),
    pattern.state(...)."""

    __slots__ = ("pattern", "angles", "positions", "drive", "label")

    def __init__(self, pattern: Pattern, angles, positions, drive: Optional[float] = None, label: str = ""):
        self.pattern = pattern
        self.angles = angles
        self.positions = positions
        self.drive = drive
        self.label = label

    @property
    def angles_deg(self) -> Optional[np.ndarray]:
        """The fold angles in degrees (a copy)."""
        return None if self.angles is None else np.degrees(self.angles)

    def render(self, path=None, *, format: Optional[str] = None, **options):
        """Draw the state (`orikin render`): SVG, PDF or PNG, to path (by its extension) or as
        bytes. Options: view ('3d' or 'cp': the flat crease pattern), camera ('iso', 'top',
        'front', 'side', 'bottom'), yaw / pitch / roll (degrees), perspective, size=(w, h),
        front / back / background colours ('#rrggbb' or a name), texture (a PNG path or bytes),
        edges (F and J edges too), grid, labels (crease view: indices), shading, face_orders
        (FOLD faceOrders triples for faces folded flat onto each other)."""
        kw = _draw_kwargs(options)
        if path is None and format is None:
            format = "png"
        return _c.render(self.pattern._p, self.positions, self.angles, path, format, **kw)

    def export(self, path=None, *, format: Optional[str] = None, thickness: float = 0.0):
        """A mesh of the state (`orikin export`): OBJ, STL, PLY, glTF or GLB, to path (by its
        extension) or as bytes; thickness > 0 makes closed panels for 3D printing."""
        if path is None and format is None:
            format = "glb"
        return _c.export_mesh(self.pattern._p, self.positions, self.angles, path, format, thickness)

    def collide(self, clearance: float = 0.0) -> Collision:
        """Self-collision of the state (`orikin collide`): penetrating and touching face pairs
        and the least clearance between faces sharing no vertex."""
        d = _c.collide(self.pattern._p, self.positions, clearance)
        d["contacts"] = [Contact(c) for c in d["contacts"]]
        return Collision(d)

    def to_fold(self) -> dict:
        """The pattern's FOLD with this state appended as a folded-form frame."""
        angles = np.zeros(self.pattern.edge_count) if self.angles is None else self.angles
        text = self.pattern._p.with_states(self.positions[None], np.asarray(angles)[None],
                                           [self.label] if self.label else None)
        return json.loads(text)

    def __repr__(self) -> str:
        return f"<orikin.State of {self.pattern.source}{': ' + self.label if self.label else ''}>"


# --- the compliant fold --------------------------------------------------------------------------

class CompliantFold(Report):
    """A compliant (bar-and-hinge) fold (`orikin fold --compliant`; Pattern.fold(compliant=True)):
    solver ('static' or 'explicit'), preset, percent, reached, reached_fraction, reason (why not,
    or None), max_strain, energy, crease_error_deg, gradient_norm, load_scale, vertices, bars,
    hinges, triangles, steps and time_step (explicit), newton_iterations, factorizations,
    load_steps (static); arrays (copies): fold_angles (E, radians), strains (E, axial strain
    (L - L0)/L0 per edge), face_energies (F, the strain energy of each face's bars and facet
    hinges), face_strains (F, its largest |strain|), positions (V, 3), frame_fractions (F), frame_times (F:
    the explicit time, 0 for load steps), frame_positions (F, V, 3), frame_angles and frame_strains (F, E):
    one frame per load step (or the explicit time history) with all_frames, else the final state; contacts: faces passing through each other during the fold, [{faces: (a, b),
    step, fraction}] (the CLI's warnings), contacts_truncated."""

    __slots__ = ("pattern",)

    def __init__(self, d: dict, pattern: "Pattern"):
        super().__init__(d)
        object.__setattr__(self, "pattern", pattern)

    @property
    def fold_angles_deg(self) -> np.ndarray:
        """The fold angles in degrees (a copy)."""
        return np.degrees(self._d["fold_angles"])

    def info(self) -> dict:
        """The CLI's --json object (without "file"): fold angles in degrees, arrays as lists."""
        keys = ["model", "solver", "preset", "percent", "reached", "reached_fraction", "max_strain", "energy",
                "crease_error_deg", "gradient_norm", "load_scale", "vertices", "bars", "hinges"]
        keys += ["steps", "time_step"] if self.solver == "explicit" else ["newton_iterations", "load_steps"]
        out = {k: ("compliant" if k == "model" else self._d[k]) for k in keys}
        out["fold_angles_deg"] = self.fold_angles_deg.tolist()
        out["strains"] = self.strains.tolist()
        out["face_energies"] = self.face_energies.tolist()
        out["face_strains"] = self.face_strains.tolist()
        out["contacts"] = [{"faces": list(c["faces"]), "step": c["step"], "fraction": c["fraction"]} for c in self.contacts]
        out["contacts_truncated"] = self.contacts_truncated
        if not self.reached:
            out["reason"] = self.reason
        return out

    def state(self, k: int = -1) -> "State":
        """Frame k (default the final state) as a State (render, export, collide)."""
        f = self._d["frame_fractions"]
        k = k + len(f) if k < 0 else k
        return State(self.pattern, self.frame_angles[k], self.frame_positions[k],
                     label=f"compliant fold: {100 * f[k]:.6g} % of the way to the targets")

    def render(self, path=None, **options):
        """Draw the final state (see State.render)."""
        return self.state().render(path, **options)

    def export(self, path=None, *, format: Optional[str] = None, thickness: float = 0.0):
        """A mesh of the final state (see State.export)."""
        return self.state().export(path, format=format, thickness=thickness)

    def __repr__(self) -> str:
        return (f"<orikin.CompliantFold of {self.pattern.source}: {self.solver}, "
                f"{'reached' if self.reached else 'stopped at'} {100 * self.reached_fraction:.6g} %>")


# --- motions -------------------------------------------------------------------------------------

def _describe(c: "CollisionEvent", with_fold: bool) -> str:
    """A collision as the CLI words it (cli_collision_describe)."""
    verb = {"near": "come closer than the clearance", "touching": "touch (within the clearance)"}.get(
        c.kind, "pass through each other (stacked layers)" if c.stacked else "penetrate")
    fold = f"fold {c.fold + 1}, " if with_fold else ""
    at = f"progress {c.progress:.9f}" if "progress" in c else f"drive {math.degrees(c.drive_rad):.6f} deg"
    x, y, z = c.point
    return f"faces {c.faces[0]} and {c.faces[1]} {verb} at {fold}step {c.step}, {at}, at ({x:.6g}, {y:.6g}, {z:.6g})"


class Motion:
    """A solved fold: its frames (exact states), verdict and reason, the solver's figures.

    motion.angles (frames, E) and motion.vertices (frames, V, 3) are read-only numpy views of
    the library's memory (radians, world coordinates): no copy; they keep the motion alive.
    """

    __slots__ = ("_m", "pattern", "fix_default", "percent", "lock_auto", "symmetric", "collision", "_info")

    def __init__(self, m: _c.Motion, pattern: Pattern, fix_default: bool = False, *, percent=None,
                 lock_auto: bool = False, symmetric: bool = False):
        self._m = m
        self.pattern = pattern
        self.fix_default = fix_default
        self.percent = percent
        self.lock_auto = lock_auto
        self.symmetric = symmetric
        self.collision: Optional[CollisionEvent] = None
        self._info = None

    def _i(self) -> dict:
        if self._info is None:
            self._info = self._m.info()
        return self._info

    # --- what it is -----------------------------------------------------------------------------

    kind = property(lambda self: self._i()["kind"], doc="'drive' (one crease), 'targets' (percent) or 'drives'.")
    fixed_face = property(lambda self: self._i()["fixed_face"], doc="The face held fixed.")
    locked = property(lambda self: [int(e) for e in self._i()["locked"]], doc="The creases held (given and automatic).")
    reason = property(lambda self: self._why(), doc="Why the fold is not valid (one line), or None.")

    @property
    def verdict(self) -> str:
        """'valid', 'invalid assignment', 'not rigidly foldable', 'underdetermined', 'blocked'
        (one drive); 'reached', 'stationary', 'limit', 'singular', 'underdetermined',
        'overdetermined' (several degrees of freedom); 'collision' when the check found one."""
        return "collision" if self.collision is not None else self._i()["verdict"]

    @property
    def valid(self) -> bool:
        """The fold reached its target as assigned, without collision (the CLI's exit 0)."""
        return self._i()["valid"] and self.collision is None

    def _why(self) -> Optional[str]:
        if self.collision is not None:
            return _describe(self.collision, False) + " (the motion stops at the last clean step)"
        return self._i()["reason"]

    @property
    def drive(self) -> Optional[int]:
        """The driven crease (one-drive folds), else None."""
        return self._i().get("drive")

    def info(self) -> dict:
        """Everything the CLI's --json reports about the fold (a dict): verdict, reason, stats,
        split (Frame A / Frame B), blocked, violations, dof, solver, goal_rad, stop_edge ..."""
        d = dict(self._i())
        d["verdict"], d["valid"], d["reason"] = self.verdict, self.valid, self.reason
        d["collision"] = None if self.collision is None else self.collision.as_dict()
        d["fix_default"] = self.fix_default
        return d

    stats = property(lambda self: self._i().get("stats"), doc="Solver statistics (steps, Newton iterations ...).")
    split = property(lambda self: self._i().get("split"), doc="Frame A / Frame B / surrounding of a single vertex, or None.")
    blocked = property(lambda self: self._i().get("blocked"), doc="Where and why a blocked fold stopped, or None.")
    violations = property(lambda self: self._i().get("violations", []), doc="Creases folding against their assignment.")
    dof = property(lambda self: self._i().get("dof"), doc="DOF of the free mechanism at the last frame.")
    solver = property(lambda self: self._i().get("solver"), doc="Which solver ran.")

    @property
    def hint(self) -> Optional[str]:
        """An underdetermined single-drive fold: a lock set that leaves one degree of freedom."""
        if self._i()["verdict"] != "underdetermined" or self.kind != "drive":
            return None
        try:
            locks = [int(e) for e in self._m.lock_suggestion()]
        except Error as e:
            return f"no lock set found ({e.reason})"
        if not locks:
            return "no lock set found (the search locked nothing)"
        return "lock {} more crease{}, e.g. lock={} (or lock='auto')".format(len(locks), "" if len(locks) == 1 else "s",
                                                                           self.locked + locks)

    # --- frames ---------------------------------------------------------------------------------

    @property
    def frame_count(self) -> int:
        """Frames (before the first contact when the motion collides)."""
        return self._m.frame_count

    def __len__(self) -> int:
        return self.frame_count

    @property
    def angles(self) -> np.ndarray:
        """(frames, E) fold angles in radians: a read-only view of the library's memory."""
        return self._m.angles()

    @property
    def angles_deg(self) -> np.ndarray:
        """(frames, E) fold angles in degrees (a copy)."""
        return np.degrees(self._m.angles())

    @property
    def vertices(self) -> np.ndarray:
        """(frames, V, 3) world vertex positions: a read-only view (computed once, then kept)."""
        return self._m.vertices()

    @property
    def drives(self) -> np.ndarray:
        """Per frame: the driven crease's angle in radians (one drive) or the progress 0 to 1."""
        return self._m.drives()

    @property
    def residuals(self) -> np.ndarray:
        """Per frame: the loop-closure residual (at most 1e-10)."""
        return self._m.residuals()

    def frame(self, k: int) -> State:
        """Frame k as a State (views of the frame's rows)."""
        return State(self.pattern, self.angles[k], self.vertices[k], float(self.drives[k]), f"frame {k}")

    def at(self, t: float) -> State:
        """The exact state at fraction t (0 to 1) of the motion: a single drive solved again
        from the frame before (as a sequence restores an instant), several degrees of freedom
        interpolated between frames and closed onto the loop-closure manifold."""
        angles, pos, x = self._m.at(float(t))
        return State(self.pattern, angles, pos, x, f"t = {t:g}")

    def end_effector(self, k: int = -1) -> Optional[tuple]:
        """The end effector of a single-vertex fold at frame k in Frame A and Frame B, or None."""
        return self._m.end_effector(k)

    def other_branch(self, k: int = -1) -> Optional[np.ndarray]:
        """The closed form's other solution at frame k (radians per edge), or None."""
        return self._m.other_branch(k)

    @property
    def creases(self) -> list:
        """Several degrees of freedom: per moving crease {edge, start_deg, goal_deg,
        reached_deg, fraction} (how far each got toward its goal)."""
        goal = self._i().get("goal_rad")
        if goal is None or self.frame_count == 0:
            return []
        a0, a1 = self.angles[0], self.angles[-1]
        out = []
        for e in range(len(goal)):
            span = goal[e] - a0[e]
            if abs(span) <= 1e-12 and abs(a1[e] - a0[e]) <= 1e-9:
                continue
            frac = (a1[e] - a0[e]) / span if abs(span) > 1e-12 else 0.0
            out.append({"edge": e, "start_deg": math.degrees(a0[e]), "goal_deg": math.degrees(goal[e]),
                        "reached_deg": math.degrees(a1[e]), "fraction": frac})
        return out

    # --- checks and outputs ---------------------------------------------------------------------

    def collide(self, clearance: float = 0.0, *, progress: Progress = None) -> Optional[CollisionEvent]:
        """Check every step for self-collision (fold() does unless collisions=False): the first
        contact, located by bisection, or None. Afterwards the motion shows the frames before it."""
        ev = self._m.collide(clearance, progress)
        self.collision = None if ev is None else CollisionEvent(ev)
        return self.collision

    def render(self, path=None, *, t: Optional[float] = None, frame: int = -1, **options):
        """Draw a state of the motion (the last frame by default; t: the exact state at t)."""
        return (self.at(t) if t is not None else self.frame(frame)).render(path, **options)

    def animate(self, path=None, *, fps: float = 15.0, hold: float = 1.0, loop: bool = True,
                progress: Progress = None, **options):
        """The motion as an animated GIF (`orikin animate`), every frame exact: to path or bytes."""
        kw = _draw_kwargs(options)
        return _c.animate(self.pattern._p, self.vertices, self.angles, path, fps, hold, loop, progress, **kw)

    def export(self, path=None, *, format: Optional[str] = None, animate: bool = False, thickness: float = 0.0,
               t: Optional[float] = None, frame: int = -1):
        """A mesh of a state, or with animate=True the whole motion as a glTF animation (one
        node per face, keyframes from the exact face poses, one second for the motion)."""
        if not animate:
            return (self.at(t) if t is not None else self.frame(frame)).export(path, format=format, thickness=thickness)
        d = self.drives
        n = self.frame_count
        times = (d - d[0]) / (d[-1] - d[0]) if n > 1 and d[-1] != d[0] else np.linspace(0.0, 1.0, n)
        poses = np.stack([self._m.face_poses(k) for k in range(n)])
        if path is None and format is None:
            format = "glb"
        return _c.export_mesh(self.pattern._p, self.vertices[-1], self.angles[-1], path, format, thickness,
                              np.ascontiguousarray(times), poses)

    def to_fold(self) -> dict:
        """The pattern's FOLD with every frame appended as a folded-form frame (the CLI's
        -o OUT.fold); a motion that stops short is marked "orikin:partial"."""
        n = self.frame_count
        if self.kind == "drive":
            titles = [f"fold crease {self.drive}: {math.degrees(x):g} deg" for x in self.drives]
        else:
            titles = [f"{'fold toward the targets' if self.kind == 'targets' else 'drives'}: {100 * x:.6g} % of the way"
                      for x in self.drives]
        custom = None
        if not self.valid and n > 0:
            custom = {"orikin:partial": json.dumps({"verdict": self.verdict, "reason": self.reason or "", "frames": n})}
        return json.loads(self.pattern._p.with_states(self.vertices, self.angles, titles, custom))

    def save(self, path: Union[str, os.PathLike]) -> None:
        """Write to_fold() to path (FOLD)."""
        with open(path, "w") as f:
            json.dump(self.to_fold(), f)

    def actuate(self, *, schedule: str = "auto", reorientations: int = -1, field=None, current_limit=None,
                gravity=None, damping=None, meters_per_unit=None, materials=None,
                progress: Progress = None) -> Actuation:
        """Size the hinges and the Lorentz actuation along this fold (`orikin actuate`): per
        hinge the moments, the current it needs, springback, optimal thickness and width range;
        the field schedule (optimised with one reorientation by default, as the thesis does)."""
        return _actuate(self._m, schedule, reorientations, progress, field, current_limit, gravity, damping,
                        meters_per_unit, materials)

    def __repr__(self) -> str:
        return f"<orikin.Motion {self.kind}: {self.verdict}, {self.frame_count} frames>"


def _actuate(fold, schedule, reorientations, progress, field, current_limit, gravity, damping, meters_per_unit,
             materials) -> Actuation:
    d = _c.actuate(fold, schedule, reorientations, progress, None if field is None else np.asarray(field, float),
                   current_limit, gravity, damping, meters_per_unit, None if materials is None else os.fspath(materials))
    d["hinges"] = [Report(h) for h in d["hinges"]]
    return Actuation(d)


class Record:
    """A fold sequence run (the folding manager): every recorded state, any instant restored.

    record.angles (states, E) and record.vertices (states, V, 3) are read-only views of the
    record; times are the sequence time T (fold k + 1 runs over [k, k + 1])."""

    __slots__ = ("_r", "pattern", "collision", "_info")

    def __init__(self, r: _c.Record, pattern: Pattern):
        self._r = r
        self.pattern = pattern
        self.collision: Optional[CollisionEvent] = None
        self._info = r.info()

    @classmethod
    def load(cls, path: Union[str, os.PathLike], *, collisions: bool = True, clearance: float = 0.0,
             progress: Progress = None) -> "Record":
        """Run a SEQ.json file: {"pattern": FILE.fold (relative to it), "frame": N, "folds": [...]}."""
        path = os.fspath(path)
        _, pattern_path, frame = _c.sequence_file(path)  # the library's reader: the CLI's messages
        with open(path, encoding="utf-8-sig") as f:
            text = f.read()  # as written: faces and creases by name or point are resolved below
        pat = Pattern.load(os.path.join(os.path.dirname(path), pattern_path))
        start, coords = pat._start(frame, None)
        r = cls(pat._p.sequence(text, start, coords, path, progress), pat)
        if collisions:
            r.collide(clearance)
        return r

    frame_count = property(lambda self: self._r.frame_count, doc="Recorded states (before the first contact).")
    times = property(lambda self: self._r.times, doc="Sequence time T of every state.")
    folds = property(lambda self: self._r.folds, doc="Fold (0-based) of every state.")
    drives = property(lambda self: self._r.drives, doc="Driven crease angle (radians) or progress of every state.")
    residuals = property(lambda self: self._r.residuals, doc="Loop-closure residual of every state.")
    duration = property(lambda self: self._info["duration"], doc="The number of completed folds (the end of time).")
    failed_fold = property(lambda self: self._info["failed_fold"], doc="The first fold that is not valid, or None.")
    completed_folds = property(lambda self: self._info["completed_folds"], doc="Folds completed validly.")

    @property
    def verdict(self) -> str:
        """'valid', the failing fold's verdict, or 'collision'."""
        return "collision" if self.collision is not None else self._info["verdict"]

    @property
    def valid(self) -> bool:
        """Every fold completed, without collision."""
        return self._info["valid"] and self.collision is None

    @property
    def reason(self) -> Optional[str]:
        """Why the sequence is not valid (the failing fold's reason, or the collision), or None."""
        if self.collision is not None:
            return _describe(self.collision, True) + f", t = {self.collision.time:.9g} (the motion stops at the last clean step)"
        return self._info["reason"]

    @property
    def angles(self) -> np.ndarray:
        """(states, E) fold angles in radians: a read-only view of the record."""
        return self._r.angles()

    @property
    def angles_deg(self) -> np.ndarray:
        """(states, E) fold angles in degrees (a copy)."""
        return np.degrees(self._r.angles())

    @property
    def vertices(self) -> np.ndarray:
        """(states, V, 3) world vertex positions: a read-only view of the record."""
        return self._r.vertices()

    def info(self) -> dict:
        """Everything `orikin sequence --json` reports about the run (a dict): verdict, reason,
        failed_fold, completed_folds, partial_frames, duration, the folds."""
        d = dict(self._info)
        d["verdict"], d["valid"], d["reason"] = self.verdict, self.valid, self.reason
        d["collision"] = None if self.collision is None else self.collision.as_dict()
        return d

    def at(self, t: float) -> State:
        """The state at sequence time t (0 <= t <= duration), solved exactly, not interpolated."""
        angles, pos, drive, fold = self._r.at(float(t))
        return State(self.pattern, angles, pos, drive, f"t = {t:g}")

    def collide(self, clearance: float = 0.0, *, progress: Progress = None) -> Optional[CollisionEvent]:
        """Check every recorded step for self-collision (Record.load and Pattern.sequence do
        unless collisions=False): the first contact, or None; afterwards the record shows the
        states before it."""
        ev = self._r.collide(clearance, progress)
        self.collision = None if ev is None else CollisionEvent(ev)
        return self.collision

    def render(self, path=None, *, t: Optional[float] = None, **options):
        """Draw the instant t (default: the end)."""
        return self.at(self.duration if t is None else t).render(path, **options)

    def animate(self, path=None, *, fps: float = 15.0, hold: float = 1.0, loop: bool = True,
                progress: Progress = None, **options):
        """The recorded states as an animated GIF (`orikin animate SEQ.json`): to path or bytes."""
        kw = _draw_kwargs(options)
        return _c.animate(self.pattern._p, self.vertices, self.angles, path, fps, hold, loop, progress, **kw)

    def export(self, path=None, *, format: Optional[str] = None, thickness: float = 0.0, t: Optional[float] = None):
        """A mesh of the instant t (default: the end); see State.export."""
        return self.at(self.duration if t is None else t).export(path, format=format, thickness=thickness)

    def to_fold(self) -> dict:
        """The pattern's FOLD with every recorded state appended (`orikin sequence -o`)."""
        titles = [f"t = {t:.6g}" for t in self.times]
        return json.loads(self.pattern._p.with_states(self.vertices, self.angles, titles))

    def actuate(self, *, schedule: str = "auto", reorientations: int = -1, field=None, current_limit=None,
                gravity=None, damping=None, meters_per_unit=None, materials=None,
                progress: Progress = None) -> Actuation:
        """Size hinges and actuation along the whole sequence (see Motion.actuate)."""
        return _actuate(self._r, schedule, reorientations, progress, field, current_limit, gravity, damping,
                        meters_per_unit, materials)

    def to_json(self) -> str:
        """The sequence as SEQ.json text (degrees)."""
        return self._r.to_json()

    def __repr__(self) -> str:
        return f"<orikin.Record: {self.verdict}, {self.completed_folds} folds, {self.frame_count} states>"


# --- layers --------------------------------------------------------------------------------------

class LayerState:
    """One flat-folded state: face_orders (FOLD faceOrders (n, 3)), folded (V, 2) vertex
    positions, flipped (F,) faces face-down, svg (a drawing) and to_fold()."""

    __slots__ = ("index", "face_orders", "folded", "flipped", "svg", "_fold")

    def __init__(self, index, face_orders, folded, flipped, svg, fold_text):
        self.index, self.face_orders, self.folded, self.flipped, self.svg = index, face_orders, folded, flipped, svg
        self._fold = fold_text

    def to_fold(self) -> dict:
        """The pattern's FOLD with this state appended as a foldedForm frame (`orikin layers -o`)."""
        return json.loads(self._fold)


class Layers:
    """Every flat-folded state of a pattern (`orikin layers`), counted exactly."""

    __slots__ = ("_l", "pattern")

    def __init__(self, l: _c.Layers, pattern: Pattern):
        self._l = l
        self.pattern = pattern

    @property
    def count(self) -> int:
        """The number of flat-folded states (exact, however large; a lower bound when limited)."""
        return self._l.states()

    @property
    def satisfiable(self) -> bool:
        """False once no flat-folded state is known to exist (then conflict says why)."""
        return self._l.info()["satisfiable"]

    @property
    def limited(self) -> bool:
        """Some component reached the limit: count is a lower bound."""
        return self._l.info()["limited"]

    @property
    def components(self) -> list:
        """Per independent component (the fixed part first): (states, variables)."""
        return self._l.components()

    @property
    def conflict(self) -> Optional[Report]:
        """Why there is no state (constraint, faces, detail ...), or None."""
        c = self._l.conflict()
        return None if c is None else Report(c)

    def info(self) -> Report:
        """Problem sizes: faces, variables (overlapping face pairs), constraints, cells ..."""
        return Report(self._l.info())

    def state(self, k: int = 0) -> LayerState:
        """State k (0 <= k < count), as `orikin layers --state K` numbers them."""
        self._l.select(int(k))
        folded, flipped = self._l.folded()
        return LayerState(k, self._l.face_orders(), folded, flipped, self._l.svg(), self._l.to_fold_text())

    def __repr__(self) -> str:
        return f"<orikin.Layers of {self.pattern.source}: {self.count} states>"


# --- module-level functions ------------------------------------------------------------------------

def load(path, *, frame: int = 0, weld: bool = False) -> Pattern:
    """Pattern.load."""
    return Pattern.load(path, frame=frame, weld=weld)


def generate(kind: str, *, rows: Optional[int] = None, cols: Optional[int] = None, sides: Optional[int] = None,
             angle: Optional[float] = None, width: Optional[float] = None, height: Optional[float] = None,
             twist_size: Optional[float] = None, bistable_height: Optional[bool] = None) -> Pattern:
    """A tessellation (`orikin generate`): 'miura', 'yoshimura', 'waterbomb', 'square-twist',
    'kresling'; angle in degrees (Miura's acute cell angle, ...); docs/generators.md."""
    return Pattern(_c.generate(kind, rows, cols, sides, None if angle is None else math.radians(angle), width, height,
                               twist_size, bistable_height))


def axiom(n: int, *, p1=None, p2=None, l1=None, l2=None) -> list:
    """Every fold line of Huzita–Hatori axiom n (1-7) as ((x, y), (dx, dy)); points are (x, y),
    lines ((x, y), (dx, dy)). Axiom 5 gives 0-2 lines, 6 gives 0-3, 7 gives 0-1."""
    return _c._axiom(n, p1, p2, l1, l2)


def unfold(source=None, *, vertices=None, faces=None, hull: bool = False, tries: int = 50, seed: int = 1,
           all: bool = False, develop: bool = False, tolerance: float = 0.0) -> Net:
    """A polyhedral surface (an OBJ, STL or FOLD file, or vertices (n, 3) and faces) cut into a
    net that folds back (`orikin unfold`); develop=True unfolds a folded form into its crease
    pattern without cuts (tolerance in degrees); hull=True takes the points' convex hull."""
    p, d = _c.unfold(source, vertices, faces, hull, tries, seed, all, develop, math.radians(tolerance))
    d["pattern"] = Pattern(p)
    return Net(d)


def unfold_linkage(coords, edges, *, steps_per_event: int = 8, max_events: int = 0) -> LinkageMotion:
    """Straighten a planar chain or convexify a polygon without self-intersection (Streinu's
    expansive motions; `orikin unfold-linkage`)."""
    return LinkageMotion(_c.unfold_linkage(coords, edges, steps_per_event, max_events))
