"""Folding crease patterns from flat the way a new user would: the whole file, every crease
to the file's own fold angle, nothing else said.

Each pattern is posed as the shortest fold problem there is::

    {"pattern": {"file": PATH},
     "actuation": [{"family": "fold", "fold_angle_deg": "file"}],
     "analysis": {"method": "fold"}}

and tried exactly so first. Where the package refuses it because something is missing,
what it asks for is added and the fold tried again: a material (``--material``), the
number of increments (``--steps``) or supports (``--support``); the table says what was
added. The materials (N, mm):

- ``stiff``: stiff bars (bar_modulus 1e5 N/mm^2, bar_area 1 mm^2), creases of 1 N mm/rad
  per mm and panels as stiff in bending;
- ``soft``: Origami Simulator's ingredients in this model's units (docs/folding.md,
  'Folding from flat'): the same creases and panels, bars of EA = 20 / 0.7 N and
  face-angle springs of 0.2 R / 0.7 N mm/rad^2, R the radius of the circle about the
  sheet's bounding box's centre through its farthest vertex [mm].

``--support auto`` holds the corners of the first panel in x, y and z (no rigid-body
motion, no crease blocked); ``--support none`` never adds supports.

Each pattern is folded in a process of its own, stopped after ``--timeout`` seconds of
wall time. Columns: the pattern's vertices and edges (``kresling.io.read_pattern``);
built: yes, or the first line of the refusal (for a file that cannot be read, the reader's
message; at most 80 characters); what was added to the problem, the material and supports
used; the increments and Newton iterations of the path; reached: the fold's load factor at
the end in percent of the targets; the creases more than 1 deg short of their targets and
those folded the other way, of the creases driven (``Simulation.fold_report``); the
seconds of the attempt that ran (reading, building and folding); the outcome: completed,
failed (the path's message, at most 80 characters) or timeout. The full refusals and
messages follow the table.

Run: ``python benchmarks/fold_patterns.py [FILE ...] [--material stiff|soft]
[--support auto|none] [--steps 50] [--assets DIR] [--large] [--timeout 60] [--jobs 1]
[--no-relax]``; ``--no-relax`` folds each with ``[analysis] relax = false`` (the equilibrium
path, stable or not, where a new user's fold relaxes the increments it cannot follow stably).
With no FILE: the Origami Simulator files under tests/data/public/origami_simulator/ and,
with ``--assets DIR`` (a checkout of Origami Simulator's assets folder), nineteen of its
patterns; with ``--large`` and ``--assets DIR``, its large patterns only (1,000 to 6,400
edges: the box-pleated ones, the circular pleat, the hex-tri tessellation), each as a new
user folds it (nothing but the pattern), with two further columns: ``tried``, the Newton
iterations of every increment tried (those given up and halved too), and ``first``, the
seconds to the first converged increment (reading and building the model, and that
increment). A fold stopped by the timeout shows what the files it wrote as it went hold:
its increments, their Newton iterations and the fold fraction reached.
"""

from __future__ import annotations

import argparse
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
VENDORED = ROOT / "tests" / "data" / "public" / "origami_simulator"
#: Patterns of Origami Simulator's assets folder, by their paths in it.
ASSETS = ("Bases/frogBase.svg", "Bases/squareBase.svg", "Bases/pinwheelBase.svg",
          "Origami/traditionalCrane.svg", "Origami/langKnlDragon.svg",
          "Origami/randlettflappingbird.svg", "Origami/singlesquaretwist.svg",
          "Tessellations/whirlpool.svg", "Tessellations/huffmanWaterbomb.svg",
          "Tessellations/HexTriFlatFoldableTess.svg", "Tessellations/miura-ori.svg",
          "Curved/huffmanTower.svg", "Curved/CircularPleat-antiFacet.svg",
          "Kirigami/honeycombKiri.svg", "Popup/popupSimple.svg",
          "SimpleFolds/simpleVertex.svg", "SimpleFolds/mapfold.svg",
          "Pleating/BoxPleatPyramid.fold", "Pleating/BoxPleatTessellation.fold")
#: Origami Simulator's patterns of 1,000 to 6,400 edges (``--large``).
LARGE = ("Pleating/BoxPleatPyramid.fold", "Pleating/BoxPleatInOutWave.fold",
         "Pleating/BoxPleatSkipOneWave.fold", "Pleating/BoxPleatSpiralPyramid.fold",
         "Curved/CircularPleat-antiFacet.svg", "Tessellations/HexTriFlatFoldableTess.svg")

#: Stiff bars, panels as stiff in bending as the creases in folding (N, mm).
STIFF = {"calibration": "manual", "bar_modulus": 1e5, "bar_area": 1.0,
         "fold_stiffness": 1.0, "bend_stiffness": 1.0}
def material(name: str, pattern) -> dict:
    """The ``[material]`` keys of ``stiff`` or ``soft`` for ``pattern``."""
    if name == "stiff":
        return dict(STIFF)
    from kresling.model.material_presets import preset_material

    # Origami Simulator's ingredients in this model's units (docs/folding.md).
    soft = preset_material("origami_simulator", pattern.vertices)
    return dict(STIFF, bar_modulus=soft.bar_modulus, face_stiffness=soft.face_stiffness)


def first_line(text: str) -> str:
    lines = str(text).strip().splitlines()
    return lines[0] if lines else ""


def fold_one(path: str, material_name: str, support: str, steps: int, stream=None,
             no_relax: bool = False) -> dict:
    """Fold one pattern, adding what a refusal asks for; a row of the table. The row so far
    is printed as a JSON line before each attempt (what a timeout leaves to report)."""
    from kresling.io import read_pattern
    from kresling.simulate import simulate

    row = {"vertices": None, "edges": None, "added": [], "refusals": [], "material": "-",
           "supports": "-"}
    try:
        pattern = read_pattern(path)
        row["vertices"], row["edges"] = pattern.num_vertices, pattern.num_edges
    except Exception as error:  # the problem's own refusal below says it again
        pattern = None
        row["read_error"] = f"{type(error).__name__}: {error}"
    problem = {"pattern": {"file": str(path)},
               "actuation": [{"family": "fold", "fold_angle_deg": "file"}],
               "analysis": {"method": "fold", **({"relax": False} if no_relax else {})}}
    first = []

    def note_first(state):   # the time of the first converged increment
        if not first:
            first.append(time.perf_counter() - start)
        return False

    while True:
        print(json.dumps(row), flush=True)
        start = time.perf_counter()
        try:
            sim = simulate(problem, progress=False, stop=note_first, stream=stream)
        except ValueError as error:
            row["seconds"] = time.perf_counter() - start
            message = str(error)
            addition = missing(message, problem, pattern, material_name, support, steps)
            if addition is None:
                row["refusal"] = message
                return row
            key, value, label = addition
            if key == "steps":
                problem["analysis"]["steps"] = value
            else:
                problem[key] = value
                row[key if key == "material" else "supports"] = label
            row["added"].append(key)
            row["refusals"].append(message)
            continue
        except Exception as error:
            row["seconds"] = time.perf_counter() - start
            row["error"] = f"{type(error).__name__}: {error}"
            return row
        break
    row["seconds"] = time.perf_counter() - start
    path_result = sim.path
    report = sim.fold_report()
    row.update(increments=int(path_result.num_steps),
               iterations=int(path_result.iterations.sum()),
               tried=int(path_result.newton_iterations),
               first=first[0] if first else None,
               reached=(100.0 * float(path_result.load_factor[-1])
                        if path_result.num_steps else 0.0),
               driven=report.get("creases_driven"),
               short_of_target=report.get("short_of_target"),
               left_branch=report.get("left_branch"),
               completed=bool(sim.completed), message=str(sim.message))
    return row


def missing(message: str, problem: dict, pattern, material_name: str, support: str,
            steps: int):
    """What a refusal asks for that this benchmark can add: (key, value, label) or None."""
    lower = message.lower()
    if ("material" not in problem and "'material'" in message
            and (material_name == "stiff" or pattern is not None)):
        return "material", material(material_name, pattern), material_name
    if "steps" not in problem["analysis"] and "'steps'" in message:
        return "steps", steps, str(steps)
    if ("support" not in problem and support == "auto" and pattern is not None
            and ("support" in lower or "rigid" in lower)):
        held = [int(v) for v in list(pattern.faces[0])[:3]]
        return "support", [{"nodes": held, "fix": "xyz"}], f"{len(held)} xyz"
    return None


def run(path: str, args) -> dict:
    """One pattern in a fresh process, stopped after ``args.timeout`` seconds (a stopped
    fold's row says how far it got, from the files it wrote as it went)."""
    with tempfile.TemporaryDirectory() as files:
        return _run(path, args, files)


def _run(path: str, args, files: str) -> dict:
    command = [sys.executable, str(Path(__file__).resolve()), "--worker", path,
               "--material", args.material, "--support", args.support,
               "--steps", str(args.steps), "--stream", files] + (["--no-relax"] if args.no_relax
                                                                   else [])
    start = time.perf_counter()
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout)
    except subprocess.TimeoutExpired as expired:
        row = last_row(expired.stdout)
        row.update(timeout=True, seconds=time.perf_counter() - start)
        row.update(so_far(Path(files) / "summary.json", path, row))
        return row
    row = last_row(done.stdout)
    if done.returncode:
        code = done.returncode
        how = (f"killed by {signal.Signals(-code).name}" if code < 0 and
               -code in signal.valid_signals() else f"exit status {code}")
        tail = done.stderr.strip().splitlines()[-1:]
        row.update(error=how + (f": {tail[0]}" if tail else ""),
                   seconds=time.perf_counter() - start)
    return row


def so_far(summary: Path, path: str, row: dict) -> dict:
    """What a fold stopped by the timeout had done: its size, and the increments, Newton
    iterations and fold fraction its streamed summary.json holds."""
    out = {}
    if row.get("edges") is None:
        from kresling.io import read_pattern

        pattern = read_pattern(path)
        out.update(vertices=pattern.num_vertices, edges=pattern.num_edges)
    try:
        summary = json.loads(summary.read_text())
    except (OSError, ValueError):   # no increment yet
        return out
    if summary.get("increments"):
        # (Not the iterations tried: a run's files count the accepted ones until its end.)
        out.update(increments=summary["increments"], iterations=summary["newton_iterations"],
                   reached=100.0 * summary["final_load_factor"])
    return out


def last_row(out) -> dict:
    """The last row a fold printed (a timeout or a crash leaves the pattern's size and what
    had been added)."""
    text = out.decode(errors="replace") if isinstance(out, bytes) else (out or "")
    for line in reversed(text.strip().splitlines()):
        try:
            return json.loads(line)
        except ValueError:  # anything else the process printed
            continue
    return {}


def cells(name: str, row: dict, timeout: float) -> list[str]:
    def number(key, form="{}"):
        value = row.get(key)
        return "-" if value is None else form.format(value)

    def of_driven(key):  # k/N: k of the N driven creases
        return "-" if row.get(key) is None else f"{row[key]}/{row.get('driven')}"

    if row.get("timeout"):
        built, outcome = "?", "timeout"
    elif "error" in row:
        built, outcome = "?", f"error: {row['error'][:80]}"
    elif "refusal" in row:
        # A file that cannot be read: its reader's message says why.
        built, outcome = first_line(row.get("read_error", row["refusal"]))[:80], "-"
    elif row["completed"]:
        built, outcome = "yes", "completed"
    else:
        built, outcome = "yes", f"failed: {first_line(row['message'])[:80]}"
    seconds = f"> {timeout:.0f}" if row.get("timeout") else number("seconds", "{:.2f}")
    return [name, number("vertices"), number("edges"), built,
            ", ".join(row.get("added", [])) or "none",
            row.get("material", "?"), row.get("supports", "?"), number("increments"),
            number("iterations"), number("tried"), number("reached", "{:.1f}"),
            of_driven("short_of_target"), of_driven("left_branch"),
            number("first", "{:.2f}"), seconds, outcome]


HEADER = ["pattern", "vertices", "edges", "built", "added", "material", "supports",
          "increments", "iterations", "tried", "reached %", "short_of_target", "left_branch",
          "first", "seconds", "outcome"]
LEFT = {"pattern", "built", "added", "material", "supports", "outcome"}


def print_table(rows: list[list[str]]) -> None:
    widths = [max(len(r[k]) for r in [HEADER] + rows) for k in range(len(HEADER))]

    def line(values):
        return " ".join(v.ljust(w) if h in LEFT else v.rjust(w)
                        for v, w, h in zip(values, widths, HEADER)).rstrip()

    print(line(HEADER))
    print("-" * len(line(HEADER)))
    for r in rows:
        print(line(r))


def patterns(args) -> list[tuple[str, str]]:
    """(name in the table, path) of every pattern to fold."""
    if args.files:
        return [(f, f) for f in args.files]
    if args.large:
        if not args.assets:
            raise SystemExit("--large needs --assets DIR (Origami Simulator's assets folder)")
        return [(Path(name).name, str(Path(args.assets) / name)) for name in LARGE]
    found = sorted(p for p in VENDORED.iterdir() if p.suffix.lower() in (".svg", ".fold"))
    listed = [(p.name, str(p)) for p in found]
    if args.assets:  # the ones not vendored already
        vendored = {p.name for p in found}
        listed += [(name, str(Path(args.assets) / name)) for name in ASSETS
                   if Path(name).name not in vendored]
    return listed


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("files", nargs="*", help="crease patterns (.svg, .fold, .obj)")
    parser.add_argument("--material", choices=("stiff", "soft"), default="stiff",
                        help="the material added where one is asked for (default stiff)")
    parser.add_argument("--support", choices=("auto", "none"), default="auto",
                        help="auto: hold the first panel's corners where supports are asked "
                             "for; none: never add supports")
    parser.add_argument("--steps", type=int, default=50,
                        help="increments, where the number is asked for (default 50)")
    parser.add_argument("--assets", help="a checkout of Origami Simulator's assets folder: "
                                         "fold nineteen of its patterns too")
    parser.add_argument("--large", action="store_true",
                        help="with --assets: its large patterns only (1,000 to 6,400 edges)")
    parser.add_argument("--timeout", type=float, default=60.0,
                        help="wall-clock seconds per pattern (default 60)")
    parser.add_argument("--jobs", type=int, default=1, help="patterns folded at once")
    parser.add_argument("--no-relax", action="store_true",
                        help="follow the equilibrium path, stable or not ([analysis] relax = "
                             "false; a new user's fold relaxes)")
    parser.add_argument("--worker", help=argparse.SUPPRESS)
    parser.add_argument("--stream", help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.worker:
        print(json.dumps(fold_one(args.worker, args.material, args.support, args.steps,
                                  args.stream, args.no_relax)))
        return 0
    listed = patterns(args)
    load = os.getloadavg()
    print(f"folding {len(listed)} patterns from flat{' (relax = false)' if args.no_relax else ''}: "
          f"--material {args.material}, --support "
          f"{args.support}, --steps {args.steps} where asked for, --timeout {args.timeout:g} s,"
          f" --jobs {args.jobs}; {os.cpu_count()} cores, load average {load[0]:.2f}",
          flush=True)
    results = {}

    def task(item):
        name, path = item
        row = run(path, args)
        results[name] = row
        print(f"  [{len(results)}/{len(listed)}] {name}: {cells(name, row, args.timeout)[-1]}",
              file=sys.stderr, flush=True)
        return row

    with ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        rows = list(pool.map(task, listed))
    print_table([cells(name, row, args.timeout) for (name, _), row in zip(listed, rows)])
    print("added: what the problem was given after a refusal asked for it; short_of_target: "
          "creases more than 1 deg from their targets at the end, of those driven; "
          "left_branch: creases folded the other way from their targets (more than 1 deg), of "
          "those driven; tried: Newton iterations of every increment tried; first: seconds "
          "to the first converged increment; seconds: wall time of the attempt that ran")
    asked = {}  # each refusal answered by an addition, once, with how many patterns it met
    for row in rows:
        for key, message in zip(row.get("added", []), row.get("refusals", [])):
            asked.setdefault((key, message), []).append(row)
    notes = [f"added {key} ({len(met)} of {len(rows)} patterns) after: {message}"
             for (key, message), met in asked.items()]
    for (name, _), row in zip(listed, rows):
        if "read_error" in row:
            notes.append(f"{name}: not read: {row['read_error']}")
        if "refusal" in row:
            notes.append(f"{name}: refused: {row['refusal']}")
        elif "error" in row:
            notes.append(f"{name}: {row['error']}")
        elif not row.get("timeout") and not row["completed"]:
            notes.append(f"{name}: failed: {row['message']}")
    if notes:
        print()
        print("\n".join(notes))
    return 0


if __name__ == "__main__":
    sys.exit(main())
