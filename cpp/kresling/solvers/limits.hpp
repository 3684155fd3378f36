#pragma once
/// \file limits.hpp
/// The documented bounds of the path solvers' controls, and the one place every solver
/// (displacement control, force control, MGDCM, and the analyses built on them) checks
/// them. A value outside is a std::invalid_argument naming the control, the value and the
/// allowed range (a Python ValueError).

#include <string>

#include "kresling/core/check.hpp"
#include "kresling/solvers/path.hpp"

namespace kresling::solvers {

/// Increments of a path (`steps`, MGDCM's `max_increments`): the path keeps every step's
/// displacement of every DOF, so its memory grows with this.
inline constexpr int kMaxSteps = 100000;
/// Levels of bisection of a failed increment: the smallest increment is 1/2^30 (about 1e-9)
/// of a nominal one; with at most kMaxSteps nominal increments it is at least 2^-47 of the
/// path, far above the rounding of the path parameter (2^-53), so every accepted increment
/// moves the path on.
inline constexpr int kMaxBisections = 30;
/// Newton iterations of one increment (`max_iterations`, `reject_iterations`).
inline constexpr int kMaxIterations = 10000;
/// Diagonal shift of the tangent [N/mm]: a regularisation that keeps a zero-stiffness mode
/// factorisable (MERLIN2's is 1e-8). Newton stops on the size of its correction, which a
/// shift comparable with the structure's stiffness shrinks: with shift = 1e9 the free DOFs
/// hardly move and the first iteration "converges" far from equilibrium.
inline constexpr double kMaxShift = 1e-3;

/// Throw unless 1 <= steps <= kMaxSteps (`name`: "steps" or "max_increments").
inline void check_steps(const std::string& name, long long steps) {
  require_integer_in(name, steps, 1, kMaxSteps);
}

inline void check_bisections(long long max_bisections) {
  require_integer_in("max_bisections", max_bisections, 0, kMaxBisections);
}

/// Throw unless 0 <= shift <= kMaxShift.
inline void check_shift(double shift) {
  require_finite("shift", shift);
  if (!(shift >= 0.0 && shift <= kMaxShift)) {
    throw_invalid("shift", shift,
                  "in [0, " + format_number(kMaxShift) +
                      "] N/mm: a small regularisation of zero-stiffness modes (MERLIN2's is "
                      "1e-8); a larger one stops Newton away from equilibrium");
  }
}

/// Throw unless tolerance is finite and > 0 and 1 <= max_iterations <= kMaxIterations.
inline void check_newton(const NewtonOptions& o) {
  require_positive("tolerance", o.tolerance);
  require_integer_in("max_iterations", o.max_iterations, 1, kMaxIterations);
  require_integer_in("give_up_after", o.give_up_after, 0, kMaxIterations);
}

/// The adaptive increments' error target (adaptive_path.hpp), relative to the monitored
/// quantity's largest value: in (0, 1e-4].
inline void check_adaptive_tolerance(double tolerance) {
  require_finite("adaptive_tolerance", tolerance);
  if (!(tolerance > 0.0 && tolerance <= 1e-4)) {
    throw_invalid("adaptive_tolerance", tolerance,
                  "in (0, 1e-4]: the samples' error relative to the path's largest value");
  }
}

}  // namespace kresling::solvers
