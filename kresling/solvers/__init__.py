"""Nonlinear solvers: displacement control (the thesis's mode), Newton and MGDCM path
following under force control, folding by crease actuation, time integration (implicit and explicit),
the linearised stiffness, the exact sensitivities of equilibria and paths to the
elements' parameters, limit points and the derivatives of their loads, and folding to a
shape by those sensitivities. Each path solver returns a
:class:`PathResult`; a solver that stops early says so (``completed``, ``message``)."""

from kresling._lazy import lazy_names
# fold is also a module's name: imported here, not when first used.
from kresling.solvers.fold import fold

# Imported when first used (a bending test needs displacement control alone): the other
# path solvers, time integration, sensitivities, folding to a shape.
__getattr__, __dir__ = lazy_names(__name__, {
    "solve_displacement_control": "displacement_control",
    **dict.fromkeys(["FoldResult", "solve_fold"], "fold"),
    **dict.fromkeys(["solve_force_control", "solve_mgdcm"], "force_control"),
    "condensed_stiffness": "linear",
    "PathResult": "path",
    **dict.fromkeys(["StableStep", "TimeHistory", "solve_dynamics", "stable_time_step"],
                    "dynamics"),
    **dict.fromkeys(["fold_model_at", "fold_sensitivity"], "fold_sensitivity"),
    **dict.fromkeys(["ShapeFold", "fold_to_shape"], "fold_to_shape"),
    **dict.fromkeys(["Direction", "EquilibriumSensitivity", "Parameter", "PathSensitivity",
                     "energy_derivative", "equilibrium_gradient", "equilibrium_sensitivity",
                     "parameter_jacobian",
                     "parameter_names", "path_sensitivity", "residual_derivative",
                     "shape_jacobian",
                     "with_parameter"], "sensitivity"),
    **dict.fromkeys(["LimitPoint", "limit_point"], "limit_points")})

__all__ = ["PathResult", "solve_displacement_control", "solve_force_control", "solve_mgdcm",
           "condensed_stiffness", "solve_fold", "fold", "FoldResult", "solve_dynamics", "TimeHistory",
           "stable_time_step", "StableStep", "Parameter", "parameter_names", "parameter_jacobian",
           "with_parameter", "EquilibriumSensitivity", "equilibrium_sensitivity",
           "equilibrium_gradient", "energy_derivative", "residual_derivative", "PathSensitivity",
           "path_sensitivity", "Direction",
           "shape_jacobian", "fold_to_shape", "ShapeFold", "fold_sensitivity", "fold_model_at",
           "LimitPoint", "limit_point"]
