"""Figures of the report's sections that need more than a few lines: one module per section
that has them (:mod:`.analyses`, :mod:`.sweeps`), beside :mod:`kresling.report.sections`."""
