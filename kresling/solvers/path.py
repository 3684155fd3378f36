"""The result every path solver returns."""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np


@dataclass(frozen=True)
class PathKnots:
    """The converged points of a path in adaptive increments that its steps were read from
    (cubic Hermite curves between consecutive knots through their values and path rates).

    Attributes
    ----------
    t : ndarray, shape (K,)
        The path parameter of each knot (as ``PathResult.load_factor``), increasing.
    displacement : ndarray, shape (K, 3N)
        [mm].
    velocity : ndarray, shape (K, 3N)
        d displacement / dt [mm per unit of t].
    step_knot : ndarray of int, shape (S,)
        Per step of the path: j when it was read off the curves between knots j - 1 and j
        (a step at knot j included), -1 when it was converged by Newton on its own.
    """

    t: np.ndarray
    displacement: np.ndarray
    velocity: np.ndarray
    step_knot: np.ndarray

    @classmethod
    def _from_core(cls, core) -> "PathKnots | None":
        t = np.asarray(core.knot_t)
        if t.size == 0:
            return None
        out = cls(t, np.asarray(core.knot_displacement), np.asarray(core.knot_velocity),
                  np.asarray(core.step_knot, dtype=np.int64))
        for value in (out.t, out.displacement, out.velocity, out.step_knot):
            value.flags.writeable = False
        return out


@dataclass(frozen=True)
class PathResult:
    """An equilibrium path, one row per accepted increment.

    Attributes
    ----------
    load_factor : ndarray, shape (S,)
        Load factor lambda (force control) or fraction of the prescribed motion.
    displacement : ndarray, shape (S, 3N)
        Displacement of every DOF [mm].
    constraint_dofs : ndarray of int, shape (C,)
        Displacement control: the imposed DOFs. Force control: the supported DOFs.
    constraint_force : ndarray, shape (S, C)
        Displacement control: the force the structure exerts on the actuator at each
        imposed DOF, ``-f_int`` (MERLIN2's reported force) [N]. Force control: the support
        reactions ``f_int`` [N].
    families : tuple of str, length F
        The model's element families ("bars", "hinges", "cables", ...), in assembly order.
    energies : ndarray, shape (S, F)
        Stored energy of each family at each step [N*mm]; ``energy_of(name)`` reads one
        column, ``energy_bars`` and ``energy_hinges`` the first two.
    iterations : ndarray of int, shape (S,)
        Newton iterations of each increment.
    negative_eigenvalues : ndarray of int, shape (S,)
        Negative eigenvalues of the free tangent (0: stable equilibrium; -1: not known).
    completed : bool
        The path reached its end (or its stopping criterion).
    message : str
        Why it stopped early ("" when completed).
    failed_increment : int
        1-based number of the attempt that failed (0 if none).
    attempted_increments : int
        Increments tried, including rejected ones.
    newton_iterations : int
        Newton iterations of every increment tried, including rejected ones
        (``iterations`` counts those of the accepted increments only).
    snapped : ndarray of bool, shape (S,)
        Steps reached by a snap (a fold's ``snap=True``): where the path the step before
        was on ended, an energy descent to a stable state, not a continuation of it.
    knots : PathKnots or None
        Adaptive increments asked to keep them (``keep_knots=True``): the converged points
        the steps were read from; None otherwise.
    """

    load_factor: np.ndarray
    displacement: np.ndarray
    constraint_dofs: np.ndarray
    constraint_force: np.ndarray
    families: tuple
    energies: np.ndarray
    iterations: np.ndarray
    negative_eigenvalues: np.ndarray
    completed: bool
    message: str
    failed_increment: int
    attempted_increments: int
    newton_iterations: int
    snapped: np.ndarray
    knots: "PathKnots | None" = None

    @classmethod
    def _from_core(cls, core) -> "PathResult":
        """Read the C++ core's path (``kresling._core.solvers.PathResult``): every field of
        this class but ``knots`` is one of its properties."""
        values = {"knots": PathKnots._from_core(core)}
        for field in fields(cls):
            if field.name == "knots":
                continue
            value = getattr(core, field.name)
            if field.name == "constraint_dofs":
                value = np.asarray(value, dtype=np.int64)
            elif field.name == "families":
                value = tuple(value)
            if isinstance(value, np.ndarray):
                value.flags.writeable = False
            values[field.name] = value
        return cls(**values)

    @property
    def num_steps(self) -> int:
        return len(self.load_factor)

    def energy_of(self, family: str) -> np.ndarray:
        """Stored energy of the element family ``family`` per step, shape (S,) [N*mm]."""
        if family not in self.families:
            raise ValueError(f"family = {family!r} is invalid: the model's families are "
                             f"{list(self.families)}")
        return self.energies[:, self.families.index(family)]

    @property
    def energy_bars(self) -> np.ndarray:
        """The bars' stored energy per step, shape (S,) [N*mm]."""
        return self.energy_of("bars")

    @property
    def energy_hinges(self) -> np.ndarray:
        """The hinges' stored energy per step, shape (S,) [N*mm]."""
        return self.energy_of("hinges")

    @property
    def energy(self) -> np.ndarray:
        """Total stored energy per step, shape (S,) [N*mm] (the families summed in order)."""
        total = np.zeros(len(self.load_factor))
        for k in range(len(self.families)):
            total = total + self.energies[:, k]
        return total

    @property
    def stable(self) -> np.ndarray:
        """True where the equilibrium's free tangent is positive definite."""
        return self.negative_eigenvalues == 0

    def __repr__(self):
        state = "completed" if self.completed else f"stopped: {self.message}"
        return (f"PathResult({self.num_steps} steps, {int(self.iterations.sum())} Newton "
                f"iterations, {state})")
