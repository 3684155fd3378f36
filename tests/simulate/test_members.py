"""Bars and hinges given one by one in problem files ([[bar]], [[hinge]]): structures that
are not panel sheets (a linkage with coincident nodes), hinges with any wings, and their
refusals.

References: Bennett's closure condition for the linkage (a closed form of its geometry
alone), the rest angle a lone hinge must reach when nothing else resists it, and the same
model built through :class:`kresling.model.Members` in Python.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from kresling.model import Members, build_pattern_model
from kresling.simulate import build_problem_model, load_problem, simulate

BENNETT = Path(__file__).resolve().parents[2] / "examples" / "bennett_linkage" / "problem.toml"

#: The joint axes of the Bennett example in order round its loop (0-based nodes).
BENNETT_AXES = ((4, 5), (11, 12), (16, 17), (1, 2))


def _joint_angles_and_twists(X):
    """Each joint's angle between the common normals of its two links, about the joint's
    axis, and each link's twist between its two axes, about their common normal [rad]."""
    points = [X[a] for a, _ in BENNETT_AXES]
    axes = [(X[b] - X[a]) / np.linalg.norm(X[b] - X[a]) for a, b in BENNETT_AXES]
    n = len(axes)
    normals = []
    for i in range(n):
        j = (i + 1) % n
        x = np.cross(axes[i], axes[j])
        x /= np.linalg.norm(x)
        normals.append(x if np.dot(points[j] - points[i], x) >= 0 else -x)
    joints = [np.arctan2(np.dot(np.cross(normals[i - 1], normals[i]), axes[i]),
                         np.dot(normals[i - 1], normals[i])) for i in range(n)]
    twists = [np.arctan2(np.dot(np.cross(axes[i], axes[(i + 1) % n]), normals[i]),
                         np.dot(axes[i], axes[(i + 1) % n])) for i in range(n)]
    return np.array(joints), np.array(twists)


def test_the_bennett_linkage_moves_as_bennetts_closed_form_says():
    sim = simulate(BENNETT)
    assert sim.completed
    model = sim.model
    assert (model.num_nodes, len(model.bars), len(model.hinges)) == (24, 68, 4)
    # Coincident nodes of different links stay two nodes.
    assert np.allclose(model.nodes[6], model.nodes[8]) and np.allclose(model.nodes[0],
                                                                       model.nodes[22])
    _, twists = _joint_angles_and_twists(model.nodes)
    alpha, beta = abs(twists[0]), np.pi - abs(twists[1])
    bennett = np.sin((alpha + beta) / 2) / np.sin((beta - alpha) / 2)
    path = sim.path.displacement
    moved = 0.0
    for u in path:
        X = model.nodes + u.reshape(-1, 3)
        joints, _ = _joint_angles_and_twists(X)
        # The bars strain by < 1e-8 (EA = 2e5 N against hinge moments of ~1 N mm): the
        # links are rigid to that, and the closed form holds to ~1e-7 relative.
        assert np.tan(joints[0] / 2) * np.tan(joints[1] / 2) == pytest.approx(bennett,
                                                                             rel=1e-6)
        np.testing.assert_allclose(joints[2:], joints[:2], atol=1e-6)
        moved = max(moved, abs(joints[0] - _joint_angles_and_twists(model.nodes)[0][0]))
        assert np.abs(model.element_state(u)["bar_strain"]).max() < 1e-8
    assert np.degrees(moved) > 80.0   # it moved: the driven joint turned by ~90 deg


def _two_triangles(**hinge):
    """Two triangles on the axis 0 -> 1, as members alone: a lone hinge (the stiffness
    given), wing 3's triangle held, the hinge folded to 40 deg."""
    entry = {"nodes": [0, 1, 2, 3], "stiffness": 2.0, **hinge}
    return {
        "pattern": {"vertices": [[0, 0, 0], [10, 0, 0], [5, 8, 0], [5, -8, 0]], "panels": []},
        "bar": [{"nodes": [[0, 1], [1, 2], [2, 0], [1, 3], [3, 0]], "modulus": 1e4,
                 "area": 1.0}],
        "hinge": [entry],
        "support": [{"nodes": [0, 1, 3], "fix": "xyz"}],
        "actuation": [{"edges": [[0, 1]], "fold_angle_deg": 40.0}],
        "analysis": {"method": "fold", "steps": 4},
    }


def test_a_lone_hinge_folds_to_its_target_whichever_convention_names_it():
    sim = simulate(_two_triangles())
    assert sim.completed
    theta = sim.model.element_state(sim.path.displacement[-1])["hinge_angle"][0]
    # Nothing else resists the hinge: it reaches its rest angle (180 - 40 deg for a hinge
    # of no panel) to Newton's tolerance (1e-6 mm on a 8 mm wing: ~1e-7 rad).
    assert np.degrees(theta) == pytest.approx(140.0, abs=1e-5)
    # Sim-FAST's order [i, j, k, l] = [c, a, b, d] and its dihedral rest angle name the
    # same hinge and the same rest angle as FOLD's fold angle does.
    by_fold = build_problem_model(dict(_two_triangles(rest_angle_deg=40.0)))
    by_simfast = build_problem_model(dict(_two_triangles(
        nodes=[2, 0, 1, 3], convention="simfast", rest_angle_deg=140.0)))
    np.testing.assert_array_equal(by_fold.model.hinges, by_simfast.model.hinges)
    np.testing.assert_allclose(by_fold.model.hinge_rest_angle, np.radians(140.0), rtol=1e-15)
    np.testing.assert_allclose(by_simfast.model.hinge_rest_angle, np.radians(140.0),
                               rtol=1e-15)
    assert by_fold.hinge_family == ("member",)


def test_members_in_a_problem_are_the_members_of_the_python_model():
    built = build_problem_model(dict(_two_triangles(rest_angle_deg=30.0)))
    p = load_problem(dict(_two_triangles(rest_angle_deg=30.0)))
    by_hand = build_pattern_model(
        p.pattern, material=p.material or _unused(), fixed=built.model.fixed,
        members=Members([[0, 1], [1, 2], [2, 0], [1, 3], [3, 0]], 1e4, 1.0, ("linear",) * 5,
                        [[0, 1, 2, 3]], 2.0, np.radians(150.0), ("linear",)))
    for name in ("bars", "bar_modulus", "bar_area", "bar_rest_length", "hinges",
                 "hinge_stiffness", "hinge_length", "hinge_law", "bar_law"):
        np.testing.assert_array_equal(getattr(built.model, name), getattr(by_hand.model, name))
    np.testing.assert_allclose(built.model.hinge_rest_angle, by_hand.model.hinge_rest_angle,
                               rtol=1e-15)
    # A member hinge's stiffness is its whole moment per radian (length 1, not its axis).
    assert built.model.hinge_length.tolist() == [1.0]


def _unused():
    from kresling.model import ManualProperties
    return ManualProperties(bar_modulus=1.0, bar_area=1.0)


def test_a_member_hinge_beside_a_sheets_creases():
    """A hinge across a quad panel's other diagonal (no bar on its axis) beside the panel's
    own bars: the model has both, the member after the pattern's elements."""
    problem = {
        "pattern": {"vertices": [[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0]],
                    "panels": [[0, 1, 2, 3]], "split": "N4B5"},
        "analysis": {"method": "fold"}, "actuation": [{"edges": [[1, 3]],
                                                       "fold_angle_deg": 10.0}],
        "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0,
                     "bend_stiffness": 1.0},
        "hinge": [{"nodes": [1, 3, 2, 0], "stiffness": 5.0}],
    }
    pm = build_problem_model(problem)
    assert pm.hinge_family[-1] == "member" and pm.hinge_family[:-1] == ("bend",)
    assert pm.model.hinges[-1].tolist() == [1, 3, 2, 0]
    assert pm.model.hinge_stiffness[-1] == 5.0
    assert pm.model.hinge_rest_angle[-1] == pytest.approx(np.pi, abs=1e-15)


@pytest.mark.parametrize("change, match", [
    ({"bar": [{"nodes": [[0, 1]], "modulus": 1.0}]}, r"\[bar\] key 'area' is missing"),
    ({"bar": [{"nodes": [0, 7], "modulus": 1.0, "area": 1.0}]}, "has node 7: out of range"),
    ({"bar": [{"nodes": [2, 2], "modulus": 1.0, "area": 1.0}]}, "2 different nodes"),
    ({"bar": [{"nodes": [[0, 1, 2]], "modulus": 1.0, "area": 1.0}]}, r"each is a bar: \[i, j\]"),
    ({"bar": [{"nodes": [0, 1], "modulus": -1.0, "area": 1.0}]}, "'modulus' = -1.0 is invalid"),
    ({"hinge": [{"nodes": [0, 1, 2], "stiffness": 1.0}]}, r"a hinge: \[a, b, c, d\]"),
    ({"hinge": [{"nodes": [0, 1, 2, 3], "stiffness": -1.0}]}, "'stiffness'.* must be >= 0"),
    ({"hinge": [{"nodes": [0, 1, 2, 3], "stiffness": 1.0, "rest_angle_deg": 200.0}]},
     r"must be a fold angle in \[-180, 180\]"),
    ({"hinge": [{"nodes": [0, 1, 2, 3], "stiffness": 1.0, "rest_angle_deg": 360.0,
                 "convention": "simfast"}]}, r"a dihedral angle in \[0, 360\)"),
    ({"hinge": [{"nodes": [0, 1, 2, 3], "stiffness": 1.0, "rest_angle_deg": [1.0, 2.0]}]},
     "has 2 angles: must be one number or 1"),
    ({"hinge": [{"nodes": [0, 1, 2, 3], "stiffness": 1.0, "convention": "merlin"}]},
     "convention"),
])
def test_bad_members_are_refused_naming_the_key(change, match):
    problem = {**_two_triangles(), **change}
    with pytest.raises(ValueError, match=match):
        build_problem_model(problem)


def test_coincident_nodes_may_not_be_joined_and_panels_need_a_material():
    problem = _two_triangles()
    problem["pattern"]["vertices"].append([10, 0, 0])   # node 4 at node 1's point
    joined = dict(problem, bar=problem["bar"] + [{"nodes": [1, 4], "modulus": 1.0,
                                                   "area": 1.0}])
    with pytest.raises(ValueError, match=r"\[\[bar\]\]: member bars\[5\] = \[1, 4\]: the bar "
                                         "joins two nodes at one point"):
        build_problem_model(joined)
    apart = dict(problem, bar=problem["bar"] + [{"nodes": [2, 4], "modulus": 1.0,
                                                  "area": 1.0}])
    assert build_problem_model(apart).model.num_nodes == 5   # node 4 on a bar of its own
    with pytest.raises(ValueError, match="vertex 4 .*is a corner of no panel"):
        build_problem_model(problem)    # node 4 on nothing
    # (A fold would take its preset material; a force-controlled run has none.)
    sheet = {"pattern": {"vertices": [[0, 0], [1, 0], [0, 1]], "panels": [[0, 1, 2]]},
             "bar": [{"nodes": [0, 1], "modulus": 1.0, "area": 1.0}],
             "load": [{"node": 2, "force": [0, 0, 1]}],
             "analysis": {"method": "force", "steps": 1}}
    with pytest.raises(ValueError, match=r"\[pattern\] key 'panels' gives panels, which need "
                                         r"a \[material\]"):
        load_problem(sheet)


def test_a_member_hinge_whose_wing_lies_on_its_axis_is_refused_naming_the_key():
    problem = _two_triangles()
    problem["pattern"]["vertices"].append([5, 0, 0])     # node 4 on the axis 0 -> 1
    problem["bar"][0]["nodes"].append([4, 2])
    problem["hinge"].append({"nodes": [0, 1, 4, 3], "stiffness": 1.0})
    with pytest.raises(ValueError, match=r"\[\[hinge\]\]: member hinges\[1\] = \[0, 1, 4, 3\]: "
                                         "wing node 4 lies on the axis line 0 -> 1"):
        build_problem_model(problem)
