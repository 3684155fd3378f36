"""sweep(): results equal single-design analyses exactly, on threads and processes; failures
are rows, not crashes; bad input is refused."""

import math
from concurrent.futures import ThreadPoolExecutor
from functools import partial

import numpy as np
import pytest

import sweep_fakes
from kresling import Design
from kresling.analyses import bending_stiffness, linear_bending_stiffness, snap_through
from kresling.sweeps import METRICS, Analysis, Metric, design_grid, sweep
from kresling.sweeps import metrics
from kresling.sweeps.metrics import resolve_metrics
from kresling.sweeps.worker import evaluate_design, make_plan, run_chunk

GRID = design_grid(size=5)  # 5 x 5 x 4: the grid of the exactness checks
VALUE_COLUMNS = ("kb_ratio", "kb_ext", "kb_con", "psi_ratio", "psi_ext", "psi_con")


@pytest.fixture(scope="module")
def table():
    return sweep(GRID, ["kb_ratio", "psi_ratio"], workers=2, progress=False)


def test_columns_and_order(table):
    assert table.columns == ("n", "Lc", "lam", "R", *VALUE_COLUMNS, "status", "reason",
                             "iterations", "seconds", "index")
    assert len(table) == 100 and table["index"].tolist() == list(range(100))
    assert table["n"].tolist() == GRID.n.tolist() and table["Lc"].tolist() == GRID.Lc.tolist()
    assert (table["status"] == "ok").all() and (table["reason"] == "").all()
    assert table.attrs["computed"] == 100 and table.attrs["loaded"] == 0


def test_equals_single_design_analyses_exactly(table):
    for i, design in enumerate(GRID):
        single = bending_stiffness(design, "0.001rad")
        assert table["kb_ratio"][i] == single.ratio
        assert table["kb_ext"][i] == single.extended.stiffness
        assert table["kb_con"][i] == single.contracted.stiffness
        assert table["iterations"][i] == (single.extended.iterations.sum()
                                          + single.contracted.iterations.sum())
        assert table["psi_ratio"][i] == design.psi_ratio
        assert table["psi_con"][i] == design.psi_con


def test_processes_and_any_executor_give_the_same_table(table):
    part = design_grid((4, 10), 3)
    by_threads = sweep(part, ["kb_ratio"], workers=1, progress=False)
    by_processes = sweep(part, ["kb_ratio"], workers=2, executor="processes", progress=False)
    with ThreadPoolExecutor(3) as pool:
        by_pool = sweep(part, ["kb_ratio"], executor=pool, chunk_size=1, progress=False)
    for other in (by_processes, by_pool):
        for column in ("kb_ratio", "kb_ext", "kb_con", "iterations", "status"):
            assert other[column].tolist() == by_threads[column].tolist()
    # A design shared by two grids gets the same number in both.
    corner = dict(n=10, Lc=15.0, lam=0.9)
    assert by_threads.where(**corner)["kb_ratio"][0] == table.where(**corner)["kb_ratio"][0]


def test_a_5mm_metric_equals_the_5mm_analysis():
    design = Design(6, 0.8, 40)
    result = sweep([design], ["kb_ratio_5mm"], workers=1, progress=False)
    assert result.columns[4:7] == ("kb_ratio_5mm", "kb_ext_5mm", "kb_con_5mm")
    assert result["kb_ratio_5mm"][0] == bending_stiffness(design, "5mm").ratio


def test_snap_through_and_linearised_metrics_equal_their_analyses():
    grid = design_grid((4, 10), 3)
    result = sweep(grid, ["snap_force", "energy_barrier", "bistable", "kb_ratio_linear"],
                   workers=2, progress=False)
    assert result.columns[4:11] == ("snap_force", "snap_displacement", "energy_barrier",
                                    "bistable", "kb_ratio_linear", "kb_ext_linear",
                                    "kb_con_linear")
    assert result.ok.all()
    for i, design in enumerate(grid):
        snap = snap_through(design)
        for column in ("snap_force", "snap_displacement", "energy_barrier"):
            assert result[column][i] == getattr(snap, column) or \
                (math.isnan(result[column][i]) and math.isnan(getattr(snap, column)))
        assert result["bistable"][i] == float(snap.bistable)
        assert result["iterations"][i] == snap.iterations.sum()  # the linear model iterates not
        assert result["kb_con_linear"][i] == linear_bending_stiffness(design, 0)
    # The monostable corner of n = 10 has no snap force: NaN, and still status "ok".
    corner = result.where(n=10, Lc=60.0, lam=0.7)
    assert math.isnan(corner["snap_force"][0]) and corner["bistable"][0] == 0.0
    assert corner["status"][0] == "ok"


def test_failed_designs_are_recorded_and_the_sweep_goes_on():
    grid = design_grid((4, 6), 3)
    result = sweep(grid, [sweep_fakes.FAILING], workers=2, progress=False)
    failed = result.take(result["status"] == "failed")
    assert len(failed) == 4  # (15, 0.9) and (15, 0.7) for each n
    raised = failed.where(lam=0.9)
    assert all(r.startswith("fake_failing: RuntimeError: scripted failure second line")
               for r in raised["reason"])  # one line: newlines replaced
    assert all("did not converge (scripted)" in r for r in failed.where(lam=0.7)["reason"])
    assert np.isnan(failed["fake"]).all()
    ok = result.take(result.ok)
    assert len(ok) == 14 and np.isfinite(ok["fake"]).all() and (ok["reason"] == "").all()
    assert failed.where(lam=0.7)["iterations"].tolist() == [3, 3]
    with pytest.raises(ValueError, match="no successful design"):
        result.where(Lc=15.0, lam=0.9).best("fake")


def test_metrics_sharing_an_analysis_run_it_once():
    calls = []
    evaluate = METRICS["psi_ratio"].analysis.evaluate

    def counting(tester, design):
        calls.append(design)
        return evaluate(tester, design)

    analysis = Analysis("counting", ("psi_ratio", "psi_ext", "psi_con"), counting)
    ratio = Metric("ratio", analysis, ("psi_ratio",))
    extended = Metric("ext", analysis, ("psi_ext",))
    result = sweep(design_grid((6,), 2), [ratio, extended], workers=1, progress=False)
    assert len(calls) == 4
    assert result.columns[4:6] == ("psi_ratio", "psi_ext")
    assert result["psi_ext"].tolist() == [d.psi_ext for d in design_grid((6,), 2)]


@pytest.mark.parametrize("kwargs, message", [
    (dict(metrics=["kb_ratio", "nope"]), "unknown metric 'nope'"),
    (dict(metrics=[]), "metrics is empty"),
    (dict(metrics=["psi_ratio", "psi_ratio"]), "named twice"),
    (dict(workers=0), r"workers = 0 is invalid: must be an integer >= 1"),
    (dict(workers=1.5), r"workers = 1.5 is invalid"),
    (dict(executor="gpu"), "executor = 'gpu' is invalid"),
    (dict(executor=object()), "executor = .* is invalid"),
])
def test_bad_arguments(kwargs, message):
    arguments = dict(metrics=["psi_ratio"], progress=False)
    arguments.update(kwargs)
    with pytest.raises(ValueError, match=message):
        sweep(design_grid((6,), 2), **arguments)


def test_odd_n_refused_for_bending_metrics_only():
    odd = design_grid((5, 6), 2)
    with pytest.raises(ValueError, match="n = 5 is invalid for kb_ratio: .* even n"):
        sweep(odd, ["psi_ratio", "kb_ratio"], progress=False)
    assert math.isfinite(sweep(odd, ["psi_ratio"], progress=False)["psi_ratio"][0])


def test_empty_designs_refused():
    with pytest.raises(ValueError, match="empty"):
        sweep([], ["psi_ratio"], progress=False)


def test_the_registry_pins_the_analyses_defaults():
    from kresling.analyses.bending import ADAPTIVE_TOLERANCE, adaptive_by_default
    from kresling.analyses.snap_through import DEFAULT_EXTRAPOLATION, DEFAULT_STEPS
    from kresling.sweeps.metrics import (BENDING_ADAPTIVE_TOLERANCE, SNAP_EXTRAPOLATION,
                                         SNAP_STEPS)

    assert SNAP_STEPS == DEFAULT_STEPS and SNAP_EXTRAPOLATION == DEFAULT_EXTRAPOLATION
    assert BENDING_ADAPTIVE_TOLERANCE == ADAPTIVE_TOLERANCE
    assert all(adaptive_by_default(protocol, 2) for protocol in ADAPTIVE_TOLERANCE)
    assert METRICS["kb_ratio"].analysis.settings == {
        "protocol": "0.001rad", "cells": 4, "increments": "adaptive", "adaptive_tolerance": 1e-8}
    assert METRICS["kb_ratio_5mm"].analysis.settings["adaptive_tolerance"] == 1e-9


def _same_row(got, expected):
    """Rows equal except the seconds (NaN equal to NaN)."""
    return [repr(v) for v in got[:-1]] == [repr(v) for v in expected[:-1]]


def test_chunks_evaluate_exactly_as_single_designs_failures_included():
    # run_chunk hands consecutive designs of one n to the bending analysis at once; each row
    # must be evaluate_design's, bit for bit: a design the core refuses (lam outside (0.5,
    # 1), Lc nearly flat) is rerun alone for its reason; psi_ratio runs design by design.
    plan = make_plan(resolve_metrics(["kb_ratio", "psi_ratio"]))
    chunk = [(0, 6, 20.0, 0.8, 30.0), (1, 6, 20.0, 0.4, 30.0), (2, 6, 1e-9, 0.8, 30.0),
             (3, 6, 15.0, 0.9, 30.0), (4, 8, 30.0, 0.8, 30.0), (5, 6, 25.0, 0.75, 30.0)]
    rows = run_chunk(plan, chunk)
    assert [row[0] for row in rows] == [0, 1, 2, 3, 4, 5]
    for row, (_index, n, Lc, lam, R) in zip(rows, chunk):
        assert _same_row(row[1:], evaluate_design(plan, n, Lc, lam, R)), row
    assert [row[-4] for row in rows] == ["ok", "failed", "failed", "ok", "ok", "ok"]
    assert rows[1][-3].startswith("design: ValueError: lam = 0.4")


def test_chunks_report_runs_that_stop_early_as_single_designs_do():
    # Every increment rejected (reject_iterations=1): both runs stop at the first, partial.
    analysis = Analysis("bending_one_iteration", METRICS["kb_ratio"].analysis.columns,
                        partial(metrics._bending, ""),
                        partial(metrics.make_tester, "BendingTester", protocol="0.001rad",
                                reject_iterations=1, max_bisections=1),
                        even_n=True, evaluate_chunk=partial(metrics._bending_chunk, ""))
    plan = make_plan([Metric("kb_ratio", analysis, analysis.columns)])
    chunk = [(0, 6, 20.0, 0.8, 30.0), (1, 6, 15.0, 0.9, 30.0)]
    rows = run_chunk(plan, chunk)
    for row, (_index, n, Lc, lam, R) in zip(rows, chunk):
        assert row[-4] == "failed" and "extended: increment 1" in row[-3]
        assert _same_row(row[1:], evaluate_design(plan, n, Lc, lam, R)), row
