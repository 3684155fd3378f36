"""Write a design's fabrication file in the format its extension names: SVG, DXF, FOLD, PNG."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from kresling.fabrication._checks import png_pixels
from kresling.fabrication.dxf import write_dxf
from kresling.fabrication.layers import CutSheet
from kresling.io.fold_format import fold_angles, fold_document, write_fold_document
from kresling.fabrication.pattern import CreasePattern, crease_pattern
from kresling.fabrication.processes import make_process
from kresling.fabrication.sheet import cut_sheet, module_sheet, split_parameters
from kresling.fabrication.svg import MARGIN, render_png, svg_document, write_svg
from kresling.geometry import STATES, Design, state_index

__all__ = ["FORMATS", "file_format", "pattern_fold_document", "write_sheet", "write_pattern"]

#: File extensions :func:`write_pattern` understands and what each writes.
FORMATS = {
    ".svg": "SVG cut file, one layer per cut pass, true mm",
    ".dxf": "DXF cut file, one layer per cut pass, mm",
    ".fold": "FOLD crease pattern with the contracted and extended states as 3D frames",
    ".png": "PNG preview of the SVG cut file",
}


def pattern_fold_document(pattern: CreasePattern, process="laminate", *,
                          key_state="extended") -> dict:
    """The FOLD document of a cell's crease pattern and its two stable states.

    Parameters
    ----------
    pattern : CreasePattern
    process : {"laminate", "paper"} or Paper or Laminate, default "laminate"
        Sets the assignments: mountains are ``"M"`` for the laminate, ``"C"`` (cut) for
        paper; valleys ``"V"``, tab creases and the seam ``"M"``, piece boundaries ``"B"``.
    key_state : {"extended", "contracted", 0, 1}, default "extended"
        Whose fold angles the key frame's ``edges_foldAngle`` holds (a simulator's target).

    Returns
    -------
    dict
        Key frame: the flat pattern (2D, mm, as seen from the outside of the cell), edges,
        assignments, faces, fold angles [deg]. ``file_frames``: ``"contracted"`` and
        ``"extended"``, each with the folded 3D coordinates [mm] and fold angles [deg].
        Custom properties ``kresling:edges_crease`` (crease kind per edge),
        ``kresling:faces_kind`` and ``kresling:design`` (the design's quantities).
    """
    process = make_process(process)
    key = state_index(key_state)
    assignments = [process.fold_assignments[kind] for kind in pattern.edge_kinds]
    # Folded flat (Lc = 0, contracted) a crease's sign is not in the geometry: the kind gives it.
    sign = np.array([1.0 if kind == "valley" else -1.0 for kind in pattern.edge_kinds])
    frames, angles = [], {}
    for name, code in STATES.items():
        coordinates = pattern.folded(code)
        angles[code] = np.degrees(fold_angles(pattern.faces, pattern.edges, coordinates))
        flat_folded = np.abs(angles[code]) > 180.0 - 1e-7
        angles[code][flat_folded] = 180.0 * sign[flat_folded]
        frames.append({"title": name, "vertices_coords": coordinates,
                       "edges_foldAngle": angles[code]})
    d = pattern.design
    return fold_document(
        pattern.points, pattern.edges, assignments, pattern.faces,
        edges_fold_angle=angles[key], frames=frames,
        title=(f"generalized Kresling cell n={d.n} lam={d.lam:g} Lc={d.Lc:g} mm R={d.R:g} mm "
               f"chirality={d.chirality:+d} ({process.name}); key frame folds to "
               f"{'extended' if key else 'contracted'}"),
        extra={"kresling:edges_crease": list(pattern.edge_kinds),
               "kresling:faces_kind": list(pattern.face_kinds),
               # JSON has no inf: Psi_ratio of a flat-folding design (Lc = 0) becomes null.
               "kresling:design": {k: float(v) if math.isfinite(v) else None
                                   for k, v in d.quantities().items()}})


def file_format(path) -> str:
    """The lower-case extension of ``path`` if it is one of :data:`FORMATS`.

    Raises
    ------
    ValueError
        Naming the extension and the allowed ones.
    """
    suffix = Path(path).suffix.lower()
    if suffix not in FORMATS:
        raise ValueError(f"file extension {Path(path).suffix!r} of {str(path)!r} is invalid: "
                         f"must be one of {sorted(FORMATS)}")
    return suffix


def write_sheet(sheet: CutSheet, path, *, dpi: float = 96.0) -> Path:
    """Write a cut sheet as .svg, .dxf or .png (a preview at ``dpi``), by extension."""
    suffix = file_format(path)
    if suffix == ".svg":
        return write_svg(sheet, path)
    if suffix == ".dxf":
        return write_dxf(sheet, path)
    if suffix == ".png":
        width, height = sheet.size
        dpi = png_pixels(width + 2 * MARGIN, height + 2 * MARGIN, dpi)  # svg_document's margins
        # A preview: lines thick enough to see at screen resolution.
        return render_png(svg_document(sheet, stroke_width=0.35), path, dpi=dpi)
    raise ValueError(f"file extension {suffix!r} is invalid for a cut sheet: must be one of "
                     "['.dxf', '.png', '.svg'] (a .fold file holds a crease pattern)")


def write_pattern(path, design: Design, process="laminate", *, module: bool = False,
                  dpi: float = 96.0, **parameters) -> Path:
    """Write the fabrication file of a design; the format comes from the file's extension.

    Parameters
    ----------
    path : str or Path
        Ending in one of :data:`FORMATS` (``.svg``, ``.dxf``, ``.fold``, ``.png``).
    design : Design
    process : {"laminate", "paper"}, default "laminate"
    module : bool, default False
        Cut a module (``design`` and its mirror image on one sheet) instead of one cell;
        not for ``.fold``, which describes one cell.
    dpi : float, default 96
        Resolution of a ``.png`` preview.
    **parameters
        Crease-pattern and process parameters [mm] (see :func:`~kresling.fabrication.cut_sheet`).

    Returns
    -------
    Path

    Raises
    ------
    ValueError
        Unknown extension, process or parameter, or a value the design cannot take.
    ImportError
        If the ``fabrication`` extra is missing (DXF needs ezdxf, PNG needs cairosvg).
    """
    if file_format(path) != ".fold":
        sheet = (module_sheet if module else cut_sheet)(design, process, **parameters)
        return write_sheet(sheet, path, dpi=dpi)
    if module:
        raise ValueError("module = True is invalid with .fold: a FOLD file describes one "
                         "cell; write the module's cut sheet as .svg, .dxf or .png")
    pattern_parameters, process_parameters = split_parameters(parameters)
    process = make_process(process, **process_parameters)
    pattern = crease_pattern(design, **pattern_parameters)
    return write_fold_document(path, pattern_fold_document(pattern, process))
