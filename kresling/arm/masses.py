"""Masses of the thesis's arm from the materials it names (section 4.1, Table 4).

Units are mm, N and s: masses in tonnes (1 g = 1e-6 t). The cells are of the thesis's PET
laminate (:mod:`kresling.analyses.laminate`); beyond them:

- **tendon guides**: discs cut from the 0.25 mm PET sheet (thesis, section 4.1), PET at
  1.38 g/cm^3 (a handbook value); their radius is not given: the arm model's
  ``guide_radius`` (40 mm by default) is taken;
- **tendons**: Power Pro Spectra fibre braid, 50 lb (thesis, Table 4): 0.36 mm across (the
  line's listed diameter) of UHMWPE at 0.97 g/cm^3 (a handbook value), 0.099 mg/mm;
- **measured**: the three-module skeleton with its guides weighs 56.3 g (thesis, section
  4.1). The materials give less (the model has one polygon per level, where the built
  cells each have their own, and no adhesive joints); ``measured_skeleton=True`` scales
  the cells and guides up to the measured mass.

The base guide is fixed, so its mass carries no load; it is counted in the skeleton's mass.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kresling._validation import as_bool
from kresling.analyses.laminate import LAMINATE_AREAL_DENSITY
from kresling.model.masses import PET_DENSITY, lumped_masses, specimen_triangles

__all__ = ["GUIDE_THICKNESS", "TENDON_LINEAR_DENSITY", "SKELETON_MASS", "ArmMasses",
           "arm_masses"]

#: The tendon guides are cut from the 0.25 mm PET sheet [mm].
GUIDE_THICKNESS = 0.25
#: Power Pro Spectra 50 lb: 0.36 mm across, UHMWPE of 0.97 g/cm^3 [t/mm].
TENDON_LINEAR_DENSITY = 0.97e-9 * math.pi * 0.18 ** 2
#: The three-module skeleton with its tendon guides, as weighed in the thesis [t].
SKELETON_MASS = 56.3e-6


@dataclass(frozen=True)
class ArmMasses:
    """The arm's node masses and what they are made of.

    Attributes
    ----------
    node : ndarray, shape (N,)
        Mass of every node of ``arm.model`` [t].
    cells, guides, tendons : float
        Mass of the cells' laminate (side triangles and polygons), of the guide discs and
        of the tendons' length inside the arm [t], before any scaling.
    scale : float
        Factor on the cells and guides (1, or what makes a three-module skeleton weigh
        :data:`SKELETON_MASS`).
    """

    node: np.ndarray
    cells: float
    guides: float
    tendons: float
    scale: float

    @property
    def total(self) -> float:
        """Sum of the node masses [t]."""
        return float(self.node.sum())

    @property
    def skeleton(self) -> float:
        """Cells and guides, as scaled [t] (the thesis's 56.3 g is this for three modules)."""
        return self.scale * (self.cells + self.guides)


def _cell_triangles(arm) -> np.ndarray:
    from kresling.model import kresling_specimen

    states = [int(c) for c in arm.configuration for _ in range(2)]
    cells = kresling_specimen(arm.design, states, chirality=[1, -1] * arm.modules)
    return specimen_triangles(cells)


def _guide_masses(arm) -> np.ndarray:
    """Each guide disc (radius ``guide_radius``): the part inside the cell's polygon shared
    like the polygon (a third to the centre, the rest by the perimeter's triangles), the
    ring outside it shared equally by the guide's three holes."""
    n, out = arm.n, np.zeros(arm.model.num_nodes)
    nodes = arm.model.nodes
    areal = GUIDE_THICKNESS * PET_DENSITY
    disc = math.pi * arm.parameters.guide_radius ** 2
    for g in range(arm.modules + 1):
        ring = [arm.node(2 * g, j) for j in range(n)]
        centre = arm.node(2 * g, n)
        fan = [[ring[j], ring[(j + 1) % n], centre] for j in range(n)]
        polygon = lumped_masses((nodes, fan), GUIDE_THICKNESS, PET_DENSITY)
        out += polygon
        outside = max(disc * areal - polygon.sum(), 0.0)
        out[arm.holes[g]] += outside / 3
    return out


def _tendon_masses(arm) -> np.ndarray:
    """Each tendon's segment between two holes, half to each hole."""
    out = np.zeros(arm.model.num_nodes)
    x = arm.model.nodes
    for t in range(3):
        holes = arm.holes[:, t]
        lengths = np.linalg.norm(np.diff(x[holes], axis=0), axis=1) * TENDON_LINEAR_DENSITY
        out[holes[:-1]] += lengths / 2
        out[holes[1:]] += lengths / 2
    return out


def arm_masses(arm, *, measured_skeleton=False) -> ArmMasses:
    """Node masses of the arm from the thesis's materials (see the module's table) [t].

    Parameters
    ----------
    arm : kresling.arm.Arm
    measured_skeleton : bool, default False
        Scale the cells and guides so that the skeleton weighs the thesis's measured
        56.3 g per three modules (:data:`SKELETON_MASS`): the model leaves out the cells'
        doubled polygons, the adhesive joints and anything else the materials alone miss.

    Returns
    -------
    ArmMasses

    Examples
    --------
    >>> from kresling.arm import build_arm
    >>> m = arm_masses(build_arm("111"))
    >>> round(m.cells * 1e6, 1), round(m.guides * 1e6, 2), round(m.tendons * 1e6, 3)   # g
    (37.5, 6.94, 0.099)
    """
    measured_skeleton = as_bool("measured_skeleton", measured_skeleton)
    count = arm.model.num_nodes
    cells = np.zeros(count)
    triangles = _cell_triangles(arm)
    cells[:triangles.max() + 1] = lumped_masses(
        (arm.model.nodes[:triangles.max() + 1], triangles), 1.0, LAMINATE_AREAL_DENSITY)
    guides, tendons = _guide_masses(arm), _tendon_masses(arm)
    skeleton = cells.sum() + guides.sum()
    scale = SKELETON_MASS * arm.modules / 3 / skeleton if measured_skeleton else 1.0
    return ArmMasses(scale * (cells + guides) + tendons, float(cells.sum()),
                     float(guides.sum()), float(tendons.sum()), float(scale))
