"""Write the API reference's pages, one per public package, from each package's ``__all__``.

Run by ``conf.py`` at every build, so a name added to an ``__all__`` appears in the reference
without editing a page. Each page holds the package's docstring and a summary table of its
names (classes, functions, then constants); autosummary writes one page per name under
``api/generated/``.
"""

from __future__ import annotations

import importlib
import inspect
import pkgutil
from pathlib import Path

#: The public packages in the order of the reference (the layers, bottom up, then the top);
#: any other public module of the package with an ``__all__`` follows (see :func:`packages`).
ORDER = (
    "kresling",
    "kresling.geometry",
    "kresling.io",
    "kresling.model",
    "kresling.laws",
    "kresling.elements",
    "kresling.assembly",
    "kresling.solvers",
    "kresling.analyses",
    "kresling.simulate",
    "kresling.sweeps",
    "kresling.view",
    "kresling.fits",
    "kresling.fabrication",
    "kresling.manipulator",
    "kresling.plots",
    "kresling.report",
    "kresling.data",
    "kresling.data.tables",
)
#: Documented elsewhere: the command line has its own reference page (its modules' functions
#: are not an API).
NOT_IN_REFERENCE = {"kresling.cli"}


def packages() -> tuple:
    """:data:`ORDER`, then every other top-level public module or subpackage of ``kresling``
    that has an ``__all__`` (so a new one is in the reference without editing this file)."""
    import kresling

    found = []
    for info in pkgutil.iter_modules(kresling.__path__, "kresling."):
        name = info.name
        if name.rpartition(".")[2].startswith("_") or name in ORDER or name in NOT_IN_REFERENCE:
            continue
        if hasattr(importlib.import_module(name), "__all__"):
            found.append(name)
    return ORDER + tuple(sorted(found))


PACKAGES = packages()

GROUPS = (("Classes", inspect.isclass), ("Functions", callable),
          ("Constants", lambda obj: True))


def public_names(module) -> list:
    """The module's ``__all__`` without dunder names (``__version__`` is said in words)."""
    names = getattr(module, "__all__", None)
    if names is None:
        raise ValueError(f"{module.__name__} has no __all__: the reference lists __all__")
    return [name for name in names if not name.startswith("__")]


def homes() -> dict:
    """Where each class and function exported by more than one package is documented: in
    the most specific package that exports it (``kresling.model`` rather than ``kresling``
    for ``Model``), so that every object is described once."""
    home = {}
    for name in PACKAGES:
        module = importlib.import_module(name)
        for attribute in public_names(module):
            obj = getattr(module, attribute)
            if not (inspect.isclass(obj) or inspect.isroutine(obj)):
                continue
            best = home.get(id(obj))
            if best is None or name.count(".") > best[0].count("."):
                home[id(obj)] = (name, attribute)
    return home


def page(name: str, home: dict) -> str:
    """The reStructuredText of one package's page."""
    module = importlib.import_module(name)
    title = f"``{name}``"
    lines = [title, "=" * len(title), "", f".. automodule:: {name}", "   :no-members:", "",
             f".. currentmodule:: {name}", ""]
    names = public_names(module)
    elsewhere = [n for n in names if home.get(id(getattr(module, n)), (name, n)) != (name, n)]
    placed = set(elsewhere)
    for heading, belongs in GROUPS:
        group = [n for n in names if n not in placed and belongs(getattr(module, n))]
        if not group:
            continue
        placed.update(group)
        lines += [heading, "-" * len(heading), "", ".. autosummary::", "   :toctree: generated",
                  "   :nosignatures:", ""]
        lines += [f"   {n}" for n in group]
        lines.append("")
    if elsewhere:
        heading = "Also exported here"
        lines += [heading, "-" * len(heading), "",
                  "The same objects as documented in another package:", ""]
        for n in elsewhere:
            other, attribute = home[id(getattr(module, n))]
            lines.append(f"- ``{name}.{n}``: :py:obj:`{other}.{attribute}`")
        lines.append("")
    return "\n".join(lines)


def index() -> str:
    lines = ["API reference", "=============", "",
             "Every public class, function and constant of the package, listed from each "
             "package's ``__all__``; the packages in the order of the layers (see "
             ":doc:`../architecture`), bottom up. Units are mm, N and rad unless a name says "
             "otherwise. ``kresling.__version__`` is the installed version (|release| here).",
             "",
             ".. toctree::", "   :maxdepth: 1", ""]
    lines += [f"   {name}" for name in PACKAGES]
    return "\n".join(lines) + "\n"


def _write(path: Path, text: str) -> None:
    """Write only when the text changed (incremental builds stay incremental)."""
    if not path.exists() or path.read_text() != text:
        path.write_text(text)


def write_api_pages(folder: Path) -> None:
    folder.mkdir(exist_ok=True)
    _write(folder / "index.rst", index())
    home = homes()
    for name in PACKAGES:
        _write(folder / f"{name}.rst", page(name, home))
