"""Nonlinear solvers: displacement control (the thesis's mode), Newton and MGDCM path
following under force control, folding by crease actuation, time integration (implicit and explicit),
the linearised stiffness, the exact sensitivities of equilibria and paths to the
elements' parameters, and folding to a shape by those sensitivities. Each path solver returns a
:class:`PathResult`; a solver that stops early says so (``completed``, ``message``)."""

from kresling.solvers.displacement_control import solve_displacement_control
from kresling.solvers.dynamics import StableStep, TimeHistory, solve_dynamics, stable_time_step
from kresling.solvers.fold import FoldResult, fold, solve_fold
from kresling.solvers.fold_sensitivity import fold_model_at, fold_sensitivity
from kresling.solvers.fold_to_shape import ShapeFold, fold_to_shape
from kresling.solvers.force_control import solve_force_control, solve_mgdcm
from kresling.solvers.linear import condensed_stiffness
from kresling.solvers.path import PathResult
from kresling.solvers.sensitivity import (Direction, EquilibriumSensitivity, Parameter,
                                          PathSensitivity, equilibrium_gradient,
                                          equilibrium_sensitivity, parameter_jacobian,
                                          parameter_names, path_sensitivity, shape_jacobian,
                                          with_parameter)

__all__ = ["PathResult", "solve_displacement_control", "solve_force_control", "solve_mgdcm",
           "condensed_stiffness", "solve_fold", "fold", "FoldResult", "solve_dynamics", "TimeHistory",
           "stable_time_step", "StableStep", "Parameter", "parameter_names", "parameter_jacobian",
           "with_parameter", "EquilibriumSensitivity", "equilibrium_sensitivity",
           "equilibrium_gradient", "PathSensitivity", "path_sensitivity", "Direction",
           "shape_jacobian", "fold_to_shape", "ShapeFold", "fold_sensitivity", "fold_model_at"]
