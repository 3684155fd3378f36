"""The thesis's PET laminate: its mass per area, and the node masses of its specimens.

Units are mm, N and s: masses in tonnes (1 g = 1e-6 t), densities in t/mm^3. The thesis
(section 4.1) builds its cells of a laminate of a 0.25 mm PET facet sheet, F9460PC transfer
tape and a 0.05 mm PET hinge sheet; it gives no densities. We take

==================  =================  =================================================
layer               thickness          density
==================  =================  =================================================
facet sheet (PET)   0.25 mm (thesis)   1.38 g/cm^3, a handbook value for PET
hinge sheet (PET)   0.05 mm (thesis)   1.38 g/cm^3
tape F9460PC        0.05 mm            1.0 g/cm^3: the thickness from the tape's
                                       datasheet (the thesis names the tape only), the
                                       density typical of acrylic pressure-sensitive
                                       adhesives
==================  =================  =================================================

so the laminate weighs :data:`LAMINATE_AREAL_DENSITY` = 4.64e-10 t/mm^2 (0.464 g per
1000 mm^2); the material cut away along the creases is left out.
"""

from __future__ import annotations

import numpy as np

from kresling.model.masses import PET_DENSITY, lumped_masses

__all__ = ["TAPE_THICKNESS", "TAPE_DENSITY", "LAMINATE_AREAL_DENSITY", "specimen_masses"]

#: Transfer tape F9460PC: 0.05 mm of acrylic adhesive [mm] (its datasheet).
TAPE_THICKNESS = 0.05
#: Density of an acrylic pressure-sensitive adhesive [t/mm^3] (about 1.0 g/cm^3).
TAPE_DENSITY = 1.0e-9
#: The laminate's mass per area [t/mm^2]: 0.25 + 0.05 mm of PET and the tape.
LAMINATE_AREAL_DENSITY = (0.25 + 0.05) * PET_DENSITY + TAPE_THICKNESS * TAPE_DENSITY


def specimen_masses(specimen) -> np.ndarray:
    """Node masses of a Kresling specimen made of the thesis's laminate [t].

    Parameters
    ----------
    specimen : KreslingSpecimen
        Its side triangles and one polygon per level carry the laminate
        (:func:`kresling.model.masses.lumped_masses`).

    Returns
    -------
    ndarray, shape (N,)

    Examples
    --------
    >>> from kresling import Design
    >>> from kresling.model import kresling_specimen
    >>> cell = kresling_specimen(Design(10, 0.9, 15, 30), ["extended"])
    >>> round(float(specimen_masses(cell).sum()) * 1e6, 2)   # g
    7.26
    """
    return lumped_masses(specimen, 1.0, LAMINATE_AREAL_DENSITY)
