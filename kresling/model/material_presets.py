"""Materials chosen by name: the ingredients of another simulator, in this model's units.

``"origami_simulator"`` is the material of Origami Simulator (Ghassaei, Demaine and
Gershenfeld, 2018), the browser simulator researchers fold their patterns in first. Its
model (docs/folding.md, 'Folding from flat') scales the sheet to a bounding radius of 1 and
gives every edge a bar of axial stiffness 20 / L0, every crease and facet hinge 0.7 per unit
length, and every corner of every triangle a spring of 0.2 on its interior angle. Expressed
with creases of 1 N mm/rad per mm on the pattern as drawn (radius R mm), the same energy
ratios are bars of EA = 20 / 0.7 N, panels as stiff in bending as the creases in folding and
corner springs of 0.2 R / 0.7 N mm/rad^2: soft bars beside the stiff ones MERLIN2's examples
use (1e5 N/mm^2), so that a pattern folds where its creases ask, stretching a little where
its panels cannot follow exactly. The ratios are independent of the pattern's size.

Its hinges' laws keep their linear range to within half a degree of folded flat (the
enhanced linear law's limits at 0.5 and 359.5 deg), so that creases reach targets of
+-180 deg within a fold's 1 deg tolerance and still never pass through each other's panels
(with the limits at 1 deg, two of the 287 creases of Origami Simulator's Miura-ori, pressed
by their panels, stopped just over 1 deg short of flat).
"""

from __future__ import annotations

import numpy as np

from kresling.model.calibration import ManualProperties

__all__ = ["MATERIAL_PRESETS", "PRESET_LIMITS_DEG", "preset_material"]

#: Origami Simulator's stiffnesses, as its model states them (per bar length, per hinge
#: length, per corner) for a sheet of bounding radius 1.
_AXIAL, _CREASE, _FACET, _FACE = 20.0, 0.7, 0.7, 0.2

#: The named materials and what each is.
MATERIAL_PRESETS = {
    "origami_simulator": "Origami Simulator's bars, creases, facets and corner springs, "
                         "in ratio; creases of 1 N mm/rad per mm",
}
#: The hinges' enhanced linear limits of a preset [deg]: linear to within 0.5 deg of flat.
PRESET_LIMITS_DEG = (0.5, 359.5)


def preset_material(name: str, vertices) -> ManualProperties:
    """The material ``name`` (one of :data:`MATERIAL_PRESETS`) for a pattern.

    Parameters
    ----------
    name : str
    vertices : array_like, shape (N, 3)
        The pattern's vertices [mm]: its bounding radius (about the bounding box's centre)
        scales the corner springs.

    Returns
    -------
    ManualProperties
    """
    if name not in MATERIAL_PRESETS:
        raise ValueError(f"preset = {name!r} is invalid: must be one of "
                         f"{sorted(MATERIAL_PRESETS)}")
    xy = np.asarray(vertices, dtype=float)
    centre = 0.5 * (xy.min(axis=0) + xy.max(axis=0))
    radius = float(np.max(np.linalg.norm(xy - centre, axis=1)))
    return ManualProperties(bar_modulus=_AXIAL / _CREASE, bar_area=1.0, fold_stiffness=1.0,
                            bend_stiffness=_FACET / _CREASE,
                            face_stiffness=_FACE * radius / _CREASE)
