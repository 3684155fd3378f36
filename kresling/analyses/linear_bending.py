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
and costs one sparse solve.

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

import numpy as np
import scipy.sparse
import scipy.sparse.linalg

from kresling import _core
from kresling._validation import as_finite_real, as_integer
from kresling.analyses.bending import require_even_n
from kresling.assembly import tangent_stiffness
from kresling.geometry import Design, as_design, state_index
from kresling.model.kresling_specimen import SpecimenParameters, kresling_specimen

__all__ = ["LinearBendingTester", "linear_bending_stiffness"]


#: A pin this close to a vertex (in the edge parameter s) is the vertex.
_AT_VERTEX = 1e-12


def _edge_point(n: int, angle: float):
    """Where the ray at ``angle`` from a regular n-gon's centre (vertex 0 at angle 0) meets
    its perimeter: ``(j, j + 1 mod n, s)``, the point ``(1 - s) x_j + s x_{j+1}``."""
    sector = 2 * math.pi / n
    phi = angle % (2 * math.pi)
    j = int(phi // sector) % n
    psi = phi - j * sector
    s = math.sin(psi) / (math.sin(psi) + math.sin(sector - psi))
    return j, (j + 1) % n, min(max(s, 0.0), 1.0)


class LinearBendingTester:
    """The linearised bending test for one polygon size, reusable across designs.

    Parameters
    ----------
    n : int
        Sides of the polygon (even, as in the nonlinear test).
    cells : int, default 4
        Even; the load acts on the middle polygon.
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
        if (cells + 1) * (n + 1) > _core.model.MAX_SPECIMEN_NODES:
            raise ValueError(f"cells = {cells} is invalid for n = {n}: the specimen would have "
                             f"(cells + 1) (n + 1) = {(cells + 1) * (n + 1)} nodes; must have "
                             f"at most {_core.model.MAX_SPECIMEN_NODES}")
        self.n, self.cells = n, cells
        self.parameters = parameters or SpecimenParameters()

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
        # The nonlinear test's check of the design in this state (Lc > 0 when contracted).
        _core.analyses.check_bending_state(design._core, state)
        specimen = kresling_specimen(design, [state] * self.cells, parameters=self.parameters)
        T, imposed = self._transformation(specimen, float(angle), float(pin_offset))
        K = (T.T @ tangent_stiffness(specimen.model) @ T).tocsc()
        free = np.setdiff1d(np.arange(K.shape[0]), imposed)
        e = np.ones(len(imposed))
        free_rows = K[free]  # sliced once, for both blocks
        Kfp_e = free_rows[:, imposed] @ e
        try:
            # Sparse LU (SuperLU): a dense Cholesky of this size is slower under BLAS threads.
            u_free = scipy.sparse.linalg.splu(free_rows[:, free].tocsc()).solve(Kfp_e)
        except RuntimeError:                 # "Factor is exactly singular"
            u_free = np.full(len(free), math.nan)
        force = e @ (K[imposed][:, imposed] @ e) - Kfp_e @ u_free
        if not (math.isfinite(force) and force > 0):
            raise ValueError(
                f"design = {design!r} has no linearised K_B in the "
                f"{'extended' if state else 'contracted'} state: the condensed stiffness is "
                f"{float(force)!r}, must be > 0; the free DOFs form a mechanism, or the tangent "
                f"is singular to working precision (Lc / R = {design.Lc / design.R:.3g})")
        L = 2.0 * design.height(state)
        return float(force * L * L * 1e-3)

    def _transformation(self, specimen, angle, pin_offset):
        """``u = T q`` from the generalized coordinates q to all DOFs, and the columns of q
        that are imposed (the middle nodes' motion along the load)."""
        n, cells = self.n, self.cells
        columns = {}                     # DOF -> [(column, coefficient)]
        count = 0

        def new_column():
            nonlocal count
            count += 1
            return count - 1

        held, slaves = set(), {}         # slave node -> (master node, coefficient)
        for level in (0, cells):
            held.add(specimen.centre(level))
            for side in (0.0, math.pi):
                pin = angle + pin_offset + side - specimen.level_angle[level]
                j, j1, s = _edge_point(n, pin)
                a, b = specimen.node(level, j), specimen.node(level, j1)
                if s <= _AT_VERTEX:
                    held.add(a)
                elif s >= 1 - _AT_VERTEX:
                    held.add(b)
                elif s >= 0.5:           # eliminate the node of the larger weight
                    slaves[b] = (a, -(1 - s) / s)
                else:
                    slaves[a] = (b, -s / (1 - s))
        middle = set(specimen.level_nodes(cells // 2).tolist())
        imposed = []
        c, s_ = math.cos(angle), math.sin(angle)
        for node in range(specimen.model.num_nodes):
            if node in held or node in slaves:
                continue
            if node in middle:
                along, across = new_column(), new_column()
                imposed.append(along)
                columns[3 * node] = [(along, -s_), (across, c)]
                columns[3 * node + 1] = [(along, c), (across, s_)]
                columns[3 * node + 2] = [(new_column(), 1.0)]
            else:
                for k in range(3):
                    columns[3 * node + k] = [(new_column(), 1.0)]
        for slave, (master, weight) in slaves.items():
            for k in range(3):
                columns[3 * slave + k] = [(col, weight * v) for col, v in columns[3 * master + k]]
        rows, cols, values = zip(*((dof, col, value) for dof, entries in columns.items()
                                   for col, value in entries))
        T = scipy.sparse.csr_matrix((values, (rows, cols)), shape=(specimen.model.num_dofs, count))
        return T, np.array(imposed)


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
