"""Bar-and-hinge models: nodes, bars, rotational-spring hinges and supports.

:class:`Model` is immutable and validated on construction (bad input raises a ``ValueError``
that names the element). :func:`panel_topology` turns panels into triangles, bars and hinges
by MERLIN2's rules for the Kresling specimen; :func:`build_pattern_model` builds the model of
any crease pattern (panels, fold families, a sheet's material) as MERLIN2 v1.1 does.
"""

from kresling.model.kresling_specimen import (EDGE_FAMILIES, MOUNTAIN_CREASES, KreslingSpecimen,
                                              SpecimenParameters, alternating_chirality,
                                              kresling_specimen)
from kresling.model.calibration import (ManualProperties, SheetMaterial, SheetStiffness,
                                        calibrate_sheet)
from kresling.model.members import Members
from kresling.model.model import BAR_LAWS, SPRING_LAWS, Model, family_kinds
from kresling.model.panel_elements import PanelElements, build_panel_elements
from kresling.model.pattern_model import (FOLD_FAMILIES, HINGE_FAMILIES, CreaseLaws, HingeLaw,
                                          PatternModel, build_pattern_model)
from kresling.model.topology import Topology, panel_topology

__all__ = ["Model", "Topology", "panel_topology", "BAR_LAWS", "SPRING_LAWS",
           "KreslingSpecimen", "SpecimenParameters", "kresling_specimen", "EDGE_FAMILIES",
           "MOUNTAIN_CREASES",
           "alternating_chirality", "PanelElements", "build_panel_elements", "SheetMaterial",
           "ManualProperties", "SheetStiffness", "calibrate_sheet", "HingeLaw", "CreaseLaws",
           "PatternModel", "build_pattern_model", "FOLD_FAMILIES", "HINGE_FAMILIES", "family_kinds",
           "Members"]
