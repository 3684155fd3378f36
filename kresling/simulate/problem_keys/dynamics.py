"""The problem file's time integration: the ``[dynamics]`` table and the ``time`` of each
``[[load]]`` (``[analysis] method = "dynamic"``), read as :mod:`kresling.simulate.problem`
reads every table (see docs/simulate.md and docs/dynamics.md).

``[dynamics]``: ``scheme`` ("newmark", "hht" or "explicit"), ``time_step`` and ``duration``
[s], ``damping = { alpha = ..., beta = ... }`` (Rayleigh, [1/s] and [s]), ``damping_tangent``
("initial": beta times the tangent at the start; "current": the tangent of each step's
start, implicit schemes), ``gravity`` [mm/s^2], ``hht_alpha`` (with "hht", in [-1/3, 0],
default -0.05) and ``record_every`` (with "explicit": keep every k-th step). A load's (or a
driven crease's) ``time``: "step" (on from t = 0, the default), "ramp" (from 0 to 1 over
``ramp_time`` [s], then held), a table ``[[t, factor], ...]`` (piecewise linear, held beyond
its ends), ``{ harmonic = [amplitude, frequency_hz] }`` (``amplitude sin(2 pi f t)``) or
``{ chirp = [amplitude, f0_hz, f1_hz, sweep_s] }`` (a sine whose frequency goes linearly from
f0 to f1 over ``sweep_s``, then stays at f1).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling.simulate.problem_keys import ProblemKey
from kresling.simulate.problem_table import number, positive, raw, vector3

__all__ = ["KEY", "Dynamics", "LoadTime", "read_load_time", "SCHEMES", "TIME_KINDS",
           "OSCILLATING", "DAMPING_TANGENTS"]

#: The schemes of ``[dynamics] scheme``.
SCHEMES = ("newmark", "hht", "explicit")
#: The words ``[[load]] time`` may be (besides a table, a harmonic and a chirp).
TIME_KINDS = ("step", "ramp")
#: The time functions that oscillate about zero (their amplitude a factor of a load, a
#: fold angle in degrees of a driven crease).
OSCILLATING = ("harmonic", "chirp")
#: ``[dynamics] damping_tangent``: the tangent in beta's share of the damping.
DAMPING_TANGENTS = ("initial", "current")
#: HHT-alpha's parameter when ``scheme = "hht"`` names none: mild damping of the modes the
#: step does not resolve, a resolved mode's amplitude loss per step falling as (w dt)^4.
DEFAULT_HHT_ALPHA = -0.05


@dataclass(frozen=True)
class Dynamics:
    """The ``[dynamics]`` table: scheme, step and duration [s], Rayleigh damping (alpha
    [1/s], beta [s]), gravity [mm/s^2] or None, HHT's alpha, the explicit scheme's
    record_every and the damping's tangent ("initial" or "current")."""

    scheme: str
    time_step: float
    duration: float
    alpha: float = 0.0
    beta: float = 0.0
    gravity: tuple | None = None
    hht_alpha: float = 0.0
    record_every: int = 1
    damping_tangent: str = "initial"


@dataclass(frozen=True)
class LoadTime:
    """A load's factor in time: ``kind`` "step", "ramp" (over ``ramp_time`` [s]), "table"
    (``table``: (t, factor) pairs), "harmonic" (``amplitude``, ``frequency_hz``) or "chirp"
    (``amplitude``, from ``frequency_hz`` to ``end_frequency_hz`` over ``sweep_time`` [s])."""

    kind: str = "step"
    ramp_time: float | None = None
    table: tuple = ()
    amplitude: float = 0.0
    frequency_hz: float = 0.0
    end_frequency_hz: float = 0.0
    sweep_time: float = 0.0

    def factor_at(self, time: float) -> float:
        """The factor at ``time`` [s]."""
        if self.kind == "step":
            return 1.0
        if self.kind == "harmonic":
            return float(self.amplitude * np.sin(2 * np.pi * self.frequency_hz * time))
        if self.kind == "chirp":   # as the integrator evaluates it
            from kresling.solvers.dynamics import time_factor
            return float(time_factor(self.for_solver(), time)[0])
        times, factors = zip(*self.for_solver())
        return float(np.interp(time, times, factors))

    def for_solver(self):
        """The time function as :func:`kresling.solvers.solve_dynamics` takes a load's."""
        if self.kind == "step":
            return None
        if self.kind == "ramp":
            return [[0.0, 0.0], [self.ramp_time, 1.0]]
        if self.kind == "table":
            return [list(row) for row in self.table]
        if self.kind == "chirp":
            return {"chirp": (self.amplitude, self.frequency_hz, self.end_frequency_hz,
                              self.sweep_time)}
        return {"harmonic": (self.amplitude, self.frequency_hz)}

    def factor_range(self) -> tuple:
        """The least and the greatest factor over all time."""
        if self.kind == "step":
            return 1.0, 1.0
        if self.kind == "ramp":
            return 0.0, 1.0
        if self.kind == "table":
            factors = [row[1] for row in self.table]
            return min(factors), max(factors)
        return -abs(self.amplitude), abs(self.amplitude)


def read_dynamics(t, context) -> dict:
    """The ``[dynamics]`` table ``t`` (a reader of the problem's tables)."""
    scheme = t.get("scheme", _choice, "newmark", choices=SCHEMES)
    time_step = t.get("time_step", positive, required=True, allowed="the time step [s] (> 0)")
    duration = t.get("duration", positive, required=True, allowed="the time to integrate [s]")
    alpha = beta = 0.0
    if t.has("damping"):
        damping = t.get("damping", raw)
        if not isinstance(damping, dict) or not damping or set(damping) - {"alpha", "beta"}:
            t.fail("damping", f"= {damping!r} is invalid: must be {{ alpha = ..., beta = ... }} "
                              "(Rayleigh: C = alpha M + beta K, alpha [1/s], beta [s])")
        alpha = _non_negative(t, "damping", "alpha", damping.get("alpha", 0.0))
        beta = _non_negative(t, "damping", "beta", damping.get("beta", 0.0))
    damping_tangent = t.get("damping_tangent", _choice, "initial", choices=DAMPING_TANGENTS)
    if damping_tangent == "current" and scheme == "explicit":
        t.fail("damping_tangent", "= 'current' applies only with scheme = 'newmark' or 'hht' "
                                  "(the explicit scheme's damping keeps the start's tangent)")
    if damping_tangent == "current" and beta == 0:
        t.fail("damping_tangent", "= 'current' needs damping = { beta = ... } > 0: it is the "
                                  "tangent in beta's share of the damping")
    gravity = t.get("gravity", vector3, None)
    if scheme != "hht" and t.has("hht_alpha"):
        t.fail("hht_alpha", f"applies only with scheme = 'hht' (given: {scheme!r})")
    hht_alpha = t.get("hht_alpha", number, DEFAULT_HHT_ALPHA) if scheme == "hht" else 0.0
    if not -1 / 3 <= hht_alpha <= 0:
        t.fail("hht_alpha", f"= {hht_alpha!r} is invalid: must be in [-1/3, 0]")
    if scheme != "explicit" and t.has("record_every"):
        t.fail("record_every", f"applies only with scheme = 'explicit' (given: {scheme!r})")
    record_every = t.get("record_every", _whole, 1)
    t.finish()
    return {"dynamics": Dynamics(scheme, time_step, duration, alpha, beta, gravity, hht_alpha,
                                 record_every, damping_tangent)}


def read_load_time(t) -> LoadTime | None:
    """A ``[[load]]`` (or ``[[actuation]]``) entry's ``time`` and ``ramp_time`` (None when it
    names neither)."""
    value = t.get("time", raw, None)
    ramp_time = t.get("ramp_time", positive, None)
    if (value == "ramp") != (ramp_time is not None):
        if value == "ramp":
            t.fail("ramp_time", "is missing: time = \"ramp\" needs the ramp's duration [s]")
        t.fail("ramp_time", f"applies only with time = \"ramp\" (given: {value!r})")
    if value is None:
        return None
    if value == "ramp":
        return LoadTime("ramp", ramp_time=ramp_time)
    if value == "step":
        return LoadTime("step")
    if isinstance(value, dict):
        return _oscillating(t, value)
    if isinstance(value, list):
        return LoadTime("table", table=_table(t, value))
    t.fail("time", f"= {value!r} is invalid: must be \"step\", \"ramp\" (with ramp_time), "
                   "[[t, factor], ...], { harmonic = [amplitude, frequency_hz] } or "
                   "{ chirp = [amplitude, f0_hz, f1_hz, sweep_s] }")


#: An oscillating time function's numbers, as a file writes them.
_OSCILLATING_FORMS = {"harmonic": "[amplitude, frequency_hz]",
                      "chirp": "[amplitude, f0_hz, f1_hz, sweep_s]"}


def _oscillating(t, value):
    kind = next(iter(value)) if len(value) == 1 else None
    if kind not in _OSCILLATING_FORMS:
        t.fail("time", f"= {value!r} is invalid: must be {{ harmonic = [amplitude, "
                       "frequency_hz] } or { chirp = [amplitude, f0_hz, f1_hz, sweep_s] }")
    numbers = value[kind]
    size = 2 if kind == "harmonic" else 4
    if not isinstance(numbers, list) or len(numbers) != size:
        t.fail("time", f"= {value!r} is invalid: must be {{ {kind} = "
                       f"{_OSCILLATING_FORMS[kind]} }}")
    amplitude, *rest = (number(t, "time", v) for v in numbers)
    if min(rest) <= 0:
        what = ("frequency must be > 0 [Hz]" if kind == "harmonic" else
                "frequencies f0_hz, f1_hz must be > 0 [Hz] and its sweep_s > 0 [s]")
        t.fail("time", f"= {value!r} is invalid: the {kind}'s {what}")
    if kind == "harmonic":
        return LoadTime("harmonic", amplitude=amplitude, frequency_hz=rest[0])
    return LoadTime("chirp", amplitude=amplitude, frequency_hz=rest[0],
                    end_frequency_hz=rest[1], sweep_time=rest[2])


def _table(t, rows):
    if not rows:
        t.fail("time", "= [] is invalid: a table needs at least one row [t, factor]")
    table = []
    for row in rows:
        if not isinstance(row, list) or len(row) != 2:
            t.fail("time", f"has a row {row!r}: each row is [t, factor] (t in s)")
        table.append(tuple(number(t, "time", v) for v in row))
    times = [row[0] for row in table]
    if any(b <= a for a, b in zip(times, times[1:])):
        t.fail("time", f"has times {times}: they must increase")
    return tuple(table)


def _non_negative(t, key, name, value):
    value = number(t, key, value)
    if value < 0:
        t.fail(key, f"{name} = {value!r} is invalid: must be >= 0")
    return value


def _choice(t, key, value, allowed=None):
    if not isinstance(value, str) or value not in allowed:
        t.fail(key, f"= {value!r} is invalid: must be one of {list(allowed)}")
    return value


def _whole(t, key, value, allowed=None):
    if isinstance(value, bool) or not isinstance(value, int) or value < 1:
        t.fail(key, f"= {value!r} is invalid: must be an integer >= 1")
    return value


def check_dynamics(problem):
    """``[dynamics]`` and the loads' ``time`` belong to a motion in time."""
    if problem.method.in_time:
        return
    if problem.dynamics is not None:
        raise ValueError(f"{problem.source}: [dynamics] applies only with [analysis] method = "
                         f"'dynamic' (given: {problem.analysis.method!r})")
    timed = [i for i, load in enumerate(problem.loads) if load.time is not None]
    if timed:
        raise ValueError(f"{problem.source}: load[{timed[0]}] key 'time' applies only with "
                         f"[analysis] method = 'dynamic' (given: {problem.analysis.method!r})")


KEY = ProblemKey("dynamics", rank=100, read=read_dynamics, absent={"dynamics": None},
                 check=check_dynamics)
