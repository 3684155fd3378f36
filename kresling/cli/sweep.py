"""``kresling sweep``: the parametric study over n x Lc x lambda, resumable.

Writes ``DIR/results.csv`` (columns ``n, Lc, lam, R``, every metric's columns, ``status``,
``reason``, ``iterations``, ``seconds``, ``index``) and ``DIR/manifest.json``; prints the
maximum of each metric per n and the optimum. Running the same command again resumes: only
designs missing from ``DIR/results.csv`` are computed. Progress bar and warnings on stderr.
"""

from __future__ import annotations

import logging
import sys
from pathlib import Path

from kresling.cli._output import check_output_folder, log_to_stderr, print_table
from kresling.cli._specimen import (add_specimen_arguments, specimen_parameters_from_args,
                                    summary_line)


def register(subparsers) -> None:
    from kresling.sweeps import DEFAULT_METRICS, METRICS, THESIS_LAM, THESIS_N

    parser = subparsers.add_parser(
        "sweep",
        help="parametric study over n x Lc x lambda (thesis section 3.4-3.5)",
        description="Compute metrics over an evenly spaced Lc x lambda grid for each n, in "
                    "parallel, writing DIR/results.csv as it goes; run again with the same "
                    "--out to resume. Metrics: " + "; ".join(
                        f"{name}: {m.description}" for name, m in METRICS.items()) + ".",
    )
    parser.add_argument("--n", type=int, nargs="+", default=list(THESIS_N),
                        help="sides of the base polygon, counts (default: 4 6 8 10)")
    parser.add_argument("--grid", type=int, nargs="+", default=[100], metavar="G",
                        help="grid points along Lc and lambda, counts: one number for both, or "
                             "two (default 100, the thesis's)")
    parser.add_argument("--Lc", type=float, nargs=2, metavar=("MIN", "MAX"),
                        help="contracted-height range [mm] (default R/2 to 2R)")
    parser.add_argument("--lam", type=float, nargs=2, metavar=("MIN", "MAX"),
                        default=list(THESIS_LAM),
                                     help="angle-ratio range, dimensionless (default 0.7 0.9)")
    parser.add_argument("--R", type=float, default=30.0, help="circumradius [mm] (default 30)")
    parser.add_argument("--metrics", nargs="+", default=list(DEFAULT_METRICS),
                        metavar="METRIC", help=f"any of {', '.join(METRICS)} "
                                               f"(default: {' '.join(DEFAULT_METRICS)})")
    parser.add_argument("--workers", type=int,
                        help="parallel workers, a count (default: every core)")
    parser.add_argument("--executor", choices=("threads", "processes"), default="threads",
                        help="run designs on threads (default; the C++ releases the GIL) or "
                             "on a process pool")
    parser.add_argument("--scheduler", metavar="ADDRESS",
                        help="run on a dask.distributed cluster (e.g. tcp://host:8786; "
                             "needs the 'dask' extra)")
    parser.add_argument("--chunk-size", type=int,
                        help="designs per task, a count (default: automatic)")
    parser.add_argument("--out", required=True, metavar="DIR",
                        help="directory of results.csv and manifest.json (resumed if present)")
    parser.add_argument("--plot", action="store_true",
                        help="also write heat maps of every metric and the maxima by n as PNG")
    parser.add_argument("--no-progress", dest="progress", action="store_false",
                        help="no progress bar")
    parser.add_argument("--verbose", action="store_true", help="log the sweep's progress")
    add_specimen_arguments(parser)
    parser.set_defaults(func=run)


def run(args) -> int:
    from kresling.sweeps import design_grid, resolve_metrics, sweep

    metrics = resolve_metrics(args.metrics)
    parameters = specimen_parameters_from_args(args)
    check_output_folder("--out", args.out)   # before the sweep, not after
    if len(args.grid) > 2:
        raise ValueError(f"--grid takes one or two numbers, got {len(args.grid)}")
    grid = design_grid(args.n, args.grid, Lc=args.Lc, lam=args.lam, R=args.R)
    client = _client(args.scheduler) if args.scheduler else None
    executor = client if client is not None else args.executor
    level = logging.INFO if args.verbose else logging.WARNING
    with log_to_stderr("kresling.sweeps", "sweep", level):
        try:
            table = sweep(grid, metrics, workers=args.workers, executor=executor, out=args.out,
                          progress=args.progress, chunk_size=args.chunk_size,
                          parameters=parameters)
        except RuntimeError as error:
            print(f"kresling sweep: error: {error}", file=sys.stderr)
            return 1
        finally:
            if client is not None:
                client.close()
    _print_summary(table, metrics, Path(args.out))
    print(f"\n{summary_line(parameters)}")
    if args.plot:
        _plot(table, metrics, Path(args.out))
    return 0


def _print_summary(table, metrics, out: Path) -> None:
    a = table.attrs
    failed = int((~table.ok).sum())
    print(f"{len(table)} designs: {a['computed']} computed, {a['loaded']} read back from "
          f"{out / 'results.csv'}, {failed} failed; {a['seconds']:.1f} s on {a['workers']} "
          f"worker{'s' if a['workers'] > 1 else ''}")
    for metric in metrics:
        rows = []
        for n in sorted({int(n) for n in table["n"]}):
            try:
                best = table.best(metric.name, n=n)
            except ValueError:
                rows.append((n, "-", "-", "-", "-"))
                continue
            rows.append((n, f"{best[metric.name]:.6g}", f"{best['Lc']:.6g}", f"{best['lam']:.6g}",
                         ", ".join(best["boundary"]) or "-"))
        print(f"\nmaximum {metric.name} by n")
        print_table(rows, ("n", metric.name, "Lc [mm]", "lam", "on boundary"))
    main = metrics[0].name
    try:
        best = table.best(main)
        print(f"\noptimum ({main}): n = {best['n']}, Lc = {best['Lc']:.6g} mm, "
              f"lam = {best['lam']:.6g}: {main} = {best[main]:.6g}")
        if best["boundary"]:
            print(f"on the boundary of the searched domain ({', '.join(best['boundary'])}): a "
                  f"better design may lie outside it; widen --n, --Lc or --lam to find out")
    except ValueError:
        print(f"\noptimum ({main}): no design succeeded")
    if failed:
        first = table.take(~table.ok).row(0)
        print(f"kresling sweep: {failed} design(s) failed, e.g. n = {first['n']}, Lc = "
              f"{first['Lc']:.6g}, lam = {first['lam']:.6g}: {first['reason']}", file=sys.stderr)


def _plot(table, metrics, out: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from kresling.sweeps.plots import plot_max_by_n, plot_maps

    for metric in metrics:
        figure = plot_maps(table, metric.name)
        figure.savefig(out / f"{metric.name}_maps.png", dpi=120)
        plt.close(figure)
        ax = plot_max_by_n(table, metric.name)
        ax.figure.savefig(out / f"{metric.name}_max_by_n.png", dpi=120)
        plt.close(ax.figure)
    print(f"figures: {out}/<metric>_maps.png, {out}/<metric>_max_by_n.png")


def _client(address: str):
    try:
        from distributed import Client
    except ImportError:
        raise ImportError("--scheduler needs dask.distributed: "
                          "pip install 'kresling[dask]'") from None
    return Client(address)
