"""Build the whole reproduction report: run the chapters, write ``report.json`` and
``report.html``.

From Python (or Jupyter)::

    from kresling.report import build_report
    report = build_report("report", quick=True)     # a few seconds per section
    report                                          # the summary table, in a notebook
    report.html_path

The command line is ``kresling reproduce``.
"""

from __future__ import annotations

import datetime
import logging
import time
from dataclasses import dataclass, field
from pathlib import Path

from kresling import __version__
from kresling.report.chapters import select_chapters
from kresling.report.html_report import summary_table_html, write_html
from kresling.report.json_report import report_document, write_json
from kresling.report.provenance import provenance
from kresling.report.runner import ERROR, NOT_AVAILABLE, run_sections

__all__ = ["Report", "build_report"]

logger = logging.getLogger(__name__)


@dataclass
class Report:
    """The outcome of :func:`build_report`.

    Attributes
    ----------
    runs : list of SectionRun
        One per chapter, in report order.
    out_dir : Path
        The report's directory; ``html_path`` and ``json_path`` are in it.
    quick : bool
    seconds : float
        Wall time of the whole run.
    command : str
        The command that made the report.
    created : str
        When it was made (ISO 8601, local time).
    provenance : dict
        The git commit (``None`` outside a git checkout) and the versions of kresling,
        numpy, scipy and Python, and the platform it ran with.
    """

    runs: list
    out_dir: Path
    quick: bool
    seconds: float = 0.0
    command: str = ""
    created: str = field(default_factory=lambda: datetime.datetime.now().isoformat(
        timespec="seconds"))
    provenance: dict = field(default_factory=provenance)

    @property
    def version(self) -> str:
        """Version of kresling that made the report."""
        return __version__

    @property
    def html_path(self) -> Path:
        """``out_dir / "report.html"``."""
        return self.out_dir / "report.html"

    @property
    def json_path(self) -> Path:
        """``out_dir / "report.json"``."""
        return self.out_dir / "report.json"

    @property
    def errors(self) -> list:
        """Runs of sections that raised."""
        return [run for run in self.runs if run.status == ERROR]

    @property
    def not_available(self) -> list:
        """Runs of chapters whose code does not exist yet."""
        return [run for run in self.runs if run.status == NOT_AVAILABLE]

    @property
    def checks_passed(self) -> int:
        """Checks within tolerance, over every section."""
        return sum(run.checks_passed for run in self.runs)

    @property
    def checks_total(self) -> int:
        """Checks over every section that ran."""
        return sum(len(run.checks) for run in self.runs)

    def document(self) -> dict:
        """The report as the JSON-ready dict written to ``report.json``."""
        return report_document(self)

    def _repr_html_(self) -> str:
        return summary_table_html(self.document())


def build_report(out_dir="report", quick: bool = True, only=None, *, chapters=None,
                 command: str = "") -> Report:
    """Run the report's chapters and write ``report.json`` and ``report.html``.

    Parameters
    ----------
    out_dir : str or Path, default "report"
        Directory of the report (created if missing); each section writes its figures and
        tables into a sub-directory named after its key.
    quick : bool, default True
        Passed to every section: coarser grids and fewer repetitions where the answer does
        not move. ``False`` runs the thesis's full resolution.
    only : sequence of str, optional
        Keys of the chapters to run (see :data:`kresling.report.chapters.CHAPTERS`).
    chapters : sequence of Chapter, optional
        The chapters to choose from (default: :data:`~kresling.report.chapters.CHAPTERS`).
    command : str, optional
        The command that made the report, shown in it.

    Returns
    -------
    Report

    Raises
    ------
    ValueError
        If ``only`` names a chapter that does not exist.
    """
    selected = select_chapters(only, chapters)
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    runs = run_sections(selected, out_dir, quick)
    report = Report(runs, out_dir, quick, time.perf_counter() - start, command)
    document = report.document()
    write_json(document, report.json_path)
    write_html(document, out_dir, report.html_path)
    logger.info("report written to %s", report.html_path)
    return report
