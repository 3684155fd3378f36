"""Bistability strength: the snap-through test (thesis section 3.5, figures 3.16-3.17).

The thesis drives one cell from its extended to its contracted height and takes the first
local maximum of the force as the measure of bistability; it gives no more of the protocol.
Ours (docs/thesis_equations.md, 'Bending test', snap-through; in C++):

- one cell, built stress-free in its extended state (its chirality does not matter: the
  mirror image responds identically);
- the bottom polygon's n+1 nodes fixed in x, y, z;
- the top polygon's n+1 nodes driven down in z by ``Le - Lc`` in equal increments, their x
  and y free (the top twists and may shift), by displacement control, which also holds the
  unstable branch where the force falls;
- F = the summed reaction at the driven nodes (positive: the cell resists compression),
  d = the drive's travel.

From the path: the **snap force** is the first local maximum of F(d), refined by the
parabola through the peak sample and its neighbours; the **energy barrier** is the strain
energy at the **unstable state**, the first zero of F after the peak, which equals the work
of the drive up to it (the energy is recorded at every step and interpolated with its
derivative F); the cell is **bistable** when F rises back through zero and the cell released
there (every top DOF free, no load) comes to rest at an energy minimum (positive-definite
tangent) other than its extended state, the only stress-free one. The drive keeps the top
polygon level; released, it may tilt: the optimum's level contracted equilibrium is a
saddle, and it comes to rest tilted by about 16 degrees.

The model is stress-free only in its extended state, so the force at the contracted height
is not zero and the second stable state lies above ``Lc``. The thesis says its figure 3.16
curve (n = 8, Lc = 30, lambda = 0.8) stays above zero; ours dips to -0.11 N there (a MERLIN2
run of the same reading: 4.34 N at 5.93 mm, then slightly below zero): compare the trends of
figure 3.17, not the sign of that dip. Those trends hold except near the
monostable corner (lambda below about 0.8 with Lc above about 45 mm for n = 8 and 10), where
the first maximum flattens, rises again slightly with Lc and then disappears (NaN).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields

import numpy as np

from kresling import _core
from kresling.analyses.travel import travel_fraction
from kresling.geometry import Design, as_design
from kresling.model.kresling_specimen import SpecimenParameters
from kresling._validation import as_integer
from kresling.solvers.displacement_control import displacement_control_options

__all__ = ["SnapThroughResult", "SnapThroughTester", "snap_through", "DEFAULT_STEPS",
           "DEFAULT_EXTRAPOLATION", "MIN_INCREMENTS_TO_PEAK"]

#: Increments from Le to Lc: the snap force within 1e-4 (relative) and its displacement
#: within 0.01 mm of the converged values on the thesis's designs, in about 5 ms a run.
DEFAULT_STEPS = 100

#: Each increment's Newton start: a cubic extrapolation through the last four equilibria.
#: Against the quadratic, on 160 random designs of the thesis's grid (n = 4-10): 15 % faster,
#: snap forces within 8e-12 and energy barriers within 3e-14 (relative), the same designs
#: bistable.
DEFAULT_EXTRAPOLATION = 3

#: Fewest increments up to the peak for the snap force to count as resolved. Measured against
#: 2000-increment runs of five designs (n = 4-10, lambda 0.7-0.9, Lc 15-45 mm): with 3 or
#: more increments before the peak the parabola-refined force was within 0.25 %; with 2 to 3
#: up to 0.94 %, with 1 to 2 up to 6.6 %, and below 1 it was off by up to 29 % or the peak was
#: missed entirely.
MIN_INCREMENTS_TO_PEAK = 3.0


@dataclass(frozen=True)
class SnapThroughResult:
    """One snap-through test (see the module's description for the definitions).

    Attributes
    ----------
    design : Design
    snap_force : float
        First local maximum of the force [N]; NaN when the force rises monotonically.
    snap_displacement : float
        Drive travel at that maximum [mm].
    unstable_displacement : float
        Travel at the first zero of the force after the peak [mm]; NaN if none.
    energy_barrier : float
        Strain energy at the unstable state = work of the drive from the extended state up
        to it [N*mm]; NaN for a monostable cell (the force never returns to zero).
    minimum_force : float
        Smallest force after the peak [N] (negative: the cell pulls the drive down).
    bistable : bool
        The released cell comes to rest at an energy minimum other than its extended state.
    bistability : str
        Why (or why not), in words.
    stable_displacement, stable_height : float
        Travel [mm] and cell height ``Le - travel`` [mm] of the second stable state (mean of
        the top polygon's perimeter: released, its centre node may dome out of plane); NaN
        if not bistable.
    stable_energy : float
        Its strain energy [N*mm].
    stable_tilt : float
        Its top polygon's tilt from horizontal [rad].
    stable_negative_eigenvalues : int
        Of its tangent (bottom polygon held): 0 when found, -1 when not reached.
    extended_height, contracted_height : float
        ``Le`` and ``Lc`` [mm].
    displacement, force, energy : ndarray, shape (S + 1,)
        The path: travel [mm], force [N], strain energy [N*mm], starting with the built
        extended state (0, 0, 0).
    iterations : ndarray of int, shape (S + 1,)
        Newton iterations per increment (0 for the start).
    completed : bool
        The drive reached ``Lc`` (False: ``message`` says at which increment and why; the
        features are then read from the part of the path that converged).
    message : str
    """

    design: Design
    snap_force: float
    snap_displacement: float
    unstable_displacement: float
    energy_barrier: float
    minimum_force: float
    bistable: bool
    bistability: str
    stable_displacement: float
    stable_height: float
    stable_energy: float
    stable_tilt: float
    stable_negative_eigenvalues: int
    extended_height: float
    contracted_height: float
    displacement: np.ndarray
    force: np.ndarray
    energy: np.ndarray
    iterations: np.ndarray
    completed: bool
    message: str

    @classmethod
    def _from_core(cls, core, design) -> "SnapThroughResult":
        """Read the C++ core's result (``kresling._core.analyses.SnapThroughResult``): every
        field of this class but ``design`` is one of its properties."""
        return cls(design=design, **{f.name: getattr(core, f.name) for f in fields(cls)
                                     if f.name != "design"})

    @property
    def partial(self) -> bool:
        """True if the drive stopped before ``Lc`` (the features come from the part of the
        path that converged)."""
        return not self.completed

    @property
    def travel_fraction(self) -> float:
        """Fraction of the travel ``Le - Lc`` the drive reached (1 when completed)."""
        reached = self.displacement[-1] if len(self.displacement) else None
        return travel_fraction(self.completed, reached,
                               self.extended_height - self.contracted_height)

    @property
    def increments_to_peak(self) -> float:
        """How many increments of the drive fit before the peak (``snap_displacement`` over
        the increment); NaN without a peak."""
        if not self.has_peak or len(self.displacement) < 2:
            return math.nan
        return float(self.snap_displacement / (self.displacement[1] - self.displacement[0]))

    @property
    def resolution(self) -> str:
        """Empty when the path resolves the peak; otherwise why the snap force is not to be
        trusted and how many increments would be (see :data:`MIN_INCREMENTS_TO_PEAK`)."""
        if len(self.displacement) < 2:
            return ""
        step = float(self.displacement[1] - self.displacement[0])
        steps = round((self.extended_height - self.contracted_height) / step)
        if self.has_peak:
            k = self.increments_to_peak
            if k >= MIN_INCREMENTS_TO_PEAK:
                return ""
            needed = math.ceil(steps * 2 * MIN_INCREMENTS_TO_PEAK / k)
            return (f"the force peak is under-resolved: only {k:.1f} increments of "
                    f"{step:.3g} mm before it (fewer than {MIN_INCREMENTS_TO_PEAK:g}: the "
                    f"snap force was off by up to 29 % in such runs); raise steps to about "
                    f"{needed} or more")
        if (self.force[1:] < 0).any():
            # The force starts positive (the cell resists compression); a negative force with
            # no sampled maximum before it means the peak fell between increments.
            return (f"the force turns negative with no sampled maximum before it: the peak "
                    f"fell between the increments of {step:.3g} mm and was missed; raise steps "
                    f"to {max(DEFAULT_STEPS, 10 * steps)} or more")
        return ""

    @property
    def has_peak(self) -> bool:
        """Whether the force has a local maximum (a snap-through force exists)."""
        return not math.isnan(self.snap_force)

    def __repr__(self) -> str:
        peak = (f"snap force {self.snap_force:.6g} N at {self.snap_displacement:.4g} mm"
                if self.has_peak else "no force peak")
        status = "" if self.completed else (f", PARTIAL: stopped at {self.travel_fraction:.0%} "
                                            f"of the travel ({self.message})")
        warning = f", {self.resolution}" if self.resolution else ""
        return (f"SnapThroughResult({self.design!r}, {peak}, "
                f"{'bistable' if self.bistable else 'not bistable'}{status}{warning})")

    def summary(self) -> dict:
        """The scalar results as a ``dict`` (NaN where undefined)."""
        keys = ("snap_force", "snap_displacement", "unstable_displacement", "energy_barrier",
                "minimum_force", "bistable", "bistability", "stable_displacement",
                "stable_height", "stable_energy", "stable_tilt", "extended_height",
                "contracted_height", "completed", "message", "partial", "travel_fraction",
                "increments_to_peak", "resolution")
        return {key: getattr(self, key) for key in keys}


class SnapThroughTester:
    """The snap-through test for one polygon size, reusable across designs (for sweeps).

    The topology, the sparsity patterns and the symbolic factorisation are built once; each
    :meth:`run` only places the nodes and solves (about 2-6 ms for n = 4-10).

    Parameters
    ----------
    n : int
        Sides of the polygon (>= 3; odd n is fine here).
    steps : int, default :data:`DEFAULT_STEPS`
        Displacement increments from ``Le`` to ``Lc``.
    parameters : SpecimenParameters, optional
        Stiffness assignment (the thesis's by default).
    extrapolation : {0, 1, 2, 3}, default :data:`DEFAULT_EXTRAPOLATION` (3)
        Starting guess of each increment (see ``solve_displacement_control``).
    **solver
        Other options of ``solve_displacement_control`` (tolerance, max_iterations, ...).

    Raises
    ------
    ValueError
        For n < 3, steps < 1 or bad parameters.
    """

    def __init__(self, n, *, steps=DEFAULT_STEPS, parameters=None,
                 extrapolation=DEFAULT_EXTRAPOLATION, **solver):
        self.n = as_integer("n", n, minimum=3)
        self.steps = as_integer("steps", steps, minimum=1)
        self.parameters = parameters or SpecimenParameters()
        options = displacement_control_options(extrapolation=extrapolation, **solver)
        self._core = _core.analyses.SnapThroughTest(self.n, self.steps, self.parameters.to_core(),
                                                    options)

    def run(self, design: Design) -> SnapThroughResult:
        """Drive ``design`` (same n) from extended to contracted."""
        design = as_design(design)
        if design.n != self.n:
            raise ValueError(f"design.n = {design.n} is invalid: this tester is for n = {self.n}")
        return SnapThroughResult._from_core(self._core.run(design._core), design)


def snap_through(design: Design, *, steps=DEFAULT_STEPS, parameters=None,
                 **solver) -> SnapThroughResult:
    """Drive one cell of ``design`` from its extended to its contracted height.

    Parameters
    ----------
    design : Design
    steps : int, default :data:`DEFAULT_STEPS`
        Displacement increments.
    parameters : SpecimenParameters, optional
        Stiffness assignment (the thesis's by default).
    **solver
        Options of ``solve_displacement_control`` (``extrapolation`` defaults to
        :data:`DEFAULT_EXTRAPOLATION`, 3).

    Returns
    -------
    SnapThroughResult

    Raises
    ------
    ValueError
        For steps outside [1, 100000], Lc = 0 (the drive would fold the cell flat) or bad
        parameters.

    Examples
    --------
    >>> from kresling import Design
    >>> r = snap_through(Design(8, 0.8, 30))
    >>> round(r.snap_force, 2), round(r.snap_displacement, 2)   # N, mm; MERLIN2: 4.34 at 5.93
    (4.34, 5.92)
    >>> r.bistable, round(r.stable_height, 1)
    (True, 33.9)
    """
    design = as_design(design)
    return SnapThroughTester(design.n, steps=steps, parameters=parameters, **solver).run(design)
