"""Switching one Kresling cell between its stable states by its creases (crease actuation).

The cell is the snap-through test's (:func:`~kresling.analyses.snap_through`): one cell built
stress-free in its extended state, its bottom polygon held. For each group of creases
(``valley``, ``mountain``, ``polygon`` edges, or every ``fold`` together) the rest angles
are driven away from their stress-free values by one change ``Delta``, each crease in the
direction that moves the cell towards the other state: the sign of (its angle in the
contracted stable state minus its stress-free angle), per family, read off the contracted
state the snap-through test finds. Each increment is an equilibrium solve of the fold
solver (:func:`kresling.solvers.solve_fold`) from the previous one; the state is followed
while it stays converged, stable and continuous, and bisection locates the change at which
it ceases to exist (the snap), to ``resolution``. Held just past it, the cell snaps; then
the rest angles are set back (released) and energy descent finds where the cell rests.
The opposite switch (contracted to extended), which a tendon pulling the cell together
cannot do, drives the other way from the contracted stable state.

The moment at the snap is ``m = -sum_i s_i M_i`` over the driven creases (``M_i = k_p L0
(theta_i - theta0_i)``, the crease's moment about its rest angle in the law's linear range;
``s_i`` its direction): the summed moment the actuators must hold [N mm]. The work the
actuation puts in is the integral over ``Delta`` of the rest angles' generalised force
``dE/dtheta0`` (``m`` while every crease stays inside the law's linear range) along the
path; with no load it equals the strain energy the actuation added (the energy's derivative
in ``Delta`` along an equilibrium path is that force), which checks the moments against the
energies. It is not the snap-through test's energy barrier and need not be: it includes the
energy of the driven creases strained against their new rest angles, and the held actuation
goes on doing work while the cell snaps. Measured, it is of the order of the barrier
(docs/folding.md, 'Switching a Kresling cell by its creases').
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

import numpy as np

from kresling import _core
from kresling._validation import as_finite_real, as_integer
from kresling.analyses.snap_through import DEFAULT_STEPS, SnapThroughResult
from kresling.geometry import Design, as_design
from kresling.model.kresling_specimen import SpecimenParameters

__all__ = ["GROUPS", "CreaseSwitch", "SwitchingResult", "switching"]

#: The crease groups, in the order the results list them.
GROUPS = ("valley", "mountain", "polygon", "fold")


@dataclass(frozen=True)
class CreaseSwitch:
    """One crease group driven one way.

    Attributes
    ----------
    group : str
        ``valley``, ``mountain``, ``polygon`` or ``fold`` (all three).
    forward : bool
        Extended to contracted (False: contracted to extended).
    creases : int
        Driven creases (those with stiffness; cut creases exert no moment).
    switched : bool
        The start state ceased to exist and the released cell rests in the other state.
    snap_change : float
        Rest-angle change at the snap, the last state on the start branch [rad].
    resolution : float
        The start branch ends within this above ``snap_change`` [rad].
    moment : float
        Summed moment of the driven creases at the snap, in the driving sense [N mm].
    max_crease_moment : float
        Largest moment of one driven crease there [N mm].
    work : float
        Work of the actuation up to the snap: the integral over the change of the rest
        angles' generalised force, ``moment`` while the creases stay in the law's linear
        range (trapezoids over the path) [N mm].
    snap_energy, start_energy : float
        Strain energy at the snap (actuated) and at the start [N mm]; their difference
        equals ``work`` to the quadrature's error.
    start_height, snap_height, landing_height : float
        Cell height (the top polygon's mean perimeter z) at the start, at the snap and
        where the released cell rests [mm].
    landing_energy : float
        Strain energy of the landing state [N mm].
    landing_tilt : float
        Its top polygon's tilt [rad].
    landing_negative_eigenvalues : int
        Of its tangent (0: an energy minimum).
    change, moments, energy, height : ndarray, shape (S,)
        The followed path: change [rad], summed moment [N mm], strain energy [N mm], height
        [mm], from the start (change 0).
    message : str
    """

    group: str
    forward: bool
    creases: int
    switched: bool
    snap_change: float
    resolution: float
    moment: float
    max_crease_moment: float
    work: float
    snap_energy: float
    start_energy: float
    start_height: float
    snap_height: float
    landing_height: float
    landing_energy: float
    landing_tilt: float
    landing_negative_eigenvalues: int
    change: np.ndarray
    moments: np.ndarray
    energy: np.ndarray
    height: np.ndarray
    message: str

    @classmethod
    def _from_core(cls, core) -> "CreaseSwitch":
        return cls(**{f.name: getattr(core, f.name) for f in fields(cls)})

    @property
    def snap_change_deg(self) -> float:
        """``snap_change`` in degrees."""
        return math.degrees(self.snap_change)


@dataclass(frozen=True)
class SwitchingResult:
    """Every crease group's switch of one cell, both ways.

    Attributes
    ----------
    design : Design
    snap : SnapThroughResult
        The cell's snap-through test (its contracted stable state and energy barrier).
    forward, backward : tuple of CreaseSwitch
        Extended to contracted and contracted to extended, one per group of :data:`GROUPS`
        (empty when the cell is not bistable).
    """

    design: Design
    snap: SnapThroughResult
    forward: tuple
    backward: tuple

    def least_actuation(self, by: str = "snap_change", forward: bool = True) -> str:
        """The group that switches with the smallest ``by`` (``snap_change``, ``moment`` or
        ``work``), or ``""`` when none switches."""
        if by not in ("snap_change", "moment", "work"):
            raise ValueError(f"by = {by!r} is invalid: must be 'snap_change', 'moment' or "
                             f"'work'")
        switches = [s for s in (self.forward if forward else self.backward) if s.switched]
        return min(switches, key=lambda s: abs(getattr(s, by))).group if switches else ""


def angle_in_radians(name, value, low, high) -> float:
    """``value`` [deg] in (low, high], in radians; else a ValueError naming ``name``."""
    value = as_finite_real(name, value)
    if not low < value <= high:
        raise ValueError(f"{name} = {value!r} is invalid: must be in ({low:g}, {high:g}] deg")
    return math.radians(value)


def switching(design: Design, *, parameters=None, snap_through_steps=DEFAULT_STEPS,
              scan_step_deg=0.25, max_change_deg=170.0, resolution_deg=1e-5,
              overshoot_deg=0.01, tolerance=1e-6, max_iterations=50) -> SwitchingResult:
    """Switch ``design``'s cell by each crease group, both ways.

    Parameters
    ----------
    design : Design
    parameters : SpecimenParameters, optional
        Stiffness assignment (the thesis's by default: mountain creases cut, so the
        ``mountain`` group drives nothing).
    snap_through_steps : int, default 100
        Increments of the snap-through test that finds the contracted state.
    scan_step_deg : float, default 0.25
        Increment of the rest-angle change while following the start state [deg].
    max_change_deg : float, default 170
        Largest change tried [deg] (at most 171; a change never takes a rest angle out of
        (0, 360) deg: the scan ends there).
    resolution_deg : float, default 1e-5
        Bisection's resolution of the change at the snap [deg].
    overshoot_deg : float, default 0.01
        How far past the snap the actuation is held while the cell snaps [deg].
    tolerance, max_iterations
        Newton's controls (2-norm of the correction [mm], iterations per increment).

    Returns
    -------
    SwitchingResult

    Raises
    ------
    ValueError
        For a design the snap-through test rejects or options out of range.
    """
    design = as_design(design)
    parameters = parameters or SpecimenParameters()
    steps = as_integer("snap_through_steps", snap_through_steps, minimum=1)
    max_change = angle_in_radians("max_change_deg", max_change_deg, 0.0, 171.0)
    scan_step = angle_in_radians("scan_step_deg", scan_step_deg, 0.0, max_change_deg)
    resolution = angle_in_radians("resolution_deg", resolution_deg, 0.0, scan_step_deg)
    overshoot = angle_in_radians("overshoot_deg", overshoot_deg, 0.0, scan_step_deg)
    core = _core.analyses.switching(
        design._core, parameters.to_core(), steps, scan_step, max_change, resolution, overshoot,
        as_finite_real("tolerance", tolerance),
        as_integer("max_iterations", max_iterations, minimum=1))
    snap = SnapThroughResult._from_core(core.snap, design)
    return SwitchingResult(design=design, snap=snap,
                           forward=tuple(CreaseSwitch._from_core(s) for s in core.forward),
                           backward=tuple(CreaseSwitch._from_core(s) for s in core.backward))
