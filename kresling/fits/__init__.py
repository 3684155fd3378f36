"""Experimental data: crease stiffness and bending stiffness from laboratory records
(thesis sections 3.2-3.3, eqns 17-23), with uncertainty.

Crease stiffness (eqns 17-19)::

    from kresling import fits
    result = fits.fit_crease_file("runs.csv")        # a list of runs, or a Table-1 table
    result.overall.mean, result.overall.sd, result.overall.ci     # N/rad

Bending stiffness (eqns 20-23)::

    result = fits.fit_bending_files(["ext1.csv", "ext2.csv", "con1.csv", ...])
    result.K, result.ratio                                       # N*m/rad per state, ratio

Conventions: sample SD (n-1); Student-t confidence intervals; outliers flagged by the
modified z-score (``|z| > 3.5``), never removed; experimental K_B from a least-squares line
with intercept, model K_B through the origin; contracted-state fits past 0.03 rad.
Synthetic records of known truth (:mod:`kresling.fits.synthetic`) test all of it.
"""

from kresling.fits.bending import (CONTRACTED_OFFSET, BendingStiffness, BendingTrial,
                                   BendingTrialFit, fit_bending, fit_bending_trial, mean_curve,
                                   model_stiffness, moment_and_angle)
from kresling.fits.bending_files import fit_bending_files, read_bending_trial
from kresling.fits.crease import (CreaseRun, CreaseRunFit, CreaseStiffness, fit_crease_run,
                                  fit_crease_runs, panel_angle, summarize_crease)
from kresling.fits.crease_files import fit_crease_file, read_crease_runs, read_stiffness_table
from kresling.fits.records import RecordError, SkippedRow, read_machine_record, read_table
from kresling.fits.statistics import Ratio, Summary, flag_outliers, ratio_of_means, summarize

__all__ = [
    "CONTRACTED_OFFSET", "BendingStiffness", "BendingTrial", "BendingTrialFit", "fit_bending",
    "fit_bending_trial", "mean_curve", "model_stiffness", "moment_and_angle",
    "fit_bending_files", "read_bending_trial", "CreaseRun", "CreaseRunFit", "CreaseStiffness",
    "fit_crease_run", "fit_crease_runs", "panel_angle", "summarize_crease", "fit_crease_file",
    "read_crease_runs", "read_stiffness_table", "RecordError", "SkippedRow",
    "read_machine_record", "read_table", "Ratio", "Summary", "flag_outliers",
    "ratio_of_means", "summarize",
]
