"""A structure of members given one by one is drawn: its member bars as lines beside the
hinges' axes (it has no panels to shade)."""

from __future__ import annotations

import numpy as np

from kresling.simulate import build_problem_model
from kresling.view.inputs import view_inputs

LINKAGE = {
    "pattern": {"vertices": [[0, 0, 0], [10, 0, 0], [5, 8, 0], [5, -8, 0]], "panels": []},
    "bar": [{"nodes": [[0, 1], [1, 2], [2, 0], [1, 3], [3, 0]], "modulus": 1e4, "area": 1.0}],
    "hinge": [{"nodes": [0, 1, 2, 3], "stiffness": 2.0}],
    "support": [{"nodes": [0, 1, 3], "fix": "xyz"}],
    "actuation": [{"edges": [[0, 1]], "fold_angle_deg": 40.0}],
    "analysis": {"method": "fold", "steps": 2},
}


def test_member_bars_are_lines_of_their_own():
    inputs = view_inputs(build_problem_model(LINKAGE))
    assert len(inputs.triangles) == 0
    np.testing.assert_array_equal(inputs.lines["member bar"],
                                  [[0, 1], [1, 2], [2, 0], [1, 3], [3, 0]])
    assert list(inputs.hinge_family) == ["member"]


def test_a_sheet_has_no_member_lines():
    sheet = {"pattern": {"vertices": [[0, 0], [1, 0], [0, 1]], "panels": [[0, 1, 2]]},
             "material": {"calibration": "manual", "bar_modulus": 1.0, "bar_area": 1.0},
             "support": [{"nodes": [0, 1, 2], "fix": "xyz"}],
             "load": [{"node": 2, "force": [0, 0, 0.0]}],
             "analysis": {"method": "force_control", "steps": 1}}
    assert view_inputs(build_problem_model(sheet)).lines == {}


def test_the_path_page_draws_the_member_bars(tmp_path):
    from kresling.simulate import simulate

    sim = simulate(LINKAGE, progress=False)
    sim.write(tmp_path)
    page = (tmp_path / "view.html").read_text()
    assert '"member bar"' in page and '"member"' in page
