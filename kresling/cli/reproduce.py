"""``kresling reproduce``: run every part of the thesis the package covers and write a report.

Writes ``DIR/report.html`` (self-contained), ``DIR/report.json`` and the figures and tables
behind them; prints one line per section and the report's path. Progress (a line as each
section starts and ends) goes to stderr. Exit status: 0 when every section ran, whatever its
checks say (checks outside tolerance are findings, shown in the report); 1 when a section
raised; 2 for bad arguments.
"""

from __future__ import annotations

import shlex
import sys

from kresling.cli._output import check_output_folder, log_to_stderr, print_table

_PROGRESS_LOGGER = "kresling.report.runner"


def register(subparsers) -> None:
    parser = subparsers.add_parser(
        "reproduce",
        help="reproduce the thesis's tables and figures as an HTML report",
        description="Run every part of the thesis the package reproduces (geometry, "
                    "experiments, bending analyses, parametric study, fabrication, "
                    "manipulator), compare each number with the thesis's within a stated "
                    "tolerance, and write DIR/report.html, DIR/report.json and the figures "
                    "and tables behind them.",
    )
    mode = parser.add_mutually_exclusive_group()
    mode.add_argument("--quick", dest="quick", action="store_true", default=True,
                      help="coarser grids, fewer steps where the answer does not move "
                           "(default; a few minutes at most)")
    mode.add_argument("--full", dest="quick", action="store_false",
                      help="the thesis's full resolution (much slower)")
    parser.add_argument("--out", default="report", metavar="DIR",
                        help="directory of the report (default: report)")
    parser.add_argument("--only", nargs="+", metavar="NAME",
                        help="run only these sections (see --list)")
    parser.add_argument("--list", action="store_true",
                        help="list the sections and whether their code exists, then exit")
    parser.set_defaults(func=run)


def run(args) -> int:
    from kresling.report import chapters

    if args.list:
        return _list(chapters.CHAPTERS)
    check_output_folder("--out", args.out)   # before the analyses, not after
    import matplotlib

    matplotlib.use("Agg")  # files only: never open a window
    from kresling.report.build import build_report

    with log_to_stderr(_PROGRESS_LOGGER, "reproduce"):
        report = build_report(args.out, quick=args.quick, only=args.only,
                              command=_command(args))
    rows = [(run.chapter.key, run.chapter.part, run.checks_text, f"{run.seconds:.1f}",
             run.outcome) for run in report.runs]
    print_table(rows, ("section", "thesis", "checks", "seconds", "outcome"))
    print(f"\n{report.checks_passed}/{report.checks_total} checks passed in "
          f"{report.seconds:.1f} s ({'quick' if report.quick else 'full'})")
    print(f"report: {report.html_path}")
    print(f"data:   {report.json_path}")
    if report.errors:
        keys = ", ".join(run.chapter.key for run in report.errors)
        print(f"kresling reproduce: error: {len(report.errors)} section(s) raised: {keys} "
              f"(tracebacks in the report)", file=sys.stderr)
        return 1
    return 0


def _list(all_chapters) -> int:
    from kresling.report.chapters import SectionNotAvailable

    rows = []
    for chapter in all_chapters:
        try:
            chapter.load()
            status = "available"
        except SectionNotAvailable:
            status = "not yet available"
        except Exception as error:  # noqa: BLE001 - shown, not raised: this is a listing
            status = f"broken: {type(error).__name__}: {error}"
        rows.append((chapter.key, chapter.part, status, chapter.title))
    print_table(rows, ("name", "thesis", "status", "title"))
    return 0


def _command(args) -> str:
    """The command line that makes this report again."""
    words = ["kresling", "reproduce", "--quick" if args.quick else "--full", "--out", args.out]
    if args.only:
        words += ["--only", *args.only]
    return shlex.join(words)
