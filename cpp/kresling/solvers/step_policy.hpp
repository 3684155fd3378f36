#pragma once
/// \file step_policy.hpp
/// How the path follower (path_follower.hpp) chooses its increments: a step policy
/// proposes the next increment from the last accepted state, hears whether it was
/// accepted, and says how the path ended. Equal increments with bisection
/// (increments.hpp), MERLIN2's step control (merlin2_steps.hpp), halving steps
/// (halving_steps.hpp) and MGDCM's step factor (mgdcm.hpp) are the policies.

#include <limits>
#include <string>

#include "kresling/solvers/path.hpp"

namespace kresling::solvers {

class PathControl;

/// One attempted increment of a path.
struct Increment {
  double from = 0.0;  ///< path parameter of the accepted state it starts from
  /// path parameter it tries to reach (the recorded load_factor); a corrector that solves
  /// the parameter (PathControl::correct, MGDCM's) sets it to where it converged
  double to = 0.0;
  /// Its size in the policy's own measure (MERLIN2's step factor, in nominal increments):
  /// a control that accumulates its increments (DisplacementDrive's MERLIN2 mode) adds
  /// size times its nominal increment, exactly as MERLIN2 does.
  double size = 0.0;
  /// Newton's iteration budget for this increment; 0: the follower's (FollowOptions).
  int newton_limit = 0;
  /// A converged increment needing this many iterations or more is rejected; 0: the
  /// follower's rule (FollowOptions::reject_iterations).
  double reject_at = 0.0;
  /// < 1: every Newton correction is scaled by it (damped_newton.hpp; MERLIN2's after ten
  /// rejections in a row), and the follower's extrapolated start is not used.
  double damping = 1.0;
};

class StepPolicy {
 public:
  virtual ~StepPolicy() = default;
  /// The next increment to attempt, or false when the path is over (then finish says how).
  virtual bool next(Increment& increment) = 0;
  /// The increment was accepted: the path is at increment.to.
  virtual void accepted(const Increment& increment) = 0;
  /// The increment failed for `reason`; false ends the path (failed).
  virtual bool rejected(const Increment& increment, const std::string& reason) = 0;
  /// After rejected() ended the path at `increment`, the follower reached its end another
  /// way (a snap, FollowOptions::snap): true when the policy goes on from increment.to as
  /// if it had been accepted. False by default: the policy cannot resume.
  virtual bool resume(const Increment& /*increment*/) { return false; }
  /// Set result.completed and, for a path that ended early, failed_increment and message
  /// (worded by `control` or the policy). Called once when next() or rejected() ended the
  /// path (not when the caller's stop rule did).
  virtual void finish(const PathControl& control, PathResult& result) const = 0;
};

}  // namespace kresling::solvers
