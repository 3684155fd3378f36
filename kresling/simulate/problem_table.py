"""One table of a problem file being read, and the readers of its values.

A :class:`ProblemTable` hands out its keys' values through typed readers (``number``,
``positive``, ``string``, ...: functions ``(table, key, value, allowed) -> value``), remembers
which keys were read, and reports an unknown key at the end. Every refusal is a ``ValueError``
naming the file, the line (when it can be found in the TOML text), the table and the key.

>>> t = ProblemTable({"steps": 10}, "analysis", "problem.toml")
>>> t.get("steps", count), t.get("tolerance", positive, 1e-6)
(10, 1e-06)
"""

from __future__ import annotations

import math
import re

import numpy as np

from kresling import _core
from kresling._validation import show

__all__ = ["ProblemTable", "QUANTITY_RANGE", "AXES", "raw", "number", "positive", "quantity",
           "quantities", "stiffnesses", "integer", "count", "boolean", "string", "vector3",
           "array_of_tables", "limits", "panels", "node_list", "node_rows", "line_of",
           "in_range"]

#: A support's or a monitor's axis letter and its DOF offset within a node.
AXES = {"x": 0, "y": 1, "z": 2}


class ProblemTable:
    """One TOML table being read: typed getters, and unknown keys reported at the end."""

    def __init__(self, data, name, source, text=None, occurrence=0):
        self.name, self.source, self.text, self.occurrence = name, source, text, occurrence
        if not isinstance(data, dict):
            self.fail(None, f"must be a table, got {type(data).__name__}")
        self.data, self.used = data, set()

    def where(self, key):
        label = f"[{self.name}]" if key is None else f"[{self.name}] key {key!r}"
        line = line_of(self.text, self.name, key, self.occurrence) if self.text else None
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

    def table(self, key, default=None, *, required=False, allowed=None) -> "ProblemTable":
        """The sub-table ``key`` (``[name.key]``, or an inline table) as a table of its own,
        or ``default`` (a dict, read as the table) when it is absent."""
        value = self.get(key, raw, default, required=required, allowed=allowed)
        name = f"{self.name}.{key}" if self.name else key
        return ProblemTable(value, name, self.source, self.text)

    def entries(self, key) -> list:
        """The ``[[key]]`` entries, each a table of its own (entry i knows it is the i-th,
        to find its lines)."""
        return [ProblemTable(entry, key, self.source, self.text, occurrence=i)
                for i, entry in enumerate(self.get(key, array_of_tables, []))]

    def finish(self):
        unknown = sorted(set(self.data) - self.used)
        if unknown:
            self.fail(unknown[0], f"is unknown: allowed keys are {sorted(self.used)}")


def line_of(text, table, key, occurrence=0):
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
def raw(t, key, value, allowed=None):
    """The value as the TOML file gives it (its reader checks it)."""
    return value


def number(t, key, value, allowed=None):
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        t.fail(key, f"= {value!r} is invalid: must be a finite number")
    return float(value)


def positive(t, key, value, allowed=None):
    value = number(t, key, value)
    if value <= 0:
        t.fail(key, f"= {value!r} is invalid: must be > 0")
    return value


#: Magnitudes a physical quantity of a problem (a modulus, a length, an area, a stiffness,
#: a force) may have: far beyond any sheet in mm, N and N/mm^2, and far enough inside the
#: floating-point range (1e-308 to 1e308) that the model's products of a few of them
#: (stiffness times length squared, ...) neither overflow nor vanish.
QUANTITY_RANGE = (1e-30, 1e30)


def in_range(t, key, value, *, zero=False):
    low, high = QUANTITY_RANGE
    if not (low <= abs(value) <= high or (zero and value == 0)):
        t.fail(key, f"= {value!r} is out of range: its magnitude must be in [{low:g}, {high:g}]"
                    + (" (or 0)" if zero else ""))
    return value


def quantity(t, key, value, allowed=None):
    """A positive physical quantity, within QUANTITY_RANGE."""
    return in_range(t, key, positive(t, key, value))


def quantities(t, key, value, allowed=None, *, zero=False):
    """A number or an array of them (one per element): each > 0 (>= 0 with ``zero``),
    within QUANTITY_RANGE."""
    numbers = value if isinstance(value, list) else [value]
    checked = []
    for entry in numbers:
        entry = number(t, key, entry)
        if entry < 0 or (entry == 0 and not zero):
            where = f"has an entry {entry!r} that" if isinstance(value, list) else f"= {entry!r}"
            t.fail(key, f"{where} is invalid: must be {'>= 0' if zero else '> 0'}")
        checked.append(in_range(t, key, entry, zero=zero))
    return np.array(checked, dtype=float) if isinstance(value, list) else checked[0]


def stiffnesses(t, key, value, allowed=None):
    return quantities(t, key, value, zero=True)


def integer(t, key, value, allowed=None):
    if isinstance(value, bool) or not isinstance(value, int):
        t.fail(key, f"= {value!r} is invalid: must be an integer")
    return value


def count(t, key, value, allowed=None):
    """An increment or iteration count, in the solvers' documented range (their limits)."""
    value = integer(t, key, value)
    largest = (_core.solvers.MAX_ITERATIONS if key == "max_iterations"
               else _core.solvers.MAX_STEPS)
    if not 1 <= value <= largest:
        t.fail(key, f"= {value!r} is invalid: must be an integer in [1, {largest}]")
    return value


def boolean(t, key, value, allowed=None):
    if not isinstance(value, bool):
        t.fail(key, f"= {value!r} is invalid: must be true or false")
    return value


def string(t, key, value, allowed=None):
    if not isinstance(value, str) or (allowed and value not in allowed):
        t.fail(key, f"= {value!r} is invalid: must be one of {list(allowed)}" if allowed
               else f"= {value!r} is invalid: must be a string")
    return value


def vector3(t, key, value, allowed=None):
    if not isinstance(value, list) or len(value) != 3:
        t.fail(key, f"= {value!r} is invalid: must be 3 numbers [x, y, z]")
    return tuple(in_range(t, key, number(t, key, v), zero=True) for v in value)


def array_of_tables(t, key, value, allowed=None):
    if not isinstance(value, list):
        t.fail(key, f"= {value!r} is invalid: must be an array of tables ([[{key}]] entries)")
    return value


def limits(t, key, value, allowed=None):
    if not isinstance(value, list) or len(value) != 2:
        t.fail(key, f"= {value!r} is invalid: must be two angles [theta1, theta2] in degrees")
    low, high = (number(t, key, v) for v in value)
    if not 0 < low < high < 360:
        t.fail(key, f"= {value!r} is invalid: must satisfy 0 < theta1 < theta2 < 360 [deg]")
    return (low, high)


def panels(t, key, value, allowed=None):
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


def node_list(t, num_nodes):
    """``node = k`` or ``nodes = [k, ...]``: checked against the model's node count."""
    if t.has("node") == t.has("nodes"):
        t.fail(None, "needs exactly one of 'node' (an index) or 'nodes' (a list of indices)")
    if t.has("node"):
        nodes = [t.get("node", integer)]
        key = "node"
    else:
        value = t.get("nodes", raw)
        if not isinstance(value, list) or not value:
            t.fail("nodes", f"= {value!r} is invalid: must be a non-empty list of node indices")
        nodes = [integer(t, "nodes", v) for v in value]
        key = "nodes"
    for node in nodes:
        if not 0 <= node < num_nodes:
            t.fail(key, f"= {node} is out of range: nodes are numbered 0 to {num_nodes - 1} "
                        "(pattern vertices, then N5B8 centre nodes)")
    return tuple(nodes)


def node_rows(t, key, width, num_nodes, what):
    """``key = [i, j, ...]`` (one element of ``width`` nodes) or an array of them (several
    elements alike), shape (E, width), each node in range and no node twice in one row;
    ``what`` names the element in messages ("a bar: [i, j]")."""
    value = t.get(key, raw, required=True, allowed=f"{what}, or an array of them")
    rows = value if isinstance(value, list) and value and isinstance(value[0], list) \
        else [value]
    out = []
    for row in rows:
        if not isinstance(row, list) or len(row) != width:
            t.fail(key, f"has {show(row)}: each is {what}")
        nodes = [integer(t, key, v) for v in row]
        for node in nodes:
            if not 0 <= node < num_nodes:
                t.fail(key, f"has node {node}: out of range, nodes are numbered 0 to "
                            f"{num_nodes - 1} (pattern vertices, then N5B8 centre nodes)")
        if len(set(nodes)) != width:
            t.fail(key, f"has {nodes}: an element names {width} different nodes")
        out.append(nodes)
    return np.array(out, dtype=np.int64).reshape(-1, width)
