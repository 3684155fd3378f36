"""The thesis's experimental data (sections 3.2-3.3) recomputed, and how far the fitting
pipelines can be trusted, measured on synthetic records of known truth.

Prints: Table 1's summary and what its runs show beyond it; Table 3's experimental ratios
recomputed from its means; the crease pipeline's error and confidence-interval coverage
under the instrument noise model, and under Table-1-like scatter between samples and runs;
K_B recovery with and without the contracted-state offset. Draws the report figures.

Run: ``python studies/experimental_fits.py [--repetitions 1000] [--out out/experimental_fits]``
"""

import argparse
from pathlib import Path

import numpy as np
from scipy import stats

from kresling import data
from kresling.data.tables import merlin2_model_curves
from kresling.fits.recovery import bending_recovery, crease_recovery
from kresling.fits.thesis_tables import largest_sd_under_rounding, table1, table3
from kresling.report.sections.experiments import reproduce

KF = 0.047  # N/rad


def print_table1() -> None:
    result = table1()
    s, k = result.overall, result.k
    print("Table 1 (thesis: mean 0.047, SD 0.011 N/rad)")
    print(f"  mean {s.mean:.5f}  sample SD {s.sd:.5f}  population SD {k.std():.5f}  "
          f"largest SD the rounding allows {largest_sd_under_rounding(k, 5e-4):.5f}")
    print(f"  95% CI over runs [{s.ci[0]:.4f}, {s.ci[1]:.4f}]; over sample means "
          f"[{result.between_samples.ci[0]:.4f}, {result.between_samples.ci[1]:.4f}]")
    runs = result.runs.astype(int)
    print("  mean by run number: " + ", ".join(f"run {r}: {k[runs == r].mean():.4f}"
                                               for r in (1, 2, 3)))
    paired = stats.ttest_rel(k[runs == 3], k[runs == 1])
    print(f"  run 3 - run 1 within samples: t = {paired.statistic:.2f}, p = {paired.pvalue:.3f}")
    lengths = np.genfromtxt(data.path("thesis_table1_crease_stiffness.csv"), delimiter=",",
                            names=True)["length_mm"]
    r, p = stats.pearsonr(lengths, k)
    slope = stats.linregress(lengths, k).slope
    print(f"  k vs measured Lp: r = {r:.2f} (p = {p:.1g}), slope {slope * 1e3:.2f} mN/rad per mm")
    anova = stats.f_oneway(*(k[result.samples == s] for s in result.per_sample))
    print(f"  between-sample differences (one-way ANOVA): F = {anova.statistic:.2f}, "
          f"p = {anova.pvalue:.3f}")


def print_table3() -> None:
    print("\nTable 3 experimental K_B ratio: printed vs recomputed from the printed means")
    for row in table3():
        ratio, (low, high) = row.ratio_of_means, row.ratio_rounding_range
        flag = "" if row.listed_ratio_consistent else "   <- printed ratio inconsistent"
        sd = f"± {ratio.sd:.2f} (SD)" if np.isfinite(ratio.sd) else "(no SD printed)"
        print(f"  {row.label:38s} printed {row.ratio_listed:6.2f}  recomputed {ratio.value:6.2f}"
              f" {sd:15s}  rounding allows {low:.2f}-{high:.2f}{flag}")


def print_crease_recovery(repetitions: int) -> None:
    print(f"\nCrease pipeline on {repetitions} synthetic data sets (5 samples x 3 runs, "
          f"kf = {KF} N/rad)")
    scenarios = (("instrument noise only", {}),
                 ("+ 20 % between runs", {"run_cv": 0.20}),
                 ("+ 15 % between samples and runs", {"sample_cv": 0.15, "run_cv": 0.15}))
    print(f"  {'scenario':34s} {'bias':>7s} {'SD':>7s} {'|err|<2%':>9s} "
          f"{'CI runs':>8s} {'CI samples':>10s}")
    for index, (name, options) in enumerate(scenarios):
        rec = crease_recovery(KF, repetitions, seed=100 + index, **options)
        e = rec.relative_errors
        print(f"  {name:34s} {e.mean():7.2%} {e.std():7.2%} {np.mean(np.abs(e) < 0.02):9.1%} "
              f"{rec.coverage:8.1%} {rec.coverage_between_samples:10.1%}")


def print_bending_recovery() -> None:
    print("\nK_B recovery, worst relative error of 3 synthetic trials")
    cases = (("extended, all points, intercept", dict(K=3.5, state=1, module_length=110.6)),
             ("extended, all points, origin", dict(K=3.5, state=1, module_length=110.6,
                                                   method="origin")),
             ("contracted + rise, past 0.03 rad", dict(K=0.8, state=0, module_length=60.0)),
             ("contracted + rise, from 0 rad", dict(K=0.8, state=0, module_length=60.0,
                                                    offset=0.0)),
             ("contracted + rise, origin, from 0", dict(K=0.8, state=0, module_length=60.0,
                                                        offset=0.0, method="origin")),
             ("contracted, no rise, from 0 rad", dict(K=0.8, state=0, module_length=60.0,
                                                      offset=0.0, rise=False)))
    for name, case in cases:
        errors = bending_recovery(seed=5, **case)
        print(f"  {name:36s} {errors[np.argmax(np.abs(errors))]:+8.2%}")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repetitions", type=int, default=1000)
    parser.add_argument("--out", type=Path, default=Path("out/experimental_fits"),
                        help="where the report figures and tables go")
    parser.add_argument("--no-figures", action="store_true")
    args = parser.parse_args(argv)
    print_table1()
    print_table3()
    print_crease_recovery(args.repetitions)
    print_bending_recovery()
    if args.no_figures:
        return 0
    # Against the MERLIN2 reference runs' curves (the report uses our own bending test's).
    section = reproduce(args.out, quick=args.repetitions < 1000,
                        model_curves=merlin2_model_curves())
    print(f"\nReport section: {sum(c.passed for c in section.checks)} of "
          f"{len(section.checks)} checks pass; figures and tables in {args.out}/")
    for check in section.checks:
        print(f"  {'ok ' if check.passed else 'NO '} {check.name}: {check.value:.4g} vs "
              f"{check.reference:.4g}" + (f"  ({check.note})" if not check.passed else ""))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
