"""The two fabrication processes of the thesis, as cut layers made from a crease pattern.

- :class:`Paper` (section 2.2): 150 gsm paper on a cutting plotter; creases perforated,
  mountain creases cut through, reinforcement panels cut as separate pieces.
- :class:`Laminate` (section 4.1, Appendix C): 0.25 mm PET + transfer tape + 0.05 mm PET.
  Cut layer 1 goes through the thick PET before lamination (base polygon, a gap centred on
  each valley crease, straight cuts on the other creases); cut layer 2 cuts the outline
  through the laminate.

Every parameter is a length in mm. Where the thesis gives a value it is the default; where
it is silent the docstring says so and why the default was chosen.
"""

from __future__ import annotations

from dataclasses import dataclass, fields
from typing import ClassVar

import numpy as np

from kresling._validation import show
from kresling.fabrication._checks import cut_path_count, non_negative, positive
from kresling.fabrication.layers import CutLayer, CutPath, CutSheet
from kresling.fabrication.pattern import CreasePattern
from kresling.fabrication.planar import clip_convex, dashes, offset_polygon, shorten, signed_area
from kresling.fabrication.pieces import base_polygon_paths, reinforcement_panels

__all__ = ["Paper", "Laminate", "PROCESSES", "make_process"]


@dataclass(frozen=True)
class Paper:
    """Paper cells (thesis section 2.2): one sheet, three passes of the same blade.

    The file is drawn as seen from the outside of the cell: fold it with the face that was up
    on the cutter outside (turned over, the same file folds the opposite chirality).

    Parameters
    ----------
    dash_length, tie_length : float, default 1.0, 1.0
        Perforation of the valley creases, tab creases and the seam: cut dashes of
        ``dash_length`` separated by uncut ties of ``tie_length`` [mm]. The thesis says
        "perforated cut lines" without numbers; 1 mm / 1 mm folds 150 gsm paper cleanly and
        keeps half of the crease uncut.
    mountain_bridge : float, default 1.0
        Uncut paper left at each end of the cut through a mountain crease [mm]. The thesis
        cuts the mountains (as its refs [24], [27]) but its model keeps a weak bar along them,
        i.e. the strip stays joined at the vertices; it gives no length, so 1 mm.
    panel_inset : float, default 1.5
        How far each reinforcement panel's sides lie inside its facet's creases [mm] (thesis
        silent); the panels are glued to the inside and must not reach the creases.
    kerf : float, default 0.0
        Width of material the tool removes [mm]: outlines move out by half of it, dashes
        and cuts end half of it early. 0 for the thesis's drag-knife plotter (Graphtec
        FCX4000); about 0.1-0.2 for a laser.
    panel_spacing : float, default 5.0
        Gap between the strip and the panels in the layout [mm].
    """

    dash_length: float = 1.0
    tie_length: float = 1.0
    mountain_bridge: float = 1.0
    panel_inset: float = 1.5
    kerf: float = 0.0
    panel_spacing: float = 5.0

    name: ClassVar[str] = "paper"
    #: FOLD assignment per crease kind: paper's mountains are cut ("C": faces joined only
    #: at the cut's ends, the thesis's zero-stiffness "cut hinge").
    fold_assignments: ClassVar[dict] = {"mountain": "C", "valley": "V", "tab": "M",
                                        "seam": "M", "boundary": "B"}

    def __post_init__(self):
        for name in ("dash_length", "tie_length", "panel_inset"):
            positive(name, getattr(self, name))
        for name in ("mountain_bridge", "panel_spacing"):
            non_negative(name, getattr(self, name))
        if non_negative("kerf", self.kerf) >= self.dash_length:
            raise ValueError(f"kerf = {self.kerf!r} is invalid for paper: must be < dash_length "
                             f"= {self.dash_length!r} mm (each dash is shortened by the kerf)")

    def cut_sheet(self, pattern: CreasePattern) -> CutSheet:
        """The three cut passes of a paper cell. Returns a :class:`CutSheet`."""
        half_kerf = 0.5 * self.kerf
        lines = [(pattern.points[a], pattern.points[b]) for kind in ("valley", "tab", "seam")
                 for a, b in pattern.edges_of_kind(kind)]
        lengths = np.array([np.linalg.norm(b - a) for a, b in lines])
        cut_path_count(int(np.maximum(np.floor((lengths - self.tie_length)
                                               / (self.dash_length + self.tie_length)), 0).sum()),
                       f"lengthen the dashes (dash_length = {self.dash_length:g} mm, "
                       f"tie_length = {self.tie_length:g} mm) or cut a smaller design")
        perforated = [dash for kind in ("valley", "tab", "seam")
                      for a, b in pattern.edges_of_kind(kind)
                      for dash in dashes(pattern.points[a], pattern.points[b], self.dash_length,
                                         self.tie_length, self.kerf)]
        mountains = [_mountain_cut(pattern, a, b, self.mountain_bridge, self.kerf)
                     for a, b in pattern.edges_of_kind("mountain")]
        outline = offset_polygon(pattern.outline(), half_kerf)
        polygon = offset_polygon(pattern.base_polygon(), half_kerf)
        panels = [offset_polygon(panel, half_kerf)
                  for panel in reinforcement_panels(pattern, self.panel_inset, self.panel_spacing)]
        layers = (
            CutLayer("1-perforations", "1 perforated creases (valleys, tabs, seam)", "#00a000",
                     tuple(CutPath(d, False, "perforation") for d in perforated),
                     "full-depth cut; the ties hold the crease"),
            CutLayer("2-mountain-cuts", "2 mountain creases cut through", "#0000ff",
                     tuple(CutPath(m, False, "mountain cut") for m in mountains),
                     "full-depth cut, stopping mountain_bridge short of each vertex"),
            CutLayer("3-outlines", "3 outlines (cell, base polygon, reinforcement panels)",
                     "#ff0000",
                     (CutPath(outline, True, "outline"), CutPath(polygon, True, "base polygon"))
                     + tuple(CutPath(p, True, "reinforcement panel") for p in panels),
                     "full-depth cut, last so the sheet does not move before"),
        )
        pieces = (("cell", outline), ("base polygon", polygon)) + tuple(
            (f"reinforcement panel {k}", panel) for k, panel in enumerate(panels))
        notes = ("drawn from the outside of the cell: fold with the face up on the cutter outside",
                 "reinforcement panels: turn them over with the strip and glue each inside the "
                 "facet it was cut above",
                 "glue the closing tab inside facet 0, then the tabs onto the base polygon")
        return CutSheet(_title(pattern, self), layers, pieces, notes)


@dataclass(frozen=True)
class Laminate:
    """PET laminate cells (thesis section 4.1 and Appendix C): two cut layers.

    Layer 1 is cut into the 0.25 mm PET with its transfer tape before the 0.05 mm PET goes
    on (blade depth 0.4 mm): the base polygon, a gap centred on every valley crease and a
    straight cut on every other crease. The gap pieces and the base polygon are lifted out,
    the thin PET is laminated on, and layer 2 cuts the outline. The thin PET is the hinge.

    The file is drawn as the plotter sees the sheet, from the thin-PET side, which is the
    inside of the cell: the valleys fold towards the thick PET (hence their gap, Appendix C
    step 2), so the thick PET is outside. It is therefore the mirror image of the paper
    file of the same chirality.

    Parameters
    ----------
    gap_width : float, default 1.0
        Width of the material removed along each valley crease, centred on it [mm]; thesis
        section 4.1 and Appendix C step 2 (1 mm).
    polygon_bridges : int, default 2
        Uncut bridges left in layer 1 on the base polygon's outline so it does not come loose
        during the passes of the first cut; layer 2 cuts them (Appendix C step 3 asks for
        "some material", without a number: 2, on opposite edges).
    bridge_width : float, default 1.0
        Length of each bridge [mm] (thesis silent).
    kerf : float, default 0.0
        Tool kerf [mm]; see :class:`Paper`. The valley gaps shrink by it so that the gap
        removed is ``gap_width``.
    """

    gap_width: float = 1.0
    polygon_bridges: int = 2
    bridge_width: float = 1.0
    kerf: float = 0.0

    name: ClassVar[str] = "laminate"
    #: FOLD assignment per crease kind: every crease is a thin-PET hinge.
    fold_assignments: ClassVar[dict] = {"mountain": "M", "valley": "V", "tab": "M",
                                        "seam": "M", "boundary": "B"}

    def __post_init__(self):
        positive("gap_width", self.gap_width)
        positive("bridge_width", self.bridge_width)
        if non_negative("kerf", self.kerf) >= self.gap_width:
            raise ValueError(f"kerf = {self.kerf!r} is invalid for the laminate: must be < "
                             f"gap_width = {self.gap_width!r} mm")
        bridges = self.polygon_bridges
        if isinstance(bridges, bool) or not isinstance(bridges, (int, np.integer)) or bridges < 0:
            raise ValueError(f"polygon_bridges = {bridges!r} is invalid: must be an integer >= 0")

    def cut_sheet(self, pattern: CreasePattern) -> CutSheet:
        """Cut layers 1 and 2 of a laminate cell, drawn from the inside. Returns a
        :class:`CutSheet`."""
        half_kerf = 0.5 * self.kerf
        gaps = [_valley_gap(pattern, a, b, self.gap_width, half_kerf)
                for a, b in pattern.edges_of_kind("valley")]
        straight = [pattern.points[[a, b]] for kind in ("mountain", "tab", "seam")
                    for a, b in pattern.edges_of_kind(kind)]
        polygon = offset_polygon(pattern.base_polygon(), half_kerf)
        polygon_cuts, bridges = base_polygon_paths(polygon, self.polygon_bridges,
                                                   self.bridge_width + self.kerf)
        outline = offset_polygon(pattern.outline(), half_kerf)
        layers = (
            CutLayer("1-creases-and-base", "cut layer 1: base polygon, valley gaps, crease cuts",
                     "#0000ff",
                     tuple(CutPath(g, True, "valley gap") for g in gaps)
                     + tuple(CutPath(s, False, "crease cut") for s in straight)
                     + tuple(CutPath(c, False, "base polygon") for c in polygon_cuts),
                     "before lamination, through the 0.25 mm PET and tape (blade depth 0.4 mm); "
                     "lift out the valley gaps and the base polygon"),
            CutLayer("2-outline", "cut layer 2: outline", "#ff0000",
                     (CutPath(outline, True, "outline"),)
                     + tuple(CutPath(b, False, "bridge") for b in bridges),
                     "after laminating the 0.05 mm PET, through the whole laminate"),
        )
        pieces = (("cell", outline), ("base polygon", polygon))
        notes = ("drawn from the thin-PET side, which is the inside of the cell",
                 "glue the closing tab inside facet 0, then the tabs onto the adhesive side "
                 "of the base polygon")
        return CutSheet(_title(pattern, self), layers, pieces, notes).mirrored()


#: The processes by name.
PROCESSES = {"paper": Paper, "laminate": Laminate}


def make_process(process, **parameters):
    """A process from its name (``"paper"`` or ``"laminate"``) and parameters.

    A :class:`Paper` or :class:`Laminate` instance is returned as it is (then no parameters
    may be given).

    Raises
    ------
    ValueError
        For an unknown name or parameter, or an invalid value; the message lists what is
        allowed.
    """
    if isinstance(process, tuple(PROCESSES.values())):
        if parameters:
            raise ValueError(f"parameters {sorted(parameters)} given with a {process.name} "
                             "process instance: set them on the instance")
        return process
    if not isinstance(process, str) or process not in PROCESSES:
        raise ValueError(f"process = {show(process)} is invalid: must be one of "
                         f"{sorted(PROCESSES)} (or a Paper or Laminate instance)")
    kind = PROCESSES[process]
    allowed = [f.name for f in fields(kind)]
    unknown = sorted(set(parameters) - set(allowed))
    if unknown:
        raise ValueError(f"{unknown[0]} is not a parameter of the {process} process: "
                         f"allowed are {allowed}")
    return kind(**parameters)


def _title(pattern: CreasePattern, process) -> str:
    d = pattern.design
    return (f"Kresling cell n={d.n} lam={d.lam:g} Lc={d.Lc:g} mm R={d.R:g} mm "
            f"chirality={d.chirality:+d}, {process.name}")


def _mountain_cut(pattern: CreasePattern, a: int, b: int, bridge: float, kerf: float):
    """The cut along mountain crease ``a-b``, ``bridge`` (plus half the kerf) short of each end."""
    start, end = pattern.points[a], pattern.points[b]
    length = float(np.linalg.norm(end - start))
    if 2.0 * bridge + kerf >= length:
        raise ValueError(f"mountain_bridge = {bridge!r} mm is invalid for this design: the "
                         f"mountain creases are {length:.4g} mm long; must be < "
                         f"{0.5 * (length - kerf):.4g} mm")
    return shorten(start, end, bridge + 0.5 * kerf, bridge + 0.5 * kerf)


def _valley_gap(pattern: CreasePattern, a: int, b: int, width: float, half_kerf: float):
    """The quadrilateral removed along valley crease ``a-b``: ``width`` wide, centred on the
    crease, cut off where the strip ends (its bottom and top edges, its two ends)."""
    start, end = pattern.points[a], pattern.points[b]
    length = float(np.linalg.norm(end - start))
    along = (end - start) / length
    across = np.array([-along[1], along[0]])
    # The facets either side are as high across the valley as 2 * area / Vg.
    height = abs(signed_area(pattern.faces_of_kind("facet")[0])) * 2.0 / length
    if 0.5 * width >= height:
        raise ValueError(f"gap_width = {width!r} mm is invalid for this design: the facets are "
                         f"{height:.4g} mm high across a valley crease and the gap takes half "
                         f"its width from each; must be < {2 * height:.4g} mm")
    reach = width + length  # long enough to cross the strip's edges, which then cut it
    gap = np.array([start - reach * along - 0.5 * width * across,
                    end + reach * along - 0.5 * width * across,
                    end + reach * along + 0.5 * width * across,
                    start - reach * along + 0.5 * width * across])
    strip = pattern.points[[pattern.bottom[0], pattern.bottom[-1], pattern.top[-1], pattern.top[0]]]
    strip = strip if signed_area(strip) > 0 else strip[::-1]
    for k in range(4):
        edge = strip[(k + 1) % 4] - strip[k]
        gap = clip_convex(gap, strip[k], [-edge[1], edge[0]])   # left of a CCW edge is inside
    gap = gap if signed_area(gap) > 0 else gap[::-1]
    return offset_polygon(gap, -half_kerf)
