"""The snap-through in time: one cell jumping under a step load just above its snap force.

The static test (:mod:`kresling.analyses.snap_through`) drives the top polygon down and
reads the force; here the cell (the same one: built stress-free extended, bottom polygon
held, the thesis's laminate as its mass, :mod:`kresling.analyses.laminate`) is pushed by a
force and moves by its inertia (:func:`kresling.solvers.solve_dynamics`):

- at ``t = 0`` a load ``(1 + margin)`` times the static snap force is applied to the top
  polygon's ``n`` perimeter nodes, shared equally but for a small eccentricity ``e``: node
  ``j`` at angle ``theta_j`` carries ``F / n (1 + 2 e cos(theta_j) / R)``, the push of a
  finger ``e`` off the axis. The model's second stable state is tilted; a push exactly on
  the axis keeps the cell level, on the level contracted equilibrium (a saddle) until
  round-off tips it over, an unpredictable time later;
- the load is held for ``hold`` seconds (the cell snaps and comes to rest under it) and
  removed within one time step; the cell springs back to its second stable state;
- damping is Rayleigh's mass-proportional ``C = alpha M`` with ``alpha = 2 zeta omega_1``,
  ``omega_1`` the cell's lowest natural frequency extended: ``zeta`` is that mode's damping
  ratio, and every underdamped mode's amplitude decays as ``exp(-alpha t / 2)``;
- HHT-alpha (``-0.1``) removes the modes the step does not resolve (the polygon's
  in-plane modes, above 2 kHz): with the average acceleration scheme alone their energy
  feeds back into the slow motion and the cell does not come to rest.

The cell's travel is the mean downward motion of the top perimeter, as in the static test.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kresling._validation import as_finite_real, as_positive_real
from kresling.analyses.laminate import specimen_masses
from kresling.analyses.snap_through import SnapThroughResult, snap_through
from kresling.geometry import Design, as_design

__all__ = ["DynamicSnapResult", "snap_in_time", "snap_test_cell", "SETTLING_BAND", "AT_REST"]

#: The settling time is when the travel last leaves a band of this fraction of the stable
#: state's travel about where the cell comes to rest (the usual 2 % criterion).
SETTLING_BAND = 0.02

#: The cell is at rest when its kinetic energy is below this fraction of the static energy
#: barrier (the default run ends 1e-21 below it).
AT_REST = 1e-9


@dataclass(frozen=True)
class DynamicSnapResult:
    """A cell snapping in time (see the module's description for the protocol).

    Attributes
    ----------
    design : Design
    static : SnapThroughResult
        The static test of the same cell: its snap force and second stable state.
    load : float
        The step load [N]: ``(1 + margin)`` times the snap force.
    mass_damping : float
        Rayleigh's ``alpha`` [1/s].
    time, travel, kinetic : ndarray, shape (S,)
        Time [s], the top perimeter's mean downward travel [mm] and the kinetic energy
        [N*mm], starting at rest (0, 0, 0).
    hold : float
        When the load was removed [s].
    jump_time : float
        From the step to the cell first reaching its stable state's travel [s] (NaN if it
        never does).
    peak_travel : float
        The largest travel [mm] (under the held load).
    loaded_travel : float
        The travel when the load is removed [mm].
    rebound : float
        After the release, how far the cell swings back above its stable state's height
        [mm] (0 if it never does).
    settled_travel, settled_height, settled_tilt : float
        Where the cell rests at the end: travel [mm], height ``Le - travel`` [mm], the top
        polygon's tilt [rad].
    settling_time : float
        The last time the travel was outside :data:`SETTLING_BAND` of the stable state's
        travel about ``settled_travel`` [s].
    final_kinetic : float
        Kinetic energy at the end [N*mm]: near zero when the cell has come to rest.
    completed : bool
        The integration reached ``duration``.
    message : str
    """

    design: Design
    static: SnapThroughResult
    load: float
    mass_damping: float
    time: np.ndarray
    travel: np.ndarray
    kinetic: np.ndarray
    hold: float
    jump_time: float
    peak_travel: float
    loaded_travel: float
    rebound: float
    settled_travel: float
    settled_height: float
    settled_tilt: float
    settling_time: float
    final_kinetic: float
    completed: bool
    message: str

    @property
    def height(self) -> np.ndarray:
        """Cell height ``Le - travel`` at every step [mm], shape (S,)."""
        return self.static.extended_height - self.travel

    @property
    def at_rest(self) -> bool:
        """The kinetic energy at the end is below 1e-9 of the static energy barrier."""
        return self.final_kinetic < AT_REST * self.static.energy_barrier

    @property
    def overshoot(self) -> float:
        """How far the cell swings past its stable state's travel [mm]."""
        return self.peak_travel - self.static.stable_displacement

    @property
    def height_error(self) -> float:
        """Settled height minus the static test's stable height [mm]."""
        return self.settled_height - self.static.stable_height

    def summary(self) -> dict:
        """The scalar results as a ``dict``."""
        keys = ("load", "mass_damping", "hold", "jump_time", "peak_travel", "overshoot",
                "loaded_travel", "rebound", "settled_travel", "settled_height", "settled_tilt",
                "settling_time", "final_kinetic", "at_rest", "height_error", "completed",
                "message")
        out = {key: getattr(self, key) for key in keys}
        out.update(snap_force=self.static.snap_force,
                   stable_height=self.static.stable_height,
                   stable_travel=self.static.stable_displacement,
                   unstable_travel=self.static.unstable_displacement)
        return out


def snap_test_cell(design: Design, parameters=None, state="extended"):
    """The static test's cell: one cell built stress-free in ``state`` (extended, as the
    test's), its bottom polygon's ``n + 1`` nodes held; returns ``(specimen, masses (N,)
    [t])`` with the laminate's masses."""
    from kresling.model import kresling_specimen

    n = design.n
    fixed = np.zeros((2 * (n + 1), 3), dtype=bool)
    fixed[:n + 1] = True
    cell = kresling_specimen(design, [state], parameters=parameters, fixed=fixed)
    return cell, specimen_masses(cell)


def _tilt(cell, u) -> float:
    """The top perimeter's tilt from horizontal [rad], as the static test measures it: the
    angle of its Newell normal (the polygon's vector area) from the z axis."""
    x = cell.model.nodes + u.reshape(-1, 3)
    ring = x[[cell.node(1, j) for j in range(cell.design.n)]]
    normal = np.cross(ring, np.roll(ring, -1, axis=0)).sum(axis=0)
    return math.acos(min(1.0, abs(float(normal[2])) / float(np.linalg.norm(normal))))


def snap_in_time(design: Design, *, margin=0.05, damping=0.05, eccentricity=0.1, hold=0.3,
                 duration=2.0, time_step=2e-4, parameters=None,
                 steps=None) -> DynamicSnapResult:
    """Push one cell with a step load just above its snap force and follow it in time.

    Parameters
    ----------
    design : Design
        A bistable cell (the static test must find a second stable state).
    margin : float, default 0.05
        The load is ``(1 + margin)`` times the static snap force (> 0).
    damping : float, default 0.05
        Damping ratio ``zeta`` of the cell's lowest extended mode (> 0; see the module).
    eccentricity : float, default 0.1
        Offset of the push from the axis [mm] (>= 0).
    hold : float, default 0.3
        How long the load is held [s].
    duration : float, default 2.0
        The time integrated over [s] (> hold).
    time_step : float, default 2e-4
        [s]
    parameters : SpecimenParameters, optional
    steps : int, optional
        Increments of the static test (its default when None).

    Returns
    -------
    DynamicSnapResult

    Raises
    ------
    ValueError
        Naming the parameter, for values out of range or a cell the static test does not
        find bistable.
    """
    from kresling.analyses.modes import vibration_modes
    from kresling.solvers import solve_dynamics

    design = as_design(design)
    margin = as_positive_real("margin", margin)
    damping = as_positive_real("damping", damping)
    eccentricity = as_finite_real("eccentricity", eccentricity)
    if eccentricity < 0:
        raise ValueError(f"eccentricity = {eccentricity!r} is invalid: must be >= 0 [mm]")
    hold = as_positive_real("hold", hold)
    duration = as_positive_real("duration", duration)
    time_step = as_positive_real("time_step", time_step)
    if not duration > hold + time_step:
        raise ValueError(f"duration = {duration!r} is invalid: must exceed hold + time_step "
                         f"= {hold + time_step:.6g} s (the cell needs time after the release)")
    static = snap_through(design, parameters=parameters,
                          **({} if steps is None else {"steps": steps}))
    if not static.bistable:
        raise ValueError(f"design = {design!r} is invalid here: the static test finds no "
                         f"second stable state ({static.bistability})")
    cell, masses = snap_test_cell(design, parameters)
    model, n = cell.model, design.n
    top = np.array([cell.node(1, j) for j in range(n)])
    theta = np.arctan2(model.nodes[top, 1], model.nodes[top, 0])
    load = (1.0 + margin) * static.snap_force
    forces = np.zeros((model.num_nodes, 3))
    forces[top, 2] = -load / n * (1.0 + 2.0 * eccentricity * np.cos(theta) / design.R)
    if not np.isfinite(forces).all():
        raise ValueError(f"eccentricity = {eccentricity!r} is invalid: the top's loads it "
                         f"shifts are not finite (it must be of the order of R = {design.R:g} mm "
                         "or less)")
    omega = 2 * math.pi * float(vibration_modes(model, masses, 1).frequencies_hz[0])
    alpha = 2.0 * damping * omega
    history = solve_dynamics(model, masses, time_step, duration, forces=forces,
                             load_table=[[0.0, 1.0], [hold, 1.0], [hold + time_step, 0.0]],
                             hht_alpha=-0.1, mass_damping=alpha, tolerance=1e-10)
    u = np.vstack([np.zeros(model.num_dofs), history.path.displacement])
    travel = -u[:, 3 * top + 2].mean(axis=1)
    return _result(design, static, cell, load, alpha, hold, u,
                   np.concatenate([[0.0], history.time]),
                   np.concatenate([[0.0], history.kinetic]), travel, history)


def _result(design, static, cell, load, alpha, hold, u, time, kinetic, travel, history):
    stable = static.stable_displacement
    reached = np.flatnonzero(travel >= stable)
    settled = float(travel[-1])
    outside = np.flatnonzero(np.abs(travel - settled) > SETTLING_BAND * stable)
    loaded = int(np.searchsorted(time, hold, side="right")) - 1
    return DynamicSnapResult(
        design=design, static=static, load=float(load), mass_damping=float(alpha),
        time=time, travel=travel, kinetic=kinetic, hold=float(hold),
        jump_time=float(time[reached[0]]) if reached.size else math.nan,
        peak_travel=float(travel.max()), loaded_travel=float(travel[loaded]),
        rebound=max(float(stable - travel[loaded:].min()), 0.0),
        settled_travel=settled, settled_height=float(static.extended_height - settled),
        settled_tilt=_tilt(cell, u[-1]),
        settling_time=float(time[min(outside[-1] + 1, len(time) - 1)]) if outside.size else 0.0,
        final_kinetic=float(kinetic[-1]), completed=bool(history.completed),
        message=history.path.message)


def plot_snap_in_time(result: DynamicSnapResult, ax=None):
    """Height against time, with the static test's stable and unstable heights and the
    release marked; returns the axes."""
    import matplotlib.pyplot as plt

    if ax is None:
        ax = plt.subplots(figsize=(7, 4))[1]
    s = result.static
    ax.plot(result.time, result.height, color="C0", label="cell height")
    ax.axhline(s.stable_height, color="C2", ls="--", lw=1,
               label=f"static stable state ({s.stable_height:.3f} mm)")
    ax.axhline(s.extended_height - s.unstable_displacement, color="C3", ls=":", lw=1,
               label="static unstable state")
    ax.axvline(result.hold, color="0.5", lw=1, label=f"load removed ({result.hold:g} s)")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("height [mm]")
    ax.set_title(f"step load {result.load:.3g} N ({result.load / s.snap_force - 1:.0%} above "
                 f"the snap force)")
    ax.legend(fontsize=8)
    return ax
