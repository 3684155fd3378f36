#pragma once
/// \file path_follower.hpp
/// The incremental driver every fixed-step path shares: displacement control, force
/// control, crease actuation (folding) and any other control (path_control.hpp). The
/// parameter t goes from 0 to 1 in `steps` equal increments; each increment is a Newton
/// solve of the control's model with its held DOFs and external force at the new t, from
/// the previous equilibrium or an extrapolation along the path; an increment that fails is
/// retried as two halves, recursively (increments.hpp).

#include "kresling/assembly/assembler.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/path.hpp"
#include "kresling/solvers/path_control.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::solvers {

struct FollowOptions {
  NewtonOptions newton;
  int max_bisections = 10;
  /// Each increment's start: 0 = the previous equilibrium, 1-3 = a linear, quadratic or
  /// cubic extrapolation through the last 2-4 equilibria (see DisplacementControlOptions).
  int extrapolation = 0;
  /// > 0: Newton's budget per increment, and an increment needing that many iterations is
  /// rejected (MERLIN2's rule); 0: newton.max_iterations, and every converged increment is
  /// accepted.
  int reject_iterations = 0;
  StopRule stop;                  ///< ends the path early (completed) when it returns true
  ExtraTerms* extra = nullptr;    ///< terms added to every Newton solve (optional)
};

/// Follow `control` in `steps` increments from `u` (all DOFs; the accepted state at t = 0,
/// left at the last accepted one). `assembler` is bound to a workspace whose rows leave out
/// the supports and the control's held DOFs; it is rebound to the control's model at each
/// attempt when the control changes the model, and `solver` keeps its factorisation
/// between solves. Steps are appended to `result` (whose attempted increments count on);
/// its recorded DOFs and families are set here.
void follow_path(PathControl& control, assembly::Assembler& assembler, TangentSolver& solver,
                 VectorX& u, int steps, const FollowOptions& options, PathResult& result);

}  // namespace kresling::solvers
