#include "kresling/solvers/time_steps.hpp"

#include <algorithm>
#include <cmath>

#include "kresling/solvers/path_control.hpp"

namespace kresling::solvers {

HalvedTimeSteps::HalvedTimeSteps(double time_step, double duration, int max_halvings)
    : nominal_(time_step),
      end_(duration),
      smallest_(std::ldexp(time_step, -max_halvings)),
      max_halvings_(max_halvings),
      dt_(time_step) {}

bool HalvedTimeSteps::next(Increment& increment) {
  // The relative margin keeps rounding in the summed steps from adding a sliver of a step.
  if (failed_ || !(t_ < end_ * (1.0 - 1e-12))) return false;
  dt_ = std::min(dt_, end_ - t_);
  increment = Increment{};
  increment.from = t_;
  increment.to = t_ + dt_;
  increment.size = dt_;
  return true;
}

void HalvedTimeSteps::accepted(const Increment& increment) {
  t_ = increment.to;
  dt_ = std::min(2.0 * dt_, nominal_);  // grown back after a halving
}

bool HalvedTimeSteps::rejected(const Increment&, const std::string& reason) {
  dt_ *= 0.5;
  if (dt_ >= smallest_) return true;
  failed_ = true;
  reason_ = reason;
  return false;
}

void HalvedTimeSteps::finish(const PathControl& control, PathResult& result) const {
  result.completed = !failed_;
  if (result.completed) return;
  result.failed_increment = result.attempted_increments;
  result.message = control.failure_message(0, 0, t_, max_halvings_, reason_);
}

FixedTimeSteps::FixedTimeSteps(long long steps, double duration, long long group)
    : steps_(steps), group_(group), duration_(duration),
      dt_(duration / static_cast<double>(steps)) {}

double FixedTimeSteps::time_at(long long k) const {
  return k == steps_ ? duration_ : static_cast<double>(k) * dt_;
}

bool FixedTimeSteps::next(Increment& increment) {
  if (failed_ || k_ >= steps_) return false;
  const long long last = std::min(k_ + group_, steps_);
  increment = Increment{};
  increment.from = time_at(k_);
  increment.to = time_at(last);
  increment.size = static_cast<double>(last - k_);
  return true;
}

void FixedTimeSteps::accepted(const Increment& increment) {
  k_ += static_cast<long long>(increment.size);
}

bool FixedTimeSteps::rejected(const Increment&, const std::string& reason) {
  failed_ = true;  // an explicit step is not retried
  reason_ = reason;
  return false;
}

void FixedTimeSteps::finish(const PathControl&, PathResult& result) const {
  result.completed = !failed_;
  if (!failed_) return;
  result.failed_increment = result.attempted_increments;
  result.message = reason_;
}

}  // namespace kresling::solvers
