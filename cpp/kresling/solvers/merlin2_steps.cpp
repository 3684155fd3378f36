#include "kresling/solvers/merlin2_steps.hpp"

#include <algorithm>
#include <cmath>

#include "kresling/core/check.hpp"
#include "kresling/solvers/limits.hpp"

namespace kresling::solvers {

Merlin2Steps::Merlin2Steps(int steps, int max_iterations)
    : steps_(steps), max_iterations_(max_iterations) {
  check_steps("steps", steps);
}

bool Merlin2Steps::next(Increment& increment) {
  if (!(moved_ <= 1.0 && rejections_ <= 20)) return false;
  increment = Increment{};
  increment.from = moved_;
  increment.to = moved_ + step_size_ / steps_;
  increment.size = step_size_;
  increment.damping = damping_;
  // MERLIN2 rejects an increment needing this many iterations (more for a bold step);
  // iterating past it cannot change the outcome.
  increment.reject_at = ((step_size_ > 1.0) + 1.0) * max_iterations_ / (damping_ + 1.0);
  increment.newton_limit =
      std::min(max_iterations_, static_cast<int>(std::ceil(increment.reject_at)));
  return true;
}

void Merlin2Steps::accepted(const Increment&) {
  moved_ += step_size_ / steps_;
  rejections_ = 0;
  damping_ = 1.0;
  step_size_ =
      step_size_ < 1.0 ? std::min(step_size_ * 1.1, 1.0) : std::max(step_size_ * 0.9, 1.0);
}

bool Merlin2Steps::rejected(const Increment&, const std::string& reason) {
  last_failure_ = reason;
  ++rejections_;
  if (rejections_ <= 10) {
    step_size_ *= 0.5;
  } else {
    step_size_ = std::max(step_size_, 1.0) * 1.5;
    damping_ *= 0.75;
  }
  return true;  // next() decides when the rejections in a row are too many
}

void Merlin2Steps::finish(const PathControl&, PathResult& result) const {
  result.completed = moved_ > 1.0;
  if (result.completed) return;
  result.failed_increment = result.attempted_increments;
  result.message = "increment " + std::to_string(result.steps.size() + 1) + " (at " +
                   format_rounded(moved_) + " of the prescribed motion) was rejected 21 times " +
                   "in a row; last: " + last_failure_;
}

}  // namespace kresling::solvers
