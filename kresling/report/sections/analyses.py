"""The bar-and-hinge analyses section of the reproduction report (thesis chapter 3.1,
3.4-3.5, Appendices A-B).

What it reproduces: Table 3's model column (against the MERLIN2 reference runs and the
printed thesis values), the optimum's K_B ratio 16.77, the experiment-model agreement the
thesis claims, the independence of the ratio from kf, the trends of section 3.4 (K_B ratio,
Psi ratio) and of figure 3.17 (snap force), the axisymmetry of Appendix A, and figures
3.5-3.7 and 3.15, 3.14, 3.16 and A-1 with a 3D view of the optimal specimen (drawn by
:mod:`kresling.report.figures.analyses`).
"""

from __future__ import annotations

import csv
import logging
import math
from pathlib import Path

import numpy as np

from kresling.analyses.bending import bending_stiffness, bending_test
from kresling.analyses.facet_angle import facet_angle_ratio, facet_angles
from kresling.analyses.linear_bending import LinearBendingTester
from kresling.analyses.orientation import orientation_study
from kresling.analyses.snap_through import SnapThroughTester, snap_through
from kresling.analyses.table3 import TABLE3_DESIGNS, table3_comparison, topology_effect
from kresling.data.tables import merlin2_model_curves
from kresling.geometry import Design
from kresling.model.kresling_specimen import SpecimenParameters
from kresling.report.figures.analyses import draw_figures
from kresling.report.section import Check, Section
from kresling.report.thesis_values import (EXPERIMENT_RATIO_ATOL, MERLIN2_HISTORY_ATOL,
                                           MERLIN2_RTOL, RECONSTRUCTION, SNAP_REFERENCE,
                                           TABLE3_HALF_UNIT, TOPOLOGY_EFFECT_N10_CONTRACTED)

__all__ = ["reproduce"]

logger = logging.getLogger(__name__)

#: Half a unit of the last digit the thesis prints for K_B and its ratio (2 decimals).
HALF_UNIT = TABLE3_HALF_UNIT


def reproduce(out_dir, quick: bool = True) -> Section:
    """Reproduce chapter 3's bar-and-hinge results into ``out_dir``.

    Parameters
    ----------
    out_dir : str or Path
        Where the figures (PNG), tables (CSV) and the optimal specimen's FOLD file go.
    quick : bool
        Fewer orientation angles and snap-through increments (a few seconds in all); the
        Table 3 runs are the thesis's 350 steps either way.

    Returns
    -------
    Section
    """
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    section = Section("Bar-and-hinge analyses: Table 3, snap-through, orientation "
                      "(chapter 3.1, 3.4-3.5, Appendices A-B)")
    table = table3_comparison()
    studies = [orientation_study(Design(n, 0.9, 15), points=9 if quick else 25)
               for n in (4, 6, 8, 10)]
    notes = [_table3_part(section, out_dir, table), _trend_part(section),
             _linear_part(section, studies), _snap_part(section, out_dir, quick),
             _topology_part(section, out_dir)]
    draw_figures(section, out_dir, table, studies, quick)
    section.summary = " ".join(notes)
    logger.info("analyses section: %d of %d checks passed",
                sum(c.passed for c in section.checks), len(section.checks))
    return section


def _table3_part(section: Section, out_dir: Path, table) -> str:
    for entry in table:
        d, ours = entry.design, entry.ours_values
        label = f"n={d.n} Lc={d.Lc:g} lambda={d.lam:g}"
        for key, name in (("extended", "K_ext"), ("contracted", "K_con"), ("ratio", "K_B ratio")):
            unit = "" if key == "ratio" else "N*m/rad"
            section.checks.append(Check(
                f"{name}, {label}, vs MERLIN2", ours[key], entry.reference[key],
                "MERLIN2 reference run (5 mm, 350 steps)", rtol=MERLIN2_RTOL, unit=unit,
                note="the agreement asked of the reconstruction is 0.1 %; the reference "
                     "prints 6 decimals, which we match"))
            if math.isfinite(entry.thesis_model[key]):
                section.checks.append(Check(
                    f"{name}, {label}, vs the thesis", ours[key], entry.thesis_model[key],
                    "thesis Table 3 (model)" if d.n != 10 else "thesis section 3.4",
                    atol=HALF_UNIT, rtol=RECONSTRUCTION, unit=unit,
                    note="half a unit of the printed 2 decimals plus 0.5 %: the thesis's "
                         "generator is reconstructed (docs/thesis_equations.md, "
                         "'Bending test')"))
        if entry.experiment and math.isfinite(entry.thesis_model["extended"]):
            # The thesis's "within nearly ±1" is about samples 1-3; for the optimum it notes
            # "a degree of disagreement" (16.77 against 11.79).
            section.checks.append(Check(
                f"K_B ratio, {label}, model vs experiment", ours["ratio"],
                entry.experiment["ratio"], "thesis Table 3 (experiment, printed ratio)",
                atol=EXPERIMENT_RATIO_ATOL, note="the thesis: 'within nearly ±1'; from the printed means the "
                               f"experimental ratio is {entry.experiment['ratio_of_means']:.2f}"))
    worst = max(_history_error(entry) for entry in table)
    section.checks.append(Check(
        "force histories vs MERLIN2, largest relative difference", worst, 0.0,
        "MERLIN2 reference runs, all 350 steps of 8 runs", atol=MERLIN2_HISTORY_ATOL,
        note="pointwise agreement asked of the reconstruction: 1e-4 relative"))
    path = _write_rows(out_dir / "table3.csv", [entry.row() for entry in table])
    section.add_table(path, "Table 3 side by side: ours, the MERLIN2 reference runs, the "
                            "thesis's model and experiment columns (K_B in N*m/rad).")
    optimum = table[-1].ours.ratio
    return (f"Table 3: our bending test (5 mm in 350 steps, the thesis's Appendix B protocol) "
            f"matches the MERLIN2 reference runs to their 6 printed decimals and their force "
            f"histories to {worst:.0e} (relative), and the thesis's printed model values within "
            f"rounding and the 0.5 % of the reconstructed generator; the optimum's ratio is "
            f"{optimum:.2f} (thesis 16.77; its specimen measured 11.79, a disagreement the "
            f"thesis notes). Model and experimental ratios of samples 1-3 agree within ±1, as "
            f"the thesis says, with its printed ratios.")


def _write_rows(path: Path, rows) -> Path:
    """Write dicts with the same keys as CSV (a header, then one line each)."""
    with open(path, "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]), lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    return path


def _history_error(entry) -> float:
    curves = merlin2_model_curves()[(entry.design.n, entry.design.Lc, entry.design.lam)]
    worst = 0.0
    for name in ("extended", "contracted"):
        ours = getattr(entry.ours, name).moment
        worst = max(worst, float(np.abs(ours / curves[name][1] - 1).max()))
    return worst


def _fraction_monotone(values, rising: bool) -> float:
    steps = np.diff(np.asarray(values, dtype=float))
    return float(np.mean(steps > 0 if rising else steps < 0))


def _trend_part(section: Section) -> str:
    small = "0.001rad"
    lams, Lcs = np.linspace(0.7, 0.9, 4), np.linspace(15, 60, 4)
    by_lam = [bending_stiffness(Design(8, lam, 30), small).ratio for lam in lams]
    by_Lc = [bending_stiffness(Design(8, 0.8, Lc), small).ratio for Lc in Lcs]
    by_n = [bending_stiffness(Design(n, 0.8, 30), small) for n in (4, 6, 8, 10)]
    psi_lam = [facet_angle_ratio(Design(8, lam, 30)) for lam in lams]
    psi_Lc = [facet_angle_ratio(Design(8, 0.8, Lc)) for Lc in Lcs]
    source = "thesis section 3.4, figures 3.9-3.12"
    trends = (("K_B ratio rises with lambda (n=8, Lc=30)", by_lam, True),
              ("K_B ratio falls with Lc (n=8, lambda=0.8)", by_Lc, False),
              ("K_ext falls as n rises (lambda=0.8, Lc=30)", [c.extended.stiffness for c in by_n], False),
              ("K_con falls as n rises (lambda=0.8, Lc=30)", [c.contracted.stiffness for c in by_n], False),
              ("Psi ratio rises with lambda (n=8, Lc=30)", psi_lam, True),
              ("Psi ratio falls with Lc (n=8, lambda=0.8)", psi_Lc, False))
    for name, values, rising in trends:
        section.checks.append(Check(name, _fraction_monotone(values, rising), 1.0, source,
                                    note="fraction of successive steps in the thesis's "
                                         "direction (0.001 rad protocol)"))
    d = Design(6, 0.8, 20)
    base = bending_stiffness(d, small).ratio
    scaled = bending_stiffness(d, small, parameters=SpecimenParameters(kf=0.47)).ratio
    section.checks.append(Check("K_B ratio with kf x 10, n=6 lambda=0.8 Lc=20", scaled, base,
                                "the same ratio with kf = 0.047", rtol=1e-6,
                                note="every stiffness is proportional to kf"))
    worst = 0.0
    for n, Lc, lam in TABLE3_DESIGNS:
        design = Design(n, lam, Lc)
        for state, closed in ((1, design.psi_ext), (0, design.psi_con)):
            worst = max(worst, float(np.abs(facet_angles(design, state) - closed).max()))
    section.checks.append(Check("Psi of the built cells vs the closed form, worst", worst, 0.0,
                                "Design.psi_ext / psi_con", atol=1e-12, unit="rad",
                                note="polygon-edge hinges of the four Table 3 designs, both states"))
    return ("Section 3.4's trends hold (0.001 rad protocol): the K_B ratio and the facet-angle "
            "ratio rise with lambda and fall with Lc, both K_B fall as n rises; the ratio does "
            "not depend on kf; Psi read from the built model's hinges is the closed form.")


def _linear_part(section: Section, studies) -> str:
    d = Design(10, 0.9, 15)
    tester = LinearBendingTester(10)
    for state, name in ((1, "extended"), (0, "contracted")):
        section.checks.append(Check(
            f"linearised K_B vs the nonlinear 0.001 rad test, optimum, {name}",
            tester.run(d, state), bending_test(d, state, "0.001rad").stiffness,
            "nonlinear bending test, 0.001 rad in 10 steps", rtol=3e-5, unit="N*m/rad",
            note="the geometric nonlinearity at 0.001 rad, second order in the angle"))
    worst = max(study.variation() for study in studies)
    section.checks.append(Check(
        "K_B ratio spread over the bending axis angle, worst of n = 4-10", worst, 0.0,
        "thesis Appendix A: 'largely unchanged' (axisymmetric)", atol=0.01,
        note="(max - min) / mean over one period 2 pi/n; Lc = 15, lambda = 0.9 as in "
             "Appendix A; 1 % allowance (measured: 0.36 % for n = 4, less for larger n)"))
    return (f"Appendix A: the linearised model agrees with the 0.001 rad test to 1e-5, and "
            f"turning the bending axis changes the K_B ratio by at most {100 * worst:.2f} % "
            f"(axisymmetric, as the thesis found); turning only the pin line against the load "
            f"would change it by 4-65 % (docs/thesis_equations.md, 'Bending test').")


def _snap_part(section: Section, out_dir: Path, quick: bool) -> str:
    steps = 100 if quick else 400
    reference = snap_through(Design(8, 0.8, 30), steps=steps)
    force, force_tol = SNAP_REFERENCE["force"]
    travel, travel_tol = SNAP_REFERENCE["displacement"]
    source = "MERLIN2 reference run (docs/thesis_equations.md, 'Bending test')"
    section.checks += [
        Check("snap force, n=8 Lc=30 lambda=0.8", reference.snap_force, force, source,
              atol=force_tol, unit="N", note="half a unit of 4.34"),
        Check("snap displacement, n=8 Lc=30 lambda=0.8", reference.snap_displacement, travel,
              source, atol=travel_tol, unit="mm",
              note="ours is the parabola through the peak sample; the reference run's peak "
                   "sample lies within its step (about 0.07 mm)"),
    ]
    lams, Lcs = (0.75, 0.8, 0.85, 0.9), (15, 25, 40, 60)
    for n in (4, 6, 8, 10):
        tester = SnapThroughTester(n, steps=steps)
        up = [tester.run(Design(n, lam, 20)).snap_force for lam in lams]
        down = [tester.run(Design(n, 0.85, Lc)).snap_force for Lc in Lcs]
        section.checks.append(Check(
            f"snap force rises with lambda and falls with Lc, n={n}",
            (_fraction_monotone(up, True) + _fraction_monotone(down, False)) / 2, 1.0,
            "thesis figure 3.17", note="fraction of successive steps in the thesis's "
                                       "direction (lambda 0.75-0.9 at Lc=20; Lc 15-60 at 0.85)"))
    path = out_dir / "snap_through.csv"
    keys = ("snap_force", "snap_displacement", "energy_barrier", "minimum_force", "bistable",
            "stable_height", "stable_tilt")
    with open(path, "w", newline="") as handle:
        writer = csv.writer(handle, lineterminator="\n")
        writer.writerow(("n", "Lc_mm", "lambda") + keys + ("bistability",))
        for n, Lc, lam in TABLE3_DESIGNS:
            r = snap_through(Design(n, lam, Lc), steps=steps)
            writer.writerow((n, Lc, lam) + tuple(getattr(r, k) for k in keys) + (r.bistability,))
    section.add_table(path, "Snap-through of the Table 3 designs: force [N], travel [mm], "
                            "energy barrier [N*mm], second stable state (height mm, tilt rad).")
    return (f"Snap-through (one cell driven from Le to Lc, top free to twist): the MERLIN2 "
            f"reference design peaks at {reference.snap_force:.2f} N at "
            f"{reference.snap_displacement:.2f} mm and dips to {reference.minimum_force:.2f} N "
            f"(the thesis says its curve stays above zero; our model, like the reference run, "
            f"is bistable there); the snap force follows figure 3.17's trends.")


def _topology_part(section: Section, out_dir: Path) -> str:
    effect = topology_effect()
    path = _write_rows(out_dir / "topology_effect.csv", effect)
    section.add_table(path, "One bar and hinge per edge instead of MERLIN2's one per pair of "
                            "triangles: relative change of K_B and of the ratio (5 mm).")
    optimum = next(e for e in effect if e["n"] == 10)
    change, tolerance = TOPOLOGY_EFFECT_N10_CONTRACTED
    stops = ("its path stops there" if not optimum["completed_contracted"]
             else "the path goes on")
    section.checks.append(Check(
        "de-duplicated topology: change of K_con, n=10 Lc=15 lambda=0.9",
        abs(optimum["contracted"]), change,
        "MERLIN2 with one bar and hinge per edge ('8 % for n = 10 contracted'; docs/model.md, "
        "'Topology')", atol=tolerance,
        note="half a unit of the rounded 8 %; MERLIN2's Newton sequence and factorisation "
             "(CHOLMOD's), as the 8 % came from MERLIN2. The de-duplicated specimen loses "
             f"stability near 4.9 mm ({stops}), so K_B is fitted to the part before; the "
             "branch taken there is decided by rounding (other factorisations: 7.4-8.4 %)"))
    ext = max(abs(e["extended"]) for e in effect)
    con = max(abs(e["contracted"]) for e in effect)
    return (f"MERLIN2's duplicated bars and hinges on the intermediate polygons matter: one "
            f"per edge lowers K_ext by up to {100 * ext:.1f} % and K_con by up to "
            f"{100 * con:.1f} % (single cells, as in the snap-through test, are unaffected).")
