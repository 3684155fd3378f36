#pragma once
/// \file stable_time_step.hpp
/// The largest time step explicit central differences take stably on a model with lumped
/// masses: 2 / w_max undamped, w_max the highest natural frequency of the tangent at a
/// state. With Rayleigh damping C = a M + b K the scheme of explicit_dynamics.hpp is stable
/// for mode w while w dt <= 2 (sqrt(1 + xi^2) - xi), xi = a / (2 w) + b w / 2; that bound
/// falls with w, so the highest mode sets the step:
///     dt_stable = 2 / (sqrt(w^2 + s^2) + s),  s = (a + b w^2) / 2  at w = w_max.
///
/// w_max^2 is the largest eigenvalue of M^-1/2 K M^-1/2 on the free DOFs, estimated by a
/// Lanczos iteration (the power iteration's Krylov refinement: its largest Ritz value theta
/// approaches w_max^2 from below, much faster than a power iteration's Rayleigh quotient)
/// until the Ritz vector's residual r is below 1e-10 theta (at most 300 steps); theta + r
/// is taken, which bounds w_max^2 from above once theta has converged, capped by
/// Gershgorin's bound max_i sum_j |K_ij| / sqrt(m_i m_j).

#include "kresling/core/types.hpp"
#include "kresling/model/model.hpp"

namespace kresling::solvers {

struct StableStep {
  double time_step = 0.0;        ///< dt_stable [s] (+inf for a model without stiffness)
  double omega_max = 0.0;        ///< the Lanczos estimate of w_max [rad/s]
  double omega_bound = 0.0;      ///< Gershgorin's upper bound of w_max [rad/s]
  int iterations = 0;            ///< Lanczos steps taken
};

/// The stable step of the model at displacement u (all DOFs; empty: the rest state) with
/// lumped masses `masses` (one per DOF [t], > 0 at every free DOF) and Rayleigh damping
/// coefficients mass_damping [1/s] and stiffness_damping [s].
StableStep stable_time_step(const model::Model& model, const VectorX& masses,
                            const VectorX& u = VectorX(), double mass_damping = 0.0,
                            double stiffness_damping = 0.0);

/// dt_stable for a highest frequency w [rad/s] under Rayleigh damping (a, b).
double damped_stable_step(double omega, double mass_damping, double stiffness_damping);

}  // namespace kresling::solvers
