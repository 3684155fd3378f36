"""A problem's run along its path: the problem, its model, the path, and what the run
records of it (history.csv's columns, summary.json, a fold's report)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling.model import PatternModel
from kresling.model.fold_angles import fold_angles_deg
from kresling.simulate.element_histories import ElementHistories, element_histories
from kresling.simulate.fold_plan import FOLD_TOLERANCE_DEG, FoldPlan
from kresling.simulate.problem_keys import problem_keys
# The package, folding by sensitivities read when first used (a path needs none of it).
from kresling import solvers
from kresling.solvers import PathResult

__all__ = ["Simulation", "PathState", "FOLD_TOLERANCE_DEG", "largest_bar_strain"]

#: A fold reaches its end when every driven crease is within this many degrees of its
#: target fold angle there (``short_of_target`` counts the others).


@dataclass(frozen=True)
class PathState:
    """What a stopping rule sees after each accepted increment.

    Attributes
    ----------
    step : int
        1-based number of the increment.
    load_factor : float
        Load factor (force control, MGDCM) or fraction of the prescribed motion.
    displacement : ndarray, shape (N, 3)
        Displacement of every node [mm].
    """

    step: int
    load_factor: float
    displacement: np.ndarray


@dataclass(frozen=True)
class Simulation:
    """A problem, its model and the path it followed.

    Attributes
    ----------
    problem : Problem
    pattern_model : PatternModel
        The model with its supports; ``pattern_model.model`` is what was solved.
    path : PathResult
    driven_dofs : ndarray of int
        Displacement control: the driven DOFs (``path.constraint_dofs``); otherwise the
        DOFs that carry a force.
    fold : FoldPlan or None
        ``method = "fold"``: the stages, the driven hinges and their targets.
    interrupted : str
        The signal ("SIGINT", "SIGTERM") that ended the path early, keeping the increments
        before it; "" if none did.
    advice : str
        A fold with a material of its own whose path stopped early: that Origami
        Simulator's material goes on past that point, when a second fold with it shows so.
    stall : str
        A fold whose path ended early: why, measured at its last equilibrium (a limit point,
        the panel triangle squashed furthest, where the energy leads past it); "" otherwise.
    """

    problem: object
    pattern_model: PatternModel
    path: PathResult
    driven_dofs: np.ndarray
    fold: FoldPlan | None = None
    interrupted: str = ""
    #: A fold that stalled with a material of its own: where Origami Simulator's goes on.
    advice: str = ""
    #: A fold whose path ended early: why, measured where it ended
    #: (:func:`kresling.simulate.fold_stall.fold_stall`).
    stall: str = ""

    @property
    def model(self):
        return self.pattern_model.model

    def model_at(self, step: int = -1):
        """The model the path's ``step`` (0-based, negative from the end) is an equilibrium
        of: a fold's driven hinges at the rest angles reached there
        (:func:`kresling.solvers.fold_model_at`), otherwise the model as built. Its tangent
        at ``path.displacement[step]`` is the state's (vibration modes, stability)."""
        load_factor = float(self.path.load_factor[step])  # an IndexError names a bad step
        if self.fold is None:
            return self.model
        return solvers.fold_model_at(self.model, self.fold.stages, load_factor)

    @property
    def completed(self) -> bool:
        """Whether the run reached its end: the path ran to it and, for a fold, every
        driven crease is within the analysis's ``target_tolerance_deg`` (default
        :data:`FOLD_TOLERANCE_DEG`) of its target there."""
        return self.path.completed and not self.interrupted and not self._fold_shortfall()

    @property
    def message(self) -> str:
        """Why the run did not reach its end ("" when it did)."""
        if self.interrupted:
            return (f"interrupted ({self.interrupted}) after {self.path.num_steps} increments: "
                    "the path so far is kept")
        message = self.path.message or self._fold_shortfall()
        if message and self.fold is not None:   # a fold that stopped early or fell short
            message += self._closure_note()
        return "; ".join(part for part in (message, self.stall, self.advice) if part)

    def _fold_shortfall(self) -> str:
        """For a fold whose path ran to its end: which creases fell short, in words."""
        report = self.fold_report() if self.fold is not None else {}
        short = report.get("short_of_target", 0)
        if not short:
            return ""
        worst = report["worst"]
        return (f"the fold ran to its end but {short} of {report['creases_driven']} driven "
                f"creases are more than {report['tolerance_deg']:g} deg from their targets (held "
                f"back by the structure or by their laws' limits); the farthest, hinge "
                f"{worst['hinge']}, reached {worst['fold_angle_deg']:.4g} deg of "
                f"{worst['target_deg']:.4g} deg")

    def _closure_note(self) -> str:
        """Where the targets cannot all be reached with rigid panels, that, in words (from
        the plan: nothing of the path is evaluated again)."""
        closure = self.fold.closure
        words = (closure.words(self.problem.analysis.target_tolerance_deg,
                               "whose creases are all driven") if closure is not None else "")
        return (f"; the targets are {words}: only panels that bend or stretch can reach them"
                if words else "")

    def element_histories(self) -> ElementHistories:
        """Per-element and per-family histories along the path (see
        :func:`kresling.simulate.element_histories`)."""
        return element_histories(self.pattern_model, self.path)

    def history_columns(self) -> dict:
        """The columns of ``history.csv``: step, load_factor, the driven DOFs' reactions
        (displacement control: the force the structure exerts on each driven DOF, -f_int,
        as MERLIN2 reports it [N]), the stored energy by family [N*mm] and Newton iterations.
        """
        path = self.path
        columns = {"step": np.arange(1, path.num_steps + 1), "load_factor": path.load_factor}
        columns.update(self.problem.method.history_columns(self))
        energies = self.element_histories().energy_by_family()
        # The model's other families (cables, springs, ...) that it holds any of: their
        # energies as the solver recorded them, and in the total.
        for name in path.families:
            if name not in ("bars", "hinges") and _holds_elements(self.model.family(name)):
                energies[name] = path.energy_of(name)
                energies["total"] = energies["total"] + energies[name]
        energies["total"] = energies.pop("total")
        for key in problem_keys():   # the columns of keys such as [contact]
            if key.history is not None:
                columns.update(key.history(self))
        for name, values in energies.items():
            columns[f"energy_{name}"] = values
        columns["iterations"] = path.iterations
        return columns

    def write(self, directory, *, view=True, every=None) -> dict:
        """Write history.csv, displacements.csv, path.fold, summary.json (and view.html)
        into ``directory``, keeping every ``every``-th increment (the last always; default:
        the problem's ``[output] every``); returns the paths written by name."""
        from kresling.simulate.outputs import write_outputs

        return write_outputs(self, directory, view=view, every=every)

    def fold_report(self) -> dict:
        """``method = "fold"``: how far the driven creases got. ``short_of_target`` counts
        the creases more than ``tolerance_deg`` (the analysis's ``target_tolerance_deg``,
        1 deg unless set) from their target fold angle at the end (held at their
        law's limit, by the structure, or by a path that stopped), ``worst`` names the
        farthest (angles compared on the circle: -164 deg is 16 deg from 180 deg);
        ``left_branch`` counts those folded the other way from their target (past flat on
        the other side, farther from the target than flat is);
        ``snaps`` the fold fractions (the steps' load factors) where the fold snapped."""
        plan = self.fold
        if plan is None or not self.path.num_steps or not plan.hinges.size:
            return {}
        tolerance = self.problem.analysis.target_tolerance_deg
        final = fold_angles_deg(self.pattern_model, self.path.displacement[-1], plan.signs)
        reached = final[plan.hinges]
        # Fold angles live on a circle: a crease folded 16 deg past flat reads -164 deg,
        # 16 deg from a target of 180, not 344.
        miss = np.abs((reached - plan.target_deg + 180.0) % 360.0 - 180.0)
        worst = int(np.argmax(miss))
        # The other way: on the far side of flat, farther from the target than flat is (a
        # crease folded past 180 deg is past its target, not the other way).
        other_way = ((np.sign(reached) * np.sign(plan.target_deg) < 0)
                     & (np.abs(reached) > FOLD_TOLERANCE_DEG)
                     & (miss > np.abs(plan.target_deg)))
        return {"creases_driven": int(plan.hinges.size),
                "short_of_target": int(np.count_nonzero(miss > tolerance)),
                "tolerance_deg": tolerance,
                "largest_shortfall_deg": float(miss[worst]),
                "worst": {"hinge": int(plan.hinges[worst]),
                          "target_deg": float(plan.target_deg[worst]),
                          "fold_angle_deg": float(reached[worst])},
                "left_branch": int(np.count_nonzero(other_way)),
                "snaps": [float(t) for t in self.path.load_factor[self.path.snapped]],
                "rigid_closure": (None if plan.closure is None
                                  else plan.closure.report(tolerance))}

    def summary(self) -> dict:
        path = self.path
        extra = {"fold": self.fold_report()} if self.fold is not None else {}
        return {
            "source": self.problem.source,
            "method": self.problem.analysis.method,
            "stepping": self.problem.method.stepping(self.problem),
            "nodes": self.model.num_nodes,
            "bars": len(self.model.bars),
            "hinges": len(self.model.hinges),
            "supported_dofs": int(self.model.fixed.sum()),
            "increments": path.num_steps,
            "newton_iterations": int(path.iterations.sum()),
            # Rejected increments (halved, retried) cost iterations too.
            "attempted_increments": int(path.attempted_increments),
            "attempted_newton_iterations": int(path.newton_iterations),
            "final_load_factor": float(path.load_factor[-1]) if path.num_steps else None,
            "completed": bool(self.completed),
            "interrupted": bool(self.interrupted),
            "message": self.message,
            **self._material_summary(),
            **extra,
        }

    def _material_summary(self) -> dict:
        """The preset used and the supports chosen (when the problem named neither), and
        the largest bar strain along the path (how far the bars gave to let it fold)."""
        out = {}
        if self.problem.preset is not None:
            out["material_preset"] = self.problem.preset
        if self.problem.held:
            out["held"] = [{"node": s.node, "axes": s.axes} for s in self.problem.held]
        if self.path.num_steps and len(self.model.bars):
            out["largest_bar_strain"] = largest_bar_strain(self.model, self.path.displacement)
        return out


def largest_bar_strain(model, displacements) -> float:
    """The largest |strain| of any bar at any of the states ``displacements`` (S, 3N)."""
    bars = np.asarray(model.bars)
    rest = np.asarray(model.bar_rest_length)
    displacements = np.asarray(displacements)
    largest = 0.0
    # A few states at once (one numpy call each, not one per state), each batch within a
    # cache (about 32,000 coordinates).
    chunk = max(1, 2 ** 15 // max(1, 3 * len(bars)))
    for start in range(0, len(displacements), chunk):
        x = model.nodes + displacements[start:start + chunk].reshape(-1, model.num_nodes, 3)
        length = np.linalg.norm(x[:, bars[:, 1]] - x[:, bars[:, 0]], axis=2)
        largest = max(largest, float(np.max(np.abs(length / rest - 1.0))))
    return largest


def _holds_elements(columns: dict) -> bool:
    """Whether a family's table holds any element (nodes of a node family, triangles of
    the self-contact family)."""
    key = "triangles" if "triangles" in columns else "nodes"
    return columns[key].size > 0
