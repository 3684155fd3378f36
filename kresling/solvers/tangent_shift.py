"""The tangent's diagonal shift in the model's own stiffness units.

Every solver adds a small shift to the tangent's diagonal so that a mode with no stiffness
(a mechanism) still factorises and shows up as an unbounded correction. MERLIN2 adds
1e-8 N/mm whatever the model. That number is small beside a 100 mm sheet's stiffnesses, but
not beside a micro-scale one's: a 1 um sheet's bars are 1e5 times softer in N/mm, the shift
then holds its softest modes back and Newton, run on a tangent it perturbs, stalls short of
its tolerance. A large flat sheet's long-wave bending modes are as soft relative to its
bars. Here the shift is a fixed fraction of the model's own largest diagonal stiffness, so
that the same pattern drawn at any size factorises the same tangent, up to the units.
"""

from __future__ import annotations

import numpy as np

from kresling.assembly import assemble

__all__ = ["RELATIVE_SHIFT", "MERLIN2_SHIFT", "scale_free_shift"]

#: The shift as a fraction of the largest diagonal entry of the model's tangent at rest:
#: about 100 times the factorisation's own rounding of that entry (eps = 2.2e-16), so it
#: keeps an exactly singular tangent factorisable and stays far below any stiffness a
#: structure resolves. (On a 100 mm sheet with bars of EA = 1e5 N that is ~6e-10 N/mm.)
RELATIVE_SHIFT = 1e-14
#: MERLIN2's shift [N/mm], the solvers' default and the one ``merlin2_compat`` keeps.
MERLIN2_SHIFT = 1e-8


def scale_free_shift(model) -> float:
    """The diagonal shift [N/mm] for ``model``: :data:`RELATIVE_SHIFT` times the largest
    diagonal entry of its tangent at rest (supported DOFs included), or
    :data:`MERLIN2_SHIFT` when that tangent is zero (a model with no stiffness at rest).

    Parameters
    ----------
    model : kresling.model.Model

    Returns
    -------
    float
        The shift [N/mm], for the solvers' ``shift`` argument.
    """
    diagonal = np.abs(assemble(model, shift=0.0).stiffness.diagonal())
    largest = float(diagonal.max()) if diagonal.size else 0.0
    return RELATIVE_SHIFT * largest if largest > 0.0 and np.isfinite(largest) else MERLIN2_SHIFT
