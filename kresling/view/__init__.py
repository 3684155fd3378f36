"""Interactive 3D views and animations of bar-and-hinge models and their paths (plotly).

- :func:`view_model`: a model (or a Kresling specimen) in one state: shaded panels, creases
  coloured by family, optionally edges coloured by a field (bar strain, hinge angle change,
  stored energy) with a colour bar;
- :func:`view_path`: a :class:`kresling.solvers.PathResult` animated over its increments
  (slider, play/pause) beside its load-displacement curve, whose marker follows the frame;
- :func:`view_bending` and :func:`view_snap_through`: the thesis's bending test in both
  stable states (two scenes, one slider, both moment-angle curves) and its snap-through
  test beside the force-travel curve;
- :func:`view_fold`: any FOLD (or OBJ) file, its frames animated;
- :func:`write_html`: one self-contained page that works offline and opens at
  ``#frame=K``; :func:`check_writable` checks its path before a long computation;
- :mod:`kresling.view.explorer`: the design explorer page (sliders over n, lambda and Lc,
  the cell in both states, its flat pattern, the K_B-ratio and snap-force maps);
- :class:`ExplorerWidget`: the same explorer in Jupyter, every design recomputed live by
  the C++ core (needs ``ipywidgets`` and ``anywidget``).

The figures are :class:`plotly.graph_objects.Figure`: they display themselves in Jupyter,
and ``.show()`` opens them elsewhere. Coordinates are rounded to 1e-10 mm in the figures
(a page's frames hold the path's node positions to that precision).

Examples
--------
>>> from kresling import Design
>>> from kresling.model import kresling_specimen
>>> from kresling.view import view_model
>>> fig = view_model(kresling_specimen(Design(8, 0.8, 30), ["extended"] * 2))
>>> fig.layout.scene.aspectmode
'data'
"""

from kresling.view.explorer_widget import ExplorerWidget
from kresling.view.fields import FIELDS, element_energy
from kresling.view.figure import view_model, view_path
from kresling.view.fold import view_fold
from kresling.view.html import check_writable, write_html
from kresling.view.specimens import view_bending, view_snap_through
from kresling.view.surface import FAMILY_STYLES

__all__ = ["view_model", "view_path", "view_bending", "view_snap_through", "view_fold",
           "write_html", "check_writable", "FIELDS", "FAMILY_STYLES", "element_energy",
           "ExplorerWidget"]
