"""Element properties of a crease pattern: from a sheet's material ("auto") or given
directly ("manual"). See docs/model.md, 'Material calibration'.

>>> m = SheetMaterial(youngs_modulus=5e3, poisson_ratio=0.35, thickness=0.127)
>>> round(m.bending_rigidity, 6)
0.972642
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kresling import _core
from kresling._validation import as_finite_real, as_positive_real, as_real

__all__ = ["SheetMaterial", "ManualProperties", "SheetStiffness", "calibrate_sheet"]


@dataclass(frozen=True)
class SheetMaterial:
    """A thin elastic sheet: the "auto" calibration (Filipov et al. 2017, as in MERLIN2).

    Parameters
    ----------
    youngs_modulus : float
        E [N/mm^2]. Bars follow the Ogden law with C0 = E.
    poisson_ratio : float
        nu, in (-1, 0.5].
    thickness : float
        t [mm].
    length_scale : float, optional
        Ls [mm] in the fold stiffness D / Ls; default twice the mean fold length.
    """

    youngs_modulus: float
    poisson_ratio: float
    thickness: float
    length_scale: float | None = None

    def __post_init__(self):
        object.__setattr__(self, "youngs_modulus",
                           as_positive_real("youngs_modulus", self.youngs_modulus))
        nu = as_real("poisson_ratio", self.poisson_ratio)
        if not -1.0 < nu <= 0.5:
            raise ValueError(f"poisson_ratio = {nu!r} is invalid: must be in (-1, 0.5]")
        object.__setattr__(self, "poisson_ratio", nu)
        object.__setattr__(self, "thickness", as_positive_real("thickness", self.thickness))
        if self.length_scale is not None:
            object.__setattr__(self, "length_scale",
                               as_positive_real("length_scale", self.length_scale))

    @property
    def bending_rigidity(self) -> float:
        """Plate bending rigidity D = E t^3 / (12 (1 - nu^2)) [N*mm]."""
        nu = self.poisson_ratio
        return self.youngs_modulus * self.thickness ** 3 / (12.0 * (1.0 - nu * nu))


@dataclass(frozen=True)
class ManualProperties:
    """Element properties given directly: the "manual" calibration.

    Each value is a scalar for every element of its kind or an array in the order of
    :class:`~kresling.model.panel_elements.PanelElements` (``bars``, ``folds``, ``bends``).

    Parameters
    ----------
    bar_modulus : float
        Bar modulus C0 [N/mm^2]; the axial stiffness is C0 times the area.
    bar_area : float or array_like, shape (B,)
        Bar cross-sections [mm^2].
    fold_stiffness, bend_stiffness : float or array_like, optional
        Rotational stiffness per unit hinge length [N*mm/rad/mm]; needed when the pattern
        has hinges of that kind.
    face_stiffness : float, optional
        Stiffness of a spring on every interior angle of every triangle of the model
        [N*mm/rad^2]: the panels' in-plane shear stiffness beside their bars, as Origami
        Simulator gives its faces (energy ``k/2 (alpha - alpha0)^2`` per corner; the
        ``face_angles`` element family). None or 0: no such springs.
    """

    bar_modulus: float
    bar_area: object
    fold_stiffness: object = None
    bend_stiffness: object = None
    face_stiffness: object = None

    def __post_init__(self):
        object.__setattr__(self, "bar_modulus", as_positive_real("bar_modulus", self.bar_modulus))
        if self.face_stiffness is not None:
            k = as_finite_real("face_stiffness", self.face_stiffness)
            if k < 0.0:
                raise ValueError(f"face_stiffness = {self.face_stiffness!r} is invalid: must be "
                                 "a finite number >= 0 [N*mm/rad^2]")
            object.__setattr__(self, "face_stiffness", k)


@dataclass(frozen=True)
class SheetStiffness:
    """Properties the calibration gives, in :class:`PanelElements` order.

    Attributes
    ----------
    bar_area : ndarray, shape (B,)
        [mm^2]
    fold_stiffness : ndarray, shape (F,)
        Per unit length [N*mm/rad/mm].
    bend_stiffness : ndarray, shape (Nb,)
        Per unit length [N*mm/rad/mm].
    length_scale : float
        The Ls used [mm] (nan without folds).
    """

    bar_area: np.ndarray
    fold_stiffness: np.ndarray
    bend_stiffness: np.ndarray
    length_scale: float


def calibrate_sheet(elements, material: SheetMaterial, *, merlin2_compat=False) -> SheetStiffness:
    """Bar areas and hinge stiffnesses of an N5B8 model from the sheet's material.

    Parameters
    ----------
    elements : kresling.model.PanelElements
        Built with ``split="N5B8"``.
    material : SheetMaterial
    merlin2_compat : bool, default False
        Pair values with elements as MERLIN2 v1.1 does. Where a panel's vertices are not
        listed in increasing order it gives spoke values to the spokes ranked by vertex index
        and, for a quad whose four sides are all folds, side areas to the sides ranked by
        their (lower, higher) vertex pair; the formulas themselves are the same.
        Reproduces MERLIN2's numbers exactly; off by default.

    Returns
    -------
    SheetStiffness
    """
    if not isinstance(material, SheetMaterial):
        raise ValueError(f"material = {material!r} is invalid: must be a SheetMaterial")
    core = _core.model.SheetMaterial()
    core.youngs_modulus = material.youngs_modulus
    core.poisson_ratio = material.poisson_ratio
    core.thickness = material.thickness
    core.length_scale = 0.0 if material.length_scale is None else material.length_scale
    s = _core.model.calibrate_sheet(elements._core, [list(p) for p in elements.panels], core,
                                    bool(merlin2_compat))
    length_scale = s.length_scale if len(elements.folds) else math.nan
    return SheetStiffness(np.asarray(s.bar_area), np.asarray(s.fold_stiffness),
                          np.asarray(s.bend_stiffness), length_scale)
