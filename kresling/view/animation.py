"""Animation over a path's increments: which increments become frames, the slider and the
play/pause buttons, and the load-displacement curve whose marker follows the frame.

Increments are numbered from 1: frame ``"K"`` shows row ``K - 1`` of a path's arrays
(``PathResult.displacement[K - 1]``), and its slider step reads "increment K / S".
"""

from __future__ import annotations

import numpy as np

from kresling._validation import as_integer

__all__ = ["select_rows", "default_curve", "check_curve", "slider", "play_buttons",
           "frame_name", "partial_line", "FRAME_DURATION_MS"]

#: Colour of a title's line that says a run stopped before the end of its travel.
PARTIAL_COLOUR = "#c00000"

#: Characters on one line of a title: plotly does not wrap titles, and a longer line is cut
#: off at the page's edge (about 110 characters fit a 1,200 px wide page at 14 px).
TITLE_LINE = 100

#: Time each frame is shown when playing [ms].
FRAME_DURATION_MS = 60

_AXES = "xyz"


def partial_line(increments: int, reason: str) -> str:
    """The red title lines of a path that stopped early: "PARTIAL: the solver stopped after
    ``increments`` increments" and ``reason`` (HTML-escaped), broken into lines of at most
    :data:`TITLE_LINE` characters (a word longer than that is broken too), each starting
    with ``<br>``, so that a long message is shown whole."""
    import html   # (a path that stopped early only)
    import textwrap

    text = (f"PARTIAL: the solver stopped after {increments} increments "
            f"({reason.strip() or 'no reason given'})")
    lines = textwrap.wrap(text, TITLE_LINE, break_long_words=True, break_on_hyphens=False)
    head = len(f"PARTIAL: the solver stopped after {increments} increments")
    shown = []
    for k, line in enumerate(lines):
        if k == 0 and len(line) >= head:   # the statement in bold, the reason plain
            line = f"<b>{html.escape(line[:head])}</b>{html.escape(line[head:])}"
        else:
            line = html.escape(line)
        shown.append(f'<br><span style="color:{PARTIAL_COLOUR}">{line}</span>')
    return "".join(shown)


def frame_name(row: int) -> str:
    """The frame (and increment) name of a path's row: ``str(row + 1)``."""
    return str(int(row) + 1)


def select_rows(num_steps: int, frame_stride=None, max_frames: int = 200) -> np.ndarray:
    """The path rows that become frames.

    Parameters
    ----------
    num_steps : int
        S, the path's increments.
    frame_stride : int, optional
        Every ``frame_stride``-th increment, the last always included. Default: evenly
        spaced increments, the first and last included.
    max_frames : int, default 200
        At most this many frames; a stride that gives more is thinned evenly.

    Returns
    -------
    ndarray of int
        Ascending rows (0-based).
    """
    num_steps = as_integer("num_steps", num_steps, minimum=1)
    max_frames = as_integer("max_frames", max_frames, minimum=1)
    if frame_stride is None:
        rows = np.arange(num_steps)
    else:
        stride = as_integer("frame_stride", frame_stride, minimum=1)
        rows = np.unique(np.append(np.arange(0, num_steps, stride), num_steps - 1))
    if len(rows) > max_frames:
        picks = np.round(np.linspace(0, len(rows) - 1, max_frames)).astype(int)
        picks = picks[np.r_[True, picks[1:] != picks[:-1]]]   # ascending: repeats adjacent
        rows = rows[picks]
    return rows


def default_curve(model, path) -> tuple:
    """Load factor against the displacement of the DOF that moves most over the path.

    Returns
    -------
    (ndarray, ndarray, str, str)
        x (S,) [mm], y (S,), x label, y label.
    """
    u = np.asarray(path.displacement, dtype=float)
    dof = int(np.argmax(np.abs(u).max(axis=0))) if u.size else 0
    node, axis = divmod(dof, 3)
    x_label = f"u{_AXES[axis]} of node {node} [mm]"
    return u[:, dof], np.asarray(path.load_factor, dtype=float), x_label, "load factor [-]"


def check_curve(curve, num_steps: int) -> tuple:
    """``curve`` as (x, y, x_label, y_label) with x and y of length S; else a ValueError."""
    try:
        x, y, x_label, y_label = curve
    except (TypeError, ValueError):
        raise ValueError("curve is invalid: must be (x, y, x_label, y_label)") from None
    x, y = np.asarray(x, dtype=float).ravel(), np.asarray(y, dtype=float).ravel()
    if len(x) != num_steps or len(y) != num_steps:
        raise ValueError(f"curve has x of length {len(x)} and y of length {len(y)}: both "
                         f"must have one value per increment ({num_steps})")
    return x, y, str(x_label), str(y_label)


def _animate_args(names, duration):
    return [names, {"mode": "immediate", "frame": {"duration": duration, "redraw": True},
                    "transition": {"duration": 0}, "fromcurrent": True}]


def slider(names, num_steps: int, active: int = 0, prefix: str = "increment ",
           method: str = "animate") -> dict:
    """A slider with one step per frame, labelled by increment.

    Parameters
    ----------
    names : sequence of str
        Frame names (increments).
    num_steps : int
        S, shown as "increment K / S".
    active : int
        Index of the step shown first.
    prefix : str, default "increment "
        What the frames are (a FOLD file's: "frame ").
    method : {"animate", "skip"}
        "animate": each step shows its figure frame; "skip": the step only moves the
        slider, and the page's own script draws the frame.
    """
    return dict(
        active=int(active), x=0.04, len=0.92, y=0.0, yanchor="top", pad=dict(t=36, b=6),
        currentvalue=dict(prefix=prefix, suffix=f" / {num_steps}", visible=True,
                          xanchor="left", font=dict(size=14)),
        transition=dict(duration=0),
        steps=[dict(label=name, method=method, args=_animate_args([name], 0))
               for name in names])


def play_buttons(method: str = "animate") -> dict:
    """Play and pause buttons (play runs from the current frame); with ``method="skip"``
    the page's own script plays (the buttons' first argument says "play" or "pause")."""
    if method == "skip":
        return dict(type="buttons", direction="left", showactive=False, x=0.04, y=0.0,
                    xanchor="right", yanchor="top", pad=dict(t=44, r=8),
                    buttons=[dict(label="▶ play", method="skip", args=["play"]),
                             dict(label="❚❚ pause", method="skip", args=["pause"])])
    return dict(
        type="buttons", direction="left", showactive=False, x=0.04, y=0.0, xanchor="right",
        yanchor="top", pad=dict(t=44, r=8),
        buttons=[dict(label="▶ play", method="animate",
                      args=[None, _animate_args(None, FRAME_DURATION_MS)[1]]),
                 dict(label="❚❚ pause", method="animate",
                      args=[[None], {"mode": "immediate", "frame": {"duration": 0,
                                                                     "redraw": False},
                                     "transition": {"duration": 0}}])])
