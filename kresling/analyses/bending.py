"""The three-point bending test (thesis section 3.4, Appendix B; docs/thesis_equations.md,
'Bending test').

Two modules (four cells, chirality + - + -) in one state; nodes 0, n/2 and the centre of
the end polygons pinned; the middle polygon driven transversely. From the summed reaction
F and the centre's deflection y: ``M = F L`` and ``delta = atan(y / L)`` with L the module
length, and K_B the least-squares slope of M on delta through the origin (as the thesis's
code fits it; the fit with intercept, as a lab would fit a measured curve, is reported too).

Two protocols: the thesis's Table 3 runs drive the middle polygon 5 mm in 350 steps; its
parametric study drives it to a 0.001 rad deflection (``L tan(0.001)``) in 10 steps.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

import numpy as np

from kresling import _core
from kresling._validation import as_finite_real, as_integer, show
from kresling.analyses.travel import travel_fraction
from kresling.geometry import Design, as_design, state_index
from kresling.model.kresling_specimen import SpecimenParameters
from kresling.solvers.displacement_control import displacement_control_options

__all__ = ["PROTOCOLS", "BendingResult", "BendingComparison", "BendingTester", "bending_test",
           "bending_stiffness", "require_even_n"]

#: The thesis's two loading protocols: Table 3 (5 mm in 350 steps) and the parametric
#: study (0.001 rad, 10 steps: our choice, docs/thesis_equations.md, 'Bending test'; the
#: thesis gives no step count).
PROTOCOLS = {
    "5mm": {"deflection": 5.0, "deflection_angle": 0.0, "steps": 350},
    "0.001rad": {"deflection": 0.0, "deflection_angle": 0.001, "steps": 10},
}


def require_even_n(n) -> int:
    """``n`` if the bending test can be run on it; otherwise a ValueError that says why not.

    The test pins each end polygon at two opposite vertices, 0 and n/2, as the thesis's model
    does (Appendix B). A polygon with an odd number of sides has no vertex opposite another:
    opposite vertex 0 lies the middle of an edge, where the model has no node, so those
    supports cannot be placed, and any other choice (a vertex and an edge's midpoint node, or
    two vertices off the diameter) would be a different test whose K_B the thesis's cannot be
    compared with. Odd n is fine everywhere else (geometry, snap-through, patterns).
    """
    n = as_integer("n", n)
    if n % 2:
        raise ValueError(
            f"n = {n} is invalid: must be even for the bending test: it pins each end polygon "
            f"at two opposite vertices (0 and n/2), and a polygon with an odd number of sides "
            f"has none (opposite a vertex lies the middle of an edge, where the model has no "
            f"node). The snap-through test and the geometry take any n >= 3")
    return n


@dataclass(frozen=True)
class BendingResult:
    """One bending test.

    Attributes
    ----------
    design : Design
    state : int
        0 contracted, 1 extended.
    stiffness : float
        K_B, least-squares slope of M on delta through the origin [N*m/rad].
    stiffness_intercept, intercept : float
        Slope [N*m/rad] and intercept [N*m] of the fit with intercept.
    module_length : float
        L, two cells' height [mm].
    deflection, force, angle, moment : ndarray, shape (S,)
        Per step: the middle polygon's centre deflection [mm], the summed reaction [N],
        delta [rad] and M [N*m].
    iterations, negative_eigenvalues : ndarray of int, shape (S,)
    completed : bool
        False if an increment failed (``message`` says which and why); the fits then use
        the increments that converged.
    num_free_dofs : int
    final_displacement : ndarray, shape (N, 3)
        Every node's displacement at the last converged step [mm] (empty if none), in the
        node order of ``kresling_specimen(design, [state] * cells)``.
    target_deflection : float
        The drive's full travel [mm] (``deflection``, or ``L tan(deflection_angle)``).

    Notes
    -----
    A run that stopped early (``completed`` False) is *partial*: ``stiffness`` is fitted to
    the increments that converged, ``travel_fraction`` of the drive; its ``repr`` says so.
    """

    design: Design
    state: int
    stiffness: float
    stiffness_intercept: float
    intercept: float
    module_length: float
    deflection: np.ndarray
    force: np.ndarray
    angle: np.ndarray
    moment: np.ndarray
    iterations: np.ndarray
    negative_eigenvalues: np.ndarray
    completed: bool
    message: str
    num_free_dofs: int
    final_displacement: np.ndarray = None
    target_deflection: float = float("nan")

    @classmethod
    def _from_core(cls, core, **values) -> "BendingResult":
        """Read the C++ core's result (``kresling._core.analyses.BendingResult``): every field
        of this class not given in ``values`` is one of its properties."""
        for f in fields(cls):
            if f.name not in values:
                value = getattr(core, f.name)
                values[f.name] = value.reshape(-1, 3) if f.name == "final_displacement" else value
        return cls(**values)

    def __repr__(self) -> str:
        status = "" if self.completed else (f", PARTIAL: stopped at {self.travel_fraction:.0%} "
                                            f"of the travel ({self.message})")
        return (f"BendingResult({self.design!r}, {self.state_name}, K_B = "
                f"{self.stiffness:.6g} N*m/rad{status})")

    @property
    def partial(self) -> bool:
        """True if the run stopped before the end of its travel (the values are fitted to the
        part that converged)."""
        return not self.completed

    @property
    def travel_fraction(self) -> float:
        """Fraction of the drive's travel reached (1 for a completed run; 0 if no increment
        converged)."""
        reached = abs(self.deflection[-1]) if len(self.deflection) else None
        return travel_fraction(self.completed, reached, self.target_deflection)

    @property
    def state_name(self) -> str:
        return "extended" if self.state == 1 else "contracted"

    @property
    def stable(self) -> bool:
        """True if no increment ended on an equilibrium with a negative stiffness direction
        (every step's free tangent positive definite, or its inertia unknown)."""
        return bool((self.negative_eigenvalues <= 0).all())


@dataclass(frozen=True)
class BendingComparison:
    """K_B in both states and the ratio K_ext / K_con (thesis eqn 23)."""

    extended: BendingResult
    contracted: BendingResult

    @property
    def ratio(self) -> float:
        return self.extended.stiffness / self.contracted.stiffness

    @property
    def partial(self) -> bool:
        """True if either run stopped early (then so is the ratio)."""
        return self.extended.partial or self.contracted.partial

    def __repr__(self) -> str:
        stopped = [f"{r.state_name} stopped at {r.travel_fraction:.0%}"
                   for r in (self.extended, self.contracted) if r.partial]
        status = f", PARTIAL: {'; '.join(stopped)}" if stopped else ""
        return (f"BendingComparison({self.extended.design!r}, K_ext = "
                f"{self.extended.stiffness:.6g}, K_con = {self.contracted.stiffness:.6g} "
                f"N*m/rad, ratio {self.ratio:.6g}{status})")

    @property
    def completed(self) -> bool:
        return self.extended.completed and self.contracted.completed


def protocol_settings(protocol, deflection=None, deflection_angle=None, steps=None) -> dict:
    """A protocol's preset (:data:`PROTOCOLS`) with overrides, each checked for its type:
    ``deflection`` [mm] and ``deflection_angle`` [rad] finite numbers, ``steps`` an integer
    (ranges are the core's to check)."""
    if not isinstance(protocol, str) or protocol not in PROTOCOLS:
        raise ValueError(f"protocol = {show(protocol)} is invalid: must be one of "
                         f"{sorted(PROTOCOLS)}")
    preset = dict(PROTOCOLS[protocol])
    if deflection is not None:
        preset.update(deflection=as_finite_real("deflection", deflection), deflection_angle=0.0)
    if deflection_angle is not None:
        preset.update(deflection_angle=as_finite_real("deflection_angle", deflection_angle))
    if steps is not None:
        preset["steps"] = as_integer("steps", steps, minimum=1)
    return preset


#: The adaptive increments' error target of each protocol (relative to the largest drive
#: force): the 5 mm protocol's 350 samples at 1e-9 (within 1.3e-9 of fixed steps on the
#: Table 3 designs); the 0.001 rad protocol's ten at 1e-8, where the estimate is far from
#: sharp: its samples come within 3.5e-9 of fixed steps on the Table 3 designs and 3.0e-9 on
#: 240 random designs of the thesis's grid (K_B within 9.4e-10), at either target, while 1e-9
#: takes more increments than fixed steps' own cost.
ADAPTIVE_TOLERANCE = {"5mm": 1e-9, "0.001rad": 1e-8}


def adaptive_by_default(protocol, extrapolation) -> bool:
    """Whether a bending test follows its path in adaptive increments unless told: for both
    protocols (5 mm: 2-11 times faster on the Table 3 designs, side by side; 0.001 rad:
    1.3-1.4 times on 240 random designs of the thesis's grid), not with ``extrapolation=0``
    (MERLIN2's Newton sequence, increment for increment)."""
    return protocol in ADAPTIVE_TOLERANCE and extrapolation != 0


def adaptive_options(protocol, extrapolation, adaptive, solver) -> tuple:
    """``(adaptive, solver)`` of a bending test: the flag by :func:`adaptive_by_default`
    unless given, and the solver options with the protocol's error target
    (:data:`ADAPTIVE_TOLERANCE`) unless ``adaptive_tolerance`` is given."""
    adaptive = adaptive_by_default(protocol, extrapolation) if adaptive is None else adaptive
    if adaptive and protocol in ADAPTIVE_TOLERANCE:
        solver = dict(solver)
        solver.setdefault("adaptive_tolerance", ADAPTIVE_TOLERANCE[protocol])
    return adaptive, solver


class BendingTester:
    """A bending test for one polygon size, reusable across designs (for sweeps).

    The specimen's topology, the sparsity pattern and the symbolic factorisation are built
    once; each :meth:`run` only places the nodes and solves.

    Parameters
    ----------
    n : int
        Sides of the polygon, even: the pins need opposite vertices (see
        :func:`require_even_n` for why odd n cannot be tested).
    protocol : {"5mm", "0.001rad"}, optional
        Presets of ``deflection``, ``deflection_angle`` and ``steps`` (:data:`PROTOCOLS`).
    deflection : float, optional
        Transverse motion of the middle polygon [mm].
    deflection_angle : float, optional
        Drive to this deflection angle instead, ``L tan(angle)`` [rad].
    steps : int, optional
    cells : int, default 4
        Even; the load acts on the middle polygon. The specimen's ``(cells + 1) (n + 1)``
        nodes are at most ``MAX_BENDING_NODES`` (20,000; the thesis's has 55).
    parameters : SpecimenParameters, optional
        Stiffness assignment (the thesis's by default).
    extrapolation : {0, 1, 2, 3}, default 2
        Starting guess of each increment (see ``solve_displacement_control``): 2 converges
        in about one Newton iteration per increment to the same equilibria as MERLIN2's 0.
    adaptive : bool, optional
        Follow the path between the protocol's samples in increments chosen by an error
        estimate (``solve_displacement_control``'s ``adaptive``: the sampled drive force
        agrees with fixed steps to a few 1e-9 of its largest value; the error target is the
        protocol's, :data:`ADAPTIVE_TOLERANCE`, unless ``adaptive_tolerance`` is given). By
        default on for both protocols ("5mm": 2-11 times faster on the Table 3 designs;
        "0.001rad": 1.3-1.4 times) and off with ``extrapolation=0`` (MERLIN2's Newton
        sequence, increment for increment). An adaptive run that stops before the end of
        its travel is run again in fixed steps, so it never completes less of the path than
        fixed steps would.
    **solver
        Other options of ``solve_displacement_control`` (tolerance, max_iterations, ...).
    """

    def __init__(self, n, protocol="5mm", *, deflection=None, deflection_angle=None, steps=None,
                 cells=4, parameters=None, extrapolation=2, adaptive=None, **solver):
        preset = protocol_settings(protocol, deflection, deflection_angle, steps)
        adaptive, solver = adaptive_options(protocol, extrapolation, adaptive, solver)
        self.n = require_even_n(as_integer("n", n, minimum=3))
        self.parameters = parameters or SpecimenParameters()
        self.settings = dict(preset, cells=as_integer("cells", cells))
        options = displacement_control_options(extrapolation=extrapolation, adaptive=adaptive,
                                               **solver)
        self._core = _core.analyses.BendingTest(
            self.n, preset["deflection"], preset["deflection_angle"], preset["steps"],
            self.settings["cells"], self.parameters.to_core(), options)

    def run(self, design: Design, state) -> BendingResult:
        """Bend ``design`` (same n) in ``state`` (0/1 or "contracted"/"extended")."""
        design = as_design(design)
        state = state_index(state)
        if design.n != self.n:
            raise ValueError(f"design.n = {design.n} is invalid: this tester is for n = {self.n}")
        core = self._core.run(design._core, state)
        target = self.settings["deflection"] if self.settings["deflection_angle"] == 0 else \
            core.module_length * np.tan(self.settings["deflection_angle"])
        return BendingResult._from_core(core, design=design, state=state,
                                        target_deflection=float(target))

    def run_both_states(self, designs) -> list:
        """K_B of many designs (this tester's n) in both states, in one call to the core.

        What a sweep's K_B-ratio metric reads, without the full :class:`BendingResult` of
        each run: the values are those of ``run(design, 1)`` and ``run(design, 0)``, bit for
        bit, the per-design overhead of two calls and their results is saved, and the GIL
        is released for the whole list.

        Parameters
        ----------
        designs : sequence of (lam, Lc, R)
            Angle ratio, contracted height [mm] and radius [mm] of each design.

        Returns
        -------
        list
            Per design ``(K_ext, K_con, iterations, failures)``: K_B of each state
            [N*m/rad] (fitted to the converged increments if a run stopped early), Newton
            iterations summed over both runs, and the runs that stopped early as
            ``"extended: <why>"`` / ``"contracted: <why>"`` (empty if both completed);
            ``None`` where the design or a run raised (call :meth:`run` on it for the error).
        """
        rows = [(float(lam), float(Lc), float(R)) for lam, Lc, R in designs]
        out = []
        for pair in self._core.run_both_states(rows):
            if pair is None:
                out.append(None)
                continue
            k_ext, k_con, iterations, ext_done, ext_message, con_done, con_message = pair
            failures = [f"{name}: {message}" for name, done, message in
                        (("extended", ext_done, ext_message),
                         ("contracted", con_done, con_message)) if not done]
            out.append((k_ext, k_con, int(iterations), failures))
        return out


def bending_test(design: Design, state, protocol="5mm", **options) -> BendingResult:
    """Run the three-point bending test on ``design`` in one state.

    Parameters
    ----------
    design : Design
    state : {0, 1, "contracted", "extended"}
    protocol : {"5mm", "0.001rad"}
        The thesis's Table 3 runs or its parametric study (:data:`PROTOCOLS`).
    **options
        Overrides: ``deflection`` [mm], ``deflection_angle`` [rad], ``steps``, ``cells``,
        ``parameters`` (SpecimenParameters), solver options (see :class:`BendingTester`).

    Returns
    -------
    BendingResult

    Raises
    ------
    ValueError
        For odd n (the pins need opposite vertices), a deflection that is zero or as large
        as the polygon's radius, an odd cell count, or bad options.

    Examples
    --------
    >>> from kresling import Design
    >>> r = bending_test(Design(8, 0.8, 30), "extended")
    >>> round(r.stiffness, 4)    # N*m/rad; MERLIN2: 2.797835, thesis: 2.79
    2.7978
    """
    design = as_design(design)
    return BendingTester(design.n, protocol, **options).run(design, state)


def bending_stiffness(design: Design, protocol="5mm", **options) -> BendingComparison:
    """K_B in both states and their ratio (see :func:`bending_test` for the options)."""
    design = as_design(design)
    tester = BendingTester(design.n, protocol, **options)
    return BendingComparison(extended=tester.run(design, 1), contracted=tester.run(design, 0))
