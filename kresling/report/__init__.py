"""The reproduction report (``kresling reproduce``): the top layer of the package, under the
command line only (docs/architecture.md).

Each chapter of the thesis has a section in :mod:`kresling.report.sections` that runs the
library and returns a :class:`Section` of checks against the thesis, with figures and tables;
:func:`build_report` runs the chapters listed in :data:`CHAPTERS` (in thesis order) and
writes ``report.html`` and ``report.json``. No library package imports this one.
"""

from kresling.report.build import Report, build_report
from kresling.report.chapters import CHAPTERS, Chapter
from kresling.report.section import Check, Section

__all__ = ["Check", "Section", "build_report", "Report", "CHAPTERS", "Chapter"]
