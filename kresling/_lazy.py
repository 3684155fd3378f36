"""Names of a package imported from their modules when first used: importing the package
(or any one of its modules) then costs only what is used. The command line's start-up pays
for it: ``kresling bend`` needs the bending test, not the package's other analyses and
solvers."""

from __future__ import annotations

import sys
from importlib import import_module

__all__ = ["lazy_names"]


def lazy_names(package: str, homes: dict) -> tuple:
    """``(__getattr__, __dir__)`` for ``package``, whose names in ``homes`` (name -> the
    module that defines it, relative to the package) are imported when first asked for.

    A name must not be the name of one of the package's modules: importing that module
    would put the module where the name is looked for.
    """
    def __getattr__(name):
        if name not in homes:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(import_module(f"{package}.{homes[name]}"), name)
        setattr(sys.modules[package], name, value)   # asked once
        return value

    def __dir__():
        return sorted(set(vars(sys.modules[package])) | set(homes))

    return __getattr__, __dir__
