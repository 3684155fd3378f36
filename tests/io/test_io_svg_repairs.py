"""Hand-drawn SVG crease patterns read as Origami Simulator reads them: strokes that miss
each other by a fraction of a pixel snapped together (``snap_tolerance``, 3 px by default),
regions bounded only by black strokes taken as holes, black strokes left between two panels
made facet creases, strokes that bound no panel dropped; each repair said in a warning
naming the file. Every test draws its own small SVG."""

from __future__ import annotations

import logging

import numpy as np
import pytest

from kresling.io import read_pattern, read_svg
from kresling.io.svg_format import MM_PER_PX
from kresling.simulate import load_problem

COLOUR = {"B": "#000000", "M": "#ff0000", "V": "#0000ff", "F": "#ffff00"}


def _svg(tmp_path, strokes, name="drawing.svg"):
    """An SVG of straight strokes ``(letter, x1, y1, x2, y2)`` in px."""
    lines = "\n".join(f'<line x1="{x1}" y1="{y1}" x2="{x2}" y2="{y2}" stroke="{COLOUR[k]}"/>'
                      for k, x1, y1, x2, y2 in strokes)
    path = tmp_path / name
    path.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" width="400" height="400">'
                    f'\n{lines}\n</svg>\n')
    return path


def _square(size=300.0):
    s = size
    return [("B", 0, 0, s, 0), ("B", s, 0, s, s), ("B", s, s, 0, s), ("B", 0, s, 0, 0)]


def test_a_crease_that_misses_the_corner_by_half_a_pixel_is_snapped_to_it(tmp_path):
    # The valley diagonal ends 0.5 px beyond the corner (300, 300), as hand-drawn lines do.
    path = _svg(tmp_path, _square() + [("V", 0, 0, 300.4, 300.3)])
    snapped = read_svg(path)
    assert snapped.num_vertices == 4 and len(snapped.faces) == 2
    assert sorted(snapped.edges_assignment) == ["B", "B", "B", "B", "V"]
    # At 0.01 px it stays apart (the corner is 0.07 px off its line): the diagonal crosses
    # the right side 0.1 px below the corner, which becomes a vertex of its own, and the
    # piece beyond bounds nothing.
    tight = read_svg(path, snap_tolerance=0.01)
    assert tight.num_vertices == 5 and len(tight.faces) == 2
    problem = {"pattern": {"file": str(path), "snap_tolerance": 0.01},
               "actuation": [{"family": "fold", "fold_angle_deg": "file"}],
               "analysis": {"method": "fold"}}
    assert load_problem(problem).pattern.num_vertices == 5


def test_a_region_bounded_only_by_black_strokes_is_a_hole(tmp_path, caplog):
    # A 100 px square hole in the middle of the left half, its sides joined to the sheet's
    # by two valley creases across the half: the left half is two panels around the hole.
    hole = [("B", 50, 100, 150, 100), ("B", 150, 100, 150, 200), ("B", 150, 200, 50, 200),
            ("B", 50, 200, 50, 100)]
    creases = [("V", 150, 0, 150, 300), ("V", 100, 0, 100, 100), ("V", 100, 200, 100, 300)]
    path = _svg(tmp_path, _square() + hole + creases)
    with caplog.at_level(logging.WARNING, logger="kresling.io.svg_format"):
        pattern = read_svg(path)
    assert "1 region(s) bounded only by boundary (black) strokes taken as holes" in caplog.text
    assert str(path) in caplog.text
    area = sum(_area(pattern.vertices[list(f), :2]) for f in pattern.faces)
    np.testing.assert_allclose(area, (300 ** 2 - 100 ** 2) * MM_PER_PX ** 2, rtol=1e-12)
    # The hole's sides are the panels' boundary (B), each a side of one panel.
    assert all(a in "BV" for a in pattern.edges_assignment)


def test_a_black_stroke_between_two_panels_becomes_a_facet_crease(tmp_path, caplog):
    path = _svg(tmp_path, _square() + [("B", 150, 0, 150, 300), ("V", 0, 0, 150, 150)])
    with caplog.at_level(logging.WARNING, logger="kresling.io.svg_format"):
        pattern = read_svg(path)
    assert "lie between two panels, made facet creases F" in caplog.text
    middle = [a for (u, v), a in zip(pattern.edges.tolist(), pattern.edges_assignment)
              if np.allclose(pattern.vertices[[u, v], 0], 150 * MM_PER_PX)]
    assert middle and set(middle) == {"F"}
    load_problem({"pattern": {"file": str(path)}, "actuation": [{"family": "valley",
                  "fold_angle_deg": 90.0}], "analysis": {"method": "fold"}})


def test_a_region_touching_itself_at_a_corner_is_refused_naming_the_file(tmp_path):
    # A triangle of valleys inside the sheet touching its corner (0, 0): the region around
    # it wraps round the triangle and meets itself there.
    inner = [("V", 0, 0, 100, 50), ("V", 100, 50, 50, 100), ("V", 50, 100, 0, 0)]
    path = _svg(tmp_path, _square() + inner)
    with pytest.raises(ValueError, match=r"drawing\.svg.*outline touches itself at vertex"):
        read_svg(path)


def test_snap_tolerance_is_checked_and_applies_to_svg_only(tmp_path):
    path = _svg(tmp_path, _square() + [("V", 0, 0, 300, 300)])
    with pytest.raises(ValueError, match=r"snap_tolerance = -1 is invalid: must be a number > 0"):
        read_svg(path, snap_tolerance=-1)
    fold = tmp_path / "sheet.fold"
    fold.write_text('{"vertices_coords": [[0,0],[1,0],[1,1]], "faces_vertices": [[0,1,2]]}')
    with pytest.raises(ValueError, match="only SVG drawings are snapped"):
        read_pattern(fold, snap_tolerance=1.0)
    with pytest.raises(ValueError, match=r"\[pattern\] key 'snap_tolerance' = 1\.0 applies only "
                                         "to an SVG drawing's file"):
        load_problem({"pattern": {"file": str(fold), "snap_tolerance": 1.0},
                      "actuation": [{"family": "fold", "fold_angle_deg": 90.0}],
                      "analysis": {"method": "fold"}})


def _area(corners):
    x, y = corners[:, 0], corners[:, 1]
    return 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(np.roll(x, -1), y))
