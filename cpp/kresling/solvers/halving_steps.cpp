#include "kresling/solvers/halving_steps.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kresling/core/check.hpp"
#include "kresling/solvers/path_control.hpp"

namespace kresling::solvers {

HalvingSteps::HalvingSteps(int steps, int max_bisections)
    : steps_(steps),
      max_bisections_(max_bisections),
      failed_at_(std::numeric_limits<double>::quiet_NaN()) {
  if (steps < 1) throw_invalid("steps", steps, "an integer >= 1");
  if (max_bisections < 0 || max_bisections > 30) {
    throw_invalid("max_bisections", max_bisections, "an integer in [0, 30]");
  }
  nominal_ = 1.0 / steps;
  smallest_ = nominal_ / std::pow(2.0, max_bisections);
  h_ = nominal_;
}

bool HalvingSteps::next(Increment& increment) {
  if (!std::isnan(failed_at_) || !(t_ < 1.0 - 1e-12)) return false;
  h_ = std::min(h_, 1.0 - t_);
  increment = Increment{};
  increment.from = t_;
  increment.to = std::min(1.0, t_ + h_);
  increment.size = h_;
  return true;
}

void HalvingSteps::accepted(const Increment& increment) {
  t_ = increment.to;
  first_failure_.clear();
  h_ = std::min(2.0 * h_, nominal_);
}

bool HalvingSteps::rejected(const Increment& increment, const std::string& reason) {
  halved_ = !first_failure_.empty();
  if (!halved_) first_failure_ = reason;
  reason_ = reason;
  last_size_ = increment.size;
  if (h_ > 1.5 * smallest_) {
    h_ *= 0.5;
    return true;
  }
  failed_at_ = increment.to;
  return false;
}

void HalvingSteps::finish(const PathControl& control, PathResult& result) const {
  result.completed = std::isnan(failed_at_);
  if (result.completed) return;
  result.failed_increment = result.attempted_increments;
  const int k = std::min(steps_, static_cast<int>(t_ * steps_) + 1);
  result.message = control.failure_message(
      k, steps_, t_, max_bisections_, failure_at_sizes(first_failure_, last_size_, reason_, halved_));
}

}  // namespace kresling::solvers
