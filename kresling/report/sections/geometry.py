"""The geometry section of the reproduction report (thesis chapter 2, eqns 1-9).

Checks the closed-form geometry (docs/thesis_equations.md, 'Geometry'): the extended height
``Le`` of the optimal design and of the three paper specimens, the truss path's end points
(``L(alpha0) = Lc``, ``L(alpha_e) = Le``, the mountain bar back at ``Mg``), that both stable
states are stress-free, the facet angle Psi of the MERLIN2 golden model, the extended module
length of eqn 30 and the traditional-Kresling limit. Nothing here depends on ``quick``: it
is all closed form.
"""

from __future__ import annotations

import csv
import logging
import math
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure

from kresling.geometry import STATES, Design
from kresling.plots import plot_cell, plot_kinematic_path
from kresling.report.section import Check, Section
from kresling.report.thesis_values import (EXACT, HALF_UNIT_6TH, LE_DESIGNS,
                                           LE_OPTIMUM_40_DIGITS, MODULE_LENGTH_EQN_30,
                                           PSI_GOLDEN)

__all__ = ["reproduce", "DESIGNS", "bar_length_errors"]

logger = logging.getLogger(__name__)

#: The designs checked, (n, lambda, Lc [mm]) -> (Le [mm], its source): see
#: :data:`kresling.report.thesis_values.LE_DESIGNS`.
DESIGNS = LE_DESIGNS


def bar_length_errors(design: Design) -> dict:
    """Largest deviation of each bar family of the built cell from its stress-free length.

    Returns
    -------
    dict of str to float
        ``"valley"`` (``|b_i t_{i+1}| - Vg``), ``"mountain"`` (``|b_i t_i| - Mg``) and
        ``"polygon"`` (sides ``- P``), the worst over both stable states [mm].
    """
    worst = dict.fromkeys(("valley", "mountain", "polygon"), 0.0)
    for code in STATES.values():
        bottom, top = design.vertices(code)
        ahead = np.roll(top, -design.chirality, axis=0)
        pairs = {"valley": (bottom, ahead, design.Vg), "mountain": (bottom, top, design.Mg),
                 "polygon": (top, np.roll(top, -1, axis=0), design.P)}
        for kind, (a, b, length) in pairs.items():
            error = np.abs(np.linalg.norm(b - a, axis=1) - length).max()
            worst[kind] = max(worst[kind], float(error))
    return worst


def reproduce(out_dir, quick: bool = True) -> Section:
    """Check chapter 2's geometry and draw the optimal cell.

    Parameters
    ----------
    out_dir : str or Path
        Where the figures (PNG) and the table (CSV) go; created if missing.
    quick : bool
        Ignored: every number is closed form.

    Returns
    -------
    Section
    """
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    section = Section(
        "Generalized Kresling geometry (chapter 2, eqns 1-9)",
        "Every crease length, twist and height of a cell follows from n, R, lambda and Lc "
        "(eqns 1-9). The extended state is the second root of m(alpha) = Mg, in closed form: "
        "alpha_e = pi - alpha0 - 2 pi/n and Le = sqrt(Lc^2 - 2R^2 (cos alpha0 + cos(alpha0 + "
        "2 pi/n))). Checked: Le of the optimal design (n=10, lambda=0.9, Lc=15 mm, R=30 mm) "
        "and of the three paper specimens, the end points of the truss path, that valley and "
        "mountain bars have their stress-free lengths in both states, Psi of the MERLIN2 "
        "golden model and the traditional-Kresling limit.")
    optimum = Design(10, 0.9, 15.0)
    section.checks += _height_checks() + _path_checks(optimum) + _limit_checks()
    _write_table(section, out_dir / "designs.csv")
    _draw_figures(section, out_dir, optimum)
    logger.info("geometry section: %d of %d checks passed",
                sum(c.passed for c in section.checks), len(section.checks))
    return section


def _height_checks() -> list:
    checks = []
    for (n, lam, Lc), (Le, source) in DESIGNS.items():
        thesis_code = n == 10
        checks.append(Check(
            f"Le, n={n} lambda={lam:g} Lc={Lc:g} mm", Design(n, lam, Lc).Le, Le, source,
            atol=EXACT if thesis_code else HALF_UNIT_6TH, unit="mm",
            note=("the thesis's code value is a numerical root of m(alpha) = Mg; ours is the "
                  "closed form (exact to 1e-14 mm, next check): they differ by 1.6e-10 mm"
                  if thesis_code else "half a unit of the 6th decimal")))
    le = Design(10, 0.9, 15.0).Le
    checks += [
        Check("Le, optimum, against 40-digit arithmetic", le, LE_OPTIMUM_40_DIGITS,
              "closed form in mpmath, 40 digits", atol=1e-12, unit="mm",
              note="double precision of the C++ core"),
        Check("extended module length 2 Le, optimum", 2 * le, MODULE_LENGTH_EQN_30[0],
              "thesis eqn 30", atol=MODULE_LENGTH_EQN_30[1], unit="mm",
              note="half a unit of the printed digit"),
    ]
    return checks


def _path_checks(design: Design) -> list:
    checks = [
        Check("L(alpha0), optimum", design.height_at(design.alpha0), design.Lc,
              "eqn 8: the contracted state", atol=EXACT, unit="mm"),
        Check("L(alpha_e), optimum", design.height_at(design.alpha_e), design.Le,
              "eqn 8: the extended state", atol=EXACT, unit="mm"),
        Check("m(alpha0), optimum", design.mountain_length_at(design.alpha0), design.Mg,
              "eqn 9: mountain bar stress-free (Mg, eqn 7)", atol=EXACT, unit="mm"),
        Check("m(alpha_e), optimum", design.mountain_length_at(design.alpha_e), design.Mg,
              "eqn 9: the second root of m(alpha) = Mg", atol=EXACT, unit="mm"),
        Check("Psi_ext, golden model n=4 lambda=0.7 Lc=30 mm", Design(4, 0.7, 30.0).psi_ext,
              PSI_GOLDEN, "MERLIN2 golden model, hinge 1 of folds.csv", atol=1e-12,
              unit="rad", note="dihedral between a perimeter triangle and the base polygon"),
    ]
    errors = [bar_length_errors(Design(*key).mirrored()) for key in DESIGNS]
    errors += [bar_length_errors(Design(*key)) for key in DESIGNS]
    for kind in ("valley", "mountain", "polygon"):
        worst = max(error[kind] for error in errors)
        checks.append(Check(f"{kind} bars at their stress-free length, both states", worst,
                            0.0, "bistability: both states stress-free", atol=EXACT, unit="mm",
                            note="worst of the four designs, both chiralities"))
    return checks


def _limit_checks() -> list:
    checks = []
    for n in (4, 10):
        traditional = Design(n, 1.0 - 1e-12, 0.0)
        checks.append(Check(
            f"traditional limit lambda -> 1, Lc = 0: Le, n={n}", traditional.Le,
            2 * 30.0 * math.cos(math.pi / n), "thesis 2.1: Le = M = 2R cos(pi/n)",
            atol=1e-6, unit="mm", note="lambda = 1 - 1e-12 (the design space is open)"))
    return checks


def _write_table(section: Section, path: Path) -> None:
    names = ("n", "lam", "Lc", "P", "V", "M", "Vg", "Mg", "theta_g", "alpha0", "alpha_e", "Le",
             "Psi_con", "Psi_ext", "Psi_ratio")
    with open(path, "w", newline="") as handle:
        writer = csv.writer(handle, lineterminator="\n")
        writer.writerow(names)
        for key in DESIGNS:
            quantities = Design(*key).quantities()
            writer.writerow([quantities[name] for name in names])
    section.add_table(path, "The four designs of the thesis (R = 30 mm): crease lengths "
                            "(mm), twists and facet angles (rad).")


def _draw_figures(section: Section, out_dir: Path, design: Design) -> None:
    cells = Figure(figsize=(9.0, 4.5))
    for index, state in enumerate(("contracted", "extended")):
        plot_cell(design, state, cells.add_subplot(1, 2, index + 1, projection="3d"))
    cells.tight_layout()
    cells.savefig(out_dir / "optimal_cell_states.png", dpi=100)
    section.add_figure(out_dir / "optimal_cell_states.png",
                       "The optimal cell (n=10, lambda=0.9, Lc=15 mm, R=30 mm) in its two "
                       "stable states: valley creases solid blue, mountain creases dashed red "
                       "(cf. figures 2.1 and 2.5).")
    path = Figure(figsize=(7.0, 4.0))
    plot_kinematic_path(design, path.add_subplot())
    path.tight_layout()
    path.savefig(out_dir / "optimal_cell_kinematic_path.png", dpi=100)
    section.add_figure(out_dir / "optimal_cell_kinematic_path.png",
                       "Truss kinematics of the optimal cell (eqns 8-9): height, mountain bar and "
                       "facet angle Psi against the twist. The mountain bar is at its "
                       "stress-free length Mg only in the two stable states and shorter in "
                       "between: the barrier that makes the cell bistable.")
