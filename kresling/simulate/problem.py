"""A simulation problem stated in a TOML file (or a dict of the same shape).

The file names a crease pattern (FOLD, OBJ or SVG), how to build its model, its supports and
loads, and the analysis; :func:`load_problem` reads and checks it. Every node index is
0-based in the pattern file's vertex order; N5B8 centre nodes follow the vertices, in panel
order. Bad input raises a ``ValueError`` naming the file, the table and key (with the line
when it can be found) and what is allowed. See docs/simulate.md for every key.

>>> problem = load_problem({
...     "pattern": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "panels": [[0, 1, 2]]},
...     "material": {"calibration": "manual", "bar_modulus": 1e3, "bar_area": 1.0},
...     "support": [{"node": 0, "fix": "xyz"}, {"node": 1, "fix": "yz"}, {"node": 2, "fix": "z"}],
...     "load": [{"node": 2, "force": [0.0, 1.0, 0.0]}],
...     "analysis": {"method": "force_control", "steps": 4}})
>>> problem.analysis.method, problem.loads[0].kind
('force_control', 'force')
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from kresling import _core
from kresling._validation import show
from kresling.io import UNITS, mm_per_unit, pattern_from_arrays, read_pattern, separate_cuts
from kresling.io.cuts import check_duplicate_vertices
from kresling.model import CreaseLaws, HingeLaw, ManualProperties, SheetMaterial
from kresling.model.material_presets import MATERIAL_PRESETS, PRESET_LIMITS_DEG, preset_material
from kresling.model.pattern_model import CONVENTIONS, FOLD_FAMILIES
from kresling.model.panel_elements import CENTRES, SPLITS, build_panel_elements
from kresling.laws import BAR_LAWS, SPRING_LAWS
from kresling.simulate.output_table import Output, read_output
from kresling.simulate.problem_actuation import read_actuations, read_springs
from kresling.simulate.problem_contact import read_contact
from kresling.simulate.problem_dynamics import read_dynamics, read_load_time
from kresling.simulate.problem_modes import read_about
from kresling.simulate.problem_file import read_toml
from kresling.simulate.problem_mass import SheetMass, read_masses, read_sheet_mass
from kresling.simulate.rigid_hold import rigid_body_hold

__all__ = ["Problem", "Support", "Load", "MonitorStop", "Analysis", "load_problem", "METHODS"]

#: MGDCM's defaults, as the core declares them.
_MGDCM = _core.solvers.MgdcmOptions()
#: Analysis methods and what each needs.
METHODS = ("displacement_control", "force_control", "mgdcm", "fold", "modes", "dynamic")
#: The named states vibration modes (``method = "modes"``) are computed about (besides a
#: loaded one, an ``[analysis.about]`` table).
ABOUT = ("rest",)
#: How displacement control and folding step between their samples.
INCREMENTS = ("fixed", "adaptive")
#: Displacement control with fixed increments: each Newton solve's start, by the order of its
#: extrapolation along the path (the previous equilibrium, then through 2, 3 or 4 of them).
PREDICTORS = ("previous", "linear", "quadratic", "cubic")
_AXES = {"x": 0, "y": 1, "z": 2}
#: Newton's default tolerance on the correction's 2-norm, as a fraction of the model's size
#: (the diagonal of the pattern's bounding box, in mm): 1e-6 mm on a 100 mm pattern, the
#: same number of digits at any scale. An explicit ``tolerance`` [mm] replaces it.
RELATIVE_TOLERANCE = 1e-8
#: MERLIN2's own Newton tolerance [mm], the default under merlin2_compat.
MERLIN2_TOLERANCE = 1e-6
#: ``method = "fold"``: increments per stage when the problem gives no ``steps``.
FOLD_STEPS = 40
#: ``method = "fold"``: each increment's start when the problem gives no ``predictor`` (and
#: no ``[contact]``: then the previous equilibrium).
FOLD_PREDICTOR = "quadratic"
#: ``method = "fold"``: Newton gives an increment up (and halves it) when its correction
#: at this iteration or later is still above 1e-3 of its first (no ``max_iterations`` of
#: wandering where the path turns sharply; docs/folding.md, 'Large patterns'). Not with
#: ``[contact]``, whose barriers shorten Newton's steps near touching panels and so slow
#: it down without its wandering.
FOLD_GIVE_UP_AFTER = 12
#: The hinges' enhanced linear limits [deg] when ``[laws]`` gives none (with a preset
#: material, the preset's).
LAW_LIMITS_DEG = (45.0, 315.0)
#: ``method = "fold"``: the material when the problem gives no ``[material]``.
DEFAULT_FOLD_PRESET = "origami_simulator"


@dataclass(frozen=True)
class Support:
    """Supported axes of a node (u = 0 there)."""

    node: int
    axes: str


@dataclass(frozen=True)
class Load:
    """A force [N] or a prescribed displacement [mm] on each of ``nodes``; ``time`` (a
    :class:`~kresling.simulate.problem_dynamics.LoadTime`, ``method = "dynamic"`` only) its
    factor in time, None when the entry names none."""

    nodes: tuple
    kind: str  # "force" | "displacement"
    vector: tuple
    time: object = None


@dataclass(frozen=True)
class MonitorStop:
    """Stop once ``|u|`` of ``node`` along ``axis`` exceeds ``beyond`` [mm]."""

    node: int
    axis: str
    beyond: float

    @property
    def dof(self) -> int:
        return 3 * self.node + _AXES[self.axis]


@dataclass(frozen=True)
class Analysis:
    """The path-following analysis and its settings (see :func:`kresling.simulate`)."""

    method: str
    steps: int | None = None
    initial_load_factor: float = _MGDCM.initial_load_factor
    max_increments: int = 100
    max_load_factor: float = math.inf
    stop: MonitorStop | None = None
    tolerance: float = 1e-6
    max_iterations: int = 50
    #: Displacement control and fold: "fixed" (equal increments, MERLIN2's step control
    #: under merlin2_compat) or "adaptive" (the same samples, increments by an error
    #: estimate).
    increments: str = "fixed"
    #: Displacement control with fixed increments: each increment's Newton start, one of
    #: PREDICTORS ("previous": the last equilibrium, as MERLIN2; the others extrapolate the
    #: path through the last equilibria; a start other than "previous" uses bisection, not
    #: MERLIN2's step control, under merlin2_compat).
    predictor: str = "previous"
    #: ``method = "fold"``: where the fold's equilibrium path ends, snap to a stable state
    #: and fold on (:func:`kresling.solvers.solve_fold`'s ``snap``).
    snap: bool = False
    #: ``method = "fold"``: fold through stable states only, relaxing an increment whose
    #: equilibrium is unstable or not found (:func:`kresling.solvers.solve_fold`'s
    #: ``relax``); None: the default, on with Origami Simulator's material (a preset), off
    #: with a material of the problem's own (:meth:`Problem.relaxes`).
    relax: bool | None = None
    #: ``method = "fold"``: every target fold angle is scaled by fold_percent / 100.
    fold_percent: float = 100.0
    #: ``method = "modes"``: how many of the lowest modes, about which state: "rest" or a
    #: :class:`~kresling.simulate.problem_modes.LoadedState`.
    modes: int = 10
    about: object = "rest"


@dataclass(frozen=True)
class Problem:
    """A checked problem: pattern, model settings, supports, loads and analysis.

    Attributes
    ----------
    pattern : kresling.io.Pattern
    split : str
        "N5B8" or "N4B5".
    material : SheetMaterial or ManualProperties
    merlin2_compat : bool
        Build and drive the model exactly as MERLIN2 v1.1 would.
    laws : CreaseLaws
    supports, loads : tuple
    analysis : Analysis
    source : str
        Where the problem came from (the file, or "problem" for a dict).
    centre : str
        N5B8 centre nodes: "merlin2" (its rules) or "mean" (of the corners).
    assignments : str
        The convention of the pattern's edge assignments: "fold" or "origami_simulator".
    """

    pattern: object
    split: str
    material: object
    merlin2_compat: bool
    laws: CreaseLaws
    supports: tuple
    loads: tuple
    analysis: Analysis
    source: str = "problem"
    centre: str = "merlin2"
    #: The [output] table: increments kept in the files, the view's curve.
    output: Output = Output()
    #: Crease actuation (``[[actuation]]``, with ``method = "fold"``): Actuation entries.
    actuations: tuple = ()
    #: Zero-length springs to fixed points (``[[spring]]``): Spring entries.
    springs: tuple = ()
    #: How FOLD assignments become hinges: "fold" (the spec) or "origami_simulator".
    assignments: str = "fold"
    #: ``[material] density`` and the sheet's thickness (the sheet's mass).
    sheet_mass: SheetMass = SheetMass()
    #: Explicit node masses (``[[mass]]``): NodeMass entries.
    masses: tuple = ()
    #: Rigid planes the nodes are kept off (``[contact]``), or None.
    contact: object = None
    #: ``[dynamics]`` (``method = "dynamic"``): a Dynamics, or None.
    dynamics: object = None
    #: The named material (``[material] preset``, or a fold's default), or None.
    preset: str | None = None
    #: The supports chosen to hold a fold's free sheet (no ``[[support]]`` given): the
    #: rigid-body motions only (:func:`~kresling.simulate.rigid_hold.rigid_body_hold`).
    held: tuple = ()
    #: The model's node count the problem was checked against (:func:`node_count`), so
    #: that building the model does not split the panels once more to find it.
    num_nodes: int | None = None

    def relaxes(self) -> bool:
        """Whether a fold relaxes the increments its path cannot follow stably
        (``[analysis] relax``): by default with Origami Simulator's material, whose sheet is
        meant to come to rest as Origami Simulator's relaxation brings it."""
        if self.analysis.relax is not None:
            return self.analysis.relax
        return self.preset is not None


class _Table:
    """One TOML table being read: typed getters, and unknown keys reported at the end."""

    def __init__(self, data, name, source, text=None, occurrence=0):
        self.name, self.source, self.text, self.occurrence = name, source, text, occurrence
        if not isinstance(data, dict):
            self.fail(None, f"must be a table, got {type(data).__name__}")
        self.data, self.used = data, set()

    def where(self, key):
        label = f"[{self.name}]" if key is None else f"[{self.name}] key {key!r}"
        line = _line_of(self.text, self.name, key, self.occurrence) if self.text else None
        return f"{self.source}:{line}: {label}" if line else f"{self.source}: {label}"

    def fail(self, key, message):
        raise ValueError(f"{self.where(key)} {message}")

    def has(self, key):
        return key in self.data

    def get(self, key, kind, default=None, *, required=False, allowed=None, choices=None):
        """The value of ``key`` read by ``kind``; ``allowed`` words what a missing required
        key must be, ``choices`` the values a string may take."""
        self.used.add(key)
        if key not in self.data:
            if required:
                wanted = allowed or (f"one of {list(choices)}" if choices else None)
                self.fail(key, "is missing" + (f": must be {wanted}" if wanted else ""))
            return default
        return kind(self, key, self.data[key], choices)

    def finish(self):
        unknown = sorted(set(self.data) - self.used)
        if unknown:
            self.fail(unknown[0], f"is unknown: allowed keys are {sorted(self.used)}")


def _line_of(text, table, key, occurrence=0):
    """The line of ``key`` in the ``occurrence``-th ``[table]`` (or ``[[table]]``) of the
    TOML text (best effort: keys of inline tables are not found), or None."""
    lines = text.splitlines()
    inside = table == ""
    seen = -1
    for number, line in enumerate(lines, 1):
        stripped = line.strip()
        match = re.match(r"^\[\[?\s*([^\]]+?)\s*\]\]?", stripped)
        if match:
            if match.group(1) == table:
                seen += 1
            inside = match.group(1) == table and seen == occurrence
            if inside and key is None:
                return number
            continue
        if inside and key is not None and re.match(rf"^{re.escape(key)}\s*=", stripped):
            return number
    return None


# -- typed readers: (table, key, value, allowed) -> value ---------------------------------
def _number(t, key, value, allowed=None):
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        t.fail(key, f"= {value!r} is invalid: must be a finite number")
    return float(value)


def _positive(t, key, value, allowed=None):
    value = _number(t, key, value)
    if value <= 0:
        t.fail(key, f"= {value!r} is invalid: must be > 0")
    return value


#: Magnitudes a physical quantity of a problem (a modulus, a length, an area, a stiffness,
#: a force) may have: far beyond any sheet in mm, N and N/mm^2, and far enough inside the
#: floating-point range (1e-308 to 1e308) that the model's products of a few of them
#: (stiffness times length squared, ...) neither overflow nor vanish.
QUANTITY_RANGE = (1e-30, 1e30)


def _in_range(t, key, value, *, zero=False):
    low, high = QUANTITY_RANGE
    if not (low <= abs(value) <= high or (zero and value == 0)):
        t.fail(key, f"= {value!r} is out of range: its magnitude must be in [{low:g}, {high:g}]"
                    + (" (or 0)" if zero else ""))
    return value


def _quantity(t, key, value, allowed=None):
    """A positive physical quantity, within QUANTITY_RANGE."""
    return _in_range(t, key, _positive(t, key, value))


def _quantities(t, key, value, allowed=None, *, zero=False):
    """A number or an array of them (one per element): each > 0 (>= 0 with ``zero``),
    within QUANTITY_RANGE."""
    numbers = value if isinstance(value, list) else [value]
    checked = []
    for number in numbers:
        number = _number(t, key, number)
        if number < 0 or (number == 0 and not zero):
            where = f"has an entry {number!r} that" if isinstance(value, list) else f"= {number!r}"
            t.fail(key, f"{where} is invalid: must be {'>= 0' if zero else '> 0'}")
        checked.append(_in_range(t, key, number, zero=zero))
    return np.array(checked, dtype=float) if isinstance(value, list) else checked[0]


def _stiffnesses(t, key, value, allowed=None):
    return _quantities(t, key, value, zero=True)


def _integer(t, key, value, allowed=None):
    if isinstance(value, bool) or not isinstance(value, int):
        t.fail(key, f"= {value!r} is invalid: must be an integer")
    return value


def _count(t, key, value, allowed=None):
    """An increment or iteration count, in the solvers' documented range (their limits)."""
    value = _integer(t, key, value)
    largest = (_core.solvers.MAX_ITERATIONS if key == "max_iterations"
               else _core.solvers.MAX_STEPS)
    if not 1 <= value <= largest:
        t.fail(key, f"= {value!r} is invalid: must be an integer in [1, {largest}]")
    return value


def _boolean(t, key, value, allowed=None):
    if not isinstance(value, bool):
        t.fail(key, f"= {value!r} is invalid: must be true or false")
    return value


def _string(t, key, value, allowed=None):
    if not isinstance(value, str) or (allowed and value not in allowed):
        t.fail(key, f"= {value!r} is invalid: must be one of {list(allowed)}" if allowed
               else f"= {value!r} is invalid: must be a string")
    return value


def _vector3(t, key, value, allowed=None):
    if not isinstance(value, list) or len(value) != 3:
        t.fail(key, f"= {value!r} is invalid: must be 3 numbers [x, y, z]")
    return tuple(_in_range(t, key, _number(t, key, v), zero=True) for v in value)


def _array_of_tables(t, key, value, allowed=None):
    if not isinstance(value, list):
        t.fail(key, f"= {value!r} is invalid: must be an array of tables ([[{key}]] entries)")
    return value


def _limits(t, key, value, allowed=None):
    if not isinstance(value, list) or len(value) != 2:
        t.fail(key, f"= {value!r} is invalid: must be two angles [theta1, theta2] in degrees")
    low, high = (_number(t, key, v) for v in value)
    if not 0 < low < high < 360:
        t.fail(key, f"= {value!r} is invalid: must satisfy 0 < theta1 < theta2 < 360 [deg]")
    return (low, high)


def _panels(t, key, value, allowed=None):
    """Inline panels: a non-empty array of arrays of integers (their ranges are the
    pattern's to check)."""
    if not isinstance(value, list) or not value:
        t.fail(key, f"= {show(value)} is invalid: must be a non-empty array of panels, each "
                    "an array of vertex indices")
    for index, panel in enumerate(value):
        if not isinstance(panel, list) or not all(
                isinstance(v, int) and not isinstance(v, bool) for v in panel):
            t.fail(key, f"[{index}] = {show(panel)} is invalid: must be an array of vertex "
                        "indices (integers)")
    return value


def _node_list(t, count):
    """``node = k`` or ``nodes = [k, ...]``: checked against the model's node count."""
    if t.has("node") == t.has("nodes"):
        t.fail(None, "needs exactly one of 'node' (an index) or 'nodes' (a list of indices)")
    if t.has("node"):
        nodes = [t.get("node", _integer)]
        key = "node"
    else:
        value = t.get("nodes", lambda t_, k, v, a: v)
        if not isinstance(value, list) or not value:
            t.fail("nodes", f"= {value!r} is invalid: must be a non-empty list of node indices")
        nodes = [_integer(t, "nodes", v) for v in value]
        key = "nodes"
    for node in nodes:
        if not 0 <= node < count:
            t.fail(key, f"= {node} is out of range: nodes are numbered 0 to {count - 1} "
                        "(pattern vertices, then N5B8 centre nodes)")
    return tuple(nodes)


# -- sections -------------------------------------------------------------------------------
def _read_pattern(t, base, compat):
    split = t.get("split", _string, "N5B8", choices=tuple(SPLITS))
    centre = t.get("centre", _string, "merlin2", choices=tuple(CENTRES))
    tolerance = t.get("planarity_tolerance", _positive, 1e-3)
    unit = t.get("unit", _string, None, choices=tuple(UNITS))
    scale = t.get("scale", _positive, None)
    if scale is not None and unit != "unit":
        t.fail("scale", f"= {scale!r} applies only with unit = \"unit\" (mm per unit of a "
                        "pattern without a physical unit)")
    frame = t.get("frame", _integer, 0)
    snap = t.get("snap_tolerance", _positive, None)
    convention = "fold"
    if snap is not None and not (t.has("file") and str(t.data["file"]).lower().endswith(".svg")):
        t.fail("snap_tolerance", f"= {snap!r} applies only to an SVG drawing's file (its "
                                 "strokes are merged into vertices within it)")
    if t.has("file"):
        name = t.get("file", _string)
        path = Path(name) if Path(name).is_absolute() else base / name
        if not path.is_file():
            t.fail("file", f"= {name!r}: no such file ({path})")
        if frame < 0:
            t.fail("frame", f"= {frame} is invalid: must be >= 0 (0 is the key frame)")
        if frame and path.suffix.lower() != ".fold":
            t.fail("frame", f"= {frame} applies only to FOLD files: {name!r} has no frames")
        convention = "origami_simulator" if path.suffix.lower() == ".svg" else "fold"
        pattern = read_pattern(path, planarity_tolerance=tolerance, unit=unit, scale=scale,
                               frame=frame, snap_tolerance=snap)
    elif t.has("vertices"):
        if t.has("frame"):
            t.fail("frame", "applies only to a pattern file (FOLD frames)")
        pattern = _inline_pattern(t, tolerance, unit, scale)
    else:
        t.fail(None, "needs 'file' (a .fold, .obj or .svg file) or 'vertices' and 'panels'")
    convention = t.get("assignments", _string, convention, choices=CONVENTIONS)
    t.finish()
    return separate_cuts(pattern), split, centre, convention


def _inline_pattern(t, tolerance, unit, scale):
    vertices = t.get("vertices", lambda t_, k, v, a: v)
    panels = t.get("panels", _panels, required=True,
                   allowed="a list of panels (lists of vertex indices)")
    factor = mm_per_unit(unit or "mm", scale)
    try:
        pattern = pattern_from_arrays(np.asarray(vertices, dtype=float) * factor, panels,
                                      planarity_tolerance=tolerance)
        check_duplicate_vertices(pattern.vertices, pattern.faces, pattern.edges,
                                 pattern.edges_assignment, ValueError)
    except (TypeError, ValueError, OverflowError) as error:
        # The pattern calls the panels "faces": name the problem's key.
        t.fail("panels" if str(error).startswith("faces") else "vertices",
               f"does not describe a pattern: {error}")
    return pattern


def default_tolerance(pattern, compat: bool) -> float:
    """Newton's tolerance [mm] when the problem gives none: MERLIN2's 1e-6 mm under
    merlin2_compat, else :data:`RELATIVE_TOLERANCE` times the pattern's size (the
    diagonal of its bounding box [mm])."""
    if compat:
        return MERLIN2_TOLERANCE
    size = float(np.linalg.norm(np.ptp(pattern.vertices, axis=0)))
    return RELATIVE_TOLERANCE * size if size > 0 else MERLIN2_TOLERANCE


def _read_material(t):
    if t.has("preset"):
        # Named: resolved once the pattern is read (the corner springs scale with its size).
        name = t.get("preset", _string, choices=tuple(MATERIAL_PRESETS))
        for key in ("calibration", "merlin2_compat"):
            if t.has(key):
                t.fail(key, f"does not go with preset = {name!r} (the preset is a manual "
                            "calibration of its own)")
        sheet_mass = read_sheet_mass(t, None, _quantity)
        t.finish()
        return name, False, sheet_mass
    calibration = t.get("calibration", _string, required=True, choices=("auto", "manual"))
    compat = t.get("merlin2_compat", _boolean, False)
    if calibration == "auto":
        E = t.get("E", _quantity, required=True, allowed="Young's modulus [N/mm^2]")
        nu = t.get("nu", _number, required=True, allowed="Poisson's ratio in (-1, 0.5]")
        if not -1 < nu <= 0.5:
            t.fail("nu", f"= {nu!r} is invalid: must be in (-1, 0.5]")
        thickness = t.get("thickness", _quantity, required=True, allowed="the thickness [mm]")
        length_scale = t.get("length_scale", _quantity, None)
        material = SheetMaterial(E, nu, thickness, length_scale)
    else:
        material = ManualProperties(
            bar_modulus=t.get("bar_modulus", _quantity, required=True,
                              allowed="the bars' modulus C0 [N/mm^2]"),
            bar_area=t.get("bar_area", _quantities, required=True,
                           allowed="the bars' area [mm^2] (a number or one per bar)"),
            fold_stiffness=t.get("fold_stiffness", _stiffnesses, None),
            bend_stiffness=t.get("bend_stiffness", _stiffnesses, None),
            face_stiffness=t.get("face_stiffness", _quantity, None))
    sheet_mass = read_sheet_mass(t, material, _quantity)
    t.finish()
    return material, compat, sheet_mass


def _read_laws(t, calibration_auto, limits=LAW_LIMITS_DEG):
    laws = sorted(SPRING_LAWS)
    bar = t.get("bar", _string, "ogden", choices=tuple(sorted(BAR_LAWS)))
    fold = HingeLaw(t.get("fold", _string, "enhanced_linear", choices=laws),
                    t.get("fold_limits_deg", _limits, limits),
                    t.get("fold_stiffness", _quantity, None))
    bend_default = "super_linear_bend" if calibration_auto else "enhanced_linear"
    bend = HingeLaw(t.get("bend", _string, bend_default, choices=laws),
                    t.get("bend_limits_deg", _limits, limits),
                    t.get("bend_stiffness", _quantity, None))
    families = {}
    for family in FOLD_FAMILIES:
        if not t.has(family):
            continue
        sub = _Table(t.get(family, lambda t_, k, v, a: v), f"{t.name}.{family}", t.source, t.text)
        families[family] = HingeLaw(sub.get("law", _string, fold.law, choices=laws),
                                    sub.get("limits_deg", _limits, fold.limits_deg),
                                    sub.get("stiffness", _quantity, fold.stiffness))
        sub.finish()
    t.finish()
    return CreaseLaws(bar=bar, fold=fold, bend=bend, families=families)


def _read_analysis(t, num_nodes):
    method = t.get("method", _string, required=True, choices=METHODS)
    settings = {"method": method,
                "tolerance": t.get("tolerance", _positive, None),
                "max_iterations": t.get("max_iterations", _count, 50)}
    if method in ("displacement_control", "force_control"):
        settings["steps"] = t.get("steps", _count, required=True,
                                  allowed="the number of increments (an integer >= 1)")
    elif method == "fold":
        settings["steps"] = t.get("steps", _count, FOLD_STEPS)
        percent = t.get("fold_percent", _number, 100.0)
        if not 0 < percent <= 100:
            t.fail("fold_percent", f"= {percent!r} is invalid: must be in (0, 100] (the "
                                   "percentage of every target fold angle folded to)")
        settings["fold_percent"] = percent
    if method in ("displacement_control", "fold"):
        settings["increments"] = t.get("increments", _string, "fixed",
                                       choices=INCREMENTS)
        if settings["increments"] == "adaptive" and t.has("predictor"):
            t.fail("predictor", "applies to fixed increments only: adaptive increments start "
                                "each Newton solve from their own cubic Hermite curves")
        # A fold starts each increment from its quadratic extrapolation: along a smooth
        # fold it halves the Newton iterations (the box-pleat pyramid: 5 instead of 10).
        settings["predictor"] = t.get("predictor", _string,
                                      FOLD_PREDICTOR if method == "fold" else "previous",
                                      choices=PREDICTORS)
        if method == "fold":
            settings["snap"] = t.get("snap", _boolean, False)
            settings["relax"] = t.get("relax", _boolean, None)
    elif method == "dynamic":
        pass  # the steps are [dynamics]'s
    elif method == "modes":
        settings["modes"] = t.get("modes", _count, 10)
        settings["about"] = read_about(
            t, lambda value: _Table(value, "analysis.about", t.source, t.text), _number, _count)
        t.finish()
        return Analysis(**settings)
    else:
        settings["initial_load_factor"] = t.get("initial_load_factor", _number,
                                                _MGDCM.initial_load_factor)
        if settings["initial_load_factor"] == 0:
            t.fail("initial_load_factor", "= 0 is invalid: must be non-zero (its sign sets "
                                          "the loading direction)")
        settings["max_increments"] = t.get("max_increments", _count, 100)
    if method not in ("displacement_control", "fold", "dynamic"):
        settings["max_load_factor"] = t.get("max_load_factor", _positive, math.inf)
    if t.has("stop"):
        sub = _Table(t.get("stop", lambda t_, k, v, a: v), "analysis.stop", t.source, t.text)
        node = _node_list(sub, num_nodes)
        if len(node) != 1:
            sub.fail("nodes", "must name one node")
        settings["stop"] = MonitorStop(node[0], sub.get("axis", _string, required=True,
                                                        choices=tuple(_AXES)),
                                       sub.get("beyond", _quantity, required=True,
                                               allowed="a displacement magnitude [mm]"))
        sub.finish()
    t.finish()
    return Analysis(**settings)


def _read_supports(entries, source, text, num_nodes):
    supports = []
    for i, entry in enumerate(entries):
        t = _Table(entry, "support", source, text, occurrence=i)
        fix = t.get("fix", _string, required=True, allowed="any of the letters x, y, z")
        if not fix or set(fix) - set(_AXES) or len(set(fix)) != len(fix):
            t.fail("fix", f"= {fix!r} is invalid: must be some of the letters x, y, z, each once")
        for node in _node_list(t, num_nodes):
            supports.append(Support(node, "".join(sorted(fix))))
        t.finish()
    return tuple(supports)


def _read_loads(entries, source, text, num_nodes):
    loads = []
    for i, entry in enumerate(entries):
        t = _Table(entry, "load", source, text, occurrence=i)
        if t.has("force") == t.has("displacement"):
            t.fail(None, f"(entry {i}) needs exactly one of 'force' [N] or 'displacement' [mm]")
        kind = "force" if t.has("force") else "displacement"
        vector = t.get(kind, _vector3)
        time = read_load_time(t, _number, _positive)
        loads.append(Load(_node_list(t, num_nodes), kind, vector, time))
        t.finish()
    return tuple(loads)


def node_count(pattern, split, centre="merlin2"):
    """Pattern vertices plus the centre nodes N5B8 adds (one per panel of 4+ vertices that
    is star-shaped from a centre; the others are cut along diagonals)."""
    if split != "N5B8" or all(len(face) == 3 for face in pattern.faces):
        return pattern.num_vertices
    try:
        return len(build_panel_elements(pattern.vertices, pattern.faces, split=split,
                                        centre=centre).nodes)
    except ValueError:  # a bad panel: building the model says which, naming the file
        return pattern.num_vertices + sum(1 for face in pattern.faces if len(face) > 3)


def _check_consistency(problem, t_analysis):
    method = problem.analysis.method
    kinds = {load.kind for load in problem.loads}
    if (method == "fold") != bool(problem.actuations):
        if method == "fold":
            raise ValueError(f"{problem.source}: [[actuation]] is missing: method = 'fold' "
                             "drives the creases it names")
        raise ValueError(f"{problem.source}: [[actuation]] drives creases only with "
                         f"[analysis] method = 'fold' (given: {method!r})")
    if (method == "dynamic") != (problem.dynamics is not None):
        if method == "dynamic":
            t_analysis.fail("method", "= 'dynamic' needs a [dynamics] table (scheme, time_step, "
                                      "duration)")
        raise ValueError(f"{problem.source}: [dynamics] applies only with [analysis] method = "
                         f"'dynamic' (given: {method!r})")
    timed = [i for i, load in enumerate(problem.loads) if load.time is not None]
    if timed and method != "dynamic":
        raise ValueError(f"{problem.source}: load[{timed[0]}] key 'time' applies only with "
                         f"[analysis] method = 'dynamic' (given: {method!r})")
    if method == "modes":
        _check_modes(problem, t_analysis)
        return
    if method == "dynamic":
        _check_dynamic(problem, t_analysis, kinds)
        return
    if method == "fold":
        if kinds - {"force"}:
            t_analysis.fail("method", "= 'fold' takes force loads only (they ramp with the "
                                      "first stage); a prescribed displacement is not one")
        stages = sorted({a.stage for a in problem.actuations})
        if stages != list(range(1, len(stages) + 1)):
            raise ValueError(f"{problem.source}: [[actuation]] stages are {stages}: must be "
                             "numbered 1, 2, ... without a gap")
        return
    if not problem.loads:
        raise ValueError(f"{problem.source}: [[load]] is missing: at least one load is needed")
    wanted = "displacement" if method == "displacement_control" else "force"
    if kinds != {wanted}:
        t_analysis.fail("method", f"= {method!r} needs every [[load]] to be a {wanted} "
                                  f"(given: {sorted(kinds)})")
    supported = {(s.node, a) for s in problem.supports for a in s.axes}
    for i, load in enumerate(problem.loads):
        if load.kind != "displacement":
            continue
        for node in load.nodes:
            for axis, value in zip("xyz", load.vector):
                if value != 0 and (node, axis) in supported:
                    raise ValueError(f"{problem.source}: load[{i}] drives node {node} along "
                                     f"{axis}, which a [[support]] fixes: a DOF is either "
                                     "supported or driven")


def _check_modes(problem, t_analysis):
    kinds = {load.kind for load in problem.loads}
    if problem.analysis.about == "rest" and problem.loads:
        t_analysis.fail("about", "= 'rest': the modes are about the rest state, so a [[load]] "
                                 "would have no effect; remove it, or give an [analysis.about] "
                                 "table (the modes about the loaded state)")
    if problem.analysis.about != "rest" and kinds != {"force"}:
        t_analysis.fail("about", "is a loaded state: it needs [[load]] forces (and forces "
                                 f"only; given: {sorted(kinds) or 'none'})")
    if problem.sheet_mass.density is None and not problem.masses:
        t_analysis.fail("method", "= 'modes' needs masses: [material] density [t/mm^3] (with "
                                  "the sheet's thickness) or [[mass]] entries")


def _check_dynamic(problem, t_analysis, kinds):
    if kinds - {"force"}:
        t_analysis.fail("method", "= 'dynamic' takes force loads only (each with its time); a "
                                  "prescribed displacement is not one")
    if problem.sheet_mass.density is None and not problem.masses:
        t_analysis.fail("method", "= 'dynamic' needs masses: [material] density [t/mm^3] (with "
                                  "the sheet's thickness) or [[mass]] entries")
    if problem.contact is not None and problem.dynamics.scheme == "explicit":
        raise ValueError(f"{problem.source}: [dynamics] scheme = 'explicit' cannot keep "
                         "[contact]'s barriers (each step must not cross them): use 'newmark' "
                         "or 'hht'")


def _peek_method(data):
    """The problem's ``[analysis] method`` if it names one (read properly later)."""
    analysis = data.get("analysis") if isinstance(data, dict) else None
    return analysis.get("method") if isinstance(analysis, dict) else None


def _with_overrides(data, overrides, source):
    """A copy of the problem's tables with ``overrides``' keys set (tables created)."""
    if not isinstance(data, dict):
        return data  # the reader says what is wrong with it
    merged = dict(data)
    for table, keys in overrides.items():
        current = merged.get(table, {})
        if not isinstance(current, dict):
            raise ValueError(f"{source}: [{table}] must be a table, got "
                             f"{type(current).__name__}")
        merged[table] = {**current, **keys}
    return merged


def load_problem(problem, *, overrides=None) -> Problem:
    """Read and check a problem.

    Parameters
    ----------
    problem : str, os.PathLike or dict
        A TOML file, or a dict with the same tables (``pattern.file`` relative to the
        current directory; or ``pattern.vertices`` and ``pattern.panels`` inline).
    overrides : dict, optional
        Keys that replace the problem's own, by table: ``{"pattern": {"snap_tolerance":
        2.0}, "analysis": {"fold_percent": 50}}`` (what the command line's options set).

    Returns
    -------
    Problem

    Raises
    ------
    ValueError
        For a missing or unreadable file, bad TOML, an unknown or missing key, a bad value,
        a node out of range, a DOF both supported and driven, or a pattern file that cannot
        be read; the message names the file, the table and the key.
    """
    if isinstance(problem, Problem):
        return problem
    if isinstance(problem, dict):
        data, source, text, base = problem, "problem", None, Path.cwd()
    else:
        path = Path(problem)
        source, base = str(path), path.parent
        data, text = read_toml(path)
    if overrides:
        data = _with_overrides(data, overrides, source)
    root = _Table(data, "", source, text)
    root.where = lambda key: f"{source}: key {key!r}" if key else source

    t_pattern = _Table(root.get("pattern", lambda t, k, v, a: v, required=True,
                                allowed="a table naming the crease pattern"),
                       "pattern", source, text)
    folding = _peek_method(data) == "fold"
    # A fold needs no [material]: Origami Simulator's, which folds what it folds.
    t_material = _Table(root.get("material", lambda t, k, v, a: v,
                                 {"preset": DEFAULT_FOLD_PRESET} if folding else None,
                                 required=not folding,
                                 allowed="a table with the calibration (or a preset)"),
                        "material", source, text)
    material, compat, sheet_mass = _read_material(t_material)
    pattern, split, centre, convention = _read_pattern(t_pattern, base, compat)
    preset = material if isinstance(material, str) else None
    if preset is not None:
        material = preset_material(preset, pattern.vertices)
    laws = _read_laws(_Table(root.get("laws", lambda t, k, v, a: v, {}), "laws", source, text),
                      isinstance(material, SheetMaterial),
                      PRESET_LIMITS_DEG if preset else LAW_LIMITS_DEG)
    count = node_count(pattern, split, centre)
    supports = _read_supports(root.get("support", _array_of_tables, []), source, text, count)
    held = ()
    if folding and not supports:
        # A fold is driven from inside: hold the free sheet's rigid-body motions only.
        held = tuple(Support(node, axes) for node, axes in
                     rigid_body_hold(pattern.vertices, pattern.faces))
        supports = held
    loads = _read_loads(root.get("load", _array_of_tables, []), source, text, count)
    t_analysis = _Table(root.get("analysis", lambda t, k, v, a: v, required=True,
                                 allowed="a table with the method"), "analysis", source, text)
    analysis = _read_analysis(t_analysis, count)
    driven = {(node, axis) for load in loads if load.kind == "displacement"
              for node in load.nodes for axis, value in zip("xyz", load.vector) if value}
    output = read_output(_Table(root.get("output", lambda t, k, v, a: v, {}), "output", source,
                                text), count, analysis.method, driven)
    actuations = read_actuations(
        root.get("actuation", _array_of_tables, []),
        lambda entry, i: _Table(entry, "actuation", source, text, occurrence=i),
        _number, _integer, _string, pattern.num_vertices)
    springs = read_springs(root.get("spring", _array_of_tables, []),
                           lambda entry, i: _Table(entry, "spring", source, text, occurrence=i),
                           _number, lambda t: _node_list(t, count), _vector3)
    masses = read_masses(root.get("mass", _array_of_tables, []),
                         lambda entry, i: _Table(entry, "mass", source, text, occurrence=i),
                         _number, lambda t: _node_list(t, count))
    dynamics = None
    if root.has("dynamics"):
        dynamics = read_dynamics(_Table(root.get("dynamics", lambda t, k, v, a: v), "dynamics",
                                        source, text), _number, _positive, _vector3)
    contact = None
    if root.has("contact"):
        contact = read_contact(_Table(root.get("contact", lambda t, k, v, a: v), "contact", source,
                                      text), _number, _positive, _boolean, _vector3, _string)
    if analysis.tolerance is None:
        analysis = replace(analysis, tolerance=default_tolerance(pattern, compat))
    if (contact is not None and analysis.method == "fold" and analysis.increments != "adaptive"
            and not t_analysis.has("predictor")):
        # With panel contact a fold starts each increment from the previous equilibrium: an
        # extrapolated start may carry panels into each other, where the barriers' own
        # limits then shorten every Newton step.
        analysis = replace(analysis, predictor="previous")
    root.finish()
    result = Problem(pattern, split, material, compat, laws, supports, loads, analysis, source,
                     centre, output, actuations, springs, convention, sheet_mass, masses,
                     contact, dynamics, preset, held, count)
    _check_consistency(result, t_analysis)
    return result
