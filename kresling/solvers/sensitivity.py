"""Exact sensitivities of equilibria and equilibrium paths to the elements' parameters.

A parameter is a column of one element family's table: ``"bars.modulus"``, ``"bars.area"``,
``"bars.rest_length"``, ``"hinges.stiffness"``, ``"hinges.rest_angle"``, ``"hinges.length"``,
``"cables.stiffness"``, ``"cables.rest_length"``, ``"springs.stiffness"``,
``"springs.anchor"``, ``"face_angles.rest_angle"``, ``"face_angles.stiffness"``
(:func:`parameter_names` lists a model's). Named so, a parameter moves every entry of the
column by the same amount (for a column whose entries are equal, the derivative with respect
to their common value); ``"hinges.stiffness[3]"`` is one element's entry; a
:class:`Parameter` with a ``direction`` moves the entries in any fixed ratio (a chain rule
through a calibration, say).

The mathematics (docs/sensitivities.md): at an equilibrium ``f_int(u, p) = f_ext`` with the
held DOFs given, ``K_ff du_f/dp = -df_f/dp`` (one solve per parameter with the factorised
tangent), the held DOFs' forces change by ``df_c/dp + K_cf du_f/dp``, and a scalar
objective's gradient with respect to every element's parameter takes one adjoint solve,
``K_ff lambda = dJ/du_f``, ``dJ/dtheta = dJ/dtheta|_u - lambda^T df_f/dtheta``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

import numpy as np

from kresling import _core
from kresling._validation import as_float_array, show
from kresling.assembly import assemble

__all__ = ["Parameter", "Direction", "parameter_names", "parameter_jacobian", "shape_jacobian",
           "with_parameter",
           "EquilibriumSensitivity", "equilibrium_sensitivity", "equilibrium_gradient",
           "residual_derivative", "energy_derivative", "PathSensitivity", "path_sensitivity"]

_NAME = re.compile(r"^([a-z_]+)\.([a-z_0-9]+)(?:\[(\d+)\])?$")


@dataclass(frozen=True)
class Parameter:
    """One scalar parameter: a direction in one column of a family's table.

    Attributes
    ----------
    family : str
        The element family ("bars", "hinges", ...).
    column : str
        Its parameter column ("modulus", "rest_angle", ...).
    direction : ndarray, shape (m,), or None
        How the column's m entries move per unit of the parameter; None: all by 1.
    entry : int or None
        Only this entry moves (by 1); exclusive with ``direction``.
    name : str
        How results label it (``"bars.modulus"``, ``"hinges.stiffness[3]"``).
    """

    family: str
    column: str
    direction: np.ndarray | None = None
    entry: int | None = None
    name: str = ""

    @classmethod
    def parse(cls, spec) -> "Parameter":
        """A Parameter from ``"family.column"`` or ``"family.column[entry]"``, or itself."""
        if isinstance(spec, Parameter):
            return spec
        match = _NAME.match(spec) if isinstance(spec, str) else None
        if match is None:
            raise ValueError(f"parameter = {show(spec)} is invalid: must be 'family.column' or "
                             "'family.column[entry]' (e.g. 'bars.modulus', "
                             "'hinges.rest_angle[3]') or a Parameter")
        family, column, entry = match.groups()
        return cls(family, column, entry=None if entry is None else int(entry), name=spec)

    @property
    def label(self) -> str:
        return self.name or f"{self.family}.{self.column}"

    def weights(self, entries: int) -> np.ndarray:
        """dtheta/dp over the column's ``entries`` values."""
        if self.entry is not None:
            if not 0 <= self.entry < entries:
                raise ValueError(f"parameter {self.label!r}: entry {self.entry} is out of range "
                                 f"[0, {entries})")
            w = np.zeros(entries)
            w[self.entry] = 1.0
            return w
        if self.direction is None:
            return np.ones(entries)
        w = as_float_array(f"parameter {self.label!r} direction", self.direction)
        if w.shape != (entries,):
            raise ValueError(f"parameter {self.label!r}: direction has shape {w.shape}: must be "
                             f"({entries},), one value per entry of {self.family}.{self.column}")
        return w


@dataclass(frozen=True)
class Direction:
    """A variable seen through the model's construction: how the reference positions, the
    parameter columns and a prescribed motion move per unit of it (the chain rule from a
    design to the model, e.g. a Kresling cell's lambda through its node positions).

    Attributes
    ----------
    name : str
        How results label it.
    positions : ndarray, shape (3N,), or None
        dX/dv of the reference positions [mm per unit]; the rest values that hold the
        reference geometry follow (:func:`shape_jacobian`).
    columns : dict
        ``{"family.column": ndarray (m,)}``: d theta/dv of parameter columns.
    drive : ndarray, shape (3N,), or None
        d/dv of a displacement control's prescribed motion at full travel [mm per unit]
        (step k moves by its fraction of it); only its entries at the imposed DOFs count.
    """

    name: str
    positions: np.ndarray | None = None
    columns: dict = field(default_factory=dict)
    drive: np.ndarray | None = None

    @property
    def label(self) -> str:
        return self.name


def _parse(spec):
    return spec if isinstance(spec, Direction) else Parameter.parse(spec)


def shape_jacobian(model, u):
    """The derivatives of the internal force and the energy with respect to the reference
    positions X at fixed displacement u, the model's rest lengths, hinge lengths and rest
    angles that hold the reference geometry following it (a model built stress-free stays
    so; a fold's target angle stays put).

    Returns
    -------
    force : scipy.sparse.csc_matrix, shape (3N, 3N)
        ``d f_int / dX`` [N/mm].
    energy : ndarray, shape (3N,)
        ``dE/dX`` [N].
    """
    u = _displacement(model, u)
    (data, indices, indptr, shape), energy = _core.assembly.shape_jacobian(model._core, u)
    return _csc((data, indices, indptr, shape)), np.asarray(energy)


def parameter_names(model) -> list:
    """Every ``"family.column"`` the model's families differentiate by, in assembly order."""
    return [f"{family}.{column}"
            for family, columns in _core.assembly.family_parameters(model._core).items()
            for column in columns]


def _displacement(model, u) -> np.ndarray:
    if u is None:
        return np.zeros(model.num_dofs)
    u = as_float_array("u", u).ravel()
    if u.shape != (model.num_dofs,):
        raise ValueError(f"u has {u.size} entries: must have {model.num_dofs} (3 per node)")
    return u


def parameter_jacobian(model, u, parameter):
    """The partial derivatives of the internal force and the stored energy with respect to
    every entry of one parameter column, at fixed positions.

    Parameters
    ----------
    model : kresling.model.Model
    u : array_like, shape (3N,), or None
        Displacement [mm] (None: the reference state).
    parameter : str or Parameter
        The column (an entry or direction, if given, is ignored here: every entry is returned).

    Returns
    -------
    force : scipy.sparse.csc_matrix, shape (3N, m)
        ``d f_int / d theta_j`` [N per unit of the parameter].
    energy : ndarray, shape (m,)
        ``dE / d theta_j`` [N mm per unit of the parameter].

    Raises
    ------
    ValueError
        If the model has no such family or the family no such parameter.
    """
    p = Parameter.parse(parameter)
    u = _displacement(model, u)
    try:
        (data, indices, indptr, shape), energy = _core.assembly.parameter_jacobian(
            model._core, u, p.family, p.column)
    except ValueError as error:
        raise ValueError(f"parameter {p.label!r}: {error}") from None
    return _csc((data, indices, indptr, shape)), np.asarray(energy)


def with_parameter(model, parameter, values):
    """A copy of ``model`` with the column of ``parameter`` set to ``values`` (shape (m,),
    the column's entries in table order): for finite-difference checks and fitting."""
    p = Parameter.parse(parameter)
    tables = {name: {k: np.asarray(v) for k, v in table.items()}
              for name, table in model._core.tables().items()}
    if p.family not in tables:
        raise ValueError(f"parameter {p.label!r}: the model has no element family "
                         f"{p.family!r}: it has {list(tables)}")
    if p.column not in _core.assembly.family_parameters(model._core)[p.family]:
        raise ValueError(f"parameter {p.label!r}: the family {p.family} has no parameter "
                         f"{p.column!r}")
    old = tables[p.family][p.column]
    new = as_float_array("values", values).reshape(old.shape)
    tables[p.family][p.column] = np.ascontiguousarray(new)
    core = _core.model.Model(model._core.nodes, model._core.fixed, tables)
    return type(model)._from_core(core)


class _Resolved:
    """P parameters resolved against one model, once: each as its reference positions' motion
    dX/dp (3N, P) and, per parameter column, the motion of its entries (m, P) - the explicit
    weights plus, for the entries that hold the reference geometry, R_c dX/dp. Then at any
    state the residual's partial derivatives are K dX/dp + sum_c G_c W_c, without forming
    any matrix product of the Jacobians."""

    def __init__(self, model, parameters):
        n, P = model.num_dofs, len(parameters)
        self.positions = np.zeros((n, P))
        self.moves = False
        self.weights = {}
        for j, p in enumerate(parameters):
            if isinstance(p, Direction):
                if p.positions is not None:
                    dX = as_float_array(f"{p.name}: positions", p.positions).ravel()
                    if dX.shape != (n,):
                        raise ValueError(f"{p.name}: positions has {dX.size} entries: must "
                                         f"have {n} (3 per node)")
                    self.positions[:, j] = dX
                    self.moves = True
                for spec, w in p.columns.items():
                    column = Parameter.parse(spec)
                    self._add(model, Parameter(column.family, column.column, direction=w,
                                               name=f"{p.name}: {spec}"), j, P)
            else:
                self._add(model, p, j, P)
        if self.moves:
            for family, columns in _core.assembly.family_parameters(model._core).items():
                for column in columns:
                    R = _csc(_core.assembly.reference_geometry_jacobian(model._core, family,
                                                                         column))
                    if R.nnz:
                        self._weight(f"{family}.{column}", R.shape[0], P)[:] += R @ self.positions

    def _weight(self, key, entries, P):
        if key not in self.weights:
            self.weights[key] = np.zeros((entries, P))
        return self.weights[key]

    def _add(self, model, p, j, P):
        key = f"{p.family}.{p.column}"
        if key not in self.weights:
            force, _ = parameter_jacobian(model, None, p)  # checks the name, gives m
            self.weights[key] = np.zeros((force.shape[1], P))
        W = self.weights[key]
        W[:, j] += p.weights(W.shape[0])

    def residual(self, model, u, state):
        """dF/dp (3N, P) and dE/dp|_u (P,) at u, ``state`` the factorised core object at u
        (its tangent and internal force)."""
        if self.moves:
            dforce = np.asarray(state.tangent_times(self.positions))
            denergy = np.asarray(state.internal_force) @ self.positions
        else:
            dforce = np.zeros_like(self.positions)
            denergy = np.zeros(self.positions.shape[1])
        for key, W in self.weights.items():
            force, energy = parameter_jacobian(model, u, key)
            dforce += force @ W
            denergy += energy @ W
        return dforce, denergy


class _Assembled:
    """The internal force and, when first asked for, the tangent at one state: what
    :meth:`_Resolved.residual` reads of a state that need not be factorised (a singular
    one, at a limit point)."""

    def __init__(self, model, u):
        self._model, self._u = model, u
        self._tangent = None
        self.internal_force = assemble(model, u, stiffness=False).force

    def tangent_times(self, M):
        if self._tangent is None:
            self._tangent = assemble(self._model, self._u).stiffness
        return self._tangent @ M


def _csc(parts):
    # Here, not at the top: a command that never differentiates (kresling bend) does not
    # pay for importing scipy.
    import scipy.sparse as sp

    data, indices, indptr, shape = parts
    return sp.csc_matrix((data, indices, indptr), shape=shape)


def _held_motion(parameters, held_dofs, fraction):
    """d u_c/dp at the held DOFs (C, P): a Direction's drive at this step's fraction; None
    when nothing moves."""
    drives = [p.drive if isinstance(p, Direction) else None for p in parameters]
    if all(d is None for d in drives):
        return None
    out = np.zeros((len(held_dofs), len(parameters)))
    for j, d in enumerate(drives):
        if d is not None:
            out[:, j] = fraction * np.asarray(d, dtype=float).ravel()[held_dofs]
    return out


def _held(model, held) -> np.ndarray:
    held = np.asarray(held if held is not None else [], dtype=np.int64).ravel()
    return held


@dataclass(frozen=True)
class EquilibriumSensitivity:
    """The derivatives of one equilibrium with respect to P parameters.

    Attributes
    ----------
    parameters : tuple of str, length P
    displacement : ndarray, shape (3N, P)
        du/dp [mm per unit of each parameter].
    held_dofs : ndarray of int, shape (C,)
        The supported DOFs (in DOF order), then the held ones in the order given.
    held_force : ndarray, shape (C, P)
        d f_int/dp at the held DOFs: the support reactions' and the held DOFs' forces
        [N per unit].
    energy : ndarray, shape (P,)
        dE/dp of the stored energy along the equilibrium [N mm per unit].
    negative_eigenvalues : int
        Of the free tangent (0: a stable equilibrium).
    """

    parameters: tuple
    displacement: np.ndarray
    held_dofs: np.ndarray
    held_force: np.ndarray
    energy: np.ndarray
    negative_eigenvalues: int


def _factorised(model, u, held):
    try:
        s = _core.solvers.EquilibriumSensitivity(model._core, u, [int(d) for d in held])
    except ValueError as error:
        # The core names what is wrong: a held DOF ("held: DOF 3 is supported") or a motion
        # nothing resists.
        raise ValueError(f"no sensitivity at this state: {error}") from None
    if not s.ok:
        raise ValueError("the tangent at this state is singular (a limit or bifurcation point, "
                         "or a mechanism the supports leave free): it has no derivative")
    return s


def equilibrium_sensitivity(model, u, parameters, *, held=None, load_derivative=None):
    """Direct sensitivity of an equilibrium: one solve per parameter on one factorisation.

    Parameters
    ----------
    model : kresling.model.Model
    u : array_like, shape (3N,)
        A converged equilibrium [mm] (under the supports, the held DOFs and any loads).
    parameters : sequence of str or Parameter, length P
    held : sequence of int, optional
        DOFs held at their values besides the supports (a displacement control's imposed
        DOFs).
    load_derivative : array_like, shape (3N, P), optional
        d f_ext/dp where the applied loads depend on the parameters [N per unit].

    Returns
    -------
    EquilibriumSensitivity

    Raises
    ------
    ValueError
        For an unknown parameter, a held DOF out of range, supported or repeated, or a
        singular tangent (no derivative exists there).
    """
    parameters = tuple(_parse(p) for p in parameters)
    u = _displacement(model, u)
    resolved = _Resolved(model, parameters)
    s = _factorised(model, u, _held(model, held))
    dforce, denergy = resolved.residual(model, u, s)
    dresidual = dforce
    if load_derivative is not None:
        load = as_float_array("load_derivative", load_derivative).reshape(dforce.shape)
        dresidual = dforce - load
    motion = _held_motion(parameters, np.asarray(s.held_dofs, dtype=np.int64), 1.0)
    du = s.displacement(dresidual) if motion is None else s.displacement(dresidual, motion)
    return EquilibriumSensitivity(
        parameters=tuple(p.label for p in parameters), displacement=du,
        held_dofs=np.asarray(s.held_dofs, dtype=np.int64), held_force=s.held_force(dforce, du),
        energy=denergy + np.asarray(s.internal_force) @ du,
        negative_eigenvalues=s.negative_eigenvalues)


def equilibrium_gradient(model, u, objective_gradient, parameters, *, held=None,
                         explicit=None) -> dict:
    """Gradient of a scalar J(u) with respect to every entry of each parameter column by
    one adjoint solve.

    Parameters
    ----------
    model : kresling.model.Model
    u : array_like, shape (3N,)
        A converged equilibrium [mm].
    objective_gradient : array_like, shape (3N,)
        dJ/du at u (its entries at held DOFs are ignored: they do not move).
    parameters : sequence of str
        Parameter columns (``"hinges.rest_angle"``, ...); entries and directions ignored.
    held : sequence of int, optional
        As for :func:`equilibrium_sensitivity`.
    explicit : dict, optional
        dJ/dtheta at fixed u, by column name, where J depends on the parameters directly.

    Returns
    -------
    dict
        ``{"family.column": ndarray (m,)}``: dJ/dtheta_j for every entry j.
    """
    u = _displacement(model, u)
    g = as_float_array("objective_gradient", objective_gradient).ravel()
    if g.shape != (model.num_dofs,):
        raise ValueError(f"objective_gradient has {g.size} entries: must have {model.num_dofs}")
    s = _factorised(model, u, _held(model, held))
    adjoint = np.asarray(s.adjoint(g))
    out = {}
    for spec in parameters:
        p = Parameter.parse(spec)
        label = f"{p.family}.{p.column}"
        force, _ = parameter_jacobian(model, u, p)
        gradient = -(force.T @ adjoint)
        if explicit and label in explicit:
            gradient = gradient + as_float_array(f"explicit[{label!r}]", explicit[label])
        out[label] = gradient
    return out


def residual_derivative(model, u, parameters):
    """The partial derivatives of the internal force and the stored energy with respect to
    P parameters at fixed displacement u, each a parameter column's entries moving in its
    direction or a :class:`Direction` (the reference positions too, and the rest values that
    follow them; a Direction's ``drive`` is not part of them).

    Parameters
    ----------
    model : kresling.model.Model
    u : array_like, shape (3N,)
        Displacement [mm].
    parameters : sequence of str, Parameter or Direction, length P

    Returns
    -------
    force : ndarray, shape (3N, P)
        ``d f_int/dp`` at fixed u [N per unit of each parameter].
    energy : ndarray, shape (P,)
        ``dE/dp`` at fixed u [N mm per unit of each parameter].
    labels : tuple of str, length P
        The parameters' names.
    """
    parameters = tuple(_parse(p) for p in parameters)
    u = _displacement(model, u)
    force, energy = _Resolved(model, parameters).residual(model, u, _Assembled(model, u))
    return force, energy, tuple(p.label for p in parameters)


def energy_derivative(model, u, parameters, *, load_derivative=None) -> np.ndarray:
    """The derivative of an equilibrium's energy with respect to P parameters: the partial
    derivative at fixed displacement, which needs no factorisation (envelope theorem).

    At an equilibrium, the total potential ``Pi = E(u, p) - f_ext . u`` is stationary in
    the free DOFs and the supported ones do not move, so along the equilibrium
    ``dPi/dp = dE/dp|_u - u . d f_ext/dp``: the state's own motion ``du/dp`` drops out.
    Unloaded (a stable state, or the saddle between two), that is the derivative of the
    stored energy itself, as :func:`equilibrium_sensitivity` gives it; loaded, that of the
    total potential. Because nothing is solved, it is defined where the tangent is singular
    too: at a limit point, where the equilibria under the same load exist on one side of p
    only, it is their one-sided derivative.

    Parameters
    ----------
    model : kresling.model.Model
    u : array_like, shape (3N,)
        An equilibrium [mm]. Elsewhere the result is still the partial derivative at fixed
        u, but not the derivative of any equilibrium's energy: the state is not checked.
    parameters : sequence of str, Parameter or Direction, length P
    load_derivative : array_like, shape (3N, P), optional
        d f_ext/dp where the applied loads depend on the parameters [N per unit].

    Returns
    -------
    ndarray, shape (P,)
        dPi/dp [N mm per unit of each parameter].
    """
    u = _displacement(model, u)
    _, denergy, labels = residual_derivative(model, u, parameters)
    if load_derivative is not None:
        load = as_float_array("load_derivative", load_derivative)
        if load.shape != (model.num_dofs, len(labels)):
            raise ValueError(f"load_derivative has shape {load.shape}: must be "
                             f"({model.num_dofs}, {len(labels)}), one column per parameter")
        denergy = denergy - u @ load
    return denergy


@dataclass(frozen=True)
class PathSensitivity:
    """The derivatives of every step of an equilibrium path with respect to P parameters,
    each at the step's own control value (the prescribed motion's fraction, or the load
    factor): the history columns' derivatives.

    Attributes
    ----------
    parameters : tuple of str, length P
    displacement : ndarray, shape (S, 3N, P)
        du/dp per step [mm per unit].
    constraint_force : ndarray, shape (S, C, P)
        The derivative of the path's ``constraint_force`` (the force on the actuator at
        each imposed DOF, or the support reactions) [N per unit].
    energy : ndarray, shape (S, P)
        dE/dp of the total stored energy per step [N mm per unit].
    """

    parameters: tuple
    displacement: np.ndarray
    constraint_force: np.ndarray
    energy: np.ndarray


def _knots(path):
    """The core's form of an adaptive path's knots, or None."""
    k = getattr(path, "knots", None)
    if k is None:
        return None
    return ([float(t) for t in k.t], list(k.displacement), list(k.velocity),
            [int(j) for j in k.step_knot])


def path_sensitivity(model, path, parameters) -> PathSensitivity:
    """Sensitivities along a displacement- or force-controlled path, one factorisation per
    step (per knot for a path in adaptive increments that kept its knots).

    An elastic path has no history: each step is an equilibrium at its control value, so its
    derivative is that equilibrium's (the direct differentiation of the path at fixed
    control). Under displacement control the imposed DOFs are held (the prescribed motion
    does not depend on the parameters); under force control (``path.constraint_dofs`` are
    supports) the loads are fixed at the step's load factor.

    A path in adaptive increments with ``keep_knots=True`` read its steps off cubic Hermite
    curves between converged points (knots); its derivatives are those of the same curves,
    through the knots' derivatives and their rates along the path (docs/sensitivities.md,
    'Adaptive paths'), so only the knots are factorised.

    Parameters
    ----------
    model : kresling.model.Model
        The model the path was solved on.
    path : kresling.solvers.PathResult
        A path from :func:`~kresling.solvers.solve_displacement_control`,
        :func:`~kresling.solvers.solve_force_control` or
        :func:`~kresling.solvers.solve_mgdcm`; it must have completed.
    parameters : sequence of str or Parameter, length P

    Raises
    ------
    ValueError
        If the path did not complete (its gradient would be that of another problem), or at
        a step whose tangent is singular (a limit or bifurcation point on the path).
    """
    if not path.completed:
        raise ValueError(f"path did not complete ({path.message}): its derivatives are refused "
                         "(they would be those of a path that stopped early)")
    parameters = tuple(_parse(p) for p in parameters)
    supports = set(np.flatnonzero(model.fixed.ravel()).tolist())
    dofs = np.asarray(path.constraint_dofs, dtype=np.int64)
    force_control = bool(len(dofs)) and all(int(d) in supports for d in dofs)
    held = np.zeros(0, dtype=np.int64) if force_control else dofs
    sign = 1.0 if force_control else -1.0  # displacement control reports -f_int
    n = model.num_dofs
    resolved = _Resolved(model, parameters)
    columns = [(*key.split("."), W) for key, W in resolved.weights.items()]
    positions = resolved.positions if resolved.moves else np.zeros((n, 0))
    drives = [p.drive if isinstance(p, Direction) else None for p in parameters]
    drive = np.zeros((n, 0))
    if not force_control and any(d is not None for d in drives):
        drive = np.column_stack([np.zeros(n) if d is None else
                                 as_float_array("drive", d).ravel() for d in drives])
    try:
        # One workspace and one symbolic analysis for the whole path, in the core.
        held_dofs, du_all, held_force, de_all = _core.solvers.path_sensitivity(
            model._core, list(path.displacement), [float(t) for t in path.load_factor],
            [int(d) for d in held], positions, columns, drive, _knots(path))
    except (ValueError, RuntimeError) as error:
        raise ValueError(f"no sensitivity along this path: {error}") from None
    order = {int(d): i for i, d in enumerate(held_dofs)}
    dc_all = sign * held_force[:, [order[int(d)] for d in dofs], :]
    return PathSensitivity(parameters=tuple(p.label for p in parameters), displacement=du_all,
                           constraint_force=dc_all, energy=de_all)
