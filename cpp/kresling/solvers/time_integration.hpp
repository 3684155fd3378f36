#pragma once
/// \file time_integration.hpp
/// Implicit time integration of M a + C v + f_int(u) = f(t): Newmark's average
/// acceleration (the trapezoidal rule) and its HHT-alpha generalisation, each step a Newton
/// solve of the model with the inertia and damping terms added (newton.hpp's ExtraTerms),
/// the step halved on failure and grown back: the path follower (path_follower.hpp) with
/// time as its parameter (time_control.hpp) and HalvedTimeSteps (time_steps.hpp). Units:
/// mm, N, s, so masses in tonnes.
///
/// HHT-alpha (Hilber, Hughes and Taylor), alpha in [-1/3, 0]: beta = (1 - alpha)^2 / 4,
/// gamma = 1/2 - alpha, and the equation of motion balanced at t_n + (1 + alpha) dt,
///     M a_{n+1} + (1 + alpha) (C v_{n+1} + f_int(u_{n+1})) - alpha (C v_n + f_int(u_n))
///         = (1 + alpha) f(t_{n+1}) - alpha f(t_n);
/// alpha = 0 is the average acceleration scheme (beta = 1/4, gamma = 1/2): unconditionally
/// stable, no numerical damping, energy conserving for linear models, its period
/// lengthened as tan(w_h dt / 2) = w dt / 2. alpha < 0 damps the highest modes.
/// Rayleigh damping C = alpha_m M + beta_k K0, K0 the tangent at the start (an initial-
/// stiffness Rayleigh damping: constant, so the dissipation is a quadratic form), or with
/// `damping_current_tangent` C_n = alpha_m M + beta_k K_t(u_n): the tangent of the state
/// each step starts from, held over that step (so Newton's tangent of the step, with
/// beta_k K_t(u_n) in it, is exact and Newton converges quadratically). The damping force
/// at a step's start is the one the step before balanced (C_{n-1} v_n), so the energy
/// balance below holds as with a constant C.
///
/// Creases driven in time (`actuation`, a RestAngleSchedule): the hinges' rest angles at
/// t_{n+1} in the step's internal force, its tangent and its recorded energy. The work the
/// actuation does on the sheet is the trapezoidal rule in the rest angles,
///     W_{n+1} - W_n = 1/2 [E(u_n, r_{n+1}) - E(u_n, r_n) + E(u_{n+1}, r_{n+1}) - E(u_{n+1}, r_n)],
/// E the hinges' energy at displacement u and rest angles r: for a moment affine in the rest
/// angle (every hinge law's) it is 1/2 (r_{n+1} - r_n) . (dE/dr_n + dE/dr_{n+1}), which the
/// average acceleration scheme balances exactly for a linear model (as its loads' work).

#include <functional>
#include <vector>

#include "kresling/model/model.hpp"
#include "kresling/solvers/path.hpp"
#include "kresling/solvers/time_function.hpp"

namespace kresling::solvers {

/// Creases driven in time: the rest angle of each hinge of a term at time t is
/// start + factor(t) delta [rad] (the hinge's own rest angle where no term drives it; a
/// hinge in two terms: the later's).
struct RestAngleSchedule {
  struct Term {
    std::vector<Index> hinges;  ///< the model's hinge indices
    VectorX start, delta;       ///< one per hinge [rad]
    std::function<double(double)> factor;  ///< of t [s]; empty: 1
  };
  std::vector<Term> terms;

  bool empty() const { return terms.empty(); }
};

struct TimeIntegrationOptions {
  NewtonOptions newton;
  double time_step = 1e-4;   ///< dt [s]
  double duration = 0.1;     ///< [s]
  double hht_alpha = 0.0;    ///< in [-1/3, 0]; 0: average acceleration (Newmark)
  double mass_damping = 0.0;       ///< Rayleigh alpha [1/s]
  double stiffness_damping = 0.0;  ///< Rayleigh beta [s]
  /// The stiffness in the damping: false K0, the tangent at the start; true the tangent at
  /// each step's start.
  bool damping_current_tangent = false;
  RestAngleSchedule actuation;  ///< creases driven in time (none: empty)
  int max_halvings = 10;     ///< a failed step is halved up to this many times
  double shift = 0.0;        ///< diagonal shift of the effective tangent (the mass term
                             ///< makes it definite; 0 keeps the equations exact)
  StopRule stop;
};

struct TimeHistory {
  PathResult path;               ///< load_factor: the time [s]; displacement per step
  std::vector<VectorX> velocity;  ///< per step [mm/s]
  std::vector<double> kinetic;    ///< 1/2 v^T M v per step [N mm]
  std::vector<double> strain;     ///< the model's stored energy per step [N mm]
  std::vector<double> dissipated; ///< damping's dissipated energy up to each step [N mm]
  std::vector<double> work;       ///< the loads' work up to each step [N mm]
  /// The work the driven creases' rest angles have done up to each step [N mm] (0 without
  /// an actuation).
  std::vector<double> actuation_work;
  /// Explicit integration: the stable step at the start [s] (stable_time_step.hpp) and
  /// the step taken; implicit: 0 and the nominal step.
  double stable_time_step = 0.0;
  double time_step = 0.0;
};

/// A load in time: the sum of its terms' forces (one entry per DOF [N]) times their
/// factor(t) (an empty factor: 1), e.g. a step on one node and a harmonic on another.
struct TimeLoad {
  struct Term {
    VectorX forces;
    std::function<double(double)> factor;
  };
  std::vector<Term> terms;

  /// The load at t [N], n entries (zero without terms); throws std::invalid_argument when
  /// a factor is not finite.
  VectorX at(double t, Index n) const;
  /// The same into `out` (resized to n entries), which a run reuses from step to step.
  void at(double t, Index n, VectorX& out) const;
};

/// The checks every integrator makes of its input: masses, each load term's forces, u0 and
/// v0 (u0, v0 may be empty) one finite entry per DOF, and a mass > 0 at every free DOF.
/// Throws std::invalid_argument.
void check_motion_input(const model::Model& model, const VectorX& masses, const TimeLoad& load,
                        const VectorX& u0, const VectorX& v0);

/// Integrate from (u0, v0) (empty: zero) under the load `forces` (one entry per DOF, [N])
/// times `load_factor(t)` (empty: 1), with lumped masses `masses` (one per DOF [t], > 0 at
/// every free DOF). Throws std::invalid_argument for bad input.
TimeHistory integrate_newmark(const model::Model& model, const VectorX& masses,
                              const VectorX& forces, const std::function<double(double)>& load_factor,
                              const TimeIntegrationOptions& options, const VectorX& u0 = VectorX(),
                              const VectorX& v0 = VectorX());
/// The same under a load of several terms (TimeLoad).
TimeHistory integrate_newmark(const model::Model& model, const VectorX& masses,
                              const TimeLoad& load, const TimeIntegrationOptions& options,
                              const VectorX& u0 = VectorX(), const VectorX& v0 = VectorX());

}  // namespace kresling::solvers
