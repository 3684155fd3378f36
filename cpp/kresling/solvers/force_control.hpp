#pragma once
/// \file force_control.hpp
/// Path following under force control: Newton with load steps (MGDCM, which passes limit
/// points and snap-backs, is in mgdcm.hpp).

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

/// Check a load-driven path's inputs: `forces` one finite entry per DOF with one acting on a
/// free DOF, `initial` empty or one finite entry per DOF, the supports stopping every
/// rigid-body motion. Throws std::invalid_argument naming the input.
void check_load_inputs(const model::Model& model, const VectorX& forces, const VectorX& initial);

}  // namespace kresling::solvers
