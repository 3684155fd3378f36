"""The report's experiments chapter: the fits of thesis sections 3.2-3.3 compared with our
own bar-and-hinge model's curves (``kresling.fits`` stays a leaf: it takes the model curves
as input, and this module supplies them from ``kresling.analyses``)."""

from __future__ import annotations

from kresling.report.section import Section


def reproduce(out_dir, quick: bool = True) -> Section:
    """``kresling.fits.reproduce`` with the model curves of our bending test (5 mm)."""
    from kresling.analyses.table3 import model_curves
    from kresling.fits.reproduce import reproduce as reproduce_fits

    return reproduce_fits(out_dir, quick, model_curves=model_curves())
