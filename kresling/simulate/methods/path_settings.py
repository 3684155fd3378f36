"""Settings shared by the path-following methods: how increments are sized and started,
the adaptive increments' error target, and the check of the loads' kind."""

from __future__ import annotations

from kresling.simulate.problem_table import string

__all__ = ["INCREMENTS", "PREDICTORS", "ADAPTIVE_TOLERANCE", "read_increments",
           "check_load_kind"]

#: How displacement control and folding step between their samples.
INCREMENTS = ("fixed", "adaptive")
#: Displacement control with fixed increments: each Newton solve's start, by the order of its
#: extrapolation along the path (the previous equilibrium, then through 2, 3 or 4 of them).
PREDICTORS = ("previous", "linear", "quadratic", "cubic")
#: The adaptive increments' error target (relative to the largest drive force so far, or for
#: a fold the largest stored energy) for any crease pattern: tighter than the bending test's
#: 1e-9 because the estimate assumes a smooth path, which MERLIN2's super-linear bend law is
#: not at rest. On its GMiura sheet 1e-9 let one sample's reaction err by 1.65e-8 of the
#: largest; 3e-10 keeps every sample within 3.8e-10 (and costs 2 % more time).
ADAPTIVE_TOLERANCE = 3e-10


def read_increments(t, predictor: str) -> dict:
    """``increments`` ("fixed" or "adaptive") and, with fixed ones, ``predictor`` (default
    ``predictor``)."""
    increments = t.get("increments", string, "fixed", choices=INCREMENTS)
    if increments == "adaptive" and t.has("predictor"):
        t.fail("predictor", "applies to fixed increments only: adaptive increments start "
                            "each Newton solve from their own cubic Hermite curves")
    return {"increments": increments,
            "predictor": t.get("predictor", string, predictor, choices=PREDICTORS)}


def check_load_kind(problem, t, wanted: str) -> None:
    """At least one load, each a ``wanted`` ("force" or "displacement")."""
    if not problem.loads:
        raise ValueError(f"{problem.source}: [[load]] is missing: at least one load is needed")
    kinds = {load.kind for load in problem.loads}
    if kinds != {wanted}:
        t.fail("method", f"= {problem.analysis.method!r} needs every [[load]] to be a {wanted} "
                         f"(given: {sorted(kinds)})")
