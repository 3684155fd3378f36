"""Fuzz: crease patterns, cut sheets and the files they are written to."""

import tempfile
from pathlib import Path

from hypothesis import given
from hypothesis import strategies as st

from _fuzz import attempt, edgy_floats, finite, fuzz, junk, mostly
from kresling import Design
from kresling.fabrication import crease_pattern, cut_sheet, module_sheet, write_pattern

designs = st.builds(Design, n=st.integers(3, 16), lam=st.floats(0.55, 0.95),
                    Lc=mostly(st.floats(1, 60), st.floats(0, 5000)),
                    R=mostly(st.floats(5, 60), st.floats(0.01, 3000)),
                    chirality=st.sampled_from([1, -1]))
lengths = mostly(st.floats(0.1, 20), edgy_floats, junk)
parameters = st.fixed_dictionaries({}, optional={
    "tab_height": lengths, "closing_tab_width": lengths, "tab_clearance": lengths,
    "polygon_spacing": lengths, "kerf": lengths, "gap_width": lengths, "dash_length": lengths,
    "tie_length": lengths, "panel_inset": lengths, "mountain_bridge": lengths,
    "unknown_parameter": lengths})
NAMES = ("design", "source", "process", "tab_height", "closing_tab_width", "tab_clearance",
         "polygon_spacing", "kerf", "gap_width", "dash_length", "tie_length", "panel_inset",
         "mountain_bridge", "unknown_parameter", "parameter", "cell_spacing", "dpi", "module",
         "sheet", "crease pattern", "extension", "path", "cut paths", "bridge", "clearance")


@fuzz(120)
@given(mostly(designs, junk), mostly(st.sampled_from(["laminate", "paper"]), junk), parameters)
def test_cut_sheet(design, process, kwargs):
    sheet = attempt(lambda: cut_sheet(design, process, **kwargs), *NAMES)
    if sheet is not None:
        for layer in sheet.layers:
            for path in layer.paths:
                finite(path.points)
        finite(sheet.size)


@fuzz(60)
@given(mostly(designs, junk), parameters,
       mostly(st.floats(0, 50), edgy_floats, junk))
def test_module_sheet(design, kwargs, spacing):
    kwargs.pop("unknown_parameter", None)
    sheet = attempt(lambda: module_sheet(design, "laminate", cell_spacing=spacing, **kwargs),
                    *NAMES)
    if sheet is not None:
        finite(sheet.size)


@fuzz(40)
@given(mostly(designs, junk), st.sampled_from([".svg", ".dxf", ".fold", ".png", ".txt", ""]),
       mostly(st.sampled_from(["laminate", "paper"]), junk), st.booleans(),
       mostly(st.floats(10, 100), edgy_floats, junk))
def test_write_pattern(design, suffix, process, module, dpi):
    with tempfile.TemporaryDirectory() as directory:
        path = Path(directory) / f"sheet{suffix}"
        try:
            written = write_pattern(path, design, process, module=module, dpi=dpi)
        except ImportError:
            return  # an optional extra (ezdxf, cairosvg) missing: says so
        except ValueError as error:
            assert any(name in str(error) for name in NAMES + (suffix or "sheet",)), error
            return
        assert Path(written).stat().st_size > 0


@fuzz(100)
@given(mostly(designs, junk), parameters)
def test_crease_pattern(design, kwargs):
    for key in ("kerf", "gap_width", "dash_length", "tie_length", "panel_inset",
                "mountain_bridge", "unknown_parameter"):  # keyword-only: not its parameters
        kwargs.pop(key, None)
    pattern = attempt(lambda: crease_pattern(design, **kwargs), *NAMES)
    if pattern is not None:
        finite(pattern.points)
