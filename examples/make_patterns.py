"""Write the crease patterns of the examples (and the Kresling cell's problem file).

Run from anywhere: ``.venv/bin/python examples/make_patterns.py [OUT_DIR]`` (default: the
folder this script is in). It writes

- ``miura_bending/miura_4x4.obj``: a partly folded Miura-ori sheet, 4 x 4 parallelogram
  panels (OBJ: vertices and panels only, so every crease is "unassigned");
- ``single_vertex/single_vertex.fold``: one degree-4 vertex of four triangles, slightly
  folded, one mountain and three valleys (FOLD 1.1 with ``edges_assignment`` and
  ``edges_foldAngle``);
- ``kresling_tower/cell_n10_laminate.fold``: the file ``kresling pattern --n 10 --lam 0.9
  --Lc 15 --R 30 -o cell_n10_laminate.fold`` writes (the flat pattern, with the two stable
  states as folded frames);
- ``kresling_tower/kresling_n10.fold``: the closed cell built from that file's "extended"
  frame (see :func:`folded_cell`) with its two end polygons added;
- ``kresling_tower/problem.toml``: the snap-through problem of that cell (generated because
  its per-bar areas and its travel follow from the design).

Every length is in mm. The problem files of the other two examples are written by hand.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np

import kresling
from kresling.fabrication import write_pattern
from kresling.io import fold_angles, pattern_from_arrays, read_fold, write_fold, write_obj
from kresling.model import build_panel_elements

HERE = Path(__file__).resolve().parent


# -- Miura-ori ------------------------------------------------------------------------------

def miura_sheet(columns, rows, a, b, sector_deg, fold_deg):
    """Vertices and panels of a Miura-ori sheet of ``columns x rows`` parallelograms.

    Panels have sides ``a`` (along y, the straight crease lines of the flat pattern) and
    ``b`` (along x, the zig-zag lines) with the sector angle ``sector_deg`` between them;
    ``fold_deg`` tilts every panel out of the sheet's mean plane (0: flat, 90: folded flat).
    Vertex ``(i, j)`` (column i, row j) is number ``j (columns + 1) + i``; panels run row by
    row, counter-clockwise about +z.
    """
    gamma, theta = np.radians(sector_deg), np.radians(fold_deg)
    height = a * np.sin(theta) * np.sin(gamma)        # rise of the zig-zag along y
    pitch = np.sqrt(a * a - height * height)          # its run along y
    shift = a * b * np.cos(gamma) / pitch             # y offset of odd columns
    width = np.sqrt(b * b - shift * shift)            # x pitch of the columns
    vertices = np.array([[i * width, j * pitch + (i % 2) * shift, (j % 2) * height]
                         for j in range(rows + 1) for i in range(columns + 1)])

    def number(i, j):
        return j * (columns + 1) + i

    panels = [[number(i, j), number(i + 1, j), number(i + 1, j + 1), number(i, j + 1)]
              for j in range(rows) for i in range(columns)]
    return vertices, panels


def single_vertex(a, b, sector_deg, fold_deg):
    """A Miura-type degree-4 vertex of four triangles, slightly folded.

    Node 0 is the vertex; nodes 1-4 the ends of its creases: 1 (+x side) and 3 (-x side) of
    the zig-zag creases, 2 (+y) and 4 (-y) of the straight pair. Sector angles are
    ``sector_deg``, ``180 - sector_deg``, ``180 - sector_deg``, ``sector_deg`` (Kawasaki's
    condition holds: the vertex folds flat), the creases have lengths ``b`` and ``a``.
    Returns vertices, triangles (counter-clockwise about +z), and the edges with their FOLD
    assignments and fold angles [deg] measured on the geometry (valley positive).
    """
    gamma, theta = np.radians(sector_deg), np.radians(fold_deg)
    height = a * np.sin(theta) * np.sin(gamma)
    pitch = np.sqrt(a * a - height * height)
    shift = a * b * np.cos(gamma) / pitch
    width = np.sqrt(b * b - shift * shift)
    vertices = np.array([[0.0, 0.0, 0.0], [width, -shift, 0.0], [0.0, pitch, height],
                         [-width, -shift, 0.0], [0.0, -pitch, height]])
    triangles = [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 1]]
    pattern = pattern_from_arrays(vertices, triangles)
    angles = np.degrees(fold_angles(pattern.faces, pattern.edges, pattern.vertices))
    assignment = ["B" if letter == "B" else ("V" if angle > 0 else "M")
                  for letter, angle in zip(pattern.edges_assignment, angles)]
    return vertices, triangles, pattern.edges, assignment, angles


# -- Kresling cell from the fabrication FOLD ------------------------------------------------

def folded_cell(path, state="extended", tolerance=1e-6):
    """The closed 3D cell of a FOLD file written by ``kresling pattern``.

    That file's key frame is the flat pattern (the strip of ``2n`` facets, its tabs, the
    closing tab and the separate base polygon); its frames ``"contracted"`` and
    ``"extended"`` hold every point's position on the folded cell. Here the ``2n`` facets
    are taken at the positions of ``state`` (faces with ``kresling:faces_kind`` "facet"),
    points that the folding brings together are merged (the strip's two ends, ``B_n`` onto
    ``B_0`` and ``T_n`` onto ``T_0``: the seam closes), and the edges keep the file's
    assignments (a merged edge keeps the assignment that is not "B"; the tab lines, where
    the facets meet the base polygon, keep "M").

    Returns
    -------
    vertices : dict of str to ndarray, shape (2n, 3)
        The merged points in every frame of the file, by title (bottom vertices 0..n-1, then
        top vertices n..2n-1, as :meth:`kresling.Design.vertices` numbers them).
    facets : list of list of int
        The ``2n`` triangles, outward normals.
    assignment : dict of (int, int) to str
        FOLD assignment of every facet edge, keyed by the sorted vertex pair.
    """
    document = json.loads(Path(path).read_text(encoding="utf-8"))
    pattern = read_fold(path)
    titles = [frame.get("frame_title", "") for frame in document["file_frames"]]
    folded = pattern.frames[titles.index(state)]
    facets = [face for face, kind in zip(pattern.faces, document["kresling:faces_kind"])
              if kind == "facet"]
    kept, number = [], {}
    for point in sorted({v for face in facets for v in face}):
        twin = next((k for k, other in enumerate(kept)
                     if np.linalg.norm(folded[point] - folded[other]) < tolerance), None)
        if twin is None:
            kept.append(point)
            twin = len(kept) - 1
        number[point] = twin
    assignment = {}
    for (u, v), letter in zip(pattern.edges.tolist(), pattern.edges_assignment):
        if u in number and v in number:
            key = tuple(sorted((number[u], number[v])))
            if assignment.get(key, "B") == "B":
                assignment[key] = letter
    vertices = {title: frame[kept] for title, frame in zip(titles, pattern.frames)}
    return vertices, [[number[v] for v in face] for face in facets], assignment


def kresling_simulation_cell(fabrication_fold, n):
    """The cell as the thesis models it, from the fabrication FOLD's extended frame.

    Facets as in :func:`folded_cell`; the bottom and top polygons added as panels (outward
    normals), their sides folds (the tabs glued to the polygon: a crease of stiffness kf,
    assigned "M" or "V" by the sign of its fold angle), the mountain creases "C" (cut
    through, as in the thesis's specimens: the faces still share both ends of each cut, so
    the bar stays and there is no hinge), the valleys "V". Returns the Pattern (extended
    state, the contracted one as frame 1).
    """
    frames, facets, fabricated = folded_cell(fabrication_fold, "extended")
    bottom, top = list(range(n)), list(range(n, 2 * n))
    panels = facets + [bottom[::-1], top]
    assignment = {}
    for (u, v), letter in fabricated.items():
        if (u < n) == (v < n):        # a polygon side: its letter follows its fold angle
            assignment[(u, v)] = "U"
        else:                         # a crease of the strip (the seam is a mountain)
            assignment[(u, v)] = {"M": "C", "V": "V"}[letter]
    edges = sorted(assignment)
    pattern = pattern_from_arrays(frames["extended"], panels, edges=edges,
                                  edges_assignment=[assignment[e] for e in edges])
    angles = np.degrees(fold_angles(pattern.faces, pattern.edges, pattern.vertices))
    letters = [("V" if angle > 0 else "M") if letter == "U" else letter
               for letter, angle in zip(pattern.edges_assignment, angles)]
    pattern = pattern_from_arrays(pattern.vertices, pattern.faces, edges=pattern.edges,
                                  edges_assignment=letters)
    return pattern, angles, frames["contracted"]


KRESLING_PROBLEM = """\
# Snap-through of one bistable Kresling cell: the thesis's optimum design n = 10,
# lambda = 0.9, Lc = 15 mm, R = 30 mm, modelled as the thesis did (section 3.1, Appendix B).
# GENERATED by examples/make_patterns.py from the FOLD file 'kresling pattern' writes
# (cell_n10_laminate.fold): edit the script, not this file.
#
# The cell is built stress-free in its extended state (height Le = {Le:.4f} mm). The bottom
# polygon (vertices 0-{nb}, centre node {cb}) is fixed; the top polygon (vertices {t0}-{t1},
# centre node {ct}) is pushed straight down by Le - Lc = {travel:.4f} mm in 100 increments,
# its nodes free to move sideways (the top twists as it descends).
#
# Expected behaviour (the run takes well under a second): the summed reaction of the top
# nodes (history.csv: the sum of the reaction_<node>_z columns, the force the cell pushes
# back with [N]) rises to a peak of about 9.0 N at about 6.7 mm of travel - the snap
# force, which a hand pushing on the cell must overcome - then falls, through zero near
# 24.3 mm (the unstable equilibrium, where the stored energy peaks at about 131 N*mm: past
# it the cell pulls the drive down, under a force it would snap through) to a minimum of
# about -2 N near 33 mm, and rises back through zero near 38.6 mm: the second stable
# state (height about 17 mm, a little above Lc because the model is stress-free only when
# extended). Two zero crossings with a negative force between them: a bistable cell. This
# is the curve 'kresling snap --n 10 --lam 0.9 --Lc 15' computes for the thesis's
# specimen model (snap force 8.99 N, unstable state at 24.3 mm): the same model, reached
# here from a FOLD file.
#
# Nodes: 0-based, the FOLD file's vertices (bottom 0-{nb}, top {t0}-{t1}), then the N5B8
# centre nodes of the two polygon panels in panel order ({cb} bottom, {ct} top).

[pattern]
file = "kresling_n10.fold"
split = "N5B8"

[material]
# The thesis's manual properties, with kf = 0.047 N/rad its measured crease stiffness.
calibration = "manual"
bar_modulus = {C0:g}      # C0 = 1e5 kf [N/mm^2]
fold_stiffness = {kf:g}   # valleys and polygon sides: kf [N*mm/rad per mm]
bend_stiffness = {kb:g}    # polygon spokes (bend hinges): 10 kf
# One area per bar [mm^2], in the model's bar order (bend axes, fold axes, boundary): 1,
# except 0.01 on the {nm} cut mountain creases (the thesis's weak bars, EA = 1e3 kf).
bar_area = [
{areas}
]

[laws]
bar = "ogden"
fold = "enhanced_linear"
fold_limits_deg = [5.0, 355.0]
bend = "enhanced_linear"
bend_limits_deg = [5.0, 355.0]

[[support]]
nodes = [{support}]
fix = "xyz"

[[load]]
nodes = [{driven}]
displacement = [0.0, 0.0, {minus_travel:.10g}]

[analysis]
method = "displacement_control"
steps = 100
"""


def kresling_problem(pattern, design, kf=0.047):
    """The problem file's text (see :data:`KRESLING_PROBLEM`)."""
    n = design.n
    elements = build_panel_elements(pattern.vertices, pattern.faces, split="N5B8")
    letter = {tuple(sorted(e)): a for e, a in zip(pattern.edges.tolist(),
                                                   pattern.edges_assignment)}
    area = np.ones(len(elements.bars))
    first_fold = len(elements.bends)
    for j, (a, b, _, _) in enumerate(elements.folds.tolist()):
        if letter[(a, b)] == "C":
            area[first_fold + j] = 0.01
    rows = [", ".join(f"{x:g}" for x in area[k:k + 15]) for k in range(0, len(area), 15)]
    cb, ct = 2 * n, 2 * n + 1            # centre nodes: bottom polygon, then top polygon
    travel = design.Le - design.Lc
    return KRESLING_PROBLEM.format(
        Le=design.Le, nb=n - 1, t0=n, t1=2 * n - 1, cb=cb, ct=ct, travel=travel,
        C0=1e5 * kf, kf=kf, kb=10 * kf, nm=int((area < 1).sum()),
        areas=",\n".join("    " + row for row in rows),
        support=", ".join(str(k) for k in list(range(n)) + [cb]),
        driven=", ".join(str(k) for k in list(range(n, 2 * n)) + [ct]),
        minus_travel=-travel)


def main(out=HERE):
    out = Path(out)
    written = []

    folder = out / "miura_bending"
    folder.mkdir(parents=True, exist_ok=True)
    vertices, panels = miura_sheet(4, 4, a=20.0, b=20.0, sector_deg=60.0, fold_deg=30.0)
    written.append(write_obj(folder / "miura_4x4.obj", vertices, panels))

    folder = out / "single_vertex"
    folder.mkdir(parents=True, exist_ok=True)
    vertices, triangles, edges, assignment, angles = single_vertex(
        a=20.0, b=20.0, sector_deg=60.0, fold_deg=10.0)
    written.append(write_fold(
        folder / "single_vertex.fold", vertices, triangles, edges=edges,
        edges_assignment=assignment, edges_fold_angle=angles,
        frame_title="degree-4 vertex, sector angles 60-120-120-60 deg, pre-folded",
        metadata={"file_title": "single degree-4 vertex (one mountain, three valleys)"}))

    folder = out / "kresling_tower"
    folder.mkdir(parents=True, exist_ok=True)
    design = kresling.Design(n=10, lam=0.9, Lc=15.0, R=30.0)
    fabrication_fold = write_pattern(folder / "cell_n10_laminate.fold", design, "laminate")
    written.append(fabrication_fold)
    pattern, angles, contracted = kresling_simulation_cell(fabrication_fold, design.n)
    written.append(write_fold(
        folder / "kresling_n10.fold", pattern, edges_fold_angle=angles, frames=[contracted],
        frame_title=["extended (rest state of the simulation)", "contracted"],
        metadata={"file_title": "Kresling cell n=10 lam=0.9 Lc=15 mm R=30 mm for simulation: "
                                "facets of cell_n10_laminate.fold, seam closed, end "
                                "polygons added; mountains cut (C), polygon sides folds (M/V)"}))
    problem = folder / "problem.toml"
    problem.write_text(kresling_problem(pattern, design), encoding="utf-8")
    written.append(problem)
    return written


if __name__ == "__main__":
    for path in main(sys.argv[1] if len(sys.argv) > 1 else HERE):
        print(f"wrote {path}")
