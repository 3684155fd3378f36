"""The constitutive laws of bars and hinges, by name: the codes the C++ core takes.

Both the element kernels (:mod:`kresling.elements`) and the model (:class:`kresling.Model`)
name their laws through these tables, so they live below both. The formulation of each law
is in docs/model.md, 'Bars' and 'Spring laws'.
"""

from __future__ import annotations

import numpy as np

__all__ = ["BAR_LAWS", "SPRING_LAWS", "FOLD_LIMITS"]

#: Bar laws by name (docs/model.md, 'Bars'): "ogden" is MERLIN2's Ogden law with exponents
#: (5, 1).
BAR_LAWS = {"linear": 0, "ogden": 1}
#: Spring laws by name (docs/model.md, 'Spring laws'): "enhanced_linear" (MERLIN2's, with
#: limits), "linear", "super_linear_bend" (``M ~ |dtheta|^(4/3)``).
SPRING_LAWS = {"linear": 0, "enhanced_linear": 1, "super_linear_bend": 2}

#: MERLIN2's default limits of the enhanced linear law for fold hinges [rad] (5 and 355 deg).
FOLD_LIMITS = (np.radians(5.0), np.radians(355.0))
