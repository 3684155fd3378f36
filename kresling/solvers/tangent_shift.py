"""The tangent's diagonal shift in proportion to the model's size.

Every solver adds a small shift to the tangent's diagonal so that a mode with no stiffness
(a mechanism) still factorises and shows up as an unbounded correction. MERLIN2 adds
1e-8 N/mm whatever the model. That number is small beside a 100 mm sheet's stiffnesses, but
not beside a micro-scale one's: a similar sheet 1e5 times smaller is 1e5 times softer in
N/mm (a stiffness is a modulus times a length), the shift then holds its softest modes back,
and Newton, run on a tangent it perturbs, stalls short of its tolerance. Here the shift is
MERLIN2's for a model 100 mm across and scales with the model's size, as a similar
structure's stiffnesses do, so that the same pattern drawn at any size factorises the same
tangent, up to the units, and takes the same Newton iterations.
"""

from __future__ import annotations

import numpy as np

__all__ = ["MERLIN2_SHIFT", "REFERENCE_SIZE", "scale_free_shift"]

#: MERLIN2's shift [N/mm], the solvers' default and the one ``merlin2_compat`` keeps.
MERLIN2_SHIFT = 1e-8
#: The size [mm] (the diagonal of the nodes' bounding box) at which the scale-free shift is
#: MERLIN2's.
REFERENCE_SIZE = 100.0


def scale_free_shift(model) -> float:
    """The diagonal shift [N/mm] for ``model``: :data:`MERLIN2_SHIFT` times its size (the
    diagonal of its nodes' bounding box [mm]) over :data:`REFERENCE_SIZE`.

    Parameters
    ----------
    model : kresling.model.Model

    Returns
    -------
    float
        The shift [N/mm], for the solvers' ``shift`` argument (MERLIN2's for a model of no
        extent).
    """
    size = float(np.linalg.norm(np.ptp(np.asarray(model.nodes), axis=0)))
    if not (size > 0.0 and np.isfinite(size)):
        return MERLIN2_SHIFT
    return MERLIN2_SHIFT * size / REFERENCE_SIZE
