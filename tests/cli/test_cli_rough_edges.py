"""What a new user hit on the command line, one test each: infinite quantities in JSON, a
glob that picks up a file that is not a record, output paths checked before the work and
reported after it, one name per option in errors, an under-resolved snap force, the
manipulator's step range and unreachable targets, K_con > K_ext, partial results marked
as such, the pattern's extent beside its page, odd n in the bending test, Lc = 0 in the
bending path."""

from __future__ import annotations

import dataclasses
import glob
import json
import math

import numpy as np
import pytest

import kresling.analyses
from cli_helpers import run_kresling
from kresling import Design, data
from kresling.analyses import bending_stiffness, bending_test, snap_through
from kresling.analyses.paths import bending_path
from kresling.cli import main

BEND = ["bend", "--n", "4", "--lam", "0.7", "--Lc", "30", "--deflection-rad", "0.001"]


def test_design_json_writes_infinity_as_a_string(capsys):
    # Lc = 0 is a valid design whose Psi_con is 0, so Psi_ext / Psi_con is infinite.
    assert main(["design", "--n", "8", "--lam", "0.85", "--Lc", "0", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["Psi_ratio"] == "inf" and out["Psi_con"] == 0.0
    assert main(["design", "--n", "8", "--lam", "0.85", "--Lc", "0"]) == 0
    table = capsys.readouterr().out
    assert "[deg]" in table
    phi = next(line for line in table.splitlines() if line.startswith("phi "))
    assert "22.5" in phi.split()   # pi / 8 in degrees beside the radians


def test_fit_bending_glob_skips_the_truth_table(tmp_path):
    folder = data.path("examples/synthetic_bending/truth.csv").parent
    files = sorted(glob.glob(f"{folder}/*.csv"))   # as a shell expands DIR/*.csv
    assert any(f.endswith("truth.csv") for f in files)
    result = run_kresling("fit", "bending", *files, "--json", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "skipped" in result.stderr and "truth.csv" in result.stderr
    report = json.loads(result.stdout)
    records = [f for f in files if not f.endswith("truth.csv")]
    alone = json.loads(run_kresling("fit", "bending", *records, "--json", cwd=tmp_path).stdout)
    assert report == alone   # the same six trials fitted


def test_fit_error_names_the_cli_option_not_a_python_keyword(tmp_path):
    truth = str(data.path("examples/synthetic_bending/truth.csv"))
    result = run_kresling("fit", "bending", truth, cwd=tmp_path)
    assert result.returncode == 2 and "Traceback" not in result.stderr
    assert "--column displacement=HEADER" in result.stderr and "names=" not in result.stderr


def _no_analysis(*_args, **_kwargs):
    raise AssertionError("the analysis ran before the output path was checked")


@pytest.mark.parametrize("command, option", [
    (BEND, "--plot"), (["snap", "--n", "4", "--lam", "0.7", "--Lc", "30"], "--plot")])
def test_bad_output_path_fails_before_the_analysis(monkeypatch, capsys, command, option):
    monkeypatch.setattr(kresling.analyses, "bending_stiffness", _no_analysis)
    monkeypatch.setattr(kresling.analyses, "snap_through", _no_analysis)
    assert main([*command, option, "/nonexistent/dir/x.png"]) == 2
    err = capsys.readouterr().err
    assert option in err and "/nonexistent/dir" in err and "does not exist" in err


@pytest.mark.parametrize("command", [
    ["pattern", "--n", "8", "--lam", "0.8", "--Lc", "30", "-o", "/nonexistent/dir/x.svg"],
    ["sweep", "--n", "4", "--grid", "2", "--out", "/dev/null/x"],
    ["reproduce", "--quick", "--out", "/dev/null/x"],
    ["arm", "--table", "--plot", "/nonexistent/dir/x.png"],
])
def test_other_commands_check_outputs_first(capsys, command):
    assert main(command) == 2
    err = capsys.readouterr().err
    assert "/nonexistent/dir" in err or "/dev/null" in err
    assert "Traceback" not in err


def test_plot_says_what_it_wrote(tmp_path, capsys):
    target = tmp_path / "bend.png"
    assert main([*BEND, "--plot", str(target)]) == 0
    assert target.stat().st_size > 0
    assert f"wrote {target}" in capsys.readouterr().out
    target = tmp_path / "snap.png"
    assert main(["snap", "--n", "4", "--lam", "0.7", "--Lc", "30", "--plot", str(target)]) == 0
    assert f"wrote {target}" in capsys.readouterr().out


def test_errors_name_the_cli_option(capsys):
    # The library calls it deflection_angle; the command line --deflection-rad.
    assert main([*BEND[:-1], "1.5"]) == 2
    err = capsys.readouterr().err
    assert "--deflection-rad = 1.5 is invalid" in err and "deflection_angle" not in err


def test_snap_warns_when_the_peak_is_under_resolved(capsys):
    # n = 8, lambda = 0.9, Lc = 15 mm: with 3 increments the force peak (at 6.8 mm) falls
    # within the first increment of 13 mm, and the snap force comes out 29 % low.
    args = ["snap", "--n", "8", "--lam", "0.9", "--Lc", "15", "--json"]
    assert main([*args, "--steps", "3"]) == 0
    captured = capsys.readouterr()
    coarse = json.loads(captured.out)
    assert "under-resolved" in captured.err and "--steps" in captured.err
    assert coarse["resolution"]
    assert main(args) == 0
    captured = capsys.readouterr()
    fine = json.loads(captured.out)
    assert "under-resolved" not in captured.err and fine["resolution"] == ""
    assert coarse["snap_force"] / fine["snap_force"] - 1 < -0.2


def test_under_resolution_criterion_as_measured():
    # Against a 2000-increment reference: 3 or more increments before the peak give the
    # force within 0.25 % (no warning); fewer are flagged. Two designs of the measurement.
    for design, steps_ok, steps_bad in ((Design(8, 0.8, 30), 15, 8),
                                        (Design(10, 0.9, 15), 30, 10)):
        reference = snap_through(design, steps=2000).snap_force
        ok, bad = snap_through(design, steps=steps_ok), snap_through(design, steps=steps_bad)
        assert ok.increments_to_peak >= 3 and ok.resolution == ""
        assert ok.snap_force == pytest.approx(reference, rel=2.5e-3)
        assert bad.increments_to_peak < 3 and "under-resolved" in bad.resolution
    # A peak skipped entirely: the force is negative at the first increment.
    missed = snap_through(Design(10, 0.9, 15), steps=3)
    assert math.isnan(missed.snap_force) and "missed" in missed.resolution


def test_manipulator_k_range_and_unit(capsys):
    assert main(["manipulator", "--k", "100"]) == 2
    err = capsys.readouterr().err
    assert "--k = 100.0 is invalid: must be in [-30, 15] mm" in err
    assert main(["manipulator", "--k", "15"]) == 0   # the end of the range: l1 = 0
    capsys.readouterr()
    text = run_kresling("manipulator", "--help", cwd=".").stdout
    assert "--k MM" in text and "[mm]" in text


def test_manipulator_target_beyond_reach_exits_non_zero(capsys):
    assert main(["manipulator", "--target", "0", "0", "1000"]) == 1
    captured = capsys.readouterr()
    assert "NOT reachable" in captured.out and "beyond the arm's reach" in captured.err
    assert main(["manipulator", "--target", "0", "0", "1000", "--json"]) == 1
    assert json.loads(capsys.readouterr().out)["reachable"] is False


def test_manipulator_prints_bend_angles_in_degrees(capsys):
    assert main(["manipulator"]) == 0
    out = capsys.readouterr().out
    assert "bend [rad]" in out and "[deg]" in out


def test_k_con_above_k_ext_is_commented(monkeypatch, capsys):
    # Tall contracted specimens can come out stiffer than extended ones (n = 40, lambda = 0.9,
    # Lc = 15 mm: K_con 2.4-11.5 against K_ext 1.23 N*m/rad, the branch its bifurcating path
    # takes decided by rounding); here the states of a thesis design are swapped instead.
    assert main(BEND) == 0
    assert "K_con > K_ext" not in capsys.readouterr().out   # the thesis's kind: no note
    real = bending_stiffness

    def swapped(design, protocol, **options):
        result = real(design, protocol, **options)
        return dataclasses.replace(result, extended=result.contracted,
                                   contracted=result.extended)

    monkeypatch.setattr(kresling.analyses, "bending_stiffness", swapped)
    assert main(BEND + ["--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["ratio"] < 1 and any("K_con > K_ext" in note for note in out["notes"])


def _stopped_at(result, fraction, message="increment 4 failed (scripted)"):
    # The increments up to ``fraction`` of the travel, as a run that failed after them.
    keep = int(np.sum(np.abs(result.deflection) <= fraction * result.target_deflection * 1.001))
    arrays = {k: getattr(result, k)[:keep] for k in ("deflection", "force", "angle", "moment",
                                                      "iterations", "negative_eigenvalues")}
    return dataclasses.replace(result, completed=False, message=message, **arrays)


def test_partial_results_are_marked_everywhere(monkeypatch, capsys):
    # A contracted run that stops at 30 % of its travel (n = 200 once stopped at 21 %): the
    # table, the JSON and the Python result each say so, and the exit status is 1.
    real = bending_stiffness

    def stopping(design, protocol, **options):
        result = real(design, protocol, **options)
        return dataclasses.replace(result, contracted=_stopped_at(result.contracted, 0.3))

    monkeypatch.setattr(kresling.analyses, "bending_stiffness", stopping)
    assert main(BEND) == 1
    captured = capsys.readouterr()
    k_con = next(line for line in captured.out.splitlines() if line.startswith("K_con"))
    assert "PARTIAL" in k_con and "30%" in k_con
    ratio = next(line for line in captured.out.splitlines() if line.startswith("ratio"))
    assert "PARTIAL" in ratio
    k_ext = next(line for line in captured.out.splitlines() if line.startswith("K_ext"))
    assert "PARTIAL" not in k_ext
    assert "stopped at 30%" in captured.err
    assert main([*BEND, "--json"]) == 1
    out = json.loads(capsys.readouterr().out)
    assert out["completed"] is False
    assert out["partial"] == {"contracted": pytest.approx(0.3, abs=1e-3)}
    result = stopping(Design(4, 0.7, 30), "0.001rad")
    assert result.partial and result.contracted.partial and not result.extended.partial
    assert "PARTIAL" in repr(result) and "PARTIAL" in repr(result.contracted)
    assert "PARTIAL" not in repr(result.extended)


def test_a_real_failed_run_reports_its_travel():
    # A tolerance the solver cannot reach stops the run at its first increment.
    r = bending_test(Design(8, 0.8, 30), 0, tolerance=1e-14, max_iterations=3)
    assert r.partial and r.travel_fraction == 0.0 and "PARTIAL" in repr(r)
    s = snap_through(Design(8, 0.8, 30), tolerance=1e-14, max_iterations=3)
    assert s.partial and s.travel_fraction < 1 and s.summary()["partial"] is True
    assert "PARTIAL" in repr(s)
    assert "PARTIAL" not in repr(snap_through(Design(8, 0.8, 30)))


def test_pattern_reports_extent_and_page(tmp_path, capsys):
    svg = tmp_path / "cell.svg"
    assert main(["pattern", "--n", "8", "--lam", "0.8", "--Lc", "30", "-o", str(svg)]) == 0
    out = capsys.readouterr().out
    text = svg.read_text()
    page = [float(v) for v in (text.split('width="')[1].split("mm")[0],
                               text.split('height="')[1].split("mm")[0])]
    assert f"page {page[0]:.1f} x {page[1]:.1f} mm with 5 mm margins" in out
    assert f"pattern {page[0] - 10:.1f} x {page[1] - 10:.1f} mm" in out
    assert main(["pattern", "--n", "8", "--lam", "0.8", "--Lc", "30", "-o",
                 str(tmp_path / "cell.svg"), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["page_width_mm"] == pytest.approx(summary["width_mm"] + 10)
    assert summary["page_width_mm"] == pytest.approx(page[0], abs=1e-5)


def test_odd_n_in_the_bending_test_is_explained(capsys):
    assert main(["bend", "--n", "5", "--lam", "0.9", "--Lc", "15"]) == 2
    err = capsys.readouterr().err
    assert "must be even for the bending test" in err and "opposite" in err
    assert "snap-through test" in err
    assert main(["snap", "--n", "5", "--lam", "0.9", "--Lc", "15"]) == 0   # odd n is fine there


def test_bending_path_at_lc_zero_names_lc():
    with pytest.raises(ValueError, match="^Lc = 0.0 is invalid: must be > 0 for the bending "
                                         "test in the contracted state"):
        bending_path(Design(8, 0.8, 0), "contracted")
    assert np.isfinite(bending_path(Design(8, 0.8, 0), "extended", steps=2).force).all()


def _options(parser, name):
    import argparse

    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sub, subparser in action.choices.items():
                yield from _options(subparser, f"{name} {sub}".strip())
        elif action.option_strings:
            yield name, action


def test_every_numeric_option_says_its_unit():
    # A number on the command line is a length, a force, an angle, a stiffness ... or a
    # count or a ratio: the help says which.
    import re

    from kresling.cli import build_parser

    unit = re.compile(r"\[[^\]]+\]|\bcounts?\b|dimensionless|\bratio\b|RATIO|fraction|\bmm\b|"
                      r"dots per inch|\bindex\b|number of")
    missing = [f"{name} {action.option_strings[-1]}" for name, action in
               _options(build_parser(), "") if action.type in (int, float)
               and not action.choices and not unit.search(action.help or "")]
    assert not missing, missing


def test_fit_crease_table_has_units_and_degrees(capsys):
    runs = str(data.path("examples/synthetic_crease/runs.csv"))
    assert main(["fit", "crease", runs]) == 0
    header = capsys.readouterr().out.splitlines()[0].split()
    assert header[:5] == ["sample", "run", "k", "[N/rad]", "F1"]
    assert "beta1" in header and header[header.index("beta1") + 2] == "[deg]"


def test_default_steps_resolve_the_thesis_s_designs():
    # No false alarm: 100 increments leave at least 16 before the peak over the thesis's
    # space (measured on 4 x 21 x 19 designs; here a 4 x 5 x 5 subset).
    from kresling.analyses import SnapThroughTester

    for n in (4, 6, 8, 10):
        tester = SnapThroughTester(n)
        for lam in np.linspace(0.7, 0.9, 5):
            for Lc in np.linspace(15, 60, 5):
                r = tester.run(Design(n, lam, Lc))
                assert r.resolution == "", (n, lam, Lc, r.resolution)
                assert not r.has_peak or r.increments_to_peak > 15


def test_figures_of_partial_runs_say_so():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from kresling.analyses.plots import plot_moment_angle, plot_snap_through

    whole = bending_stiffness(Design(4, 0.7, 30), "0.001rad")
    stopped = dataclasses.replace(whole, contracted=_stopped_at(whole.contracted, 0.3))
    labels = [t.get_text() for t in plot_moment_angle(stopped).get_legend().get_texts()]
    assert sum("PARTIAL: stopped at 30%" in label for label in labels) == 1
    labels = [t.get_text() for t in plot_moment_angle(whole).get_legend().get_texts()]
    assert not any("PARTIAL" in label for label in labels)
    s = snap_through(Design(8, 0.8, 30), tolerance=1e-14, max_iterations=3)
    assert "PARTIAL" in plot_snap_through(s).get_title()
    assert "PARTIAL" not in plot_snap_through(snap_through(Design(8, 0.8, 30))).get_title()
    plt.close("all")


# -- the interactive pages of a run that stopped early --------------------------------------

def test_partial_paths_know_how_far_they_went():
    # A tolerance below round-off stops both paths early; completed paths reach 1. The
    # fractions against the travel computed from the design.
    from kresling.analyses.paths import snap_through_path

    d = Design(8, 0.8, 30)
    # 25 iterations an increment (the rejection bound) get some increments done before the
    # tolerance stops the path; Newton stops at max_iterations, so 3 would get none.
    snap = snap_through_path(d, steps=100, tolerance=1e-14, max_iterations=25)
    assert snap.partial and not snap.path.completed and len(snap.travel) > 0
    assert snap.travel_fraction == pytest.approx(snap.travel[-1] / (d.Le - d.Lc), rel=1e-12)
    assert 0 < snap.travel_fraction < 1
    whole = snap_through_path(d, steps=20)
    assert not whole.partial and whole.travel_fraction == 1.0
    assert whole.travel[-1] == pytest.approx(d.Le - d.Lc, rel=1e-9)
    # no increment at all: an empty path, not an error
    bent = bending_path(d, 0, "0.001rad", tolerance=1e-14, max_iterations=3)
    assert bent.partial and bent.travel_fraction == 0.0 and len(bent.force) == 0
    bent = bending_path(d, 0, "0.001rad")
    assert not bent.partial and bent.travel_fraction == 1.0
    assert bent.target_deflection == pytest.approx(2 * d.Lc * math.tan(0.001), rel=1e-12)


def test_python_views_of_runs_that_stopped_say_so():
    from kresling.analyses.paths import snap_through_path
    from kresling.view import view_bending, view_path, view_snap_through

    d = Design(8, 0.8, 30)
    # 25 iterations an increment get the snap-through some increments before the tolerance
    # stops it (Newton stops at max_iterations; 3 get none, which the bending run shows).
    snap_solver = {"tolerance": 1e-14, "max_iterations": 25}
    solver = {"tolerance": 1e-14, "max_iterations": 3}
    path = snap_through_path(d, steps=100, **snap_solver)
    title = view_snap_through(d, steps=100, **snap_solver).layout.title.text
    assert f"PARTIAL: stopped at {path.travel_fraction:.0%} of the travel" in title
    assert "PARTIAL" in view_snap_through(d, path=path, title="mine").layout.title.text
    title = view_path(path.specimen, path.path).layout.title.text
    assert f"PARTIAL: the solver stopped after {len(path.travel)} increments" in title
    assert path.path.message.split(" (")[0] in title
    # A bending run that converged no increment: both states at 0 %, the page still drawn.
    fig = view_bending(d, "0.001rad", **solver)
    assert ("PARTIAL: the extended run stopped at 0% of its travel; the contracted run "
            "stopped at 0% of its travel") in fig.layout.title.text and len(fig.frames) == 1
    # A contracted run stopped at 30 % (scripted, as above): its curve and the title only.
    whole = bending_stiffness(Design(4, 0.7, 30), "0.001rad")
    stopped = dataclasses.replace(whole, contracted=_stopped_at(whole.contracted, 0.3))
    paths = [bending_path(Design(4, 0.7, 30), state, "0.001rad") for state in (1, 0)]
    fig = view_bending(Design(4, 0.7, 30), paths=paths, results=stopped)
    title = fig.layout.title.text
    assert "PARTIAL: the contracted run stopped at 30% of its travel" in title
    assert "extended run" not in title
    names = [t.name for t in fig.data if t.type == "scatter" and t.mode == "lines"]
    assert [("PARTIAL" in name) for name in names] == [False, True]
    for fig in (view_bending(Design(4, 0.7, 30), paths=paths, results=whole),
                view_snap_through(d, steps=20), view_path(path.specimen, snap_through_path(
                    d, steps=20).path)):
        assert "PARTIAL" not in fig.layout.title.text


def test_cli_view_pages_of_runs_that_stopped_say_so(monkeypatch, tmp_path, capsys):
    # The page says what the table says: a contracted run stopped at 30 % (scripted), and a
    # snap-through run stopped by a tolerance below round-off (a real stop).
    from view_cases import page_figure

    real_bending, real_snap = bending_stiffness, snap_through

    def stopping(design, protocol, **options):
        result = real_bending(design, protocol, **options)
        return dataclasses.replace(result, contracted=_stopped_at(result.contracted, 0.3))

    def failing(design, **options):
        return real_snap(design, **options, tolerance=1e-14, max_iterations=3)

    monkeypatch.setattr(kresling.analyses, "bending_stiffness", stopping)
    assert main([*BEND, "--view", str(tmp_path / "bend.html")]) == 1
    _, layout, _ = page_figure((tmp_path / "bend.html").read_text(encoding="utf-8"))
    assert "PARTIAL: the contracted run stopped at 30% of its travel" in layout["title"]["text"]
    monkeypatch.setattr(kresling.analyses, "snap_through", failing)
    fraction = failing(Design(8, 0.8, 30), steps=40).travel_fraction
    assert fraction < 1
    assert main(["snap", "--n", "8", "--lam", "0.8", "--Lc", "30", "--steps", "40", "--view",
                 str(tmp_path / "snap.html")]) == 1
    _, layout, _ = page_figure((tmp_path / "snap.html").read_text(encoding="utf-8"))
    assert f"PARTIAL: stopped at {fraction:.0%} of the travel" in layout["title"]["text"]
    capsys.readouterr()


def test_a_snap_through_view_of_a_path_with_no_increment_is_drawn():
    # Newton stops at max_iterations = 3 before the 1e-14 tolerance: no increment converges,
    # and the page says so instead of failing on its own bookkeeping.
    from kresling.view import view_snap_through

    fig = view_snap_through(Design(8, 0.8, 30), steps=100, tolerance=1e-14, max_iterations=3)
    assert "PARTIAL" in fig.layout.title.text
