"""What runs in a worker: a chunk of designs through the analyses of a plan.

Everything here is picklable and importable at module level, so the same function runs in
a thread, a process pool or a Dask worker. Testers (one per analysis and n) are cached per
worker *thread*: the C++ testers hold mutable solver state, and threads run in parallel
because each ``run`` releases the GIL.
"""

from __future__ import annotations

import math
import threading
import time
from dataclasses import dataclass

from kresling.geometry import Design
from kresling.sweeps.table import FAILED, OK

__all__ = ["Plan", "make_plan", "run_chunk", "evaluate_design"]

_local = threading.local()


@dataclass(frozen=True)
class Plan:
    """The analyses to run on every design, and the value columns they fill, in order.

    Attributes
    ----------
    analyses : tuple of Analysis
    columns : tuple of str
        The metric columns of the table (a subset of the analyses' columns).
    parameters : SpecimenParameters, optional
        The specimens' stiffnesses for every tester (None: the thesis's).
    """

    analyses: tuple
    columns: tuple
    parameters: object = None


def make_plan(metrics, parameters=None) -> Plan:
    """The plan of resolved ``metrics``: each analysis once, the columns in metric order;
    ``parameters`` (a ``SpecimenParameters``) go to every tester."""
    analyses, columns = [], []
    for metric in metrics:
        if metric.analysis not in analyses:
            analyses.append(metric.analysis)
        columns += [c for c in metric.columns if c not in columns]
    return Plan(tuple(analyses), tuple(columns), parameters)


def _tester(analysis, n: int, parameters=None):
    cache = getattr(_local, "testers", None)
    if cache is None:
        cache = _local.testers = {}
    key = (analysis.name, repr(sorted(analysis.settings.items())), n, repr(parameters))
    if key not in cache:
        cache[key] = analysis.make_tester(n) if parameters is None else \
            analysis.make_tester(n, parameters=parameters)
    return cache[key]


def evaluate_design(plan: Plan, n: int, Lc: float, lam: float, R: float) -> tuple:
    """One design through every analysis of ``plan``.

    Returns
    -------
    tuple
        The values of ``plan.columns`` (floats, NaN where an analysis failed), then
        ``status`` ("ok"/"failed"), ``reason`` (one line, empty when ok), ``iterations``
        (int) and ``seconds`` (compute time).
    """
    start = time.perf_counter()
    values, failures, iterations = {}, [], 0
    try:
        design = Design(n, lam, Lc, R)
    except Exception as error:  # noqa: BLE001 - a design that cannot be built is a failure
        design, failures = None, [f"design: {_describe(error)}"]
    for analysis in plan.analyses if design is not None else ():
        try:
            tester = _tester(analysis, n, plan.parameters) \
                if analysis.make_tester is not None else None
            result = analysis.evaluate(tester, design)
        except Exception as error:  # noqa: BLE001 - recorded in the table, the sweep goes on
            failures.append(f"{analysis.name}: {_describe(error)}")
            continue
        values.update(result.values)
        iterations += result.iterations
        if result.failure:
            failures.append(f"{analysis.name}: {result.failure}")
    row = [float(values.get(column, math.nan)) for column in plan.columns]
    reason = " | ".join(failures).replace("\n", " ").replace("\r", " ")
    return (*row, FAILED if failures else OK, reason, iterations, time.perf_counter() - start)


def run_chunk(plan: Plan, chunk) -> list:
    """Evaluate ``chunk``, a list of ``(index, n, Lc, lam, R)``.

    Returns
    -------
    list of tuple
        ``(index, *evaluate_design(...))`` per design, in the chunk's order.
    """
    return [(index, *evaluate_design(plan, n, Lc, lam, R)) for index, n, Lc, lam, R in chunk]


def _describe(error: BaseException) -> str:
    return f"{type(error).__name__}: {error}"
