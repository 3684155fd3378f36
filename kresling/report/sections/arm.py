"""The manipulator as a structure: beyond the thesis's chapter 4 (docs/arm.md).

The arm of modules, stiff guides and sliding tendons as one bar-and-hinge model: its unloaded
tip against eqn 30, the small-load response (linear, Maxwell-Betti), pulling all tendons of
one module against the cell's snap-through force, one contracted module's bend against the
constant-curvature model, the load-capacity table, the protocol's markers beside the
kinematic model's, and the module lengths beside Table 5 (a prediction, not a fit).
"""

from __future__ import annotations

import csv
import logging
import math
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from kresling.analyses import snap_through
from kresling.arm import ArmSolver, build_arm, pull_until_snap, tip_load
from kresling.arm.actuation import pseudo_linkage_run, table5_comparison
from kresling.arm.capacity import capacity_rows, load_capacity_table
from kresling.arm.plots import plot_actuation, plot_load_capacity
from kresling.arm.switching import switching_map
from kresling.report.section import Check, Section
from kresling.report.thesis_values import L_EQN_30

__all__ = ["reproduce"]

logger = logging.getLogger(__name__)


def _write_csv(path: Path, rows: list) -> Path:
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]), lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    return path


def _maxwell_betti(configuration: str = "011", force: float = 0.01) -> tuple[float, float]:
    """Asymmetry of the central-difference tip compliance (relative to its largest entry)
    and the ratio of the responses to twice and once the load (sideways)."""
    arm = build_arm(configuration)
    solver = ArmSolver(arm)
    columns, ratio = [], math.nan
    for k in range(3):
        e = np.eye(3)[k]
        plus, minus = (tip_load(arm, s * force * e, solver=solver) for s in (1, -1))
        columns.append((plus.tip_displacement - minus.tip_displacement) / (2 * force))
        if k == 0:
            twice = tip_load(arm, 2 * force * e, solver=solver)
            ratio = twice.tip_displacement[0] / plus.tip_displacement[0]
    C = np.column_stack(columns)
    return float(np.abs(C - C.T).max() / np.abs(C).max()), float(ratio)


def reproduce(out_dir, quick: bool = True) -> Section:
    """The arm as a structure; write figures and tables.

    Parameters
    ----------
    out_dir : str or Path
    quick : bool, default True
        Leave out the switching map (about 80 s).
    """
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    section = Section(
        "The manipulator as a structure (beyond chapter 4)",
        "The three-module arm as one bar-and-hinge model: modules of two Kresling cells of the "
        "optimum, stiff guide plates with tendon holes at d = 32 mm, base fixed, three sliding, "
        "tension-only tendons (EA = 500 N, an assumption) from the base to the tip guide, "
        "pretensioned to 1 N each (an assumption) before tip loads and the protocol. Tip "
        "compliance, load capacity of every configuration, pulling tendons until a module "
        "snaps, the section 4.3 protocol beside the constant-curvature model, and the module "
        "lengths beside Table 5 as a prediction (docs/arm.md).")

    built = ArmSolver(build_arm("111")).built()
    section.checks.append(Check(
        "unloaded (1 1 1) structure: tip height", float(built.tip_position[2]), 3 * L_EQN_30,
        "thesis eqn 30, L = 111.6389", atol=1.5e-4, unit="mm",
        note="the structure is built stress-free; 3 x the thesis's 4-decimal L"))

    asymmetry, ratio = _maxwell_betti()
    section.checks += [
        Check("(0 1 1), 0.01 N: tip compliance asymmetry / largest entry", asymmetry, 0.0,
              "Maxwell-Betti (a conservative structure)", atol=1e-3,
              note="central differences of the pretensioned arm's response"),
        Check("(0 1 1): response to 0.02 N / response to 0.01 N (sideways)", ratio, 2.0,
              "linear for small loads", rtol=0.01),
    ]

    pulled = pull_until_snap(build_arm("1"))
    cell = snap_through(build_arm("1").design).snap_force
    section.checks.append(Check(
        "one extended module, all tendons pulled: summed tension at the snap",
        pulled.tension_sum, cell, "the cell's snap-through force (kresling snap)", rtol=0.2,
        unit="N", note="the tendons control the module's length: it passes the force maximum "
                       "(about the cell's) and snaps later at a lower force; one cell snaps, the "
                       "other re-extends"))

    one = pseudo_linkage_run(build_arm("0"), steps=[0, 1, 2, 3])
    section.checks.append(Check(
        "one contracted module, protocol k = 1: bend", float(one.bend_angles[1, 0]),
        float(one.kinematic_bend_angles[1, 0]), "constant-curvature model, 2 asin(1/32)",
        rtol=0.02, unit="rad", note=f"bend plane {math.degrees(one.bend_direction[1]):.2f} "
                                     "degrees from tendon 1's; the tips differ by "
                                     f"{one.tip_error[1]:.2f} mm (pretension shortens the module)"))

    table = load_capacity_table(3)
    rows = capacity_rows(table)
    section.add_table(_write_csv(out_dir / "arm_load_capacity.csv", rows),
                      "Load capacity of every configuration (1 N pretension): length, tip "
                      "compliance, the largest tip load per direction and what ends it.")
    figure = plot_load_capacity(table)
    figure.savefig(out_dir / "arm_load_capacity.png", dpi=110)
    plt.close(figure)
    stiffest = max(table, key=lambda r: r.sideways_stiffness)
    section.add_figure(out_dir / "arm_load_capacity.png",
                       "Stiffness against length and the largest tip loads. The all-extended "
                       "arm is the longest, not the stiffest: "
                       f"({stiffest.configuration}) is "
                       f"{stiffest.sideways_stiffness / table[-1].sideways_stiffness:.1f} times "
                       "stiffer sideways.")

    run = pseudo_linkage_run(build_arm("011"))
    figure = plot_actuation(run)
    figure.savefig(out_dir / "arm_protocol_011.png", dpi=110)
    plt.close(figure)
    section.add_figure(out_dir / "arm_protocol_011.png",
                       "(0 1 1) under the section 4.3 protocol: the structure's markers beside "
                       "the constant-curvature model's (figures 4.13-4.15 with a mechanical "
                       "model); the extended modules bend too, so the tip lags.")

    table5 = table5_comparison()
    section.add_table(_write_csv(out_dir / "arm_table5.csv", table5),
                      "Module lengths under the protocol: Table 5, the kinematic model and the "
                      "structure (a prediction, not a fit).")
    bending = [r for r in table5 if r["config"] != "111"]
    section.checks.append(Check(
        "Table 5: mean predicted length range under the protocol",
        float(np.mean([r["predicted_max_mm"] - r["predicted_min_mm"] for r in bending])),
        float(np.mean([r["max_mm"] - r["min_mm"] for r in bending])),
        "Table 5's mean measured range (the kinematic model predicts 0)", rtol=1.0, unit="mm",
        note="same size, not the same pattern; the pretension shortens every module, so the "
             f"ranges lie outside the measured ones by "
             f"{np.mean([r['outside_by_mm'] for r in table5]):.2f} mm on average"))

    if not quick:
        switches = switching_map(3)
        section.add_table(_write_csv(out_dir / "arm_switching.csv", [
            {"start": s.start, "pull": s.pull, "end": s.end, "snapped_module": s.snapped_module,
             "pull_mm": s.pull_mm, "tension_sum_N": s.tension_sum} for s in switches]),
            "Which pulls reach which configurations (pull all, or one tendon, until a module "
            "snaps).")
    logger.info("arm section: %d checks, %d passed", len(section.checks),
                sum(c.passed for c in section.checks))
    return section
