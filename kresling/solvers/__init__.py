"""Nonlinear solvers: displacement control (the thesis's mode), Newton and MGDCM path
following under force control, folding by crease actuation, time integration (implicit and explicit),
the linearised stiffness, the exact sensitivities of equilibria and paths to the
elements' parameters, and folding to a shape by those sensitivities. Each path solver returns a
:class:`PathResult`; a solver that stops early says so (``completed``, ``message``)."""

from kresling._lazy import lazy_names
from kresling.solvers.displacement_control import solve_displacement_control
from kresling.solvers.fold import FoldResult, fold, solve_fold
from kresling.solvers.force_control import solve_force_control, solve_mgdcm
from kresling.solvers.linear import condensed_stiffness
from kresling.solvers.path import PathResult

# Imported when first used (a path needs none of them): time integration, sensitivities,
# folding to a shape. (fold is also a module's name, so it is imported above.)
__getattr__, __dir__ = lazy_names(__name__, {
    **dict.fromkeys(["StableStep", "TimeHistory", "solve_dynamics", "stable_time_step"],
                    "dynamics"),
    **dict.fromkeys(["fold_model_at", "fold_sensitivity"], "fold_sensitivity"),
    **dict.fromkeys(["ShapeFold", "fold_to_shape"], "fold_to_shape"),
    **dict.fromkeys(["Direction", "EquilibriumSensitivity", "Parameter", "PathSensitivity",
                     "equilibrium_gradient", "equilibrium_sensitivity", "parameter_jacobian",
                     "parameter_names", "path_sensitivity", "shape_jacobian",
                     "with_parameter"], "sensitivity")})

__all__ = ["PathResult", "solve_displacement_control", "solve_force_control", "solve_mgdcm",
           "condensed_stiffness", "solve_fold", "fold", "FoldResult", "solve_dynamics", "TimeHistory",
           "stable_time_step", "StableStep", "Parameter", "parameter_names", "parameter_jacobian",
           "with_parameter", "EquilibriumSensitivity", "equilibrium_sensitivity",
           "equilibrium_gradient", "PathSensitivity", "path_sensitivity", "Direction",
           "shape_jacobian", "fold_to_shape", "ShapeFold", "fold_sensitivity", "fold_model_at"]
