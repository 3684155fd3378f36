"""The reproduction report (``kresling reproduce``): each part of the package contributes a
:class:`Section` of checks against the thesis, figures and tables."""

from kresling.report.section import Check, Section

__all__ = ["Check", "Section"]
