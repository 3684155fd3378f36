"""Cut passes of the two processes: what each layer holds, the thesis's dimensions, the
parameters' effects, the module sheet, and bad input."""

import math

import numpy as np
import pytest

import kresling
from kresling.fabrication import Laminate, Paper, crease_pattern, cut_sheet, make_process, module_sheet
from kresling.fabrication.planar import convex_overlap, signed_area

OPTIMUM = kresling.Design(10, 0.9, 15.0)


def _distance_to_line(points, a, b):
    direction = (b - a) / np.linalg.norm(b - a)
    offset = points - a
    return np.abs(offset[:, 0] * direction[1] - offset[:, 1] * direction[0])


def test_laminate_layers_follow_appendix_c():
    sheet = cut_sheet(OPTIMUM, "laminate")
    first, second = sheet.layers
    assert (first.key, second.key) == ("1-creases-and-base", "2-outline")
    assert first.colour != second.colour
    n = 10
    assert first.count("valley gap") == n
    # Straight cuts: n - 1 mountains, the seam, n tab creases.
    assert first.count("crease cut") == (n - 1) + 1 + n
    # Base polygon cut in two parts between its two bridges; layer 2 cuts the bridges.
    assert first.count("base polygon") == 2 and second.count("bridge") == 2
    assert second.count("outline") == 1
    bridges = [p.length() for p in second.paths if p.role == "bridge"]
    np.testing.assert_allclose(bridges, 1.0, atol=1e-12)
    polygon_cut = sum(p.length() for p in first.paths if p.role == "base polygon")
    assert polygon_cut + sum(bridges) == pytest.approx(10 * OPTIMUM.P, abs=1e-9)


def test_laminate_gap_is_centred_on_each_valley_and_one_mm_wide():
    pattern = crease_pattern(OPTIMUM)
    sheet = Laminate().cut_sheet(pattern).mirrored()   # back to the outside view
    gaps = [p.points for p in sheet.layer("1-creases-and-base").paths if p.role == "valley gap"]
    # The unmirrored sheet sits where the pattern is (the mirror is about the sheet's middle).
    shift = pattern.outline()[:, 0].min() - sheet.pieces[0][1][:, 0].min()
    valleys = pattern.edges_of_kind("valley")
    for gap, (a, b) in zip(gaps, valleys):
        distance = _distance_to_line(gap + [shift, 0.0], pattern.points[a], pattern.points[b])
        assert distance.max() == pytest.approx(0.5, abs=1e-9)
        assert signed_area(gap) > 0
    # The gap never leaves the strip: every corner within the strip's height.
    heights = np.vstack(gaps)[:, 1]
    strip_height = pattern.points[pattern.top, 1].max()
    assert heights.min() >= -1e-9 and heights.max() <= strip_height + 1e-9


def test_laminate_is_drawn_from_the_inside():
    """The plotter sees the thin-PET side, the inside of the cell: the laminate file is the
    mirror image of the paper file (drawn from the outside) of the same design."""
    paper = Paper().cut_sheet(crease_pattern(OPTIMUM)).pieces[0][1]
    laminate = Laminate().cut_sheet(crease_pattern(OPTIMUM)).pieces[0][1]
    mirrored = paper * [-1.0, 1.0]
    mirrored += [laminate[:, 0].min() - mirrored[:, 0].min(), 0.0]
    assert {tuple(np.round(p, 9)) for p in laminate} == {tuple(np.round(p, 9)) for p in mirrored}


def test_paper_layers():
    sheet = cut_sheet(OPTIMUM, "paper")
    perforations, mountains, outlines = sheet.layers
    assert len({layer.colour for layer in sheet.layers}) == 3
    assert mountains.count("mountain cut") == 9
    assert outlines.count("reinforcement panel") == 20
    assert outlines.count("outline") == 1 and outlines.count("base polygon") == 1
    for path in mountains.paths:                   # 1 mm uncut at each end of an Mg crease
        assert path.length() == pytest.approx(OPTIMUM.Mg - 2.0, abs=1e-9)
    dashes = np.array([p.length() for p in perforations.paths])
    np.testing.assert_allclose(dashes, 1.0, atol=1e-12)


def test_perforation_ties_keep_the_crease_ends():
    pattern = crease_pattern(OPTIMUM)
    sheet = Paper(dash_length=2.0, tie_length=1.5).cut_sheet(pattern)
    a, b = pattern.edges_of_kind("valley")[0]
    start, end = pattern.points[a], pattern.points[b]
    on_crease = [p.points for p in sheet.layers[0].paths
                 if _distance_to_line(p.points, start, end).max() < 1e-9
                 and np.all(np.dot(p.points - start, end - start) > 0)
                 and np.all(np.dot(p.points - end, start - end) > 0)]
    along = sorted(np.linalg.norm(d - start, axis=1).min() for d in on_crease)
    assert along[0] >= 1.5 - 1e-9
    np.testing.assert_allclose(np.diff(along), 3.5, atol=1e-9)   # dash + tie


def test_panels_are_insets_of_the_facets():
    pattern = crease_pattern(OPTIMUM)
    sheet = Paper(panel_inset=2.0).cut_sheet(pattern)
    panels = [p for name, p in sheet.pieces if name.startswith("reinforcement")]
    facets = pattern.faces_of_kind("facet")
    shift = [0.0, pattern.points[pattern.top, 1].max() + Paper().panel_spacing]
    for panel, facet in zip(panels, facets):
        for k in range(3):
            distance = _distance_to_line(panel - shift, facet[k], facet[(k + 1) % 3])
            assert distance.min() == pytest.approx(2.0, abs=1e-9)
    for a in range(len(panels)):
        for b in range(a + 1, len(panels)):
            assert convex_overlap(panels[a], panels[b]) < 0


def test_kerf_moves_outlines_out_and_shrinks_gaps():
    pattern = crease_pattern(OPTIMUM)
    plain, kerfed = Laminate().cut_sheet(pattern), Laminate(kerf=0.2).cut_sheet(pattern)
    width_plain, width_kerfed = plain.size[0], kerfed.size[0]
    assert width_kerfed > width_plain
    gap_plain = [p for p in plain.layers[0].paths if p.role == "valley gap"][3]
    gap_kerf = [p for p in kerfed.layers[0].paths if p.role == "valley gap"][3]
    # Half the kerf off every side of the gap's quadrilateral: 0.1 mm in from each long side.
    assert abs(signed_area(gap_kerf.points)) < abs(signed_area(gap_plain.points))
    bridges = [p.length() for p in kerfed.layers[1].paths if p.role == "bridge"]
    np.testing.assert_allclose(bridges, 1.2, atol=1e-12)  # 1 mm of material + the kerf


@pytest.mark.parametrize("process", ["laminate", "paper"])
@pytest.mark.parametrize("n", [4, 6, 8, 10])
def test_module_sheet_holds_two_cells_of_opposite_chirality_without_overlap(process, n):
    design = kresling.Design(n, 0.8, 15.0)
    single = cut_sheet(design, process)
    module = module_sheet(design, process, cell_spacing=10.0)
    assert [len(layer.paths) for layer in module.layers] == [2 * len(layer.paths)
                                                             for layer in single.layers]
    upper = [p for name, p in module.pieces if name.startswith("cell +1")]
    lower = [p for name, p in module.pieces if name.startswith("cell -1")]
    assert len(upper) == len(lower) == len(single.pieces)
    lowest_upper = min(p[:, 1].min() for p in upper)
    highest_lower = max(p[:, 1].max() for p in lower)
    assert lowest_upper - highest_lower == pytest.approx(10.0, abs=1e-9)
    assert module.size[0] == pytest.approx(single.size[0], abs=1e-9)


@pytest.mark.parametrize(
    "process, options, message",
    [
        ("laminate", {"gap_width": 40.0}, "gap_width = 40.0 mm is invalid for this design"),
        ("laminate", {"gap_width": -1.0}, "gap_width = -1.0 is invalid: must be > 0"),
        ("laminate", {"kerf": 1.5}, "kerf = 1.5 is invalid for the laminate"),
        ("laminate", {"polygon_bridges": 11}, "polygon_bridges = 11 is invalid: must be <= n"),
        ("laminate", {"polygon_bridges": 1.5}, "polygon_bridges = 1.5 is invalid"),
        ("laminate", {"bridge_width": 30.0}, "bridge_width = 30.0 mm is invalid"),
        ("laminate", {"panel_inset": 1.0}, "panel_inset is not a parameter of the laminate"),
        ("paper", {"panel_inset": 9.0}, "panel_inset = 9.0 mm is invalid for this design"),
        ("paper", {"mountain_bridge": 30.0}, "mountain_bridge = 30.0 mm is invalid"),
        ("paper", {"dash_length": 0.0}, "dash_length = 0.0 is invalid"),
        ("paper", {"kerf": 2.0}, "kerf = 2.0 is invalid for paper"),
        ("plastic", {}, r"process = 'plastic' is invalid: must be one of \['laminate', 'paper'\]"),
    ],
)
def test_bad_process_parameters(process, options, message):
    with pytest.raises(ValueError, match=message):
        cut_sheet(OPTIMUM, process, **options)


def test_make_process_rejects_parameters_with_an_instance():
    assert make_process(Paper()) == Paper()
    with pytest.raises(ValueError, match="set them on the instance"):
        make_process(Paper(), kerf=0.1)


def test_tab_height_default_fits_every_thesis_design():
    for n in (4, 6, 8, 10):
        assert 8.0 < 30.0 * math.cos(math.pi / n)
        cut_sheet(kresling.Design(n, 0.7, 60.0), "paper")
