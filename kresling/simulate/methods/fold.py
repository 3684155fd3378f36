"""``method = "fold"``: creases driven to their target fold angles ([[actuation]], in
stages), the sheet following as equilibria of its rest angles' increments."""

from __future__ import annotations

import dataclasses

import numpy as np

from kresling.simulate.fold_plan import FOLD_TOLERANCE_DEG, fold_plan
from kresling.simulate.methods.method import PathMethod
from kresling.simulate.methods.path_settings import ADAPTIVE_TOLERANCE, PREDICTORS, read_increments
from kresling.simulate.problem_table import boolean, number, positive
from kresling.solvers import solve_fold

__all__ = ["METHOD", "FOLD_STEPS", "FOLD_PREDICTOR", "FOLD_GIVE_UP_AFTER",
           "DEFAULT_FOLD_PRESET"]

#: Increments per stage when the problem gives no ``steps``.
FOLD_STEPS = 40
#: Each increment's start when the problem gives no ``predictor`` (and no ``[contact]``:
#: then the previous equilibrium).
FOLD_PREDICTOR = "quadratic"
#: Newton gives an increment up (and halves it) when its correction at this iteration or
#: later is still above 1e-3 of its first (no ``max_iterations`` of wandering where the
#: path turns sharply; docs/folding.md, 'Large patterns'). Not with ``[contact]``, whose
#: barriers shorten Newton's steps near touching panels and so slow it down without its
#: wandering.
FOLD_GIVE_UP_AFTER = 12
#: The material when the problem gives no ``[material]``.
DEFAULT_FOLD_PRESET = "origami_simulator"


class Fold(PathMethod):
    name = "fold"
    drives_creases = True
    holds_free_sheet = True
    default_preset = DEFAULT_FOLD_PRESET

    def read_settings(self, t) -> dict:
        settings = self.read_steps(t, FOLD_STEPS)
        percent = t.get("fold_percent", number, 100.0)
        if not 0 < percent <= 100:
            t.fail("fold_percent", f"= {percent!r} is invalid: must be in (0, 100] (the "
                                   "percentage of every target fold angle folded to)")
        settings["fold_percent"] = percent
        settings["target_tolerance_deg"] = t.get("target_tolerance_deg", positive,
                                                 FOLD_TOLERANCE_DEG)
        # Each increment starts from its quadratic extrapolation: along a smooth fold it
        # halves the Newton iterations (the box-pleat pyramid: 5 instead of 10).
        settings.update(read_increments(t, FOLD_PREDICTOR))
        settings["snap"] = t.get("snap", boolean, False)
        settings["relax"] = t.get("relax", boolean, None)
        return settings

    def check(self, problem, t):
        if not problem.actuations:
            raise ValueError(f"{problem.source}: [[actuation]] is missing: method = 'fold' "
                             "drives the creases it names")
        if {load.kind for load in problem.loads} - {"force"}:
            t.fail("method", "= 'fold' takes force loads only (they ramp with the first "
                             "stage); a prescribed displacement is not one")
        stages = sorted({a.stage for a in problem.actuations})
        if stages != list(range(1, len(stages) + 1)):
            raise ValueError(f"{problem.source}: [[actuation]] stages are {stages}: must be "
                             "numbered 1, 2, ... without a gap")

    def finalize(self, problem, t):
        analysis = problem.analysis
        if (problem.contact is not None and analysis.increments != "adaptive"
                and not t.has("predictor")):
            # With panel contact a fold starts each increment from the previous
            # equilibrium: an extrapolated start may carry panels into each other, where
            # the barriers' own limits then shorten every Newton step.
            return dataclasses.replace(
                problem, analysis=dataclasses.replace(analysis, predictor="previous"))
        return problem

    def stepping(self, problem) -> str:
        analysis = problem.analysis
        if analysis.increments == "adaptive":
            return ("adaptive increments of the creases' rest angles, the equal samples read "
                    "off the path between them")
        start = ("the previous equilibrium" if analysis.predictor == "previous"
                 else f"a {analysis.predictor} extrapolation")
        return f"equal increments of the creases' rest angles, each started from {start}"

    def plan(self, problem, pattern_model):
        return fold_plan(problem, pattern_model)

    def solve(self, problem, pattern_model, vector, common, plan):
        analysis = problem.analysis
        return solve_fold(pattern_model.model, plan.stages, analysis.steps, forces=vector,
                          extrapolation=PREDICTORS.index(analysis.predictor),
                          adaptive=analysis.increments == "adaptive",
                          adaptive_tolerance=ADAPTIVE_TOLERANCE, snap=analysis.snap,
                          relax=relaxes(problem),
                          give_up_after=0 if problem.contact is not None else FOLD_GIVE_UP_AFTER,
                          **common)

    def history_columns(self, simulation) -> dict:
        load_factor = simulation.path.load_factor
        # load_factor runs over (k - 1, k] in stage k.
        stage = np.maximum(np.ceil(load_factor - 1e-12), 1).astype(int)
        # Of the full targets: a fold to fold_percent ends at fold_percent / 100.
        return {"stage": stage,
                "fold_fraction": ((load_factor - (stage - 1))
                                  * simulation.problem.analysis.fold_percent / 100.0)}

    def curve(self, simulation, columns) -> tuple:
        """The stored energy against the fold's progress in per cent (100 per stage)."""
        return (100.0 * np.asarray(simulation.path.load_factor, dtype=float),
                np.asarray(columns["energy_total"], dtype=float), "fold [%]",
                "energy_total [N*mm]")


def relaxes(problem) -> bool:
    """Whether a fold relaxes the increments its path cannot follow stably (``[analysis]
    relax``): by default with Origami Simulator's material, whose sheet is meant to come to
    rest as Origami Simulator's relaxation brings it."""
    if problem.analysis.relax is not None:
        return problem.analysis.relax
    return problem.preset is not None


METHOD = Fold()
