"""The constitutive laws of bars and hinges, by name: the codes the C++ core takes.

Both the element kernels (:mod:`kresling.elements`) and the model (:class:`kresling.Model`)
name their laws through these tables, so they live below both. The formulation of each law
is in docs/model.md, 'Bars' and 'Spring laws'.
"""

from __future__ import annotations

from types import MappingProxyType

import numpy as np

from kresling import _core

__all__ = ["BAR_LAWS", "SPRING_LAWS", "FOLD_LIMITS", "HINGE_ANGLES"]

#: Bar laws by name (docs/model.md, 'Bars'): "linear", and "ogden", MERLIN2's Ogden law with
#: exponents (5, 1). Names and codes come from the C++ core's law kinds.
BAR_LAWS = MappingProxyType({name: int(kind) for name, kind in
                             _core.elements.BarLawKind.__members__.items()})
#: Spring laws by name (docs/model.md, 'Spring laws'): "enhanced_linear" (MERLIN2's, with
#: limits), "linear", "super_linear_bend" (``M ~ |dtheta|^(4/3)``).
SPRING_LAWS = MappingProxyType({name: int(kind) for name, kind in
                                _core.elements.SpringLawKind.__members__.items()})

#: How a hinge's dihedral angle is computed (docs/model.md, 'Hinges'): "exact" (atan2,
#: accurate to rounding at every angle, flat sheets included) and "merlin2" (MERLIN2's
#: arccosine, up to ~1e-8 rad of rounding near 0 and pi; to reproduce its runs).
HINGE_ANGLES = MappingProxyType({name: int(kind) for name, kind in
                                 _core.elements.DihedralForm.__members__.items()})

#: MERLIN2's default limits of the enhanced linear law for fold hinges [rad] (5 and 355 deg).
FOLD_LIMITS = (np.radians(5.0), np.radians(355.0))
