"""Run a simulation problem: build the pattern's model, apply supports and loads, follow
the path."""

from __future__ import annotations

import dataclasses
import logging
import sys
from dataclasses import dataclass

import numpy as np

from kresling.model import PatternModel, build_pattern_model
from kresling.model.fold_angles import fold_angles_deg
from kresling.simulate.actuation import FoldPlan, fold_plan
from kresling.simulate.element_histories import ElementHistories, element_histories
from kresling.simulate.graceful_stop import GracefulStop
from kresling.simulate.preset_check import preset_goes_past
from kresling.simulate.progress_log import ProgressLog
from kresling.simulate.modes_output import run_modes
from kresling.simulate.problem import (_AXES, FOLD_GIVE_UP_AFTER, PREDICTORS, Problem,
                                       load_problem, node_count)
from kresling.simulate.problem_contact import TANGENTS, auto_barrier_stiffness
from kresling.solvers import (PathResult, solve_displacement_control, solve_force_control,
                              solve_fold, solve_mgdcm)
from kresling.solvers.tangent_shift import MERLIN2_SHIFT, scale_free_shift

__all__ = ["Simulation", "PathState", "simulate", "build_problem_model"]

logger = logging.getLogger(__name__)

#: The adaptive increments' error target (relative to the largest drive force so far, or for
#: a fold the largest stored energy) for any crease pattern: tighter than the bending test's 1e-9 because the estimate assumes a smooth
#: path, which MERLIN2's super-linear bend law is not at rest. On its GMiura sheet 1e-9 let
#: one sample's reaction err by 1.65e-8 of the largest; 3e-10 keeps every sample within
#: 3.8e-10 (and costs 2 % more time).
ADAPTIVE_TOLERANCE = 3e-10
#: A fold reaches its end when every driven crease is within this many degrees of its
#: target fold angle there (``short_of_target`` counts the others).
FOLD_TOLERANCE_DEG = 1.0


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
    """

    problem: Problem
    pattern_model: PatternModel
    path: PathResult
    driven_dofs: np.ndarray
    fold: FoldPlan | None = None
    interrupted: str = ""
    #: A fold that stalled with a material of its own: where Origami Simulator's goes on.
    advice: str = ""

    @property
    def model(self):
        return self.pattern_model.model

    @property
    def completed(self) -> bool:
        """Whether the run reached its end: the path ran to it and, for a fold, every
        driven crease is within :data:`FOLD_TOLERANCE_DEG` of its target there."""
        return self.path.completed and not self.interrupted and not self._fold_shortfall()

    @property
    def message(self) -> str:
        """Why the run did not reach its end ("" when it did)."""
        if self.interrupted:
            return (f"interrupted ({self.interrupted}) after {self.path.num_steps} increments: "
                    "the path so far is kept")
        message = self.path.message or self._fold_shortfall()
        return f"{message}; {self.advice}" if self.advice else message

    def _fold_shortfall(self) -> str:
        """For a fold whose path ran to its end: which creases fell short, in words."""
        report = self.fold_report() if self.fold is not None else {}
        short = report.get("short_of_target", 0)
        if not short:
            return ""
        worst = report["worst"]
        return (f"the fold ran to its end but {short} of {report['creases_driven']} driven "
                f"creases are more than {FOLD_TOLERANCE_DEG:g} deg from their targets (held "
                f"back by the structure or by their laws' limits); the farthest, hinge "
                f"{worst['hinge']}, reached {worst['fold_angle_deg']:.4g} deg of "
                f"{worst['target_deg']:.4g} deg")

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
        if self.problem.analysis.method == "fold":
            # load_factor runs over (k - 1, k] in stage k.
            stage = np.maximum(np.ceil(path.load_factor - 1e-12), 1).astype(int)
            columns["stage"] = stage
            # Of the full targets: a fold to fold_percent ends at fold_percent / 100.
            columns["fold_fraction"] = ((path.load_factor - (stage - 1))
                                        * self.problem.analysis.fold_percent / 100.0)
        elif self.problem.analysis.method == "displacement_control":
            for k, dof in enumerate(path.constraint_dofs):
                columns[f"reaction_{dof // 3}_{'xyz'[dof % 3]}"] = path.constraint_force[:, k]
        else:
            stop = self.problem.analysis.stop
            if stop is not None:
                columns[f"u_{stop.node}_{stop.axis}"] = path.displacement[:, stop.dof]
        energies = self.element_histories().energy_by_family()
        # The model's other families (cables, springs, ...) that it holds any of: their
        # energies as the solver recorded them, and in the total.
        for name in path.families:
            if name not in ("bars", "hinges") and _holds_elements(self.model.family(name)):
                energies[name] = path.energy_of(name)
                energies["total"] = energies["total"] + energies[name]
        energies["total"] = energies.pop("total")
        columns.update(_contact_columns(self.model, path))
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
        the creases more than 1 deg from their target fold angle at the end (held at their
        law's limit, by the structure, or by a path that stopped), ``worst`` names the
        farthest; ``left_branch`` counts those folded the other way from their target;
        ``snaps`` the fold fractions (the steps' load factors) where the fold snapped."""
        plan = self.fold
        if plan is None or not self.path.num_steps or not plan.hinges.size:
            return {}
        final = fold_angles_deg(self.pattern_model, self.path.displacement[-1], plan.signs)
        reached = final[plan.hinges]
        miss = np.abs(reached - plan.target_deg)
        worst = int(np.argmax(miss))
        other_way = ((np.sign(reached) * np.sign(plan.target_deg) < 0)
                     & (np.abs(reached) > FOLD_TOLERANCE_DEG))
        return {"creases_driven": int(plan.hinges.size),
                "short_of_target": int(np.count_nonzero(miss > FOLD_TOLERANCE_DEG)),
                "tolerance_deg": FOLD_TOLERANCE_DEG,
                "largest_shortfall_deg": float(miss[worst]),
                "worst": {"hinge": int(plan.hinges[worst]),
                          "target_deg": float(plan.target_deg[worst]),
                          "fold_angle_deg": float(reached[worst])},
                "left_branch": int(np.count_nonzero(other_way)),
                "snaps": [float(t) for t in self.path.load_factor[self.path.snapped]]}

    def summary(self) -> dict:
        path = self.path
        extra = {"fold": self.fold_report()} if self.fold is not None else {}
        return {
            "source": self.problem.source,
            "method": self.problem.analysis.method,
            "stepping": stepping(self.problem),
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
    largest = 0.0
    for u in np.asarray(displacements):
        x = model.nodes + u.reshape(-1, 3)
        length = np.linalg.norm(x[bars[:, 1]] - x[bars[:, 0]], axis=1)
        largest = max(largest, float(np.max(np.abs(length / rest - 1.0))))
    return largest


def held_in_words(held) -> str:
    """``node 12 (x, y, z), node 40 (y, z), node 41 (z)``."""
    return ", ".join(f"node {s.node} ({', '.join(s.axes)})" for s in held)


def stepping(problem) -> str:
    """How the problem's path is stepped, in words (the summary's record of it)."""
    analysis = problem.analysis
    if analysis.method == "dynamic":
        return {"newmark": "time steps of Newmark's average acceleration scheme",
                "hht": f"time steps of HHT-alpha (alpha = {problem.dynamics.hht_alpha:g})",
                "explicit": "explicit central-difference time steps"}[problem.dynamics.scheme]
    if analysis.method == "fold":
        if analysis.increments == "adaptive":
            return ("adaptive increments of the creases' rest angles, the equal samples read "
                    "off the path between them")
        start = ("the previous equilibrium" if analysis.predictor == "previous"
                 else f"a {analysis.predictor} extrapolation")
        return f"equal increments of the creases' rest angles, each started from {start}"
    if analysis.method == "mgdcm":
        return "MGDCM (generalized displacement control)"
    if analysis.method == "force_control":
        return "equal load increments"
    if analysis.increments == "adaptive":
        return "adaptive increments, the equal samples read off the path between them"
    if analysis.predictor != "previous":
        return f"equal increments, each started from a {analysis.predictor} extrapolation"
    if problem.merlin2_compat:
        return "equal increments with MERLIN2's step control"
    return "equal increments, each started from the previous equilibrium"


def build_problem_model(problem) -> PatternModel:
    """The problem's pattern model with its supports (no loads)."""
    problem = load_problem(problem)
    # The supports go in with the model (not added to a copy afterwards: the copy was 28 %
    # of the model's cost); the node count is the one the problem was checked against
    # (pattern vertices and the split's centres).
    count = problem.num_nodes or node_count(problem.pattern, problem.split, problem.centre)
    fixed = np.zeros((count, 3), dtype=bool)
    for support in problem.supports:
        for axis in support.axes:
            fixed[support.node, _AXES[axis]] = True
    try:
        pm = build_pattern_model(problem.pattern, material=problem.material,
                                 split=problem.split, centre=problem.centre, laws=problem.laws,
                                 fixed=fixed, merlin2_compat=problem.merlin2_compat,
                                 assignments=problem.assignments)
    except ValueError as error:  # a value the model cannot take: name the problem's key
        raise ValueError(f"{problem.source}: {_where(str(error))}: {error}") from None
    families = {}
    nodes = pm.model.nodes
    if problem.springs:
        families["springs"] = {
            "nodes": np.array([s.node for s in problem.springs], dtype=np.int64),
            "stiffness": np.array([s.stiffness for s in problem.springs], dtype=float),
            "anchor": np.array([nodes[s.node] if s.anchor is None else s.anchor
                                for s in problem.springs], dtype=float)}
    if problem.contact is not None and problem.contact.planes:
        families["contact"] = _contact_table(problem, pm.model)
    if problem.contact is not None and problem.contact.self_contact:
        families["self_contact"] = _self_contact_table(problem, pm)
    if not families:
        return pm
    try:
        # The pattern model's own families (the faces' angle springs) stay beside these.
        model = pm.model.with_families(families)
    except ValueError as error:
        key = "[contact]" if "contact" in str(error) else "[[spring]]"
        raise ValueError(f"{problem.source}: {key}: {error}") from None
    return dataclasses.replace(pm, model=model)


def _barrier_stiffness(problem, model) -> float:
    """kappa [N/mm^3] of ``[contact]``: its number, or "auto" from the model's mean diagonal
    stiffness at rest (docs/simulate.md, '[contact]')."""
    from kresling.assembly import assemble

    contact = problem.contact
    if contact.stiffness is not None:
        return contact.stiffness
    diagonal = assemble(model).stiffness.diagonal()[~model.fixed.ravel()]
    return auto_barrier_stiffness(float(np.mean(diagonal)), contact.distance)


def _contact_table(problem, model) -> dict:
    """The contact family's columns: every node against every plane."""
    contact = problem.contact
    return {"nodes": np.arange(model.num_nodes, dtype=np.int64),
            "origin": np.array([p for p, _ in contact.planes], dtype=float),
            "normal": np.array([n for _, n in contact.planes], dtype=float),
            "distance": np.array([contact.distance]),
            "stiffness": np.array([_barrier_stiffness(problem, model)])}


def _self_contact_table(problem, pm) -> dict:
    """The self-contact family's columns: the pattern's triangles (N5B8 centre nodes
    included), kept off each other."""
    table = {"triangles": np.asarray(pm.elements.triangles, dtype=np.int64),
             "distance": np.array([problem.contact.distance]),
             "stiffness": np.array([_barrier_stiffness(problem, pm.model)])}
    if problem.contact.tangent != "adaptive":
        table["tangent"] = np.array([float(TANGENTS.index(problem.contact.tangent))])
    joined = _joined_at_rest(pm.model.nodes)
    if joined is not None:
        table["joined"] = joined
    return table


def _joined_at_rest(nodes):
    """Each node's representative among the nodes at its place at rest (the two sides of
    a cut, separated into copies of its vertices), or None where no two coincide: the
    contact barrier counts them as one node, so that a cut is not a contact."""
    from kresling.io.cuts import DUPLICATE_TOLERANCE
    from kresling.io.planar_graph import merge_points

    # "At one place" as a pattern's own vertices are judged (kresling.io.cuts).
    size = float(np.linalg.norm(np.ptp(nodes, axis=0)))
    joined = merge_points(nodes, DUPLICATE_TOLERANCE * size).astype(np.int64)
    return joined if np.any(joined != np.arange(len(nodes))) else None


def _holds_elements(columns: dict) -> bool:
    """Whether a family's table holds any element (nodes of a node family, triangles of
    the self-contact family)."""
    key = "triangles" if "triangles" in columns else "nodes"
    return columns[key].size > 0


def _contact_columns(model, path) -> dict:
    """The contact columns of ``history.csv`` along ``path``: ``min_gap`` [mm] (with planes
    or panel contact) and, with planes, ``reaction_planes_x/y/z`` [N], the planes' force on
    the model (the barrier's force on its nodes, summed over every node and plane)."""
    if not {"contact", "self_contact"} & set(path.families):
        return {}
    states = [model.element_state(u) for u in path.displacement]
    columns = {}
    gaps = [_min_gap(state) for state in states]
    if None not in gaps:  # (a mesh of one panel has no pair to measure)
        columns["min_gap"] = np.array(gaps)
    if "contact" in path.families:
        reaction = np.array([state["contact_force"].reshape(-1, 3).sum(axis=0)
                             for state in states]).reshape(-1, 3)
        for k, axis in enumerate("xyz"):
            columns[f"reaction_planes_{axis}"] = reaction[:, k]
    return columns


def _min_gap(state: dict) -> float | None:
    """The smallest node-plane and panel-panel distance of an element state [mm], or None
    when there is neither."""
    gaps = [state[k].min() for k in ("contact_gap", "self_contact_gap")
            if k in state and state[k].size]
    return float(min(gaps)) if gaps else None


#: The problem file's key of each material parameter the model's messages name.
_MATERIAL_KEYS = {"youngs_modulus": "E", "poisson_ratio": "nu", "thickness": "thickness",
                  "length_scale": "length_scale", "bar_modulus": "bar_modulus",
                  "bar_area": "bar_area", "fold_stiffness": "fold_stiffness",
                  "bend_stiffness": "bend_stiffness", "face_stiffness": "face_stiffness"}


def _where(message: str) -> str:
    """The table and key of the problem a model-building message is about."""
    name = message.split(" ", 1)[0]
    if name in _MATERIAL_KEYS:
        return f"[material] key {_MATERIAL_KEYS[name]!r}"
    return "[pattern] with its [material] (building the model)"


#: The problem's table and key behind each solver argument a solver's message can name.
_SOLVER_KEYS = {"forces": "[[load]] key 'force'", "prescribed": "[[load]] key 'displacement'",
                "stages": "[[actuation]]", "targets": "[[actuation]] key 'fold_angle_deg'",
                "monitor_dof": "[analysis] key 'stop'",
                "max_displacement": "[analysis] stop key 'beyond'",
                **{key: f"[analysis] key {key!r}" for key in (
                    "steps", "tolerance", "max_iterations", "initial_load_factor",
                    "max_increments", "max_load_factor")}}


def _solver_where(message: str) -> str:
    """A solver's message about its arguments, prefixed with the problem's table and key."""
    if message.startswith("forces: no force acts on a free DOF"):
        # In the problem's terms: what the [[load]] tables and the supports leave.
        return ("[[load]] key 'force': no force acts on a free DOF (every force is zero, or "
                "on a DOF a [[support]] fixes)")
    name = message.split(" ", 1)[0].rstrip(":").split("[", 1)[0]
    return f"{_SOLVER_KEYS.get(name, '[analysis]')}: {message}"


def _load_vector(problem, num_dofs):
    vector = np.zeros(num_dofs)
    for load in problem.loads:
        for node in load.nodes:
            vector[3 * node:3 * node + 3] += load.vector
    return vector


def simulate(problem, *, stop=None, progress=None, stream=None, overrides=None) -> Simulation:
    """Run a problem file (or dict, or :class:`Problem`).

    Parameters
    ----------
    problem : str, os.PathLike, dict or Problem
        See :func:`load_problem` and docs/simulate.md.
    stop : callable, optional
        ``stop(state: PathState) -> bool``, asked after every accepted increment; True ends
        the path there (completed), e.g. ``lambda s: s.displacement[4, 2] < -10``.
    progress : bool, optional
        A progress bar on stderr; default: when stderr is a terminal. Otherwise (unless
        False) progress lines on this module's logger: what runs, from half a second after
        the call (reading and building the model, then the path), and where the path is
        every few seconds.
    stream : str or os.PathLike, optional
        A directory: the run's files are written there as the path goes (history.csv and
        displacements.csv row by row, summary.json and path.fold rewritten whole as it goes;
        :mod:`kresling.simulate.path_stream`), so that a run ended any way at all, even
        killed, leaves its path so far. :meth:`Simulation.write` into the same directory at
        the end replaces them. Not for ``method = "modes"`` or ``"dynamic"``.
    overrides : dict, optional
        Keys replacing the problem's own, by table, as :func:`load_problem` takes them
        (read within the run, so that its progress lines cover reading the pattern).

    Returns
    -------
    Simulation, ModesRun or DynamicRun
        A :class:`~kresling.simulate.modes_output.ModesRun` for ``method = "modes"``, a
        :class:`~kresling.simulate.dynamics_output.DynamicRun` for ``method = "dynamic"``
        (its ``stop`` sees the time as the load factor);
        ``completed`` is False when the path stopped early; ``path.message`` says why.

    Raises
    ------
    ValueError
        For a bad problem (naming the file and key), or a model the supports leave free to
        move as a rigid body.
    """
    lines = None  # progress lines where there is no bar (a log, a batch job)
    if progress is not False:
        source = problem.source if isinstance(problem, Problem) else str(
            problem if not isinstance(problem, dict) else "problem")
        lines = ProgressLog(source, "reading the problem and building its model")
    try:
        return _simulate(load_problem(problem, overrides=overrides), stop, progress, stream,
                         lines)
    finally:
        if lines is not None:
            lines.close()


def _simulate(problem, stop, progress, stream, lines) -> Simulation:
    """:func:`simulate` with its progress lines running."""
    problem = load_problem(problem)
    if problem.preset is not None:
        logger.info("%s: material: preset %r", problem.source, problem.preset)
    if problem.held:
        logger.info("%s: no [[support]]: holding the free sheet's rigid-body motions only, "
                    "at %s", problem.source, held_in_words(problem.held))
    pm = build_problem_model(problem)
    if problem.analysis.method == "modes":   # no path: the modes about the rest state
        return run_modes(problem, pm)
    if problem.analysis.method == "dynamic":
        return _run_dynamic(problem, pm, stop)
    model = pm.model
    analysis = problem.analysis
    vector = _load_vector(problem, model.num_dofs)
    bar = _progress_bar(problem, progress)
    if bar is not None and lines is not None:   # the bar takes over
        lines.close()
        lines = None
    count = [0]
    try:
        plan = fold_plan(problem, pm) if analysis.method == "fold" else None
    except ValueError as error:   # named as the solver's own refusals are
        raise ValueError(f"{problem.source}: {_solver_where(str(error))}") from None
    # The DOFs that carry a force (displacement control: the imposed DOFs, which the path
    # records as its constraint DOFs).
    driven = np.flatnonzero(vector)
    writer = None
    if stream is not None:
        from kresling.simulate.path_stream import PathStream

        recorded = (np.flatnonzero(vector) if analysis.method == "displacement_control"
                    else np.flatnonzero(model.fixed.ravel()))
        before = Simulation(problem, pm, _no_path(model.num_dofs, recorded, model.families),
                            driven, plan)
        writer = PathStream(stream, before, problem.output.every)
    # The problem's own rules where the C++ solver has none (MGDCM checks them itself).
    monitor = analysis.stop if analysis.method != "mgdcm" else None
    bound = analysis.max_load_factor if analysis.method == "force_control" else np.inf

    def rule(load_factor, u, step=None):
        count[0] += 1
        if writer is not None:
            writer.append(load_factor, u, step)
        if bar is not None:
            bar.update(count[0], load_factor, u)
        if lines is not None:
            lines.update(count[0], load_factor)
        if graceful.requested:
            return True
        if monitor is not None and abs(u[monitor.dof]) > monitor.beyond:
            return True
        if abs(load_factor) > bound:
            return True
        if stop is None:
            return False
        return bool(stop(PathState(count[0], float(load_factor), np.asarray(u).reshape(-1, 3))))

    rule.takes_step = writer is not None  # the step's iterations and energies too

    # Scale-free like the tolerance: MERLIN2's absolute shift only to reproduce its runs.
    shift = MERLIN2_SHIFT if problem.merlin2_compat else scale_free_shift(model)
    if lines is not None:
        lines.begin(f"{model.num_nodes} nodes, {len(model.bars)} bars, {len(model.hinges)} "
                    f"hinges; {stepping(problem)}")
    with GracefulStop() as graceful:
        # The rule is asked only where it has something to do (Python at every increment
        # otherwise for nothing); a Ctrl-C or a kill it listens for is one of those.
        needed = (graceful.listening or lines is not None or bar is not None
                  or stop is not None or monitor is not None or np.isfinite(bound)
                  or writer is not None)
        common = {"tolerance": analysis.tolerance, "max_iterations": analysis.max_iterations,
                  "stop": rule if needed else None, "shift": shift}
        try:
            path = _solve(problem, pm, vector, common, plan)
        except ValueError as error:
            raise ValueError(f"{problem.source}: {_solver_where(str(error))}") from None
        finally:
            if bar is not None:
                bar.close()
            if writer is not None:
                writer.close()
    if graceful.requested:
        logger.warning("%s: %s: the path stopped after %d increments; they are kept",
                       problem.source, graceful.requested, path.num_steps)
    elif not path.completed:
        logger.warning("%s: the path stopped after %d increments: %s", problem.source,
                       path.num_steps, path.message)
    driven = (path.constraint_dofs if analysis.method == "displacement_control"
              else driven)
    return Simulation(problem, pm, path, np.asarray(driven, dtype=np.int64), plan,
                      graceful.requested, _preset_advice(problem, path, graceful.requested))


def _no_path(num_dofs, constraint_dofs, families) -> PathResult:
    """A path without a step yet (what a streamed run's files start from)."""
    count = len(constraint_dofs)
    return PathResult(np.zeros(0), np.zeros((0, num_dofs)), np.asarray(constraint_dofs, np.int64),
                      np.zeros((0, count)), tuple(families), np.zeros((0, len(families))),
                      np.zeros(0, np.int64), np.zeros(0, np.int64), False, "", 0, 0, 0,
                      np.zeros(0, bool))


def _solve(problem, pm, vector, common, plan):
    """The problem's path by its method's solver (``plan``: a fold's stages)."""
    model, analysis = pm.model, problem.analysis
    if analysis.method == "displacement_control":
        adaptive = analysis.increments == "adaptive"
        order = PREDICTORS.index(analysis.predictor)  # its extrapolation's order
        return solve_displacement_control(
            model, vector, analysis.steps, adaptive=adaptive,
            adaptive_tolerance=ADAPTIVE_TOLERANCE, extrapolation=order,
            merlin2_steps=problem.merlin2_compat and not adaptive and order == 0,
            **common)
    if analysis.method == "force_control":
        return solve_force_control(model, vector, analysis.steps, **common)
    if analysis.method == "fold":
        return solve_fold(model, plan.stages, analysis.steps, forces=vector,
                          extrapolation=PREDICTORS.index(analysis.predictor),
                          adaptive=analysis.increments == "adaptive",
                          adaptive_tolerance=ADAPTIVE_TOLERANCE, snap=analysis.snap,
                          relax=problem.relaxes(),
                          give_up_after=0 if problem.contact is not None else FOLD_GIVE_UP_AFTER,
                          **common)
    monitor = analysis.stop
    return solve_mgdcm(model, vector, initial_load_factor=analysis.initial_load_factor,
                       max_increments=analysis.max_increments,
                       max_load_factor=analysis.max_load_factor,
                       monitor_dof=None if monitor is None else monitor.dof,
                       max_displacement=np.inf if monitor is None else monitor.beyond,
                       **common)


def _preset_advice(problem, path, interrupted) -> str:
    """For a fold with a material of its own that stalled: whether Origami Simulator's
    material goes on past that point (checked by folding it so), in words; "" otherwise."""
    if (problem.analysis.method != "fold" or path.completed or interrupted
            or problem.preset is not None or problem.merlin2_compat):
        return ""
    stopped = float(path.load_factor[-1]) if path.num_steps else 0.0
    reached = preset_goes_past(problem, stopped)
    if reached is None:
        return ""
    return (f"with Origami Simulator's softer material ([material] preset = "
            f"\"origami_simulator\") the same fold goes on past {stopped:.3g} (checked: to "
            f"{reached:.3g})")


def _run_dynamic(problem, pm, stop):
    """``method = "dynamic"``, with the problem's monitor and the caller's stopping rule."""
    from kresling.simulate.dynamics_output import run_dynamics

    monitor, count = problem.analysis.stop, [0]

    def rule(time, u):
        count[0] += 1
        if monitor is not None and abs(u[monitor.dof]) > monitor.beyond:
            return True
        return stop is not None and bool(
            stop(PathState(count[0], float(time), np.asarray(u).reshape(-1, 3))))

    run = run_dynamics(problem, pm, stop=rule if monitor is not None or stop else None)
    if not run.path.completed:
        logger.warning("%s: the motion stopped after %d steps: %s", problem.source,
                       run.path.num_steps, run.path.message)
    return run


class _Bar:
    """A tqdm bar over the fraction of the run done (displacement, steps or the monitor)."""

    def __init__(self, problem):
        from tqdm.auto import tqdm

        a = problem.analysis
        self.problem = problem
        self.total = a.steps if a.method != "mgdcm" else a.max_increments
        self.tqdm = tqdm(total=self.total, desc="simulate", unit="incr", leave=False,
                         file=sys.stderr)

    def update(self, count, load_factor, u):
        a = self.problem.analysis
        if a.method != "mgdcm":  # the load factor runs from 0 to 1 over the steps
            done = load_factor * a.steps
        else:
            done = count
            if a.stop is not None:
                done = max(done, abs(u[a.stop.dof]) / a.stop.beyond * self.total)
        self.tqdm.n = min(round(done, 2), self.total)
        self.tqdm.refresh()

    def close(self):
        self.tqdm.close()


def _progress_bar(problem, progress):
    if progress is None:
        progress = sys.stderr.isatty()
    return _Bar(problem) if progress else None
