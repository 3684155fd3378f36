"""Cut sheets of a design: one cell, or a module of two cells of opposite chirality.

A module (thesis section 3.1 and 4.1) is two cells of opposite chirality, so that their
twists cancel; both are cut from one sheet here, one above the other.
"""

from __future__ import annotations

import inspect
from dataclasses import replace

from kresling.fabrication._checks import non_negative
from kresling.fabrication.layers import CutSheet
from kresling.fabrication.pattern import CreasePattern, crease_pattern
from kresling.fabrication.processes import make_process
from kresling.geometry import Design

__all__ = ["PATTERN_PARAMETERS", "split_parameters", "cut_sheet", "module_sheet"]

#: Parameters of :func:`~kresling.fabrication.pattern.crease_pattern` (the rest go to the process).
PATTERN_PARAMETERS = tuple(name for name, parameter in
                           inspect.signature(crease_pattern).parameters.items()
                           if parameter.kind is inspect.Parameter.KEYWORD_ONLY)


def split_parameters(parameters: dict) -> tuple:
    """Split keyword parameters into those of the crease pattern and those of the process.

    Returns
    -------
    (dict, dict)
    """
    pattern = {k: v for k, v in parameters.items() if k in PATTERN_PARAMETERS}
    process = {k: v for k, v in parameters.items() if k not in PATTERN_PARAMETERS}
    return pattern, process


def cut_sheet(source, process="laminate", **parameters) -> CutSheet:
    """The cut sheet of one cell.

    Parameters
    ----------
    source : Design or CreasePattern
        A design (its crease pattern is built with the pattern parameters among
        ``parameters``) or a crease pattern.
    process : {"laminate", "paper"} or Paper or Laminate, default "laminate"
    **parameters
        Crease-pattern parameters (:data:`PATTERN_PARAMETERS`, e.g. ``tab_height``) and the
        process's parameters (e.g. ``gap_width``, ``kerf``), all in mm.

    Returns
    -------
    CutSheet

    Raises
    ------
    ValueError
        For an unknown process or parameter, or a value the design cannot take.

    Examples
    --------
    >>> import kresling
    >>> sheet = cut_sheet(kresling.Design(10, 0.9, 15.0), "laminate", gap_width=1.0)
    >>> [layer.key for layer in sheet.layers]
    ['1-creases-and-base', '2-outline']
    """
    pattern_parameters, process_parameters = split_parameters(parameters)
    process = make_process(process, **process_parameters)
    if isinstance(source, CreasePattern):
        if pattern_parameters:
            raise ValueError(f"parameters {sorted(pattern_parameters)} given with a crease "
                             "pattern: build the pattern with them instead")
        pattern = source
    elif isinstance(source, Design):
        pattern = crease_pattern(source, **pattern_parameters)
    else:
        raise ValueError(f"source = {source!r} is invalid: must be a Design or a CreasePattern")
    return process.cut_sheet(pattern)


def module_sheet(design: Design, process="laminate", *, cell_spacing: float = 10.0,
                 **parameters) -> CutSheet:
    """The cut sheet of a module: ``design`` and its mirror image, one above the other.

    Parameters
    ----------
    design : Design
        The upper cell; the lower one is ``design.mirrored()``.
    process : {"laminate", "paper"} or Paper or Laminate, default "laminate"
    cell_spacing : float, default 10.0
        Gap between the two cells' parts [mm].
    **parameters
        As :func:`cut_sheet`.

    Returns
    -------
    CutSheet
        The layers of both cells merged pass by pass; pieces named ``"cell +1: ..."`` and
        ``"cell -1: ..."`` after their chirality.
    """
    non_negative("cell_spacing", cell_spacing)
    upper = cut_sheet(design, process, **parameters)
    lower = cut_sheet(design.mirrored(), process, **parameters)
    (ux0, uy0), _ = upper.bounds()
    (lx0, _), (_, ly1) = lower.bounds()
    lower = lower.translated([ux0 - lx0, uy0 - cell_spacing - ly1])
    layers = tuple(replace(a, paths=a.paths + b.paths) for a, b in zip(upper.layers, lower.layers))
    pieces = tuple((f"cell {sheet_design.chirality:+d}: {name}", polygon)
                   for sheet, sheet_design in ((upper, design), (lower, design.mirrored()))
                   for name, polygon in sheet.pieces)
    d = design
    title = (f"Kresling module (two cells of opposite chirality) n={d.n} lam={d.lam:g} "
             f"Lc={d.Lc:g} mm R={d.R:g} mm, {make_process(process).name}")
    notes = upper.notes + (f"upper cell chirality {d.chirality:+d}, lower cell "
                           f"{-d.chirality:+d}",)
    return CutSheet(title, layers, pieces, notes)

