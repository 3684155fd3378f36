"""The whole paths of the bending and snap-through tests: every node's displacement at every
increment, for views and animations.

:func:`~kresling.analyses.bending_test` and :func:`~kresling.analyses.snap_through` run in
C++ and keep, of each increment, what their results need (forces, deflections, energies).
The functions here take the C++ tests' own set-up (specimen, supports and drive:
``setup`` of the core's ``BendingTest`` and ``SnapThroughTest``) and follow the same path
with :func:`kresling.solvers.solve_displacement_control` (same solver options), which keeps
every node's displacement: the curves they give are those of the C++ tests.

- :func:`bending_path`: a four-cell specimen in one state, nodes 0 and n/2 and the centre of
  the end polygons pinned, the middle polygon driven sideways (-y);
- :func:`snap_through_path`: one cell built extended, its bottom polygon fixed, its top
  polygon driven down to ``Lc``, free to twist.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from kresling import _core
from kresling._validation import as_integer
from kresling.analyses.bending import adaptive_options, protocol_settings, require_even_n
from kresling.analyses.snap_through import DEFAULT_EXTRAPOLATION, DEFAULT_STEPS
from kresling.analyses.travel import travel_fraction
from kresling.geometry import Design, as_design, state_index
from kresling.model.kresling_specimen import (SpecimenParameters, alternating_chirality,
                                              specimen_from_core)
from kresling.solvers.displacement_control import (displacement_control_options,
                                                   solve_displacement_control)

__all__ = ["BendingPath", "SnapThroughPath", "bending_path", "snap_through_path"]

# The smallest facet angle the bending test accepts [rad], as the C++ tester (cell_checks):
# hinge angles near a flat fold carry errors up to ~1e-8 rad.
_MIN_FACET_ANGLE = 1e-6


@dataclass(frozen=True)
class BendingPath:
    """A bending test's path with every node's displacement.

    Attributes
    ----------
    specimen : KreslingSpecimen
        The four-cell specimen with its supports.
    path : kresling.solvers.PathResult
        One row per increment; ``path.displacement`` (S, 3N) [mm].
    state : int
        0 contracted, 1 extended.
    module_length : float
        L, two cells' height [mm].
    deflection, force, angle, moment : ndarray, shape (S,)
        Per increment, as :class:`~kresling.analyses.BendingResult` has them: the middle
        polygon's centre deflection [mm], the summed reaction [N], delta = atan(y / L)
        [rad] and M = F L [N*m].
    target_deflection : float
        The drive's full travel [mm] (NaN: not known).

    Notes
    -----
    A path that stopped early (``path.completed`` False) is *partial*, as the bending
    test's result would be: ``travel_fraction`` says how far it went.
    """

    specimen: object
    path: object
    state: int
    module_length: float
    deflection: np.ndarray
    force: np.ndarray
    angle: np.ndarray
    moment: np.ndarray
    target_deflection: float = float("nan")

    @property
    def state_name(self) -> str:
        return "extended" if self.state == 1 else "contracted"

    @property
    def partial(self) -> bool:
        """True if the path stopped before the end of its travel."""
        return not self.path.completed

    @property
    def travel_fraction(self) -> float:
        """Fraction of the drive's travel reached (1 for a completed path; 0 if no increment
        converged or the travel is not known), as
        :attr:`kresling.analyses.BendingResult.travel_fraction`."""
        reached = abs(self.deflection[-1]) if len(self.deflection) else None
        return travel_fraction(not self.partial, reached, self.target_deflection)


@dataclass(frozen=True)
class SnapThroughPath:
    """A snap-through test's path with every node's displacement.

    Attributes
    ----------
    specimen : KreslingSpecimen
        One cell, built extended, its bottom polygon fixed.
    path : kresling.solvers.PathResult
        One row per increment; ``path.displacement`` (S, 3N) [mm].
    travel, force : ndarray, shape (S,)
        The drive's travel [mm] and the summed reaction at the driven nodes [N] (positive:
        the cell resists compression), as :class:`~kresling.analyses.SnapThroughResult`
        has them after its first entry (the built state).

    Notes
    -----
    A path that stopped before ``Lc`` (``path.completed`` False) is *partial*:
    ``travel_fraction`` says how far it went.
    """

    specimen: object
    path: object
    travel: np.ndarray
    force: np.ndarray

    @property
    def partial(self) -> bool:
        """True if the drive stopped before ``Lc``."""
        return not self.path.completed

    @property
    def travel_fraction(self) -> float:
        """Fraction of the travel ``Le - Lc`` reached (1 when completed, 0 if no increment
        converged), as :attr:`kresling.analyses.SnapThroughResult.travel_fraction`."""
        design = self.specimen.design
        reached = self.travel[-1] if len(self.travel) else None
        return travel_fraction(not self.partial, reached, design.height(1) - design.height(0))


def bending_path(design: Design, state, protocol="5mm", *, deflection=None,
                 deflection_angle=None, steps=None, cells=4, parameters=None,
                 extrapolation=2, adaptive=None, **solver) -> BendingPath:
    """The three-point bending test of :func:`~kresling.analyses.bending_test`, every node
    at every increment (the same path: adaptive increments where the bending test uses them,
    fixed steps where those could not finish it).

    Parameters
    ----------
    design : Design
    state : {0, 1, "contracted", "extended"}
    protocol : {"5mm", "0.001rad"}
        The presets of :data:`kresling.analyses.PROTOCOLS`.
    deflection, deflection_angle, steps, cells, parameters, extrapolation, adaptive, **solver
        As for :class:`~kresling.analyses.BendingTester`.

    Returns
    -------
    BendingPath

    Raises
    ------
    ValueError
        As :func:`~kresling.analyses.bending_test`: an odd n, an odd cell count, a
        deflection that is zero or as large as the polygon's radius, bad options.

    Examples
    --------
    >>> from kresling import Design
    >>> bent = bending_path(Design(10, 0.9, 15), "extended", "0.001rad")
    >>> bent.path.displacement.shape, round(float(bent.moment[-1] / bent.angle[-1]), 4)
    ((10, 165), 3.2835)
    """
    settings = protocol_settings(protocol, deflection, deflection_angle, steps)
    state = state_index(state)
    n = require_even_n(design.n)
    psi = design.psi_con if state == 0 else design.psi_ext
    if psi < _MIN_FACET_ANGLE:
        # As the bending tester says it: a flat module has no length to bend over, and the
        # deflection the protocol derives from it would be zero.
        name = "Lc" if state == 0 else "lam"
        raise ValueError(
            f"{name} = {getattr(design, name)!r} is invalid: must be > 0 for the bending test in "
            f"the {'contracted' if state == 0 else 'extended'} state, and large enough that the "
            f"cell is not flat to within the model's resolution: Psi_"
            f"{'con' if state == 0 else 'ext'} = {psi:.3g} rad, must be >= "
            f"{_MIN_FACET_ANGLE:g} rad")
    if cells < 2 or cells % 2:
        raise ValueError(f"cells = {cells!r} is invalid: must be an even number >= 2 (the load "
                         "acts on the middle polygon)")
    module_length = 2.0 * design.height(state)
    drive = module_length * np.tan(settings["deflection_angle"]) \
        if settings["deflection_angle"] else settings["deflection"]
    if drive == 0.0 or abs(drive) >= design.R:
        raise ValueError(f"deflection = {drive!r} is invalid: must be non-zero and smaller than "
                         f"the polygon's radius R = {design.R:g} mm")
    adaptive, solver = adaptive_options(protocol, extrapolation, adaptive, solver)
    # The bending test's own specimen, supports and drive (only the set-up: the path is
    # followed here, keeping every node).
    parameters = parameters or SpecimenParameters()
    tester = _core.analyses.BendingTest(n, settings["deflection"], settings["deflection_angle"],
                                        settings["steps"], cells, parameters.to_core(),
                                        displacement_control_options())
    core, prescribed = tester.setup(design._core, state)
    specimen = specimen_from_core(core, design, [state] * cells, alternating_chirality(cells),
                                  parameters)
    path = solve_displacement_control(specimen.model, prescribed, settings["steps"],
                                      extrapolation=extrapolation, adaptive=adaptive, **solver)
    centre_y = 3 * specimen.centre(cells // 2) + 1
    deflection_mm = -np.asarray(path.displacement, dtype=float).reshape(
        -1, specimen.model.num_dofs)[:, centre_y]
    # One row per increment: a path that stopped at its first increment has none.
    force = np.asarray(path.constraint_force, dtype=float).reshape(
        len(deflection_mm), len(path.constraint_dofs)).sum(axis=1)
    return BendingPath(specimen=specimen, path=path, state=state, module_length=module_length,
                       deflection=deflection_mm, force=force,
                       angle=np.arctan(deflection_mm / module_length),
                       moment=force * module_length / 1000.0, target_deflection=abs(drive))


def snap_through_path(design: Design, *, steps=DEFAULT_STEPS, parameters=None,
                      extrapolation=DEFAULT_EXTRAPOLATION, **solver) -> SnapThroughPath:
    """The snap-through test of :func:`~kresling.analyses.snap_through`, every node at every
    increment (the drive from ``Le`` to ``Lc``; not the release to the second stable state).

    Parameters
    ----------
    design : Design
    steps : int, default :data:`kresling.analyses.snap_through.DEFAULT_STEPS`
    parameters, extrapolation, **solver
        As for :class:`~kresling.analyses.SnapThroughTester`.

    Returns
    -------
    SnapThroughPath

    Examples
    --------
    >>> from kresling import Design
    >>> snap = snap_through_path(Design(8, 0.8, 30))
    >>> peak = int(snap.force.argmax())
    >>> round(float(snap.force[peak]), 2), round(float(snap.travel[peak]), 2)
    (4.34, 5.82)
    """
    # The snap-through test's own specimen, supports and drive.
    parameters = parameters or SpecimenParameters()
    tester = _core.analyses.SnapThroughTest(design.n, as_integer("steps", steps, minimum=1),
                                            parameters.to_core(), displacement_control_options())
    core, prescribed = tester.setup(as_design(design)._core)
    specimen = specimen_from_core(core, design, [1], [1], parameters)
    path = solve_displacement_control(specimen.model, prescribed, steps,
                                      extrapolation=extrapolation, **solver)
    displacement = np.asarray(path.displacement, dtype=float).reshape(-1, specimen.model.num_dofs)
    travel = -displacement[:, 3 * specimen.centre(1) + 2]
    force = np.asarray(path.constraint_force, dtype=float).reshape(
        len(travel), len(path.constraint_dofs)).sum(axis=1)
    return SnapThroughPath(specimen=specimen, path=path, travel=travel, force=force)
