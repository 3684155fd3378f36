"""``kresling fit``: crease stiffness (``fit crease``) and bending stiffness (``fit bending``)
from laboratory records (thesis sections 3.2-3.3)."""

from __future__ import annotations

import argparse
import re
import sys
from contextlib import contextmanager

from kresling.cli._output import degrees, print_json, print_table


# Units of the per-run columns of 'fit crease' (thesis eqns 17-19).
_CREASE_UNITS = {"k": "N/rad", "F1": "N", "F2": "N", "beta1": "rad", "beta2": "rad",
                 "d": "mm"}


def _pair(text: str) -> tuple:
    key, found, value = text.partition("=")
    if not (found and key.strip() and value.strip()):
        raise argparse.ArgumentTypeError(f"{text!r} is not KEY=VALUE")
    return key.strip(), value.strip()


def _add_reader_options(parser, what: str) -> None:
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument("--column", type=_pair, action="append", default=[],
                        metavar="KEY=HEADER",
                        help=f"header name of a column of the {what}, e.g. force=Load")
    parser.add_argument("--unit", type=_pair, action="append", default=[], metavar="KEY=UNIT",
                        help=f"unit of a column of the {what} whose header has none, "
                             "e.g. force=lbf")
    parser.add_argument("--negate", action="append", default=[], metavar="KEY",
                        help="flip the sign of a record column (compression recorded as "
                             "negative), e.g. --negate force --negate displacement")
    parser.add_argument("--skip-invalid", action="store_true",
                        help="skip (and report) rows with bad cells instead of stopping")
    parser.add_argument("--confidence", type=float, default=0.95,
                        help="level of the confidence intervals, a fraction in (0, 1) "
                             "(default 0.95)")


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "fit", help="crease and bending stiffness from laboratory records",
        description="Fit the thesis's experimental quantities to laboratory records.")
    commands = parser.add_subparsers(dest="what", metavar="WHAT")
    commands.required = True
    crease = commands.add_parser(
        "crease", help="crease torsional stiffness per unit length (eqns 17-19), N/rad",
        description="Summarize a table of per-run crease stiffnesses shaped like the thesis's "
                    "Table 1 (columns sample, run, stiffness_N_per_rad), or fit a list of "
                    "runs (columns sample, run, record, Lp_mm, W_mm and the marker pixels "
                    "vertex_x1_px ... lower_y2_px) whose records are testing-machine exports.")
    crease.add_argument("table", metavar="TABLE.csv")
    _add_reader_options(crease, "table")
    crease.add_argument("--record-column", type=_pair, action="append", default=[],
                        metavar="KEY=HEADER", help="header name of a machine-record column")
    crease.add_argument("--record-unit", type=_pair, action="append", default=[],
                        metavar="KEY=UNIT", help="unit of a machine-record column")
    crease.set_defaults(func=run_crease)
    bending = commands.add_parser(
        "bending", help="bending stiffness K_B per state and the K_B ratio (eqns 20-23)",
        description="Fit K_B (N*m/rad) to bending-test records, one per trial, each a "
                    "testing-machine export with '# state:' and '# module_length:' lines "
                    "(or --state / --module-length).")
    bending.add_argument("records", nargs="+", metavar="RECORD.csv")
    _add_reader_options(bending, "records")
    bending.add_argument("--state", choices=("extended", "contracted", "1", "0"),
                         help="state of every record (overrides the files)")
    bending.add_argument("--module-length", type=float, metavar="MM",
                         help="module length Lm of every record [mm] (overrides the files)")
    bending.add_argument("--method", choices=("intercept", "origin"), default="intercept",
                         help="least-squares line with intercept (default, as a lab fit) or "
                              "through the origin (as the thesis's model code)")
    bending.add_argument("--offset", type=float, default=0.03, metavar="RAD",
                         help="contracted-state fits use angles >= this [rad] (default 0.03 rad = "
                              "1.7 deg)")
    bending.set_defaults(func=run_bending)


@contextmanager
def _option_hints(table=None):
    """Errors from the readers name the command's options, not the library's keywords
    (``names={'force': ...}`` becomes ``--column force=HEADER``); in a crease run's machine
    record (any file but ``table``) the ``--record-...`` options."""
    from kresling.fits.records import RecordError

    try:
        yield
    except RecordError as error:
        record = table is not None and error.path != str(table)
        raise RecordError(error.path, error.line, error.column,
                          _hint(error.problem, record)) from None


def _hint(problem: str, record: bool = False) -> str:
    """A reader's ``problem`` with its keyword hints as the command's options."""
    column, unit = ("--record-column", "--record-unit") if record else ("--column", "--unit")
    problem = re.sub(r"names=\{'(\w+)': \.\.\.\}", rf"{column} \1=HEADER", problem)
    problem = re.sub(r"units=\{'(\w+)': \.\.\.\}", rf"{unit} \1=UNIT", problem)
    problem = problem.replace("pick one with names=", f"pick one with {column} KEY=HEADER")
    return problem.replace("units= says", f"{unit} says")


def _records_only(paths, args) -> list:
    """``paths`` without the files that are not bending records at all: no '#' metadata line
    and no force or displacement column (like the examples' truth.csv, which a glob such as
    ``DIR/*.csv`` picks up); each skipped file is named on stderr. A file that is a record
    with a column the reader cannot find is kept, so that its error says what to do."""
    from kresling.fits.records import RecordError, read_machine_record

    kept = []
    for path in paths:
        try:
            read_machine_record(path, **_reader_options(args))
        except RecordError as error:
            if "no column named" in error.problem and not _has_metadata(path):
                print(f"kresling fit: skipped {path}: not a bending record (no '# state:' "
                      f"line, and {_hint(error.problem)})", file=sys.stderr)
                continue
        kept.append(path)
    return kept or list(paths)   # none left: fit them all, so that the error is reported


def _has_metadata(path) -> bool:
    try:
        with open(path, encoding="utf-8", errors="replace") as f:
            return any(line.lstrip().startswith("#") for line in f)
    except OSError:
        return True   # cannot tell: keep it, the reader reports the problem


def _reader_options(args) -> dict:
    return {"names": dict(args.column), "units": dict(args.unit),
            "on_invalid": "skip" if args.skip_invalid else "raise"}


def run_crease(args) -> int:
    from kresling.fits.crease_files import fit_crease_file

    options = _reader_options(args)
    if args.record_column or args.record_unit or args.negate:
        options.update(record_names=dict(args.record_column),
                       record_units=dict(args.record_unit), negate=tuple(args.negate))
    with _option_hints(args.table):
        result = fit_crease_file(args.table, confidence=args.confidence, **options)
    report = result.as_dict()
    if args.json:
        print_json(report)
        return 0
    keys = [k for k in ("sample", "run", "k", "F1", "F2", "beta1", "beta2", "d")
            if k in report["runs"][0]]
    # Headers with units; the panel angles beta in degrees beside radians.
    headers, rows = [], [[] for _ in report["runs"]]
    for key in keys:
        headers.append(f"{key} [{_CREASE_UNITS[key]}]" if key in _CREASE_UNITS else key)
        for row, run in zip(rows, report["runs"]):
            row.append(run[key])
        if key.startswith("beta"):
            headers.append("[deg]")
            for row, run in zip(rows, report["runs"]):
                row.append(degrees(run[key]))
    print_table(rows, headers)
    print()
    _print_summary("k [N/rad], all runs", result.overall)
    if result.between_samples:
        _print_summary("k [N/rad], sample means", result.between_samples)
    flagged = ", ".join(f"sample {o['sample']} run {o['run']}" for o in report["outliers"])
    print(f"outliers, {report['outlier_rule']}: {flagged or 'none'}")
    _print_skipped(report["skipped"])
    return 0


def run_bending(args) -> int:
    from kresling.fits.bending_files import fit_bending_files

    with _option_hints():
        records = _records_only(args.records, args)
        result = fit_bending_files(records, state=args.state,
                                   module_length=args.module_length, negate=tuple(args.negate),
                                   method=args.method, contracted_offset=args.offset,
                                   confidence=args.confidence, **_reader_options(args))
    report = result.as_dict()
    if args.json:
        print_json(report)
        return 0
    print_table([[f.source, f.state, f.K, f.intercept, f.offset, degrees(f.offset), f.points]
                 for fits in result.fits.values() for f in fits],
                ("record", "state", "K_B [N*m/rad]", "intercept [N*m]", "offset [rad]",
                 "[deg]", "points"))
    print()
    for state, summary in result.summaries.items():
        _print_summary(f"K_B {state} [N*m/rad]", summary)
    if result.ratio and result.summaries["contracted"].n > 1 < result.summaries["extended"].n:
        print(f"K_B ratio: {result.ratio.value:.4g} ± {result.ratio.sd:.2g} (SD), "
              f"± {result.ratio.se:.2g} (SE); first-order propagation")
    elif result.ratio:
        print(f"K_B ratio: {result.ratio.value:.4g} (one trial in a state: no uncertainty)")
    _print_skipped(report["skipped"])
    return 0


def _print_summary(name: str, summary) -> None:
    spread = "" if summary.n < 2 else (
        f" ± {summary.sd:.4g} (SD), {summary.confidence:.0%} CI "
        f"[{summary.ci[0]:.4g}, {summary.ci[1]:.4g}] (Student t)")
    print(f"{name}: {summary.mean:.4g}{spread}, n = {summary.n}")


def _print_skipped(skipped: dict) -> None:
    print(f"skipped lines: {skipped['count']}")
    for row in skipped["rows"]:
        print(f"  {row}")
