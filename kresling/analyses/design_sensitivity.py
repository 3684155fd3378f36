"""Exact derivatives of a Kresling cell's bending stiffness, snap force and energy barrier
with respect to its design: lambda, Lc, R, the facet sheet's thickness and the crease
stiffness kf.

Each test (the three-point bending test in each state, the snap-through test) is run once
with its whole path kept and differentiated through the factorised tangent
(:func:`kresling.solvers.path_sensitivity`): the snap-through test's every increment, the
bending test's knots (it runs in adaptive increments, its samples read off Hermite curves
between them, and so are their derivatives; docs/sensitivities.md), with each design variable
seen through the specimen's construction (:class:`kresling.solvers.Direction`: how the
node positions, the bars' areas and moduli, the hinges' stiffnesses and the drive move per
unit of it, from the C++ core's chain rule). The tests' read-outs (K_B, the least-squares
slope of the moment on the angle; the snap force, a parabola's peak; the energy barrier, a
cubic Hermite interpolation at the force's zero) are differentiated as the formulas they
are, by forward-mode arithmetic on (value, gradient) pairs.

What ``thickness`` means: the specimen has no thickness of its own (its stiffnesses are the
thesis's ratios to kf); its derivative is taken at the thesis's 0.25 mm facet sheet with
the bars' areas proportional to the thickness and the facets' bending (the polygon spokes'
hinges) to its cube, the creases unchanged (docs/sensitivities.md).

The derivatives are those of the discretised tests: the same increments, the same fit. A
quantity read where the path has a kink in its sampling (the snap force's peak moving to
another increment) has a derivative only on each side of it.

The runs that are differentiated compute the hinges' angles exactly (atan2) whatever
``hinge_angle`` the parameters name: MERLIN2's arccosine, which the thesis's runs use, is
rounded by up to ~1e-8 rad near flat (the polygon spokes), which stops Newton well short of
the 1e-10 mm a derivative needs. The two models' results agree to rounding (K_B to 1e-13
relative on the thesis's designs).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from kresling import _core
from kresling.analyses.bending import ADAPTIVE_TOLERANCE, protocol_settings, require_even_n
from kresling.analyses.snap_through import DEFAULT_STEPS
from kresling.geometry import Design, as_design, state_index
from kresling.model.kresling_specimen import SpecimenParameters
from kresling.model.model import Model
from kresling.solvers.displacement_control import solve_displacement_control
from kresling.solvers.sensitivity import Direction, path_sensitivity

__all__ = ["DESIGN_VARIABLES", "SPECIMEN_VARIABLES", "GRADIENT_QUANTITIES", "DesignGradient",
           "bending_gradient", "bending_pair_gradient", "bending_force_gradient",
           "snap_through_gradient", "design_gradient", "checked_variables"]

#: The design variables, in the order results list them.
DESIGN_VARIABLES = ("lam", "Lc", "R", "thickness", "kf")
#: What a derivative may be taken by: the design variables and the bars' modulus over kf
#: (``SpecimenParameters.modulus_factor``, a material's ratio that a fit may seek).
SPECIMEN_VARIABLES = DESIGN_VARIABLES + ("modulus_factor",)
#: The quantities :func:`design_gradient` differentiates.
GRADIENT_QUANTITIES = ("kb_ratio", "kb_extended", "kb_contracted", "snap_force",
                       "energy_barrier")
#: Newton's tolerance on the correction [mm] of the runs that are differentiated: far below
#: the tests' default (1e-6), so that a derivative is that of a converged equilibrium.
TOLERANCE = 1e-10


class _Dual:
    """A value and its gradient over the design variables: forward-mode arithmetic for the
    tests' read-outs (a handful of scalar formulas)."""

    __slots__ = ("value", "grad")

    def __init__(self, value, grad):
        self.value = float(value)
        self.grad = np.asarray(grad, dtype=float)

    @staticmethod
    def lift(x, size):
        return x if isinstance(x, _Dual) else _Dual(x, np.zeros(size))

    def _other(self, x):
        return _Dual.lift(x, self.grad.size)

    def __add__(self, x):
        x = self._other(x)
        return _Dual(self.value + x.value, self.grad + x.grad)

    __radd__ = __add__

    def __sub__(self, x):
        x = self._other(x)
        return _Dual(self.value - x.value, self.grad - x.grad)

    def __rsub__(self, x):
        return self._other(x) - self

    def __neg__(self):
        return _Dual(-self.value, -self.grad)

    def __mul__(self, x):
        x = self._other(x)
        return _Dual(self.value * x.value, self.grad * x.value + self.value * x.grad)

    __rmul__ = __mul__

    def __truediv__(self, x):
        x = self._other(x)
        return _Dual(self.value / x.value,
                     (self.grad * x.value - self.value * x.grad) / (x.value * x.value))

    def __rtruediv__(self, x):
        return self._other(x) / self


def _atan2(y: _Dual, x: _Dual) -> _Dual:
    r2 = y.value * y.value + x.value * x.value
    return _Dual(math.atan2(y.value, x.value), (x.value * y.grad - y.value * x.grad) / r2)


def _duals(values, grads):
    return [_Dual(v, g) for v, g in zip(values, grads)]


def _directions(specimen, design, states, chirality, parameters, variables, prescribed,
                drive_rate):
    """One Direction per design variable: dX/dv, the columns' d theta/dv and the drive's
    d/dv (``drive_rate[v]`` times the prescribed motion: the drive is proportional to a
    length of the design)."""
    out = []
    for v in variables:
        dX, darea, dmodulus, dstiffness = _core.model.specimen_design_derivative(
            specimen, design._core, states, chirality, parameters.to_core(), v)
        columns = {name: np.asarray(w) for name, w in (("bars.area", darea),
                                                       ("bars.modulus", dmodulus),
                                                       ("hinges.stiffness", dstiffness))
                   if np.any(w)}
        dX = np.asarray(dX)
        rate = drive_rate.get(v, 0.0)
        out.append(Direction(v, positions=dX if np.any(dX) else None, columns=columns,
                             drive=np.asarray(prescribed) * rate if rate else None))
    return out


def _height_rate(design, state, variable) -> float:
    """d height(state) / dv [mm per unit of v] (0 for the material variables)."""
    if variable not in ("lam", "Lc", "R"):
        return 0.0
    return _core.geometry.state_derivative(design._core, state, variable)[0]


def _exact_angles(parameters) -> SpecimenParameters:
    """The parameters with the hinges' angle computed exactly (see the module's note)."""
    return dataclasses.replace(parameters or SpecimenParameters(), hinge_angle="exact")


def checked_variables(variables, allowed=SPECIMEN_VARIABLES) -> tuple:
    """``variables`` as a tuple, each among ``allowed``; a ValueError names the first that
    is not."""
    variables = tuple(variables)
    for v in variables:
        if v not in allowed:
            raise ValueError(f"variables: {v!r} is invalid: must be among {', '.join(allowed)}")
    if not variables:
        raise ValueError("variables is empty: give at least one of "
                         f"{', '.join(DESIGN_VARIABLES)}")
    return variables


def _solved(model, prescribed, steps, what, adaptive_tolerance=None):
    """The test's path converged to :data:`TOLERANCE`; with ``adaptive_tolerance``, in
    adaptive increments as the bending test runs them, keeping its knots (only those are
    then differentiated)."""
    # Unshifted Newton: the tests' 1e-8 N/mm shift slows convergence to linear on the
    # contracted stacks' softest modes, where the tolerance asks for quadratic.
    adaptive = {} if adaptive_tolerance is None else dict(
        adaptive=True, adaptive_tolerance=adaptive_tolerance, keep_knots=True)
    path = solve_displacement_control(model, prescribed, steps, tolerance=TOLERANCE,
                                      extrapolation=2, shift=0.0, **adaptive)
    if not path.completed:
        raise ValueError(f"the {what} stopped at increment {path.failed_increment} of {steps} "
                         f"({path.message}): its derivative is refused (it would be that of "
                         "a shorter test)")
    return path


def bending_gradient(design: Design, state, protocol="5mm", *, parameters=None,
                     variables=DESIGN_VARIABLES, cells=4, deflection=None,
                     deflection_angle=None, steps=None) -> tuple:
    """K_B of the three-point bending test in one state and its derivatives.

    Parameters
    ----------
    design : Design
        n even (the pins need opposite vertices).
    state : {0, 1, "contracted", "extended"}
    protocol, deflection, deflection_angle, steps, cells
        As for :func:`kresling.analyses.bending_test`.
    parameters : SpecimenParameters, optional
        The thesis's by default.
    variables : sequence of str
        Among :data:`DESIGN_VARIABLES`, and ``"modulus_factor"`` (the bars' modulus over kf).

    Returns
    -------
    (float, dict)
        K_B [N m/rad] (the run's own, Newton converged to :data:`TOLERANCE`) and
        ``{variable: dK_B/dv}`` [N m/rad per unit of v: per mm for Lc, R and thickness,
        per N/rad for kf].

    Raises
    ------
    ValueError
        For a bad design, state or variable, or a run that does not complete.
    """
    variables = checked_variables(variables)
    y, dy, F, dF, L, dL = _bending_run(design, state, protocol, parameters, variables, cells,
                                       deflection, deflection_angle, steps)
    # K_B = sum(theta M) / sum(theta^2), theta = atan2(y, L), M = F L [N m]: the least-squares
    # slope through the origin, differentiated as the formula it is (arrays over the samples).
    theta = np.arctan2(y, L)
    dtheta = (L * dy - np.outer(y, dL)) / (y * y + L * L)[:, None]
    M = F * L * 1e-3
    dM = (dF * L + np.outer(F, dL)) * 1e-3
    xy, xx = theta @ M, theta @ theta
    dxy = theta @ dM + M @ dtheta
    dxx = 2.0 * (theta @ dtheta)
    k = xy / xx
    return k, dict(zip(variables, ((dxy * xx - xy * dxx) / (xx * xx)).tolist()))


def bending_force_gradient(design: Design, state, deflection, steps, *, parameters=None,
                           variables=("kf", "modulus_factor"), cells=4) -> tuple:
    """The bending test's force-deflection curve and its derivatives: what a fit of the
    specimen's stiffnesses to a laboratory record needs.

    Parameters
    ----------
    design : Design
    state : {0, 1, "contracted", "extended"}
    deflection : float
        The middle polygon's largest transverse motion [mm].
    steps : int
        Equal increments to it.
    parameters : SpecimenParameters, optional
    variables : sequence of str
        Among :data:`DESIGN_VARIABLES` and ``"modulus_factor"``.
    cells : int, default 4

    Returns
    -------
    (ndarray (S,), ndarray (S,), ndarray (S, P))
        The deflection at every increment [mm], the force F [N] and dF/dv.
    """
    variables = checked_variables(variables)
    y, _, F, dF, _, _ = _bending_run(design, state, "5mm", parameters, variables, cells,
                                     deflection, None, steps)
    return y, F, dF


def _bending_run(design, state, protocol, parameters, variables, cells, deflection,
                 deflection_angle, steps):
    """One bending run differentiated: the centre's deflection y (S,) [mm] and dy/dv (S, P),
    the force F (S,) [N] and dF/dv (S, P) at every increment, and the module length L [mm]
    and dL/dv (P,)."""
    design = as_design(design)
    state = state_index(state)
    parameters = _exact_angles(parameters)
    require_even_n(design.n)
    settings = protocol_settings(protocol, deflection, deflection_angle, steps)
    n = design.n
    test = _core.analyses.BendingTest(n, settings["deflection"], settings["deflection_angle"],
                                      settings["steps"], cells, parameters.to_core(),
                                      _core.solvers.DisplacementControlOptions())
    specimen, prescribed = test.setup(design._core, state)
    model = Model._from_core(specimen.model)
    chirality = [1 if i % 2 == 0 else -1 for i in range(cells)]
    L = 2.0 * design.height(state)
    dL = np.array([2.0 * _height_rate(design, state, v) for v in variables])
    # Under the angle protocol the drive is L tan(angle): it moves with L.
    rate = ({v: dl / L for v, dl in zip(variables, dL)} if settings["deflection_angle"] else {})
    directions = _directions(specimen, design, [state] * cells, chirality, parameters,
                             variables, prescribed, rate)
    path = _solved(model, prescribed, settings["steps"], f"bending test ({state_name(state)})",
                   ADAPTIVE_TOLERANCE.get(protocol))
    sens = path_sensitivity(model, path, directions)
    centre_y = 3 * ((cells // 2) * (n + 1) + n) + 1
    return (-path.displacement[:, centre_y], -sens.displacement[:, centre_y, :],
            path.constraint_force.sum(axis=1), sens.constraint_force.sum(axis=1), L, dL)


def state_name(state) -> str:
    return "extended" if state == 1 else "contracted"


def _first_local_maximum(x, y):
    """The Newton-form parabola's peak through the first interior sample that is a local
    maximum (as the snap-through test reads it), on duals: (index, peak) or (None, None)."""
    for i in range(1, len(y) - 1):
        if not (y[i].value > y[i - 1].value and y[i].value >= y[i + 1].value):
            continue
        x0, x1, x2 = x[i - 1], x[i], x[i + 1]
        d01 = (y[i] - y[i - 1]) / (x1 - x0)
        d12 = (y[i + 1] - y[i]) / (x2 - x1)
        a = (d12 - d01) / (x2 - x0)
        xv = (x0 + x1) * 0.5 - d01 / (a * 2.0)
        return i, y[i - 1] + d01 * (xv - x0) + a * (xv - x0) * (xv - x1)
    return None, None


def _first_downward_zero(x, y, start):
    for i in range(start + 1, len(y)):
        if y[i - 1].value > 0.0 and y[i].value <= 0.0:
            fraction = y[i - 1] / (y[i - 1] - y[i])
            return i, x[i - 1] + fraction * (x[i] - x[i - 1])
    return None, None


def _hermite(x0, x1, e0, e1, f0, f1, x):
    h = x1 - x0
    t = (x - x0) / h
    t2 = t * t
    t3 = t2 * t
    return ((t3 * 2.0 - t2 * 3.0 + 1.0) * e0 + (t3 - t2 * 2.0 + t) * h * f0
            + (t3 * -2.0 + t2 * 3.0) * e1 + (t3 - t2) * h * f1)


def snap_through_gradient(design: Design, *, parameters=None, variables=DESIGN_VARIABLES,
                          steps=DEFAULT_STEPS) -> dict:
    """The snap force and the energy barrier of the snap-through test and their derivatives.

    Parameters
    ----------
    design : Design
    parameters : SpecimenParameters, optional
    variables : sequence of str
        Among :data:`DESIGN_VARIABLES`.
    steps : int
        Increments from Le to Lc (the test's default).

    Returns
    -------
    dict
        ``{"snap_force": (value [N], {v: derivative}), "energy_barrier": (value [N mm],
        {v: derivative})}``; a value the test does not find (no peak, a monostable cell) is
        NaN with NaN derivatives.
    """
    design = as_design(design)
    variables = checked_variables(variables)
    parameters = _exact_angles(parameters)
    n = design.n
    test = _core.analyses.SnapThroughTest(n, steps, parameters.to_core(),
                                          _core.solvers.DisplacementControlOptions())
    specimen, prescribed = test.setup(design._core)
    model = Model._from_core(specimen.model)
    travel = design.height(1) - design.height(0)
    rate = {v: (_height_rate(design, 1, v) - _height_rate(design, 0, v)) / travel
            for v in variables}
    directions = _directions(specimen, design, [1], [1], parameters, variables, prescribed,
                             rate)
    path = _solved(model, prescribed, steps, "snap-through test")
    sens = path_sensitivity(model, path, directions)
    P = len(variables)
    top_z = 3 * ((n + 1) + n) + 2
    zero = np.zeros((1, P))
    d = _duals(np.r_[0.0, -path.displacement[:, top_z]],
               np.r_[zero, -sens.displacement[:, top_z, :]])
    F = _duals(np.r_[0.0, path.constraint_force.sum(axis=1)],
               np.r_[zero, sens.constraint_force.sum(axis=1)])
    E = _duals(np.r_[0.0, path.energies.sum(axis=1)], np.r_[zero, sens.energy])
    nan = (math.nan, {v: math.nan for v in variables})
    out = {"snap_force": nan, "energy_barrier": nan}
    peak_index, peak = _first_local_maximum(d, F)
    if peak is None:
        return out
    out["snap_force"] = (peak.value, dict(zip(variables, peak.grad.tolist())))
    i, x = _first_downward_zero(d, F, peak_index)
    if i is not None:
        barrier = _hermite(d[i - 1], d[i], E[i - 1], E[i], F[i - 1], F[i], x)
        out["energy_barrier"] = (barrier.value, dict(zip(variables, barrier.grad.tolist())))
    return out


@dataclass(frozen=True)
class DesignGradient:
    """A design's bending stiffnesses, their ratio, snap force and energy barrier, with
    their derivatives.

    Attributes
    ----------
    values : dict
        ``{quantity: value}`` over :data:`GRADIENT_QUANTITIES` (K_B in N m/rad, the snap
        force in N, the energy barrier in N mm; NaN where the test finds none).
    gradient : dict
        ``{quantity: {variable: d quantity / d variable}}``.
    protocol : str
        The bending tests' protocol.
    """

    values: dict
    gradient: dict
    protocol: str

    def as_dict(self) -> dict:
        """``{"values": ..., "gradient": ...}`` with NaN as None (for JSON)."""
        def clean(x):
            return None if isinstance(x, float) and math.isnan(x) else x
        return {"protocol": self.protocol,
                "values": {q: clean(v) for q, v in self.values.items()},
                "gradient": {q: {v: clean(g) for v, g in row.items()}
                             for q, row in self.gradient.items()}}


def design_gradient(design: Design, protocol="5mm", *, parameters=None,
                    variables=DESIGN_VARIABLES, **bending) -> DesignGradient:
    """K_B in both states, the K_B ratio, the snap force and the energy barrier of ``design``
    and their exact derivatives by the design variables.

    Parameters
    ----------
    design : Design
    protocol : {"5mm", "0.001rad"}
        The bending tests' protocol.
    parameters : SpecimenParameters, optional
    variables : sequence of str
        Among :data:`DESIGN_VARIABLES` (default: all five).
    **bending
        ``deflection``, ``deflection_angle``, ``steps``, ``cells`` of the bending tests.

    Returns
    -------
    DesignGradient
    """
    variables = checked_variables(variables)
    both = bending_pair_gradient(design, protocol, parameters=parameters, variables=variables,
                                 **bending)
    snap = snap_through_gradient(design, parameters=parameters, variables=variables)
    runs = dict(both, **snap)
    return DesignGradient(values={q: runs[q][0] for q in GRADIENT_QUANTITIES},
                          gradient={q: runs[q][1] for q in GRADIENT_QUANTITIES},
                          protocol=protocol)


def bending_pair_gradient(design: Design, protocol="5mm", *, parameters=None,
                          variables=DESIGN_VARIABLES, **bending) -> dict:
    """K_B of both states and their ratio with their derivatives: ``{"kb_extended",
    "kb_contracted", "kb_ratio"}`` to ``(value, {variable: derivative})`` (arguments as
    :func:`design_gradient`)."""
    variables = checked_variables(variables)
    k_ext, g_ext = bending_gradient(design, 1, protocol, parameters=parameters,
                                    variables=variables, **bending)
    k_con, g_con = bending_gradient(design, 0, protocol, parameters=parameters,
                                    variables=variables, **bending)
    ratio = _Dual(k_ext, [g_ext[v] for v in variables]) / _Dual(k_con, [g_con[v] for v in variables])
    return {"kb_extended": (k_ext, g_ext), "kb_contracted": (k_con, g_con),
            "kb_ratio": (ratio.value, dict(zip(variables, ratio.grad.tolist())))}
