#include "kresling/solvers/explicit_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "kresling/assembly/assembler.hpp"
#include "kresling/core/check.hpp"
#include "kresling/core/interrupt.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/path_follower.hpp"
#include "kresling/solvers/stable_time_step.hpp"
#include "kresling/solvers/time_control.hpp"
#include "kresling/solvers/time_steps.hpp"

namespace kresling::solvers {

namespace {

// Steps of the run: the duration in whole steps of at most time_step.
long long step_count(const ExplicitOptions& o) {
  require_positive("time_step", o.time_step);
  require_positive("duration", o.duration);
  const double steps = std::ceil(o.duration / o.time_step * (1.0 - 1e-12));
  if (!(steps <= static_cast<double>(kMaxExplicitSteps))) {
    throw std::invalid_argument("duration / time_step = " + format_number(o.duration / o.time_step) +
                                " steps: at most " + std::to_string(kMaxExplicitSteps));
  }
  require_integer_in("record_every", o.record_every, 1, kMaxExplicitSteps);
  const long long n = std::max(1LL, static_cast<long long>(steps));
  if ((n + o.record_every - 1) / o.record_every > kMaxSteps) {
    throw std::invalid_argument("record_every = " + std::to_string(o.record_every) + " keeps " +
                                std::to_string((n + o.record_every - 1) / o.record_every) +
                                " of the " + std::to_string(n) + " steps: at most " +
                                std::to_string(kMaxSteps) + " (raise record_every)");
  }
  return n;
}

// A barrier limits each step; the explicit update takes whole steps.
void refuse_barriers(const model::Model& model) {
  for (const auto& family : model.families()) {
    if (family->limits_steps()) {
      throw std::invalid_argument(std::string("the model's ") + family->name() + " elements " +
                                  "limit each step (a barrier): explicit integration cannot " +
                                  "keep them; use an implicit scheme");
    }
  }
}

void refuse_unstable(const ExplicitOptions& o, const StableStep& stable) {
  if (o.time_step <= stable.time_step) return;
  throw std::invalid_argument(
      "time_step = " + format_number(o.time_step) + " s is above the explicit scheme's stable " +
      "step " + format_number(stable.time_step) + " s (the highest natural frequency is " +
      format_number(stable.omega_max) + " rad/s at the start): must be at most the stable " +
      "step, or use an implicit scheme");
}

// Time as the path parameter of the central differences: each increment is a group of
// steps (up to the next recorded one), taken by the corrector with one internal-force
// evaluation each (the workspace assembles every DOF, for the supports' reactions).
// An explicit step cannot be retried smaller, so the corrector moves the scheme's state
// (half-step velocity, load, energies) on as it goes; a step whose state stops being
// finite or whose energy grew past kEnergyGrowthLimit times what was put in fails the
// increment, which ends the run, and is kept as its last recorded step (stopped_step).
class CentralDifferenceControl final : public TimeControl {
 public:
  CentralDifferenceControl(const model::Model& model, const TimeLoad& load,
                           const VectorX& masses, const ExplicitOptions& options,
                           const FixedTimeSteps& steps, double dt, VectorX inverse_mass,
                           const assembly::SparseMatrix& k0)
      : TimeControl(model, load), o_(options), steps_(steps), dt_(dt), masses_(masses),
        inverse_mass_(std::move(inverse_mass)), k0_(k0) {}

  // The start (u, v) with the internal force and energies at u: the first half step.
  void start(const VectorX& v, const VectorX& force, const assembly::Energies& energies) {
    const Index n = model_.num_dofs();
    force_ = force;
    energies_ = energies;
    load_now_ = load_.at(0.0, n);
    next_load_.resize(n);
    cv_.resize(n);
    kv_.resize(n);
    damping(v);
    a_ = inverse_mass_.cwiseProduct(load_now_ - force_ - cv_);
    half_ = v + 0.5 * dt_ * a_;  // v_{1/2}
    const double start_energy = 0.5 * v.dot(masses_.cwiseProduct(v)) + energies_.total();
    put_in_ = std::abs(start_energy);
  }

  // The steps of the increment, from the accepted u (trial, updated in place).
  NewtonOutcome correct(Increment& increment, assembly::Assembler& assembler,
                        TangentSolver&, VectorX& u, const VectorX&, const NewtonOptions&, int,
                        ExtraTerms*) override {
    NewtonOutcome out;
    const long long last = k_ + static_cast<long long>(increment.size);
    while (k_ < last) {
      ++k_;
      if ((k_ & 63) == 0) check_interrupt();
      const double t = steps_.time_at(k_);
      u.noalias() += dt_ * half_;
      energies_ = assembler.assemble(u, force_, false);
      load_.at(t, model_.num_dofs(), next_load_);
      const double dw = 0.5 * dt_ * half_.dot(load_now_ + next_load_);
      work_ += dw;
      put_in_ += std::abs(dw);
      damping(half_);
      dissipated_ += dt_ * half_.dot(cv_);
      a_ = inverse_mass_.cwiseProduct(next_load_ - force_ - cv_);
      v_ = half_ + 0.5 * dt_ * a_;
      half_ = v_ + 0.5 * dt_ * a_;
      load_now_.swap(next_load_);
      kinetic_ = 0.5 * v_.dot(masses_.cwiseProduct(v_));
      const double strain = energies_.total();
      const bool finite = std::isfinite(kinetic_) && std::isfinite(strain) && u.allFinite();
      // The energy at a whole step is half a step ahead of the work summed so far (v_n
      // holds dt a_n / 2 of the current load): that half step's work is in play too.
      const double ahead = 0.5 * dt_ * std::abs(v_.dot(load_now_));
      const bool grown = kinetic_ + strain > kEnergyGrowthLimit * (put_in_ + ahead);
      if (!finite || grown) {
        stopped_step = step_at(t, u);
        record_motion(v_, kinetic_, strain, dissipated_, work_);
        out.failure = "unstable at t = " + format_rounded(t) + " s: " +
                      (finite ? "the energy grew to " + format_rounded(kinetic_ + strain) +
                                    " N mm, over " + format_rounded(kEnergyGrowthLimit) +
                                    " times the " + format_rounded(put_in_ + ahead) +
                                    " N mm put in (the tangent stiffened beyond the start's "
                                    "stable step: take a smaller time_step)"
                              : std::string("the state is not finite"));
        return out;
      }
    }
    out.converged = true;
    return out;
  }

  // The step just taken, from its own evaluation (no second assembly).
  PathStep record(assembly::Assembler&, const VectorX& u, double t, const NewtonOutcome&,
                  const std::vector<Index>&, double, VectorX&) override {
    return step_at(t, u);
  }

  void accepted(const Increment&, const VectorX&, const PathStep&, const VectorX&) override {
    record_motion(v_, kinetic_, energies_.total(), dissipated_, work_);
  }

  /// Steps taken.
  long long steps_taken() const { return k_; }
  /// The step that ended the run as unstable, if one did.
  std::optional<PathStep> stopped_step;

 private:
  void damping(const VectorX& velocity) {
    cv_.noalias() = o_.mass_damping * masses_.cwiseProduct(velocity);
    if (o_.stiffness_damping != 0.0) {
      kv_.noalias() = k0_.selfadjointView<Eigen::Lower>() * velocity;
      cv_ += o_.stiffness_damping * kv_;
    }
  }
  PathStep step_at(double t, const VectorX& u) const {
    PathStep step;
    step.load_factor = t;
    step.displacement = u;
    step.constraint_force.resize(static_cast<Index>(supported_.size()));
    for (std::size_t i = 0; i < supported_.size(); ++i) {
      step.constraint_force[static_cast<Index>(i)] = force_[supported_[i]];
    }
    step.energies = energies_.vector();
    return step;
  }

  const ExplicitOptions& o_;
  const FixedTimeSteps& steps_;
  double dt_;
  const VectorX& masses_;
  VectorX inverse_mass_;
  const assembly::SparseMatrix& k0_;
  long long k_ = 0;
  VectorX force_, load_now_, next_load_, cv_, kv_, a_, v_, half_;
  assembly::Energies energies_;
  double kinetic_ = 0.0, work_ = 0.0, dissipated_ = 0.0, put_in_ = 0.0;
};

}  // namespace

TimeHistory integrate_explicit(const model::Model& model, const VectorX& masses,
                               const TimeLoad& time_load, const ExplicitOptions& o, const VectorX& u0, const VectorX& v0) {
  const long long steps = step_count(o);
  require_positive("mass_damping", o.mass_damping, /*allow_zero=*/true);
  require_positive("stiffness_damping", o.stiffness_damping, /*allow_zero=*/true);
  check_motion_input(model, masses, time_load, u0, v0);
  refuse_barriers(model);
  const Index n = model.num_dofs();
  VectorX u = u0.size() ? u0 : VectorX::Zero(n), v = v0.size() ? v0 : VectorX::Zero(n);
  VectorX inverse_mass = VectorX::Zero(n);
  for (Index i = 0; i < n; ++i) {
    if (model.fixed()[i]) {
      u[i] = v[i] = 0.0;
    } else {
      inverse_mass[i] = 1.0 / masses[i];
    }
  }
  StableStep stable;
  try {
    stable = stable_time_step(model, masses, u, o.mass_damping, o.stiffness_damping);
  } catch (const std::invalid_argument& error) {  // name the start, as the caller gave it
    throw std::invalid_argument(std::string("initial displacement: ") + error.what());
  }
  refuse_unstable(o, stable);
  const double dt = o.duration / static_cast<double>(steps);

  // Every DOF assembled (the supports' reactions are recorded); the tangent only once, for
  // the stiffness-proportional damping K0.
  assembly::Workspace workspace(model, assembly::all_dofs(n), 0.0, assembly::Storage::Lower);
  assembly::Assembler assembler(model, workspace);
  VectorX force;
  const assembly::Energies energies = assembler.assemble(u, force, o.stiffness_damping != 0.0);
  const assembly::SparseMatrix k0 = o.stiffness_damping != 0.0 ? assembler.matrix()
                                                               : assembly::SparseMatrix();
  FixedTimeSteps policy(steps, o.duration, o.record_every);
  CentralDifferenceControl control(model, time_load, masses, o, policy, dt,
                                   std::move(inverse_mass), k0);
  control.start(v, force, energies);
  TangentSolver unused;  // no solves: the corrector is the explicit update
  FollowOptions follow;
  follow.stop = o.stop;
  PathResult path;
  follow_path(control, assembler, unused, u, policy, follow, path);
  // The history counts steps, not the increments (recorded steps) the follower counted.
  path.attempted_increments = static_cast<int>(std::min<long long>(control.steps_taken(),
                                                                   2147483647LL));
  if (control.stopped_step) {
    path.steps.push_back(std::move(*control.stopped_step));
    path.failed_increment = path.attempted_increments;
  }
  TimeHistory h = std::move(control.history);
  h.path = std::move(path);
  h.stable_time_step = stable.time_step;
  h.time_step = dt;
  return h;
}

}  // namespace kresling::solvers
