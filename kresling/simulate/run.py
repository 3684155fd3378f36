"""Run a simulation problem: build the pattern's model, apply supports and loads, follow
the path."""

from __future__ import annotations

import dataclasses

import logging
import sys

import numpy as np

from kresling.simulate.fold_stall import fold_stall
from kresling.simulate.graceful_stop import GracefulStop
from kresling.simulate.methods import method_names
from kresling.simulate.preset_check import preset_goes_past
from kresling.simulate.problem import Problem, load_problem
from kresling.simulate.problem_model import build_problem_model
from kresling.simulate.problem_keys import problem_keys
from kresling.simulate.problem_keys.load import load_vector
from kresling.simulate.problem_keys.support import held_in_words
from kresling.simulate.progress_log import ProgressLog
from kresling.simulate.simulation import PathState, Simulation
from kresling.simulate.stages import StagedProblem, StagedRun, end_state
from kresling.solvers import PathResult
from kresling.solvers.tangent_shift import MERLIN2_SHIFT, scale_free_shift

__all__ = ["simulate"]

logger = logging.getLogger(__name__)

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
    _load_modules()
    lines = None  # progress lines where there is no bar (a log, a batch job)
    if progress is not False:
        source = problem.source if isinstance(problem, Problem) else str(
            problem if not isinstance(problem, dict) else "problem")
        lines = ProgressLog(source, "reading the problem and building its model")
    try:
        problem = load_problem(problem, overrides=overrides)
        if isinstance(problem, StagedProblem):
            return _run_stages(problem, stop, progress, lines)
        return _simulate(problem, stop, progress, stream, lines)
    finally:
        if lines is not None:
            lines.close()


def _run_stages(staged, stop, progress, lines) -> StagedRun:
    """Each stage from where the one before ended, until one stops short."""
    runs, start = [], None
    for name, problem in staged.stages:
        logger.info("%s: stage '%s': %s", staged.source, name, problem.analysis.method)
        run = _simulate(problem, stop, progress, None, lines, start)
        runs.append((name, run))
        if not run.completed:
            logger.warning("%s: stage '%s' stopped: %s", staged.source, name, run.message)
            break
        start = end_state(run, start)
    return StagedRun(staged, runs)


def _load_modules():
    """The methods' and keys' modules, loaded before the progress lines' clock starts: the
    lines time the run, not Python's imports."""
    method_names()
    problem_keys()


def _simulate(problem, stop, progress, stream, lines, start=None) -> Simulation:
    """:func:`simulate` with its progress lines running; ``start`` (a
    :class:`~kresling.simulate.start_state.StartState`): a stage's start, not the rest."""
    problem = load_problem(problem)
    if problem.preset is not None:
        logger.info("%s: material: preset %r", problem.source, problem.preset)
    if problem.held:
        logger.info("%s: no [[support]]: holding the free sheet's rigid-body motions only, "
                    "at %s", problem.source, held_in_words(problem.held))
    pm = build_problem_model(problem)
    if start is not None:
        pm = start.applied_to(pm)
    method = problem.method
    if not method.follows_path:   # modes, a motion in time: a run of their own
        return method.run(problem, pm, stop=stop, start=start)
    model = pm.model
    analysis = problem.analysis
    vector = load_vector(problem, model.num_dofs)
    bar = _progress_bar(problem, progress)
    if bar is not None and lines is not None:   # the bar takes over
        lines.close()
        lines = None
    count = [0]
    try:
        plan = method.plan(problem, pm)
    except ValueError as error:   # named as the solver's own refusals are
        raise ValueError(f"{problem.source}: {_solver_where(str(error))}") from None
    # The DOFs that carry a force (displacement control: the imposed DOFs, which the path
    # records as its constraint DOFs).
    driven = np.flatnonzero(vector)
    writer = None
    if stream is not None:
        from kresling.simulate.path_stream import PathStream

        recorded = method.recorded_dofs(vector, model)
        before = Simulation(problem, pm, _no_path(model.num_dofs, recorded, model.families),
                            driven, plan)
        writer = PathStream(stream, before, problem.output.every)
    # The problem's own rules where the C++ solver has none (MGDCM checks them itself).
    monitor = analysis.stop if not method.checks_own_monitor else None
    bound = analysis.max_load_factor if method.bounded else np.inf

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
                    f"hinges; {method.stepping(problem)}")
    with GracefulStop() as graceful:
        # The rule is asked only where it has something to do (Python at every increment
        # otherwise for nothing); a Ctrl-C or a kill it listens for is one of those.
        needed = (graceful.listening or lines is not None or bar is not None
                  or stop is not None or monitor is not None or np.isfinite(bound)
                  or writer is not None)
        common = {"tolerance": analysis.tolerance, "max_iterations": analysis.max_iterations,
                  "stop": rule if needed else None, "shift": shift}
        if start is not None:
            common["initial"] = start.displacement
        try:
            path = method.solve(problem, pm, vector, common, plan)
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
    driven = method.driven_dofs(path, vector)
    simulation = Simulation(problem, pm, path, np.asarray(driven, dtype=np.int64), plan,
                            graceful.requested, _preset_advice(problem, path, graceful.requested))
    stall = fold_stall(simulation)  # why a fold's path ended early, measured where it did
    return dataclasses.replace(simulation, stall=stall) if stall else simulation


def _no_path(num_dofs, constraint_dofs, families) -> PathResult:
    """A path without a step yet (what a streamed run's files start from)."""
    count = len(constraint_dofs)
    return PathResult(np.zeros(0), np.zeros((0, num_dofs)), np.asarray(constraint_dofs, np.int64),
                      np.zeros((0, count)), tuple(families), np.zeros((0, len(families))),
                      np.zeros(0, np.int64), np.zeros(0, np.int64), False, "", 0, 0, 0,
                      np.zeros(0, bool))


def _preset_advice(problem, path, interrupted) -> str:
    """For a fold with a material of its own that stalled: whether Origami Simulator's
    material goes on past that point (checked by folding it so), in words; "" otherwise."""
    if (not problem.method.drives_creases or path.completed or interrupted
            or problem.preset is not None or problem.merlin2_compat):
        return ""
    stopped = float(path.load_factor[-1]) if path.num_steps else 0.0
    reached = preset_goes_past(problem, stopped, simulate)
    if reached is None:
        return ""
    return (f"with Origami Simulator's softer material ([material] preset = "
            f"\"origami_simulator\") the same fold goes on past {stopped:.3g} (checked: to "
            f"{reached:.3g})")


class _Bar:
    """A tqdm bar over the fraction of the run done (displacement, steps or the monitor)."""

    def __init__(self, problem):
        from tqdm.auto import tqdm

        self.analysis, self.method = problem.analysis, problem.method
        self.total = self.method.progress_total(self.analysis)
        self.tqdm = tqdm(total=self.total, desc="simulate", unit="incr", leave=False,
                         file=sys.stderr)

    def update(self, count, load_factor, u):
        done = self.method.progress_done(self.analysis, count, load_factor, u)
        self.tqdm.n = min(round(done, 2), self.total)
        self.tqdm.refresh()

    def close(self):
        self.tqdm.close()


def _progress_bar(problem, progress):
    if progress is None:
        progress = sys.stderr.isatty()
    return _Bar(problem) if progress else None
