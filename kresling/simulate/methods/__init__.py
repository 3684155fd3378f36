"""The analysis methods a problem file may name, one module each: a registry.

Each module of this package states one method (``[analysis] method = "..."``) as a
:class:`~kresling.simulate.methods.method.Method` named ``METHOD``: the settings it reads
from ``[analysis]``, what it checks of the whole problem, how it runs and what it records.
:func:`method_named` looks a method up by its name, the one place where a method's name is
compared; a new method is one new module here (plus its documentation and tests): see
docs/adding_a_method.md.
"""

from __future__ import annotations

import importlib
import pkgutil

__all__ = ["method_named", "method_names", "find_method"]

#: The order in which messages list the methods (the others, added later, follow by name).
_LISTED = ("displacement_control", "force_control", "mgdcm", "fold", "modes", "dynamic")
_METHODS = None


def _methods() -> dict:
    global _METHODS
    if _METHODS is None:
        found = {}
        for info in pkgutil.iter_modules(__path__):
            module = importlib.import_module(f"{__name__}.{info.name}")
            method = getattr(module, "METHOD", None)
            if method is not None:
                found[method.name] = method
        order = [n for n in _LISTED if n in found] + sorted(set(found) - set(_LISTED))
        _METHODS = {name: found[name] for name in order}
    return _METHODS


def method_names() -> tuple:
    """Every method's name."""
    return tuple(_methods())


def method_named(name: str):
    """The method called ``name`` (a ValueError naming the others if there is none)."""
    methods = _methods()
    if name not in methods:
        raise ValueError(f"method = {name!r} is unknown: must be one of {list(methods)}")
    return methods[name]


def find_method(name):
    """The method called ``name``, or None when ``name`` names none (yet to be refused
    where it is read, with its line)."""
    return _methods().get(name) if isinstance(name, str) else None
