"""The chapters of the reproduction report, in thesis order, and the function of each.

Every chapter's section is a module of :mod:`kresling.report.sections`, imported here
plainly: adding a part of the thesis to the report is a section module and one line in
:data:`CHAPTERS`. A :class:`Chapter` may also name a module outside the package by its dotted
name (a study's own section, the tests' fakes); that one is imported only when the chapter
runs, and is reported as *not yet available* while it does not exist, never dropped.
"""

from __future__ import annotations

import importlib
import inspect
from dataclasses import dataclass
from typing import Callable, Union

from kresling.report.sections import (analyses, arm, experiments, fabrication, geometry,
                                      manipulator, sweeps)

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
    section : callable or str
        The section's function, ``section(out_dir, quick=True) -> Section``; or the dotted
        name of a module that provides it, imported when the chapter runs.
    function : str, default "reproduce"
        For a module named by ``section``: the name of the function in it (or in its
        submodule of that name).
    """

    key: str
    part: str
    title: str
    section: Union[Callable, str]
    function: str = "reproduce"

    def load(self) -> Callable:
        """The section's function (imported first when ``section`` names a module).

        Raises
        ------
        SectionNotAvailable
            If the named module (or its ``function`` submodule) does not exist.
        ImportError, AttributeError
            If the module exists but fails to import or lacks the function: a bug, not a
            missing section.
        """
        if callable(self.section):
            return self.section
        package = _import_if_present(self.section)
        if package is None:
            raise SectionNotAvailable(f"module {self.section} does not exist yet")
        found = getattr(package, self.function, None)
        if callable(found) and not inspect.ismodule(found):
            return found
        submodule = _import_if_present(f"{self.section}.{self.function}")
        if submodule is None:
            raise SectionNotAvailable(f"{self.section} has no {self.function}() yet")
        return getattr(submodule, self.function)


class SectionNotAvailable(LookupError):
    """The code of a chapter has not been written yet."""


#: The report's chapters, in thesis order.
CHAPTERS = (
    Chapter("geometry", "Chapter 2.1", "Generalized Kresling geometry", geometry.reproduce),
    Chapter("experiments", "Chapter 3.2-3.3", "Experimental data: crease stiffness and "
            "bending tests", experiments.reproduce),
    Chapter("analyses", "Chapter 3.1, 3.3-3.4", "Bending stiffness of the bar-and-hinge "
            "model: Table 3, figures 3.5-3.7 and 3.14-3.16", analyses.reproduce),
    Chapter("sweeps", "Chapter 3.4-3.5", "Parametric study: figures 3.9-3.13, 3.17 and the "
            "optimum", sweeps.reproduce),
    Chapter("fabrication", "Chapter 4.1, Appendix C", "Fabrication: cut files of the "
            "optimal cell", fabrication.reproduce),
    Chapter("manipulator", "Chapter 4.2-4.3, Appendix E", "Manipulator kinematics",
            manipulator.reproduce),
    Chapter("arm", "Beyond chapter 4", "The manipulator as a structure: load capacity, "
            "switching by pulling, actuation beside the kinematics, Table 5", arm.reproduce),
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
