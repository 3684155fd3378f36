"""SVG crease patterns with Origami Simulator's conventions: a Miura-ori, a waterbomb base and
the flapping bird drawn as long strokes (crossing, with transforms, as lines, polylines and
paths) read back as the planar patterns of their FOLD files; the stroke opacity is the fold
angle; `kresling pattern --from` converts and `kresling simulate` reads SVG directly."""

import json
import math
from collections import Counter
from pathlib import Path

import numpy as np
import pytest

from kresling.cli import main
from kresling.io import pattern_from_arrays, read_fold, read_pattern, read_svg
from kresling.simulate import load_problem

DATA = Path(__file__).resolve().parents[1] / "data" / "patterns"
COLOURS = {"M": "#ff0000", "V": "#0000ff", "B": "#000000", "C": "#00ff00", "F": "#ffff00",
           "U": "#ff00ff"}


def miura(nx=4, ny=3, width=20.0, height=15.0, shift=6.0):
    """A flat Miura-ori crease pattern: zig-zag columns of parallelograms; the zig-zag lines
    alternate mountain and valley, the straight ones alternate along each row."""
    points = [[i * width + (j % 2) * shift, j * height] for j in range(ny + 1)
              for i in range(nx + 1)]
    at = lambda i, j: j * (nx + 1) + i                                  # noqa: E731
    faces = [[at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]
             for j in range(ny) for i in range(nx)]
    edges, letters = [], []
    for j in range(ny + 1):
        for i in range(nx + 1):
            if i < nx:
                edges.append((at(i, j), at(i + 1, j)))
                letters.append("B" if j in (0, ny) else "MV"[(i + j) % 2])
            if j < ny:
                edges.append((at(i, j), at(i, j + 1)))
                letters.append("B" if i in (0, nx) else "MV"[i % 2])
    return pattern_from_arrays(points, faces, edges=edges, edges_assignment=letters)


def waterbomb(size=40.0):
    """The waterbomb base: a square's diagonals (valleys) and midlines (mountains)."""
    h = size / 2
    points = [[0, 0], [h, 0], [size, 0], [size, h], [size, size], [h, size], [0, size],
              [0, h], [h, h]]
    faces = [[k, k + 1, 8] for k in range(7)] + [[7, 0, 8]]
    edges = [(k, 8) for k in range(8)]
    letters = ["V" if k % 2 == 0 else "M" for k in range(8)]
    return pattern_from_arrays(points, faces, edges=edges, edges_assignment=letters)


def _strokes(pattern):
    """The pattern's creases as maximal straight strokes (collinear edges of one letter
    joined through the vertices where only they meet), so a reader must find every
    crossing and T-junction again."""
    points = pattern.vertices[:, :2]
    by_vertex = {}
    for k, (u, v) in enumerate(pattern.edges.tolist()):
        by_vertex.setdefault(u, []).append(k)
        by_vertex.setdefault(v, []).append(k)
    used, strokes = set(), []
    for k, (u, v) in enumerate(pattern.edges.tolist()):
        if k in used:
            continue
        letter, chain = pattern.edges_assignment[k], [u, v]
        used.add(k)
        for end in (0, 1):
            while True:
                tip, before = chain[-1], chain[-2]
                direction = points[tip] - points[before]
                step = None
                for e in by_vertex[tip]:
                    a, b = pattern.edges[e]
                    other = b if a == tip else a
                    turn = points[other] - points[tip]
                    cross = direction[0] * turn[1] - direction[1] * turn[0]
                    if e not in used and pattern.edges_assignment[e] == letter and \
                            abs(cross) < 1e-9 * np.linalg.norm(turn) * \
                            np.linalg.norm(direction) and np.dot(direction, turn) > 0:
                        step = (e, other)
                if step is None:
                    break
                used.add(step[0])
                chain.append(step[1])
            chain.reverse()
        strokes.append((letter, points[chain[0]], points[chain[-1]],
                        pattern.edges_fold_angle[k]))
    return strokes


def _svg(pattern, path):
    """The pattern drawn as Origami Simulator draws: y down, strokes inside a transformed
    group, every third a line, a polyline or a path; opacity = |fold angle| / 180."""
    rows = ['<svg xmlns="http://www.w3.org/2000/svg" width="400" height="400">',
            '<g transform="translate(200 300) scale(2 -2)">']       # y up, doubled
    for k, (letter, a, b, angle) in enumerate(_strokes(pattern)):
        opacity = "" if np.isnan(angle) else f' stroke-opacity="{abs(angle) / 180:g}"'
        style = f'stroke="{COLOURS[letter]}"{opacity} fill="none"'
        if k % 3 == 0:
            rows.append(f'<line {style} x1="{a[0]}" y1="{a[1]}" x2="{b[0]}" y2="{b[1]}"/>')
        elif k % 3 == 1:
            rows.append(f'<polyline {style} points="{a[0]},{a[1]} {b[0]},{b[1]}"/>')
        else:
            rows.append(f'<path {style} d="M {a[0]} {a[1]} L {b[0]} {b[1]}"/>')
    path.write_text("\n".join(rows + ["</g>", "</svg>"]) + "\n")
    return path


def _counts(pattern):
    letters = Counter(pattern.edges_assignment)
    return pattern.num_vertices, pattern.num_faces, letters["M"], letters["V"], letters["B"]


@pytest.mark.parametrize("name", ["miura", "waterbomb", "flapping_bird"])
def test_svg_strokes_read_back_as_the_fold_files_pattern(tmp_path, name):
    if name == "flapping_bird":
        fold = read_fold(DATA / "flapping_bird.fold")
    else:
        source = {"miura": miura, "waterbomb": waterbomb}[name]()
        fold = read_fold(_write_fold(tmp_path, source))
    svg = read_svg(_svg(fold, tmp_path / f"{name}.svg"), unit="mm")
    assert _counts(svg) == _counts(fold)
    assert len(_strokes(fold)) < fold.num_edges             # strokes had to be split
    # The same vertices: the group's transform (x2, y flipped, shifted) undone by the
    # reader's y-up, up to the shift and the doubling.
    ours = svg.vertices[:, :2] / 2
    ours = ours - ours.min(axis=0) + fold.vertices[:, :2].min(axis=0)
    gaps = np.linalg.norm(ours[:, None] - fold.vertices[None, :, :2], axis=-1).min(axis=1)
    assert gaps.max() < 1e-9 * np.ptp(fold.vertices)


def _write_fold(tmp_path, pattern):
    from kresling.io import write_fold

    return write_fold(tmp_path / "source.fold", pattern)


def test_the_flapping_bird_drawn_as_origami_simulator_draws_it():
    # 28 long strokes and the square: counted by hand on the drawing, the strokes split at
    # their crossings and T-junctions give 26 mountain, 11 valley and 10 boundary edges on 24
    # vertices; Euler's formula gives 47 - 24 + 1 = 24 faces.
    bird = read_svg(DATA / "flapping_bird.svg")
    assert _counts(bird) == (24, 24, 26, 11, 10)
    assert _counts(bird) == _counts(read_fold(DATA / "flapping_bird.fold"))
    # 200 px square, 1 px = 1/96 in.
    assert np.ptp(bird.vertices[:, 0]) == pytest.approx(200 * 25.4 / 96, rel=1e-12)


def test_opacity_is_the_fold_angle_and_the_colours_are_origami_simulators(tmp_path):
    svg = tmp_path / "vertex.svg"
    svg.write_text(
        '<svg xmlns="http://www.w3.org/2000/svg"><g fill="none">'
        '<rect x="0" y="0" width="10" height="10" stroke="black"/>'
        '<line x1="0" y1="0" x2="10" y2="10" stroke="#FF0000" stroke-opacity="0.5"/>'
        '<line x1="10" y1="0" x2="0" y2="10" style="stroke: rgb(0, 0, 255); opacity: 0.25"/>'
        '<line x1="5" y1="0" x2="5" y2="5" stroke="#ff0"/>'
        '<line x1="5" y1="10" x2="5" y2="5" stroke="magenta"/>'
        '<line x1="0" y1="5" x2="5" y2="5" stroke="#0f0"/>'
        '<text x="1" y="1" stroke="#123456">label</text></g></svg>')
    pattern = read_svg(svg)
    angle = {a: set(np.round(pattern.edges_fold_angle[[k for k, b in enumerate(
        pattern.edges_assignment) if b == a]], 9)) for a in set(pattern.edges_assignment)}
    assert angle["M"] == {-90.0} and angle["V"] == {45.0} and angle["F"] == {0.0}
    # The square's sides are split where the three half-lines end on them: 7 boundary edges.
    assert Counter(pattern.edges_assignment) == {"M": 2, "V": 2, "F": 1, "U": 1, "C": 1,
                                                 "B": 7}


def test_bad_svg_files_are_refused_with_their_name(tmp_path):
    curved = tmp_path / "curved.svg"
    curved.write_text('<svg xmlns="http://www.w3.org/2000/svg"><path id="arc" stroke="red" '
                      'd="M 0 0 C 1 1 2 1 3 0"/></svg>')
    with pytest.raises(ValueError, match=r"curved\.svg: element 'arc' has a CubicBezier"):
        read_svg(curved)
    empty = tmp_path / "empty.svg"
    empty.write_text('<svg xmlns="http://www.w3.org/2000/svg"><line x1="0" y1="0" x2="1" '
                     'y2="1" stroke="orange"/></svg>')
    with pytest.raises(ValueError, match=r"empty\.svg: has no stroke of a crease colour"):
        read_svg(empty)
    broken = tmp_path / "broken.svg"
    broken.write_text("<svg><line")
    with pytest.raises(ValueError, match=r"broken\.svg: not a valid SVG file"):
        read_svg(broken)
    open_lines = tmp_path / "open.svg"
    open_lines.write_text('<svg xmlns="http://www.w3.org/2000/svg"><line x1="0" y1="0" '
                          'x2="1" y2="1" stroke="red"/></svg>')
    with pytest.raises(ValueError, match=r"open\.svg: the 1 strokes enclose no face"):
        read_svg(open_lines)


def test_pattern_from_svg_converts_to_fold_and_simulate_reads_svg(tmp_path, capsys):
    out = tmp_path / "bird.fold"
    assert main(["pattern", "--from", str(DATA / "flapping_bird.svg"), "-o", str(out)]) == 0
    converted = read_fold(out)
    assert _counts(converted) == (24, 24, 26, 11, 10)
    assert json.loads(out.read_text())["frame_unit"] == "mm"
    problem = tmp_path / "bird.toml"
    problem.write_text(f'[pattern]\nfile = "{DATA / "flapping_bird.svg"}"\n'
                       '[material]\ncalibration = "manual"\nbar_modulus = 1e3\nbar_area = 1.0\n'
                       'fold_stiffness = 0.1\nbend_stiffness = 1.0\n'
                       '[[support]]\nnodes = [0, 1, 2]\nfix = "xyz"\n'
                       '[[load]]\nnode = 12\nforce = [0.0, 0.0, 1.0]\n'
                       '[analysis]\nmethod = "force_control"\nsteps = 1\n')
    loaded = load_problem(problem)
    assert loaded.assignments == "origami_simulator"
    assert _counts(loaded.pattern) == (24, 24, 26, 11, 10)
    assert read_pattern(DATA / "flapping_bird.svg").num_faces == 24
    assert math.isclose(loaded.analysis.tolerance,
                        1e-8 * np.linalg.norm(np.ptp(loaded.pattern.vertices, axis=0)))
