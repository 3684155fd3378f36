#pragma once
/// \file merlin2_steps.hpp
/// MERLIN2 v1.1's step control (docs/model.md, 'Displacement control'), a step policy of
/// the path follower: a rejected increment halves the step factor (after 10 rejections in a
/// row it grows it by 1.5 and damps Newton by 0.75 instead), each accepted one moves it
/// 10 % back towards 1, and the path runs while the accumulated fraction is <= 1, so it may
/// end past the prescribed motion (11 increments of 1/10, say) exactly as MERLIN2's does.
/// The path ends after 21 rejections in a row. An increment needing ((factor > 1) + 1)
/// max_iterations / (damping + 1) iterations or more is rejected.

#include <string>

#include "kresling/solvers/step_policy.hpp"

namespace kresling::solvers {

class Merlin2Steps final : public StepPolicy {
 public:
  /// `steps` nominal increments; Newton's `max_iterations` sets the rejection budget.
  Merlin2Steps(int steps, int max_iterations);
  bool next(Increment& increment) override;
  void accepted(const Increment& increment) override;
  bool rejected(const Increment& increment, const std::string& reason) override;
  void finish(const PathControl& control, PathResult& result) const override;

 private:
  int steps_, max_iterations_;
  double moved_ = 0.0;      // fraction of the prescribed motion reached
  double step_size_ = 1.0;  // in nominal increments
  double damping_ = 1.0;
  int rejections_ = 0;      // in a row
  std::string last_failure_;
};

}  // namespace kresling::solvers
