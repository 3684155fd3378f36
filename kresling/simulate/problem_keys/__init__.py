"""The problem file's top-level keys, one module each: a registry.

Each module of this package states one key (``[pattern]``, ``[[load]]``, ``[contact]``, ...)
as a :class:`ProblemKey` named ``KEY``: how its table (or its ``[[key]]`` entries) is read
into the :class:`~kresling.simulate.problem.Problem`'s fields, what it checks once the whole
problem is read, and what it adds to the model. :func:`problem_keys` finds them all, so a new
key is one new module here (plus its documentation and tests); see docs/adding_a_key.md.

Keys are read in the order of their ``rank``: a key's reader may use what keys of a lower
rank have read (the :class:`ReadContext`).
"""

from __future__ import annotations

import importlib
import pkgutil
from dataclasses import dataclass
from typing import Callable

from kresling.simulate.methods import find_method

__all__ = ["ProblemKey", "ReadContext", "problem_keys"]


@dataclass(frozen=True)
class ProblemKey:
    """One top-level key of a problem file.

    Attributes
    ----------
    name : str
        The key: ``"contact"`` for ``[contact]``, ``"load"`` for ``[[load]]``.
    rank : int
        Keys are read in increasing rank; a reader sees what lower ranks read.
    read : callable
        ``read(table, context) -> dict`` of the Problem's fields this key fills. ``table``
        is a :class:`~kresling.simulate.problem_table.ProblemTable` (for an array key, the
        list of its entries' tables, empty when the file has none).
    array : bool
        ``[[name]]`` entries rather than one ``[name]`` table.
    required : bool or callable
        Whether the file must give the key (``required(context)`` when it depends on the
        method); ``allowed`` words what it must be.
    default : dict, callable or None
        For a table key the file does not give: the table read in its place
        (``default(context)`` when it depends on the method), or None: ``absent`` is used.
    absent : dict
        The fields when the key is absent and has no default table.
    check : callable, optional
        ``check(problem)``: refusals that need the whole problem (a key that applies to
        some methods only, say); raises ValueError naming the file and the key.
    families : callable, optional
        ``families(problem, pattern_model) -> dict`` of element families' tables the key
        adds to the model (:meth:`kresling.Model.with_families`); a refusal of the model's
        names this key.
    model_check : callable, optional
        ``model_check(problem, model)``: refusals that need the built model (a parameter
        name the model has not), before any solve.
    history : callable, optional
        ``history(simulation) -> dict`` of history.csv columns the key adds.
    outputs : callable, optional
        ``outputs(simulation, directory, rows) -> dict`` of the files the key writes beside
        a path's (``rows``: the increments the files keep), by name.
    """

    name: str
    rank: int
    read: Callable
    array: bool = False
    required: object = False
    allowed: str | None = None
    default: object = None
    absent: dict | None = None
    check: Callable | None = None
    families: Callable | None = None
    model_check: Callable | None = None
    history: Callable | None = None
    outputs: Callable | None = None

    @property
    def label(self) -> str:
        """The key as the file writes it: ``[contact]`` or ``[[load]]``."""
        return f"[[{self.name}]]" if self.array else f"[{self.name}]"


class ReadContext:
    """What a key's reader may use: ``source`` (the file, or "problem"), ``text`` (its TOML,
    for line numbers), ``base`` (the directory its files are relative to), ``method`` (the
    ``[analysis] method`` it names, None if none), ``given`` (the top-level keys the file
    gives) and, as attributes, every Problem field the keys of lower rank have read
    (``context.pattern``, ``context.num_nodes``, ...)."""

    def __init__(self, source, text, base, method_name, given=frozenset()):
        self.source, self.text, self.base = source, text, base
        self.method_name = method_name
        self.given = frozenset(given)
        self.fields = {}

    @property
    def method(self):
        """The method (:class:`~kresling.simulate.methods.method.Method`): the one the
        ``[analysis]`` table names once read (rank 60), before that the one its ``method``
        key names, if any (None)."""
        analysis = self.fields.get("analysis")
        return find_method(analysis.method if analysis is not None else self.method_name)

    def __getattr__(self, name):
        fields = self.__dict__.get("fields", {})
        if name in fields:
            return fields[name]
        raise AttributeError(f"no key read so far gives {name!r} (a key of a lower rank "
                             "must read it)")


_KEYS = None


def problem_keys() -> tuple:
    """Every key of this package, by rank (found once, on first use)."""
    global _KEYS
    if _KEYS is None:
        found = []
        for info in pkgutil.iter_modules(__path__):
            module = importlib.import_module(f"{__name__}.{info.name}")
            if hasattr(module, "KEY"):
                found.append(module.KEY)
        names = [key.name for key in found]
        if len(set(names)) != len(names):
            raise RuntimeError(f"problem keys declared twice: {sorted(names)}")
        _KEYS = tuple(sorted(found, key=lambda key: (key.rank, key.name)))
    return _KEYS
