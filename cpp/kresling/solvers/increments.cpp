#include "kresling/solvers/increments.hpp"

#include <cmath>

#include "kresling/solvers/path_control.hpp"

namespace kresling::solvers {

EqualIncrements::EqualIncrements(int steps, int max_bisections)
    : steps_(steps), max_bisections_(max_bisections) {
  check_steps("steps", steps);
  check_bisections(max_bisections);
  nominal_ = 1.0 / steps;
  smallest_ = std::ldexp(nominal_, -max_bisections);
  dt_ = target() - t_;
}

bool EqualIncrements::next(Increment& increment) {
  if (failed_ || k_ > steps_) return false;
  const double end = target();
  increment = Increment{};
  increment.from = t_;
  increment.to = (dt_ >= end - t_) ? end : t_ + dt_;
  increment.size = increment.to - t_;
  return true;
}

void EqualIncrements::accepted(const Increment& increment) {
  t_ = increment.to;
  if (t_ < target()) {
    dt_ = target() - t_;  // back to the rest of the nominal increment
    return;
  }
  // The next nominal increment (one the accepted state has already reached is skipped).
  do {
    ++k_;
  } while (k_ <= steps_ && t_ >= target());
  first_failure_.clear();
  if (k_ <= steps_) dt_ = target() - t_;
}

bool EqualIncrements::rejected(const Increment& increment, const std::string& reason) {
  halved_ = !first_failure_.empty();
  if (!halved_) first_failure_ = reason;
  last_failure_ = reason;
  last_size_ = increment.size;
  dt_ *= 0.5;
  if (dt_ < smallest_) failed_ = true;
  return !failed_;
}

bool EqualIncrements::resume(const Increment& increment) {
  failed_ = false;
  first_failure_.clear();
  accepted(increment);
  return true;
}

void EqualIncrements::finish(const PathControl& control, PathResult& result) const {
  if (!failed_) {
    result.completed = true;
    return;
  }
  result.failed_increment = result.attempted_increments;
  result.message = control.failure_message(
      k_, steps_, t_, max_bisections_,
      failure_at_sizes(first_failure_, last_size_, last_failure_, halved_));
}

}  // namespace kresling::solvers
