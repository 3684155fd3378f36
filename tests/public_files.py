"""What the tests of public crease-pattern files share: where the files are, the materials
they are simulated with, and how a pattern is held."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from kresling.io import read_pattern
from kresling.model import ManualProperties

PUBLIC = Path(__file__).resolve().parent / "data" / "public"
SPEC, RABBIT_EAR, ORIGAMI_SIMULATOR = (PUBLIC / "fold_spec", PUBLIC / "rabbit_ear",
                                       PUBLIC / "origami_simulator")
#: Stiff bars, panels as stiff in bending as the creases in folding (N, mm).
STIFF = {"calibration": "manual", "bar_modulus": 1e5, "bar_area": 1.0,
         "fold_stiffness": 1.0, "bend_stiffness": 1.0}
MANUAL = ManualProperties(bar_modulus=1e5, bar_area=1.0, fold_stiffness=1.0, bend_stiffness=1.0)
#: The unit-square files (FOLD's "unit") are read as a 100 mm sheet.
SHEET = {"unit": "unit", "scale": 100.0}


def read(path, keys):
    """The pattern a problem's [pattern] keys read."""
    return read_pattern(path, **{k: v for k, v in keys.items() if k in ("unit", "scale", "frame")})


def held_and_far(pattern):
    """The corners of the first panel (held: no rigid-body motion, nothing blocked) and the
    vertex farthest from them."""
    held = list(pattern.faces[0][:3])
    distance = np.linalg.norm(pattern.vertices - pattern.vertices[held[0]], axis=1)
    distance[held] = -1.0
    return held, int(np.argmax(distance))


def diagonal(pattern) -> float:
    """The diagonal of the pattern's bounding box [mm]."""
    return float(np.linalg.norm(np.ptp(pattern.vertices, axis=0)))
