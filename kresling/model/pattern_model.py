"""A bar-and-hinge :class:`Model` of any crease pattern, built as MERLIN2 builds it.

Faces are panels. Edges between panels carry fold hinges whose family follows the
pattern's edge assignment (FOLD's M, V, F, U and J); a cut edge (C) keeps its bar but no
hinge; edges added inside panels carry bend hinges. Each family has its own law and may
have its own stiffness. See docs/model.md, 'Topology' and 'Material calibration'.

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
from kresling.laws import BAR_LAWS, SPRING_LAWS
from kresling.model.calibration import (ManualProperties, SheetMaterial, SheetStiffness,
                                        calibrate_sheet)
from kresling.model.model import Model
from kresling.model.panel_elements import PanelElements, build_panel_elements

__all__ = ["HingeLaw", "CreaseLaws", "PatternModel", "build_pattern_model", "FOLD_FAMILIES",
           "HINGE_FAMILIES"]

#: FOLD edge assignments that carry a fold hinge, and the family each gives.
FAMILY_OF_ASSIGNMENT = MappingProxyType(
    {"M": "mountain", "V": "valley", "F": "flat", "U": "unassigned", "J": "join"})
FOLD_FAMILIES = tuple(FAMILY_OF_ASSIGNMENT.values())
#: Every hinge family: the fold families and "bend" (hinges inside panels).
HINGE_FAMILIES = FOLD_FAMILIES + ("bend",)


@dataclass(frozen=True)
class HingeLaw:
    """The law of a family of hinges.

    Parameters
    ----------
    law : str
        One of ``kresling.laws.SPRING_LAWS``: "enhanced_linear", "linear",
        "super_linear_bend".
    limits_deg : (float, float)
        Limits of the enhanced-linear law's linear range [deg], 0 < theta1 < theta2 < 360.
    stiffness : float, optional
        Stiffness per unit length [N*mm/rad/mm] for every hinge of the family, replacing the
        calibrated (or manual) one.
    """

    law: str = "enhanced_linear"
    limits_deg: tuple = (45.0, 315.0)
    stiffness: float | None = None

    def __post_init__(self):
        if self.law not in SPRING_LAWS:
            raise ValueError(f"law = {self.law!r} is invalid: must be one of {sorted(SPRING_LAWS)}")
        limits = tuple(float(x) for x in np.asarray(self.limits_deg, dtype=float).ravel())
        if len(limits) != 2 or not 0.0 < limits[0] < limits[1] < 360.0:
            raise ValueError(f"limits_deg = {list(self.limits_deg)!r} is invalid: must be two "
                             "angles 0 < theta1 < theta2 < 360 [deg]")
        object.__setattr__(self, "limits_deg", limits)
        if self.stiffness is not None and not (np.isfinite(self.stiffness) and self.stiffness >= 0):
            raise ValueError(f"stiffness = {self.stiffness!r} is invalid: must be a finite "
                             "number >= 0")


@dataclass(frozen=True)
class CreaseLaws:
    """Laws of the bars and of every hinge family.

    Parameters
    ----------
    bar : {"ogden", "linear"}
    fold : HingeLaw
        Every fold family without an entry in ``families``. Default: enhanced-linear with
        limits 45 and 315 deg (MERLIN2's).
    bend : HingeLaw, optional
        Bend hinges. Default: super-linear for a calibrated sheet, enhanced-linear 45/315
        for manual properties (MERLIN2's defaults).
    families : mapping of str to HingeLaw
        Per fold family ("mountain", "valley", "flat", "unassigned", "join") overrides.
    """

    bar: str = "ogden"
    fold: HingeLaw = HingeLaw()
    bend: HingeLaw | None = None
    families: dict = field(default_factory=dict)

    def __post_init__(self):
        if self.bar not in BAR_LAWS:
            raise ValueError(f"bar = {self.bar!r} is invalid: must be one of {sorted(BAR_LAWS)}")
        unknown = sorted(set(self.families) - set(FOLD_FAMILIES))
        if unknown:
            raise ValueError(f"families: {unknown[0]!r} is not a fold family: must be one of "
                             f"{list(FOLD_FAMILIES)}")
        object.__setattr__(self, "families", MappingProxyType(dict(self.families)))

    def for_family(self, family: str, calibrated: bool) -> HingeLaw:
        if family == "bend":
            if self.bend is not None:
                return self.bend
            return HingeLaw("super_linear_bend") if calibrated else HingeLaw()
        return self.families.get(family, self.fold)


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
        Family of each model hinge (:data:`HINGE_FAMILIES`).
    hinge_element : ndarray of int, shape (H,)
        Index of each model hinge in ``elements.folds`` or ``elements.bends``.
    bar_family : tuple of str, length B
        "bend", "fold", "cut" or "boundary".
    stiffness : SheetStiffness or None
        The calibration, for a sheet material.
    """

    model: Model
    elements: PanelElements
    hinge_family: tuple
    hinge_element: np.ndarray
    bar_family: tuple
    stiffness: SheetStiffness | None

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
                            self.hinge_element, self.bar_family, self.stiffness)


def _per_element(name, value, count):
    if value is None:
        if count:
            raise ValueError(f"{name} is missing: the pattern has {count} such elements")
        return np.zeros(0)
    array = np.asarray(value, dtype=float)
    if array.ndim == 0:
        array = np.full(count, float(array))
    if array.shape != (count,):
        raise ValueError(f"{name} has shape {array.shape}: must be a number or ({count},)")
    if not (np.isfinite(array) & (array >= 0)).all():
        raise ValueError(f"{name} has a negative or non-finite entry")
    return array


def _fold_assignments(pattern, elements: PanelElements):
    """The FOLD assignment of each fold hinge's axis ("U" without assignments)."""
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


def build_pattern_model(pattern, *, material, split="N5B8", centre="merlin2", laws=None,
                        fixed=None, merlin2_compat=False) -> PatternModel:
    """Build the bar-and-hinge model of a crease pattern.

    Parameters
    ----------
    pattern : kresling.io.Pattern or (vertices, panels)
        Vertices (N, 3) [mm] and panels (vertex indices around each face). A Pattern's edge
        assignments set the fold families; without them every fold is "unassigned".
    material : SheetMaterial or ManualProperties
        "auto" calibration from the sheet (needs ``split="N5B8"``), or given properties.
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
        the super-linear bend law's tangent feels).

    Returns
    -------
    PatternModel

    Raises
    ------
    ValueError
        For a bad pattern, material, law or array size; messages name the element.
    """
    if hasattr(pattern, "vertices") and hasattr(pattern, "faces"):
        vertices, panels = pattern.vertices, pattern.faces
    else:
        try:
            vertices, panels = pattern
        except (TypeError, ValueError):
            raise ValueError("pattern must be a kresling.io.Pattern or a (vertices, panels) "
                             "pair") from None
    laws = CreaseLaws() if laws is None else laws
    if not isinstance(laws, CreaseLaws):
        raise ValueError(f"laws = {laws!r} is invalid: must be a CreaseLaws")
    elements = build_panel_elements(vertices, panels, split=split, centre=centre)
    assignments = _fold_assignments(pattern, elements)
    nb, nf = len(elements.bends), len(elements.folds)

    calibrated = isinstance(material, SheetMaterial)
    stiffness = None
    if calibrated:
        if split != "N5B8":
            raise ValueError(f"split = {split!r} is invalid with a SheetMaterial: the sheet "
                             "calibration needs 'N5B8' (use ManualProperties with 'N4B5')")
        stiffness = calibrate_sheet(elements, material, merlin2_compat=merlin2_compat)
        bar_area, fold_k, bend_k = (stiffness.bar_area, stiffness.fold_stiffness,
                                    stiffness.bend_stiffness)
        bar_modulus = material.youngs_modulus
    elif isinstance(material, ManualProperties):
        bar_area = _per_element("bar_area", material.bar_area, len(elements.bars))
        if not (bar_area > 0).all():
            raise ValueError("bar_area has an entry <= 0: every bar needs an area > 0")
        fold_k = _per_element("fold_stiffness", material.fold_stiffness, nf)
        bend_k = _per_element("bend_stiffness", material.bend_stiffness, nb)
        bar_modulus = material.bar_modulus
    else:
        raise ValueError(f"material = {material!r} is invalid: must be a SheetMaterial "
                         "(auto calibration) or ManualProperties (manual)")

    hinges, family, element, k, law, limits = [], [], [], [], [], []
    for index, letter in enumerate(assignments):
        if letter == "C":
            continue
        fam = FAMILY_OF_ASSIGNMENT[letter]
        rule = laws.for_family(fam, calibrated)
        hinges.append(elements.folds[index])
        family.append(fam)
        element.append(index)
        k.append(fold_k[index] if rule.stiffness is None else rule.stiffness)
        law.append(rule.law)
        limits.append(np.radians(rule.limits_deg))
    bend_rule = laws.for_family("bend", calibrated)
    for index in range(nb):
        hinges.append(elements.bends[index])
        family.append("bend")
        element.append(index)
        k.append(bend_k[index] if bend_rule.stiffness is None else bend_rule.stiffness)
        law.append(bend_rule.law)
        limits.append(np.radians(bend_rule.limits_deg))

    bar_family = (["bend"] * nb + ["cut" if a == "C" else "fold" for a in assignments]
                  + ["boundary"] * len(elements.boundary))
    hinges = np.asarray(hinges, dtype=np.int64).reshape(-1, 4)
    # MERLIN2 computes rest angles with Octave's scaled 2-norm: a flat panel's can be
    # ~1e-8 rad off pi, which changes the super-linear bend tangent at rest (and so its
    # Newton iterations). Compatibility reproduces it; otherwise the kernel's own angle.
    rest = (_core.model.merlin2_rest_angles(elements.nodes, hinges) if merlin2_compat else None)
    model = Model(elements.nodes, elements.bars, hinges, hinge_rest_angle=rest,
                  bar_modulus=bar_modulus, bar_area=bar_area, bar_law=laws.bar,
                  hinge_stiffness=np.asarray(k, dtype=float), hinge_law=law,
                  hinge_limits=np.asarray(limits, dtype=float).reshape(-1, 2), fixed=fixed)
    return PatternModel(model, elements, tuple(family), np.asarray(element, dtype=np.int64),
                        tuple(bar_family), stiffness)
