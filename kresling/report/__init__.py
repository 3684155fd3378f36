"""The reproduction report (``kresling reproduce``).

Each part of the package contributes a :class:`Section` of checks against the thesis, with
figures and tables; :func:`build_report` runs the chapters listed in :data:`CHAPTERS` (in
thesis order) and writes ``report.html`` and ``report.json``.
"""

from kresling.report.build import Report, build_report
from kresling.report.chapters import CHAPTERS, Chapter
from kresling.report.section import Check, Section

__all__ = ["Check", "Section", "build_report", "Report", "CHAPTERS", "Chapter"]
