"""``kresling sweep``: results.csv with its documented columns, the optimum printed, resuming,
figures, and errors without tracebacks."""

import csv
import subprocess
import sys

import pytest

from kresling.cli import main

ARGS = ["sweep", "--n", "4", "6", "--grid", "3", "--metrics", "kb_ratio", "psi_ratio",
        "--workers", "2", "--no-progress"]


def test_writes_results_prints_the_optimum_and_resumes(tmp_path, capsys):
    out = tmp_path / "study"
    assert main([*ARGS, "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "18 designs: 18 computed, 0 read back" in printed
    assert "optimum (kb_ratio): n = 6, Lc = 15 mm, lam = 0.9: kb_ratio = 18.1243" in printed
    # the thesis's optimum is on a corner of the searched domain (largest n and lambda,
    # smallest Lc): said, with the way to widen it
    assert ("on the boundary of the searched domain (n max, Lc min, lam max): a better design "
            "may lie outside it; widen --n, --Lc or --lam") in printed
    assert "4  10.3459   15       0.9  Lc min, lam max" in printed  # maximum by n
    assert not (out / ".lock").exists()  # the lock goes with the sweep
    with open(out / "results.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 18
    assert {"n", "Lc", "lam", "kb_ratio", "psi_ratio", "status"} <= set(rows[0])
    assert {row["status"] for row in rows} == {"ok"}
    assert [row["n"] for row in rows] == ["4"] * 9 + ["6"] * 9

    assert main([*ARGS, "--out", str(out)]) == 0
    assert "18 designs: 0 computed, 18 read back" in capsys.readouterr().out
    assert sorted(p.name for p in out.iterdir()) == ["manifest.json", "results.csv"]


@pytest.mark.parametrize("executor, workers, said", [
    ("threads", "2", "2 threads"), ("threads", "1", "1 thread,"),
    ("processes", "1", "1 process,")])
def test_verbose_names_the_workers(tmp_path, capsys, executor, workers, said):
    assert main(["sweep", "--n", "8", "--grid", "2", "--metrics", "psi_ratio", "--no-progress",
                 "--verbose", "--executor", executor, "--workers", workers,
                 "--out", str(tmp_path)]) == 0
    err = capsys.readouterr().err
    assert f"metrics psi_ratio, {said}" in err and "workers" not in err.split("metrics")[1]
    assert not (tmp_path / ".lock").exists()


def test_the_lock_file_goes_when_the_store_closes_and_still_keeps_out_a_second_writer(tmp_path):
    from kresling.sweeps.store import SweepStore

    manifest = {"format": "test", "columns": ["n", "index"]}
    store = SweepStore.open(tmp_path, manifest)
    assert (tmp_path / ".lock").exists()
    with pytest.raises(ValueError, match="being written by another sweep"):
        SweepStore.open(tmp_path, manifest)
    store.close()
    assert not (tmp_path / ".lock").exists()
    again = SweepStore.open(tmp_path, manifest)  # reopened and locked anew
    with pytest.raises(ValueError, match="being written by another sweep"):
        SweepStore.open(tmp_path, manifest)
    again.close()
    assert not (tmp_path / ".lock").exists()


def test_plot_writes_the_figures(tmp_path, capsys):
    assert main(["sweep", "--n", "8", "--grid", "2", "--metrics", "psi_ratio", "--out",
                 str(tmp_path), "--plot", "--no-progress"]) == 0
    assert (tmp_path / "psi_ratio_maps.png").stat().st_size > 1000
    assert (tmp_path / "psi_ratio_max_by_n.png").stat().st_size > 1000


@pytest.mark.parametrize("extra, message", [
    (["--metrics", "kb_ratio", "bogus"], "unknown metric 'bogus'"),
    (["--n", "5"], "n = 5 is invalid for kb_ratio"),
    (["--workers", "0"], "workers = 0 is invalid"),
    (["--grid", "0"], "size = 0 is invalid"),
    (["--grid", "2", "3", "4"], "--grid takes one or two numbers"),
    (["--lam", "0.9", "0.7"], "increasing range"),
])
def test_bad_input_exits_2_without_traceback(tmp_path, capsys, extra, message):
    assert main(["sweep", "--grid", "2", "--out", str(tmp_path / "s"), *extra]) == 2
    err = capsys.readouterr().err
    assert message in err and "Traceback" not in err


def test_another_sweep_in_the_directory_is_refused(tmp_path):
    out = str(tmp_path / "s")
    command = [sys.executable, "-m", "kresling", "sweep", "--n", "4", "--metrics", "psi_ratio",
               "--no-progress", "--out", out]
    assert subprocess.run([*command, "--grid", "2"], capture_output=True).returncode == 0
    result = subprocess.run([*command, "--grid", "3"], capture_output=True, text=True)
    assert result.returncode == 2
    assert "holds a sweep with different parameters" in result.stderr
    assert "Traceback" not in result.stderr


def test_building_the_parser_does_not_import_the_analyses():
    # kresling.analyses takes about a second to import; every command builds the parser.
    code = ("import sys, kresling.cli; kresling.cli.build_parser(); "
            "print(sorted(m for m in ('kresling.analyses', 'scipy.optimize') if m in sys.modules))")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert result.stdout.strip() == "[]", result.stderr
