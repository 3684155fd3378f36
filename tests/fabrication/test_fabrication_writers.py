"""SVG, DXF and PNG files read back: true millimetres, one layer per cut pass, every path."""

import builtins
import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import kresling
from kresling.fabrication import (cut_sheet, module_sheet, render_png, svg_document, write_dxf,
                                  write_pattern, write_svg)

SVG = "{http://www.w3.org/2000/svg}"
INKSCAPE = "{http://www.inkscape.org/namespaces/inkscape}"
OPTIMUM = kresling.Design(10, 0.9, 15.0)


@pytest.fixture(scope="module", params=["laminate", "paper"])
def sheet(request):
    return cut_sheet(OPTIMUM, request.param)


def _path_points(d):
    return np.array([[float(x), float(y)] for x, y in re.findall(r"([-\d.]+),([-\d.]+)", d)])


def test_svg_is_true_scale_with_one_layer_per_pass(sheet, tmp_path):
    root = ET.parse(write_svg(sheet, tmp_path / "cell.svg", margin=5.0)).getroot()
    width, height = sheet.size
    assert root.get("width") == f"{width + 10:.6f}mm"
    assert root.get("height") == f"{height + 10:.6f}mm"
    assert [float(v) for v in root.get("viewBox").split()] == pytest.approx(
        [0, 0, width + 10, height + 10], abs=1e-6)
    groups = root.findall(f"{SVG}g")
    assert [g.get(f"{INKSCAPE}label") for g in groups] == [layer.name for layer in sheet.layers]
    assert all(g.get(f"{INKSCAPE}groupmode") == "layer" for g in groups)
    colours = [re.search(r"stroke:(#[0-9a-f]{6})", g.get("style")).group(1) for g in groups]
    assert colours == [layer.colour for layer in sheet.layers] and len(set(colours)) == len(colours)
    for group, layer in zip(groups, sheet.layers):
        paths = group.findall(f"{SVG}path")
        assert len(paths) == len(layer.paths)
        closed = [p.get("d").endswith("Z") for p in paths]
        assert closed == [p.closed for p in layer.paths]
    # Every coordinate lies inside the viewBox, and the margins are 5 mm on each side.
    points = np.vstack([_path_points(p.get("d")) for p in root.iter(f"{SVG}path")])
    assert points.min(axis=0) == pytest.approx([5.0, 5.0], abs=1e-6)
    assert points.max(axis=0) == pytest.approx([width + 5, height + 5], abs=1e-6)


def test_svg_keeps_the_drawing_unmirrored(tmp_path):
    """SVG's y points down; the file must show the sheet as seen from above, not flipped."""
    sheet = cut_sheet(OPTIMUM, "paper")
    root = ET.fromstring(svg_document(sheet, margin=0.0))
    outline = root.findall(f"{SVG}g")[2].findall(f"{SVG}path")[0]
    points = _path_points(outline.get("d"))
    (x0, _), (_, y1) = sheet.bounds()
    expected = sheet.layers[2].paths[0].points
    np.testing.assert_allclose(points, np.column_stack([expected[:, 0] - x0, y1 - expected[:, 1]]),
                               atol=1e-6)


def test_dxf_reads_back_with_layers_and_entities(sheet, tmp_path):
    import ezdxf  # in the test extra: a missing one must fail, not skip
    document = ezdxf.readfile(write_dxf(sheet, tmp_path / "cell.dxf"))
    assert document.units == ezdxf.units.MM
    names = [layer.key for layer in sheet.layers]
    assert set(names) <= {layer.dxf.name for layer in document.layers}
    entities = list(document.modelspace())
    assert all(e.dxftype() == "LWPOLYLINE" for e in entities)
    for layer in sheet.layers:
        mine = [e for e in entities if e.dxf.layer == layer.key]
        assert len(mine) == len(layer.paths)
        assert [e.closed for e in mine] == [p.closed for p in layer.paths]
        assert document.layers.get(layer.key).rgb == tuple(
            int(layer.colour[k:k + 2], 16) for k in (1, 3, 5))
    corners = np.vstack([np.array(e.get_points("xy")) for e in entities])
    assert corners.min(axis=0) == pytest.approx([0.0, 0.0], abs=1e-9)
    assert corners.max(axis=0) == pytest.approx(sheet.size, abs=1e-9)


def test_png_render_of_the_svg(tmp_path):
    from PIL import Image  # comes with cairosvg (test extra)

    sheet = module_sheet(kresling.Design(6, 0.8, 15.0), "laminate")
    path = render_png(svg_document(sheet, stroke_width=0.3), tmp_path / "module.png", dpi=50.8)
    image = Image.open(path)
    width, height = sheet.size
    # 50.8 dpi = 2 px per mm; the SVG has a 5 mm margin on each side.
    assert image.size == (round(2 * (width + 10)), round(2 * (height + 10)))
    pixels = np.asarray(image.convert("RGB"))
    assert (pixels == 255).all(axis=2).mean() > 0.8          # mostly white sheet
    red = (pixels[..., 0] > 200) & (pixels[..., 1] < 80) & (pixels[..., 2] < 80)
    blue = (pixels[..., 2] > 200) & (pixels[..., 0] < 80) & (pixels[..., 1] < 80)
    assert red.any() and blue.any()                          # both cut layers drawn


def test_missing_extra_is_named(monkeypatch, tmp_path):
    real_import = builtins.__import__

    def no_cairosvg(name, *args, **kwargs):
        if name in ("cairosvg", "ezdxf"):
            raise ImportError(f"No module named {name!r}")
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_cairosvg)
    with pytest.raises(ImportError, match=r"pip install 'kresling\[fabrication\]'"):
        write_pattern(tmp_path / "cell.png", OPTIMUM)
    with pytest.raises(ImportError, match=r"needs ezdxf: pip install 'kresling\[fabrication\]'"):
        write_pattern(tmp_path / "cell.dxf", OPTIMUM)


@pytest.mark.parametrize("name", ["cell.pdf", "cell", "cell.SVG.bak"])
def test_unknown_extension(name, tmp_path):
    with pytest.raises(ValueError, match=r"file extension .* is invalid: must be one of"):
        write_pattern(tmp_path / name, OPTIMUM)


def test_module_fold_is_refused(tmp_path):
    with pytest.raises(ValueError, match="module = True is invalid with .fold"):
        write_pattern(tmp_path / "m.fold", OPTIMUM, module=True)


def test_a_png_under_one_pixel_across_is_refused_naming_dpi(tmp_path):
    # A 3-sided cell's sheet is ~100 x 59 mm with its margins: at 0.125 dpi under a pixel
    # across, which cairo cannot draw ("the SVG size is undefined").
    design = kresling.Design(3, 0.75, 1.0, R=16.0)
    with pytest.raises(ValueError, match=r"dpi = 0\.125 .* under one pixel"):
        write_pattern(tmp_path / "sheet.png", design, "laminate", dpi=0.125)
    assert write_pattern(tmp_path / "sheet.png", design, "laminate", dpi=1.0).stat().st_size
