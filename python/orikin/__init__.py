"""orikin: origami kinematics — crease patterns as closed-loop rigid multibody systems.

The library's exact C core (liborikin) with numpy arrays::

    import orikin, numpy as np
    p = orikin.Pattern.load("examples/patterns/open-corner.fold")
    m = p.fold(fix=4, drive=12, lock=[11], to=90)
    np.degrees(m.angles[-1, [8, 9]])        # 35.26..., 60.0 (the thesis' open corner)

Angles you pass are degrees (as on the command line and in FOLD files: positive = valley);
arrays handed out are radians, views of the library's memory (read-only, no copy). Errors are
orikin.InputError (bad input: the CLI's one-line message and the FOLD index), orikin.SolveError
(a solver that failed), orikin.Cancelled (a progress callback said stop). docs/python.md has
the guide.
"""

from ._api import (Actuation, Cancelled, CheckReport, Collision, CollisionEvent, CompliantFold, CompliantSimulation,
                   Contact, DofReport, Error,
                   InputError, Layers, LayerState, LinkageMotion, Motion, Net, Pattern, Record, Regularization,
                   Report, Simulation, SolveError, State, StepResult, VertexReport, Violation, axiom, generate, load,
                   unfold, unfold_linkage)
from ._orikin import version
from .design import DesignEnv, default_reward

__version__ = version()

__all__ = ["Actuation", "Cancelled", "CheckReport", "Collision", "CollisionEvent", "CompliantFold", "CompliantSimulation",
           "Contact", "DesignEnv",
           "DofReport", "Error", "InputError", "LayerState", "Layers", "LinkageMotion", "Motion", "Net", "Pattern",
           "Record", "Regularization", "Report", "Simulation", "SolveError", "State", "StepResult", "VertexReport",
           "Violation", "axiom", "default_reward", "generate", "load", "unfold", "unfold_linkage", "version"]
