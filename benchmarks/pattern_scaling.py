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

Run: ``python benchmarks/pattern_scaling.py [--max-dofs N] [--kinds miura,box ...]``.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys

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

positive, plan = factorise(K)
negative, plan_indefinite = factorise(indefinite)
print(json.dumps(dict(
    dofs=int(len(free)), elements=int(len(model.bars) + len(model.hinges)), assembly=assembly,
    positive=positive, indefinite=negative, analysis=plan["analysis_seconds"],
    flops=plan["flops"], nnz=plan["factor_nonzeros"], ordering=plan["ordering"],
    method=plan["method"], method_indefinite=plan_indefinite["method"],
    negative=plan_indefinite["negative_eigenvalues"])))
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


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max-dofs", type=int, default=105_000)
    parser.add_argument("--kinds", default=",".join(SIZES),
                        help="comma-separated: " + ", ".join(SIZES))
    args = parser.parse_args(argv)
    kinds = [k.strip() for k in args.kinds.split(",") if k.strip()]
    unknown = [k for k in kinds if k not in SIZES]
    if unknown:
        parser.error(f"--kinds: unknown {unknown}; choose from {sorted(SIZES)}")
    load = os.getloadavg()
    print(f"one Newton iteration by pattern kind; {os.cpu_count()} cores, load average "
          f"{load[0]:.2f} {load[1]:.2f} {load[2]:.2f}")
    table(kinds, args.max_dofs)
    return 0


if __name__ == "__main__":
    sys.exit(main())
