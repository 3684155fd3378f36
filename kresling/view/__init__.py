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
- :func:`write_path_page`: a path's page (as ``write_html(view_path(...))``) written
  straight from its arrays, without plotly's Python: frames as compressed binary, plotly's
  JavaScript compressed, under 2 MB for MERLIN2's examples (``kresling simulate``'s
  view.html);
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

from kresling._lazy import lazy_names

__all__ = ["view_model", "view_path", "view_bending", "view_snap_through", "view_fold",
           "write_html", "write_path_page", "check_writable", "FIELDS", "FAMILY_STYLES",
           "element_energy", "ExplorerWidget"]

#: Where each name lives. The modules are imported when a name is first used, so that a
#: writer that needs no plotly objects (write_path_page) does not import plotly's.
_HOME = {"ExplorerWidget": "explorer_widget", "FIELDS": "fields", "element_energy": "fields",
         "view_model": "figure", "view_path": "figure", "view_fold": "pattern_file",
         "check_writable": "html", "write_html": "html", "write_path_page": "path_page",
         "view_bending": "specimens", "view_snap_through": "specimens",
         "FAMILY_STYLES": "surface"}

__getattr__, __dir__ = lazy_names(__name__, _HOME)
