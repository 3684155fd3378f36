"""The numbers of docs/dynamics.md's 'What dynamics answers for the Kresling arm' (and of
its cell-frequency table) are what the code computes: each is formatted from a fresh run
as the page prints it and looked up in the page, so a change of the code that moves one
fails here until the page is updated."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from kresling import Design
from kresling.analyses.cell_frequencies import cell_frequencies
from kresling.analyses.snap_dynamics import snap_in_time
from kresling.arm import all_configurations
from kresling.arm.frequencies import arm_frequencies
from kresling.arm.gravity import gravity_table

PAGE = (Path(__file__).resolve().parents[2] / "docs" / "dynamics.md").read_text(
    encoding="utf-8")
OPTIMUM = Design(10, 0.9, 15, 30)


def _on_page(*texts):
    missing = [t for t in texts if t not in PAGE]
    assert not missing, f"docs/dynamics.md does not print {missing}"


def test_the_snap_in_time_as_the_page_prints_it():
    r = snap_in_time(OPTIMUM)
    _on_page(f"| {r.static.snap_force:.3f} N |", f"| {r.load:.3f} N |",
             f"| {r.jump_time * 1e3:.1f} ms |",
             f"| {r.peak_travel:.2f} / {r.overshoot:.2f} mm |",
             f"({r.static.stable_displacement:.2f} mm)", f"| {r.loaded_travel:.2f} mm |",
             f"| {r.rebound:.2f} mm |", f"| {r.settling_time:.2f} s |",
             f"| {r.settled_height:.6f} mm |",
             f"tilted {math.degrees(r.settled_tilt):.1f} degrees")


def test_the_cell_frequencies_as_the_page_prints_them():
    f = cell_frequencies(OPTIMUM, k=6)
    e, c, s = (m.frequencies_hz for m in (f.extended, f.contracted, f.snapped))
    _on_page(f"| 1, 2 | {e[0]:.2f} | {c[0]:.2f} | {s[0]:.3f}, {s[1]:.2f} |",
             f"| 3 | {e[2]:.2f} | {c[2]:.2f} | {s[2]:.2f} |",
             f"{f.ratio:.2f} times", f"{f.snapped_ratio:.1f} times",
             f"({f.mass * 1e6:.2f} g")


def test_the_arm_frequencies_as_the_page_prints_them():
    rows = {c: arm_frequencies(c, k=3) for c in all_configurations(3)}
    softest = min(r.modes.frequencies_hz[0] for r in rows.values())
    for config, r in rows.items():
        f = r.modes.frequencies_hz
        ratio = f"{f[0] / softest:.3g}"
        _on_page(f"| {config} | {r.mass * 1e6:.2f} | {f[0]:.4g}, {f[1]:.3f}, {f[2]:.2f} | "
                 f"{ratio} |")


@pytest.mark.parametrize("orientation", ["hanging"])
def test_the_sag_as_the_page_prints_it(orientation):
    rows = gravity_table(3, orientation)
    bent = {r["config"]: r["tip_sag_mm"] for r in rows if r["k"] == 10}
    _on_page(f"the tip moves {bent['000']:.2f} mm in (000)",
             f"{bent['010']:.2f} and {bent['011']:.2f} mm in (010) and (011)")
    rest = [r for r in rows if r["k"] == 0]
    low = min(min(r["sag_mm"][1:]) for r in rest)
    high = max(r["largest_sag_mm"] for r in rest)
    _on_page(f"the markers move {low:.2f}-{high:.2f} mm")
