"""Bar-and-hinge models of generalized Kresling stacks (the thesis's specimens).

The C++ core builds the nodes, panels and elements exactly as docs/thesis_equations.md
('Bending test') reconstructs the thesis's generator; this module is its Python face.
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields, replace

import numpy as np

from kresling import _core
from kresling._validation import (as_bool, as_choice, as_float_array, as_integer, as_list,
                                  as_mask, as_real, show)
from kresling.geometry import Design, as_design, state_index
from kresling.model.model import BAR_LAWS, HINGE_ANGLES, Model

__all__ = ["SpecimenParameters", "KreslingSpecimen", "kresling_specimen", "EDGE_FAMILIES",
           "alternating_chirality", "MOUNTAIN_CREASES"]

#: Element families by code: the family of a bar is its edge's, of a hinge its axis's (the
#: core's EdgeFamily, named in code order).
EDGE_FAMILIES = tuple(name for name, _ in sorted(_core.model.EdgeFamily.__members__.items(),
                                                 key=lambda item: int(item[1])))

#: The mountain creases' elements, cut through (the thesis's specimens: no hinge, a weak bar
#: of area 0.01) or intact (a crease like the valleys: hinge ``kf``, a bar on material).
MOUNTAIN_CREASES = {
    "cut": {"mountain_factor": 0.0, "mountain_area": 0.01},
    "intact": {"mountain_factor": 1.0, "mountain_area": 1.0},
}


@dataclass(frozen=True)
class SpecimenParameters:
    """Stiffness assignment of a Kresling specimen; the defaults are the thesis's.

    Parameters
    ----------
    kf : float
        Crease stiffness per unit length [N/rad] (thesis Table 1: 0.047).
    valley_factor, polygon_edge_factor : float
        Hinges on valley creases and polygon edges: ``factor * kf`` (1).
    spoke_factor : float
        Hinges on the polygon spokes (the flat fan inside each polygon): ``factor * kf`` (10).
    mountain_factor : float
        Hinges on the mountain creases, cut through in the specimens (0).
    modulus_factor : float
        Bar modulus ``C0 = modulus_factor * kf`` (1e5, so EA = 4700 N with area 1).
    material_area, mountain_area : float
        Bar areas on material (1) and on the cut mountain creases (0.01: EA = 1e3 kf).
    fold_limits : (float, float)
        Linear range of the enhanced linear spring law [rad] (5 and 355 degrees).
    bar_law : {"ogden", "linear"}
    duplicate_shared_edges : bool
        MERLIN2's topology (True, the thesis's default), which puts coincident bars and
        hinges on every edge shared by more than two triangles (the intermediate polygons of
        a stack), or one bar per edge (False; see ``kresling.model.panel_topology``), which
        is softer. It changes the bending stiffness of stacks: K_con of the Table 3
        specimens by 1.8 to about 8 % (5 mm protocol; up to 8.4 % for n = 10, Lc = 15 mm,
        lambda = 0.9, whose single-element run loses stability before the end of its
        travel; 9.5 % linearised), K_ext by under 1 %; a single cell not at all
        (``kresling.analyses.table3.topology_effect`` measures it).
    hinge_angle : {"merlin2", "exact"}
        How the hinges' angles are computed (:data:`kresling.laws.HINGE_ANGLES`): MERLIN2's
        arccosine (the default: the thesis's runs computed it, and the cells' flat polygon
        spokes are where the two forms differ, by ~1e-8 rad) or the exact atan2.

    Examples
    --------
    >>> p = SpecimenParameters(kf=0.1).with_mountain_creases("intact")
    >>> p.mountain_creases, p.mountain_factor, p.mountain_area
    ('intact', 1.0, 1.0)
    >>> SpecimenParameters.from_dict(p.as_dict()) == p
    True
    """

    kf: float = 0.047
    valley_factor: float = 1.0
    polygon_edge_factor: float = 1.0
    spoke_factor: float = 10.0
    mountain_factor: float = 0.0
    modulus_factor: float = 1e5
    material_area: float = 1.0
    mountain_area: float = 0.01
    fold_limits: tuple = field(default=(np.radians(5.0), np.radians(355.0)))
    bar_law: str = "ogden"
    duplicate_shared_edges: bool = True
    hinge_angle: str = "merlin2"

    def __post_init__(self):
        as_choice("bar_law", self.bar_law, BAR_LAWS)
        as_choice("hinge_angle", self.hinge_angle, HINGE_ANGLES)
        limits = as_float_array("fold_limits", self.fold_limits)
        if limits.shape != (2,):
            raise ValueError(f"fold_limits = {show(self.fold_limits)} is invalid: must be two "
                             "angles [rad]")
        for f in fields(self):  # types here; ranges in the core
            if f.name not in ("fold_limits", "bar_law", "duplicate_shared_edges",
                              "hinge_angle"):
                as_real(f.name, getattr(self, f.name))
        as_bool("duplicate_shared_edges", self.duplicate_shared_edges)

    @property
    def mountain_creases(self) -> str:
        """``"cut"`` or ``"intact"`` (:data:`MOUNTAIN_CREASES`), or ``"custom"`` for other
        values of ``mountain_factor`` and ``mountain_area``."""
        for name, values in MOUNTAIN_CREASES.items():
            if all(getattr(self, key) == value for key, value in values.items()):
                return name
        return "custom"

    def with_mountain_creases(self, kind: str) -> "SpecimenParameters":
        """A copy with the mountain creases ``"cut"`` or ``"intact"`` (:data:`MOUNTAIN_CREASES`)."""
        as_choice("mountain creases", kind, MOUNTAIN_CREASES)
        return replace(self, **MOUNTAIN_CREASES[kind])

    def as_dict(self) -> dict:
        """Every parameter as plain Python values (JSON-ready: ``fold_limits`` a list of two
        floats [rad]); :meth:`from_dict` reads it back."""
        out = {}
        for f in fields(self):
            value = getattr(self, f.name)
            if f.name == "fold_limits":
                value = [float(v) for v in value]
            elif f.name == "duplicate_shared_edges":
                value = bool(value)
            elif f.name not in ("bar_law", "hinge_angle"):
                value = float(value)
            out[f.name] = value
        return out

    @classmethod
    def from_dict(cls, values: dict) -> "SpecimenParameters":
        """The parameters of :meth:`as_dict`'s output (missing keys take the defaults)."""
        if not isinstance(values, dict):
            raise ValueError(f"parameters = {show(values)} is invalid: must be a dict")
        known = {f.name for f in fields(cls)}
        unknown = sorted(set(values) - known)
        if unknown:
            raise ValueError(f"unknown specimen parameter {unknown[0]!r}: must be one of "
                             f"{', '.join(sorted(known))}")
        values = dict(values)
        if "fold_limits" in values:
            values["fold_limits"] = tuple(values["fold_limits"])
        return cls(**values)

    def to_core(self):
        """The C++ parameters object (values are range-checked there)."""
        p = _core.model.SpecimenParameters()
        for f in fields(self):
            value = getattr(self, f.name)
            if f.name == "fold_limits":
                p.theta1, p.theta2 = (float(v) for v in value)
            elif f.name == "bar_law":
                p.bar_law = BAR_LAWS[value]
            elif f.name == "duplicate_shared_edges":
                p.duplicate_shared_edges = bool(value)
            elif f.name == "hinge_angle":
                p.hinge_angle = getattr(_core.elements.DihedralForm, value)
            else:
                setattr(p, f.name, float(value))
        return p


def alternating_chirality(cells: int) -> list:
    """``[+1, -1, +1, ...]``: modules of two cells whose twists cancel."""
    return [1 if i % 2 == 0 else -1 for i in range(cells)]


@dataclass(frozen=True)
class KreslingSpecimen:
    """A Kresling stack and its model.

    Attributes
    ----------
    design : Design
    states, chirality : tuple of int
        Per cell, base first.
    model : kresling.model.Model
        Nodes ``k (n+1) + j`` for perimeter vertex ``j`` of level ``k``, ``k (n+1) + n`` for
        its centre.
    bar_family, hinge_family : ndarray of str
        Element families (:data:`EDGE_FAMILIES`).
    level_height, level_angle : ndarray, shape (cells + 1,)
        z [mm] and twist angle [rad] of each level.
    """

    design: Design
    states: tuple
    chirality: tuple
    parameters: SpecimenParameters
    model: Model
    bar_family: np.ndarray
    hinge_family: np.ndarray
    level_height: np.ndarray
    level_angle: np.ndarray

    @property
    def cells(self) -> int:
        return len(self.states)

    def node(self, level: int, vertex: int) -> int:
        """Node index of perimeter ``vertex`` (0..n-1) of ``level`` (0..cells)."""
        n = self.design.n
        if not (0 <= level <= self.cells and 0 <= vertex < n):
            raise ValueError(f"node({level}, {vertex}): level must be in [0, {self.cells}] and "
                             f"vertex in [0, {n})")
        return level * (n + 1) + vertex

    def centre(self, level: int) -> int:
        """Node index of the centre of ``level``."""
        if not 0 <= level <= self.cells:
            raise ValueError(f"centre({level}): level must be in [0, {self.cells}]")
        return level * (self.design.n + 1) + self.design.n

    def level_nodes(self, level: int) -> np.ndarray:
        """The ``n + 1`` nodes of ``level`` (perimeter, then centre)."""
        return np.arange(self.design.n + 1) + level * (self.design.n + 1) if 0 <= level <= self.cells \
            else self.centre(level)


def kresling_specimen(design: Design, states, chirality=None, parameters=None,
                      fixed=None) -> KreslingSpecimen:
    """Build a stack of generalized Kresling cells.

    Parameters
    ----------
    design : Design
        The cell design (its own chirality is ignored: ``chirality`` sets each cell's).
    states : sequence of {0, 1, "contracted", "extended"}
        State of each cell, base first.
    chirality : sequence of {+1, -1}, optional
        Handedness of each cell; default alternating ``+1, -1, ...`` (modules).
    parameters : SpecimenParameters, optional
        Stiffness assignment (default: the thesis's).
    fixed : array_like of bool, shape (N, 3), optional
        Supports.

    Returns
    -------
    KreslingSpecimen

    Raises
    ------
    ValueError
        For an empty state list, a chirality list of another length, or bad entries.

    Examples
    --------
    >>> from kresling import Design
    >>> s = kresling_specimen(Design(10, 0.9, 15), ["extended"] * 2)
    >>> round(float(s.level_height[-1]), 3)   # the extended module
    111.639
    """
    design = as_design(design)
    states = tuple(state_index(s) for s in as_list("states", states, "states, one per cell"))
    if chirality is None:
        chirality = alternating_chirality(len(states))
    chirality = tuple(as_integer(f"chirality[{i}]", c) for i, c in
                      enumerate(as_list("chirality", chirality, "+1 or -1, one per cell")))
    parameters = parameters or SpecimenParameters()
    if not isinstance(parameters, SpecimenParameters):
        raise ValueError(f"parameters = {show(parameters)} is invalid: must be a "
                         "SpecimenParameters")
    num_nodes = (len(states) + 1) * (design.n + 1)
    if fixed is None:
        mask = np.zeros(0, dtype=np.uint8)  # the core's default: nothing held (no allocation
    else:                                   # here before it checks the specimen's size)
        mask = as_mask("fixed", fixed)
        if mask.shape != (num_nodes, 3):
            raise ValueError(f"fixed has shape {mask.shape}: must be ({num_nodes}, 3)")
        mask = mask.astype(np.uint8).ravel()
    core = _core.model.build_kresling_specimen(
        design._core, list(states), list(chirality), parameters.to_core(), mask.tolist())
    return specimen_from_core(core, design, states, chirality, parameters)


def specimen_from_core(core, design: Design, states, chirality,
                       parameters: SpecimenParameters) -> KreslingSpecimen:
    """A :class:`KreslingSpecimen` from the core's (``kresling._core.model.KreslingSpecimen``,
    built by the core for ``design``, ``states``, ``chirality`` and ``parameters``): how a
    test's own set-up reaches Python (``kresling.analyses.paths``)."""
    names = np.array(EDGE_FAMILIES)
    return KreslingSpecimen(
        design=design, states=tuple(states), chirality=tuple(chirality), parameters=parameters,
        model=Model._from_core(core.model),
        bar_family=names[np.asarray(core.bar_family, dtype=int)],
        hinge_family=names[np.asarray(core.hinge_family, dtype=int)],
        level_height=np.asarray(core.level_height),
        level_angle=np.asarray(core.level_angle))
