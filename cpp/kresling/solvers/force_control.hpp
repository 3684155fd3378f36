#pragma once
/// \file force_control.hpp
/// Path following under force control: plain Newton with load steps, and the modified
/// generalized displacement control method (MGDCM, Leon, Paulino et al. 2011), which passes
/// limit points and snap-backs.

#include <limits>

#include "kresling/model/model.hpp"
#include "kresling/solvers/path.hpp"

namespace kresling::solvers {

struct ForceControlOptions {
  NewtonOptions newton;
  int max_bisections = 10;  ///< a failed load step is halved up to this many times
  double shift = 1e-8;
  StopRule stop;            ///< ends the path (completed) when it returns true
};

/// Newton equilibrium under loads lambda * forces, lambda = 1/steps, 2/steps, ..., 1.
/// Stops (not completed) where no equilibrium is found, e.g. past a limit point.
PathResult solve_force_control(const model::Model& model, const VectorX& forces, int steps,
                               const ForceControlOptions& options = {},
                               const VectorX& initial = VectorX());

struct MgdcmOptions {
  NewtonOptions newton;
  double initial_load_factor = 0.01;  ///< first increment of lambda (MERLIN2's b_lambda)
  int max_increments = 100;           ///< accepted increments
  /// Stop (completed) once |lambda| exceeds this.
  double max_load_factor = std::numeric_limits<double>::infinity();
  /// Stop (completed) once |u[monitor_dof]| exceeds max_displacement (monitor_dof >= 0).
  Index monitor_dof = -1;
  double max_displacement = std::numeric_limits<double>::infinity();
  int shrink_above_iterations = 15;  ///< more iterations: reject, halve the step factor
  int grow_below_iterations = 3;     ///< fewer iterations: step factor times 1.5
  double min_load_factor = 1e-14;    ///< give up when the step factor falls below this
  /// Cap on the step factor's growth (|b_lambda| <= this), for a finely resolved path.
  double max_step_factor = std::numeric_limits<double>::infinity();
  double shift = 1e-8;
  StopRule stop;  ///< a further stopping criterion (completed when it returns true)
};

/// MGDCM path following under the reference load `forces`: two solves per iteration with
/// one factorisation; the first iteration's load increment is scaled by the generalized
/// stiffness parameter and flips sign when the predictor reverses (a limit point), later
/// iterations stay orthogonal to the first predictor.
PathResult solve_mgdcm(const model::Model& model, const VectorX& forces,
                       const MgdcmOptions& options = {}, const VectorX& initial = VectorX());

}  // namespace kresling::solvers
