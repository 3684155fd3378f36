"""Beyond the grid: the best design of each n found by a continuous optimiser.

The grid tells where the optimum is to within a grid step; :func:`optimize_design` finds it
to the solver's precision with SciPy's SLSQP over (Lc, lambda), under the constraints a
designer needs: bounds on Lc and lambda (manufacturing: lambda near 1 tears the material)
and bounds on any other metric (a floor on the snap-through force so the joint does not
snap by accident, a floor on K_B extended so the link stays stiff, ...).

It starts from the best feasible point of a coarse grid, so it does not stop on a local
maximum the grid can see.
"""

from __future__ import annotations

import logging
import math
from dataclasses import dataclass, field

import numpy as np

from kresling._validation import as_integer
from kresling.geometry import Design
from kresling.sweeps.designs import THESIS_LAM, design_grid
from kresling.sweeps.metrics import METRICS, require_even_n, resolve_metrics
from kresling.sweeps.sweep import sweep
from kresling.sweeps.worker import evaluate_design, make_plan

__all__ = ["DesignOptimum", "optimize_design"]

logger = logging.getLogger(__name__)

# Finite-difference step in the unit box: 4.5e-3 mm in Lc, 2e-5 in lambda over the thesis's
# ranges; the K_B ratio is smooth there to about 1e-9, so the gradient is good to ~1e-5.
_STEP = 1e-4


@dataclass(frozen=True)
class DesignOptimum:
    """The best design of one n.

    Attributes
    ----------
    design : Design
    metric : str
        What was maximised.
    value : float
        Its value at ``design``.
    values : dict
        Every column computed at the optimum (the metric's and the constraints').
    active : tuple of str
        Bounds and constraints that hold with equality at the optimum (``"Lc min"``,
        ``"lam max"``, ``"snap_force min"``, ...).
    success : bool
    message : str
    evaluations : int
        Designs evaluated by the optimiser (not counting the starting grid).
    """

    design: Design
    metric: str
    value: float
    values: dict = field(repr=False)
    active: tuple
    success: bool
    message: str
    evaluations: int


#: The metric columns with exact derivatives (kresling.analyses.design_gradient): column ->
#: (the test, its protocol, the quantity it reads).
EXACT_COLUMNS = {
    "kb_ratio": ("bending", "0.001rad", "kb_ratio"),
    "kb_ext": ("bending", "0.001rad", "kb_extended"),
    "kb_con": ("bending", "0.001rad", "kb_contracted"),
    "kb_ratio_5mm": ("bending", "5mm", "kb_ratio"),
    "kb_ext_5mm": ("bending", "5mm", "kb_extended"),
    "kb_con_5mm": ("bending", "5mm", "kb_contracted"),
    "snap_force": ("snap", None, "snap_force"),
    "energy_barrier": ("snap", None, "energy_barrier"),
}


def optimize_design(n, metric="kb_ratio", *, Lc=None, lam=THESIS_LAM, R=30.0,
                    constraints=None, start_grid=5, workers=None,
                    parameters=None, gradient="exact") -> DesignOptimum:
    """Maximise ``metric`` over Lc x lambda for one n.

    Parameters
    ----------
    n : int
    metric : str, default "kb_ratio"
        A column of a registered metric (maximised).
    Lc : (float, float), optional
        Bounds of the contracted height [mm]; default ``(R/2, 2R)``.
    lam : (float, float), default (0.7, 0.9)
        Bounds of the angle ratio.
    R : float, default 30
    constraints : dict, optional
        ``{column: (low, high)}`` with either end ``None``, e.g.
        ``{"snap_force": (1.0, None)}`` for a snap-through force of at least 1 N.
    start_grid : int, default 5
        The optimiser starts from the best feasible design of this coarse grid.
    workers : int, optional
        For the starting grid.
    parameters : SpecimenParameters, optional
        The specimens' material and model (the thesis's by default; see
        :func:`~kresling.sweeps.sweep`).
    gradient : {"exact", "differences"}, default "exact"
        How SLSQP gets its gradients: "exact" differentiates the tests themselves
        (:func:`~kresling.analyses.design_gradient`; for the columns of
        :data:`EXACT_COLUMNS`, the values and gradients of one run each, Newton converged
        to 1e-10 mm); "differences", or any other column, by forward differences of step
        1e-4 in the unit box. The optimum's ``values`` are the metrics' own either way.

    Returns
    -------
    DesignOptimum
        ``success`` is False if SLSQP did not converge or the result breaks a constraint.

    Raises
    ------
    ValueError
        For an unknown metric or constraint column, empty bounds, or an odd n with a
        bending metric; also if every design of the starting grid fails.
    """
    # Here, not at the top: scipy.optimize takes ~0.3 s, and the command line imports this
    # package for every command ('kresling --help' stays fast).
    from scipy import optimize

    n = as_integer("n", n, minimum=3)
    constraints = dict(constraints or {})
    metrics = _metrics_for([metric, *constraints])
    require_even_n(metrics, [n])
    grid = design_grid([n], start_grid, Lc=Lc, lam=lam, R=R)
    low = np.array([grid.spec["Lc"][0], grid.spec["lam"][0]])
    high = np.array([grid.spec["Lc"][1], grid.spec["lam"][1]])
    plan = make_plan(metrics, parameters)
    cache = {}

    def design_point(u):  # unit box -> (Lc, lam), the bounds exactly at its faces
        u = np.clip(u, 0.0, 1.0)
        u = np.where(u < 1e-9, 0.0, np.where(u > 1 - 1e-9, 1.0, u))
        return np.where(u == 0, low, np.where(u == 1, high, low + u * (high - low)))

    def values(u):
        key = tuple(np.clip(u, 0.0, 1.0))
        if key not in cache:
            Lc_, lam_ = design_point(key)
            row = evaluate_design(plan, n, float(Lc_), float(lam_), R)
            cache[key] = dict(zip(plan.columns, row)) if row[len(plan.columns)] == "ok" else None
        return cache[key]

    def objective(u):
        v = values(u)
        return -math.log(v[metric]) if v and v[metric] > 0 else 1e3

    if gradient not in ("exact", "differences"):
        raise ValueError(f"gradient = {gradient!r} is invalid: must be 'exact' or 'differences'")
    exact = gradient == "exact" and all(c in EXACT_COLUMNS for c in [metric, *constraints])
    start = _start(grid, metrics, metric, constraints, workers, parameters)
    if exact:
        evaluate = _ExactEvaluation(n, R, low, high, design_point, [metric, *constraints],
                                    parameters)
        result = optimize.minimize(
            evaluate.objective(metric), (start - low) / (high - low), jac=True,
            method="SLSQP", bounds=[(0, 1), (0, 1)],
            constraints=_slsqp_constraints(evaluate.values, constraints, evaluate.gradients),
            options={"ftol": 1e-9, "maxiter": 100})
        evaluations = evaluate.count
    else:
        result = optimize.minimize(
            objective, (start - low) / (high - low), method="SLSQP", bounds=[(0, 1), (0, 1)],
            constraints=_slsqp_constraints(values, constraints),
            options={"eps": _STEP, "ftol": 1e-9, "maxiter": 100})
        evaluations = None
    u = np.clip(result.x, 0, 1)
    best = values(u)
    Lc_, lam_ = design_point(u)
    feasible = best is not None and _feasible(best, constraints, rtol=1e-6)
    # SLSQP's mode 8 ("positive directional derivative for linesearch") at a feasible point
    # means it cannot improve on it within the metric's noise: converged for our purposes.
    converged = result.success or result.status == 8
    return DesignOptimum(
        design=Design(n, float(lam_), float(Lc_), R), metric=metric,
        value=best[metric] if best else math.nan, values=best or {},
        active=_active(u, best, constraints), success=bool(converged and feasible),
        message=result.message if feasible else f"{result.message}; constraints not met",
        evaluations=len(cache) if evaluations is None else evaluations)


def _metrics_for(columns):
    """The registered metrics that produce ``columns``."""
    found = []
    for column in columns:
        owner = next((m for m in METRICS.values() if column in m.columns), None)
        if owner is None:
            known = sorted(c for m in METRICS.values() for c in m.columns)
            raise ValueError(f"unknown metric column {column!r}: must be one of {', '.join(known)}")
        if owner not in found:
            found.append(owner)
    return resolve_metrics(found)


def _start(grid, metrics, metric, constraints, workers, parameters=None) -> np.ndarray:
    """The best feasible design of the grid; if none is feasible, the least infeasible."""
    table = sweep(grid, metrics, workers=workers, progress=False, parameters=parameters)
    violation = np.where(table.ok & np.isfinite(table[metric]), 0.0, np.inf)
    for column, (lo, hi) in constraints.items():
        x = table[column]
        scale = [max(abs(b), 1e-12) for b in (lo or 0, hi or 0)]
        below = np.maximum(lo - x, 0) / scale[0] if lo is not None else 0.0
        above = np.maximum(x - hi, 0) / scale[1] if hi is not None else 0.0
        violation = violation + np.nan_to_num(below + above, nan=np.inf)
    if not np.isfinite(violation).any():
        raise ValueError(f"every design of the {grid.spec['size']} starting grid failed")
    feasible = violation == 0
    if feasible.any():
        i = int(np.argmax(np.where(feasible, table[metric], -np.inf)))
    else:
        i = int(np.argmin(violation))
        logger.info("no design of the starting grid meets %s; starting from the least "
                    "infeasible", constraints)
    return np.array([table["Lc"][i], table["lam"][i]])


def _slsqp_constraints(values, constraints, gradients=None) -> list:
    """SLSQP's inequalities for ``{column: (low, high)}``: ``values(u)`` gives the columns at
    u (None where the design fails), ``gradients(u)`` their d/du (exact gradients; None:
    SLSQP differentiates by itself)."""
    out = []
    for column, (lo, hi) in constraints.items():
        for bound, sign in ((lo, 1.0), (hi, -1.0)):
            if bound is None:
                continue
            scale = max(abs(bound), 1e-12)

            def g(u, column=column, bound=bound, sign=sign, scale=scale):
                v = values(u)
                return sign * (v[column] - bound) / scale if v else -1.0
            entry = {"type": "ineq", "fun": g}
            if gradients is not None:
                def dg(u, column=column, sign=sign, scale=scale):
                    d = gradients(u)
                    return sign * d[column] / scale if d else np.zeros(2)
                entry["jac"] = dg
            out.append(entry)
    return out


def _within(x, lo, hi, rtol):
    x = np.asarray(x, float)
    ok = np.isfinite(x)
    if lo is not None:
        ok &= x >= lo - rtol * abs(lo)
    if hi is not None:
        ok &= x <= hi + rtol * abs(hi)
    return ok


def _feasible(values, constraints, rtol) -> bool:
    return all(bool(_within(values[c], lo, hi, rtol)) for c, (lo, hi) in constraints.items())


def _active(u, values, constraints, tol=1e-6) -> tuple:
    names = [f"{name} {end}" for name, x in zip(("Lc", "lam"), u)
             for end, hit in (("min", x <= tol), ("max", x >= 1 - tol)) if hit]
    for column, (lo, hi) in constraints.items():
        for end, bound in (("min", lo), ("max", hi)):
            close = values and bound is not None and \
                abs(values[column] - bound) <= 1e-4 * max(abs(bound), 1)
            if close:
                names.append(f"{column} {end}")
    return tuple(names)


class _ExactEvaluation:
    """Values and exact gradients of metric columns in the unit box, one design at a time
    (cached: SLSQP asks for the objective and each constraint at the same point)."""

    def __init__(self, n, R, low, high, design_point, columns, parameters):
        self.n, self.R, self.low, self.high = n, R, low, high
        self.design_point = design_point
        self.columns = list(dict.fromkeys(columns))
        self.parameters = parameters
        self.cache = {}
        self.count = 0

    def at(self, u):
        """{column: (value, d/du (2,))} at u, or None where a test fails there."""
        from kresling.analyses.design_sensitivity import (bending_pair_gradient,
                                                          snap_through_gradient)

        key = tuple(np.clip(u, 0.0, 1.0))
        if key in self.cache:
            return self.cache[key]
        Lc_, lam_ = self.design_point(key)
        design = Design(self.n, float(lam_), float(Lc_), self.R)
        scale = self.high - self.low  # d(Lc, lam)/du
        out = {}
        try:
            runs = {}
            for column in self.columns:
                test, protocol, quantity = EXACT_COLUMNS[column]
                if (test, protocol) not in runs:
                    runs[(test, protocol)] = (
                        bending_pair_gradient(design, protocol, parameters=self.parameters,
                                              variables=("Lc", "lam"))
                        if test == "bending" else
                        snap_through_gradient(design, parameters=self.parameters,
                                              variables=("Lc", "lam")))
                value, grad = runs[(test, protocol)][quantity]
                out[column] = (value, np.array([grad["Lc"], grad["lam"]]) * scale)
        except ValueError as error:
            logger.info("design Lc = %g, lam = %g: %s", Lc_, lam_, error)
            out = None
        self.count += 1
        self.cache[key] = out
        return out

    def objective(self, metric):
        def f(u):
            v = self.at(u)
            if not v or not v[metric][0] > 0:
                return 1e3, np.zeros(2)
            value, grad = v[metric]
            return -math.log(value), -grad / value
        return f

    def values(self, u):
        v = self.at(u)
        return {c: value for c, (value, _) in v.items()} if v else None

    def gradients(self, u):
        v = self.at(u)
        return {c: grad for c, (_, grad) in v.items()} if v else None
