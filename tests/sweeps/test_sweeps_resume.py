"""Interrupted sweeps resume with nothing recomputed and nothing lost: a process killed with
SIGKILL, a line cut short by a crash, Ctrl-C, a worker process that dies; and a directory
holding another sweep is refused."""

import csv
import json
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import sweep_fakes
from kresling.sweeps import design_grid, sweep
from kresling.sweeps.store import SweepStore

GRID = design_grid(size=10)  # 400 designs
COMPARED = ("n", "Lc", "lam", "R", "kb_ratio", "kb_ext", "kb_con", "psi_ratio", "status",
            "reason", "iterations", "index")
SCRIPT = textwrap.dedent("""
    import sys
    from kresling.sweeps import design_grid, sweep
    sweep(design_grid(size=10), ["kb_ratio", "psi_ratio"], workers=1, chunk_size=2,
          out=sys.argv[1], progress=False)
""")


def data_rows(path) -> int:
    return max(path.read_bytes().count(b"\n") - 1, 0) if path.exists() else 0


def assert_same(a, b, columns=COMPARED):
    for column in columns:
        assert a[column].tolist() == b[column].tolist(), column


@pytest.fixture(scope="module")
def reference():
    return sweep(GRID, ["kb_ratio", "psi_ratio"], workers=2, progress=False)


def test_killed_process_resumes_with_nothing_recomputed(tmp_path, reference):
    out = tmp_path / "sweep"
    process = subprocess.Popen([sys.executable, "-c", SCRIPT, str(out)])
    deadline = time.monotonic() + 60
    while data_rows(out / "results.csv") < 40 and process.poll() is None:
        assert time.monotonic() < deadline, "the sweep wrote nothing in 60 s"
        time.sleep(0.005)
    process.send_signal(signal.SIGKILL)
    process.wait(timeout=30)
    on_disk = data_rows(out / "results.csv")
    assert 40 <= on_disk < len(GRID), "killed too late to test resuming"
    assert not json.loads((out / "manifest.json").read_text())["complete"]

    resumed = sweep(GRID, ["kb_ratio", "psi_ratio"], workers=2, out=out, progress=False)
    assert resumed.attrs["loaded"] == on_disk
    assert resumed.attrs["computed"] == len(GRID) - on_disk
    assert_same(resumed, reference)
    assert json.loads((out / "manifest.json").read_text())["complete"]

    again = sweep(GRID, ["kb_ratio", "psi_ratio"], workers=2, out=out, progress=False)
    assert again.attrs["computed"] == 0 and again.attrs["loaded"] == len(GRID)
    assert_same(again, resumed, COMPARED + ("seconds",))  # read back bit for bit


def test_a_line_cut_short_is_dropped_and_recomputed(tmp_path, reference, caplog):
    out = tmp_path / "sweep"
    grid = design_grid((4,), 10)
    first = sweep(grid, ["kb_ratio", "psi_ratio"], workers=1, out=out, progress=False)
    path = out / "results.csv"
    lines = path.read_bytes().splitlines(keepends=True)
    path.write_bytes(b"".join(lines[:51]) + lines[51][:17])  # header, 50 rows, a partial one
    resumed = sweep(grid, ["kb_ratio", "psi_ratio"], workers=1, out=out, progress=False)
    assert resumed.attrs["loaded"] == 50 and resumed.attrs["computed"] == 50
    assert "incomplete last line" in caplog.text
    assert_same(resumed, first)
    assert data_rows(path) == 100


def test_ctrl_c_keeps_finished_chunks(tmp_path):
    out, grid = tmp_path / "sweep", design_grid((4, 6), 6)
    sweep_fakes.INTERRUPT_AT[:] = [(6, 15.0, 0.7)]  # the first design of n = 6
    try:
        with pytest.raises(KeyboardInterrupt):
            sweep(grid, [sweep_fakes.INTERRUPTING], workers=1, chunk_size=4, out=out,
                  progress=False)
    finally:
        sweep_fakes.INTERRUPT_AT.clear()
    # Every chunk of n = 4 (designs 0-35) was saved, none of the interrupted chunk (36-39).
    # Two chunks are kept in flight per worker: the next one (40-43) may have finished before
    # the interruption reached the sweep, and a finished chunk is kept too.
    with open(out / "results.csv", newline="") as results:
        saved = sorted(int(row["index"]) for row in csv.DictReader(results))
    assert saved in (list(range(36)), list(range(36)) + list(range(40, 44)))
    assert not (out / ".lock").exists()  # unlocked and removed on the way out
    resumed = sweep(grid, [sweep_fakes.INTERRUPTING], workers=1, out=out, progress=False)
    assert resumed.attrs["loaded"] == len(saved)
    assert resumed.attrs["computed"] == len(grid) - len(saved)
    assert resumed["fake"].tolist() == [d.psi_ratio for d in grid]


def test_a_worker_process_that_dies_costs_only_its_design(tmp_path):
    grid = design_grid((4,), 3)  # (4, 60, 0.9) kills its worker process
    result = sweep(grid, [sweep_fakes.CRASHING], workers=2, executor="processes",
                   chunk_size=3, out=tmp_path / "sweep", progress=False)
    failed = result.take(~result.ok)
    assert len(failed) == 1 and (failed["Lc"][0], failed["lam"][0]) == (60.0, 0.9)
    assert failed["reason"][0].startswith("its worker was lost twice")
    assert np.isfinite(result.take(result.ok)["fake"]).all() and result.ok.sum() == 8


@pytest.mark.parametrize("change, message", [
    (dict(designs=design_grid((4,), 4)), r"designs: 9 designs \(grid .*size \[3, 3\].* there, "
                                         r"16 designs \(grid .*size \[4, 4\]"),
    (dict(metrics=["psi_ratio", "kb_ratio"]), "metrics"),
])
def test_a_directory_of_another_sweep_is_refused(tmp_path, change, message):
    out = tmp_path / "sweep"
    sweep(design_grid((4,), 3), ["psi_ratio"], out=out, progress=False)
    arguments = dict(designs=design_grid((4,), 3), metrics=["psi_ratio"])
    arguments.update(change)
    before = (out / "results.csv").read_bytes()
    with pytest.raises(ValueError, match="holds a sweep with different parameters .*" + message):
        sweep(arguments["designs"], arguments["metrics"], out=out, progress=False)
    assert (out / "results.csv").read_bytes() == before


def test_a_bending_map_of_another_increments_method_is_not_resumed(tmp_path):
    # A K_B map written when the bending test took fixed increments (its manifest's settings
    # name no increments) is not completed with adaptive ones: the two differ by a few 1e-9.
    out = tmp_path / "sweep"
    designs = design_grid((4,), 2)
    sweep(designs, ["kb_ratio"], out=out, progress=False)
    manifest = json.loads((out / "manifest.json").read_text())
    settings = manifest["analyses"]["bending_0.001rad"]
    assert settings["increments"] == "adaptive" and settings["adaptive_tolerance"] == 1e-8
    del settings["increments"], settings["adaptive_tolerance"]
    (out / "manifest.json").write_text(json.dumps(manifest))
    with pytest.raises(ValueError, match="holds a sweep with different parameters .*analyses"):
        sweep(designs, ["kb_ratio"], out=out, progress=False)


def test_results_without_a_manifest_are_refused(tmp_path):
    (tmp_path / "results.csv").write_text("n,Lc,lam\n")
    with pytest.raises(ValueError, match="no manifest.json"):
        sweep(design_grid((4,), 2), ["psi_ratio"], out=tmp_path, progress=False)


def test_two_sweeps_cannot_write_one_directory(tmp_path):
    grid = design_grid((4,), 2)
    manifest = {"format": "test", "columns": ["n", "index"]}
    store = SweepStore.open(tmp_path, manifest)
    try:
        with pytest.raises(ValueError, match="being written by another sweep"):
            sweep(grid, ["psi_ratio"], out=tmp_path, progress=False)
    finally:
        store.close()


def test_the_same_designs_made_another_way_resume(tmp_path):
    grid = design_grid((4,), 3)
    sweep(grid, ["psi_ratio"], out=tmp_path, progress=False)
    as_list = list(grid)  # same values, described as a list in the manifest
    assert sweep(as_list, ["psi_ratio"], out=tmp_path, progress=False).attrs["computed"] == 0
