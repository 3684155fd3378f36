"""Any crease pattern against MERLIN2 v1.1's own example problems.

tests/data/merlin2_examples/ holds MERLIN2 v1.1's runs (under GNU Octave) of four of its
example problems, the model it built and the path it followed; see its README. Each is
posed here as a problem file and run through ``kresling simulate`` (the N4B5 hexagon, one
stiffness per bend hinge, through the Python API). Tolerances:
- the model: same bars and hinges (up to order), areas and stiffnesses to 1e-12 relative
  (both evaluate the same closed forms in double precision);
- the path: the same increments, the load factor (and, under displacement control, the
  reaction at the driven DOF) within 1e-6 of its largest value and every displacement within
  1e-6 mm (MERLIN2's Newton tolerance is 1e-6 on the correction norm: paths that agree to
  that are the same path).
"""

from __future__ import annotations

import csv
import dataclasses
import json
import tomllib
from pathlib import Path

import numpy as np
import pytest

from cli_helpers import run_kresling
from kresling.model import CreaseLaws, HingeLaw, ManualProperties, build_pattern_model
from kresling.simulate import build_problem_model, load_problem, simulate
from kresling.solvers import solve_mgdcm

DATA = Path(__file__).resolve().parents[1] / "data" / "merlin2_examples"


def reference(case, name, dtype=float):
    path = DATA / case / name
    if not path.exists():
        # A large history is stored gzip-compressed (Uhis.csv.gz); loadtxt reads it as is.
        return np.loadtxt(path.with_name(name + ".gz"), delimiter=",", ndmin=2, dtype=dtype)
    text = path.read_text().strip()
    if text in ("", ","):
        return np.zeros((0,), dtype=dtype)
    return np.loadtxt(path, delimiter=",", ndmin=2, dtype=dtype)


def analysis_method(case):
    with open(DATA / case / "problem.toml", "rb") as handle:
        return tomllib.load(handle)["analysis"]["method"]


def read_csv(path):
    with open(path, newline="") as handle:
        rows = list(csv.reader(handle))
    return rows[0], np.array(rows[1:], dtype=float)


def element_rows(nodes, values):
    """Sorted (nodes..., value) rows: a model's elements up to their order."""
    return sorted(zip(map(tuple, np.asarray(nodes).tolist()), np.asarray(values).tolist()))


#: Rest angles of hinges that lie flat (within 1e-6 rad of pi) are compared to this absolute
#: tolerance [rad] instead of 1e-12 relative: both codes take them from the arc cosine of the
#: normals' dot product, and acos(-1 + d) = pi - sqrt(2 d) turns the last few bits of that
#: dot product into ~1e-8 rad (a 10-ulp error in it gives sqrt(2 * 10 * 1.1e-16) = 4.7e-8).
#: MERLIN2's own flat values scatter so (3.14159263..., 3.14159264... for one flat sheet),
#: and which bits a machine's vectorised arithmetic rounds decides ours.
FLAT_REST_ANGLE_ATOL = 1e-7


def assert_same_elements(ours_nodes, ours_values, ref_nodes, ref_values, flat_atol=0.0):
    if np.asarray(ref_nodes).size == 0:
        # No element of this kind (MERLIN2 then stores its default stiffness alone).
        assert len(ours_nodes) == 0
        return
    ours = element_rows(ours_nodes, ours_values)
    width = np.asarray(ours_nodes).shape[1]
    ref = element_rows(np.asarray(ref_nodes).reshape(len(ref_values), width) - 1, ref_values)
    assert [r[0] for r in ours] == [r[0] for r in ref]
    ours_v, ref_v = np.array([r[1] for r in ours]), np.array([r[1] for r in ref])
    flat = np.abs(ref_v - np.pi) < 1e-6 if flat_atol else np.zeros(len(ref_v), dtype=bool)
    np.testing.assert_allclose(ours_v[~flat], ref_v[~flat], rtol=1e-12, atol=0)
    np.testing.assert_allclose(ours_v[flat], ref_v[flat], rtol=0, atol=flat_atol)


def assert_model_equals_merlin2(pattern_model, case):
    model, elements = pattern_model.model, pattern_model.elements
    np.testing.assert_allclose(model.nodes, reference(case, "nodes.csv"), rtol=0, atol=1e-12)
    assert_same_elements(model.bars, model.bar_area, reference(case, "bars.csv", int),
                         reference(case, "bar_area.csv").ravel())
    folds = np.array([f != "bend" for f in pattern_model.hinge_family], dtype=bool)
    for mask, nodes, stiffness, rest in ((folds, "fold.csv", "Kf.csv", "pf0.csv"),
                                         (~folds, "bend.csv", "Kb.csv", "pb0.csv")):
        ref_nodes = reference(case, nodes, int)
        assert_same_elements(model.hinges[mask], model.hinge_stiffness[mask], ref_nodes,
                             reference(case, stiffness).ravel())
        assert_same_elements(model.hinges[mask], model.hinge_rest_angle[mask], ref_nodes,
                             reference(case, rest).ravel(), flat_atol=FLAT_REST_ANGLE_ATOL)
    assert len(elements.triangles) == len(reference(case, "trigl.csv"))


@pytest.fixture(scope="module",
                params=["polygon_N5B8_auto", "kresling_folding", "gmiura_pointload"])
def simulated(request, tmp_path_factory):
    case = request.param
    out = tmp_path_factory.mktemp(case)
    result = run_kresling("simulate", str(DATA / case / "problem.toml"), "--out", str(out),
                          "--no-view", "--json", cwd=out)
    return case, out, result


def test_cli_run_completes(simulated):
    case, out, result = simulated
    assert result.returncode == 0, result.stderr
    for name in ("history.csv", "displacements.csv", "path.fold", "summary.json"):
        assert (out / name).is_file()
    stepping = {"polygon_N5B8_auto": "MGDCM (generalized displacement control)",
                "kresling_folding": "MGDCM (generalized displacement control)",
                "gmiura_pointload": "equal increments with MERLIN2's step control"}
    assert json.loads((out / "summary.json").read_text())["stepping"] == stepping[case]


def test_model_equals_merlin2s(simulated):
    case, _, _ = simulated
    assert_model_equals_merlin2(build_problem_model(DATA / case / "problem.toml"), case)


def test_path_equals_merlin2s(simulated):
    case, out, _ = simulated
    header, history = read_csv(out / "history.csv")
    _, displacements = read_csv(out / "displacements.csv")
    load_factor = history[:, header.index("load_factor")]
    ref_u, ref_f = reference(case, "Uhis.csv"), reference(case, "Fhis.csv")
    if analysis_method(case) == "displacement_control":
        # MERLIN2's Fhis is then the reaction at the driven DOFs (-f_int, one column each, in
        # DOF order, as our reaction columns); its fraction of the prescribed motion made is
        # in Uhis, at the driven DOFs.
        drive = reference(case, "load.csv").ravel()
        ref_lambda = ref_u @ drive / (drive @ drive)
        reactions = history[:, [i for i, name in enumerate(header)
                                if name.startswith("reaction_")]]
        assert reactions.shape == ref_f.shape
        assert np.abs(reactions - ref_f).max() <= 1e-6 * np.abs(ref_f).max()
    else:
        ref_lambda = ref_f.ravel()
    assert len(load_factor) == len(ref_lambda)
    assert np.abs(load_factor - ref_lambda).max() <= 1e-6 * np.abs(ref_lambda).max()
    assert np.abs(displacements - ref_u).max() <= 1e-6
    np.testing.assert_array_equal(history[:, 0], np.arange(1, len(ref_lambda) + 1))


def test_monitored_column_is_the_stop_dof(simulated):
    case, out, _ = simulated
    if case != "polygon_N5B8_auto":
        pytest.skip("only the polygon run has a monitored DOF")
    header, history = read_csv(out / "history.csv")
    _, displacements = read_csv(out / "displacements.csv")
    np.testing.assert_array_equal(history[:, header.index("u_4_z")], displacements[:, 14])
    # The stopping rule: the last increment passed 12 mm, the one before did not.
    assert abs(displacements[-1, 14]) > 12.0 >= abs(displacements[-2, 14])


def test_n4b5_hexagon_with_one_stiffness_per_bend_hinge():
    case = "polygon_N4B5_manual"
    vertices = reference(case, "input_nodes.csv")
    panels = [list(range(6))]
    # The problem gives each bend hinge its own stiffness per unit length (about
    # 0.9726 (L / 0.127)^(1/3) / L for a diagonal of length L), in bend-hinge order, which
    # PanelElements.bends shares with MERLIN2.
    stiffness = reference(case, "Kb.csv").ravel()
    laws = CreaseLaws(bar="ogden", fold=HingeLaw("enhanced_linear", (15.0, 345.0)),
                      bend=HingeLaw("super_linear_bend"))
    fixed = np.zeros((6, 3), dtype=bool)
    fixed.ravel()[reference(case, "fixed_dofs.csv", int).ravel() - 1] = True
    pm = build_pattern_model((vertices, panels), split="N4B5", laws=laws, fixed=fixed,
                             material=ManualProperties(bar_modulus=5e3, bar_area=2.4652,
                                                       bend_stiffness=stiffness),
                             merlin2_compat=True)
    assert_model_equals_merlin2(pm, case)
    path = solve_mgdcm(pm.model, reference(case, "load.csv").ravel(), initial_load_factor=1e-5,
                       max_increments=100, monitor_dof=14, max_displacement=12.0)
    ref_u, ref_lambda = reference(case, "Uhis.csv"), reference(case, "Fhis.csv").ravel()
    assert path.completed and path.num_steps == len(ref_lambda)
    assert np.abs(path.load_factor - ref_lambda).max() <= 1e-6 * np.abs(ref_lambda).max()
    assert np.abs(path.displacement - ref_u).max() <= 1e-6


def test_energy_split_equals_merlin2s(simulated):
    """PostProcess's energies: bars, folds, bends per increment, to 1e-7 of the largest.

    Our bar strains come from squared lengths, MERLIN2's from the displacements: the two
    roundings differ, and at the hexagon's strains (~1e-4) that shows in the bar energy
    at 1.3e-8 of its largest value; 1e-7 leaves room for it and nothing more."""
    case, out, _ = simulated
    header, history = read_csv(out / "history.csv")
    for ours, theirs in (("energy_bars", "energy_bars.csv"), ("energy_folds", "energy_fold.csv"),
                         ("energy_bends", "energy_bend.csv")):
        ref = reference(case, theirs).ravel()
        values = history[:, header.index(ours)]
        scale = max(np.abs(ref).max(), 1e-300)
        assert np.abs(values - ref).max() <= 1e-7 * scale + 1e-15, ours


@pytest.mark.parametrize("analysis, share, stepping", [
    ({"increments": "adaptive"}, 0.2, "adaptive increments"),
    ({"predictor": "cubic"}, 0.3, "equal increments, each started from a cubic extrapolation"),
], ids=["adaptive increments", "fixed increments, cubic predictor"])
def test_faster_modes_follow_merlin2s_gmiura_path(analysis, share, stepping):
    # The GMiura point load's 200 samples, followed in adaptive increments, or in its fixed
    # ones with each Newton solve started from a cubic extrapolation of the path (MERLIN2
    # took 1,863 Newton iterations from the previous equilibrium). MERLIN2's own increments
    # are the samples k/200 up to its first rejected one (188): there the paths agree as
    # the samples are meant to, the reaction within 1e-8 of its largest value, and the
    # displacements within MERLIN2's Newton tolerance (1e-6 mm), as the fixed-step
    # comparisons above. Measured: adaptive 3.6e-10 and 1.2e-7 mm in 274 iterations; cubic
    # predictor 3.9e-12 and 1.2e-7 mm in 481 iterations.
    case = "gmiura_pointload"
    problem = load_problem(DATA / case / "problem.toml")
    ours = simulate(dataclasses.replace(
        problem, analysis=dataclasses.replace(problem.analysis, **analysis)), progress=False)
    ref_u, ref_f = reference(case, "Uhis.csv"), reference(case, "Fhis.csv").ravel()
    drive = reference(case, "load.csv").ravel()
    fraction = ref_u @ drive / (drive @ drive)
    same = np.flatnonzero(np.abs(fraction - np.arange(1, len(fraction) + 1) / 200) < 1e-12)
    assert ours.completed and ours.path.num_steps == 200
    assert ours.summary()["stepping"].startswith(stepping)
    assert len(same) == 187 and same[-1] == 186
    np.testing.assert_allclose(ours.path.load_factor[same], fraction[same], rtol=1e-12)
    assert np.abs(ours.path.displacement[same] - ref_u[same]).max() <= 1e-6
    reaction = np.asarray(ours.path.constraint_force)[same, 0]
    assert np.abs(reaction - ref_f[same]).max() <= 1e-8 * np.abs(ref_f).max()
    assert ours.path.iterations.sum() < share * 1863
