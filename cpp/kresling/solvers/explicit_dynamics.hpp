#pragma once
/// \file explicit_dynamics.hpp
/// Explicit time integration of M a + C v + f_int(u) = f(t) by central differences with
/// lumped (diagonal) masses, in the leapfrog form:
///     a_n       = M^-1 (f(t_n) - f_int(u_n) - C v_{n-1/2})
///     v_{n+1/2} = v_{n-1/2} + dt a_n          (v_{-1/2}: v_0 - dt a_0 / 2, so v_{1/2} = v_0 + dt a_0 / 2)
///     u_{n+1}   = u_n + dt v_{n+1/2}
/// and v_{n+1} = v_{n+1/2} + dt a_{n+1} / 2 reported. Undamped it is the central difference
/// u_{n+1} - 2 u_n + u_{n-1} = dt^2 a_n, second order, its period shortened as
/// cos(w_h dt) = 1 - (w dt)^2 / 2. The damping force uses the velocity half a step back
/// (C = alpha M + beta K0 need not be diagonal), first order in it. Each step evaluates the
/// internal force once: no tangent, no factorisation; the price is a step at most
/// stable_time_step.hpp's dt_stable, which a larger `time_step` is refused for. The run is
/// the path follower (path_follower.hpp) with time as its parameter (time_control.hpp),
/// FixedTimeSteps (time_steps.hpp) grouping the steps between recorded ones, and the
/// explicit update as each increment's corrector.
///
/// Energies per step as for the implicit schemes (time_integration.hpp): kinetic, stored,
/// dissipated (sum of dt v_{n+1/2}^T C v_{n+1/2}) and the loads' work (trapezoidal in u);
/// their balance holds to O((w dt)^2). The run stops with a message, never silently, when
/// the state stops being finite or its energy (kinetic + stored) exceeds kEnergyGrowthLimit
/// times what the start and the loads put in (the start's energy, the magnitudes of the
/// loads' work's increments and the half step of work the velocity at a whole step is
/// ahead by, dt |v . f| / 2): an instability, e.g. a tangent stiffened beyond
/// the start's stable step. (A stable run's energy at the whole steps stays within
/// 1 / (1 - (w dt)^2 / 4) of the scheme's conserved one, far below that limit.)

#include <functional>

#include "kresling/model/model.hpp"
#include "kresling/solvers/time_integration.hpp"

namespace kresling::solvers {

struct ExplicitOptions {
  double time_step = 1e-6;         ///< dt [s], at most the stable step
  double duration = 1e-3;          ///< [s]
  double mass_damping = 0.0;       ///< Rayleigh alpha [1/s]
  double stiffness_damping = 0.0;  ///< Rayleigh beta [s], with K0 the tangent at the start
  /// Keep every record_every-th step (and the last) in the history: explicit runs take
  /// many small steps.
  long long record_every = 1;
  StopRule stop;                   ///< asked at every recorded step
};

/// How many times the energy put in a run's energy may grow before it is called unstable.
inline constexpr double kEnergyGrowthLimit = 100.0;
/// Steps of an explicit run: each is one force evaluation, and only the recorded ones
/// (at most kMaxSteps) are kept.
inline constexpr long long kMaxExplicitSteps = 2'000'000'000LL;

/// Integrate from (u0, v0) (empty: zero) under the load `load` (time_integration.hpp), with lumped masses `masses` (one per DOF [t], > 0 at every
/// free DOF). The history's stable_time_step is dt_stable at the start. Throws
/// std::invalid_argument for bad input, a time_step above dt_stable, or a model whose
/// elements limit each step (contact barriers need implicit steps).
TimeHistory integrate_explicit(const model::Model& model, const VectorX& masses,
                               const TimeLoad& load, const ExplicitOptions& options, const VectorX& u0 = VectorX(),
                               const VectorX& v0 = VectorX());

}  // namespace kresling::solvers
