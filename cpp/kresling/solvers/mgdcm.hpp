#pragma once
/// \file mgdcm.hpp
/// The modified generalized displacement control method (MGDCM, Leon, Paulino et al. 2011):
/// path following under a reference load whose factor lambda is an unknown, through limit
/// points and snap-backs.
///
/// Each increment is Newton with two solves per iteration on one factorisation. The first
/// iteration's load increment is the step factor scaled by the generalized stiffness
/// parameter, its sign flipped where the predictor turns against the previous one (a limit
/// point); later iterations stay orthogonal to the first predictor. The step control is
/// MERLIN2's: the step factor grows by 1.5 after an increment of fewer than
/// `grow_below_iterations` iterations, an increment of more than `shrink_above_iterations`
/// is rejected and retried at half the step. One case is told apart: where Newton's
/// corrections stall at an accuracy floor above the tolerance (round-off near a singular
/// tangent, at a bifurcation or limit point), a shorter step cannot help, so the increment
/// is retried with a longer one, to land past the singular point; where that fails too the
/// path ends with the floor and the tolerance it would need.

#include <limits>

#include "kresling/model/model.hpp"
#include "kresling/solvers/path.hpp"

namespace kresling::solvers {

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

/// Follow the equilibrium path of lambda * `forces` (one entry per DOF [N]) from `initial`
/// (all DOFs; empty: zero) by MGDCM. Steps record the supports' reactions.
PathResult solve_mgdcm(const model::Model& model, const VectorX& forces,
                       const MgdcmOptions& options = {}, const VectorX& initial = VectorX());

}  // namespace kresling::solvers
