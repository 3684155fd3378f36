"""Run the report's sections one by one: time each, keep going when one fails.

Every chapter runs in its own sub-directory of the report. A section that raises is recorded
with its error and traceback; a chapter whose code does not exist yet is recorded as not
available. Progress goes to the ``kresling.report.runner`` logger (one line as a section
starts, one as it ends).
"""

from __future__ import annotations

import logging
import sys
import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path

from kresling.report.chapters import Chapter, SectionNotAvailable
from kresling.report.section import Section

__all__ = ["SectionRun", "run_section", "run_sections", "RAN", "ERROR", "NOT_AVAILABLE"]

logger = logging.getLogger(__name__)

#: Outcomes of running a chapter.
RAN, ERROR, NOT_AVAILABLE = "ran", "error", "not available"


@dataclass
class SectionRun:
    """What running one chapter gave.

    Attributes
    ----------
    chapter : Chapter
    status : {"ran", "error", "not available"}
    section : Section or None
        The section (``None`` unless it ran).
    error : str
        One line: the exception, or why the chapter is not available.
    traceback : str
        The formatted traceback of an error (empty otherwise).
    seconds : float
        Wall time, including the import of the chapter's module.
    """

    chapter: Chapter
    status: str
    section: Section | None = None
    error: str = ""
    traceback: str = ""
    seconds: float = 0.0
    checks: list = field(init=False)

    def __post_init__(self):
        self.checks = list(self.section.checks) if self.section is not None else []

    @property
    def title(self) -> str:
        return self.section.title if self.section is not None else self.chapter.title

    @property
    def checks_passed(self) -> int:
        return sum(bool(check.passed) for check in self.checks)

    @property
    def checks_text(self) -> str:
        """``passed/total``, or ``-`` for a section that did not run."""
        return f"{self.checks_passed}/{len(self.checks)}" if self.status == RAN else "-"

    @property
    def outcome(self) -> str:
        """A few words for the summary: the error, "not yet available", or how many checks
        are outside their tolerance."""
        if self.status == NOT_AVAILABLE:
            return "not yet available"
        if self.status == ERROR:
            return f"error: {self.error}"
        failed = len(self.checks) - self.checks_passed
        if not self.checks:
            return "no checks"
        return f"{failed} outside tolerance" if failed else "all within tolerance"


def run_section(chapter: Chapter, out_dir, quick: bool = True) -> SectionRun:
    """Run one chapter's ``reproduce`` into ``out_dir / chapter.key``.

    Never raises for a failing section (``KeyboardInterrupt`` still stops the run).
    """
    section_dir = Path(out_dir) / chapter.key
    logger.info("%s: started (%s)", chapter.key, chapter.part)
    start = time.perf_counter()
    figures_before = _open_figures()
    try:
        section = chapter.load()(section_dir, quick=quick)
        _check_outputs(section)
    except SectionNotAvailable as error:
        run = SectionRun(chapter, NOT_AVAILABLE, error=str(error))
    except Exception as error:  # a section's failure is reported, the others still run
        run = SectionRun(chapter, ERROR, error=f"{type(error).__name__}: {error}",
                         traceback=traceback.format_exc())
    else:
        run = SectionRun(chapter, RAN, section=section)
    finally:
        _close_figures_opened_since(figures_before)
    run.seconds = time.perf_counter() - start
    if run.section is not None:
        run.section.seconds = run.seconds
    log = logger.error if run.status == ERROR else logger.info
    checks = f"{run.checks_text} checks passed, " if run.status == RAN else ""
    log("%s: %s%s (%.1f s)", chapter.key, checks, run.outcome, run.seconds)
    return run


def run_sections(chapters, out_dir, quick: bool = True) -> list:
    """Run every chapter in order; return a list of :class:`SectionRun`."""
    return [run_section(chapter, out_dir, quick) for chapter in chapters]


def _check_outputs(section) -> None:
    """The section is a :class:`Section` and every file it lists was written."""
    if not isinstance(section, Section):
        raise TypeError(f"reproduce() returned {type(section).__name__}, not a Section")
    for kind, items in (("figure", section.figures), ("table", section.tables)):
        for path, _ in items:
            if not Path(path).is_file():
                raise FileNotFoundError(f"the section lists {kind} {path} but did not write it")


def _open_figures() -> set:
    """Numbers of the open pyplot figures (none if pyplot was never imported)."""
    pyplot = sys.modules.get("matplotlib.pyplot")
    return set(pyplot.get_fignums()) if pyplot is not None else set()


def _close_figures_opened_since(before: set) -> None:
    """Close the pyplot figures a section left open (not the caller's own)."""
    pyplot = sys.modules.get("matplotlib.pyplot")
    if pyplot is not None:
        for number in set(pyplot.get_fignums()) - before:
            pyplot.close(number)
