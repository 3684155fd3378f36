"""The immutable bar-and-hinge :class:`Model`."""

from __future__ import annotations

import numpy as np

from kresling import _core
from kresling._validation import (as_float_array, as_integer, as_integer_array, as_mask,
                                  show)
# The law tables live in kresling.laws (the element kernels name laws too); these names
# stay importable from here and from kresling.model.
from kresling.laws import BAR_LAWS, FOLD_LIMITS, HINGE_ANGLES, SPRING_LAWS  # noqa: F401


def _per_element(name, value, count, dtype=float):
    array = as_float_array(name, value)
    if array.ndim == 0:
        array = np.full(count, array, dtype=dtype)
    if array.shape != (count,):
        raise ValueError(f"{name} has shape {array.shape}: must be a scalar or ({count},)")
    return np.ascontiguousarray(array)


def _law_codes(name, value, table, count):
    if isinstance(value, str):
        values = [value] * count
    elif isinstance(value, (list, tuple, np.ndarray)):
        values = list(value)
    else:
        raise ValueError(f"{name} = {show(value)} is invalid: must be one of {sorted(table)} "
                         f"or a list of {count} of them")
    if len(values) != count:
        raise ValueError(f"{name} has {len(values)} entries: must be a name or {count} names")
    unknown = [v for v in values if not isinstance(v, str) or v not in table]
    if unknown:
        raise ValueError(f"{name} = {show(unknown[0])} is invalid: must be one of {sorted(table)}")
    return np.array([table[v] for v in values], dtype=np.int64)


def _index_rows(name, value, width):
    """Element node indices as an (E, width) int64 array: integers only (1.7 is not node 1,
    True is not node 1)."""
    array = as_integer_array(name, value).astype(np.int64)
    if array.size % width:
        raise ValueError(f"{name} has {array.size} entries: must be rows of {width} node "
                         "indices")
    return np.ascontiguousarray(array.reshape(-1, width))


class Model:
    """A bar-and-hinge model (immutable).

    Parameters
    ----------
    nodes : array_like, shape (N, 3)
        Node coordinates of the reference state [mm].
    bars : array_like of int, shape (B, 2)
        End nodes of every bar (0-based).
    hinges : array_like of int, shape (H, 4)
        ``(a, b, c, d)``: axis nodes ``a -> b`` and wing nodes ``c``, ``d``.
    bar_modulus : float or array_like, shape (B,)
        Modulus C0 [N/mm^2]; the axial stiffness is ``C0 * bar_area``.
    hinge_stiffness : float or array_like, shape (H,)
        Rotational stiffness per unit length kp [N*mm/rad/mm = N/rad]; 0 for a free hinge.
    bar_area : float or array_like, shape (B,), default 1
        Cross-section A [mm^2].
    bar_rest_length : array_like, shape (B,), optional
        Rest lengths [mm]; default: the lengths in ``nodes`` (stress-free reference).
    bar_law : str or sequence of str, default "ogden"
        One of :data:`BAR_LAWS`.
    hinge_rest_angle : array_like, shape (H,), optional
        Rest angles in [0, 2 pi) [rad]; default: the angles in ``nodes``.
    hinge_length : array_like, shape (H,), optional
        Length multiplying each spring law [mm]; default: the axis length in ``nodes``.
    hinge_law : str or sequence of str, default "enhanced_linear"
        One of :data:`SPRING_LAWS`.
    hinge_limits : (float, float) or array_like, shape (H, 2), default (5 deg, 355 deg)
        Limits of the enhanced linear law's linear range [rad].
    hinge_angle : str or sequence of str, default "exact"
        How each hinge's dihedral angle is computed, one of :data:`HINGE_ANGLES`: "exact"
        (atan2, accurate to rounding flat or folded) or "merlin2" (MERLIN2's arccosine, to
        reproduce its runs to rounding). The default rest angles use the same form.
    fixed : array_like of bool, shape (N, 3), optional
        Supported DOFs (u = 0). Default: none.
    cables : sequence of (nodes, stiffness, rest_length), optional
        Sliding cables (tendons): each runs from ``nodes[0]`` through frictionless guides
        ``nodes[1:-1]`` to ``nodes[-1]``, tension only, with axial rigidity ``stiffness`` EA
        [N] and ``rest_length`` [mm] (``None``: its path length in ``nodes``, just taut).
        Read back as ``cable_nodes`` (tuple of arrays), ``cable_stiffness``,
        ``cable_rest_length``. Default: none.
    families : dict, optional
        Further element families by name, each a dict of its columns (arrays with one row
        per element), e.g. ``{"springs": {"nodes": [3], "stiffness": [[kx, ky, kz]],
        "anchor": [[x, y, z]]}}``; :func:`family_kinds` lists the families there are and
        ``model.family(name)`` reads one back. Default: none.

    Raises
    ------
    ValueError
        For inconsistent shapes, indices out of range, degenerate elements (zero-length bars,
        a wing on its hinge's axis line), negative stiffness or non-finite values; the
        message names the element.

    Notes
    -----
    DOF ``3 i + k`` is coordinate ``k`` (x, y, z) of node ``i``.
    """

    def __init__(self, nodes, bars, hinges, *, bar_modulus, hinge_stiffness, bar_area=1.0,
                 bar_rest_length=None, bar_law="ogden", hinge_rest_angle=None, hinge_length=None,
                 hinge_law="enhanced_linear", hinge_limits=FOLD_LIMITS, fixed=None, cables=None,
                 families=None, hinge_angle="exact"):
        nodes = np.ascontiguousarray(as_float_array("nodes", nodes))
        if nodes.ndim != 2 or nodes.shape[1] != 3:
            raise ValueError(f"nodes has shape {nodes.shape}: must be (N, 3)")
        bars = _index_rows("bars", bars, 2)
        hinges = _index_rows("hinges", hinges, 4)
        nb, nh = len(bars), len(hinges)
        for name, idx in (("bars", bars), ("hinges", hinges)):
            if idx.size and (idx.min() < 0 or idx.max() >= len(nodes)):
                row = int(np.argwhere((idx < 0) | (idx >= len(nodes)))[0, 0])
                raise ValueError(f"{name}[{row}] = {idx[row].tolist()}: node index out of range "
                                 f"[0, {len(nodes)})")
        if bar_rest_length is None:
            bar_rest_length = np.linalg.norm(nodes[bars[:, 1]] - nodes[bars[:, 0]], axis=1)
        angle_forms = _law_codes("hinge_angle", hinge_angle, HINGE_ANGLES, nh)
        if hinge_rest_angle is None:
            hinge_rest_angle = _default_rest_angles(nodes, hinges, angle_forms)
        if hinge_length is None:
            hinge_length = np.linalg.norm(nodes[hinges[:, 1]] - nodes[hinges[:, 0]], axis=1)
        limits = as_float_array("hinge_limits", hinge_limits)
        limits = np.broadcast_to(limits, (nh, 2)) if limits.shape == (2,) else limits
        if limits.shape != (nh, 2):
            raise ValueError(f"hinge_limits has shape {limits.shape}: must be (2,) or ({nh}, 2)")
        if fixed is None:
            fixed = np.zeros((len(nodes), 3), dtype=bool)
        fixed = as_mask("fixed", fixed)
        if fixed.shape != nodes.shape:
            raise ValueError(f"fixed has shape {fixed.shape}: must be {nodes.shape}")

        cable_nodes, cable_stiffness, cable_rest = _cables(cables, nodes)
        self._arrays = {
            "nodes": nodes,
            "bars": bars,
            "bar_area": _per_element("bar_area", bar_area, nb),
            "bar_rest_length": _per_element("bar_rest_length", bar_rest_length, nb),
            "bar_law": _law_codes("bar_law", bar_law, BAR_LAWS, nb),
            "bar_modulus": _per_element("bar_modulus", bar_modulus, nb),
            "hinges": hinges,
            "hinge_stiffness": _per_element("hinge_stiffness", hinge_stiffness, nh),
            "hinge_rest_angle": _per_element("hinge_rest_angle", hinge_rest_angle, nh),
            "hinge_length": _per_element("hinge_length", hinge_length, nh),
            "hinge_law": _law_codes("hinge_law", hinge_law, SPRING_LAWS, nh),
            "hinge_limits": np.ascontiguousarray(limits),
            "hinge_angle": angle_forms,
            "fixed": fixed,
            "cable_stiffness": cable_stiffness,
            "cable_rest_length": cable_rest,
        }
        for array in self._arrays.values():
            array.flags.writeable = False
        self._arrays["cable_nodes"] = cable_nodes
        self._core = _core.model.Model(nodes, fixed.astype(np.uint8).ravel(),
                                       {**_builtin_tables(self._arrays), **_tables(families)})

    @classmethod
    def _from_core(cls, core) -> "Model":
        """Wrap a model built (and validated) by the C++ core, e.g. a Kresling specimen."""
        tables = {name: {k: np.asarray(v) for k, v in table.items()}
                  for name, table in core.tables().items()}
        bars, hinges, cables = tables["bars"], tables["hinges"], tables["cables"]
        self = cls.__new__(cls)
        self._arrays = {
            "nodes": np.asarray(core.nodes), "bars": bars["nodes"].reshape(-1, 2),
            "bar_area": bars["area"], "bar_rest_length": bars["rest_length"],
            "bar_law": bars["law"], "bar_modulus": bars["modulus"],
            "hinges": hinges["nodes"].reshape(-1, 4), "hinge_stiffness": hinges["stiffness"],
            "hinge_rest_angle": hinges["rest_angle"], "hinge_length": hinges["length"],
            "hinge_law": hinges["law"],
            "hinge_limits": np.column_stack([hinges["theta1"], hinges["theta2"]]),
            "hinge_angle": hinges["angle_form"],
            "fixed": np.asarray(core.fixed).astype(bool).reshape(-1, 3),
            "cable_stiffness": cables["stiffness"], "cable_rest_length": cables["rest_length"],
        }
        for array in self._arrays.values():
            array.flags.writeable = False
        self._arrays["cable_nodes"] = tuple(
            np.split(cables["nodes"].astype(np.int64), np.cumsum(cables["node_count"])[:-1])
            if len(cables["node_count"]) else ())
        for array in self._arrays["cable_nodes"]:
            array.flags.writeable = False
        self._core = core
        return self

    @property
    def families(self) -> tuple:
        """The element families the model holds, in assembly order ("bars", "hinges",
        "cables", then any others)."""
        return tuple(self._core.families)

    def family(self, name: str) -> dict:
        """The columns of element family ``name`` (read-only arrays, one row per element)."""
        tables = self.__dict__.get("_family_tables")
        if tables is None:
            # Read from the core once: a model never changes, and a path's output asks at
            # every increment.
            tables = {family: {k: np.asarray(v) for k, v in table.items()}
                      for family, table in self._core.tables().items()}
            for table in tables.values():
                for array in table.values():
                    array.flags.writeable = False
            self.__dict__["_family_tables"] = tables
        if name not in tables:
            raise ValueError(f"name = {name!r} is invalid: the model's families are "
                             f"{list(tables)}")
        return dict(tables[name])

    @classmethod
    def from_panels(cls, nodes, panels, *, split="N4B5", duplicate_shared_edges=True,
                    **properties):
        """Build a model from panels (see :func:`kresling.model.panel_topology`).

        ``properties`` are the keyword arguments of :class:`Model` (scalars apply to every
        element; arrays follow the topology's element order, which
        ``Model.from_panels(...).bars`` / ``.hinges`` show).
        """
        from kresling.model.topology import panel_topology

        topo = panel_topology(nodes, panels, split=split,
                              duplicate_shared_edges=duplicate_shared_edges)
        return cls(topo.nodes, topo.bars, topo.hinges, **properties)

    def replace(self, **changes) -> "Model":
        """A copy with some arrays or properties changed, e.g. ``model.replace(fixed=mask)``."""
        a = dict(self._arrays)
        kwargs = {
            "bar_modulus": a["bar_modulus"], "hinge_stiffness": a["hinge_stiffness"],
            "bar_area": a["bar_area"], "bar_rest_length": a["bar_rest_length"],
            "bar_law": [_name(BAR_LAWS, c) for c in a["bar_law"]],
            "hinge_rest_angle": a["hinge_rest_angle"], "hinge_length": a["hinge_length"],
            "hinge_law": [_name(SPRING_LAWS, c) for c in a["hinge_law"]],
            "hinge_limits": a["hinge_limits"], "fixed": a["fixed"],
            "hinge_angle": [_name(HINGE_ANGLES, c) for c in a["hinge_angle"]],
            "cables": list(zip(a["cable_nodes"], a["cable_stiffness"], a["cable_rest_length"])),
            "families": self._further_families(),
        }
        positional = {"nodes": a["nodes"], "bars": a["bars"], "hinges": a["hinges"]}
        for key, value in changes.items():
            if key in positional:
                positional[key] = value
            elif key in kwargs:
                kwargs[key] = value
            else:
                raise ValueError(f"replace: unknown field {key!r}")
        return Model(positional["nodes"], positional["bars"], positional["hinges"], **kwargs)

    def with_families(self, families: dict) -> "Model":
        """A copy with further element families added (or, by name, replaced), the ones it
        holds beside its bars, hinges and cables kept: ``{name: {column: array}}`` as for
        ``Model(..., families=...)``."""
        return self.replace(families={**self._further_families(), **families})

    def _further_families(self) -> dict:
        """The columns of every family beside the bars, hinges and cables, by name."""
        return {name: self.family(name) for name in self.families
                if name not in _BUILTIN_FAMILIES}

    # -- read-only views -------------------------------------------------------------
    def __getattr__(self, name):
        arrays = self.__dict__.get("_arrays", {})
        if name in arrays:
            return arrays[name]
        raise AttributeError(name)

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._arrays))

    @property
    def num_nodes(self) -> int:
        return len(self._arrays["nodes"])

    @property
    def num_dofs(self) -> int:
        return 3 * self.num_nodes

    @property
    def free_dofs(self) -> np.ndarray:
        """Indices of the DOFs without a support."""
        return np.flatnonzero(~self._arrays["fixed"].ravel())

    def dof(self, node: int, axis) -> int:
        """The DOF index of ``node``'s coordinate ``axis`` (0/1/2 or "x"/"y"/"z")."""
        node = as_integer("node", node, minimum=0, maximum=self.num_nodes - 1)
        k = {"x": 0, "y": 1, "z": 2}.get(axis, axis) if isinstance(axis, (str, int)) else None
        if isinstance(k, bool) or k not in (0, 1, 2):
            raise ValueError(f"axis = {show(axis)} is invalid: must be 0, 1, 2 or 'x', 'y', 'z'")
        return 3 * node + int(k)

    def element_state(self, u=None) -> dict:
        """Bar strains and axial forces, hinge angles and moments at displacement ``u``.

        Returns
        -------
        dict
            ``bar_strain`` (B,), ``bar_force`` (B,) [N], ``hinge_angle`` (H,) [rad],
            ``hinge_moment`` (H,) [N*mm]; ``cable_length`` (C,) [mm], ``cable_tension`` (C,)
            [N] (0 when slack).

        Raises
        ------
        ValueError
            For a ``u`` of the wrong size or with NaN, or one where an element's state is not
            finite (a degenerate element, a hinge folded flat, an overflow).
        """
        if u is None:
            u = np.zeros(self.num_dofs)
        else:
            u = as_float_array("u", u).ravel()
            if u.shape != (self.num_dofs,):
                raise ValueError(f"u has {u.size} entries: must have {self.num_dofs} (3 per "
                                 "node)")
            if not np.isfinite(u).all():
                raise ValueError("u contains NaN or inf")
        # Every family's columns, in the order the core's families add them.
        state = {k: np.asarray(v)
                 for k, v in _core.assembly.element_state(self._core, u).items()}
        for key, values in state.items():
            if values.size and not np.isfinite(values).all():
                i = int(np.flatnonzero(~np.isfinite(values))[0])
                raise ValueError(f"u is invalid: the element states are not finite there "
                                 f"({key}[{i}] = {values[i]!r}: an element degenerated, a hinge "
                                 "folded flat, or the displacement is beyond what a float holds)")
        return state

    def __repr__(self):
        cables = f"{len(self.cable_nodes)} cables, " if len(self.cable_nodes) else ""
        return (f"Model({self.num_nodes} nodes, {len(self.bars)} bars, {len(self.hinges)} hinges, "
                f"{cables}{int(self.fixed.sum())} supported DOFs)")


#: The families every model holds, whose columns the Model's own attributes show.
_BUILTIN_FAMILIES = ("bars", "hinges", "cables")


def family_kinds() -> dict:
    """The element families a model can hold: ``{name: description}``, in assembly order."""
    return dict(_core.model.family_kinds())


def _builtin_tables(a) -> dict:
    """The bars', hinges' and cables' columns (the core's tables) from the Model's arrays."""
    cable_nodes = a["cable_nodes"]
    return {
        "bars": {"nodes": a["bars"], "area": a["bar_area"], "rest_length": a["bar_rest_length"],
                 "law": a["bar_law"], "modulus": a["bar_modulus"]},
        "hinges": {"nodes": a["hinges"], "stiffness": a["hinge_stiffness"],
                   "rest_angle": a["hinge_rest_angle"], "length": a["hinge_length"],
                   "law": a["hinge_law"], "theta1": np.ascontiguousarray(a["hinge_limits"][:, 0]),
                   "theta2": np.ascontiguousarray(a["hinge_limits"][:, 1]),
                   "angle_form": a["hinge_angle"]},
        "cables": {"nodes": (np.concatenate(cable_nodes) if cable_nodes
                             else np.zeros(0, dtype=np.int64)),
                   "node_count": np.array([len(c) for c in cable_nodes], dtype=np.int64),
                   "stiffness": a["cable_stiffness"], "rest_length": a["cable_rest_length"]},
    }


def _default_rest_angles(nodes, hinges, forms):
    """The hinges' angles in ``nodes``, each computed in its own form."""
    angles = np.empty(len(hinges))
    for name, code in HINGE_ANGLES.items():
        chosen = forms == code
        if chosen.any():
            angles[chosen] = _core.elements.dihedral_angles(
                nodes, hinges[chosen], getattr(_core.elements.DihedralForm, name))
    return angles


def _tables(families) -> dict:
    """Further families' columns as the core takes them: integer arrays stay integers (node
    indices), every other number becomes a float."""
    if families is None:
        return {}
    if not isinstance(families, dict):
        raise ValueError(f"families = {show(families)} is invalid: must be a dict "
                         "{name: {column: array}}")
    tables = {}
    for name, columns in families.items():
        if name in _BUILTIN_FAMILIES:
            raise ValueError(f"families[{name!r}] is invalid: {name} are given by the Model's "
                             "own arguments")
        if not isinstance(columns, dict):
            raise ValueError(f"families[{name!r}] = {show(columns)} is invalid: must be a dict "
                             "of columns")
        table = {}
        for key, value in columns.items():
            array = np.asarray(value)
            if array.dtype.kind not in "iu":
                array = as_float_array(f"families[{name!r}][{key!r}]", value)
            table[key] = np.ascontiguousarray(array)
        tables[name] = table
    return tables


def _cables(cables, nodes):
    """Cable nodes (a tuple of read-only int arrays), stiffnesses and rest lengths."""
    if cables is None:
        return (), np.zeros(0), np.zeros(0)
    node_lists, stiffness, rest = [], [], []
    for i, cable in enumerate(cables):
        try:
            path, k, length = cable
        except (TypeError, ValueError):
            raise ValueError(f"cables[{i}] must be (nodes, stiffness, rest_length)") from None
        path = np.asarray(path, dtype=np.int64).ravel()
        if path.size and (path.min() < 0 or path.max() >= len(nodes)):
            raise ValueError(f"cables[{i}] = {path.tolist()}: node index out of range "
                             f"[0, {len(nodes)})")
        if length is None:
            length = float(np.linalg.norm(np.diff(nodes[path], axis=0), axis=1).sum())
        path.flags.writeable = False
        node_lists.append(path)
        stiffness.append(float(k))
        rest.append(float(length))
    return tuple(node_lists), np.array(stiffness), np.array(rest)


def _name(table, code):
    return next(k for k, v in table.items() if v == code)
