"""A run's files written as its path goes: what a run killed partway leaves (history.csv,
displacements.csv, path.fold with its frames, summary.json saying it did not complete), the
rows the same as the finished run's, and the progress line a run in a log or batch job
prints at its start."""

from __future__ import annotations

import csv
import json
import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

from kresling.simulate import simulate
from public_files import ORIGAMI_SIMULATOR

POPUP = ORIGAMI_SIMULATOR / "popupSimple.svg"


def _fold_problem(steps):
    return {"pattern": {"file": str(POPUP)},
            "actuation": [{"family": "fold", "fold_angle_deg": "file"}],
            "analysis": {"method": "fold", "steps": steps}}


def _problem_file(tmp_path, steps):
    path = tmp_path / "popup.toml"
    path.write_text(f'[pattern]\nfile = "{POPUP.as_posix()}"\n\n[[actuation]]\n'
                    'family = "fold"\nfold_angle_deg = "file"\n\n'
                    f'[analysis]\nmethod = "fold"\nsteps = {steps}\n')
    return path


def _rows(path):
    with open(path, newline="") as handle:
        return list(csv.DictReader(handle))


def test_the_files_hold_the_path_so_far_at_every_increment(tmp_path):
    seen = []

    def look(state):   # the files as a kill at this increment would leave them
        history = _rows(tmp_path / "history.csv")
        summary = json.loads((tmp_path / "summary.json").read_text())
        fold = tmp_path / "path.fold"   # (written from the first increment on)
        frames = json.loads(fold.read_text()).get("file_frames", []) if fold.exists() else []
        seen.append((state.step, len(history), len(_rows(tmp_path / "displacements.csv")),
                     summary, len(frames)))
        return False

    sim = simulate(_fold_problem(8), stop=look, progress=False, stream=tmp_path)
    assert sim.completed and sim.path.num_steps == 8
    for step, history, displacements, summary, frames in seen:
        assert history == displacements == step   # the rows: every increment, at once
        assert summary["completed"] is False and summary["interrupted"] is True
        assert summary["partial"] is True
        # summary.json and path.fold are one snapshot (rewritten together, at most every
        # increment, path.fold first): as many frames as increments it counts.
        assert 0 <= summary["increments"] <= step and frames == summary["increments"]
        assert "fold" in summary and "short_of_target" in summary["fold"] or not frames
    # The rows streamed are the finished run's (to rounding: sums over one row or all).
    streamed = _rows(tmp_path / "history.csv")
    columns = sim.history_columns()
    assert list(streamed[0]) == list(columns)
    for name, values in columns.items():
        assert [float(r[name]) for r in streamed] == pytest.approx(
            np.asarray(values, dtype=float).tolist(), rel=1e-14, abs=0), name
    # The run's end rewrites the files as a run without streaming writes them.
    sim.write(tmp_path, view=False)
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["completed"] is True and summary["interrupted"] is False
    assert "partial" not in summary
    assert not list(tmp_path.glob("*.part"))


def test_a_fold_killed_partway_leaves_its_path_so_far(tmp_path):
    # SIGKILL: no handler runs, so what is on disk is what the run wrote as it went.
    problem = _problem_file(tmp_path, steps=2000)
    out = tmp_path / "out"
    process = subprocess.Popen([sys.executable, "-m", "kresling", "simulate", str(problem),
                                "--out", str(out), "--no-view", "--quiet"],
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    try:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and process.poll() is None:
            history = out / "history.csv"
            if history.exists() and len(history.read_text().splitlines()) > 5:
                break
            time.sleep(0.02)
        assert process.poll() is None, process.stderr.read()
        time.sleep(0.3)
        process.send_signal(signal.SIGKILL)
    finally:
        process.kill()
        process.wait()
    assert process.returncode == -signal.SIGKILL
    summary = json.loads((out / "summary.json").read_text())
    assert summary["completed"] is False and summary["interrupted"] is True
    assert summary["partial"] is True and "still running" in summary["message"]
    history = _rows(out / "history.csv")
    assert len(history) >= 5 and [int(r["step"]) for r in history] == list(
        range(1, len(history) + 1))
    assert float(history[-1]["fold_fraction"]) < 1.0
    document = json.loads((out / "path.fold").read_text())
    frames = document.get("file_frames", [])
    # path.fold is rewritten before summary.json: it holds at least the increments the
    # summary counts, and no more than the rows.
    assert summary["increments"] <= len(frames) <= len(history)
    assert all(len(f["vertices_coords"]) == len(document["vertices_coords"]) for f in frames)
    rows = _rows(out / "displacements.csv")
    assert len(rows) >= len(history) - 1   # (the row being written when it was killed)


def test_a_run_in_a_log_says_what_runs_within_its_first_second(tmp_path):
    # stderr is a pipe, not a terminal: progress lines instead of a bar. The first comes
    # half a second into the run, while the model is built; the process's own start
    # (Python, the package's imports) comes before it.
    problem = _problem_file(tmp_path, steps=400)
    env = {**os.environ, "PYTHONUNBUFFERED": "1"}
    start = time.monotonic()
    process = subprocess.Popen([sys.executable, "-m", "kresling", "simulate", str(problem),
                                "--out", str(tmp_path / "out"), "--no-view"],
                               stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                               env=env)
    lines = []
    try:
        while not lines or "running:" not in lines[-1]:
            line = process.stderr.readline()
            if not line:
                break
            lines.append(line)
            if len(lines) == 1:
                took = time.monotonic() - start
    finally:
        process.kill()
        process.wait()
    assert lines and "running:" in lines[-1], lines
    # Well within a second on an idle machine (benchmarks/fold_patterns.py --startup).
    assert took < 5.0
