"""[[stage]]: a fold, a load, modes and a motion in time in one problem file, each stage
from where the one before ended."""

import csv
import json

import numpy as np
import pytest

from small_models import CREASED_SQUARE
from kresling.analyses.modes import vibration_modes
from kresling.assembly import assemble
from kresling.simulate import simulate
from kresling.simulate.problem_keys.mass import problem_masses

SHARED = CREASED_SQUARE
FOLD = {"name": "fold", "method": "fold", "steps": 10, "tolerance": 1e-12,
        "actuation": [{"edges": [[0, 2]], "fold_angle_deg": 90.0}]}
PUSH = {"name": "push", "method": "force_control", "steps": 4, "tolerance": 1e-12,
        "load": [{"node": 3, "force": [0.0, 0.0, -0.002]}]}
MODES = {"name": "modes", "method": "modes", "modes": 3}
HOLD = {"name": "hold", "method": "dynamic", "tolerance": 1e-12,
        "dynamics": {"scheme": "newmark", "time_step": 1e-4, "duration": 1e-3}}
STAGED = {**SHARED, "stage": [FOLD, PUSH, MODES, HOLD]}


@pytest.fixture(scope="module")
def staged():
    return simulate(STAGED, progress=False)


def test_every_stage_runs_and_the_fold_is_the_fold_alone(staged):
    assert staged.completed and [name for name, _ in staged.runs] == [
        "fold", "push", "modes", "hold"]
    alone = simulate({**SHARED, "actuation": FOLD["actuation"],
                      "analysis": {"method": "fold", "steps": 10, "tolerance": 1e-12}},
                     progress=False)
    np.testing.assert_array_equal(staged.runs[0][1].path.displacement, alone.path.displacement)


def test_the_load_stage_starts_folded_and_ends_in_equilibrium_under_its_force(staged):
    fold, push = staged.runs[0][1], staged.runs[1][1]
    # It starts at the fold's end: its first increment is a small step from there.
    first = push.path.displacement[0] - fold.path.displacement[-1]
    assert np.abs(first).max() < 0.1 * np.abs(fold.path.displacement[-1]).max()
    # Its model holds the crease at 90 deg (the fold's), and at its end the internal force
    # balances the push at every free DOF: an equilibrium of the folded sheet.
    model = push.model_at(-1)
    np.testing.assert_allclose(model.hinge_rest_angle, fold.model_at(-1).hinge_rest_angle)
    f_int = assemble(model, push.path.displacement[-1]).force
    free = ~model.fixed.ravel()
    applied = np.zeros(model.num_dofs)
    applied[3 * 3 + 2] = -0.002
    # Newton's 1e-12 mm correction times the sheet's stiffness (~50 N/mm): 1e-9 N.
    np.testing.assert_allclose(f_int[free], applied[free], atol=1e-9)


def test_the_modes_are_about_the_loaded_folded_state(staged):
    push, modes = staged.runs[1][1], staged.runs[2][1]
    model = push.model_at(-1)
    masses = problem_masses(push.problem, push.pattern_model)
    expected = vibration_modes(model, masses, k=3, u=push.path.displacement[-1])
    np.testing.assert_allclose(modes.modes.frequencies_hz, expected.frequencies_hz, rtol=1e-12)


def test_the_motion_starts_at_rest_in_that_equilibrium_and_stays_there(staged):
    push, hold = staged.runs[1][1], staged.runs[3][1]
    # Its loads held (the push's force), no velocity, the crease at 90 deg: nothing moves.
    # 1e-9 mm: the equilibrium's own residual (1e-9 N) over the sheet's stiffness.
    np.testing.assert_allclose(hold.path.displacement,
                               np.broadcast_to(push.path.displacement[-1],
                                               hold.path.displacement.shape), atol=1e-9)
    assert np.abs(hold.history.kinetic).max() < 1e-12


def test_the_files_name_the_stages(staged, tmp_path):
    written = staged.write(tmp_path, view=False)
    with open(written["history"]) as handle:
        rows = list(csv.DictReader(handle))
    assert [r["stage"] for r in rows] == ["fold"] * 10 + ["push"] * 4 + ["hold"] * 10
    assert {"fold_stage", "fold_fraction", "time", "energy_total"} <= set(rows[0])
    assert rows[10]["fold_fraction"] == "" and rows[0]["time"] == ""
    assert (tmp_path / "3_modes" / "modes.csv").is_file()
    assert (tmp_path / "2_push" / "path.fold").is_file()
    summary = json.loads(written["summary"].read_text())
    assert summary["completed"] and [s["name"] for s in summary["stages"]] == [
        "fold", "push", "modes", "hold"]


def test_a_stage_that_stops_names_itself_and_ends_the_run():
    short = {**PUSH, "name": "crush", "steps": 1, "max_iterations": 1}
    run = simulate({**SHARED, "stage": [FOLD, short, MODES]}, progress=False)
    assert not run.completed and [n for n, _ in run.runs] == ["fold", "crush"]
    assert run.message.startswith("stage 'crush' stopped: ")


def test_a_load_stage_after_a_loaded_one_holds_the_first_load():
    # Two pushes of F after the fold end where one push of 2 F does: the first stays
    # applied (the model's held forces) while the second is ramped.
    twice = simulate({**SHARED, "stage": [FOLD, PUSH, {**PUSH, "name": "again"}]},
                     progress=False)
    double = {**PUSH, "load": [{"node": 3, "force": [0.0, 0.0, -0.004]}]}
    once = simulate({**SHARED, "stage": [FOLD, double]}, progress=False)
    assert twice.completed and once.completed
    again = twice.runs[2][1]
    assert again.model.family("forces")["force"].tolist() == [[0.0, 0.0, -0.002]]
    # Both are equilibria of the same elastic sheet under the same load, to Newton's 1e-12 mm.
    np.testing.assert_allclose(again.path.displacement[-1], once.runs[1][1].path.displacement[-1],
                               atol=1e-9)


@pytest.mark.parametrize("problem, match", [
    ({**STAGED, "analysis": {"method": "fold"}}, r"\[analysis\] is given per stage"),
    ({**SHARED, "stage": [FOLD, {**FOLD, "name": "fold"}]}, "'fold' names two stages"),
    ({**SHARED, "stage": [{**PUSH, "steps": 0}]}, r"stage 'push': \[analysis\] key 'steps'"),
    ({**SHARED, "stage": []}, r"\[\[stage\]\] must be an array of tables"),
])
def test_bad_stages_are_refused_naming_the_stage(problem, match):
    with pytest.raises(ValueError, match=match):
        simulate(problem, progress=False)
