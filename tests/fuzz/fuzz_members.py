"""Fuzz: the problem keys that build structures member by member - [[bar]], [[hinge]]
(both conventions), ``panels = []`` with coincident nodes, and a fold's
``target_tolerance_deg`` - with values of every kind. A problem is built and run (the run
ends finite, or stopped saying why) or refused with a ValueError naming the key; never a
traceback, a crash or a silent NaN."""

import copy

import numpy as np
from hypothesis import event, given
from hypothesis import strategies as st

from _fuzz import edgy_floats, fuzz, junk, mostly, path_ok
from kresling.simulate import load_problem, simulate

#: Two triangles on the axis 0 -> 1 as members alone, and a node 4 at node 1's point.
TRIANGLES = {
    "pattern": {"vertices": [[0, 0, 0], [10, 0, 0], [5, 8, 0], [5, -8, 0], [10, 0, 0]],
                "panels": []},
    "bar": [{"nodes": [[0, 1], [1, 2], [2, 0], [1, 3], [3, 0], [2, 4]], "modulus": 1e4,
             "area": 1.0}],
    "hinge": [{"nodes": [0, 1, 2, 3], "stiffness": 2.0}],
    "support": [{"nodes": [0, 1, 3], "fix": "xyz"}],
    "actuation": [{"edges": [[0, 1]], "fold_angle_deg": 40.0}],
    "analysis": {"method": "fold", "steps": 2},
}
node = mostly(st.integers(0, 4), st.integers(-3, 8), junk)
nodes = st.one_of(st.lists(node, min_size=0, max_size=5),
                  st.lists(st.lists(node, min_size=1, max_size=5), min_size=0, max_size=3),
                  junk)


def _run(problem, *keys):
    try:
        loaded = load_problem(problem)
        run = simulate(loaded, progress=False)
    except ValueError as error:
        assert any(key in str(error) for key in keys), f"names none of {keys}: {error}"
        event("refused")
        return None
    path_ok(run.path)
    assert np.isfinite(run.path.displacement).all()
    event("completed" if run.completed else "stopped")
    return run


@fuzz(30)
@given(nodes, mostly(st.floats(1e-3, 1e6), edgy_floats, junk),
       mostly(st.floats(1e-3, 1e3), edgy_floats, junk),
       mostly(st.sampled_from(["linear", "ogden"]), junk, st.text(max_size=5)))
def test_bar_entries(bar_nodes, modulus, area, law):
    problem = copy.deepcopy(TRIANGLES)
    problem["bar"].append({"nodes": bar_nodes, "modulus": modulus, "area": area, "law": law})
    _run(problem, "[bar]", "member bars", "vertex")


@fuzz(30)
@given(nodes, mostly(st.floats(0, 1e3), edgy_floats, junk),
       st.one_of(st.none(), mostly(st.floats(-200, 400), edgy_floats, junk),
                 st.lists(st.floats(-200, 400), max_size=3)),
       mostly(st.sampled_from(["fold", "simfast"]), junk),
       mostly(st.sampled_from(["linear", "enhanced_linear", "super_linear_bend"]), junk))
def test_hinge_entries(hinge_nodes, stiffness, rest, convention, law):
    problem = copy.deepcopy(TRIANGLES)
    entry = {"nodes": hinge_nodes, "stiffness": stiffness, "convention": convention,
             "law": law}
    if rest is not None:
        entry["rest_angle_deg"] = rest
    problem["hinge"].append(entry)
    _run(problem, "[hinge]", "member hinges", "hinges[")


@fuzz(20)
@given(st.lists(st.lists(mostly(st.floats(-20, 20), edgy_floats), min_size=3, max_size=3),
                min_size=5, max_size=5),
       st.sampled_from([[], [[0, 1, 2]], "none", [[]]]))
def test_member_structure_geometry(vertices, panels):
    """Any node positions (coincident, collinear, far apart) and empty or odd panels."""
    problem = copy.deepcopy(TRIANGLES)
    problem["pattern"] = {"vertices": vertices, "panels": panels}
    _run(problem, "[pattern]", "[bar]", "[hinge]", "member", "vertex", "hinge", "bar",
         "[[support]]", "[analysis]")


@fuzz(15)
@given(mostly(st.floats(1e-3, 180), edgy_floats, junk))
def test_target_tolerance_key(tolerance):
    problem = copy.deepcopy(TRIANGLES)
    problem["analysis"]["target_tolerance_deg"] = tolerance
    run = _run(problem, "target_tolerance_deg")
    if run is not None:
        assert run.fold_report()["tolerance_deg"] == float(tolerance)
