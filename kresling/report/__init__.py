"""The reproduction report (``kresling reproduce``): each part of the package contributes a
:class:`Section` of checks against the thesis, figures and tables; :func:`build_report` runs
the chapters listed in :data:`~kresling.report.chapters.CHAPTERS` and writes
``report.html`` and ``report.json``."""

from kresling.report.section import Check, Section

__all__ = ["Check", "Section", "build_report", "Report", "CHAPTERS", "Chapter"]


def __getattr__(name):
    # The runner and the renderers are imported on first use: the areas import Check and
    # Section from here, and must not pull in the report machinery (or each other) with them.
    if name in ("build_report", "Report"):
        from kresling.report import build

        return getattr(build, name)
    if name in ("CHAPTERS", "Chapter"):
        from kresling.report import chapters

        return getattr(chapters, name)
    raise AttributeError(f"module 'kresling.report' has no attribute {name!r}")
