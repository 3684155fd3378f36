"""The fabrication section of the reproduction report: the optimal cell's cut files, checked.

Thesis section 2.2, section 4.1 and Appendix C draw each cell from eqns 1-7 by hand in CAD;
here the pattern is computed, and the checks show that it folds onto the 3D cell exactly.
"""

from __future__ import annotations

import logging
import math
import xml.etree.ElementTree as ET
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from kresling.fabrication.accuracy import closure_error, edge_length_errors, isometry_error
from kresling.fabrication.export import pattern_fold_document, write_sheet
from kresling.io.fold_format import fold_angles, write_fold_document
from kresling.fabrication.pattern import CreasePattern, crease_pattern
from kresling.fabrication.plot import plot_sheet
from kresling.fabrication.processes import Laminate, Paper
from kresling.fabrication.sheet import module_sheet
from kresling.fabrication.svg import write_svg
from kresling.geometry import STATES, Design
from kresling.report.section import Check, Section
from kresling.report.thesis_values import FABRICATION_LENGTH_TOL, LAMINATE_GAP, OPTIMUM

__all__ = ["reproduce", "edge_length_errors", "isometry_error", "closure_error"]

logger = logging.getLogger(__name__)

#: Tolerance on lengths [mm]: the pattern is exact up to floating-point rounding.
LENGTH_TOL = FABRICATION_LENGTH_TOL
SVG_MARGIN = 5.0


def _facet_angles(pattern: CreasePattern) -> np.ndarray:
    """Angle of every lower facet at ``B_i`` between its P and Vg sides [rad], shape (n,)."""
    n, p = pattern.design.n, pattern.points
    b, t = pattern.bottom, pattern.top
    u, v = p[b[1:]] - p[b[:n]], p[t[1:]] - p[b[:n]]
    cosine = np.einsum("ij,ij->i", u, v) / np.linalg.norm(u, axis=1) / np.linalg.norm(v, axis=1)
    return np.arccos(np.clip(cosine, -1.0, 1.0))


def _write_png(sheet, path: Path) -> str:
    """PNG of the SVG (cairosvg); a Matplotlib drawing of the sheet if cairosvg is missing."""
    try:
        write_sheet(sheet, path, dpi=60)
        return "rendered from the SVG with cairosvg"
    except ImportError as error:
        logger.warning("%s; drawing %s with Matplotlib instead", error, path.name)
        ax = plot_sheet(sheet)
        ax.figure.savefig(path, dpi=100, bbox_inches="tight")
        plt.close(ax.figure)
        return "drawn with Matplotlib (cairosvg not installed)"


def reproduce(out_dir, quick: bool = True) -> Section:
    """Write the optimal cell's cut files and check its flat pattern against the 3D model.

    Parameters
    ----------
    out_dir : str or Path
        Directory for the files (created if missing).
    quick : bool, default True
        If False, also write the module sheets (laminate and paper, SVG and DXF) and the
        FOLD file of the cell.

    Returns
    -------
    Section
    """
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    n, Lc, lam = OPTIMUM
    design = Design(n=n, lam=lam, Lc=Lc, R=30.0)
    pattern = crease_pattern(design)
    section = Section(
        title="Fabrication: cut files of the optimal cell (sections 2.2, 4.1, Appendix C)",
        summary=("The flat pattern of the n=10, lambda=0.9, Lc=15 mm, R=30 mm cell is computed "
                 "from eqns 1-7 and folded onto both stable states: every line has the length "
                 "of its 3D crease, every face folds rigidly, the strip closes, and the tabs "
                 "fold to the facet angle Psi. Cut files: PET laminate (cut layer 1 with a 1 mm "
                 "gap on each valley, cut layer 2 the outline; drawn from the inside) and paper "
                 "(perforated creases, mountains cut, reinforcement panels)."))
    for kind, (value, reference) in edge_length_errors(pattern).items():
        section.checks.append(Check(f"{kind} crease length, flat pattern", value, reference,
                                    {"valley": "Vg, eqn 6", "tab": "P, eqn 1"}.get(kind, "Mg, eqn 7"),
                                    atol=LENGTH_TOL, unit="mm", note="worst of all such lines"))
    angles = _facet_angles(pattern)
    section.checks.append(Check("facet angle P-Vg, flat pattern",
                                float(angles[np.argmax(np.abs(angles - design.theta_g))]),
                                design.theta_g, "theta_g, eqn 5", atol=1e-12, unit="rad"))
    for name, code in STATES.items():
        psi = design.psi_ext if code else design.psi_con
        tab_fold = fold_angles(pattern.faces, pattern.edges, pattern.folded(code))
        tab_fold = tab_fold[[k for k, kind in enumerate(pattern.edge_kinds) if kind == "tab"]]
        section.checks += [
            Check(f"strip closure gap, {name}", closure_error(pattern, code), 0.0,
                  "B_n T_n meets B_0 T_0", atol=LENGTH_TOL, unit="mm"),
            Check(f"face isometry, {name}", isometry_error(pattern, code), 0.0,
                  "folding preserves every face", atol=LENGTH_TOL, unit="mm",
                  note="largest change of a corner-to-corner distance"),
            Check(f"tab crease fold angle, {name}", float(-tab_fold.min()), math.pi - psi,
                  f"pi - Psi_{'ext' if code else 'con'}", atol=1e-9, unit="rad",
                  note="the tabs lie on the base polygon"),
        ]
    for process in (Laminate(), Paper()):
        sheet = process.cut_sheet(pattern)
        svg_path = write_svg(sheet, out_dir / f"cell_n10_{process.name}.svg", margin=SVG_MARGIN)
        width_mm = float(ET.parse(svg_path).getroot().get("width").removesuffix("mm"))
        section.checks.append(Check(f"SVG width, {process.name}", width_mm,
                                    sheet.size[0] + 2 * SVG_MARGIN, "pattern extent + margins",
                                    atol=1e-5, unit="mm", note="written to 6 decimals"))
        png_path = out_dir / f"cell_n10_{process.name}.png"
        how = _write_png(sheet, png_path)
        section.add_figure(png_path, f"{sheet.title}: cut file ({how}); {'; '.join(sheet.notes)}")
    gap = Laminate().cut_sheet(pattern).layer("1-creases-and-base")
    section.checks.append(Check("laminate valley gap width", _gap_width(gap), LAMINATE_GAP,
                                "thesis 4.1, Appendix C step 2", atol=1e-9, unit="mm"))
    if not quick:
        write_fold_document(out_dir / "cell_n10.fold",
                            pattern_fold_document(pattern, "laminate"))
        for name in ("laminate", "paper"):
            sheet = module_sheet(design, name)
            write_sheet(sheet, out_dir / f"module_n10_{name}.svg")
            write_sheet(sheet, out_dir / f"module_n10_{name}.dxf")
    return section


def _gap_width(layer) -> float:
    """Width of the first valley gap, measured across its valley crease [mm]."""
    gap = next(path.points for path in layer.paths if path.role == "valley gap")
    # The laminate sheet is mirrored; the gap's own long sides give the crease direction.
    sides = np.roll(gap, -1, axis=0) - gap
    longest = sides[np.argmax(np.linalg.norm(sides, axis=1))]
    normal = np.array([-longest[1], longest[0]]) / np.linalg.norm(longest)
    across = gap @ normal
    return float(across.max() - across.min())
