#pragma once
/// \file halving_steps.hpp
/// Increments that halve on failure and double back on success, the step policy of ramps
/// that end where equilibrium is lost (the arm's pulls and loads, analyses/arm_analysis.hpp):
/// the path parameter goes from 0 to 1 in increments of at most 1/steps; a rejected
/// increment is halved, an accepted one lets the next be twice as long (up to 1/steps), and
/// an increment rejected at 1/2^max_bisections of 1/steps ends the path there: the last
/// accepted state and the failed increment's end bracket where it ended.

#include <string>

#include "kresling/solvers/step_policy.hpp"

namespace kresling::solvers {

class HalvingSteps final : public StepPolicy {
 public:
  /// Throws std::invalid_argument for steps < 1 or max_bisections outside [0, 30].
  HalvingSteps(int steps, int max_bisections);
  bool next(Increment& increment) override;
  void accepted(const Increment& increment) override;
  bool rejected(const Increment& increment, const std::string& reason) override;
  /// The message of a failed path is the control's (PathControl::failure_message).
  void finish(const PathControl& control, PathResult& result) const override;

  /// The end of the increment that failed for good (the path's end bracket), NaN if none.
  double failed_at() const { return failed_at_; }
  /// Why it failed.
  const std::string& reason() const { return reason_; }

 private:
  int steps_, max_bisections_;
  double nominal_, smallest_;
  double t_ = 0.0, h_;
  double failed_at_;
  std::string reason_;
  std::string first_failure_;  // why the increment failed at its first size tried
  double last_size_ = 0.0;     // the size of the last (smallest) attempt
  bool halved_ = false;        // tried smaller than at its first size
};

}  // namespace kresling::solvers
