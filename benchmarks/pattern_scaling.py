"""Cost of one Newton iteration by pattern kind, from ~1,000 to ~100,000 DOFs.

Four kinds of pattern, each at growing sizes, each size in a fresh process:

- ``miura``: a folded Miura-ori sheet (``kresling.io.miura_sheet``, 30 deg), N5B8;
- ``box pleat``: a flat square grid of quads, N5B8 (a centre node per square), as Origami
  Simulator's box-pleated tessellations are read (2,704 vertices: 15,915 DOFs);
- ``kresling tower``: a stack of the thesis's n = 10 Kresling cells (a long, thin pattern);
- ``triangulated``: a flat square grid of triangles (each square cut along a diagonal), no
  centre nodes.

Each is calibrated as a 0.25 mm sheet (E = 1000 N/mm^2, nu = 0.3; the tower with the
thesis's parameters), held at three nodes. One Newton iteration is one assembly of force
and tangent through a kept workspace, one factorisation and one solve. Its cost is timed at
the reference state, where the tangent is positive definite (Cholesky), and on the same
tangent shifted to be indefinite (past a limit point or bifurcation: the Cholesky fails and
an LDL^T gives the inertia), best of three; the symbolic analysis, done once per pattern, is
reported on its own. A shared machine makes absolute times noisy: compare rows of one run.

With ``--compare``, the tangents of each kind's largest size (and two small ones: the
thesis's n = 10 bending specimen of four cells, 136 DOFs, and MERLIN2's 427-DOF GMiura
sheet) go to ``benchmarks/cpp/factorisation_cost --compare`` instead, which factorises each
side by side with the supernodal factorisation's baseline (SSE2) dense kernels, its AVX2+FMA
ones, and CHOLMOD's own supernodal factorisation on the BLAS it is linked to and, when an
OpenBLAS library is found (``--openblas PATH``), on OpenBLAS, preloaded into that process
alone. The table then gives one Newton iteration (assembly, factorisation, solve) with each.

Run: ``python benchmarks/pattern_scaling.py [--max-dofs N] [--kinds miura,box ...]
[--compare [--openblas PATH]]``.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FACTORISATION_COST = ROOT / "build" / "py" / "factorisation_cost"
# Where Debian's libopenblas0-pthread puts OpenBLAS (as a BLAS it also serves libblas.so.3).
OPENBLAS = Path("/usr/lib/x86_64-linux-gnu/openblas-pthread/libopenblas.so.0")

# One pattern in a fresh process; prints one JSON line.
_PROBE = r"""
import json, sys, time
import numpy as np, scipy.sparse as sp
from kresling import _core, Design
from kresling.assembly import Workspace, assemble
from kresling.io import miura_sheet
from kresling.model import kresling_specimen
from kresling.model.calibration import SheetMaterial
from kresling.model.pattern_model import CreaseLaws, HingeLaw, build_pattern_model

kind, size = sys.argv[1], int(sys.argv[2])
matrix_file = sys.argv[3] if len(sys.argv) > 3 else None

def grid(n, triangles):
    v = np.array([[i, j, 0.0] for j in range(n + 1) for i in range(n + 1)], float) * 10.0
    quads = [[j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1,
              (j + 1) * (n + 1) + i] for j in range(n) for i in range(n)]
    if not triangles:
        return v, quads
    return v, [t for a, b, c, d in quads for t in ([a, b, c], [a, c, d])]

laws = CreaseLaws(bend=HingeLaw("enhanced_linear"))
material = SheetMaterial(1e3, 0.3, 0.25)
if kind == "kresling tower":
    model = kresling_specimen(Design(10, 0.9, 15.0), ["extended"] * size).model
else:
    pattern = miura_sheet(size, size) if kind == "miura" else grid(size, kind == "triangulated")
    model = build_pattern_model(pattern, material=material, laws=laws).model
# Three nodes not on a line hold the six rigid-body motions: node 0 fully, the node farthest
# from it in y and z, the node farthest from the line through both in z.
x = model.nodes
far = int(np.argmax(np.linalg.norm(x - x[0], axis=1)))
axis = (x[far] - x[0]) / np.linalg.norm(x[far] - x[0])
off = x - x[0]
third = int(np.argmax(np.linalg.norm(off - np.outer(off @ axis, axis), axis=1)))
fixed = np.zeros((model.num_nodes, 3), bool)
fixed[0] = True
fixed[far, 1:] = True
fixed[third, 2] = True
model = model.replace(fixed=fixed)
free = np.flatnonzero(~fixed.ravel())
workspace = Workspace(model)

def best(function, repeat=3):
    times = []
    for _ in range(repeat):
        start = time.perf_counter(); function(); times.append(time.perf_counter() - start)
    return min(times)

assembly = best(lambda: assemble(model, workspace=workspace))
K = sp.tril(assemble(model, workspace=workspace).stiffness[free][:, free]).tocsc()
# The same pattern with the diagonal lowered (scipy's K - s I would drop the pattern's
# explicit zeros, which the path's tangents keep, and factorise a sparser matrix).
indefinite = K.copy()
columns = np.repeat(np.arange(K.shape[1]), np.diff(K.indptr))
indefinite.data[K.indices == columns] -= 1e-3 * np.median(K.diagonal())

def factorise(matrix, repeat=3):
    # factorization_plan analyses and factorises once; its own clock gives the analysis,
    # which each call's time leaves out.
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        plan = _core.solvers.factorization_plan(matrix)
        times.append(time.perf_counter() - start - plan["analysis_seconds"])
    return min(times), plan

if matrix_file:  # for factorisation_cost --compare: the tangent and the assembly's time
    import scipy.io
    scipy.io.mmwrite(matrix_file, K, symmetry="symmetric")
    print(json.dumps(dict(dofs=int(len(free)), assembly=assembly)))
    sys.exit(0)
positive, plan = factorise(K)
negative, plan_indefinite = factorise(indefinite)
print(json.dumps(dict(
    dofs=int(len(free)), elements=int(len(model.bars) + len(model.hinges)), assembly=assembly,
    positive=positive, indefinite=negative, analysis=plan["analysis_seconds"],
    flops=plan["flops"], nnz=plan["factor_nonzeros"], ordering=plan["ordering"],
    method=plan["method"], method_indefinite=plan_indefinite["method"],
    negative=plan_indefinite["negative_eigenvalues"])))
"""

# The small models of the comparison: the thesis's n = 10 bending specimen of four cells with
# the bending test's supports (136 free DOFs), and MERLIN2's GMiura sheet (427).
_SMALL_PROBE = r"""
import json, sys, time
from pathlib import Path
import numpy as np, scipy.io, scipy.sparse as sp
from kresling import Design
from kresling.assembly import Workspace, assemble
from kresling.model.kresling_specimen import kresling_specimen
from kresling.simulate import build_problem_model

kind, matrix_file, root = sys.argv[1], sys.argv[2], Path(sys.argv[3])
if kind == "bending specimen":
    s = kresling_specimen(Design(10, 0.9, 15), [1] * 4)
    # The bending test's supports: pins at both ends, the middle polygon held in y.
    pins = [s.node(level, j) for level in (0, 4) for j in (0, 5)] + [s.centre(0), s.centre(4)]
    fixed = np.zeros((s.model.num_nodes, 3), bool)
    fixed[pins] = True
    fixed[s.level_nodes(2), 1] = True
    fixed = fixed.ravel()
    model = s.model
else:
    model = build_problem_model(root / "tests/data/merlin2_examples/gmiura_pointload/problem.toml").model
    fixed = model.fixed.ravel()
free = np.flatnonzero(~fixed)
workspace = Workspace(model)
times = []
for _ in range(20):
    start = time.perf_counter(); assemble(model, workspace=workspace)
    times.append(time.perf_counter() - start)
K = sp.tril(assemble(model, workspace=workspace).stiffness[free][:, free]).tocsc()
scipy.io.mmwrite(matrix_file, K, symmetry="symmetric")
print(json.dumps(dict(dofs=int(len(free)), assembly=min(times))))
"""

# Sizes per kind (grid cells along a side, or cells of the tower): ~1k, 5k, 16k, 33k, 100k DOFs.
SIZES = {
    "miura": (13, 30, 51, 73, 129),
    "box pleat": (13, 30, 51, 73, 129),
    "kresling tower": (30, 150, 480, 1000, 3030),
    "triangulated": (18, 41, 73, 105, 182),
}


def estimated_dofs(kind: str, size: int) -> int:
    """DOFs of a size before building it (N5B8 adds a centre node per quad)."""
    if kind == "kresling tower":
        return 3 * 11 * (size + 1)
    vertices = (size + 1) ** 2
    return 3 * (vertices + size * size if kind in ("miura", "box pleat") else vertices)


def run(kind: str, size: int) -> dict | None:
    out = subprocess.run([sys.executable, "-c", _PROBE, kind, str(size)], capture_output=True,
                         text=True)
    if out.returncode:
        print(f"{kind} {size}: failed: {out.stderr.strip().splitlines()[-1:]}")
        return None
    return json.loads(out.stdout.strip().splitlines()[-1])


def table(kinds, max_dofs: int) -> None:
    header = (f"{'pattern':<15} {'DOFs':>7} {'elements':>8} {'asm s':>7} {'LL^T s':>7} "
              f"{'LDL^T s':>8} {'iter s':>7} {'iter s indef':>12} {'analysis s':>10} "
              f"{'GFlop':>6} {'fill':>5} {'ordering':>8}")
    print(header)
    print("-" * len(header))
    for kind in kinds:
        for size in SIZES[kind]:
            if estimated_dofs(kind, size) > max_dofs:
                break
            r = run(kind, size)
            if r is None:
                continue
            ordering = "ND" if r["ordering"] == "nested dissection" else r["ordering"]
            print(f"{kind:<15} {r['dofs']:>7} {r['elements']:>8} {r['assembly']:>7.3f} "
                  f"{r['positive']:>7.3f} {r['indefinite']:>8.3f} "
                  f"{r['assembly'] + r['positive']:>7.3f} "
                  f"{r['assembly'] + r['indefinite']:>12.3f} {r['analysis']:>10.3f} "
                  f"{r['flops'] / 1e9:>6.2f} {r['nnz'] / r['dofs']:>5.0f} {ordering:>8}"
                  + ("" if r["method"] == "supernodal cholesky" else f" ({r['method']})")
                  + f" {r['method_indefinite']}, {r['negative']} negative",
                  flush=True)
    print("asm: one assembly of force and tangent (kept workspace, Python call included); "
          "LL^T: one positive definite factorisation; LDL^T: the same tangent shifted to be "
          "indefinite (the failed Cholesky included); iter: assembly + factorisation, "
          "positive definite and indefinite; analysis: ordering and symbolic factor, once "
          "per pattern; GFlop: one Cholesky; fill: nnz(L) per DOF")


def write_tangent(kind: str, size: int | None, path: Path) -> dict | None:
    """Write the kind's tangent (lower triangle, free DOFs) to path; its DOFs and assembly s."""
    if size is None:
        command = [sys.executable, "-c", _SMALL_PROBE, kind, str(path), str(ROOT)]
    else:
        command = [sys.executable, "-c", _PROBE, kind, str(size), str(path)]
    out = subprocess.run(command, capture_output=True, text=True)
    if out.returncode:
        print(f"{kind} {size}: failed: {out.stderr.strip().splitlines()[-1:]}")
        return None
    return json.loads(out.stdout.strip().splitlines()[-1])


def factorisation_costs(paths: list[Path], preload: Path | None = None) -> dict[str, dict]:
    """factorisation_cost --compare on the matrices (OpenBLAS preloaded if given), by path."""
    env = dict(os.environ)
    if preload is not None:
        env["LD_PRELOAD"] = str(preload)
    out = subprocess.run([str(FACTORISATION_COST), "--compare", *map(str, paths)],
                         capture_output=True, text=True, env=env, check=True)
    rows = [json.loads(line) for line in out.stdout.splitlines() if line.startswith("{")]
    return {row["matrix"]: row for row in rows}


def comparison(kinds, max_dofs: int, openblas: Path | None) -> None:
    """One Newton iteration per matrix with each factorisation, side by side (module doc)."""
    if not FACTORISATION_COST.exists():
        sys.exit(f"{FACTORISATION_COST} is missing: build with `make install` "
                 "(KRESLING_BUILD_BENCHMARKS=ON)")
    cases = [("bending specimen", None), ("GMiura sheet", None)]
    for kind in kinds:
        fitting = [size for size in SIZES[kind] if estimated_dofs(kind, size) <= max_dofs]
        if fitting:
            cases.append((kind, fitting[-1]))
    with tempfile.TemporaryDirectory() as tmp:
        written = []
        for k, (kind, size) in enumerate(cases):
            path = Path(tmp) / f"{k}.mtx"
            r = write_tangent(kind, size, path)
            if r is not None:
                written.append((kind, path, r))
        paths = [path for _, path, _ in written]
        own = factorisation_costs(paths)
        on_openblas = factorisation_costs(paths, openblas) if openblas else {}
    blas = next(iter(own.values()))["blas"] if own else "?"
    header = (f"{'pattern':<17} {'DOFs':>7} {'GFlop':>6} {'thr':>3} {'asm':>7} "
              f"{'LL^T SSE2':>9} {'AVX2':>7} {'CHOLMOD':>7} {'CM+OB':>7} {'LDL^T SSE2':>10} "
              f"{'AVX2':>7} {'solve':>7} {'iter SSE2':>9} {'iter AVX2':>9} {'iter CM+OB':>10} "
              f"{'negative':>11}")
    print(header)
    print("-" * len(header))

    def ms(seconds, width):  # milliseconds, three significant digits
        return f"{'-':>{width}}" if seconds is None else f"{seconds * 1e3:>{width}.3g}"

    for kind, path, r in written:
        c = own[str(path)]
        base, avx2 = c["baseline"], c.get("avx2")
        cm_ob = on_openblas.get(str(path), {}).get("cholmod")
        iteration = lambda t: t and r["assembly"] + t["llt"] + t["solve"]  # noqa: E731
        negative = f"{base['negative']}/{avx2['negative'] if avx2 else '-'}"
        print(f"{kind:<17} {c['n']:>7} {c['flops'] / 1e9:>6.2f} {c['threads']:>3} "
              f"{ms(r['assembly'], 7)} {ms(base['llt'], 9)} {ms(avx2 and avx2['llt'], 7)} "
              f"{ms(c['cholmod']['llt'], 7)} {ms(cm_ob and cm_ob['llt'], 7)} "
              f"{ms(base['ldlt'], 10)} {ms(avx2 and avx2['ldlt'], 7)} {ms(base['solve'], 7)} "
              f"{ms(iteration(base), 9)} {ms(iteration(avx2), 9)} {ms(iteration(cm_ob), 10)} "
              f"{negative:>11}", flush=True)
    print(f"milliseconds, best of several; asm: one assembly; LL^T: one positive definite factorisation by our "
          f"supernodal one with its baseline (SSE2) or AVX2+FMA dense kernels, by CHOLMOD's "
          f"supernodal one on {blas} (CHOLMOD) and on "
          f"{openblas if openblas else 'OpenBLAS (not found)'} (CM+OB); LDL^T: the tangent "
          f"shifted to be indefinite; thr: threads of ours; iter: assembly + LL^T + solve; "
          f"neg: negative eigenvalues of the shifted tangent by each kernel set. The tangent "
          f"solver takes the AVX2 kernels from 1e7 flops per factorisation up (where the "
          f"processor has them), the SSE2 ones below")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max-dofs", type=int, default=105_000)
    parser.add_argument("--kinds", default=",".join(SIZES),
                        help="comma-separated: " + ", ".join(SIZES))
    parser.add_argument("--compare", action="store_true",
                        help="factorise each kind's largest tangent and two small ones with "
                             "every kernel set side by side (see the module's doc)")
    parser.add_argument("--openblas", type=Path, default=OPENBLAS,
                        help="OpenBLAS library preloaded for CHOLMOD's supernodal factorisation "
                             "in --compare (default: Debian's libopenblas0-pthread's)")
    args = parser.parse_args(argv)
    kinds = [k.strip() for k in args.kinds.split(",") if k.strip()]
    unknown = [k for k in kinds if k not in SIZES]
    if unknown:
        parser.error(f"--kinds: unknown {unknown}; choose from {sorted(SIZES)}")
    load = os.getloadavg()
    print(f"one Newton iteration by pattern kind; {os.cpu_count()} cores, load average "
          f"{load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    if args.compare:
        comparison(kinds, args.max_dofs, args.openblas if args.openblas.exists() else None)
    else:
        table(kinds, args.max_dofs)
    return 0


if __name__ == "__main__":
    sys.exit(main())
