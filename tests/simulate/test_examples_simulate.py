"""The problems in examples/ run and behave as their files say they do.

Each example's problem.toml is run through ``kresling.simulate.simulate`` in full (each
takes well under a second), and what its header promises is checked as physics: the
Miura sheet resists its corner being pushed down, the single vertex folds as a rigid
mechanism with mountain and valley turning opposite ways, the Kresling cell snaps through
exactly as the specimen analysis ``kresling snap`` says. The committed pattern files must
be what examples/make_patterns.py writes.
"""

import csv
import importlib.util
from pathlib import Path

import numpy as np
import pytest

from cli_helpers import run_kresling
from kresling import Design
from kresling.analyses import snap_through
from kresling.io import read_pattern
from kresling.simulate import simulate

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def _module(path):
    spec = importlib.util.spec_from_file_location(path.stem, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def miura():
    return simulate(EXAMPLES / "miura_bending" / "problem.toml", progress=False)


@pytest.fixture(scope="module")
def vertex():
    return simulate(EXAMPLES / "single_vertex" / "problem.toml", progress=False)


@pytest.fixture(scope="module")
def kresling_cell():
    return simulate(EXAMPLES / "kresling_tower" / "problem.toml", progress=False)


# -- the files -------------------------------------------------------------------------------

def test_committed_patterns_are_what_make_patterns_writes(tmp_path):
    """Regenerated files equal the committed ones: patterns to 1e-9 mm (the last digit of a
    coordinate may differ between platforms' trigonometry), problem.toml to the letter."""
    written = _module(EXAMPLES / "make_patterns.py").main(tmp_path)
    assert written
    for path in written:
        committed = EXAMPLES / path.relative_to(tmp_path)
        assert committed.is_file(), f"{committed} is missing: run examples/make_patterns.py"
        if path.suffix == ".toml":
            assert path.read_text() == committed.read_text(), committed
            continue
        new, old = read_pattern(path), read_pattern(committed)
        assert new.faces == old.faces and new.edges_assignment == old.edges_assignment
        np.testing.assert_allclose(new.vertices, old.vertices, rtol=0, atol=1e-9)
        assert len(new.frames) == len(old.frames)
        for a, b in zip(new.frames, old.frames):
            np.testing.assert_allclose(a, b, rtol=0, atol=1e-9)


def test_every_example_has_its_files_and_a_readme_line():
    readme = (EXAMPLES / "README.md").read_text()
    for folder in ("miura_bending", "single_vertex", "kresling_tower", "bennett_linkage",
                   "micro_mirror"):
        problem = EXAMPLES / folder / "problem.toml"
        assert problem.read_text().startswith("#"), f"{problem}: expected behaviour on top"
        assert f"{folder}/" in readme


# -- Miura-ori sheet bent by one corner ------------------------------------------------------

def test_miura_sheet_pushes_back_harder_the_further_its_corner_goes(miura):
    assert miura.completed and miura.path.num_steps == 50
    force = miura.history_columns()["reaction_24_z"]
    # Positive: the sheet pushes the corner back up (the drive moves it down). Strictly
    # increasing: no buckling or snapping on this path, each increment needs more force.
    assert (force > 0).all()
    assert (np.diff(force) > 0).all()
    # mN, as the header says (E = 1e3 N/mm^2, t = 0.25 mm: a very soft sheet); 20 % bounds
    # hold the order of magnitude without pinning the calibration's digits.
    assert 4e-3 < force[-1] < 6.5e-3


def test_miura_work_of_the_drive_is_the_stored_energy(miura):
    """Conservative and quasi-static: the area under the force-travel curve equals the
    strain energy at the end. The trapezoid rule over 50 increments of a smooth curve errs
    by ~1e-4 of it (measured 8e-5); 1 % leaves room and still catches a sign or a factor."""
    columns = miura.history_columns()
    travel = 20.0 * columns["load_factor"]
    force, travel = np.r_[0.0, columns["reaction_24_z"]], np.r_[0.0, travel]
    work = np.sum(0.5 * (force[1:] + force[:-1]) * np.diff(travel))      # trapezoid rule
    assert work == pytest.approx(columns["energy_total"][-1], rel=1e-2)


def test_miura_sheet_bends_by_bending_its_panels(miura):
    """A Miura-ori sheet cannot bend out of plane by folding alone: most of the energy is
    in the panels' bend hinges (measured: 85 % at the end)."""
    energy = miura.history_columns()
    assert energy["energy_bends"][-1] > 0.5 * energy["energy_total"][-1]


def test_miura_example_runs_from_the_command_line(tmp_path, miura):
    result = run_kresling("simulate", str(EXAMPLES / "miura_bending" / "problem.toml"),
                          "--out", str(tmp_path), "--quiet", "--no-view", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    with (tmp_path / "history.csv").open() as handle:
        rows = list(csv.DictReader(handle))
    force = np.array([float(row["reaction_24_z"]) for row in rows])
    np.testing.assert_allclose(force, miura.history_columns()["reaction_24_z"], rtol=1e-12)


# -- single degree-4 vertex --------------------------------------------------------------------

@pytest.fixture(scope="module")
def fold_angles(vertex):
    """Signed fold angles [deg] along the path, by crease (examples' own helper)."""
    module = _module(EXAMPLES / "single_vertex" / "hinge_angles.py")
    rho, families, creases = module.signed_fold_angles(vertex)
    return {crease: (family, rho[:, k]) for k, (family, crease)
            in enumerate(zip(families, creases))}


def test_vertex_folds_until_its_monitor_is_reached(vertex):
    assert vertex.completed
    lift = vertex.history_columns()["u_2_z"]
    assert lift[-1] > 8.0 and (np.diff(lift) > 0).all()
    assert (np.diff(vertex.path.load_factor) > 0).all()   # the springs wind up: no limit point


def test_vertex_mountain_and_valleys_turn_opposite_ways(fold_angles):
    families = sorted(family for family, _ in fold_angles.values())
    assert families == ["mountain", "valley", "valley", "valley"]
    for family, rho in fold_angles.values():
        turn = np.diff(rho)
        if family == "valley":      # valleys fold further: angle grows from its positive start
            assert rho[0] > 0 and (turn > 0).all()
        else:                       # the mountain folds further the other way
            assert rho[0] < 0 and (turn < 0).all()
    # Each crease folds substantially (the header: 20 -> ~80, 10 -> ~45 deg).
    assert all(abs(rho[-1]) > 3 * abs(rho[0]) for _, rho in fold_angles.values())


def test_vertex_follows_rigid_folding_kinematics(vertex, fold_angles):
    """With near-rigid triangles (EA = 1e4 N against forces of ~0.05 N: strains ~1e-5) the
    vertex moves as the rigid-folding mechanism of a flat-foldable degree-4 vertex: the
    straight pair (creases 0-2, 0-4) folds by equal and opposite angles, the zig-zag pair
    (0-1, 0-3) by equal angles (mirror images), and tan(rho_zigzag / 2) =
    tan(rho_straight / 2) / cos 60 deg. What the bars' stretching leaves (measured): 0.003
    deg between the straight pair, 3e-5 relative on the tangent ratio; the bounds, 0.05 deg
    and 1e-3, are ~15 and ~40 times that and far below the ~35 deg each crease turns."""
    rho = {crease: angles for crease, (_, angles) in fold_angles.items()}
    np.testing.assert_allclose(rho[(0, 2)], -rho[(0, 4)], rtol=0, atol=5e-2)
    np.testing.assert_allclose(rho[(0, 1)], rho[(0, 3)], rtol=0, atol=5e-2)
    ratio = np.tan(np.radians(rho[(0, 1)]) / 2) / np.tan(np.radians(rho[(0, 2)]) / 2)
    np.testing.assert_allclose(ratio, 1 / np.cos(np.radians(60.0)), rtol=1e-3)
    energy = vertex.history_columns()
    assert (energy["energy_bars"] < 1e-3 * energy["energy_folds"]).all()
    assert (energy["energy_bends"] == 0).all()     # triangles only: no bend hinges


# -- Kresling cell from the fabrication FOLD ---------------------------------------------------

def _cell_force(simulation):
    columns = simulation.history_columns()
    return sum(v for k, v in columns.items() if k.startswith("reaction_"))


def test_kresling_cell_snaps_through(kresling_cell):
    """The force on the top rises to a local maximum, falls through zero (past the unstable
    state the cell pulls the drive down: it would snap) and rises again near the contracted
    height: a bistable cell."""
    assert kresling_cell.completed and kresling_cell.path.num_steps == 100
    force = _cell_force(kresling_cell)
    peak = int(np.argmax(force[:50]))
    assert 0 < peak < 49 and force[peak] > force[peak - 1] and force[peak] > force[peak + 1]
    after = force[peak:]
    assert after.min() < -0.1 * force[peak]          # a clear negative force, not round-off
    lowest = peak + int(np.argmin(after))
    assert force[-1] > force[lowest] + 0.5 * abs(force[lowest])   # rising again at the end


def test_kresling_cell_from_fold_is_the_thesis_specimen(kresling_cell):
    """The FOLD route builds the model ``kresling snap`` builds from the design (same
    elements, properties and 100 increments), so the two force-travel curves agree to what
    the Newton tolerance allows: 1e-6 mm on the displacements times a stiffness of ~100
    N/mm is 1e-4 N; 1e-3 N (1e-4 of the peak) bounds it. Measured: 5e-10 N."""
    reference = snap_through(Design(n=10, lam=0.9, Lc=15.0, R=30.0))
    force = _cell_force(kresling_cell)
    np.testing.assert_allclose(force, reference.force[1:], rtol=0, atol=1e-3)
    travel = kresling_cell.path.load_factor * (reference.extended_height
                                               - reference.contracted_height)
    np.testing.assert_allclose(travel, reference.displacement[1:], rtol=0, atol=1e-9)
    # The snap force the analysis refines (a parabola through the peak sample and its
    # neighbours) from the same samples: the sample itself is 0.03 % below it.
    assert force[:50].max() == pytest.approx(reference.snap_force, rel=1e-3)


def test_fold_then_vibrate_folds_then_rings_at_the_creases_frequency():
    from kresling.model.fold_angles import fold_angles_deg

    run = simulate(EXAMPLES / "fold_then_vibrate" / "problem.toml", progress=False)
    assert run.completed and [name for name, _ in run.runs] == ["fold", "modes", "shake"]
    # The panel turning about the crease: k = 0.05 N*mm/rad/mm * 20 sqrt(2) mm, its mass
    # 1e-6 t at r = 20 / sqrt(2) mm from the crease; the stiff bars lower it by 1e-7 only.
    k, inertia = 0.05 * 20 * np.sqrt(2), 1e-6 * 200.0
    lowest = run.runs[1][1].modes.frequencies_hz[0]
    assert lowest == pytest.approx(np.sqrt(k / inertia) / (2 * np.pi), rel=1e-6)
    shake = run.runs[2][1]
    angles = np.array([fold_angles_deg(shake.pattern_model, u)[0]
                       for u in shake.path.displacement])
    # A swing about the folded 90 deg (0.08 deg statically, about five times that so near
    # resonance), within the header's degree.
    assert 0.1 < np.abs(angles - 90.0).max() < 1.0


def test_fold_then_chirp_sweeps_the_folded_crease_through_its_resonance():
    from kresling.model.fold_angles import fold_angles_deg

    run = simulate(EXAMPLES / "fold_then_chirp" / "problem.toml", progress=False)
    assert run.completed and [name for name, _ in run.runs] == ["fold", "modes", "sweep"]
    lowest = run.runs[1][1].modes.frequencies_hz[0]   # 13.383 Hz (fold_then_vibrate's)
    sweep = run.runs[2][1]
    h, columns = sweep.history, sweep.history_columns()
    angles = np.array([fold_angles_deg(sweep.pattern_model, u)[0]
                       for u in sweep.path.displacement])
    # The sweep starts where the fold left the crease, at rest at 90 deg.
    assert angles[0] == pytest.approx(90.0, abs=0.01)
    # The chirp's frequency passes the mode's at t = (13.383 - 5) / 20 * 0.6 s = 0.25 s.
    crossing = (lowest - 5.0) / 20.0 * 0.6
    swing = np.abs(angles - 90.0)
    # Below it the panel follows the +-2 deg rest angle (steadily amplified by
    # 1 / (1 - (f / f_n)^2), 1.6 at 8 Hz; the start's transient and the sweep keep it under
    # twice the drive up to 10 Hz, 3.1 deg measured); past it, it swings several times
    # further, the largest swing after the crossing (a chirp's response peaks late).
    assert swing[h.time < 0.15].max() < 2.0 * 2.0
    assert swing.max() > 3.0 * 2.0
    assert h.time[np.argmax(swing)] > crossing
    np.testing.assert_allclose(np.abs(columns["actuation_0_factor"]).max(), 2.0, rtol=1e-3)
    # The driven rest angle's work balances the energies, to the average acceleration
    # scheme's O((w dt)^2) ~ 7e-3 on the turning panel (measured: 1.4e-4 of the work).
    balance = h.kinetic + h.strain + h.dissipated - h.work - h.actuation_work
    assert np.ptp(balance) < 1e-3 * np.abs(h.actuation_work).max()
