"""``[pattern]``: the crease pattern (a FOLD, OBJ or SVG file, or vertices and panels
inline), how its panels are split into triangles and how its edge assignments are read."""

from __future__ import annotations

import logging
from pathlib import Path

import numpy as np

from kresling.io import UNITS, mm_per_unit, pattern_from_arrays, read_pattern, separate_cuts
from kresling.io.cuts import check_duplicate_vertices
from kresling.model.material_presets import preset_material
from kresling.model.panel_elements import CENTRES, SPLITS, build_panel_elements
from kresling.model.pattern_model import CONVENTIONS
from kresling.simulate.problem_keys import ProblemKey
from kresling.simulate.problem_table import integer, panels, positive, raw, string

__all__ = ["KEY", "node_count"]

#: The logger whose warning says a pattern file's vertices were merged.
MERGE_LOGGER = "kresling.io.coincident_vertices"


def read_pattern_key(t, context) -> dict:
    """The pattern, its split, centre nodes and assignment convention, and the model's node
    count; a named material (``[material] preset``) is made here, its corner springs scaled
    to the pattern's size."""
    split = t.get("split", string, "N5B8", choices=tuple(SPLITS))
    centre = t.get("centre", string, "merlin2", choices=tuple(CENTRES))
    tolerance = t.get("planarity_tolerance", positive, 1e-3)
    unit = t.get("unit", string, None, choices=tuple(UNITS))
    scale = t.get("scale", positive, None)
    if scale is not None and unit != "unit":
        t.fail("scale", f"= {scale!r} applies only with unit = \"unit\" (mm per unit of a "
                        "pattern without a physical unit)")
    frame = t.get("frame", integer, 0)
    snap = t.get("snap_tolerance", positive, None)
    convention = "fold"
    merges = _MergeRecord()
    if snap is not None and not (t.has("file") and str(t.data["file"]).lower().endswith(".svg")):
        t.fail("snap_tolerance", f"= {snap!r} applies only to an SVG drawing's file (its "
                                 "strokes are merged into vertices within it)")
    if t.has("file"):
        name = t.get("file", string)
        path = Path(name) if Path(name).is_absolute() else context.base / name
        if not path.is_file():
            t.fail("file", f"= {name!r}: no such file ({path})")
        if frame < 0:
            t.fail("frame", f"= {frame} is invalid: must be >= 0 (0 is the key frame)")
        if frame and path.suffix.lower() != ".fold":
            t.fail("frame", f"= {frame} applies only to FOLD files: {name!r} has no frames")
        convention = "origami_simulator" if path.suffix.lower() == ".svg" else "fold"
        with merges:
            pattern = read_pattern(path, planarity_tolerance=tolerance, unit=unit,
                                   scale=scale, frame=frame, snap_tolerance=snap)
    elif t.has("vertices"):
        if t.has("frame"):
            t.fail("frame", "applies only to a pattern file (FOLD frames)")
        pattern = _inline_pattern(t, tolerance, unit, scale, "bar" in context.given)
    else:
        t.fail(None, "needs 'file' (a .fold, .obj or .svg file) or 'vertices' and 'panels'")
    convention = t.get("assignments", string, convention, choices=CONVENTIONS)
    if pattern.faces and context.material is None and context.preset is None:
        t.fail("panels" if t.has("panels") else "file",
               "gives panels, which need a [material] (only a structure of [[bar]] and "
               "[[hinge]] members alone, panels = [], goes without one)")
    t.finish()
    pattern = separate_cuts(pattern)
    fields = {"pattern": pattern, "split": split, "centre": centre, "assignments": convention,
              "num_nodes": node_count(pattern, split, centre),
              "renumbered": merges.message}
    if not pattern.faces:   # members alone: no sheet for a material or a preset
        fields.update(material=None, preset=None)
    elif context.preset is not None:
        fields["material"] = preset_material(context.preset, pattern.vertices)
    return fields


class _MergeRecord(logging.Handler):
    """The warning of a pattern file whose coincident vertices were merged (its vertices
    renumbered), caught while the file is read."""

    def __init__(self):
        super().__init__(logging.WARNING)
        self.message = ""

    def emit(self, record):
        self.message = record.getMessage()

    def __enter__(self):
        logging.getLogger(MERGE_LOGGER).addHandler(self)
        return self

    def __exit__(self, *exc):
        logging.getLogger(MERGE_LOGGER).removeHandler(self)


def check_numbering(problem):
    """Node numbers of a pattern file whose vertices were merged would count the merged
    vertices, not the file's: a problem that names nodes or vertices is refused."""
    if not problem.renumbered:
        return
    named = [label for label, given in (
        ("[[support]]", problem.supports and not problem.held), ("[[load]]", problem.loads),
        ("[[spring]]", problem.springs), ("[[mass]]", problem.masses),
        ("[[actuation]] edges", any(a.edges for a in problem.actuations)),
        ("[analysis.stop]", problem.analysis.stop is not None),
        ("[output] curve", problem.output.curve is not None)) if given]
    if named:
        raise ValueError(f"{problem.source}: {named[0]} numbers nodes of a pattern whose file "
                         f"writes a vertex twice ({problem.renumbered}): remove the copy from "
                         "the file, so that its vertex numbers are the problem's")


def _inline_pattern(t, tolerance, unit, scale, members):
    vertices = t.get("vertices", raw)
    given = t.get("panels", raw, required=True,
                  allowed="a list of panels (lists of vertex indices), or [] for a structure "
                          "of [[bar]] and [[hinge]] members alone")
    if given == [] and not members:
        t.fail("panels", "= [] is invalid: must be a non-empty array of panels (each an array "
                         "of vertex indices), or [] for a structure of [[bar]] members alone")
    faces = [] if given == [] else panels(t, "panels", given)
    factor = mm_per_unit(unit or "mm", scale)
    try:
        pattern = pattern_from_arrays(np.asarray(vertices, dtype=float) * factor, faces,
                                      planarity_tolerance=tolerance,
                                      panels_required=False)
        check_duplicate_vertices(pattern.vertices, pattern.faces, pattern.edges,
                                 pattern.edges_assignment, ValueError)
    except (TypeError, ValueError, OverflowError) as error:
        # The pattern calls the panels "faces": name the problem's key.
        t.fail("panels" if str(error).startswith("faces") else "vertices",
               f"does not describe a pattern: {error}")
    return pattern


def node_count(pattern, split, centre="merlin2"):
    """Pattern vertices plus the centre nodes N5B8 adds (one per panel of 4+ vertices that
    is star-shaped from a centre; the others are cut along diagonals)."""
    if split != "N5B8" or all(len(face) == 3 for face in pattern.faces):
        return pattern.num_vertices
    try:
        return len(build_panel_elements(pattern.vertices, pattern.faces, split=split,
                                        centre=centre).nodes)
    except ValueError:  # a bad panel: building the model says which, naming the file
        return pattern.num_vertices + sum(1 for face in pattern.faces if len(face) > 3)


KEY = ProblemKey("pattern", rank=20, read=read_pattern_key, required=True,
                 allowed="a table naming the crease pattern", check=check_numbering)
