"""Design search (SPEC item 22): an environment that adds one crease per step and says whether the
pattern still folds rigidly, how many degrees of freedom it has and whether it collides — the loop
a reinforcement-learning (gym) environment or a search needs, one call into the library per step.
"""

from __future__ import annotations

import math
from typing import Any, Callable, Optional, Union

from . import _orikin as _c
from ._api import InputError, Pattern, StepResult

Action = Union[dict, tuple, list]


def default_reward(result: StepResult) -> float:
    """+1 for a crease that keeps the pattern rigidly foldable without collision, -1 otherwise
    (including a crease that missed the sheet)."""
    if not result.applied:
        return -1.0
    return 1.0 if result.rigid_foldable and not result.collides else -1.0


class DesignEnv:
    """Add creases to a sheet one step at a time and judge the pattern after each.

        env = orikin.DesignEnv(orikin.Pattern.square(4))
        r = env.step({"line": ((0, 0), (4, 4)), "assignment": "V"})
        r.rigid_foldable, r.dof, r.collides        # True, 1, False
        obs, reward, terminated, truncated, info = r.astuple()

    An action is a dict:
      {"line": ((x0, y0), (x1, y1))}                       the line through two points
      {"axiom": n, "p1": ..., "p2": ..., "l1": ..., "l2": ..., "solution": 0}
                                                           a Huzita-Hatori fold line (orikin.axiom)
    with optional "assignment" ('M', 'V', 'F', 'U'; default the env's), "face" (index, name or
    point: crease only that face; default every face the line crosses) and "segment" (True:
    only between the two points); or a 4-sequence (x0, y0, x1, y1): a line.

    Each step adds the crease (a new pattern; the old one is kept by whoever holds it), then
    folds the pattern toward its targets (every crease to +-180 by its assignment, `percent` of
    the way, from the flat sheet with the face `fix` held, default the centre face; at most
    `max_steps` continuation steps, so that a fold creeping toward a stationary point stops in
    milliseconds) and judges: rigid_foldable (the mechanism has a motion and the fold takes it,
    every crease as assigned), progress (how far it got, 0 to 1), dof (the degrees of freedom
    along that motion: the rank count of the loop-closure Jacobian half way, a regular state;
    when the fold does not move, the generic probe at the flat sheet, within probe_budget
    solves; None when undetermined), collides (self-collision along that fold, located to
    1e-6). A crease that misses the sheet leaves the pattern unchanged (applied False).

    terminated: the step left the pattern not rigidly foldable or colliding (when
    terminate_on_failure); truncated: max_creases reached. reward(result) -> float (default
    default_reward).
    """

    def __init__(self, sheet: Union[Pattern, float, Any] = 1.0, *, assignment: str = "V", fix=None,
                 percent: float = 100.0, step: float = 10.0, collisions: bool = True, clearance: float = 0.0,
                 probe: bool = True, probe_budget: int = 32, max_steps: int = 2000,
                 max_creases: Optional[int] = None, terminate_on_failure: bool = True,
                 reward: Callable[[StepResult], float] = default_reward):
        if isinstance(sheet, Pattern):
            self.sheet = sheet
        elif isinstance(sheet, (int, float)):
            self.sheet = Pattern.square(float(sheet))
        else:
            self.sheet = Pattern.sheet(sheet)
        if not (0.0 <= percent <= 100.0):
            raise ValueError(f"percent must be from 0 to 100, got {percent:g}")
        self.assignment = assignment
        self.fix = fix
        self.fraction = percent / 100.0
        self.step_rad = math.radians(step)
        self.collisions = collisions
        self.clearance = clearance
        self.probe = probe
        self.probe_budget = probe_budget
        self.max_steps = max_steps
        self.max_creases = max_creases
        self.terminate_on_failure = terminate_on_failure
        self.reward = reward
        self.pattern = self.sheet
        self.steps = 0
        self.history: list = []

    def reset(self) -> Pattern:
        """Back to the blank sheet; returns it (the first observation)."""
        self.pattern = self.sheet
        self.steps = 0
        self.history = []
        return self.pattern

    def _line(self, action: Action) -> tuple:
        """(a, b, assignment, face, segment) of an action."""
        if not isinstance(action, dict):
            x0, y0, x1, y1 = (float(v) for v in action)
            return (x0, y0), (x1, y1), self.assignment, -1, False
        asg = action.get("assignment", self.assignment)
        face = action.get("face")
        f = -1 if face is None else self.pattern.face(face, "--face")
        segment = bool(action.get("segment", False))
        if "line" in action:
            a, b = action["line"]
            return tuple(a), tuple(b), asg, f, segment
        if "axiom" in action:
            lines = _c._axiom(int(action["axiom"]), action.get("p1"), action.get("p2"), action.get("l1"),
                              action.get("l2"))
            k = int(action.get("solution", 0))
            if not 0 <= k < len(lines):
                return None, None, asg, f, segment  # no such solution: the step adds nothing
            (px, py), (dx, dy) = lines[k]
            return (px, py), (px + dx, py + dy), asg, f, segment
        raise ValueError("an action is {'line': (a, b)} or {'axiom': n, ...} (or x0, y0, x1, y1)")

    def step(self, action: Action) -> StepResult:
        """Add the action's crease and judge the pattern (see the class)."""
        a, b, asg, face, segment = self._line(action)
        fix = -1
        if self.fix is not None:
            fix = self.pattern.face(self.fix, "--fix")
        if a is None:
            info = {"applied": False, "error": "the axiom has no such solution", "edges": [], "creases": None,
                    "rigid_foldable": False, "dof": None, "flat_dof": None, "verdict": None, "progress": 0.0,
                    "against_assignment": 0, "against_edge": None, "collides": False, "collision_checked": False,
                    "collision": None}
            new = None
        else:
            new, info = _c.design_step(self.pattern._p, a, b, asg, face, not segment, fix, self.fraction, self.step_rad,
                                       self.collisions, self.clearance, self.probe, self.max_steps, self.probe_budget)
        self.steps += 1
        if new is not None:
            self.pattern = Pattern(new)
            self.history.append(action)
        failed = info["applied"] and (not info["rigid_foldable"] or info["collides"])
        info["pattern"] = self.pattern
        info["terminated"] = bool(self.terminate_on_failure and failed)
        info["truncated"] = bool(self.max_creases is not None and len(self.history) >= self.max_creases)
        result = StepResult(info)
        info["reward"] = float(self.reward(result))
        return result


__all__ = ["DesignEnv", "default_reward", "InputError"]
