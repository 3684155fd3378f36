"""A bar-and-hinge :class:`Model` of any crease pattern, built as MERLIN2 builds it.

Faces are panels. Edges between panels carry hinges by their assignment, read in one of two
conventions (:mod:`kresling.model.crease_kinds`): FOLD's M, V, F and U are fold hinges of
their family; J (join) edges, and Origami Simulator's facet creases F, carry bend hinges as
the edges added inside panels do; a cut (C) separates its faces (a bar remains where they
still share both ends); Origami Simulator's undriven U keeps a bar and no hinge. Each
family has its own law and may have its own stiffness. See docs/model.md, 'Topology' and
'Material calibration', and docs/patterns.md.

>>> import numpy as np
>>> sheet = (np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0]], float),
...          [[0, 1, 4, 3], [1, 2, 5, 4]])
>>> pm = build_pattern_model(sheet, material=SheetMaterial(1e3, 0.3, 0.25))
>>> pm.model
Model(8 nodes, 15 bars, 9 hinges, 0 supported DOFs)
>>> sorted(set(pm.hinge_family))
['bend', 'unassigned']
"""

from __future__ import annotations

from dataclasses import dataclass, field
from types import MappingProxyType

import numpy as np

from kresling import _core
from kresling.io import separate_cuts
from kresling.model.calibration import (ManualProperties, SheetMaterial, SheetStiffness,
                                        calibrate_sheet)
from kresling.model.crease_kinds import CONVENTIONS, FAMILY_OF_FOLD, FOLD_FAMILIES, crease_kind
from kresling.model.crease_laws import CreaseLaws, HingeLaw
from kresling.model.members import Members  # noqa: F401 (documented with the builder)
from kresling.model.model import Model
from kresling.model.panel_elements import PanelElements, build_panel_elements
from kresling.model.rest_angles import check_rest_angles

__all__ = ["HingeLaw", "CreaseLaws", "PatternModel", "build_pattern_model", "FOLD_FAMILIES",
           "HINGE_FAMILIES", "CONVENTIONS", "MEMBER"]

#: FOLD edge assignments that carry a fold hinge (in FOLD's convention), and the family
#: each gives.
FAMILY_OF_ASSIGNMENT = FAMILY_OF_FOLD
#: Every hinge family: the fold families and "bend" (hinges inside panels and on joins).
HINGE_FAMILIES = FOLD_FAMILIES + ("bend",)
#: The family of the bars and hinges given one by one (:class:`Members`).
MEMBER = "member"


@dataclass(frozen=True)
class PatternModel:
    """A crease pattern's bar-and-hinge model and where each element came from.

    Attributes
    ----------
    model : Model
        Bars in :class:`PanelElements` order (bend axes, fold axes, boundary); hinges: the
        fold hinges (cut ones left out), then the bend hinges.
    elements : PanelElements
    hinge_family : tuple of str, length H
        Family of each model hinge (:data:`HINGE_FAMILIES`, or ``"member"`` for the hinges
        given one by one, which follow the pattern's).
    hinge_element : ndarray of int, shape (H,)
        Index of each model hinge in ``elements.folds`` (fold hinges, and bend hinges on
        joins: see ``hinge_on_edge``) or ``elements.bends`` (bend hinges inside panels);
        -1 for a member hinge.
    bar_family : tuple of str, length B
        "bend", "fold", "cut" (a bar on a cut edge), "boundary" or "member".
    stiffness : SheetStiffness or None
        The calibration, for a sheet material.
    """

    model: Model
    elements: PanelElements
    hinge_family: tuple
    hinge_element: np.ndarray
    bar_family: tuple
    stiffness: SheetStiffness | None
    #: True for each hinge on an edge between panels (fold hinges and joins), False for the
    #: bend hinges inside panels.
    hinge_on_edge: np.ndarray = None

    @property
    def num_vertices(self) -> int:
        """Vertices of the pattern; centre nodes follow them."""
        return self.elements.num_vertices

    def family_mask(self, family: str) -> np.ndarray:
        """Boolean mask (H,) of the model's hinges in ``family``."""
        if family not in HINGE_FAMILIES:
            raise ValueError(f"family = {family!r} is invalid: must be one of "
                             f"{list(HINGE_FAMILIES)}")
        return np.array([f == family for f in self.hinge_family], dtype=bool)

    def with_supports(self, fixed) -> "PatternModel":
        """The same model with supports ``fixed`` (bool, shape (N, 3), N with centres)."""
        return PatternModel(self.model.replace(fixed=fixed), self.elements, self.hinge_family,
                            self.hinge_element, self.bar_family, self.stiffness,
                            self.hinge_on_edge)


def _per_element(name, value, count, needed=None):
    """One value per element; ``needed`` elements (default all) make a missing one an
    error."""
    if value is None:
        needed = count if needed is None else needed
        if needed:
            raise ValueError(f"{name} is missing: the pattern has {needed} such elements")
        return np.zeros(count)
    array = np.asarray(value, dtype=float)
    if array.ndim == 0:
        array = np.full(count, float(array))
    if array.shape != (count,):
        raise ValueError(f"{name} has shape {array.shape}: must be a number or ({count},)")
    if not (np.isfinite(array) & (array >= 0)).all():
        raise ValueError(f"{name} has a negative or non-finite entry")
    return array


def _fold_assignments(pattern, elements: PanelElements):
    """The assignment of each fold element's axis ("U" without assignments)."""
    edges = getattr(pattern, "edges", None)
    assignment = getattr(pattern, "edges_assignment", None)
    lookup = {}
    if edges is not None and assignment is not None:
        for k, ((a, b), letter) in enumerate(zip(np.asarray(edges).tolist(), assignment)):
            lookup[(min(a, b), max(a, b))] = (k, letter)
    source = getattr(pattern, "source", "") or "pattern"
    out = []
    for a, b, _, _ in elements.folds.tolist():
        k, letter = lookup.get((a, b), (None, "U"))
        if letter == "B":
            raise ValueError(f"{source}: edge {k} ({a}, {b}) is assigned 'B' (boundary) but "
                             "joins two panels: assign it M, V, F, U, C or J")
        out.append(letter)
    return out


def _join_stiffness(elements, joins, material, calibrated):
    """Bend stiffness [N*mm/rad per mm] of the hinges on join edges (indices into folds).

    A join is a modelling edge across one effective panel, so it gets the panel's bending
    stiffness: for a sheet, the bend formula of docs/model.md with the join as the
    diagonal, D (L / t)^(1/3) / L (Filipov et al. 2017); with manual properties, the
    bend_stiffness when it is one number.
    """
    if not joins:
        return np.zeros(0)
    nodes = elements.nodes
    axes = elements.folds[joins][:, :2]
    length = np.linalg.norm(nodes[axes[:, 0]] - nodes[axes[:, 1]], axis=1)
    if calibrated:
        t = material.thickness
        return material.bending_rigidity * np.cbrt(length / t) / length
    value = material.bend_stiffness
    if value is None or np.ndim(value) != 0:
        raise ValueError(f"bend_stiffness {'is missing' if value is None else 'is an array'}: "
                         f"the pattern's {len(joins)} join (J) or facet edges carry bend "
                         "hinges, so bend_stiffness must be one number (or set [laws] "
                         "bend_stiffness)")
    return np.full(len(joins), float(value))


def _edge_hinges(kinds, assignments, elements, fold_k, join_k, laws, calibrated):
    """Hinges on edges between panels: (hinge, family, element, stiffness, law, limits)."""
    rows, joined = [], iter(join_k)
    for index, (kind, letter) in enumerate(zip(kinds, assignments)):
        if kind == "fold":
            family = FAMILY_OF_FOLD[letter]
            stiffness = fold_k[index]
        elif kind == "bend":
            family, stiffness = "bend", next(joined)
        else:                                   # cut or free: a bar, no hinge
            continue
        rule = laws.for_family(family, calibrated)
        rows.append((elements.folds[index], family, index,
                     stiffness if rule.stiffness is None else rule.stiffness, rule.law,
                     np.radians(rule.limits_deg)))
    return rows


def _material_values(material, elements, split, merlin2_compat, folds_needed):
    """Bar areas, fold and bend stiffnesses, bar modulus and the calibration (or None);
    ``folds_needed`` fold elements carry fold hinges."""
    nb, nf = len(elements.bends), len(elements.folds)
    if isinstance(material, SheetMaterial):
        if split != "N5B8":
            raise ValueError(f"split = {split!r} is invalid with a SheetMaterial: the sheet "
                             "calibration needs 'N5B8' (use ManualProperties with 'N4B5')")
        s = calibrate_sheet(elements, material, merlin2_compat=merlin2_compat)
        return s.bar_area, s.fold_stiffness, s.bend_stiffness, material.youngs_modulus, s
    if isinstance(material, ManualProperties):
        bar_area = _per_element("bar_area", material.bar_area, len(elements.bars))
        if not (bar_area > 0).all():
            raise ValueError("bar_area has an entry <= 0: every bar needs an area > 0")
        fold_k = _per_element("fold_stiffness", material.fold_stiffness, nf, folds_needed)
        bend_k = _per_element("bend_stiffness", material.bend_stiffness, nb)
        return bar_area, fold_k, bend_k, material.bar_modulus, None
    raise ValueError(f"material = {material!r} is invalid: must be a SheetMaterial "
                     "(auto calibration) or ManualProperties (manual)")


def _vertices_and_panels(pattern):
    if hasattr(pattern, "vertices") and hasattr(pattern, "faces"):
        return pattern.vertices, pattern.faces
    try:
        vertices, panels = pattern
    except (TypeError, ValueError):
        raise ValueError("pattern must be a kresling.io.Pattern or a (vertices, panels) "
                         "pair") from None
    return vertices, panels


def build_pattern_model(pattern, *, material, split="N5B8", centre="merlin2", laws=None,
                        fixed=None, merlin2_compat=False, assignments="fold",
                        members=None) -> PatternModel:
    """Build the bar-and-hinge model of a crease pattern.

    Parameters
    ----------
    pattern : kresling.io.Pattern or (vertices, panels)
        Vertices (N, 3) [mm] and panels (vertex indices around each face). A Pattern's edge
        assignments set the hinges (see ``assignments``); without them every fold is
        "unassigned". A Pattern's cut (C) edges are separated first
        (:func:`kresling.io.separate_cuts`: copies of vertices follow the vertices).
    material : SheetMaterial or ManualProperties
        "auto" calibration from the sheet (needs ``split="N5B8"``), or given properties.
        Join (J) edges, and Origami Simulator's facet (F) edges, get bend hinges: with a
        sheet, the bend formula with the edge as the panel's diagonal; with manual
        properties, ``bend_stiffness`` (one number).
    split : {"N5B8", "N4B5"}
        See :func:`build_panel_elements`.
    centre : {"merlin2", "mean"}
        Where N5B8 puts centre nodes (see :func:`build_panel_elements`).
    laws : CreaseLaws, optional
        Bar law and hinge laws per family (MERLIN2's defaults).
    fixed : array_like of bool, shape (N + C, 3), optional
        Supported DOFs of every node, centre nodes included.
    merlin2_compat : bool, default False
        Build the model exactly as MERLIN2 v1.1 does: its pairing of calibrated values
        with elements (see :func:`calibrate_sheet`) and its rest angles (computed with
        Octave's scaled 2-norm; they can differ from the exact ones by ~1e-8 rad, which
        the super-linear bend law's tangent feels) and hinge angles (its arccosine, see
        :class:`Model`'s ``hinge_angle``).
    assignments : {"fold", "origami_simulator"}
        The convention of the letters (:mod:`kresling.model.crease_kinds`).
    members : Members, optional
        Bars and hinges given one by one (:mod:`kresling.model.members`), after the
        pattern's own (family ``"member"``); a vertex of no panel that a member bar holds is
        part of the structure. A pattern of no panels is a structure of members alone.

    Returns
    -------
    PatternModel

    Raises
    ------
    ValueError
        For a bad pattern, material, law or array size (messages name the element), or
        hinges folded flat at rest (:func:`~kresling.model.rest_angles.check_rest_angles`).
    """
    if hasattr(pattern, "edges_assignment") and hasattr(pattern, "frames"):
        pattern = separate_cuts(pattern)
    vertices, panels = _vertices_and_panels(pattern)
    laws = CreaseLaws() if laws is None else laws
    if not isinstance(laws, CreaseLaws):
        raise ValueError(f"laws = {laws!r} is invalid: must be a CreaseLaws")
    if assignments not in CONVENTIONS:
        raise ValueError(f"assignments = {assignments!r} is invalid: must be one of "
                         f"{list(CONVENTIONS)}")
    try:
        elements = build_panel_elements(vertices, panels, split=split, centre=centre)
    except ValueError as error:   # a panel of the file: name the file
        source = getattr(pattern, "source", "")
        if not source or str(error).startswith(("split", "centre")):
            raise
        raise ValueError(f"{source}: {error}") from None
    _check_every_vertex_held(pattern, len(vertices), panels, fixed,
                             () if members is None else members.nodes)
    letters = _fold_assignments(pattern, elements)
    kinds = [crease_kind(letter, assignments) for letter in letters]
    bar_area, fold_k, bend_k, bar_modulus, stiffness = _material_values(
        material, elements, split, merlin2_compat, kinds.count("fold"))
    calibrated = stiffness is not None
    joins = [k for k, kind in enumerate(kinds) if kind == "bend"]
    join_k = _join_stiffness(elements, joins, material, calibrated)
    rows = _edge_hinges(kinds, letters, elements, fold_k, join_k, laws, calibrated)
    bend_rule = laws.for_family("bend", calibrated)
    for index in range(len(elements.bends)):
        rows.append((elements.bends[index], "bend", index,
                     bend_k[index] if bend_rule.stiffness is None else bend_rule.stiffness,
                     bend_rule.law, np.radians(bend_rule.limits_deg)))
    on_edge = np.arange(len(rows)) < len(rows) - len(elements.bends)
    hinges, family, element, k, law, limits = (list(column) for column in zip(*rows)) \
        if rows else ([], [], [], [], [], [])
    bar_family = (["bend"] * len(elements.bends)
                  + ["cut" if a == "C" else "fold" for a in letters]
                  + _boundary_families(pattern, elements))
    hinges = np.asarray(hinges, dtype=np.int64).reshape(-1, 4)
    # MERLIN2 computes rest angles with Octave's scaled 2-norm: a flat panel's can be
    # ~1e-8 rad off pi, which changes the super-linear bend tangent at rest (and so its
    # Newton iterations). Compatibility reproduces it, and MERLIN2's arccosine angle in the
    # elements; otherwise the exact angle, at rest and in every state.
    rest = (_core.model.merlin2_rest_angles(elements.nodes, hinges) if merlin2_compat else None)
    model = Model(elements.nodes, elements.bars, hinges, hinge_rest_angle=rest,
                  hinge_angle="merlin2" if merlin2_compat else "exact",
                  bar_modulus=bar_modulus, bar_area=bar_area, bar_law=laws.bar,
                  hinge_stiffness=np.asarray(k, dtype=float), hinge_law=law,
                  hinge_limits=np.asarray(limits, dtype=float).reshape(-1, 2), fixed=fixed,
                  families=_face_angle_family(material, elements))
    check_rest_angles(model.hinge_rest_angle, hinges, family,
                      source=getattr(pattern, "source", "") or "pattern")
    element = np.asarray(element, dtype=np.int64)
    if members is not None and len(members):
        model = members.added_to(model)
        family += [MEMBER] * len(members.hinges)
        element = np.concatenate([element, np.full(len(members.hinges), -1)])
        bar_family += [MEMBER] * len(members.bars)
        on_edge = np.concatenate([on_edge, np.zeros(len(members.hinges), dtype=bool)])
    return PatternModel(model, elements, tuple(family), element, tuple(bar_family), stiffness,
                        on_edge)


def _check_every_vertex_held(pattern, count, panels, fixed, member_nodes=()) -> None:
    """A vertex on no panel and no member bar has no bar: its DOFs have no stiffness unless
    all are supported (the solvers refuse such a node; here the pattern's file is named, and
    the vertex)."""
    on_panel = np.zeros(count, dtype=bool)
    on_panel[[v for panel in panels for v in panel]] = True
    on_panel[[v for v in member_nodes if v < count]] = True
    if on_panel.all():
        return
    held = (np.zeros((count, 3), dtype=bool) if fixed is None
            else np.asarray(fixed, dtype=bool).reshape(-1, 3)[:count])
    loose = np.flatnonzero(~on_panel & ~held.all(axis=1))
    if loose.size:
        source = getattr(pattern, "source", "") or "pattern"
        more = f" (and {loose.size - 1} more)" if loose.size > 1 else ""
        raise ValueError(f"{source}: vertex {loose[0]}{more} is a corner of no panel: no bar "
                         "holds it (an edge of it that bounds no face makes no element); "
                         "remove it from the pattern, make it a panel's corner, or support "
                         "it in x, y and z")


def _face_angle_family(material, elements) -> dict | None:
    """The ``face_angles`` family of a material with a face stiffness: one element per
    triangle of the panels, resting at its flat interior angles."""
    k = getattr(material, "face_stiffness", None)
    if not k:
        return None
    triangles = np.asarray(elements.triangles, dtype=np.int64).reshape(-1, 3)
    return {"face_angles": {
        "nodes": triangles,
        "rest_angle": _core.elements.triangle_angles(np.ascontiguousarray(elements.nodes, dtype=float),
                                                     triangles),
        "stiffness": np.full(len(triangles), float(k))}}


def _boundary_families(pattern, elements) -> list:
    """"cut" for a boundary bar on a cut edge (a side of a separated cut), else
    "boundary"."""
    cut = set()
    if hasattr(pattern, "edges_assignment"):
        cut = {(min(u, v), max(u, v)) for (u, v), a in
               zip(np.asarray(pattern.edges).tolist(), pattern.edges_assignment) if a == "C"}
    return ["cut" if (min(a, b), max(a, b)) in cut else "boundary"
            for a, b in np.asarray(elements.boundary).reshape(-1, 2).tolist()]
