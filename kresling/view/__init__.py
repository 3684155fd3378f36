"""Interactive 3D views and animations of bar-and-hinge models and their paths (plotly).

- :func:`view_model`: a model (or a Kresling specimen) in one state: shaded panels, creases
  coloured by family, optionally edges coloured by a field (bar strain, hinge angle change,
  stored energy) with a colour bar;
- :func:`view_path`: a :class:`kresling.solvers.PathResult` animated over its increments
  (slider, play/pause) beside its load-displacement curve, whose marker follows the frame;
- :func:`write_html`: one self-contained page that works offline and opens at
  ``#frame=K``.

The figures are :class:`plotly.graph_objects.Figure`: they display themselves in Jupyter,
and ``.show()`` opens them elsewhere. Coordinates are rounded to 1e-4 mm in the figures.

Examples
--------
>>> from kresling import Design
>>> from kresling.model import kresling_specimen
>>> from kresling.view import view_model
>>> fig = view_model(kresling_specimen(Design(8, 0.8, 30), ["extended"] * 2))
>>> fig.layout.scene.aspectmode
'data'
"""

from kresling.view.fields import FIELDS, element_energy
from kresling.view.figure import view_model, view_path
from kresling.view.html import write_html
from kresling.view.surface import FAMILY_STYLES

__all__ = ["view_model", "view_path", "write_html", "FIELDS", "FAMILY_STYLES",
           "element_energy"]
