"""Bar-and-hinge models: nodes, bars, rotational-spring hinges and supports.

:class:`Model` is immutable and validated on construction (bad input raises a ``ValueError``
that names the element). :func:`panel_topology` turns panels into triangles, bars and hinges
by MERLIN2's rules for the Kresling specimen; :func:`build_pattern_model` builds the model of
any crease pattern (panels, fold families, a sheet's material) as MERLIN2 v1.1 does.
"""

from kresling._lazy import lazy_names
# kresling_specimen is also a module's name: imported here, not when first used.
from kresling.model.kresling_specimen import kresling_specimen

# Imported when first used: the bending test needs the specimen's model, not the pattern
# models (nor the pattern readers they bring).
__getattr__, __dir__ = lazy_names(__name__, {
    **dict.fromkeys(["EDGE_FAMILIES", "MOUNTAIN_CREASES", "KreslingSpecimen",
                     "SpecimenParameters", "alternating_chirality"], "kresling_specimen"),
    **dict.fromkeys(["ManualProperties", "SheetMaterial", "SheetStiffness", "calibrate_sheet"],
                    "calibration"),
    "Members": "members",
    **dict.fromkeys(["BAR_LAWS", "SPRING_LAWS", "Model", "family_kinds"], "model"),
    **dict.fromkeys(["PanelElements", "build_panel_elements"], "panel_elements"),
    **dict.fromkeys(["FOLD_FAMILIES", "HINGE_FAMILIES", "CreaseLaws", "HingeLaw",
                     "PatternModel", "build_pattern_model"], "pattern_model"),
    **dict.fromkeys(["Topology", "panel_topology"], "topology")})

__all__ = ["Model", "Topology", "panel_topology", "BAR_LAWS", "SPRING_LAWS",
           "KreslingSpecimen", "SpecimenParameters", "kresling_specimen", "EDGE_FAMILIES",
           "MOUNTAIN_CREASES",
           "alternating_chirality", "PanelElements", "build_panel_elements", "SheetMaterial",
           "ManualProperties", "SheetStiffness", "calibrate_sheet", "HingeLaw", "CreaseLaws",
           "PatternModel", "build_pattern_model", "FOLD_FAMILIES", "HINGE_FAMILIES", "family_kinds",
           "Members"]
