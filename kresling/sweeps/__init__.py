"""Parametric design studies (thesis sections 3.4-3.5): many designs through the bending,
facet-angle and snap-through analyses, in parallel and resumable, and what to do with them.

- :func:`design_grid` and :class:`DesignSet`: the designs (the thesis's n x Lc x lambda grid).
- :data:`METRICS`: what can be computed per design (K_B ratio at 0.001 rad and 5 mm, the
  facet-angle ratio, ...).
- :func:`sweep`: the computation, on threads, processes or any ``concurrent.futures``
  executor (Dask), written to disk as it goes and resumed after an interruption.
- :class:`SweepTable`: the results, one row per design.
- :func:`optimize_design`: beyond the grid, the best design of an n by SLSQP under bounds
  and constraints on any metric; :func:`sensitivity`: how fast a metric falls away from it.
- Submodules: ``plots`` (heat maps, figure 3.13), ``conclusions`` (the thesis's claims as
  measurements on a table). The report's section on them is
  :mod:`kresling.report.sections.sweeps`.

Examples
--------
>>> from kresling.sweeps import design_grid, sweep
>>> table = sweep(design_grid((10,), 3), ["kb_ratio", "psi_ratio"], progress=False)
>>> best = table.best("kb_ratio")
>>> best["Lc"], best["lam"], round(best["kb_ratio"], 2)
(15.0, 0.9, 21.69)
"""

from kresling.sweeps.designs import THESIS_LAM, THESIS_N, DesignSet, as_design_set, design_grid
from kresling.sweeps.metrics import METRICS, Analysis, Evaluation, Metric, resolve_metrics
from kresling.sweeps.sweep import DEFAULT_METRICS, sweep
from kresling.sweeps.table import SweepTable
from kresling.sweeps.optimize import DesignOptimum, optimize_design  # noqa: E402 (uses sweep)
from kresling.sweeps.sensitivity import Sensitivity, sensitivity  # noqa: E402

__all__ = ["sweep", "design_grid", "DesignSet", "as_design_set", "SweepTable", "METRICS",
           "Metric", "Analysis", "Evaluation", "resolve_metrics", "DEFAULT_METRICS",
           "THESIS_N", "THESIS_LAM", "optimize_design", "DesignOptimum", "sensitivity",
           "Sensitivity"]
