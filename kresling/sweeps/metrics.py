"""What a sweep can compute per design: a small registry of metrics.

A :class:`Metric` names the columns it adds to the results table and the :class:`Analysis`
that produces them. An analysis runs once per design however many of its metrics are asked
for (``snap_force``, ``energy_barrier`` and ``bistable`` share one snap-through run). An
analysis that needs a simulation has a *tester*: an object built once per polygon size n
(topology, sparsity pattern, symbolic factorisation) and reused for every design of that n.

Adding a metric is one entry in :data:`METRICS`; its functions must be importable at module
level, so that process pools and Dask workers can unpickle them. The analyses are imported
only when a tester is made: ``kresling.analyses`` takes about a second to import, and the
command line imports this module for every command.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import partial
from typing import TYPE_CHECKING, Any, Callable, Optional

from kresling.geometry import Design

if TYPE_CHECKING:  # pragma: no cover
    from kresling.analyses import BendingTester, LinearBendingTester, SnapThroughTester

__all__ = ["Analysis", "Evaluation", "Metric", "METRICS", "resolve_metrics", "require_even_n"]


@dataclass(frozen=True)
class Evaluation:
    """One analysis of one design.

    Attributes
    ----------
    values : dict of str to float
        The analysis's columns (NaN where it failed).
    iterations : int
        Newton iterations summed over the analysis's runs.
    failure : str
        Empty when it succeeded; otherwise why not (solver message or exception).
    """

    values: dict
    iterations: int = 0
    failure: str = ""


@dataclass(frozen=True)
class Analysis:
    """A computation on one design that yields one or more columns.

    Attributes
    ----------
    name : str
        Unique; with ``settings``, the key of its testers in a worker's cache.
    columns : tuple of str
        Everything ``evaluate`` returns, in table order.
    evaluate : callable
        ``evaluate(tester, design) -> Evaluation`` (``tester`` is ``None`` without a
        factory). Exceptions it raises are recorded as the design's failure.
    make_tester : callable, optional
        ``make_tester(n) -> tester``, called once per n in each worker thread.
    even_n : bool
        Needs an even n (the bending test pins opposite vertices).
    settings : dict
        What fixes its results (protocol, steps ...): recorded in a sweep's manifest.
    evaluate_chunk : callable, optional
        ``evaluate_chunk(tester, designs) -> list``: the same evaluations for many designs
        of one n at once (``designs`` a list of ``(n, Lc, lam, R)``), each an
        :class:`Evaluation` equal to ``evaluate``'s, or ``None`` where ``evaluate`` must be
        called on that design alone (it raised). Saves the per-design overhead in sweeps.
    """

    name: str
    columns: tuple
    evaluate: Callable[[Any, Design], Evaluation]
    make_tester: Optional[Callable[[int], Any]] = None
    even_n: bool = False
    settings: dict = field(default_factory=dict)
    evaluate_chunk: Optional[Callable[[Any, list], list]] = None


@dataclass(frozen=True)
class Metric:
    """A quantity a sweep can map.

    Attributes
    ----------
    name : str
        What users ask for (``--metrics kb_ratio``); also the table's main column for it.
    analysis : Analysis
    columns : tuple of str
        Columns it adds, ``name`` first.
    label : str
        Short label of the main column for plots, with its unit.
    description : str
    """

    name: str
    analysis: Analysis
    columns: tuple
    label: str = ""
    description: str = ""


def make_tester(kind: str, n: int, **options):
    """``kresling.analyses.<kind>(n, **options)``, e.g. ``make_tester("BendingTester", 8,
    protocol="5mm")``: the factory of the registry's analyses."""
    # Here, not at the top: kresling.analyses takes about a second to import, and the
    # command line imports this module for every command ('kresling --help' stays fast).
    from kresling import analyses

    return getattr(analyses, kind)(n, **options)


def _psi(_tester, design: Design) -> Evaluation:
    return Evaluation({"psi_ratio": design.psi_ratio, "psi_ext": design.psi_ext,
                       "psi_con": design.psi_con})


def _bending(suffix: str, tester: BendingTester, design: Design) -> Evaluation:
    extended, contracted = tester.run(design, 1), tester.run(design, 0)
    iterations = int(extended.iterations.sum() + contracted.iterations.sum())
    failed = [f"{r.state_name}: {r.message}" for r in (extended, contracted) if not r.completed]
    names = (f"kb_ratio{suffix}", f"kb_ext{suffix}", f"kb_con{suffix}")
    if failed:
        return Evaluation(dict.fromkeys(names, math.nan), iterations, "; ".join(failed))
    # The ratio exactly as BendingComparison.ratio computes it.
    values = (extended.stiffness / contracted.stiffness, extended.stiffness, contracted.stiffness)
    return Evaluation(dict(zip(names, values)), iterations)


def _bending_chunk(suffix: str, tester: BendingTester, designs: list) -> list:
    """:func:`_bending` of many designs in one call to the core (same values, bit for bit)."""
    names = (f"kb_ratio{suffix}", f"kb_ext{suffix}", f"kb_con{suffix}")
    out = []
    for pair in tester.run_both_states([(lam, Lc, R) for _n, Lc, lam, R in designs]):
        if pair is None:
            out.append(None)  # raised: evaluated alone, for the error
            continue
        k_ext, k_con, iterations, failed = pair
        if failed:
            out.append(Evaluation(dict.fromkeys(names, math.nan), iterations, "; ".join(failed)))
        else:
            out.append(Evaluation(dict(zip(names, (k_ext / k_con, k_ext, k_con))), iterations))
    return out


# The bending tests' adaptive increments and their error targets, passed explicitly so that
# the manifest records them (a map resumed across a change of either would mix two methods;
# kresling.analyses.bending.ADAPTIVE_TOLERANCE; the tests check they agree).
BENDING_ADAPTIVE_TOLERANCE = {"5mm": 1e-9, "0.001rad": 1e-8}


def _bending_analysis(protocol: str, suffix: str) -> Analysis:
    tolerance = BENDING_ADAPTIVE_TOLERANCE[protocol]
    return Analysis(f"bending_{protocol}", (f"kb_ratio{suffix}", f"kb_ext{suffix}",
                                            f"kb_con{suffix}"),
                    partial(_bending, suffix),
                    partial(make_tester, "BendingTester", protocol=protocol, adaptive=True,
                            adaptive_tolerance=tolerance),
                    even_n=True,
                    settings={"protocol": protocol, "cells": 4, "increments": "adaptive",
                              "adaptive_tolerance": tolerance},
                    evaluate_chunk=partial(_bending_chunk, suffix))


def _linear_bending(tester: LinearBendingTester, design: Design) -> Evaluation:
    extended, contracted = tester.run(design, 1), tester.run(design, 0)
    names = ("kb_ratio_linear", "kb_ext_linear", "kb_con_linear")
    if not (math.isfinite(extended) and math.isfinite(contracted)):
        return Evaluation(dict.fromkeys(names, math.nan), 0,
                          "the linearised specimen is a mechanism (K_B is NaN)")
    return Evaluation(dict(zip(names, (extended / contracted, extended, contracted))))


_SNAP_COLUMNS = ("snap_force", "snap_displacement", "energy_barrier", "bistable")


def _snap_through(tester: SnapThroughTester, design: Design) -> Evaluation:
    r = tester.run(design)
    iterations = int(r.iterations.sum())
    if not r.completed:
        return Evaluation(dict.fromkeys(_SNAP_COLUMNS, math.nan), iterations, r.message)
    # A monostable cell has no peak: its snap force is NaN with status ok (a result, not a
    # failure); bistable is 1.0 or 0.0.
    values = (r.snap_force, r.snap_displacement, r.energy_barrier, float(r.bistable))
    return Evaluation(dict(zip(_SNAP_COLUMNS, values)), iterations)


# The snap-through test's increments and their Newton start, passed explicitly so that the
# manifest records them (kresling.analyses.snap_through.DEFAULT_STEPS and
# DEFAULT_EXTRAPOLATION; the tests check they agree).
SNAP_STEPS = 100
SNAP_EXTRAPOLATION = 3
_PSI = Analysis("facet_angles", ("psi_ratio", "psi_ext", "psi_con"), _psi)
_LINEAR = Analysis("bending_linear", ("kb_ratio_linear", "kb_ext_linear", "kb_con_linear"),
                   _linear_bending, partial(make_tester, "LinearBendingTester"), even_n=True,
                   settings={"cells": 4, "model": "linearised at the stable state"})
_SNAP = Analysis("snap_through", _SNAP_COLUMNS, _snap_through,
                 partial(make_tester, "SnapThroughTester", steps=SNAP_STEPS,
                         extrapolation=SNAP_EXTRAPOLATION),
                 settings={"steps": SNAP_STEPS, "cells": 1, "extrapolation": SNAP_EXTRAPOLATION})
_BENDING_SMALL = _bending_analysis("0.001rad", "")
_BENDING_5MM = _bending_analysis("5mm", "_5mm")

#: Every metric a sweep knows, by name.
METRICS = {
    metric.name: metric for metric in (
        Metric("kb_ratio", _BENDING_SMALL, _BENDING_SMALL.columns, "K_B ratio (0.001 rad)",
               "K_B ratio extended/contracted at a 0.001 rad deflection (the thesis's study), "
               "with K_B of each state [N*m/rad]"),
        Metric("kb_ratio_5mm", _BENDING_5MM, _BENDING_5MM.columns, "K_B ratio (5 mm)",
               "K_B ratio and K_B of each state [N*m/rad] for the 5 mm protocol (Table 3)"),
        Metric("kb_ratio_linear", _LINEAR, _LINEAR.columns, "K_B ratio (linearised)",
               "K_B ratio and K_B of each state [N*m/rad] of the model linearised at the "
               "stable state (Appendix A)"),
        Metric("psi_ratio", _PSI, _PSI.columns, "facet-angle ratio Psi_ext / Psi_con",
               "facet-angle ratio Psi_ext/Psi_con, with Psi of each state [rad]"),
        Metric("snap_force", _SNAP, ("snap_force", "snap_displacement"),
               "snap-through force [N]", "first local maximum of the force driving one cell "
               "from extended to contracted [N], and its travel [mm] (NaN: no maximum)"),
        Metric("energy_barrier", _SNAP, ("energy_barrier",), "energy barrier [N*mm]",
               "strain energy at the unstable state [N*mm] (NaN: monostable)"),
        Metric("bistable", _SNAP, ("bistable",), "bistable (1) or not (0)",
               "1 if the released cell rests at a second stable state, else 0"),
    )
}


def resolve_metrics(names) -> tuple:
    """The :class:`Metric` objects for ``names`` (names or Metric objects), in order.

    Raises
    ------
    ValueError
        For no metrics, an unknown name (the message lists the known ones), or a repeat.
    """
    if isinstance(names, (str, Metric)):
        names = [names]
    if not isinstance(names, (list, tuple)) and not hasattr(names, "__iter__"):
        raise ValueError(f"metrics = {names!r} is invalid: must be a metric name or a list of "
                         f"them, from {', '.join(METRICS)}")
    names = list(names)
    if not names:
        raise ValueError("metrics is empty: name at least one of " + ", ".join(METRICS))
    metrics = []
    for name in names:
        if isinstance(name, Metric):
            metrics.append(name)
        elif isinstance(name, str) and name in METRICS:
            metrics.append(METRICS[name])
        else:
            raise ValueError(f"unknown metric {name!r}: must be one of {', '.join(METRICS)}")
    seen = [m.name for m in metrics]
    repeated = sorted({m for m in seen if seen.count(m) > 1})
    if repeated:
        raise ValueError(f"metric {repeated[0]!r} is named twice")
    return tuple(metrics)


def require_even_n(metrics, ns) -> None:
    """Raise ValueError if a metric needs an even n and ``ns`` holds an odd one."""
    odd = sorted({int(n) for n in ns if int(n) % 2})
    needs_even = [m.name for m in metrics if m.analysis.even_n]
    if odd and needs_even:
        raise ValueError(f"n = {odd[0]} is invalid for {needs_even[0]}: the bending test needs "
                         f"an even n (its pins are opposite vertices)")
