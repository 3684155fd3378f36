"""The chapters of the reproduction report, in thesis order, and where each one's code lives.

A chapter names a module that provides ``reproduce(out_dir, quick=True) -> Section``, either
defined in the module itself or in its submodule ``reproduce`` (``kresling.fits`` ->
``kresling.fits.reproduce.reproduce``). Adding a part of the thesis to the report is one
line in :data:`CHAPTERS`. A chapter whose module does not exist yet is reported as *not yet
available*, never dropped.
"""

from __future__ import annotations

import importlib
import inspect
from dataclasses import dataclass
from typing import Callable

__all__ = ["Chapter", "CHAPTERS", "SectionNotAvailable", "select_chapters"]


@dataclass(frozen=True)
class Chapter:
    """One part of the report.

    Parameters
    ----------
    key : str
        Short name used on the command line (``--only key``) and for the section's
        sub-directory of the report.
    part : str
        Where it is in the thesis, e.g. ``"Chapter 2"``.
    title : str
        Title shown when the section cannot run (otherwise the section's own title is used).
    module : str
        Dotted name of the module that provides the section.
    function : str, default "reproduce"
        Name of the function in ``module`` (or in ``module.<function>``).
    """

    key: str
    part: str
    title: str
    module: str
    function: str = "reproduce"

    def load(self) -> Callable:
        """Import and return the section's function.

        Raises
        ------
        SectionNotAvailable
            If ``module`` (or its ``reproduce`` submodule) does not exist.
        ImportError, AttributeError
            If the module exists but fails to import or lacks the function: a bug, not a
            missing section.
        """
        package = _import_if_present(self.module)
        if package is None:
            raise SectionNotAvailable(f"module {self.module} does not exist yet")
        found = getattr(package, self.function, None)
        if callable(found) and not inspect.ismodule(found):
            return found
        submodule = _import_if_present(f"{self.module}.{self.function}")
        if submodule is None:
            raise SectionNotAvailable(f"{self.module} has no {self.function}() yet")
        return getattr(submodule, self.function)


class SectionNotAvailable(LookupError):
    """The code of a chapter has not been written yet."""


#: The report's chapters, in thesis order.
CHAPTERS = (
    Chapter("geometry", "Chapter 2.1", "Generalized Kresling geometry",
            "kresling.report.geometry_section"),
    Chapter("experiments", "Chapter 3.2-3.3", "Experimental data: crease stiffness and "
            "bending tests", "kresling.report.experiments_section"),
    Chapter("analyses", "Chapter 3.1, 3.3-3.4", "Bending stiffness of the bar-and-hinge "
            "model: Table 3, figures 3.5-3.7 and 3.14-3.16", "kresling.analyses"),
    Chapter("sweeps", "Chapter 3.4-3.5", "Parametric study: figures 3.9-3.13, 3.17 and the "
            "optimum", "kresling.sweeps"),
    Chapter("fabrication", "Chapter 4.1, Appendix C", "Fabrication: cut files of the "
            "optimal cell", "kresling.fabrication"),
    Chapter("manipulator", "Chapter 4.2-4.3, Appendix E", "Manipulator kinematics",
            "kresling.manipulator"),
)


def select_chapters(names=None, chapters=None) -> tuple:
    """The chapters named in ``names`` (all when ``None`` or empty), in report order.

    Raises
    ------
    ValueError
        If a name is not the key of a chapter; the message lists the keys.
    """
    chapters = CHAPTERS if chapters is None else tuple(chapters)
    if not names:
        return chapters
    keys = [chapter.key for chapter in chapters]
    unknown = [name for name in names if name not in keys]
    if unknown:
        raise ValueError(f"unknown section {', '.join(map(repr, unknown))}: must be one of "
                         f"{', '.join(keys)}")
    return tuple(chapter for chapter in chapters if chapter.key in names)


def _import_if_present(name: str):
    """The module ``name``, or ``None`` if it (or a package above it) does not exist.

    A ``ModuleNotFoundError`` raised *inside* an existing module (a missing dependency) is
    re-raised: that is an error to report, not a section still to write.
    """
    try:
        return importlib.import_module(name)
    except ModuleNotFoundError as error:
        if error.name is not None and (name == error.name or name.startswith(error.name + ".")):
            return None
        raise
