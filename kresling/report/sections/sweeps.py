"""The parametric-study section of the reproduction report (thesis sections 3.4-3.5).

Sweeps the thesis's design space (n = 4, 6, 8, 10; Lc 15-60 mm; lambda 0.7-0.9) on a 20 x 20
grid per n (quick) or the thesis's 100 x 100, and checks the thesis's conclusions on it:
where each n's maximum K_B ratio is, how the maximum grows with n, the optimum, the trends
of the facet-angle ratio, and the 5 mm runs of figure 3.14. Draws figures 3.9-3.13 (with
:mod:`kresling.report.figures.sweeps`), and goes beyond the grid with the continuous
optimiser and the sensitivity at the optimum.
"""

from __future__ import annotations

import logging
import shutil
from pathlib import Path

from kresling.analyses import bending_stiffness
from kresling.geometry import Design
from kresling.report.figures.sweeps import add_figures
from kresling.report.section import Check, Section
from kresling.report.thesis_values import OPTIMUM, SWEEP_CONSTRAINTS
from kresling.sweeps import conclusions as c
from kresling.sweeps.designs import THESIS_N, design_grid
from kresling.sweeps.optimize import optimize_design
from kresling.sweeps.sensitivity import plot_sensitivity, sensitivity
from kresling.sweeps.sweep import sweep

__all__ = ["reproduce", "OPTIMUM"]

logger = logging.getLogger(__name__)

_STUDY = "thesis section 3.4"
_TRENDS = "thesis sections 3.4-3.5 (figures 3.9-3.12, 3.17)"
_METRICS = ("kb_ratio", "psi_ratio", "snap_force", "energy_barrier", "bistable")
#: The constraints of the report's constrained optimum (see
#: :data:`kresling.report.thesis_values.SWEEP_CONSTRAINTS`).
CONSTRAINTS = SWEEP_CONSTRAINTS


def reproduce(out_dir, quick: bool = True, *, workers=None) -> Section:
    """Reproduce the parametric study into ``out_dir``.

    Parameters
    ----------
    out_dir : str or Path
        Figures (PNG), tables (CSV) and the sweep's directory go here.
    quick : bool
        20 x 20 designs per n (a few seconds on two cores) instead of the thesis's
        100 x 100. The full sweep is kept in ``out_dir/sweep_100`` and resumed if interrupted;
        the quick one is recomputed every time.
    workers : int, optional
        Parallel workers (default: every core).

    Returns
    -------
    Section
    """
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    size = 20 if quick else 100
    sweep_dir = out_dir / f"sweep_{size}"
    if quick:
        shutil.rmtree(sweep_dir, ignore_errors=True)
    table = sweep(design_grid(THESIS_N, size), _METRICS, workers=workers, out=sweep_dir,
                  progress=False)
    section = Section("Parametric study: figures 3.9-3.13, 3.17 and the optimum")
    notes = [_grid_note(table, size), _corner_part(section, table), _by_n_part(section, table),
             _optimum_part(section, table), _trend_part(section, table),
             _five_mm_part(section, table)]
    optimum = Design(OPTIMUM[0], OPTIMUM[2], OPTIMUM[1])
    notes.append(_beyond_part(section, optimum, workers))
    local = sensitivity(optimum, "kb_ratio", workers=workers)
    notes.append("Sensitivity at the optimum: " + local.summary().replace("\n", ";"))
    add_figures(section, table, out_dir, plot_sensitivity(local))
    section.summary = " ".join(notes)
    return section


def _grid_note(table, size) -> str:
    a = table.attrs
    failed = int((~table.ok).sum())
    return (f"{len(table)} designs ({size} x {size} per n, Lc 15-60 mm, lambda 0.7-0.9; K_B "
            f"ratio by the 0.001 rad bending protocol, Psi ratio, snap-through force, energy "
            f"barrier, bistability) in {a['seconds']:.1f} s on {a['workers']} workers "
            f"({a['computed']} computed, {a['loaded']} read back), {failed} failed.")


def _corner_part(section: Section, table) -> str:
    for metric in ("kb_ratio", "snap_force"):
        for n, best in c.maxima_by_n(table, metric).items():
            Lc, lam = c.corner(table, n)
            where = f"{'figure 3.17' if metric == 'snap_force' else 'figures 3.9-3.12'}"
            section.checks += [
                Check(f"n = {n}: Lc of the largest {metric}", best["Lc"], Lc,
                      f"{where}: highest lambda, lowest Lc", unit="mm"),
                Check(f"n = {n}: lambda of the largest {metric}", best["lam"], lam,
                      f"{where}: highest lambda, lowest Lc")]
    maxima = c.maxima_by_n(table, "snap_force").values()
    forces = ", ".join(f"{r['snap_force']:.2f}" for r in maxima)
    return (f"For every n the largest K_B ratio and the largest snap-through force (figure "
            f"3.17: {forces} N for n = 4..10) are at the grid corner Lc = 15 mm, lambda = 0.9: "
            f"on the boundary of the searched domain, so each maximum may be beaten just "
            f"outside it (the continuous optimiser below stays within the thesis's bounds).")


def _by_n_part(section: Section, table) -> str:
    maxima = {m: [r[m] for r in c.maxima_by_n(table, m).values()]
              for m in ("kb_ratio", "psi_ratio")}
    shown = ", ".join(f"{v:.2f}" for v in maxima["kb_ratio"])
    level = c.leveling(maxima["kb_ratio"])
    section.checks += [
        Check("steps n -> n+2 where the max K_B ratio rises", c.rising_steps(maxima["kb_ratio"]),
              len(maxima["kb_ratio"]) - 1, "figure 3.13", note=f"maxima for n = 4..10: {shown}"),
        Check("max K_B ratio levels off: gain n = 8 -> 10 over gain n = 4 -> 6", level, 0.0,
              "figure 3.13: 'levels off at n = 8 and n = 10'", atol=0.2,
              note="passes when the last step gains less than a fifth of the first"),
        Check("steps n -> n+2 where the max Psi ratio rises", c.rising_steps(maxima["psi_ratio"]),
              len(maxima["psi_ratio"]) - 1, _STUDY + ": 'maximum values of each ratio increase "
              "with n'")]
    return (f"Maximum K_B ratio for n = 4, 6, 8, 10: {shown} (figure 3.13); the gain from 8 to 10 "
            f"is {level:.1%} of the gain from 4 to 6.")


def _optimum_part(section: Section, table) -> str:
    best = table.best("kb_ratio")
    n, Lc, lam = OPTIMUM
    section.checks += [Check("optimum of the grid: n", best["n"], n, _STUDY),
                       Check("optimum of the grid: Lc", best["Lc"], Lc, _STUDY, unit="mm"),
                       Check("optimum of the grid: lambda", best["lam"], lam, _STUDY)]
    single = bending_stiffness(Design(n, lam, Lc), "0.001rad").ratio
    section.checks.append(Check(
        "K_B ratio at the optimum: sweep minus a single bending_stiffness run", best["kb_ratio"] -
        single, 0.0, "kresling.analyses.bending_stiffness", note="bit for bit"))
    edge = (f" It lies on the boundary of the searched domain ({', '.join(best['boundary'])}): "
            f"a better design may lie outside it." if best["boundary"] else "")
    return (f"Optimum of the grid: n = {best['n']}, Lc = {best['Lc']:g} mm, lambda = "
            f"{best['lam']:g}, K_B ratio {best['kb_ratio']:.2f} at 0.001 rad.{edge}")


def _trend_part(section: Section, table) -> str:
    for metric in ("kb_ratio", "psi_ratio", "snap_force"):
        snap = metric == "snap_force"
        section.checks += [
            Check(f"fraction of grid neighbours where {metric} rises with lambda",
                  c.monotone_fraction(table, metric, "lam", +1), 1.0, _TRENDS),
            Check(f"fraction of grid neighbours where {metric} falls with Lc",
                  c.monotone_fraction(table, metric, "Lc", -1), 1.0, _TRENDS,
                  atol=0.05 if snap else 0.0,
                  note="near the monostable corner (lambda below about 0.75, Lc above about "
                       "40 mm, n >= 6) the first maximum flattens and rises again slightly "
                       "with Lc (see the analyses section); the thesis states the overall "
                       "trend" if snap else "")]
    optimum = table.where(n=OPTIMUM[0], Lc=OPTIMUM[1], lam=OPTIMUM[2])
    section.checks.append(Check("the optimum is bistable (1 = yes)", optimum["bistable"][0], 1.0,
                                "section 3.5: the optimum has the greatest bistability"))
    rho = min(c.rank_correlation(table, "kb_ratio", "psi_ratio", n) for n in THESIS_N)
    section.checks.append(Check(
        "K_B ratio vs Psi ratio: smallest Spearman rank correlation over n", rho, 1.0,
        _STUDY + ": 'trends strikingly similar'", atol=0.05,
        note="1 would be the same ordering of designs"))
    return f"The Psi ratio orders the designs like the K_B ratio (Spearman >= {rho:.3f})."


def _five_mm_part(section: Section, table) -> str:
    _, Lc, lam = OPTIMUM
    runs = {n: bending_stiffness(Design(n, lam, Lc), "5mm") for n in THESIS_N}
    small = {n: table.where(n=n, Lc=Lc, lam=lam)["kb_ratio"][0] for n in THESIS_N}
    ratios = [runs[n].ratio for n in THESIS_N]
    falls = sum(int(runs[b].extended.stiffness < runs[a].extended.stiffness) +
                int(runs[b].contracted.stiffness < runs[a].contracted.stiffness)
                for a, b in zip(THESIS_N, THESIS_N[1:]))
    section.checks += [
        Check("n with a 5 mm ratio below the 0.001 rad ratio (Lc = 15, lambda = 0.9)",
              sum(runs[n].ratio < small[n] for n in THESIS_N), len(THESIS_N),
              "section 3.4: figure 3.14's ratios are lower than figure 3.13's"),
        Check("steps n -> n+2 where the 5 mm ratio rises", c.rising_steps(ratios),
              len(THESIS_N) - 1, "figure 3.14(b): same trend with n"),
        Check("steps n -> n+2 where K_B falls (both states, 5 mm)", falls,
              2 * (len(THESIS_N) - 1), "section 3.4: increasing n reduces both stiffnesses")]
    return ("5 mm protocol at Lc = 15 mm, lambda = 0.9 (figure 3.14): ratios " +
            ", ".join(f"{r:.2f}" for r in ratios) + " for n = 4..10.")


def _beyond_part(section: Section, optimum: Design, workers) -> str:
    found = optimize_design(optimum.n, "kb_ratio", workers=workers)
    section.checks += [
        Check("continuous optimiser (SLSQP), n = 10: Lc", found.design.Lc, optimum.Lc,
              _STUDY + " (grid corner)", atol=1e-6, unit="mm"),
        Check("continuous optimiser (SLSQP), n = 10: lambda", found.design.lam, optimum.lam,
              _STUDY + " (grid corner)", atol=1e-8)]
    constrained = [optimize_design(n, "kb_ratio", constraints=CONSTRAINTS, workers=workers)
                   for n in THESIS_N]
    feasible = [r for r in constrained if r.success]
    cells = "; ".join(f"n = {r.design.n}: {r.value:.2f} at Lc = {r.design.Lc:.2f} mm, lambda = "
                      f"{r.design.lam:.3g} (active: {', '.join(r.active)})" if r.success else
                      f"n = {r.design.n}: infeasible" for r in constrained)
    best = max(feasible, key=lambda r: r.value) if feasible else None
    winner = (f"n = {best.design.n} wins" if best else "no n meets them")
    return (f"Beyond the grid: the continuous optimiser confirms the corner for n = 10 (active "
            f"bounds: {', '.join(found.active)}). For a joint no softer than K_con = 0.3 N*m/rad "
            f"that still needs 8 N to snap, the best K_B ratios are {cells}: {winner}.")
