"""The arm under its own weight: how far gravity moves its markers.

The arm's masses come from the thesis's materials (:mod:`kresling.arm.masses`). From an
equilibrium without gravity (the pretensioned arm, or a step of the tendon protocol) the
tendons' rest lengths are held, as the motors hold them, and gravity is applied as a body
load, each node's mass times ``g`` (9810 mm/s^2), in load steps of Newton's method
(:func:`kresling.solvers.solve_force_control`). The markers are the module ends (the guide
centres), as in the thesis's section 4.3.

Orientations (the arm's model has its base at z = 0 and its tip up, tendon 1 on +x):

- ``"hanging"``: the thesis's set-up. The arm hangs from its base plate (the base marker is
  the uppermost, the markers are read as (-x, -z)) and bends in the vertical plane of
  tendon 1, so gravity points along +z, from the base to the tip;
- ``"standing"``: the base below, gravity along -z;
- ``"horizontal"``: the axis horizontal with tendon 1 on top, gravity along -x (in the
  plane of the protocol's bending).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from kresling._validation import as_choice, as_integer, as_positive_real, as_real, show
from kresling.arm.analyses import DEFAULT_PRETENSION, ArmSolver, ArmState
from kresling.arm.structure import Arm

__all__ = ["GRAVITY", "ORIENTATIONS", "GravitySag", "gravity_sag", "held_tendons_model",
           "gravity_table", "PROTOCOL_STEPS", "pretensioned"]

#: The protocol steps the table weighs the arm at: at rest and fully bent (section 4.3).
PROTOCOL_STEPS = (0, 10)

#: The acceleration of gravity [mm/s^2].
GRAVITY = 9810.0
#: Unit vector of gravity in the arm's frame for each orientation.
ORIENTATIONS = {"hanging": (0.0, 0.0, 1.0), "standing": (0.0, 0.0, -1.0),
                "horizontal": (-1.0, 0.0, 0.0)}


@dataclass(frozen=True)
class GravitySag:
    """The arm's markers with and without its weight, the tendons' lengths held.

    Attributes
    ----------
    configuration, orientation : str
    gravity : ndarray, shape (3,)
        [mm/s^2] in the arm's frame.
    masses : kresling.arm.masses.ArmMasses
    start : ArmState
        The equilibrium without gravity.
    displacement : ndarray, shape (3N,)
        Every DOF with gravity [mm].
    markers, loaded_markers : ndarray, shape (m + 1, 3)
        Base and module ends without and with gravity [mm].
    tension : ndarray, shape (3,)
        Tendon tensions with gravity [N].
    completed : bool
        The whole weight was carried (otherwise ``message`` says where it stopped).
    message : str
    """

    configuration: str
    orientation: str
    gravity: np.ndarray
    masses: object
    start: ArmState
    displacement: np.ndarray
    markers: np.ndarray
    loaded_markers: np.ndarray
    tension: np.ndarray
    completed: bool
    message: str

    @property
    def marker_sag(self) -> np.ndarray:
        """Each marker's motion under gravity [mm], shape (m + 1, 3)."""
        return self.loaded_markers - self.markers

    @property
    def sag(self) -> np.ndarray:
        """Each marker's distance moved [mm], shape (m + 1,)."""
        return np.linalg.norm(self.marker_sag, axis=1)

    @property
    def module_length_change(self) -> np.ndarray:
        """Change of each module's guide-to-guide length under gravity [mm], shape (m,)."""
        length = lambda x: np.linalg.norm(np.diff(x, axis=0), axis=1)   # noqa: E731
        return length(self.loaded_markers) - length(self.markers)


def pretensioned(solver: ArmSolver, pretension) -> ArmState:
    """The arm of ``solver`` with every tendon at ``pretension`` N (finite, >= 0).

    Raises
    ------
    ValueError
        Naming ``pretension`` when it is out of range or the arm cannot reach it.
    """
    value = as_real("pretension", pretension)
    if not (math.isfinite(value) and value >= 0):
        raise ValueError(f"pretension = {value!r} is invalid: must be a finite tension >= 0 "
                         "(N per tendon)")
    try:
        return solver.pretension(value)
    except RuntimeError as error:
        raise ValueError(f"pretension = {value!r} N is invalid for this arm: {error}") from None


def held_tendons_model(arm: Arm, pulls):
    """``arm.model`` with every tendon's rest length fixed at its slack length minus
    ``pulls`` (3,) [mm]: the tendons as the motors hold them."""
    rest = np.asarray(arm.slack_length, dtype=float) - np.asarray(pulls, dtype=float)
    cables = list(zip(arm.model.cable_nodes, arm.model.cable_stiffness, rest))
    return arm.model.replace(cables=cables)


def gravity_sag(arm: Arm, orientation="hanging", *, start: ArmState | None = None,
                pretension: float = DEFAULT_PRETENSION, masses=None,
                g: float = GRAVITY, steps: int = 5,
                solver: ArmSolver | None = None) -> GravitySag:
    """The arm's markers moved by its own weight from an equilibrium without it.

    Parameters
    ----------
    arm : Arm
    orientation : {"hanging", "standing", "horizontal"}, default "hanging"
        Where gravity points (see the module; "hanging" is the thesis's set-up).
    start : ArmState, optional
        The equilibrium without gravity (default: the arm pretensioned to
        ``pretension`` N per tendon).
    masses : ArmMasses, optional
        Default: :func:`kresling.arm.masses.arm_masses` of the thesis's materials.
    g : float, default 9810
        [mm/s^2]
    steps : int, default 5
        Load steps of the weight.

    Returns
    -------
    GravitySag

    Examples
    --------
    >>> from kresling.arm import build_arm
    >>> s = gravity_sag(build_arm("0"), "horizontal")
    >>> s.completed, round(float(s.sag[-1]), 2)   # the tip, mm
    (True, 0.06)
    """
    # The masses import the analyses (the laminate): lazily, so that building the command
    # line's parser, which reads ORIENTATIONS, stays light.
    from kresling.arm.masses import ArmMasses, arm_masses
    from kresling.solvers import solve_force_control

    if not isinstance(arm, Arm):
        raise ValueError(f"arm = {show(arm)} is invalid: must be a kresling.arm.Arm")
    orientation = as_choice("orientation", orientation, tuple(ORIENTATIONS))
    g = as_positive_real("g", g)
    solver = ArmSolver(arm) if solver is None else solver
    start = pretensioned(solver, pretension) if start is None else start
    if not isinstance(start, ArmState):
        raise ValueError(f"start = {show(start)} is invalid: must be an ArmState of this arm")
    masses = arm_masses(arm) if masses is None else masses
    if not isinstance(masses, ArmMasses):
        raise ValueError(f"masses = {show(masses)} is invalid: must be an ArmMasses")
    gravity = g * np.asarray(ORIENTATIONS[orientation])
    model = held_tendons_model(arm, start.pulls)
    weight = (masses.node[:, None] * gravity[None, :]).ravel()
    if not np.any(weight):  # a g so small that every weight m g underflows to zero
        raise ValueError(f"g = {g!r} mm/s^2 is invalid: too small for any weight (m g) of "
                         f"this arm's masses to be non-zero")
    steps = as_integer("steps", steps, minimum=1, maximum=1000)
    path = solve_force_control(model, weight, steps, initial=start.displacement, tolerance=1e-6)
    u = path.displacement[-1] if path.num_steps else start.displacement
    positions = lambda d: arm.model.nodes + np.asarray(d).reshape(-1, 3)   # noqa: E731
    tension = model.element_state(u)["cable_tension"]
    return GravitySag(arm.configuration, orientation, gravity, masses, start, np.asarray(u),
                      arm.guide_centres(positions(start.displacement)),
                      arm.guide_centres(positions(u)), np.asarray(tension, dtype=float),
                      bool(path.completed and path.num_steps), path.message)


def gravity_table(modules: int = 3, orientation="hanging", *, steps=PROTOCOL_STEPS,
                  configurations=None, measured_skeleton: bool = False,
                  pretension: float = DEFAULT_PRETENSION, **arm_options) -> list:
    """The sag of every configuration's markers at protocol steps (section 4.3).

    Parameters
    ----------
    modules : int, default 3
    orientation : str, default "hanging"
        As in :func:`gravity_sag`.
    steps : sequence of int, default (0, 10)
        Protocol steps ``k`` (tendon 1 in by ``2 k f``, tendons 2 and 3 out by ``k f`` for
        ``f`` contracted modules); a configuration without a contracted module is weighed
        at rest only.
    configurations : sequence of str, optional
        Default: all ``2^modules`` of them.
    measured_skeleton : bool, default False
        Scale the masses to the thesis's weighed skeleton (:func:`arm_masses`).
    **arm_options
        Passed to :func:`kresling.arm.build_arm` (the cell, ``parameters``).

    Returns
    -------
    list of dict
        One per configuration and step: ``config``, ``k``, ``mass_g`` (the arm's mass
        [g]), ``sag_mm`` (each marker from the base, (m + 1,)), ``tip_sag_mm``,
        ``largest_sag_mm``, ``tip_sag_vector_mm`` (3,), ``module_length_change_mm``
        (m,), ``tension_N`` (3,), ``completed``, ``message``.
    """
    from kresling.arm.actuation import pseudo_linkage_run
    from kresling.arm.masses import arm_masses
    from kresling.arm.structure import all_configurations, build_arm

    rows = []
    for config in all_configurations(modules) if configurations is None else configurations:
        arm = build_arm(config, **arm_options)
        solver = ArmSolver(arm)
        masses = arm_masses(arm, measured_skeleton=measured_skeleton)
        if "0" in config:
            run = pseudo_linkage_run(arm, list(steps), pretension=pretension, solver=solver)
            starts = list(zip(steps, run.states))
        else:
            starts = [(0, pretensioned(solver, pretension))]
        for k, start in starts:
            s = gravity_sag(arm, orientation, start=start, masses=masses, solver=solver)
            rows.append({"config": config, "k": int(k), "mass_g": masses.total * 1e6,
                         "sag_mm": s.sag.tolist(), "tip_sag_mm": float(s.sag[-1]),
                         "largest_sag_mm": float(s.sag.max()),
                         "tip_sag_vector_mm": s.marker_sag[-1].tolist(),
                         "module_length_change_mm": s.module_length_change.tolist(),
                         "tension_N": s.tension.tolist(), "completed": s.completed,
                         "message": s.message})
    return rows
