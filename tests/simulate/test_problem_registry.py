"""The problem file and the run as registries: every key a module of
kresling.simulate.problem_keys, every method one of kresling.simulate.methods; a key or a
method added to its registry alone is read, checked, built and run."""

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

import kresling.simulate.methods as methods_registry
import kresling.simulate.problem_keys as keys_registry
from kresling.simulate import build_problem_model, load_problem, simulate
from kresling.simulate.methods import method_named, method_names
from kresling.simulate.methods.force_control import METHOD as FORCE_CONTROL
from kresling.simulate.problem_keys import ProblemKey, problem_keys
from kresling.simulate.problem_table import node_list, number

DOCS = Path(__file__).resolve().parents[2] / "docs"

TRIANGLE = {
    "pattern": {"vertices": [[0, 0, 0], [10, 0, 0], [0, 10, 0]], "panels": [[0, 1, 2]]},
    "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0},
    "support": [{"node": 0, "fix": "xyz"}, {"node": 1, "fix": "yz"}, {"node": 2, "fix": "z"}],
    "load": [{"node": 2, "force": [0.0, 1.0, 0.0]}],
    "analysis": {"method": "force_control", "steps": 2}}


def test_every_key_and_method_is_documented_under_its_own_name():
    simulate_md = (DOCS / "simulate.md").read_text() + (DOCS / "dynamics.md").read_text()
    for key in problem_keys():
        assert f"`{key.label}`" in simulate_md, key.label
    assert [key.rank for key in problem_keys()] == sorted(key.rank for key in problem_keys())
    methods_row = re.search(r"^\| `method` \| (.*?) \|", (DOCS / "simulate.md").read_text(),
                            re.M).group(1)
    assert re.findall(r'"(\w+)"', methods_row) == list(method_names())


@dataclass(frozen=True)
class Ground:
    stiffness: float
    nodes: tuple


def _read_ground(t, context):
    # Any number: the model's springs family refuses a negative one, naming this key.
    ground = Ground(t.get("stiffness", number, required=True, allowed="k [N/mm]"),
                    node_list(t, context.num_nodes))
    t.finish()
    return {"ground": ground}


def _ground_families(problem, pattern_model):
    if problem.ground is None:
        return {}
    nodes = np.array(problem.ground.nodes, dtype=np.int64)
    return {"springs": {"nodes": nodes,
                        "stiffness": np.full((len(nodes), 3), problem.ground.stiffness),
                        "anchor": pattern_model.model.nodes[nodes]}}


def _only_static(problem):
    if problem.ground is not None and problem.method.in_time:
        raise ValueError(f"{problem.source}: [ground] is for static runs")


GROUND = ProblemKey("ground", rank=120, read=_read_ground, absent={"ground": None},
                    check=_only_static, families=_ground_families)


@pytest.fixture
def with_ground(monkeypatch):
    """The registry with one more key, as a new module of the package would add it."""
    monkeypatch.setattr(keys_registry, "_KEYS", problem_keys() + (GROUND,))


def test_a_key_added_to_the_registry_alone_is_read_built_and_run(with_ground):
    problem = {**TRIANGLE, "support": [{"node": 0, "fix": "xyz"}, {"node": 1, "fix": "yz"}],
               "ground": {"node": 2, "stiffness": 4.0}}
    read = load_problem(problem)
    assert read.ground == Ground(4.0, (2,))
    assert "springs" in build_problem_model(read).model.families
    run = simulate(problem, progress=False)
    # Node 2's y-spring of 4 N/mm takes the 1 N with the bars, so it moves less than 1/4 mm.
    assert run.completed and 0 < run.path.displacement[-1, 7] < 0.25
    assert "energy_springs" in run.history_columns()
    assert load_problem(TRIANGLE).ground is None


def test_an_added_keys_refusals_name_it(with_ground):
    with pytest.raises(ValueError, match=r"\[ground\] key 'stiffness' is missing: must be k"):
        load_problem({**TRIANGLE, "ground": {"node": 2}})
    with pytest.raises(ValueError, match=r"\[ground\] key 'extra' is unknown"):
        load_problem({**TRIANGLE, "ground": {"node": 2, "stiffness": 1.0, "extra": 0}})
    with pytest.raises(ValueError, match=r"problem: \[ground\]: spring 0 \(nodes 2\): stiffness"):
        simulate({**TRIANGLE, "ground": {"node": 2, "stiffness": -1.0}}, progress=False)


def test_without_the_registration_the_key_is_unknown():
    with pytest.raises(ValueError, match=r"key 'ground' is unknown"):
        load_problem({**TRIANGLE, "ground": {"node": 2, "stiffness": 4.0}})


class HalfForce(type(FORCE_CONTROL)):
    """Force control to half the load: a method of its own."""

    name = "half_force"

    def solve(self, problem, pattern_model, vector, common, plan):
        return super().solve(problem, pattern_model, 0.5 * vector, common, plan)


def test_a_method_added_to_the_registry_alone_is_read_and_run(monkeypatch):
    monkeypatch.setattr(methods_registry, "_METHODS",
                        {**methods_registry._methods(), "half_force": HalfForce()})
    half = simulate({**TRIANGLE, "analysis": {"method": "half_force", "steps": 2}},
                    progress=False)
    halved = simulate({**TRIANGLE, "load": [{"node": 2, "force": [0.0, 0.5, 0.0]}]},
                      progress=False)
    assert half.summary()["stepping"] == "equal load increments"
    # The same equations as force control under half the force: the same path, bit for bit.
    np.testing.assert_array_equal(half.path.displacement, halved.path.displacement)


def test_an_unknown_method_lists_every_registered_one():
    with pytest.raises(ValueError, match=r"\[analysis\] key 'method' = 'arc' is invalid: "
                                         r"must be one of \['displacement_control'"):
        load_problem({**TRIANGLE, "analysis": {"method": "arc"}})
    with pytest.raises(ValueError, match="is unknown: must be one of"):
        method_named("arc")
