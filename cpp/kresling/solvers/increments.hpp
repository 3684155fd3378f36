#pragma once
/// \file increments.hpp
/// The stepping both displacement control and load-stepped Newton use: a path parameter
/// goes from 0 to 1 in `steps` equal increments; an increment that fails is retried as two
/// halves, recursively, down to 1/2^max_bisections of its size.

#include <cmath>
#include <string>

#include "kresling/core/interrupt.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/path.hpp"

namespace kresling::solvers {

/// `attempt(t_from, t_to, failure)` tries to reach `t_to` from the accepted state at
/// `t_from`; it records the step and returns true, or sets `failure` and returns false.
/// `stop()` is asked after every accepted attempt: true ends the march there (completed).
/// `describe(k, t, reason)` words the message when increment k fails at parameter t for
/// good (reason: why its full-size attempt failed). Returns result.completed.
/// Throws std::invalid_argument for steps outside [1, kMaxSteps] or max_bisections outside
/// [0, kMaxBisections]; calls check_interrupt() before every attempt.
template <typename Attempt, typename Stop, typename Describe>
bool march(int steps, int max_bisections, PathResult& result, Attempt&& attempt, Stop&& stop,
           Describe&& describe) {
  check_steps("steps", steps);
  check_bisections(max_bisections);
  const double nominal = 1.0 / steps;
  const double smallest = std::ldexp(nominal, -max_bisections);
  double t = 0.0;
  for (int k = 1; k <= steps; ++k) {
    const double target = (k == steps) ? 1.0 : k * nominal;
    double dt = target - t;
    std::string first_failure;  // why the whole increment failed, the most telling reason
    while (t < target) {
      check_interrupt();
      ++result.attempted_increments;
      const double t_new = (dt >= target - t) ? target : t + dt;
      std::string failure;
      if (attempt(t, t_new, failure)) {
        t = t_new;
        dt = target - t;  // back to the rest of the nominal increment
        if (stop()) {
          result.completed = true;
          return true;
        }
        continue;
      }
      if (first_failure.empty()) first_failure = failure;
      dt *= 0.5;
      if (dt < smallest) {
        result.failed_increment = result.attempted_increments;
        result.message = describe(k, t, first_failure);
        return false;
      }
    }
  }
  result.completed = true;
  return true;
}

}  // namespace kresling::solvers
