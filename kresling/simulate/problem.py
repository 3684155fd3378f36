"""A simulation problem stated in a TOML file (or a dict of the same shape).

The file names a crease pattern (FOLD, OBJ or SVG), how to build its model, its supports and
loads, and the analysis; :func:`load_problem` reads and checks it. Every node index is
0-based in the pattern file's vertex order; N5B8 centre nodes follow the vertices, in panel
order. Bad input raises a ``ValueError`` naming the file, the table and key (with the line
when it can be found) and what is allowed. See docs/simulate.md for every key.

Each top-level key is read by its own module of :mod:`kresling.simulate.problem_keys`, and
the analysis's settings by its method's module of :mod:`kresling.simulate.methods`.

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

import dataclasses
from dataclasses import dataclass, field
from pathlib import Path

from kresling.model import CreaseLaws
from kresling.simulate.methods import method_named
from kresling.simulate.problem_file import read_toml
from kresling.simulate.problem_keys import ReadContext, problem_keys
from kresling.simulate.problem_keys.analysis import Analysis, MonitorStop
from kresling.simulate.problem_keys.load import Load
from kresling.simulate.problem_keys.mass import SheetMass
from kresling.simulate.problem_keys.output import Output
from kresling.simulate.problem_keys.support import Support
from kresling.simulate.problem_table import ProblemTable, raw
from kresling.simulate.stages import StagedProblem, read_stages

__all__ = ["Problem", "Support", "Load", "MonitorStop", "Analysis", "load_problem"]


@dataclass(frozen=True, kw_only=True)
class Problem:
    """A checked problem: pattern, model settings, supports, loads and analysis.

    Every top-level key of the file fills some of these fields; the keys that are not part
    of every problem (``[[actuation]]``, ``[[spring]]``, ``[[mass]]``, ``[contact]``,
    ``[dynamics]``, and any key added later) are in ``extra`` and read as attributes
    too: ``problem.contact``, ``problem.springs``.

    Attributes
    ----------
    pattern : kresling.io.Pattern
    split : str
        "N5B8" or "N4B5".
    centre : str
        N5B8 centre nodes: "merlin2" (its rules) or "mean" (of the corners).
    assignments : str
        How FOLD assignments become hinges: "fold" (the spec) or "origami_simulator".
    num_nodes : int
        The model's node count the problem was checked against (pattern vertices, then
        N5B8 centre nodes).
    renumbered : str
        Where the pattern file writes a vertex twice: the warning of its merge ("" if not).
    material : SheetMaterial or ManualProperties
    merlin2_compat : bool
        Build and drive the model exactly as MERLIN2 v1.1 would.
    preset : str or None
        The named material (``[material] preset``, or a fold's default).
    sheet_mass : SheetMass
        ``[material] density`` and the sheet's thickness.
    laws : CreaseLaws
    supports : tuple of Support
    held : tuple of Support
        The supports chosen to hold a fold's free sheet (no ``[[support]]`` given): the
        rigid-body motions only.
    loads : tuple of Load
    analysis : Analysis
    output : Output
        The ``[output]`` table: increments kept in the files, the view's curve, formats.
    source : str
        Where the problem came from (the file, or "problem" for a dict).
    extra : dict
        The other keys' fields, by field name.
    """

    pattern: object
    split: str = "N5B8"
    centre: str = "merlin2"
    assignments: str = "fold"
    num_nodes: int | None = None
    #: The warning of a pattern file whose coincident vertices were merged ("" if none).
    renumbered: str = ""
    material: object = None
    merlin2_compat: bool = False
    preset: str | None = None
    sheet_mass: SheetMass = SheetMass()
    laws: CreaseLaws = CreaseLaws()
    supports: tuple = ()
    held: tuple = ()
    loads: tuple = ()
    analysis: Analysis = None
    output: Output = Output()
    source: str = "problem"
    extra: dict = field(default_factory=dict)

    def __getattr__(self, name):
        extra = self.__dict__.get("extra", {})
        if name in extra:
            return extra[name]
        raise AttributeError(f"{type(self).__name__!r} has no field {name!r}")

    def replace(self, **changes) -> "Problem":
        """A copy with ``changes`` (any field, ``extra``'s too: ``contact=None``)."""
        declared = {f.name for f in dataclasses.fields(self)}
        extra = {**self.extra, **{k: v for k, v in changes.items() if k not in declared}}
        return dataclasses.replace(self, extra=extra,
                                   **{k: v for k, v in changes.items() if k in declared})

    @property
    def method(self):
        """The analysis method (:class:`~kresling.simulate.methods.method.Method`)."""
        return method_named(self.analysis.method)


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


def _read_key(root, key, context):
    """One key's fields, and its table (None for an array key or a key left out)."""
    if key.array:
        return key.read(root.entries(key.name), context), None
    required = key.required(context) if callable(key.required) else key.required
    default = key.default(context) if callable(key.default) else key.default
    if default is None and not required and not root.has(key.name):
        root.get(key.name, raw)  # known, though absent
        return dict(key.absent or {}), None
    table = root.table(key.name, default, required=required, allowed=key.allowed)
    return key.read(table, context), table


def load_problem(problem, *, overrides=None, source=None):
    """Read and check a problem.

    Parameters
    ----------
    problem : str, os.PathLike or dict
        A TOML file, or a dict with the same tables (``pattern.file`` relative to the
        current directory; or ``pattern.vertices`` and ``pattern.panels`` inline).
    overrides : dict, optional
        Keys that replace the problem's own, by table: ``{"pattern": {"snap_tolerance":
        2.0}, "analysis": {"fold_percent": 50}}`` (what the command line's options set).
    source : str, optional
        How messages name a dict problem (default "problem").

    Returns
    -------
    Problem, or StagedProblem
        A :class:`~kresling.simulate.stages.StagedProblem` for a problem in stages
        (``[[stage]]``).

    Raises
    ------
    ValueError
        For a missing or unreadable file, bad TOML, an unknown or missing key, a bad value,
        a node out of range, a DOF both supported and driven, or a pattern file that cannot
        be read; the message names the file, the table and the key.
    """
    if isinstance(problem, (Problem, StagedProblem)):
        return problem
    if isinstance(problem, dict):
        data, source, text, base = problem, source or "problem", None, Path.cwd()
    else:
        path = Path(problem)
        source, base = str(path), path.parent
        data, text = read_toml(path)
    if isinstance(data, dict) and "stage" in data:
        if overrides and "analysis" in overrides:
            raise ValueError(f"{source}: a problem in [[stage]]s takes its analysis settings "
                             "per stage (set fold_percent in the stages it belongs to)")
        if overrides:
            data = _with_overrides(data, overrides, source)
        return read_stages(data, source, base, load_problem)
    if overrides:
        data = _with_overrides(data, overrides, source)
    root = ProblemTable(data, "", source, text)
    root.where = lambda key: f"{source}: key {key!r}" if key else source
    context = ReadContext(source, text, base, _peek_method(data),
                          data if isinstance(data, dict) else ())
    tables = {}
    for key in problem_keys():
        fields, tables[key.name] = _read_key(root, key, context)
        context.fields.update(fields)
    root.finish()
    declared = {f.name for f in dataclasses.fields(Problem)}
    result = Problem(source=source,
                     extra={k: v for k, v in context.fields.items() if k not in declared},
                     **{k: v for k, v in context.fields.items() if k in declared})
    for key in problem_keys():
        if key.check is not None:
            key.check(result)
    result.method.check(result, tables["analysis"])
    return result.method.finalize(result, tables["analysis"])

