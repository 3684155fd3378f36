"""The linearised (infinitesimal) bending stiffness: the Schenk-Guest model of Appendix A.

At a stable state every element is stress-free, so the tangent stiffness there is the linear
bar-and-hinge model ``K = C^T diag(EA/L) C + J^T diag(k L0) J``. The bending test's
supports and load are imposed on it as linear constraints, and the stiffness seen by a
uniform unit motion of the middle polygon is its Schur complement (every other DOF free):

    F = e^T (K_pp - K_pf K_ff^-1 K_fp) e        [N/mm]
    K_B = F L^2 1e-3                           [N*m/rad]

with the conversions of the nonlinear test, ``M = F y L 1e-3`` and ``delta = y / L`` (in the
limit y -> 0), L the module length. It agrees with the nonlinear 0.001 rad protocol to
about 1e-5 (the geometric nonlinearity at that angle, second order in it: 1e-7 at 1e-4 rad)
and costs one factorisation: the C++ core computes it (about 0.4 ms for n = 10) without
holding the GIL, so a sweep's threads run designs in parallel. F cancels (e^T K_pp e is up
to ~1e4 F, the bars being 1e5 times stiffer than the hinges), which leaves K_B determined to
~1e-11 relative by the rounding of the tangent's entries; the core refines its solve once.

The bending axis can be turned by an angle ``beta`` about the specimen's axis: the middle
polygon then moves along ``(-sin beta, cos beta, 0)`` (the nodes stay free perpendicular to
it and in z), and each end is pinned at its centre and at the two points where the line at
``beta`` crosses its perimeter, a point on an edge being held by fixing the weighted mean
``(1 - s) u_j + s u_{j+1}`` of the edge's nodes (a vertex when the line meets one). At
``beta = 0`` these are the nonlinear test's supports: vertices 0 and n/2 and the centre.
``pin_offset`` turns the pin line further, away from perpendicular to the load.
"""

from __future__ import annotations

import math

from kresling import _core
from kresling._validation import as_finite_real, as_integer
from kresling.analyses.bending import require_even_n
from kresling.geometry import Design, as_design, state_index
from kresling.model.kresling_specimen import SpecimenParameters

__all__ = ["LinearBendingTester", "linear_bending_stiffness"]



class LinearBendingTester:
    """The linearised bending test for one polygon size, reusable across designs.

    Parameters
    ----------
    n : int
        Sides of the polygon (even, as in the nonlinear test).
    cells : int, default 4
        Even; the load acts on the middle polygon. The specimen's ``(cells + 1) (n + 1)``
        nodes are at most ``MAX_BENDING_NODES`` (20,000; the thesis's has 55).
    parameters : SpecimenParameters, optional
        Stiffness assignment (the thesis's by default).

    Raises
    ------
    ValueError
        For odd n or a bad cell count.
    """

    def __init__(self, n, *, cells=4, parameters=None):
        n, cells = as_integer("n", n), as_integer("cells", cells)
        if n < 4 or n % 2:
            require_even_n(n)   # odd: says why
            raise ValueError(f"n = {n!r} is invalid: must be even and >= 4 for the bending test")
        if cells < 2 or cells % 2:
            raise ValueError(f"cells = {cells!r} is invalid: must be an even number >= 2 (the "
                             "load acts on the middle polygon)")
        if (cells + 1) * (n + 1) > _core.analyses.MAX_BENDING_NODES:
            raise ValueError(f"cells = {cells} is invalid for n = {n}: the specimen would have "
                             f"(cells + 1) (n + 1) = {(cells + 1) * (n + 1)} nodes; must have "
                             f"at most {_core.analyses.MAX_BENDING_NODES}")
        self.n, self.cells = n, cells
        self.parameters = parameters or SpecimenParameters()
        self._core = _core.analyses.LinearBendingTest(n, cells, self.parameters.to_core())

    def run(self, design: Design, state, *, angle=0.0, pin_offset=0.0) -> float:
        """K_B of ``design`` in ``state`` [N*m/rad].

        Parameters
        ----------
        design : Design
            Same n as the tester.
        state : {0, 1, "contracted", "extended"}
        angle : float
            Bending axis angle beta [rad]: load and pin line turned together.
        pin_offset : float
            Further turn of the pin line alone [rad] (0: perpendicular to the load).

        Raises
        ------
        ValueError
            For bad input, a flat cell (Lc = 0 contracted), or a design whose condensed
            stiffness is not a positive number: the free DOFs form a mechanism, or the tangent
            is singular to working precision (an extreme shape, say Lc / R = 1e6). Never a
            bare NaN.
        """
        design = as_design(design)
        state = state_index(state)
        if design.n != self.n:
            raise ValueError(f"design.n = {design.n} is invalid: this tester is for n = {self.n}")
        angle = as_finite_real("angle", angle)
        pin_offset = as_finite_real("pin_offset", pin_offset)
        # The C++ core checks the state as the nonlinear test does (Lc > 0 when contracted).
        stiffness, force, cancelled = self._core.run(design._core, state, float(angle),
                                                     float(pin_offset))
        # F = e^T K_pp e - (a non-negative term) for a positive definite free block: a value
        # outside (0, e^T K_pp e] is rounding noise of a nearly singular tangent.
        if not (math.isfinite(force) and 0 < force <= cancelled):
            raise ValueError(
                f"design = {design!r} has no linearised K_B in the "
                f"{'extended' if state else 'contracted'} state: the condensed stiffness is "
                f"{float(force)!r}, must be > 0; the free DOFs form a mechanism, or the tangent "
                f"is singular to working precision (Lc / R = {design.Lc / design.R:.3g})")
        return float(stiffness)


def linear_bending_stiffness(design: Design, state, *, parameters=None, angle=0.0,
                             pin_offset=0.0, cells=4) -> float:
    """The linearised bending stiffness K_B [N*m/rad] (see :class:`LinearBendingTester`).

    Examples
    --------
    >>> from kresling import Design
    >>> round(linear_bending_stiffness(Design(8, 0.8, 30), "extended"), 4)  # 0.001 rad: 2.7560
    2.756
    """
    design = as_design(design)
    return LinearBendingTester(design.n, cells=cells, parameters=parameters).run(
        design, state, angle=angle, pin_offset=pin_offset)
