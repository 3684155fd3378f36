"""Write synthetic records to disk in the file shapes the readers take, with their truth.

The example sets shipped in ``kresling/data/examples/`` are made by running this module::

    python -m kresling.fits.synthetic_files kresling/data/examples
"""

from __future__ import annotations

import argparse
import csv
import logging
from dataclasses import replace
from pathlib import Path

import numpy as np

from kresling.fits.crease import MARKERS
from kresling.fits.synthetic import (BendingRig, CreaseRig, synthetic_bending_trials,
                                     synthetic_crease_runs)
from kresling.geometry import Design

__all__ = ["write_machine_record", "write_crease_example", "write_bending_example",
           "EXAMPLE_SEED"]

logger = logging.getLogger(__name__)

#: Seed of the shipped example sets.
EXAMPLE_SEED = 20240306


def write_machine_record(path, time, displacement, force, metadata=None,
                         force_format: str = "%.5f") -> None:
    """Write a testing-machine export: ``# key: value`` lines, then
    ``time_s,displacement_mm,force_N`` (arrays of shape (m,))."""
    lines = [f"# {key}: {value}" for key, value in (metadata or {}).items()]
    lines.append("time_s,displacement_mm,force_N")
    row = f"%.2f,%.4f,{force_format}"
    lines += [row % values for values in zip(time, displacement, force)]
    Path(path).write_text("\n".join(lines) + "\n")


def write_crease_example(directory, *, kf: float = 0.047, seed: int = EXAMPLE_SEED,
                         rig: CreaseRig = replace(CreaseRig(), sample_rate=5.0)) -> Path:
    """Write a synthetic crease test (5 samples x 3 runs) of true stiffness ``kf`` (N/rad):
    ``runs.csv`` (the list of runs), one record per run, and ``truth.csv``.

    Returns
    -------
    Path
        The list of runs.
    """
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    runs, truth = synthetic_crease_runs(kf, np.random.default_rng(seed), rig=rig)
    header = ["sample", "run", "record", "Lp_mm", "W_mm"]
    header += [f"{m}_{axis}{frame}_px" for frame in (1, 2) for m in MARKERS for axis in "xy"]
    rows = []
    for run in runs:
        name = f"s{run.sample}_r{run.run}.csv"
        write_machine_record(directory / name, rig.times(), run.displacement, run.force,
                             {"synthetic": f"crease sample {run.sample} run {run.run}"})
        markers = np.concatenate([run.markers_first.ravel(), run.markers_last.ravel()])
        rows.append([run.sample, run.run, name, f"{run.Lp:.2f}", f"{run.W:.1f}",
                     *(f"{v:.1f}" for v in markers)])
    _write_rows(directory / "runs.csv", header, rows)
    _write_rows(directory / "truth.csv", ["sample", "run", "kf_N_per_rad"],
                [[r.sample, r.run, f"{k:.6g}"] for r, k in zip(runs, truth)])
    return directory / "runs.csv"


def write_bending_example(directory, *, design: Design = Design(8, 0.8, 30.0),
                          K=(3.50, 0.80), trial_cv=(0.083, 0.0875), seed: int = EXAMPLE_SEED,
                          rig: BendingRig = replace(BendingRig(), sample_rate=5.0)) -> list:
    """Write synthetic bending trials, three per state, and ``truth.csv``.

    Defaults: the design of the thesis's figure 3.5 with Table 3's experimental means
    (3.50 and 0.80 N*m/rad) and relative SDs as truth; module lengths 2 Le and 2 Lc.

    Returns
    -------
    list of Path
        The trial records.
    """
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    rng = np.random.default_rng(seed)
    paths, truth_rows = [], []
    for state, K_state, cv, length in (("extended", K[0], trial_cv[0], 2 * design.Le),
                                       ("contracted", K[1], trial_cv[1], 2 * design.Lc)):
        trials, truth = synthetic_bending_trials(K_state, state, round(length, 2), rng,
                                                 trial_cv=cv, rig=rig)
        for index, (trial, K_true) in enumerate(zip(trials, truth), start=1):
            path = directory / f"{state}_{index}.csv"
            write_machine_record(path, rig.times(), trial.displacement, trial.force,
                                 {"state": state,
                                  "module_length": f"{trial.module_length:.2f} mm"},
                                 force_format="%.4f")
            paths.append(path)
            truth_rows.append([path.name, state, f"{K_true:.6g}"])
    _write_rows(directory / "truth.csv", ["record", "state", "K_B_Nm_per_rad"], truth_rows)
    return paths


def _write_rows(path: Path, header, rows) -> None:
    with open(path, "w", newline="") as handle:
        writer = csv.writer(handle, lineterminator="\n")
        writer.writerow(header)
        writer.writerows(rows)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description="Write the synthetic example record sets.")
    parser.add_argument("directory", type=Path, help="e.g. kresling/data/examples")
    args = parser.parse_args(argv)
    write_crease_example(args.directory / "synthetic_crease")
    write_bending_example(args.directory / "synthetic_bending")
    return 0


if __name__ == "__main__":  # pragma: no cover
    raise SystemExit(main())
