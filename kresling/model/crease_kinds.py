"""What each FOLD edge assignment becomes in a bar-and-hinge model, by convention.

Two conventions are in use among the tools that write crease patterns:

- ``"fold"``, the FOLD specification's (1.2): ``M``, ``V``, ``F`` (flat, unfolded crease)
  and ``U`` (unassigned crease) are folds; ``J`` (join) is a modelling edge inside one
  effective face, so a bend; ``C`` (cut) separates the faces; ``B`` is the boundary.
- ``"origami_simulator"``, Origami Simulator's (Ghassaei et al. 2018) and that of the
  editors that target it: ``M`` and ``V`` are folds; ``F`` is a facet crease (a
  triangulation edge: the panel stays flat and stiff, so a bend); ``U`` is an undriven
  crease that swings freely (a bar, no hinge); ``J``, ``C`` and ``B`` as in FOLD.

A *fold* carries a bar and a fold hinge of the assignment's family; a *bend* a bar and a
bend hinge (the law and stiffness of the panels' own bending); *free* a bar only; a *cut*
a bar only where its faces still share both ends (the faces are separated elsewhere, see
:func:`kresling.io.separate_cuts`).
"""

from __future__ import annotations

from types import MappingProxyType

__all__ = ["CONVENTIONS", "FAMILY_OF_FOLD", "FAMILY_OF_LETTER", "FOLD_FAMILIES", "crease_kind"]

#: The conventions :func:`crease_kind` knows.
CONVENTIONS = ("fold", "origami_simulator")

#: The fold family of each letter that is a fold in some convention.
FAMILY_OF_FOLD = MappingProxyType({"M": "mountain", "V": "valley", "F": "flat",
                                   "U": "unassigned"})
#: The fold families, in that order.
FOLD_FAMILIES = tuple(FAMILY_OF_FOLD.values())
#: The name of every FOLD assignment letter's edges: the folds' families and the others'.
FAMILY_OF_LETTER = MappingProxyType({**FAMILY_OF_FOLD, "B": "boundary", "C": "cut",
                                     "J": "join"})

_KINDS = {
    "fold": {"M": "fold", "V": "fold", "F": "fold", "U": "fold", "J": "bend", "C": "cut",
             "B": "boundary"},
    "origami_simulator": {"M": "fold", "V": "fold", "F": "bend", "U": "free", "J": "bend",
                          "C": "cut", "B": "boundary"},
}


def crease_kind(letter: str, convention: str = "fold") -> str:
    """``"fold"``, ``"bend"``, ``"free"``, ``"cut"`` or ``"boundary"`` for an assignment.

    Raises
    ------
    ValueError
        For an unknown convention or letter.
    """
    if convention not in _KINDS:
        raise ValueError(f"assignments = {convention!r} is invalid: must be one of "
                         f"{list(CONVENTIONS)}")
    kinds = _KINDS[convention]
    if letter not in kinds:
        raise ValueError(f"assignment {letter!r} is invalid: must be one of {sorted(kinds)}")
    return kinds[letter]
