"""The specimen's stiffnesses fitted to bending records on the full bar-and-hinge model.

The closed-form fits (:mod:`kresling.fits`) read a stiffness off each record by regression
beside the model. Here the model itself is fitted: the crease stiffness kf and the bars'
modulus over it (``modulus_factor``) that make the three-point bending test's
force-deflection curves, in whatever designs and states were recorded, closest to the
records in least squares,

    min  sum_records sum_k ((F_model(y_k) - F_k) / max |F|)^2      over ln kf, ln modulus_factor,

each record weighted by its largest force (so that a soft contracted state counts as much as
a stiff extended one). The Jacobian is exact (:func:`bending_force_gradient`: every
increment of each run differentiated); SciPy's trust-region least squares does the rest.
The model's curve is sampled at equal increments to the record's largest deflection and
read at the record's deflections by linear interpolation (exact where they coincide).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from kresling._validation import as_float_array, as_integer
from kresling.analyses.design_sensitivity import (bending_force_gradient, bending_gradient,
                                                checked_variables)
from kresling.geometry import Design, as_design, state_index
from kresling.model.kresling_specimen import SpecimenParameters

__all__ = ["BendingRecord", "StiffnessFit", "fit_specimen_stiffness", "fit_bending_stiffnesses",
           "record_from_model"]

#: The specimen parameters a fit may seek.
FIT_VARIABLES = ("kf", "modulus_factor")


@dataclass(frozen=True)
class BendingRecord:
    """A bending test's force-deflection record.

    Attributes
    ----------
    design : Design
    state : int
        0 contracted, 1 extended.
    deflection : ndarray, shape (K,)
        The middle polygon's transverse motion [mm], increasing, positive.
    force : ndarray, shape (K,)
        The force on it [N].
    """

    design: Design
    state: int
    deflection: np.ndarray
    force: np.ndarray

    def __post_init__(self):
        object.__setattr__(self, "design", as_design(self.design))
        object.__setattr__(self, "state", state_index(self.state))
        y = as_float_array("deflection", self.deflection).ravel()
        f = as_float_array("force", self.force).ravel()
        if y.size == 0 or y.shape != f.shape:
            raise ValueError(f"deflection and force have {y.size} and {f.size} values: must be "
                             "equally many, at least one")
        if np.any(y <= 0) or np.any(np.diff(y) <= 0):
            raise ValueError("deflection must be positive and increasing [mm]")
        object.__setattr__(self, "deflection", y)
        object.__setattr__(self, "force", f)


@dataclass(frozen=True)
class StiffnessFit:
    """What :func:`fit_specimen_stiffness` found.

    Attributes
    ----------
    parameters : SpecimenParameters
        The starting parameters with the fitted values.
    values : dict
        ``{variable: fitted value}`` (kf in N/rad).
    residual : ndarray
        Every record's model-minus-record force over its largest force, concatenated.
    evaluations : int
        Model evaluations (each every record's run and its Jacobian).
    success : bool
    message : str
    """

    parameters: SpecimenParameters
    values: dict
    residual: np.ndarray
    evaluations: int
    success: bool
    message: str

    @property
    def rms(self) -> float:
        """Root mean square of the weighted residual."""
        return float(np.sqrt(np.mean(self.residual ** 2)))


def fit_specimen_stiffness(records, *, variables=FIT_VARIABLES, initial=None, steps=20,
                           max_evaluations=50) -> StiffnessFit:
    """Fit kf and (or) the bars' modulus ratio to bending records on the full model.

    Parameters
    ----------
    records : sequence of BendingRecord
    variables : sequence of str, default ("kf", "modulus_factor")
        Which of them to fit; the others keep ``initial``'s values.
    initial : SpecimenParameters, optional
        The start (the thesis's by default) and every other parameter of the specimens.
    steps : int, default 20
        Equal increments of each run to its record's largest deflection.
    max_evaluations : int, default 50

    Returns
    -------
    StiffnessFit

    Raises
    ------
    ValueError
        For no records, a variable that is not fitted here, or a run that does not complete.
    """
    records = list(records)
    if not records or not all(isinstance(r, BendingRecord) for r in records):
        raise ValueError("records must be a non-empty sequence of BendingRecord")
    variables = checked_variables(variables, FIT_VARIABLES)
    steps = as_integer("steps", steps, minimum=1)
    scales = [float(np.max(np.abs(r.force))) or 1.0 for r in records]

    def misfit(params):
        residuals, jacobians = [], []
        for record, scale in zip(records, scales):
            y, F, dF = bending_force_gradient(record.design, record.state,
                                              float(record.deflection[-1]), steps,
                                              parameters=params, variables=variables)
            # Linear interpolation at the record's deflections: weights fixed by the
            # (prescribed) deflections, so the derivative is interpolated the same way.
            residuals.append((np.interp(record.deflection, y, F) - record.force) / scale)
            jacobians.append(np.column_stack([np.interp(record.deflection, y, dF[:, j])
                                              for j in range(len(variables))]) / scale)
        return np.concatenate(residuals), np.vstack(jacobians)

    return _fit(misfit, variables, initial, 1e-14, max_evaluations)


def fit_bending_stiffnesses(measured, *, variables=FIT_VARIABLES, initial=None,
                            protocol="5mm", max_evaluations=50) -> StiffnessFit:
    """Fit kf and (or) the bars' modulus ratio so that the model's K_B matches measured ones
    (Table 3's experimental means, say) in least squares of their logarithms.

    Parameters
    ----------
    measured : sequence of (Design, state, K_B [N m/rad])
    variables, initial, max_evaluations
        As for :func:`fit_specimen_stiffness`.
    protocol : {"5mm", "0.001rad"}
        The model's bending test.

    Returns
    -------
    StiffnessFit
        ``residual``: ln K_model - ln K_measured per entry.
    """
    measured = [(as_design(d), state_index(s), float(k)) for d, s, k in measured]
    if not measured or any(not k > 0 for _, _, k in measured):
        raise ValueError("measured must be a non-empty sequence of (design, state, K_B > 0)")
    variables = checked_variables(variables, FIT_VARIABLES)

    def misfit(params):
        r, J = [], []
        for design, state, k in measured:
            value, gradient = bending_gradient(design, state, protocol, parameters=params,
                                               variables=variables)
            r.append(np.log(value / k))
            J.append([gradient[v] / value for v in variables])  # d ln K / dv
        return np.array(r), np.array(J)

    return _fit(misfit, variables, initial, 1e-12, max_evaluations)


def _fit(misfit, variables, initial, xtol, max_evaluations) -> StiffnessFit:
    """Least squares of ``misfit(parameters) -> (residual, d residual / d variables)`` over
    the logarithms of ``variables`` (positive, of any scale), from ``initial``."""
    from scipy.optimize import least_squares

    initial = initial or SpecimenParameters()
    cache = {}

    def evaluate(x):
        # least_squares asks for the residual, then the Jacobian, of one point: one run.
        key = x.tobytes()
        if key not in cache:
            r, J = misfit(dataclasses.replace(initial, **dict(zip(variables, np.exp(x)))))
            cache.clear()
            cache[key] = (r, J * np.exp(x)[None, :])  # d/d ln v = v d/dv
        return cache[key]

    x0 = np.log([getattr(initial, v) for v in variables])
    result = least_squares(lambda x: evaluate(x)[0], x0, jac=lambda x: evaluate(x)[1],
                           method="trf", xtol=xtol, ftol=1e-15, gtol=1e-15,
                           max_nfev=as_integer("max_evaluations", max_evaluations, minimum=1))
    values = dict(zip(variables, np.exp(result.x).tolist()))
    return StiffnessFit(parameters=dataclasses.replace(initial, **values), values=values,
                        residual=evaluate(result.x)[0], evaluations=int(result.nfev),
                        success=bool(result.success), message=str(result.message))


def record_from_model(design, state, deflection, steps, parameters) -> BendingRecord:
    """A noise-free record made by the model itself (for tests and examples): the bending
    test in ``steps`` equal increments to ``deflection`` [mm]."""
    y, F, _ = bending_force_gradient(design, state, deflection, steps, parameters=parameters,
                                     variables=("kf",))
    return BendingRecord(as_design(design), state, y, F)

