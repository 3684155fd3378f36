#pragma once
/// \file adaptive_path.hpp
/// Adaptive increments with dense output, for any path control that has rates
/// (path_control.hpp: displacement control, force control, crease actuation; docs/model.md,
/// 'Displacement control').
///
/// The path u(t), t in [0, 1], is followed in increments whose size comes from an error
/// estimate; the protocol's samples t_k = k/steps are taken between converged points. Each
/// converged point carries its exact path derivatives (path_point.hpp), so between two of
/// them the displacements, recorded forces and energies are cubic Hermite curves: the
/// predictor of the next increment (extrapolated) and the samples inside (interpolated, no
/// iteration). The error of the control's monitored quantity (PathControl::monitored: the
/// drive's force under displacement control, the stored energy otherwise) is estimated
/// from how far the previous increment's curve, extrapolated, misses the new converged
/// point; an increment whose estimate is above `tolerance` times the quantity's largest
/// value so far is retried shorter, but never shorter than to the next sample (which it
/// then ends on, converged by Newton as in fixed steps). No increment crosses a change of
/// the tangent's negative-eigenvalue count, a hinge crossing a limit of the enhanced linear
/// law, or a cable going taut or slack: each is located to 1e-3 of a sample spacing first.
/// With a barrier among the model's families (contact), every move is limited by its
/// collision check: each predictor is shortened from the last converged point, and the
/// samples inside an increment are converged by Newton from the Hermite curve (so shortened
/// too) rather than interpolated, since a curve between two states whose panels are apart
/// may still pass them through each other.

#include "kresling/assembly/assembler.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/path.hpp"
#include "kresling/solvers/path_control.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::solvers {

struct AdaptiveOptions {
  NewtonOptions newton;
  /// > 0: Newton's budget per solve, and a solve needing that many iterations is rejected;
  /// 0: newton.max_iterations, every converged solve accepted.
  int reject_iterations = 25;
  int max_bisections = 10;  ///< an increment may be cut to 1/2^this of a sample spacing
  double tolerance = 1e-9;  ///< the monitored quantity's error, relative to its largest
  StopRule stop;            ///< ends the path early (completed) when it returns true
  /// Keep the converged points the samples are read from (PathResult::knots, step_knot).
  bool keep_knots = false;
};

/// Follow `control` from `start` (all DOFs; t = 0) with `steps` equal samples. `assembler`
/// is bound over the free rows (the supports and the control's held DOFs left out) with
/// `solver`; `full` over every DOF, unshifted, lower triangle; both to control.model_at(0)
/// and, when the control changes the model, rebound at every solve. Throws
/// std::invalid_argument for a control without rates.
PathResult follow_adaptive(PathControl& control, assembly::Assembler& assembler,
                           assembly::Assembler& full, TangentSolver& solver,
                           const VectorX& start, int steps, const AdaptiveOptions& options);

}  // namespace kresling::solvers
