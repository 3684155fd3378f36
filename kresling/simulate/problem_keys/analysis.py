"""``[analysis]``: the method (a path followed by displacement or force control, MGDCM or
a fold, vibration modes, or a motion in time) and its settings, and an optional monitor
(``[analysis.stop]``). Each method reads its own settings
(:mod:`kresling.simulate.methods`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling import _core
from kresling.simulate.fold_plan import FOLD_TOLERANCE_DEG
from kresling.simulate.methods import method_names, method_named
from kresling.simulate.problem_keys import ProblemKey
from kresling.simulate.problem_table import AXES, count, node_list, positive, quantity, string

__all__ = ["KEY", "Analysis", "MonitorStop", "default_tolerance", "RELATIVE_TOLERANCE",
           "MERLIN2_TOLERANCE"]

#: The solvers' defaults, as the core declares them (MGDCM's hold every one of these).
_MGDCM = _core.solvers.MgdcmOptions()
#: Newton's default tolerance on the correction's 2-norm, as a fraction of the model's size
#: (the diagonal of the pattern's bounding box, in mm): 1e-6 mm on a 100 mm pattern, the
#: same number of digits at any scale. An explicit ``tolerance`` [mm] replaces it.
RELATIVE_TOLERANCE = 1e-8
#: MERLIN2's own Newton tolerance [mm], the default under merlin2_compat.
MERLIN2_TOLERANCE = 1e-6


@dataclass(frozen=True)
class MonitorStop:
    """Stop once ``|u|`` of ``node`` along ``axis`` exceeds ``beyond`` [mm]."""

    node: int
    axis: str
    beyond: float

    @property
    def dof(self) -> int:
        return 3 * self.node + AXES[self.axis]


@dataclass(frozen=True)
class Analysis:
    """The analysis and its settings (see :func:`kresling.simulate.simulate`); a method
    reads the settings that are its own (the others keep these defaults)."""

    method: str
    steps: int | None = None
    initial_load_factor: float = _MGDCM.initial_load_factor
    max_increments: int = _MGDCM.max_increments
    max_load_factor: float = _MGDCM.max_load_factor
    stop: MonitorStop | None = None
    tolerance: float = _MGDCM.tolerance
    max_iterations: int = _MGDCM.max_iterations
    #: Displacement control and fold: "fixed" (equal increments, MERLIN2's step control
    #: under merlin2_compat) or "adaptive" (the same samples, increments by an error
    #: estimate).
    increments: str = "fixed"
    #: Displacement control with fixed increments: each increment's Newton start, one of
    #: PREDICTORS ("previous": the last equilibrium, as MERLIN2; the others extrapolate the
    #: path through the last equilibria; a start other than "previous" uses bisection, not
    #: MERLIN2's step control, under merlin2_compat).
    predictor: str = "previous"
    #: ``method = "fold"``: where the fold's equilibrium path ends, snap to a stable state
    #: and fold on (:func:`kresling.solvers.solve_fold`'s ``snap``).
    snap: bool = False
    #: ``method = "fold"``: fold through stable states only, relaxing an increment whose
    #: equilibrium is unstable or not found (:func:`kresling.solvers.solve_fold`'s
    #: ``relax``); None: the default, on with Origami Simulator's material (a preset), off
    #: with a material of the problem's own.
    relax: bool | None = None
    #: ``method = "fold"``: every target fold angle is scaled by fold_percent / 100.
    fold_percent: float = 100.0
    #: ``method = "fold"``: a driven crease farther than this from its target at the end
    #: [deg] makes the fold fall short (not completed).
    target_tolerance_deg: float = FOLD_TOLERANCE_DEG
    #: ``method = "modes"``: how many of the lowest modes, about which state: "rest" or a
    #: :class:`~kresling.simulate.methods.modes.LoadedState`.
    modes: int = 10
    about: object = "rest"


def read_analysis(t, context) -> dict:
    name = t.get("method", string, required=True, choices=method_names())
    method = method_named(name)
    settings = {"method": name,
                "tolerance": t.get("tolerance", positive, None),
                "max_iterations": t.get("max_iterations", count, _MGDCM.max_iterations)}
    settings.update(method.read_settings(t))
    if method.monitors and t.has("stop"):
        sub = t.table("stop")
        node = node_list(sub, context.num_nodes)
        if len(node) != 1:
            sub.fail("nodes", "must name one node")
        settings["stop"] = MonitorStop(node[0], sub.get("axis", string, required=True,
                                                        choices=tuple(AXES)),
                                       sub.get("beyond", quantity, required=True,
                                               allowed="a displacement magnitude [mm]"))
        sub.finish()
    t.finish()
    if settings["tolerance"] is None:
        settings["tolerance"] = default_tolerance(context.pattern, context.merlin2_compat)
    return {"analysis": Analysis(**settings)}


def default_tolerance(pattern, compat: bool) -> float:
    """Newton's tolerance [mm] when the problem gives none: MERLIN2's 1e-6 mm under
    merlin2_compat, else :data:`RELATIVE_TOLERANCE` times the pattern's size (the
    diagonal of its bounding box [mm])."""
    if compat:
        return MERLIN2_TOLERANCE
    size = float(np.linalg.norm(np.ptp(pattern.vertices, axis=0)))
    return RELATIVE_TOLERANCE * size if size > 0 else MERLIN2_TOLERANCE


KEY = ProblemKey("analysis", rank=60, read=read_analysis, required=True,
                 allowed="a table with the method")
