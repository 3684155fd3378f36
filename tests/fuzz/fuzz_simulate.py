"""Fuzz: simulation problems (load_problem, simulate) from random problem dicts (unknown
keys, wrong types, NaN, huge numbers, out-of-range nodes) and mutated TOML files. Bad input
is a ValueError naming the key (or the file); a run returns a finite path or says why it
stopped."""

import copy
import math
import tempfile
import zlib
from pathlib import Path

import numpy as np
from hypothesis import event, given
from hypothesis import strategies as st

from _fuzz import edgy_floats, finite, fuzz, junk, mostly, path_ok
from kresling.simulate import build_problem_model, load_problem, simulate

SHEET = {"vertices": [[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0]],
         "panels": [[0, 1, 4, 3], [1, 2, 5, 4]]}
BASES = [
    {"pattern": dict(SHEET),
     "material": {"calibration": "auto", "E": 1000.0, "nu": 0.3, "thickness": 0.25},
     "support": [{"nodes": [0, 3], "fix": "xyz"}, {"node": 1, "fix": "z"}],
     "load": [{"nodes": [2, 5], "force": [0.0, 0.0, 0.01]}],
     "analysis": {"method": "mgdcm", "max_increments": 4}},
    {"pattern": dict(SHEET, split="N4B5"),
     "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0,
                  "fold_stiffness": 0.1, "bend_stiffness": 1.0},
     "laws": {"fold": "linear", "bend": "enhanced_linear", "valley": {"stiffness": 0.2}},
     "support": [{"nodes": [0, 3], "fix": "xyz"}, {"node": 1, "fix": "yz"},
                 {"node": 4, "fix": "z"}],
     "load": [{"nodes": [2, 5], "displacement": [0.0, 0.0, 0.2]}],
     "analysis": {"method": "displacement_control", "steps": 3},
     "output": {"every": 2, "curve": {"x": "u_2_z", "y": "reaction_2_z"}}},
    {"pattern": dict(SHEET),
     "material": {"calibration": "auto", "E": 1000.0, "nu": 0.3, "thickness": 0.25},
     "support": [{"nodes": [0, 3], "fix": "xyz"}, {"node": 1, "fix": "z"}],
     "load": [{"node": 5, "force": [0.0, 0.0, 0.001]}],
     "analysis": {"method": "force_control", "steps": 2, "max_load_factor": 1.0,
                  "stop": {"node": 5, "axis": "z", "beyond": 1.0}}},
    # Crease actuation in two stages, with elastic supports and a load that ramps.
    {"pattern": dict(SHEET),
     "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0,
                  "fold_stiffness": 0.1, "bend_stiffness": 1.0},
     "support": [{"nodes": [0, 3], "fix": "xyz"}, {"node": 1, "fix": "z"}],
     "spring": [{"nodes": [2, 5], "stiffness": [0.0, 0.0, 0.01]}],
     "load": [{"node": 5, "force": [0.0, 0.0, 0.001]}],
     "actuation": [{"edges": [[1, 4]], "fold_angle_deg": 30.0},
                   {"family": "fold", "fold_angle_deg": -10.0, "stage": 2}],
     "analysis": {"method": "fold", "steps": 2, "predictor": "linear"}},
    # Vibration modes from the sheet's density and node masses.
    {"pattern": dict(SHEET),
     "material": {"calibration": "auto", "E": 1000.0, "nu": 0.3, "thickness": 0.25,
                  "density": 1.38e-9},
     "support": [{"nodes": [0, 3], "fix": "xyz"}],
     "mass": [{"nodes": [2, 5], "mass": 1e-6}],
     "analysis": {"method": "modes", "modes": 3}},
    # A motion in time: a ramped and a harmonic load, damping and gravity; and explicit.
    {"pattern": dict(SHEET),
     "material": {"calibration": "auto", "E": 1000.0, "nu": 0.3, "thickness": 0.25,
                  "density": 1.38e-9},
     "support": [{"nodes": [0, 3], "fix": "xyz"}],
     "mass": [{"nodes": [2, 5], "mass": 1e-6}],
     "load": [{"node": 5, "force": [0.0, 0.0, 0.001], "time": "ramp", "ramp_time": 1e-3},
              {"node": 2, "force": [0.0, 0.0, 0.001], "time": {"harmonic": [1.0, 100.0]}}],
     "dynamics": {"scheme": "hht", "hht_alpha": -0.1, "time_step": 1e-3, "duration": 5e-3,
                  "damping": {"alpha": 10.0, "beta": 1e-5}, "gravity": [0.0, 0.0, -9810.0]},
     "analysis": {"method": "dynamic"}},
    {"pattern": dict(SHEET),
     "material": {"calibration": "auto", "E": 1000.0, "nu": 0.3, "thickness": 0.25,
                  "density": 1.38e-9},
     "support": [{"nodes": [0, 3], "fix": "xyz"}],
     "load": [{"node": 5, "force": [0.0, 0.0, 0.001], "time": [[0.0, 0.0], [1e-5, 1.0]]}],
     "dynamics": {"scheme": "explicit", "time_step": 1e-7, "duration": 1e-5,
                  "record_every": 10},
     "analysis": {"method": "dynamic", "stop": {"node": 5, "axis": "z", "beyond": 1.0}}},
    # A sheet lifted above a floor and pushed onto it.
    {"pattern": {"vertices": [[x, y, 1.0] for x, y, _ in SHEET["vertices"]],
                 "panels": SHEET["panels"]},
     "material": {"calibration": "auto", "E": 1000.0, "nu": 0.3, "thickness": 0.25},
     "support": [{"nodes": [0, 3], "fix": "xyz"}, {"node": 1, "fix": "z"}],
     "load": [{"nodes": [2, 5], "displacement": [0.0, 0.0, -1.5]}],
     "contact": {"distance": 0.2, "stiffness": "auto",
                 "planes": [{"point": [0, 0, 0], "normal": [0, 0, 1]}]},
     "analysis": {"method": "displacement_control", "steps": 3}},
    # A new user's fold: no material, no supports, no steps (a preset, a 3-2-1 hold, 40);
    # half of every target, and the end state written as STL and OBJ.
    {"pattern": dict(SHEET),
     "actuation": [{"edges": [[1, 4]], "fold_angle_deg": 60.0}],
     "analysis": {"method": "fold", "fold_percent": 50.0},
     "output": {"formats": ["stl", "obj"]}},
    # Two panels folded shut onto each other, kept apart by panel-panel contact.
    {"pattern": dict(SHEET, split="N4B5"),
     "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0,
                  "fold_stiffness": 0.1, "bend_stiffness": 1.0},
     "support": [{"nodes": [0, 1, 3], "fix": "xyz"}],
     "actuation": [{"edges": [[1, 4]], "fold_angle_deg": 178.0}],
     "contact": {"distance": 0.1, "stiffness": "auto", "self": True},
     "analysis": {"method": "fold", "steps": 3}},
    # A fold, its modes, then shaken: stages from where the one before ended.
    {"pattern": dict(SHEET),
     "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0,
                  "fold_stiffness": 0.05},
     "support": [{"nodes": [0, 1, 3], "fix": "xyz"}],
     "mass": [{"nodes": [2, 4, 5], "mass": 1e-6}],
     "stage": [{"name": "fold", "method": "fold", "steps": 3,
                "actuation": [{"edges": [[1, 4]], "fold_angle_deg": 45.0}]},
               {"name": "modes", "method": "modes", "modes": 2},
               {"method": "dynamic", "dynamics": {"time_step": 1e-4, "duration": 5e-4},
                "load": [{"node": 5, "force": [0.0, 0.0, 1e-4],
                          "time": {"harmonic": [1.0, 50.0]}}]}]},
    # The history differentiated by a material key, a column and the shape.
    {"pattern": dict(SHEET, centre="mean"),
     "material": {"calibration": "auto", "E": 1000.0, "nu": 0.3, "thickness": 0.25},
     "support": [{"nodes": [0, 3], "fix": "xyz"}, {"node": 1, "fix": "z"}],
     "load": [{"node": 5, "displacement": [0.0, 0.0, 1.0]}],
     "sensitivity": {"parameters": ["E", "hinges.stiffness", "vertices"]},
     "analysis": {"method": "displacement_control", "steps": 2}},
]
KEYS = ["pattern", "material", "laws", "support", "load", "analysis", "vertices", "panels",
        "split", "file", "planarity_tolerance", "calibration", "E", "nu", "thickness",
        "length_scale", "bar_modulus", "bar_area", "fold_stiffness", "bend_stiffness",
        "merlin2_compat", "bar", "fold", "bend", "fold_limits_deg", "valley", "mountain",
        "node", "nodes", "fix", "force", "displacement", "method", "steps", "tolerance",
        "max_iterations", "initial_load_factor", "max_increments", "max_load_factor", "stop",
        "axis", "beyond", "law", "limits_deg", "stiffness", "output", "every", "curve", "x",
        "y", "spring", "anchor", "actuation", "edges", "family", "fold_angle_deg", "stage",
        "predictor", "density", "mass", "modes", "about", "contact", "distance", "planes",
        "point", "normal", "self", "unit", "scale", "frame", "assignments", "dynamics",
        "scheme", "time_step", "duration", "damping", "gravity", "hht_alpha", "record_every",
        "time", "ramp_time", "alpha", "beta", "damping_tangent", "load_factor", "tangent", "preset", "fold_percent",
        "snap_tolerance", "formats", "sensitivity", "parameters", "stage", "name", "relax",
        "snap", "unknown_key"]
values = st.one_of(junk, edgy_floats, st.integers(-3, 8), st.sampled_from([100_001, 10**6]),
                   st.sampled_from(
    ["xyz", "z", "w", "N5B8", "N4B5", "auto", "manual", "linear", "mgdcm", "force_control",
     "displacement_control", [0.0, 0.0, 1.0], [1e308, 0, 0], [0, 0, float("nan")], [0, 99],
     [[0, 1, 2]], [-1], {"node": 0, "fix": "xyz"}, [{"node": 7, "fix": "x"}], "u_2_z",
     "reaction_5_z", "energy_total", {"x": "step", "y": "load_factor"}, {"x": "u_9_q"},
     "fold", "file", "valley", "join", [[1, 4]], [[1, 1]], [[0, 99]], [1e300, 0, 0],
     [{"family": "fold", "fold_angle_deg": 180.0}], [{"node": 2, "stiffness": -1.0}],
     "modes", "rest", [{"point": [0, 0, 0], "normal": [0, 0, 0]}], [{"point": [0, 0, 5]}],
     [{"nodes": [2], "mass": -1.0}], {"distance": 0.2, "planes": []}, "cm", "unit", "in",
     "origami_simulator", ["stl"], ["obj", "obj"], ["ply"], 0.0, 100.0, 150.0, "dynamic", "newmark", "hht", "explicit", "step", "ramp",
     [[0.0, 0.0], [1e-3, 1.0]], [[1e-3, 0.0], [0.0, 1.0]], [[0.0]], {"harmonic": [1.0, 50.0]},
     {"harmonic": [1.0, 0.0]}, {"harmonic": [1e300, 1e300]}, {"chirp": [1.0, 5.0, 50.0, 1e-3]},
     {"chirp": [1.0, 0.0, 5.0, 1.0]}, "current", "initial", {"alpha": 5.0}, {"beta": -1.0},
     {"gamma": 1.0}, [0.0, 0.0, -9810.0], 1e-9, 1e-4, -0.05, -0.5,
     {"load_factor": 1.0, "steps": 2}, {"load_factor": 1e300},
     {"distance": 0.2, "self": True}, {"distance": 5.0, "self": True}, True, "exact",
     "projected", "adaptive", {"distance": 0.1, "self": True, "tangent": "exact"},
     {"distance": 0.1, "self": True, "tangent": "adaptive"},
     {"distance": 0.1, "self": True, "thickness": 0.3}, ["E"], ["thickness"],
     ["vertices", "vertices"], ["bars.modulus[999]"], ["springs.anchor"], [""],
     {"parameters": ["fold_stiffness"]}, "stage 2", "", [{"method": "modes"}],
     [{"method": "force_control", "steps": 1, "load": [{"node": 2, "force": [0, 0, 1e-3]}]},
      {"method": "force_control", "steps": 1, "load": [{"node": 2, "force": [0, 0, 1e-3]}]}],
     [{"name": "a", "method": "fold"}, {"name": "a", "method": "fold"}]]))


def mutate(problem, edits):
    """Apply (path, key, value, delete) edits to a deep copy of ``problem``."""
    problem = copy.deepcopy(problem)
    for depth, key, value, delete in edits:
        table = problem
        for _ in range(depth):  # walk into a nested table or a list's entry
            inner = [v for v in (table.values() if isinstance(table, dict) else table)
                     if isinstance(v, (dict, list))]
            if not inner:
                break
            # crc32, not hash(): str hashes change from process to process, and the
            # derandomized suite must walk the same tables on every run.
            table = inner[zlib.crc32(key.encode()) % len(inner)]
            if isinstance(table, list) and table and isinstance(table[0], dict):
                table = table[0]
        if not isinstance(table, dict):
            continue
        if delete:
            table.pop(key, None)
        else:
            table[key] = value
    return problem


def named_key(error: ValueError) -> None:
    message = str(error)
    assert message.strip()
    # Every message starts with its source ("problem" or the file) and names the table and
    # key ([analysis] key 'steps') or the entry (load[0]).
    assert message.startswith("problem") or "fuzzed.toml" in message.split(":")[0], message
    assert "[" in message or "key" in message or "not valid TOML" in message, message


def run(problem):
    try:
        simulation = simulate(problem)
    except ValueError as error:
        named_key(error)
        event("ValueError")
        return
    event("completed" if simulation.completed else "stopped")
    if hasattr(simulation, "runs"):   # stages: each run as a run of its own, the files of all
        for _, stage in simulation.runs:
            if hasattr(stage, "path"):
                path_ok(stage.path)
        with tempfile.TemporaryDirectory() as folder:
            assert simulation.write(folder, view=False)["history"].is_file()
        return
    if not hasattr(simulation, "path"):  # a modes run: frequencies and shapes, no path
        finite(simulation.modes.frequencies_hz, simulation.modes.shapes, simulation.masses)
        with tempfile.TemporaryDirectory() as folder:
            simulation.write(folder)
        return
    path_ok(simulation.path)
    finite(simulation.model.nodes)
    if hasattr(simulation, "history"):   # a motion in time: its velocities and energies
        h = simulation.history
        finite(h.velocity, h.kinetic, h.strain, h.dissipated, h.work)
    for values in simulation.history_columns().values():
        finite(values)
    if simulation.path.num_steps:   # every output, the view too, of what the path holds
        with tempfile.TemporaryDirectory() as folder:
            try:
                written = simulation.write(folder)
            except ValueError as error:  # [sensitivity] names a parameter the model lacks
                named_key(error)
                return
            assert written["view"].stat().st_size > 0


@fuzz(150)
@given(st.sampled_from(range(len(BASES))),
       st.lists(st.tuples(st.integers(0, 3), st.sampled_from(KEYS), values, st.booleans()),
                min_size=1, max_size=3))
def test_load_problem_from_dicts(base, edits):
    problem = mutate(BASES[base], edits)
    try:
        loaded = load_problem(problem)
    except ValueError as error:
        named_key(error)
        return
    problems = ([stage for _, stage in loaded.stages] if hasattr(loaded, "stages")
                else [loaded])
    for one in problems:
        assert one.analysis.method in ("displacement_control", "force_control", "mgdcm", "fold",
                                       "modes", "dynamic")


@fuzz(40)
@given(st.sampled_from(range(len(BASES))),
       st.lists(st.tuples(st.integers(1, 3), st.sampled_from(KEYS), values, st.booleans()),
                max_size=2))
def test_simulate(base, edits):
    run(mutate(BASES[base], edits))


def toml(problem) -> str:
    """The problem as TOML text (the subset these problems use)."""
    def value(v):
        if isinstance(v, bool):
            return "true" if v else "false"
        if isinstance(v, str):
            return '"' + v + '"'
        if isinstance(v, float) and not math.isfinite(v):
            return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf")
        if isinstance(v, (list, tuple)):
            return "[" + ", ".join(value(x) for x in v) + "]"
        if isinstance(v, dict):
            return "{" + ", ".join(f"{k} = {value(x)}" for k, x in v.items()) + "}"
        return repr(v)

    lines = []
    for name, table in problem.items():
        entries = table if isinstance(table, list) else [table]
        for entry in entries:
            lines.append(f"[[{name}]]" if isinstance(table, list) else f"[{name}]")
            lines += [f"{k} = {value(v)}" for k, v in entry.items()]
    return "\n".join(lines) + "\n"


#: The bases with [contact]: the sheet pushed onto a floor, the panels folded shut.
CONTACT_BASES = [k for k, base in enumerate(BASES) if "contact" in base]


@fuzz(30)
@given(st.sampled_from(CONTACT_BASES),
       mostly(st.floats(0.0, 1.5), edgy_floats, junk),
       st.sampled_from([0.05, 0.1, 0.2]), st.booleans())
def test_contact_thickness(base, thickness, distance, floor):
    """[contact] thickness of any value, on the floor and on the panels folded shut (their
    triangles 0.71 mm apart at rest, a floor 1 or 2 mm below the sheet): a named refusal, or a
    path whose faces stay apart: min_gap, the gap beyond the thickness, above 0 throughout."""
    problem = copy.deepcopy(BASES[base])
    problem["contact"]["thickness"] = thickness
    problem["contact"]["distance"] = distance
    if floor:
        problem["contact"]["planes"] = [{"point": [0, 0, -1.0], "normal": [0, 0, 1]}]
    try:
        simulation = simulate(problem)
    except ValueError as error:
        named_key(error)
        assert "thickness" in str(error) or "distance" in str(error), str(error)
        event("ValueError")
        return
    event("completed" if simulation.completed else "stopped")
    path_ok(simulation.path)
    gaps = simulation.history_columns()["min_gap"]
    finite(gaps)
    assert (gaps > 0).all(), gaps


@fuzz(100)
@given(st.sampled_from(range(len(BASES))),
       st.lists(st.tuples(st.integers(0, 10**6), st.integers(1, 30)), max_size=2),
       st.lists(st.tuples(st.integers(0, 10**6), st.sampled_from(
           ["", "=", "[", "]", "\n", "\"", "x = 1\n", "[analysis]\n", "1e999", "nan", "-",
            "steps = 99999999999999999999\n", "\x00", "nodes = [0, 99]\n",
            "x = " + "[" * 600 + "\n", "y = " + "{a = " * 80 + "1" + "}" * 80 + "\n",
            "fold_stiffness = 1e300\n", "fold_stiffness = -1\n", "bar_area = 5e-324\n",
            "panels = 5\n", "panels = [[0, 1, true]]\n", "vertices = [[1e300, 0, 0]]\n",
            "\ufffd", "\\u00"])), max_size=3))
def test_load_problem_from_toml(base, cuts, insertions):
    text = toml(BASES[base])
    for position, length in cuts:
        position %= max(len(text), 1)
        text = text[:position] + text[position + length:]
    for position, word in insertions:
        position %= len(text) + 1
        text = text[:position] + word + text[position:]
    with tempfile.TemporaryDirectory() as directory:
        path = Path(directory) / "fuzzed.toml"
        path.write_text(text, encoding="utf-8")
        try:
            problem = load_problem(path)
        except ValueError as error:
            named_key(error)
            return
        except OSError:
            return
    assert problem.source.endswith("fuzzed.toml")


#: Bytes a garbled or binary file holds: not UTF-8, NUL, a BOM, deep nests.
BYTES = [b"\xff", b"\xc3(", b"\x00", b"\xef\xbb\xbf", b"[" * 700, b"{a=" * 400, b"\r\n"]


@fuzz(60)
@given(st.sampled_from(range(len(BASES))),
       st.lists(st.tuples(st.integers(0, 10**6), st.sampled_from(BYTES)), min_size=1,
                max_size=3))
def test_load_problem_from_bytes(base, insertions):
    data = toml(BASES[base]).encode()
    for position, word in insertions:
        position %= len(data) + 1
        data = data[:position] + word + data[position:]
    with tempfile.TemporaryDirectory() as directory:
        path = Path(directory) / "fuzzed.toml"
        path.write_bytes(data)
        try:
            load_problem(path)
        except ValueError as error:
            named_key(error)


@fuzz(15)
@given(st.integers(5, 400), st.sampled_from(["merlin2", "mean"]),
       st.sampled_from(["auto", "manual"]), st.floats(0.0, 0.3))
def test_large_polygon_panels(corners, centre, calibration, warp):
    """One polygon of up to 400 corners (the N5B8 centre's rule grows with the square of
    the corners' count), flat or warped a little: a model in seconds, or a named refusal."""
    angles = np.linspace(0.0, 2 * np.pi, corners, endpoint=False)
    vertices = [[50 * math.cos(a), 50 * math.sin(a), warp * math.sin(3 * a)] for a in angles]
    problem = {"pattern": {"vertices": vertices, "panels": [list(range(corners))],
                           "centre": centre, "planarity_tolerance": 0.5},
               "material": ({"calibration": "auto", "E": 1e3, "nu": 0.3, "thickness": 0.25}
                            if calibration == "auto" else
                            {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0,
                             "bend_stiffness": 1.0}),
               "support": [{"node": 0, "fix": "xyz"}, {"node": 1, "fix": "yz"},
                           {"node": 2, "fix": "z"}],
               "load": [{"node": corners // 2, "force": [0.0, 0.0, 0.01]}],
               "analysis": {"method": "force_control", "steps": 1}}
    try:
        pm = build_problem_model(problem)
    except ValueError as error:
        named_key(error)
        return
    finite(pm.model.nodes)
