"""Time to read and build the model of large patterns: one big polygon under N5B8 and an
inline grid of quads.

For each case, prints the pattern's size, the time to read and check the problem
(``load_problem``: TOML and the pattern's checks) and to build its model
(``build_problem_model``: panel elements, calibration, rest angles), best of ``--repeat``
runs. The polygon's N5B8 centre follows MERLIN2's rule (the point nearest to all its
diagonals); the grid is ``n x n`` unit quads given inline with an auto-calibrated sheet.

Run: ``python benchmarks/large_patterns.py`` (``--quick``: the smaller cases only). With
``--python OTHER/.venv/bin/python`` the same cases are also timed with another checkout's
interpreter, side by side in this run (a case over ``--timeout`` seconds shows ">").
"""

from __future__ import annotations

import argparse
import json
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path

POLYGONS = (64, 100, 300)
GRIDS = (40, 80, 100)
SHEET = ('[material]\ncalibration = "auto"\nE = 1000.0\nnu = 0.3\nthickness = 0.25\n'
         '[[support]]\nnodes = [0, 1]\nfix = "xyz"\n[[support]]\nnode = {c}\nfix = "z"\n'
         '[[load]]\nnode = {last}\nforce = [0.0, 0.0, 0.001]\n'
         '[analysis]\nmethod = "force_control"\nsteps = 1\n')


def polygon_problem(corners: int) -> str:
    vertices = [[round(50 * math.cos(2 * math.pi * k / corners), 12),
                 round(50 * math.sin(2 * math.pi * k / corners), 12), 0.0]
                for k in range(corners)]
    return (f"[pattern]\nvertices = {vertices}\npanels = [{list(range(corners))}]\n"
            + SHEET.format(c=corners // 3, last=corners // 2))


def grid_problem(n: int) -> str:
    vertices = [[float(i), float(j), 0.0] for j in range(n + 1) for i in range(n + 1)]
    panels = [[j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1,
               (j + 1) * (n + 1) + i] for j in range(n) for i in range(n)]
    return (f"[pattern]\nvertices = {vertices}\npanels = {panels}\n"
            + SHEET.format(c=n + 1, last=(n + 1) ** 2 - 1))


def time_case(path: str, repeat: int) -> dict:
    """Best read and build times [s] of one problem file, in this interpreter."""
    from kresling.simulate import build_problem_model, load_problem

    read = build = math.inf
    for _ in range(repeat):
        start = time.perf_counter()
        problem = load_problem(path)
        middle = time.perf_counter()
        model = build_problem_model(problem).model
        read, build = min(read, middle - start), min(build, time.perf_counter() - middle)
    return {"read": read, "build": build, "nodes": model.num_nodes}


def timed_elsewhere(python: str, path: Path, repeat: int, timeout: float) -> dict:
    # This script under the other interpreter, timing the one case (--case).
    command = [python, str(Path(__file__).resolve()), "--case", str(path), "--repeat",
               str(repeat)]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"read": math.nan, "build": math.nan, "over": timeout}
    if done.returncode:
        return {"read": math.nan, "build": math.nan, "error": done.stderr.strip()[-60:]}
    return json.loads(done.stdout.splitlines()[-1])


def cell(result: dict) -> str:
    if "over" in result:
        return f"> {result['over']:.0f}"
    if "error" in result:
        return "failed"
    return f"{result['read'] + result['build']:.2f}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--quick", action="store_true")
    parser.add_argument("--python", help="another checkout's interpreter, timed beside")
    parser.add_argument("--timeout", type=float, default=120.0)
    parser.add_argument("--case", help="time this one problem file and print its JSON")
    args = parser.parse_args()
    if args.case:
        print(json.dumps(time_case(args.case, args.repeat)))
        return
    cases = [(f"{m}-gon, N5B8", polygon_problem(m)) for m in POLYGONS[:2 if args.quick else 3]]
    cases += [(f"{n} x {n} grid inline", grid_problem(n)) for n in GRIDS[:2 if args.quick else 3]]
    header = f"{'case':<24} {'nodes':>7} {'read [s]':>9} {'build [s]':>10}"
    print(header + (f" {'other [s]':>10} {'ratio':>7}" if args.python else ""))
    with tempfile.TemporaryDirectory() as folder:
        for label, text in cases:
            path = Path(folder) / "problem.toml"
            path.write_text(text)
            ours = time_case(str(path), args.repeat)
            line = f"{label:<24} {ours['nodes']:>7} {ours['read']:>9.2f} {ours['build']:>10.2f}"
            if args.python:
                other = timed_elsewhere(args.python, path, args.repeat, args.timeout)
                total = ours["read"] + ours["build"]
                ratio = (other["read"] + other["build"]) / total
                line += f" {cell(other):>10} {ratio:>7.1f}" if math.isfinite(ratio) else \
                    f" {cell(other):>10} {'-':>7}"
            print(line, flush=True)


if __name__ == "__main__":
    sys.exit(main())
