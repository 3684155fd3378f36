"""Views of the thesis's tests on Kresling specimens: the bending test in both stable states
on one page (two scenes, one slider) and the snap-through test beside its force-travel
curve.

The paths are those of :mod:`kresling.analyses.paths` (the C++ tests' set-up, every node at
every increment). Frame ``"0"`` is the built, stress-free specimen and frame ``"K"``
increment K, so ``view.html#frame=K`` opens at increment K. A run that stopped before the
end of its travel is marked in the title (in red: "PARTIAL: ... stopped at 30% of ...") and
in its curve's name.
"""

from __future__ import annotations

from html import escape

import numpy as np

from kresling.analyses.paths import bending_path, snap_through_path
from kresling.view.animation import select_rows
from kresling.view.figure import PARTIAL_COLOUR, PathCurve, PathPanel, animated_figure
from kresling.view.inputs import view_inputs

__all__ = ["view_bending", "view_snap_through", "STATE_COLOURS"]

#: Curve colour of each state (as the moment-angle figures draw them).
STATE_COLOURS = {"extended": "#1f77b4", "contracted": "#ff7f0e"}


def _with_start(values, width=None) -> np.ndarray:
    """``values`` (S, ...) with a zero row in front: the built state as row 0 (rows of
    ``width`` entries, if given: a path with no increment has no width of its own)."""
    values = np.asarray(values, dtype=float)
    if width is not None:
        values = values.reshape(len(values), width)
    return np.concatenate([np.zeros((1,) + values.shape[1:]), values])


def _stopped_at(path, result=None) -> float | None:
    """How far a run that stopped early went: the path's travel fraction if the path (what
    the page shows) stopped, else the analysis's result's if it did; None if neither."""
    for run in (path, result):
        if run is not None and run.partial:
            return run.travel_fraction
    return None


def _partial_line(text: str) -> str:
    """A title line that cannot be missed: "PARTIAL: ..." in bold red."""
    return f'<br><span style="color:{PARTIAL_COLOUR}"><b>PARTIAL: {escape(text)}</b></span>'


def view_bending(design, protocol="5mm", *, paths=None, results=None, field=None,
                 max_frames=100, title=None, **options):
    """The three-point bending test in both stable states, animated together.

    Left, the extended specimen; middle, the contracted one, both at the same increment;
    right, the moment against the deflection angle in both states (the thesis's figures
    3.5-3.7) with a marker on each curve. Frame ``"0"`` is the built specimen, frame
    ``"K"`` increment K.

    Parameters
    ----------
    design : kresling.Design
        An even n (the pins are opposite vertices).
    protocol : {"5mm", "0.001rad"}
        The thesis's Table 3 runs (5 mm in 350 increments) or its parametric study.
    paths : (BendingPath, BendingPath), optional
        The extended and contracted paths of :func:`kresling.analyses.paths.bending_path`,
        if already computed (then ``protocol`` and ``options`` are not used).
    results : BendingComparison, optional
        :func:`kresling.analyses.bending_stiffness`'s result of the same test: a state
        whose run stopped early there is marked partial too (as the numbers read from it
        are), at its path's travel fraction if the path stopped too, else at its own.
    field : {None, "bar_strain", "hinge_angle_change", "energy"}
        Colour the edges by a field, on one colour range for both states.
    max_frames : int, default 100
        At most this many frames (evenly spaced increments, the first and last included);
        the curves keep every increment.
    title : str, optional
        Default: the design and the K_B ratio. A partial run adds a red line below it
        (also below a given title): "PARTIAL: the contracted run stopped at 30% of its
        travel".
    **options
        Passed to :func:`kresling.analyses.paths.bending_path` (``deflection``, ``steps``,
        solver options).

    Returns
    -------
    plotly.graph_objects.Figure
        :func:`kresling.view.write_html` makes it an offline page. The curve of a partial
        run is named "... (PARTIAL)".

    Examples
    --------
    >>> from kresling import Design
    >>> fig = view_bending(Design(10, 0.9, 15), "0.001rad")
    >>> [f.name for f in fig.frames][:3], len(fig.frames)
    (['0', '1', '2'], 11)
    """
    if paths is None:
        paths = [bending_path(design, state, protocol, **options) for state in (1, 0)]
    panels, curves, stopped, stiffnesses = [], [], [], []
    for bent in paths:
        name = bent.state_name
        panels.append(PathPanel(view_inputs(bent.specimen),
                                _with_start(bent.path.displacement, bent.specimen.model.num_dofs),
                                title=name))
        angle, moment = _with_start(bent.angle), _with_start(bent.moment)
        stiffness = float(angle @ moment / (angle @ angle)) if angle.any() else float("nan")
        stiffnesses.append(stiffness)
        fraction = _stopped_at(bent, getattr(results, name, None))
        label = f"{name}: K_B = {stiffness:.4g} N·m/rad"
        if fraction is not None:
            stopped.append(f"the {name} run stopped at {fraction:.0%} of its travel")
            label += " (PARTIAL)"   # short: the legend shares one line; the title says more
        curves.append(PathCurve(angle, moment, label, STATE_COLOURS[name]))
    steps = max(len(p.displacement) for p in panels) - 1
    rows = select_rows(steps + 1, None, max_frames)
    d = paths[0].specimen.design
    # NaN for a run with no increment (its K_B is NaN), not a division by zero.
    ratio = stiffnesses[0] / stiffnesses[1] if stiffnesses[1] else float("nan")
    default = (f"Bending test, n = {d.n}, λ = {d.lam:g}, Lc = {d.Lc:g} mm: both stable states, "
               f"K_B ratio {ratio:.2f} ({steps} increments)")
    shown = (title or default) + (_partial_line("; ".join(stopped)) if stopped else "")
    return animated_figure(panels, rows, [str(r) for r in rows], curves=curves,
                           x_label="deflection angle δ [rad]", y_label="moment M [N·m]",
                           field=field, title=shown, total=steps)


def view_snap_through(design, *, steps=100, path=None, result=None, field=None,
                      max_frames=101, title=None, **options):
    """The snap-through test: one cell driven from its extended to its contracted height,
    beside its force-travel curve (the thesis's figure 3.16).

    Frame ``"0"`` is the built cell, frame ``"K"`` increment K.

    Parameters
    ----------
    design : kresling.Design
    steps : int, default 100
        Increments from ``Le`` to ``Lc``.
    path : SnapThroughPath, optional
        From :func:`kresling.analyses.paths.snap_through_path`, if already computed.
    result : SnapThroughResult, optional
        :func:`kresling.analyses.snap_through`'s result of the same test, for the title
        (the snap force and the bistability); computed if not given. If it or the path
        stopped before ``Lc``, the title says so in a red line: "PARTIAL: stopped at 21% of
        the travel" (the path's travel fraction if the path stopped, else the result's).
    field : {None, "bar_strain", "hinge_angle_change", "energy"}
    max_frames : int, default 101
    title : str, optional
    **options
        Solver options of :func:`kresling.analyses.paths.snap_through_path`.

    Returns
    -------
    plotly.graph_objects.Figure

    Examples
    --------
    >>> from kresling import Design
    >>> fig = view_snap_through(Design(8, 0.8, 30), steps=20)
    >>> len(fig.frames), fig.layout.xaxis.title.text
    (21, 'travel d [mm]')
    """
    from kresling.analyses.snap_through import snap_through

    if path is None:
        path = snap_through_path(design, steps=steps, **options)
    if result is None:
        # (a path that converged no increment: the result of the steps asked for)
        result = snap_through(path.specimen.design, steps=len(path.travel) or steps, **options)
    num_steps = len(path.travel)
    panel = PathPanel(view_inputs(path.specimen),
                      _with_start(path.path.displacement, path.specimen.model.num_dofs))
    fraction = _stopped_at(path, result)
    stopped = "" if fraction is None else f"stopped at {fraction:.0%} of the travel"
    curve = PathCurve(_with_start(path.travel), _with_start(path.force), "force", "#1f77b4")
    rows = select_rows(num_steps + 1, None, max_frames)
    d = path.specimen.design
    peak = (f"snap force {result.snap_force:.2f} N at {result.snap_displacement:.2f} mm"
            if result.has_peak else "no snap-through force")
    default = (f"Snap-through, n = {d.n}, λ = {d.lam:g}, Lc = {d.Lc:g} mm: {peak}"
               f"<br><sup>{result.bistability}</sup>")
    shown = (title or default) + (_partial_line(stopped) if stopped else "")
    return animated_figure([panel], rows, [str(r) for r in rows], curves=[curve],
                           x_label="travel d [mm]", y_label="force F [N]", field=field,
                           title=shown, total=num_steps)
