#pragma once
/// \file increments.hpp
/// Equal increments with bisection, the step policy of fixed-step paths (displacement
/// control, force control, folding): the path parameter goes from 0 to 1 in `steps` equal
/// increments; an increment that fails is retried as two halves, recursively, down to
/// 1/2^max_bisections of its size.

#include <string>

#include "kresling/core/interrupt.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/path.hpp"
#include "kresling/solvers/step_policy.hpp"

namespace kresling::solvers {

class EqualIncrements final : public StepPolicy {
 public:
  /// Throws std::invalid_argument for steps outside [1, kMaxSteps] or max_bisections
  /// outside [0, kMaxBisections].
  EqualIncrements(int steps, int max_bisections);
  bool next(Increment& increment) override;
  void accepted(const Increment& increment) override;
  bool rejected(const Increment& increment, const std::string& reason) override;
  /// Goes on from increment.to: the rest of the nominal increment, then the next ones.
  bool resume(const Increment& increment) override;
  /// The message of a failed increment is the control's (PathControl::failure_message).
  void finish(const PathControl& control, PathResult& result) const override;

 private:
  int steps_, max_bisections_;
  double nominal_, smallest_;
  int k_ = 1;          // the nominal increment under way (1-based)
  double t_ = 0.0;     // the accepted path parameter
  double dt_;          // the size of the next attempt within increment k
  bool failed_ = false;
  std::string first_failure_;  // why increment k failed at full size, the most telling
  std::string last_failure_;   // why it failed at the last (smallest) size tried
  double last_size_ = 0.0;     // that size
  bool halved_ = false;        // tried smaller than at full size
  double target() const { return k_ == steps_ ? 1.0 : k_ * nominal_; }
};

}  // namespace kresling::solvers
