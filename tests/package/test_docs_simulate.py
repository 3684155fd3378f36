"""docs/simulate.md documents exactly the keys the problem reader accepts.

The reader reports an unknown key with the list of keys the table allows (for the variant
being read: "auto" or "manual" calibration, each analysis method, ...). Each table is given
one unknown key in every variant, and the union of what it allows is compared with the keys
the page's tables list under that table's heading, both ways: a key added to the reader
without a line in the page fails here, and so does a documented key the reader refuses.
"""

import ast
import copy
import re
from pathlib import Path

import pytest

from kresling.model.pattern_model import FOLD_FAMILIES
from kresling.simulate import load_problem

PAGE = Path(__file__).resolve().parents[2] / "docs" / "simulate.md"

SQUARE = {"vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]],
          "panels": [[0, 1, 2], [0, 2, 3]]}
BASE = {
    "pattern": dict(SQUARE),
    "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0,
                 "fold_stiffness": 0.01},
    "laws": {"mountain": {"law": "linear"}},
    "support": [{"nodes": [0, 1, 2], "fix": "xyz"}],
    "load": [{"node": 3, "displacement": [0.0, 0.0, 0.1]}],
    "analysis": {"method": "displacement_control", "steps": 2,
                 "stop": {"node": 3, "axis": "z", "beyond": 1.0}},
}
FORCE = {"load": [{"nodes": [3], "force": [0.0, 0.0, 0.1]}]}
# Each variant: changes to BASE. Every table is read in each.
VARIANTS = [
    {},
    {"pattern": {"file": "square.obj"}},
    {"material": {"calibration": "auto", "E": 1e3, "nu": 0.3, "thickness": 0.1,
                  "length_scale": 2.0}},
    {**FORCE, "analysis": {"method": "force_control", "steps": 2,
                           "stop": {"node": 3, "axis": "z", "beyond": 1.0}}},
    {**FORCE, "analysis": {"method": "mgdcm", "stop": {"nodes": [3], "axis": "z", "beyond": 1.0}}},
    {"support": [{"node": 0, "fix": "xyz"}, {"nodes": [1, 2], "fix": "xyz"}]},
    {"load": [{"nodes": [3], "force": [0.0, 0.0, 0.1], "time": "ramp", "ramp_time": 0.1}],
     "mass": [{"node": 3, "mass": 1e-6}],
     "dynamics": {"scheme": "hht", "time_step": 1e-3, "duration": 0.01,
                  "damping": {"alpha": 1.0, "beta": 1e-4}, "damping_tangent": "current",
                  "gravity": [0.0, 0.0, -9810.0], "hht_alpha": -0.1},
     "actuation": [{"edges": [[0, 2]], "fold_angle_deg": 10.0, "time": "ramp",
                    "ramp_time": 0.01}],
     "analysis": {"method": "dynamic", "stop": {"node": 3, "axis": "z", "beyond": 1.0}}},
    {**FORCE, "mass": [{"node": 3, "mass": 1e-6}],
     "dynamics": {"scheme": "explicit", "time_step": 1e-5, "duration": 0.01,
                  "record_every": 10},
     "analysis": {"method": "dynamic", "stop": {"node": 3, "axis": "z", "beyond": 1.0}}},
    {**FORCE, "actuation": [{"edges": [[0, 2]], "fold_angle_deg": 10.0}],
     "analysis": {"method": "fold", "steps": 2, "snap": True,
                  "stop": {"node": 3, "axis": "z", "beyond": 1.0}}},
    {**FORCE, "bar": [{"nodes": [0, 2], "modulus": 1.0, "area": 1.0}],
     "hinge": [{"nodes": [0, 2, 1, 3], "stiffness": 1.0}]},
    {**FORCE, "material": {"preset": "origami_simulator"},
     "actuation": [{"family": "fold", "fold_angle_deg": 10.0}],
     "analysis": {"method": "fold", "stop": {"node": 3, "axis": "z", "beyond": 1.0}}},
]
# The page's heading of each table, and where in the problem the unknown key goes.
TABLES = {
    "[pattern]": (("pattern",),),
    "[material]": (("material",),),
    "[laws]": (("laws",), ("laws", "mountain")),
    "[[support]]": (("support", 0),),
    "[[load]]": (("load", 0),),
    "[analysis]": (("analysis",), ("analysis", "stop")),
    "[dynamics]": (("dynamics",),),
    "[[actuation]]": (("actuation", 0),),
    "[[bar]]": (("bar", 0),),
    "[[hinge]]": (("hinge", 0),),
}


def _allowed(problem, where, tmp_path):
    problem = copy.deepcopy(problem)
    table = problem
    for key in where:
        table = table[key]
    table["zz_not_a_key"] = 1
    with pytest.raises(ValueError, match="zz_not_a_key") as error:
        load_problem(problem)
    return set(ast.literal_eval(re.search(r"allowed keys are (\[.*?\])", str(error.value))[1]))


def _documented(heading):
    """Keys named in the first column of the ``| key | ...`` tables under the page's
    heading ``## `HEADING`...``."""
    text = PAGE.read_text()
    section = text.split(f"## `{heading}`", 1)[1].split("\n## ", 1)[0]
    keys, in_key_table = set(), False
    for line in section.splitlines():
        if not line.startswith("|"):
            in_key_table = False
            continue
        first = line.split("|")[1].strip()
        if first == "key":
            in_key_table = True
        elif in_key_table:
            keys |= set(re.findall(r"`(\w+)`", first))
    return keys


@pytest.fixture(scope="module")
def accepted(tmp_path_factory):
    folder = tmp_path_factory.mktemp("problem")
    (folder / "square.obj").write_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n")
    keys = {heading: set() for heading in TABLES}
    for variant in VARIANTS:
        problem = {**copy.deepcopy(BASE), **copy.deepcopy(variant)}
        if "file" in problem["pattern"]:
            problem["pattern"]["file"] = str(folder / "square.obj")
        for heading, places in TABLES.items():
            for where in places:
                if where[0] in problem:   # ([dynamics] is in the dynamic variants only)
                    keys[heading] |= _allowed(problem, where, folder)
    return keys


@pytest.mark.parametrize("heading", list(TABLES))
def test_every_key_the_reader_accepts_is_documented(accepted, heading):
    # Family sub-tables of [laws] are documented as [laws.<family>], not as keys.
    missing = accepted[heading] - set(FOLD_FAMILIES) - _documented(heading)
    assert not missing, f"docs/simulate.md, {heading}: undocumented keys {sorted(missing)}"


@pytest.mark.parametrize("heading", list(TABLES))
def test_every_documented_key_is_accepted(accepted, heading):
    extra = _documented(heading) - accepted[heading]
    assert not extra, f"docs/simulate.md, {heading}: keys the reader refuses {sorted(extra)}"


def test_every_fold_family_has_its_laws_table_documented():
    text = PAGE.read_text()
    for family in FOLD_FAMILIES:
        assert f"`[laws.{family}]`" in text, family
