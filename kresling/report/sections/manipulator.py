"""The manipulator's section of the reproduction report (thesis chapter 4, Appendix E)."""

from __future__ import annotations

import csv
import logging
import math
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from kresling import data
from kresling.manipulator import plots
from kresling.manipulator.forward import forward_kinematics
from kresling.manipulator.inverse import inverse_kinematics, solve_configuration
from kresling.manipulator.joint_lengths import joint_length_table
from kresling.manipulator.markers import compare_markers, read_markers
from kresling.manipulator.model import Manipulator
from kresling.manipulator.motors import TendonDrive
from kresling.manipulator.protocol import protocol_deviations
from kresling.manipulator.synthetic import SHIPPED_FILE
from kresling.manipulator.workspace import workspaces
from kresling.report.section import Check, Section
from kresling.report.thesis_values import L_EQN_30, LE_APPENDIX_E, TABLE5_MIDPOINT_ATOL

__all__ = ["reproduce", "protocol_deviations", "appendix_e_markers"]

logger = logging.getLogger(__name__)

_APPENDIX_E = "thesis Appendix E, config [1 0 1] at L1 = 10 (k = 10)"
#: How the report names what the synthetic marker comparison shows.
_RECOVERY_LABEL = "Pipeline recovery on synthetic data, not a reproduction of the thesis's " \
                  "experiment"


def appendix_e_markers(model: Manipulator, k: float = 10.0) -> np.ndarray:
    """Appendix E's (1 0 1) markers at step k worked out by hand [mm], shape (4, 3): up one
    extended module L, across the flexible module's 30 mm chord at half its bend
    theta = 2 asin(k / d), then L along the bent axis."""
    L, chord = model.extended_length, model.rest_tendon_length
    theta = 2 * math.asin(k / model.tendon_radius)
    m2 = np.array([chord * math.sin(theta / 2), 0.0, L + chord * math.cos(theta / 2)])
    return np.array([[0, 0, 0], [0, 0, L], m2, m2 + L * np.array([math.sin(theta), 0, math.cos(theta)])])


def _ik_success(model: Manipulator, per_configuration: int, seed: int = 11) -> tuple[float, float]:
    """Fraction of FK-sampled targets that the IK reaches within 1e-6 mm, and the worst miss."""
    rng = np.random.default_rng(seed)
    lower, upper = model.tendon_bounds
    reached, total, worst = 0, 0, 0.0
    for configuration in model.configurations:
        if 0 not in configuration:
            continue
        lengths = rng.uniform(lower, upper, (per_configuration, 3))
        targets = np.array([forward_kinematics(model, configuration, l).tip for l in lengths])
        solved = solve_configuration(model, configuration, targets)
        reached += int(np.sum(solved["distance"] < 1e-6))
        total += per_configuration
        worst = max(worst, float(solved["distance"].max()))
    return reached / total, worst


def _write_csv(path: Path, rows: list, columns) -> Path:
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(columns), extrasaction="ignore",
                                lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
    return path


def _figures(section: Section, out_dir: Path, model: Manipulator, measured, comparison,
             grid_points: int) -> None:
    figures = [
        ("fig4_12_configurations.png", plots.plot_configurations(model, 10),
         "Figure 4.12: every configuration at the protocol's full displacement (k = 10)."),
        ("fig4_13_markers.png", plots.plot_marker_comparison(model, measured),
         f"{_RECOVERY_LABEL}. Figure 4.13's comparison: predicted markers against a synthetic "
         f"measured set made from the model with known perturbations (the thesis's raw marker "
         f"data is not published)."),
        ("fig4_14_error.png", plots.plot_marker_errors(comparison),
         f"{_RECOVERY_LABEL}. Figure 4.14's comparison: Euclidean error per marker and step "
         f"against the synthetic measured set."),
        ("fig4_15_normalized_error.png", plots.plot_marker_errors(comparison, normalized=True),
         f"{_RECOVERY_LABEL}. Figure 4.15's comparison: error divided by the predicted length "
         f"from the base (synthetic measured set)."),
        ("workspaces.png", plots.plot_workspaces(workspaces(model, grid_points)).figure,
         "Beyond the thesis: tip workspace of every configuration (tendons 10-40 mm)."),
    ]
    for name, figure, caption in figures:
        figure.savefig(out_dir / name, dpi=110)
        plt.close(figure)
        section.add_figure(out_dir / name, caption)


def reproduce(out_dir, quick: bool = True) -> Section:
    """Reproduce chapter 4's kinematics and Appendix E; write figures and tables.

    Parameters
    ----------
    out_dir : str or Path
        Directory for the PNG figures and CSV tables (created if missing).
    quick : bool, default True
        Fewer inverse-kinematics targets and a coarser workspace grid.

    Returns
    -------
    Section
    """
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    model, drive = Manipulator(), TendonDrive()
    section = Section(
        "Manipulator kinematics (chapter 4, Appendix E)",
        "Jones constant-curvature kinematics of the three-module Kresling arm (eqns 25-30) "
        "with atan2 and safe straight-case forms; Appendix E's configurations and motor "
        "counts; the section 4.3 pseudo-linkage protocol; Table 5's module lengths; the "
        "marker comparison run on a synthetic measured set made from the model with known "
        "perturbations (a pipeline recovery on synthetic data, not a reproduction of the "
        "thesis's experiment); and an inverse-kinematics configuration planner.")

    state = forward_kinematics(model, "101", [10.0, 40.0, 40.0])
    by_hand = appendix_e_markers(model)
    for index, label in ((2, "Coord3"), (3, "Coord4")):
        for axis, name in ((0, "x"), (2, "z")):
            section.checks.append(Check(
                f"(1 0 1), k = 10: marker {index + 1} ({label}) {name}", state.markers[index, axis],
                by_hand[index, axis], _APPENDIX_E + ", worked by hand", atol=1e-9, unit="mm"))
    tip = forward_kinematics(model, "111").tip[2]
    section.checks.append(Check("(1 1 1) tip height", tip, 3 * L_EQN_30, "thesis eqn 30, L = 111.6389",
                                atol=1.5e-4, unit="mm", note="3 x the thesis's 4-decimal L"))
    chord_error, bend_error = protocol_deviations(model)
    section.checks += [
        Check("max |flexible chord - 30 mm|, all configurations, k = 1..10", chord_error, 0.0,
              "section 4.3 (mean tendon length = chord for N = 1)", atol=1e-9, unit="mm"),
        Check("max |bend - 2 asin(k/32)|, all configurations, k = 1..10", bend_error, 0.0,
              "eqns 27-28 under the protocol (sqrt(Q) = 3k)", atol=1e-9, unit="rad"),
        Check("encoder counts per mm", drive.counts_per_mm, 4704 / (math.pi * 20),
              "Appendix E: 4 x 1176 / (pi x 0.02 m)", rtol=1e-15, unit="1/mm"),
    ]
    counts = drive.motor_counts(model, "101", [10.0, 40.0, 40.0])
    cpm = 4 * 1176 / (math.pi * 0.02)
    for motor, tendon in ((1, 3), (2, 2), (3, 1)):
        shortening = 30.0 - (10.0 if tendon == 1 else 40.0)
        section.checks.append(Check(
            f"Appendix E 'Counts {motor}' (tendon {tendon})", counts[motor - 1],
            -shortening * 1 * 0.001 * cpm, _APPENDIX_E, rtol=1e-12, unit="counts"))
    section.checks.append(Check("counts to snap one module", drive.snap_counts(model),
                                (LE_APPENDIX_E - 15) * 2 * 0.001 * cpm,
                                "Appendix E snapCounts", rtol=1e-9, unit="counts",
                                note="our Le (kresling.Design) and Appendix E's differ by 1.6e-10 mm"))

    table5 = joint_length_table(model, read_markers(data.path(SHIPPED_FILE)))
    _write_csv(out_dir / "table5_joint_lengths.csv", table5,
               ("config", "joint", "state", "min_mm", "max_mm", "predicted_min_mm",
                "predicted_max_mm", "inside", "outside_by_mm", "measured_min_mm", "measured_max_mm"))
    section.add_table(out_dir / "table5_joint_lengths.csv",
                      "Table 5 beside the predicted module lengths (and, in the measured "
                      "columns, the synthetic set's: model-generated, not the thesis's "
                      "measurements).")
    for state_code, label, expected in ((1, "extended", model.extended_length),
                                        (0, "contracted", model.rest_tendon_length)):
        middles = [0.5 * (r["min_mm"] + r["max_mm"]) for r in table5 if r["state"] == state_code]
        section.checks.append(Check(
            f"Table 5 mean module length, {label}", float(np.mean(middles)), expected,
            "model (2 Le or the 30 mm chord) vs thesis Table 5 range midpoints",
            atol=TABLE5_MIDPOINT_ATOL,
            unit="mm", note="the thesis reports module lengths varying by up to ~3 mm"))

    measured = read_markers(data.path(SHIPPED_FILE))
    comparison = compare_markers(model, measured)
    summary = comparison.summary()
    _write_csv(out_dir / "marker_errors.csv",
               [dict(config=c, **v) for c, v in summary.items()],
               ("config", "mean_error_mm", "max_error_mm", "max_normalized_error"))
    section.add_table(out_dir / "marker_errors.csv",
                      f"{_RECOVERY_LABEL}: marker errors per configuration against the "
                      f"synthetic measured set.")

    success, worst = _ik_success(model, 10 if quick else 200)
    far = inverse_kinematics(model, [0.0, 0.0, 1000.0])
    section.checks += [
        Check("IK: fraction of FK-sampled targets reached within 1e-6 mm", success, 1.0,
              "round trip through forward kinematics", atol=0.0, note=f"worst miss {worst:.2g} mm"),
        Check("IK: target 1 m up the axis reported unreachable", float(not far.reachable), 1.0,
              "outside every workspace (the arm is 335 mm long)"),
    ]
    _figures(section, out_dir, model, measured, comparison, 5 if quick else 9)
    logger.info("manipulator section: %d checks, %d passed", len(section.checks),
                sum(c.passed for c in section.checks))
    return section
