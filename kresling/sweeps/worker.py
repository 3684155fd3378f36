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
        result = _evaluate(plan, analysis, n, design, failures)
        if result is not None:
            iterations += _collect(analysis, result, values, failures)
    return (*_row(plan, values, failures, iterations), time.perf_counter() - start)


def run_chunk(plan: Plan, chunk) -> list:
    """Evaluate ``chunk``, a list of ``(index, n, Lc, lam, R)``.

    Consecutive designs of one n go through the analyses that can evaluate many designs at
    once (``Analysis.evaluate_chunk``: one call into the core instead of one per design and
    state) and one by one through the others; the values are the same as
    :func:`evaluate_design`'s. A design such an analysis could not take (its construction or
    a run raised) is evaluated alone, so that its reason reads the same. The ``seconds`` of
    a design evaluated in a group are the group's time shared equally, plus its own.

    Returns
    -------
    list of tuple
        ``(index, *evaluate_design(...))`` per design, in the chunk's order.
    """
    if not any(a.evaluate_chunk is not None for a in plan.analyses):
        return [(index, *evaluate_design(plan, n, Lc, lam, R))
                for index, n, Lc, lam, R in chunk]
    out, start = [], 0
    while start < len(chunk):
        end = start + 1
        while end < len(chunk) and chunk[end][1] == chunk[start][1]:
            end += 1
        out += _run_group(plan, chunk[start:end])
        start = end
    return out


def _run_group(plan: Plan, group) -> list:
    """:func:`run_chunk` for designs of one n."""
    n = group[0][1]
    start = time.perf_counter()
    designs = [(n, Lc, lam, R) for _index, _n, Lc, lam, R in group]
    batched = []  # per analysis: its evaluations, or None (evaluated design by design)
    for analysis in plan.analyses:
        evaluations = None
        if analysis.evaluate_chunk is not None:
            try:
                evaluations = analysis.evaluate_chunk(_tester(analysis, n, plan.parameters),
                                                      designs)
            except Exception:  # noqa: BLE001 - every design is then evaluated alone
                evaluations = [None] * len(group)
        batched.append(evaluations)
    shared = (time.perf_counter() - start) / len(group)
    rows = []
    for k, (index, _n, Lc, lam, R) in enumerate(group):
        own = time.perf_counter()
        row = _combine(plan, batched, k, n, Lc, lam, R)
        if row is None:  # an analysis could not take it: alone, as evaluate_design would
            rows.append((index, *evaluate_design(plan, n, Lc, lam, R)))
            continue
        rows.append((index, *row, shared + time.perf_counter() - own))
    return rows


def _combine(plan: Plan, batched: list, k: int, n: int, Lc: float, lam: float, R: float):
    """Design ``k`` of a group as :func:`evaluate_design` reports it (without the seconds),
    from the batched evaluations and the other analyses run here; None if a batched
    analysis has no evaluation of it or its Design cannot be built."""
    if any(evaluations is not None and evaluations[k] is None for evaluations in batched):
        return None
    values, failures, iterations, design = {}, [], 0, None
    for analysis, evaluations in zip(plan.analyses, batched):
        if evaluations is not None:
            result = evaluations[k]
        else:
            try:
                if design is None:
                    design = Design(n, lam, Lc, R)
            except Exception:  # noqa: BLE001 - evaluate_design reports it
                return None
            result = _evaluate(plan, analysis, n, design, failures)
            if result is None:
                continue
        iterations += _collect(analysis, result, values, failures)
    return _row(plan, values, failures, iterations)


def _evaluate(plan: Plan, analysis, n: int, design: Design, failures: list):
    """One analysis of one design; None, with the failure appended, if it raised (the
    table records it and the sweep goes on)."""
    try:
        tester = _tester(analysis, n, plan.parameters) \
            if analysis.make_tester is not None else None
        return analysis.evaluate(tester, design)
    except Exception as error:  # noqa: BLE001 - recorded in the table
        failures.append(f"{analysis.name}: {_describe(error)}")
        return None


def _collect(analysis, result, values: dict, failures: list) -> int:
    """Add an evaluation's values and failure to the design's; its Newton iterations."""
    values.update(result.values)
    if result.failure:
        failures.append(f"{analysis.name}: {result.failure}")
    return result.iterations


def _row(plan: Plan, values: dict, failures: list, iterations: int) -> tuple:
    """The values of ``plan.columns``, status, one-line reason and iterations of a design."""
    row = [float(values.get(column, math.nan)) for column in plan.columns]
    reason = " | ".join(failures).replace("\n", " ").replace("\r", " ")
    return (*row, FAILED if failures else OK, reason, iterations)


def _describe(error: BaseException) -> str:
    return f"{type(error).__name__}: {error}"
