"""Springs on the triangles' interior angles (the ``face_angles`` family): against the
independent implementation of kresling/testing/origami_simulator.py, through build_pattern_model
and through problem files ([material] face_stiffness).

Tolerances: the two implementations evaluate the same closed form in different orders
(atan2 of the corner's cross and dot products, the same rest angles), so forces and energies
agree to rounding: 1e-10 relative leaves room for it and catches any wrong term."""

from __future__ import annotations

import numpy as np
import pytest

from kresling.testing import origami_simulator as osm
from kresling.assembly import assemble
from kresling.io import read_pattern
from kresling.model import ManualProperties, Model, build_pattern_model, family_kinds
from kresling.simulate import load_problem, simulate
from kresling.simulate import build_problem_model
from public_files import ORIGAMI_SIMULATOR


@pytest.fixture(scope="module")
def bird():
    pattern = read_pattern(ORIGAMI_SIMULATOR / "flappingBird.svg")
    return osm.build(pattern)


def _faces_only(reference, stiffness):
    """The reference's triangles as a model of nothing but corner springs."""
    return Model(reference.x0, [], [], bar_modulus=1.0, hinge_stiffness=1.0,
                 families={"face_angles": {
                     "nodes": reference.triangles.astype(np.int64),
                     "rest_angle": reference.corner_angle,
                     "stiffness": np.full(len(reference.triangles), stiffness)}})


def test_the_family_is_registered():
    assert "face_angles" in family_kinds()


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_forces_and_energy_equal_origami_simulators_face_springs(bird, seed):
    stiffness = 0.2
    model = _faces_only(bird, stiffness)
    u = 0.05 * np.random.default_rng(seed).standard_normal(bird.x0.shape)
    x = bird.x0 + u
    theirs = np.zeros_like(x)
    osm._add_face_forces(bird, x, theirs, stiffness)      # minus the energy's gradient
    a = assemble(model, u.ravel())
    np.testing.assert_allclose(a.force, -theirs.ravel(), rtol=0,
                               atol=1e-10 * np.abs(theirs).max())
    energy = 0.5 * stiffness * np.sum((osm.corner_angles(bird, x) - bird.corner_angle) ** 2)
    assert a.energies["face_angles"] == pytest.approx(energy, rel=1e-10)
    # The tangent is the force's derivative (central differences, h = 1e-6 on a unit
    # sheet: error ~1e-10 of the largest entry).
    h, k = 1e-6, 7
    du = np.zeros(u.size)
    du[k] = h
    column = (assemble(model, u.ravel() + du).force - assemble(model, u.ravel() - du).force) / (2 * h)
    stiffness_matrix = a.stiffness.toarray()
    np.testing.assert_allclose(stiffness_matrix[:, k], column, rtol=0,
                               atol=1e-7 * np.abs(stiffness_matrix).max())


def test_a_pattern_model_with_a_face_stiffness_holds_every_triangle_at_its_flat_angles():
    pattern = read_pattern(ORIGAMI_SIMULATOR / "birdBase.svg")
    pm = build_pattern_model(pattern, material=ManualProperties(1e3, 1.0, 1.0, 1.0,
                                                                face_stiffness=0.3))
    faces = pm.model.family("face_angles")
    np.testing.assert_array_equal(faces["nodes"].reshape(-1, 3), pm.elements.triangles)
    np.testing.assert_allclose(faces["rest_angle"].reshape(-1, 3).sum(axis=1), np.pi,
                               rtol=1e-14)
    assert assemble(pm.model).energies["face_angles"] < 1e-25
    plain = build_pattern_model(pattern, material=ManualProperties(1e3, 1.0, 1.0, 1.0))
    assert "face_angles" not in plain.model.families
    with pytest.raises(ValueError, match="face_stiffness = -1 is invalid"):
        ManualProperties(1e3, 1.0, 1.0, 1.0, face_stiffness=-1)


def _problem(tmp_path, material_line, extra=""):
    path = tmp_path / "p.toml"
    path.write_text(f"""
[pattern]
vertices = [[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0]]
panels = [[0, 1, 2, 3]]
split = "N4B5"
[material]
calibration = "manual"
bar_modulus = 1e3
bar_area = 1.0
bend_stiffness = 1.0
{material_line}
[[support]]
nodes = [0, 1, 3]
fix = "xyz"
[[load]]
nodes = [2]
force = [0.0, 1.0, 0.0]
[analysis]
method = "force_control"
steps = 2
{extra}
""")
    return path


def test_the_problem_files_face_stiffness_shears_the_panel_less(tmp_path):
    # The square's far corner pushed along y: its corner springs resist the shear the bars
    # alone take (the panel's diagonal bar stretches less with them).
    soft = simulate(_problem(tmp_path, ""), progress=False)
    stiff = simulate(_problem(tmp_path, "face_stiffness = 50.0"), progress=False)
    assert soft.completed and stiff.completed
    assert "face_angles" in stiff.path.families
    assert stiff.path.energy_of("face_angles")[-1] > 0
    assert np.abs(stiff.path.displacement[-1][6:9]).max() < \
        np.abs(soft.path.displacement[-1][6:9]).max()
    # With panel contact added, the faces' springs stay in the model.
    both = load_problem(_problem(tmp_path, "face_stiffness = 50.0",
                                 "[contact]\ndistance = 0.1\nself = true"))
    assert {"face_angles", "self_contact"} <= set(build_problem_model(both).model.families)


def test_a_bad_face_stiffness_is_refused_naming_the_key(tmp_path):
    with pytest.raises(ValueError, match=r"face_stiffness"):
        load_problem(_problem(tmp_path, "face_stiffness = -2.0"))
