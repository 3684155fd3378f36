"""What a fold takes when the problem leaves it out: the free sheet held 3-2-1 (six
constraints that carry no force), Origami Simulator's material, and the command line's
``--fold-percent``, ``--snap-tolerance`` and ``kresling pattern --check``."""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest

from cli_helpers import run_kresling
from kresling.assembly import assemble
from kresling.model.material_presets import preset_material
from kresling.simulate import simulate
from kresling.simulate.rigid_hold import rigid_body_hold
from public_files import ORIGAMI_SIMULATOR

POPUP = ORIGAMI_SIMULATOR / "popupSimple.svg"


def _problem(path, **analysis):
    return {"pattern": {"file": str(path)},
            "actuation": [{"family": "fold", "fold_angle_deg": "file"}],
            "analysis": {"method": "fold", **analysis}}


@pytest.mark.parametrize("normal", [2, 1, 0])
def test_the_hold_is_three_two_one_whatever_the_sheets_plane(normal):
    # A square sheet of two triangles in the plane across axis `normal`: node a in all three
    # axes, b in the two across a -> b, c along the normal.
    square = np.array([[0, 0], [10, 0], [10, 10], [0, 10]], float)
    vertices = np.insert(square, normal, 0.0, axis=1)
    held = rigid_body_hold(vertices, [(0, 1, 2), (0, 2, 3)])
    assert [len(axes) for _, axes in held] == [3, 2, 1]
    assert held[2][1] == "xyz"[normal]
    (a, _), (b, across), _ = held
    along = int(np.argmax(np.abs(vertices[b] - vertices[a])))
    assert "xyz"[along] not in across


def test_the_held_nodes_carry_no_force_at_the_end_of_a_fold():
    # Six constraints, each taking out one rigid-body motion: statically determinate, so
    # at an equilibrium of the creases' internal drive their reactions vanish (to Newton's
    # tolerance against the sheet's internal forces).
    sim = simulate(_problem(POPUP, steps=10), progress=False)
    assert sim.completed, sim.message
    model = sim.model
    assert int(model.fixed.sum()) == 6
    np.testing.assert_array_equal(sim.path.constraint_dofs, np.flatnonzero(model.fixed.ravel()))
    # The reactions at every increment against the forces the bars carry there (the
    # unfolded model's internal force at the folded state: its creases' rest angles are the
    # flat ones, so it is of the size of the folding moments over the panels' widths).
    reactions = np.abs(sim.path.constraint_force).max()
    scale = np.abs(assemble(model, sim.path.displacement[-1], stiffness=False).force).max()
    assert reactions <= 1e-9 * scale, (reactions, scale)


def test_origami_simulators_material_is_scale_free():
    # Corner springs in proportion to the sheet's radius; everything else per unit length:
    # every energy of the same pattern drawn k times larger scales by k.
    small = preset_material("origami_simulator", np.array([[0, 0, 0], [10, 0, 0], [0, 10, 0]]))
    large = preset_material("origami_simulator", np.array([[0, 0, 0], [1e3, 0, 0], [0, 1e3, 0]]))
    assert small.bar_modulus == large.bar_modulus == pytest.approx(20 / 0.7)
    assert large.face_stiffness == pytest.approx(100 * small.face_stiffness)
    with pytest.raises(ValueError, match="preset = 'paper' is invalid: must be one of"):
        preset_material("paper", np.zeros((3, 3)))


def test_fold_percent_on_the_command_line(tmp_path):
    problem = tmp_path / "popup.toml"
    problem.write_text(f'[pattern]\nfile = "{POPUP}"\n\n[[actuation]]\nfamily = "fold"\n'
                       'fold_angle_deg = "file"\n\n[analysis]\nmethod = "fold"\nsteps = 10\n')
    result = run_kresling("simulate", str(problem), "--fold-percent", "50", "--no-view",
                          "--json", "--quiet", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    summary = json.loads(result.stdout)
    assert summary["completed"] and summary["material_preset"] == "origami_simulator"
    assert "holding the free sheet's rigid-body motions only" in result.stderr
    with open(summary["outputs"]["history"], newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert float(rows[-1]["fold_fraction"]) == pytest.approx(0.5)
    bad = run_kresling("simulate", str(problem), "--fold-percent", "150", cwd=tmp_path)
    assert bad.returncode == 2 and "fold_percent' = 150.0 is invalid" in bad.stderr


def test_a_fold_short_of_its_targets_exits_1_saying_by_how_much(tmp_path):
    problem = tmp_path / "frog.toml"
    problem.write_text(f'[pattern]\nfile = "{ORIGAMI_SIMULATOR / "frogBase.svg"}"\n\n'
                       '[[actuation]]\nfamily = "fold"\nfold_angle_deg = "file"\n\n'
                       '[analysis]\nmethod = "fold"\nsteps = 10\nfold_percent = 50\n')
    result = run_kresling("simulate", str(problem), "--no-view", "--quiet", cwd=tmp_path)
    assert result.returncode == 1
    assert "driven creases are more than 1 deg from their targets" in result.stderr
    summary = json.loads((tmp_path / "frog" / "summary.json").read_text())
    assert summary["completed"] is False and summary["fold"]["short_of_target"] > 0


def test_pattern_check_says_what_simulate_would_do(tmp_path):
    ok = run_kresling("pattern", "--check", str(POPUP), "--json", cwd=tmp_path)
    assert ok.returncode == 0, ok.stderr
    report = json.loads(ok.stdout)
    assert report["refused"] is None and report["creases_with_targets"] > 0
    flat = tmp_path / "flat.fold"    # two triangles folded flat on each other
    flat.write_text(json.dumps({"vertices_coords": [[0, 0, 0], [1, 0, 0], [1, 1, 0],
                                                    [1, 0, 1e-12]],
                                "faces_vertices": [[0, 1, 2], [0, 2, 3]],
                                "edges_vertices": [[0, 2]], "edges_assignment": ["V"]}))
    refused = run_kresling("pattern", "--check", str(flat), cwd=tmp_path)
    assert refused.returncode == 1
    assert "simulate would refuse it" in refused.stderr and "folded flat" in refused.stderr
    both = run_kresling("pattern", "--check", str(POPUP), "-o", "x.fold", cwd=tmp_path)
    assert both.returncode == 2 and "--check reads a pattern and writes nothing" in both.stderr
    # A drawing whose fold angles rigid panels cannot reach (Kawasaki's sums off by up to
    # 2.8 deg at its flat-folded vertices): built all the same, and said.
    bird = run_kresling("pattern", "--check", str(POPUP.parent / "flappingBird.svg"),
                        cwd=tmp_path)
    assert bird.returncode == 0, bird.stderr
    assert ("not those of any rigidly folded state at 10 of the 14 interior vertices"
            in bird.stdout)


def test_the_end_state_is_written_as_stl_and_obj_when_asked(tmp_path):
    from kresling.io import read_obj

    problem = _problem(POPUP, steps=4)
    problem["output"] = {"formats": ["stl", "obj"]}
    sim = simulate(problem, progress=False)
    written = sim.write(tmp_path, view=False)
    end = sim.model.nodes + sim.path.displacement[-1].reshape(-1, 3)
    back = read_obj(written["obj"], planarity_tolerance=None)
    np.testing.assert_allclose(back.vertices, end, rtol=0, atol=1e-9 * np.ptp(end))
    assert len(back.faces) == len(sim.pattern_model.elements.triangles)
    text = written["stl"].read_text()
    assert text.startswith("solid folded") and text.count("facet normal") == len(back.faces)
    with pytest.raises(ValueError, match=r"\[output\] key 'formats' = \['ply'\] is invalid"):
        simulate({**problem, "output": {"formats": ["ply"]}}, progress=False)


@pytest.fixture
def usual_signals():
    """SIGINT and SIGTERM with their usual actions for the test (a run started with nohup, or
    with SIGINT ignored, has others), the caller's restored after it."""
    import signal

    saved = {n: signal.getsignal(n) for n in (signal.SIGINT, signal.SIGTERM)}
    signal.signal(signal.SIGINT, signal.default_int_handler)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    yield
    for number, handler in saved.items():
        signal.signal(number, handler)


@pytest.mark.parametrize("name", ["SIGINT", "SIGTERM"])
def test_ctrl_c_or_a_kill_ends_the_path_at_its_next_increment_keeping_it(tmp_path, name,
                                                                          usual_signals):
    import os
    import signal

    def send_at_third(state):
        if state.step == 3:
            os.kill(os.getpid(), getattr(signal, name))
        return False

    sim = simulate(_problem(POPUP, steps=10), stop=send_at_third, progress=False)
    assert sim.interrupted == name
    assert sim.path.num_steps == 4 and not sim.completed   # the increment after it, kept
    assert sim.message == f"interrupted ({name}) after 4 increments: the path so far is kept"
    summary = json.loads(sim.write(tmp_path, view=False)["summary"].read_text())
    assert summary["interrupted"] is True and summary["increments"] == 4
    # The handlers are the usual ones again.
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    assert signal.getsignal(signal.SIGTERM) is signal.SIG_DFL


def test_an_ignored_ctrl_c_stays_ignored(usual_signals):
    # A job that ignores SIGINT (nohup, a CI runner) keeps ignoring it: nothing installed.
    import os
    import signal

    signal.signal(signal.SIGINT, signal.SIG_IGN)

    def send_at_third(state):
        if state.step == 3:
            os.kill(os.getpid(), signal.SIGINT)
        return False

    sim = simulate(_problem(POPUP, steps=6), stop=send_at_third, progress=False)
    assert sim.interrupted == "" and sim.completed and sim.path.load_factor[-1] == 1.0
    assert signal.getsignal(signal.SIGINT) is signal.SIG_IGN


def test_a_stiff_material_that_stalls_is_told_that_the_preset_goes_on():
    # The pinwheel base with bars 1e5 N/mm^2 (MERLIN2's examples') stops at 83 % of its
    # targets; folded again with Origami Simulator's material it goes past that point (the
    # check folds it one increment further), and the message says so with the number.
    problem = _problem(ORIGAMI_SIMULATOR / "pinwheelBase.svg", steps=20)
    problem["material"] = {"calibration": "manual", "bar_modulus": 1e5, "bar_area": 1.0,
                           "fold_stiffness": 1.0, "bend_stiffness": 1.0}
    problem["laws"] = {"fold_limits_deg": [1.0, 359.0], "bend_limits_deg": [1.0, 359.0]}
    sim = simulate(problem, progress=False)
    assert not sim.path.completed
    stopped = sim.path.load_factor[-1]
    assert 'preset = "origami_simulator") the same fold goes on past' in sim.message
    reached = float(sim.message.rsplit("to ", 1)[1].rstrip(")"))
    assert reached >= stopped + 1.0 / 20 - 1e-9
    # A run that stops for another reason is not second-guessed: the preset itself.
    assert simulate(_problem(ORIGAMI_SIMULATOR / "pinwheelBase.svg", steps=20),
                    progress=False).advice == ""


def test_origami_simulators_miura_folds_flat_with_nothing_but_its_pattern():
    # Every crease to its file's angle (+-180 deg: folded flat), Origami Simulator's
    # material by default, no supports: all 287 driven creases within the fold's 1 deg of
    # their targets. The preset's creases stay linear to 0.5 deg of flat; with the limits at
    # 1 deg two of them, pressed by their panels, stopped 1.0-1.1 deg short.
    sim = simulate(_problem(ORIGAMI_SIMULATOR / "miura-ori.svg"), progress=False)
    assert sim.completed, sim.message
    report = sim.fold_report()
    assert report["creases_driven"] == 287 and report["short_of_target"] == 0, report
    assert report["left_branch"] == 0 and report["largest_shortfall_deg"] <= 1.0
