"""Fabrication: flat crease patterns and cut files of generalized Kresling cells.

Thesis section 2.2 (paper cells), section 4.1 and Appendix C (PET laminate cells). From a
:class:`~kresling.Design`:

- :func:`crease_pattern` lays out the flat pattern (strip of 2n triangles, triangular tabs,
  closing tab, base polygon) with a crease kind on every line and a fold map onto either
  stable state;
- :class:`Paper` and :class:`Laminate` turn it into cut passes (:class:`CutSheet`);
  :func:`cut_sheet` and :func:`module_sheet` do both steps for one cell or a two-cell module;
- :func:`write_svg`, :func:`write_dxf`, :func:`write_fold_document` (with
  :func:`pattern_fold_document`) and :func:`render_png` write files; :func:`write_pattern`
  picks the format from the file's extension.

Lengths are in mm. DXF needs ezdxf and PNG needs cairosvg: ``pip install 'kresling[fabrication]'``.

Examples
--------
>>> import kresling
>>> from kresling import fabrication
>>> pattern = fabrication.crease_pattern(kresling.Design(10, 0.9, 15.0))
>>> pattern.edge_kinds.count("valley"), pattern.edge_kinds.count("mountain")
(10, 9)
"""

from kresling.fabrication.dxf import dxf_document, write_dxf
from kresling.fabrication.export import FORMATS, pattern_fold_document, write_pattern
from kresling.io.fold_format import fold_angles, fold_document, write_fold_document
from kresling.fabrication.layers import CutLayer, CutPath, CutSheet
from kresling.fabrication.pattern import CREASE_KINDS, CreasePattern, crease_pattern
from kresling.fabrication.processes import PROCESSES, Laminate, Paper, make_process
from kresling.fabrication.sheet import cut_sheet, module_sheet
from kresling.fabrication.svg import render_png, svg_document, write_svg

__all__ = [
    "CREASE_KINDS", "CreasePattern", "crease_pattern",
    "PROCESSES", "Paper", "Laminate", "make_process",
    "CutPath", "CutLayer", "CutSheet", "cut_sheet", "module_sheet",
    "svg_document", "write_svg", "render_png", "dxf_document", "write_dxf",
    "fold_angles", "fold_document", "write_fold_document", "pattern_fold_document",
    "FORMATS", "write_pattern",
]
