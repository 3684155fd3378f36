"""What a command costs from the shell: ``kresling bend`` on the thesis's optimum (n = 10,
lambda = 0.9, Lc = 15 mm, both states, 350 increments to 5 mm) as a whole process, minus
``kresling design``'s (the interpreter, numpy and the package's start), against MERLIN2's
time for the same two bending runs under GNU Octave (kresling/data/merlin2/timing_octave.csv,
a 2-core machine of this size; MERLIN2 has no bending driver of its own to run live).

Both commands run alternately, ``--repeat`` times each; the best of each is taken (a shared
machine's noise only adds time). Then ``python -X importtime`` of each says where their
start-up goes: the top-level imports, largest first, and whether scipy is imported at all.
The package's modules are read from their cached bytecode (``make install`` writes it): in a
shell with PYTHONDONTWRITEBYTECODE set, an uncompiled editable install would compile them at
every start. Run: ``python benchmarks/cli_startup.py [--repeat N]``.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time

import numpy as np

from kresling import data

OPTIMUM = ["--n", "10", "--lam", "0.9", "--Lc", "15"]
COMMANDS = {"design": ["design", *OPTIMUM, "--R", "30"], "bend": ["bend", *OPTIMUM, "--json"]}


def process_seconds(args) -> float:
    start = time.perf_counter()
    subprocess.run([sys.executable, "-m", "kresling", *args], check=True,
                   stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def merlin2_seconds() -> float:
    """MERLIN2's wall time for the optimum's two bending runs (extended and contracted)."""
    rows = np.genfromtxt(data.path("merlin2/timing_octave.csv"), delimiter=",", names=True)
    mask = (rows["n"] == 10) & (rows["Lc_mm"] == 15) & (np.isclose(rows["lambda"], 0.9))
    return float(rows["wall_s"][mask].sum())


def imports(args) -> list:
    """(ms, module) of the top-level imports of a command, largest first."""
    result = subprocess.run([sys.executable, "-X", "importtime", "-m", "kresling", *args],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                            check=True)
    rows = [line.split("|") for line in result.stderr.splitlines()
            if line.startswith("import time:") and "self [us]" not in line]
    tops = [(int(r[1]) / 1000, r[2].strip()) for r in rows if not r[2].startswith("   ")]
    loaded = {r[2].strip() for r in rows}
    return sorted(tops, reverse=True), any(m.split(".")[0] == "scipy" for m in loaded)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args(argv)
    print(f"load average {os.getloadavg()[0]:.2f} (2 cores)")
    best = {name: float("inf") for name in COMMANDS}
    for _ in range(args.repeat):
        for name, command in COMMANDS.items():
            best[name] = min(best[name], process_seconds(command))
    extra = best["bend"] - best["design"]
    merlin2 = merlin2_seconds()
    print(f"\n{'process':<28} {'seconds':>8}")
    print(f"{'kresling design':<28} {best['design']:>8.3f}")
    print(f"{'kresling bend':<28} {best['bend']:>8.3f}")
    print(f"{'bend minus design':<28} {extra:>8.3f}")
    print(f"{'MERLIN2 (Octave, stored)':<28} {merlin2:>8.3f}")
    print(f"ratio MERLIN2 / (bend minus design): {merlin2 / extra:.0f}x (goal 500x: bend minus "
          f"design <= {1e3 * merlin2 / 500:.1f} ms)")
    for name, command in COMMANDS.items():
        tops, scipy = imports(command)
        total = sum(ms for ms, _ in tops)
        print(f"\nkresling {name}: imports {total:.0f} ms (scipy imported: {scipy}); largest:")
        for ms, module in tops[:8]:
            print(f"  {ms:>7.1f} ms  {module}")


if __name__ == "__main__":
    main()
