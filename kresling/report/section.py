"""What one chapter contributes to the reproduction report.

Every chapter (geometry, experiments, bending analyses, sweeps, fabrication, manipulator) has
a function ``reproduce(out_dir: pathlib.Path, quick: bool = True) -> Section`` in its module
of :mod:`kresling.report.sections`; the report collects the sections, renders them to HTML
and times each one.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path


@dataclass(frozen=True)
class Check:
    """One reproduced number beside the value it is compared with.

    Parameters
    ----------
    name : str
        What is compared, e.g. ``"K_B ratio, n=8 Lc=30 lam=0.8"``.
    value : float
        Our number.
    reference : float
        The number compared with (the thesis's, or a reference run's).
    source : str
        Where ``reference`` comes from, e.g. ``"thesis Table 3"`` or ``"MERLIN2 reference run"``.
    rtol, atol : float
        Tolerance: passes when ``|value - reference| <= atol + rtol * |reference|``.
    unit : str
        Unit of both numbers.
    note : str
        Why this tolerance, or what differs (shown in the report).
    synthetic : bool
        True for a check of a pipeline on synthetic data the model generated (a known truth
        recovered), not a comparison with the thesis's experiment; the report tags it so.
    """

    name: str
    value: float
    reference: float
    source: str
    rtol: float = 0.0
    atol: float = 0.0
    unit: str = ""
    note: str = ""
    synthetic: bool = False

    @property
    def difference(self) -> float:
        """``value - reference``."""
        return self.value - self.reference

    @property
    def relative_difference(self) -> float:
        """``(value - reference) / |reference|`` (``inf`` if the reference is 0)."""
        return self.difference / abs(self.reference) if self.reference else math.inf

    @property
    def tolerance(self) -> float:
        """The largest ``|value - reference|`` that passes: ``atol + rtol * |reference|``."""
        return self.atol + self.rtol * abs(self.reference)

    @property
    def passed(self) -> bool:
        """Within tolerance (False for a NaN value)."""
        if not (math.isfinite(self.value) and math.isfinite(self.reference)):
            return False
        return abs(self.difference) <= self.tolerance


@dataclass
class Section:
    """A chapter of the report.

    Attributes
    ----------
    title : str
    summary : str
        A paragraph of plain text: what was reproduced and how.
    checks : list of Check
    figures : list of (Path, str)
        PNG files (inside the report's directory) and their captions.
    tables : list of (Path, str)
        CSV files and their captions.
    views : list of (Path, str)
        Interactive views: plotly figures saved as JSON (``Figure.write_json``, frames
        included) inside the report's directory, and their captions; the page draws them
        with plotly's JavaScript, inlined once.
    seconds : float
        Wall time the section took (set by the report).
    """

    title: str
    summary: str = ""
    checks: list = field(default_factory=list)
    figures: list = field(default_factory=list)
    tables: list = field(default_factory=list)
    views: list = field(default_factory=list)
    seconds: float = 0.0

    @property
    def passed(self) -> bool:
        return all(check.passed for check in self.checks)

    def add_figure(self, path: Path, caption: str) -> None:
        self.figures.append((Path(path), caption))

    def add_table(self, path: Path, caption: str) -> None:
        self.tables.append((Path(path), caption))

    def add_view(self, path: Path, caption: str) -> None:
        self.views.append((Path(path), caption))
