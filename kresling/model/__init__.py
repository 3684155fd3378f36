"""Bar-and-hinge models: nodes, bars, rotational-spring hinges and supports.

:class:`Model` is immutable and validated on construction (bad input raises a ``ValueError``
that names the element). :func:`panel_topology` turns panels into triangles, bars and hinges
by MERLIN2's rules.
"""

from kresling.model.kresling_specimen import (EDGE_FAMILIES, KreslingSpecimen,
                                              SpecimenParameters, alternating_chirality,
                                              kresling_specimen)
from kresling.model.model import BAR_LAWS, SPRING_LAWS, Model
from kresling.model.topology import Topology, panel_topology

__all__ = ["Model", "Topology", "panel_topology", "BAR_LAWS", "SPRING_LAWS",
           "KreslingSpecimen", "SpecimenParameters", "kresling_specimen", "EDGE_FAMILIES",
           "alternating_chirality"]
