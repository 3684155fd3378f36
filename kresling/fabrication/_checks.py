"""Checks on fabrication parameters; messages name the parameter, the value and what is allowed."""

from __future__ import annotations

import math
import numbers

from kresling._validation import show


def _real(name: str, value) -> float:
    if isinstance(value, bool) or not isinstance(value, numbers.Real) or not math.isfinite(value):
        raise ValueError(f"{name} = {show(value)} is invalid: must be a finite number")
    return float(value)


def positive(name: str, value) -> float:
    """``value`` as a float; it must be finite and > 0 (a length in mm)."""
    if _real(name, value) <= 0.0:
        raise ValueError(f"{name} = {show(value)} is invalid: must be > 0 (mm)")
    return float(value)


def non_negative(name: str, value) -> float:
    """``value`` as a float; it must be finite and >= 0 (a length in mm)."""
    if _real(name, value) < 0.0:
        raise ValueError(f"{name} = {show(value)} is invalid: must be >= 0 (mm)")
    return float(value)


#: Largest cut sheet, each side [mm]: beyond any cutting bed or plotter (a sheet of
#: Design(17, 0.82, 10000, 1621) would be 10 m by 12 m).
MAX_SHEET_SIZE = 5000.0
#: Most cut paths on one sheet (dashes count one each): writing more takes minutes and no
#: cutter's job file holds them (that 12 m sheet had 198 784).
MAX_CUT_PATHS = 50_000
#: Largest PNG preview [pixels]: 100 megapixels (a 5 m sheet at 96 dpi would be 357).
MAX_PNG_PIXELS = 100_000_000


def sheet_size(what: str, width: float, height: float) -> None:
    """Refuse a layout wider or taller than :data:`MAX_SHEET_SIZE` (``what`` names it)."""
    if not (width <= MAX_SHEET_SIZE and height <= MAX_SHEET_SIZE):
        raise ValueError(f"{what} spans {width:.6g} x {height:.6g} mm: a cut sheet must be at "
                         f"most {MAX_SHEET_SIZE:g} mm on a side (beyond any cutting bed); "
                         "scale the design down (R, Lc)")


def cut_path_count(count: int, cause: str) -> None:
    """Refuse more than :data:`MAX_CUT_PATHS` cut paths (``cause``: what to change)."""
    if count > MAX_CUT_PATHS:
        raise ValueError(f"the sheet would hold {count} cut paths: at most {MAX_CUT_PATHS}; "
                         f"{cause}")


def png_pixels(width_mm: float, height_mm: float, dpi: float) -> float:
    """``dpi`` checked: finite, > 0, at least one pixel across and at most
    :data:`MAX_PNG_PIXELS` pixels."""
    given, dpi = dpi, _real("dpi", dpi)
    if dpi <= 0:
        raise ValueError(f"dpi = {show(given)} is invalid: must be > 0")
    if min(width_mm, height_mm) / 25.4 * dpi < 1.0:  # cairo cannot draw a 0-pixel image
        smallest = 25.4 / min(width_mm, height_mm)
        raise ValueError(f"dpi = {show(given)} is invalid for a {width_mm:.6g} x {height_mm:.6g} "
                         f"mm sheet: the PNG would be under one pixel across; must be at least "
                         f"{smallest:.3g}")
    pixels = (width_mm / 25.4 * dpi) * (height_mm / 25.4 * dpi)
    if pixels > MAX_PNG_PIXELS:
        largest = dpi * math.sqrt(MAX_PNG_PIXELS / pixels)
        raise ValueError(f"dpi = {show(given)} is invalid for a {width_mm:.6g} x {height_mm:.6g} "
                         f"mm sheet: the PNG would have {pixels:.3g} pixels; must be at most "
                         f"{largest:.3g} (a {MAX_PNG_PIXELS // 1_000_000} megapixel preview)")
    return dpi
