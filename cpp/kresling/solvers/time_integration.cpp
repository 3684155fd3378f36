#include "kresling/solvers/time_integration.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "kresling/assembly/assembler.hpp"
#include "kresling/core/check.hpp"
#include "kresling/core/interrupt.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/path_follower.hpp"
#include "kresling/solvers/time_control.hpp"
#include "kresling/solvers/time_steps.hpp"

namespace kresling::solvers {

namespace {

// The converged state at the start of a step.
struct StepStart {
  double t = 0.0;
  VectorX u, v, a;      // displacement, velocity, acceleration (all DOFs)
  VectorX internal;     // f_int(u)
  VectorX damping;      // C v
  VectorX load;         // f(t)
};

// The inertia and damping of one step of size dt from `start`, as terms added to the
// model's equilibrium: Newton then solves the step's effective equation (time_integration.hpp).
class StepTerms final : public ExtraTerms {
 public:
  StepTerms(const StepStart& start, double alpha, double beta, double gamma,
            const VectorX& masses, double mass_damping, double stiffness_damping,
            const assembly::SparseMatrix& k0_full, const std::vector<double>& k0_values)
      : s_(start), alpha_(alpha), beta_(beta), gamma_(gamma), m_(masses),
        am_(mass_damping), bk_(stiffness_damping), k0_(k0_full), k0_values_(k0_values) {}

  /// The step the terms are for [s].
  void set_step(double dt) { dt_ = dt; }

  // The acceleration, velocity and damping force at u, into a, v and c (buffers the
  // caller keeps from step to step: a Newton iterate allocates nothing here).
  void acceleration(const VectorX& u, VectorX& a) const {
    a = (u - s_.u - dt_ * s_.v) / (beta_ * dt_ * dt_) - (0.5 / beta_ - 1.0) * s_.a;
  }
  void velocity(const VectorX& a, VectorX& v) const {
    v = s_.v + dt_ * ((1.0 - gamma_) * s_.a + gamma_ * a);
  }
  void damping_force(const VectorX& v, VectorX& c) {
    c = am_ * m_.cwiseProduct(v);
    if (bk_ != 0.0) {
      kv_.noalias() = k0_.selfadjointView<Eigen::Lower>() * v;
      c += bk_ * kv_;
    }
  }

  void add_force(const VectorX& u, VectorX& force) override {
    acceleration(u, a_);
    velocity(a_, v_);
    damping_force(v_, c_);
    force = (1.0 + alpha_) * (force + c_) + m_.cwiseProduct(a_) -
            alpha_ * (s_.internal + s_.damping);
  }
  void add_tangent(const VectorX&, assembly::Workspace& w) override {
    const double c0 = 1.0 / (beta_ * dt_ * dt_), c1 = gamma_ / (beta_ * dt_);
    w.scale_matrix(1.0 + alpha_);
    w.add_to_diagonal((c0 + (1.0 + alpha_) * c1 * am_) * m_);
    if (bk_ != 0.0) w.add_matrix_values(k0_values_, (1.0 + alpha_) * c1 * bk_);
  }

 private:
  const StepStart& s_;
  double dt_ = 1.0, alpha_, beta_, gamma_;
  const VectorX& m_;
  double am_, bk_;
  const assembly::SparseMatrix& k0_;
  const std::vector<double>& k0_values_;
  VectorX a_, v_, c_, kv_;  // add_force's buffers
};

// The stiffness of the damping at u in `model`: of every DOF into `k` (for C v, through the
// workspace `full`) and in the assembler's pattern into `values` (its share of the step's
// tangent); the internal force at u into `force`.
void damping_stiffness(const model::Model& model, assembly::Workspace& full,
                       assembly::Assembler& assembler, const VectorX& u, VectorX& force,
                       assembly::SparseMatrix& k, std::vector<double>& values) {
  assembly::assemble(model, full, u, force, true);
  k = full.matrix();
  assembler.assemble(u, force, true);
  values.assign(assembler.matrix().valuePtr(),
                assembler.matrix().valuePtr() + assembler.matrix().nonZeros());
}

// The damping matrix bk K0 is added in the tangent's first pattern, which changes as
// contact pairs come and go.
void refuse_stiffness_damping_with_changing_elements(const model::Model& model,
                                                     const TimeIntegrationOptions& options) {
  for (const auto& family : model.families()) {
    if (family->changes_elements() && options.stiffness_damping != 0.0) {
      throw std::invalid_argument(
          "stiffness_damping = " + format_number(options.stiffness_damping) + " is invalid "
          "with the element family " + family->name() + ": must be 0 (use mass_damping)");
    }
  }
}

void check_options(const TimeIntegrationOptions& o) {
  check_newton(o.newton);
  require_positive("time_step", o.time_step);
  require_positive("duration", o.duration);
  if (o.duration / o.time_step > kMaxSteps) {
    throw std::invalid_argument("duration / time_step = " + format_number(o.duration / o.time_step) +
                                " steps: at most " + std::to_string(kMaxSteps) +
                                " (the history keeps every step)");
  }
  require_finite("hht_alpha", o.hht_alpha);
  if (!(o.hht_alpha >= -1.0 / 3.0 && o.hht_alpha <= 0.0)) {
    throw_invalid("hht_alpha", o.hht_alpha, "in [-1/3, 0] (0: Newmark's average acceleration)");
  }
  require_positive("mass_damping", o.mass_damping, /*allow_zero=*/true);
  require_positive("stiffness_damping", o.stiffness_damping, /*allow_zero=*/true);
  require_integer_in("max_halvings", o.max_halvings, 0, kMaxBisections);
  check_shift(o.shift);
}

// x (zero when empty) with the supported DOFs at zero.
VectorX held_at_zero(const model::Model& model, const VectorX& x) {
  VectorX out = x.size() ? x : VectorX::Zero(model.num_dofs());
  for (Index i = 0; i < out.size(); ++i) {
    if (model.fixed()[i]) out[i] = 0.0;
  }
  return out;
}

// Chord iterations a step tries with the factorisation kept from an earlier step before it
// refactorises (Newton's method).
constexpr int kChordIterations = 6;

// Time as the path parameter of Newmark's and HHT-alpha's steps: each increment is a step
// of dt = increment.size from the accepted state `s_` (displacement, velocity,
// acceleration), started at Newmark's predictor, with the step's inertia and damping as
// extra terms; an accepted step moves the state on and records its motion and energies.
// With the damping of the current tangent, an accepted step's tangent (recorded with it)
// becomes the damping's stiffness for the next step; with an actuation, the rest angles at
// the step's end are the model's (TimeControl::model_at) and the step's work of the
// actuation is added up (time_integration.hpp).
class NewmarkControl final : public TimeControl {
 public:
  NewmarkControl(const model::Model& model, const TimeLoad& load, const VectorX& masses,
                 const TimeIntegrationOptions& options, StepStart start,
                 assembly::SparseMatrix k0, std::vector<double> k0_values,
                 assembly::Workspace* full)
      : TimeControl(model, load, options.actuation),
        k_(std::move(k0)),
        k_values_(std::move(k0_values)),
        full_(options.damping_current_tangent ? full : nullptr),
        s_(std::move(start)),
        alpha_(options.hht_alpha),
        beta_(0.25 * (1.0 - alpha_) * (1.0 - alpha_)),
        gamma_(0.5 - alpha_),
        masses_(masses),
        terms_(s_, alpha_, beta_, gamma_, masses, options.mass_damping,
               options.stiffness_damping, k_, k_values_),
        // A model whose elements limit each correction (a barrier) takes Newton's own
        // iterations, which respect the limits, every step.
        chords_allowed_(!families_limit_steps(model)),
        hinge_energy_(driven_.hinge_energy(s_.t, s_.u)) {}

  // The step's state, and (damping of the current tangent) its tangent for the next step.
  PathStep record(assembly::Assembler& assembler, const VectorX& u, double t,
                  const NewtonOutcome& outcome, const std::vector<Index>& recorded,
                  double sign, VectorX& internal) override {
    PathStep step = PathControl::record(assembler, u, t, outcome, recorded, sign, internal);
    if (full_) {
      damping_stiffness(assembler.model(), *full_, assembler, u, next_force_, next_k_,
                        next_k_values_);
    }
    return step;
  }

  // The step's external force (1 + alpha) f(t_{n+1}) - alpha f(t_n) and its predictor.
  void advance(const Increment& increment, const VectorX&, VectorX& u,
               VectorX& external) override {
    const double dt = increment.size;
    load_.at(increment.to, model_.num_dofs(), next_load_);
    external = (1.0 + alpha_) * next_load_ - alpha_ * s_.load;
    u = s_.u + dt * s_.v + (0.5 - beta_) * dt * dt * s_.a;  // the step's predictor
    // A predictor beyond a barrier would leave Newton on its far side.
    shorten_to_barriers(model_, s_.u, u);
  }

  ExtraTerms* extra_terms(const Increment& increment) override {
    terms_.set_step(increment.size);
    return &terms_;
  }

  // One step's equilibrium from the predictor u. The effective tangent (K + M / (beta
  // dt^2) + damping) changes little from step to step, so when the solver holds the
  // factorisation an earlier step of the same dt left, the step first iterates with it
  // (chord iterations: a force evaluation and a solve each, no assembly of the tangent, no
  // factorisation); as soon as a correction shrinks less than by half (the tangent has
  // drifted) or after kChordIterations, Newton's method takes over from there. A chord
  // correction below the tolerance ends the step: its contraction (below 1/2) leaves an
  // error smaller than the correction itself.
  NewtonOutcome correct(Increment& increment, assembly::Assembler& assembler,
                        TangentSolver& solver, VectorX& u, const VectorX& external,
                        const NewtonOptions& options, int, ExtraTerms* extra) override {
    const double dt = increment.size;
    int chords = 0;
    if (chords_allowed_ && factorised_dt_ == dt) {
      VectorX& force = chord_force_;
      VectorX& trial = chord_trial_;
      trial = u;
      double previous = INFINITY;
      while (chords < std::min(kChordIterations, options.max_iterations - 1)) {
        check_interrupt();
        assembler.assemble(trial, force, /*with_matrix=*/false);
        extra->add_force(trial, force);
        const VectorX du = solver.solve(gather_rows(assembler, external - force));
        const double size = du.norm();
        if (!std::isfinite(size) || size > 0.5 * previous) break;
        ++chords;
        scatter_add_rows(assembler, du, trial);
        u = trial;
        if (size <= options.tolerance) {
          NewtonOutcome out;
          out.converged = true;
          out.iterations = chords;
          out.negative_eigenvalues = negative_;
          return out;
        }
        previous = size;
      }
    }
    NewtonOutcome out = newton_equilibrium(assembler, solver, u, external, options,
                                           options.max_iterations - chords, extra);
    out.iterations += chords;
    // The solver now holds a factorisation of this dt's tangent, and its stability is the
    // step's; a failed step leaves none worth keeping.
    factorised_dt_ = out.converged ? dt : 0.0;
    negative_ = out.negative_eigenvalues;
    return out;
  }

  // Energy balance of the step (exact for the average acceleration scheme on linear
  // models): u_{n+1} - u_n times the mean damping and external forces.
  void accepted(const Increment& increment, const VectorX& u, const PathStep& step,
                const VectorX& internal) override {
    terms_.acceleration(u, a_);
    terms_.velocity(a_, v_);
    terms_.damping_force(v_, damping_);
    du_ = u - s_.u;
    dissipated_ += 0.5 * du_.dot(s_.damping + damping_);
    work_ += 0.5 * du_.dot(s_.load + next_load_);
    if (driven_.driven()) {
      const double end = driven_.hinge_energy(increment.to, u);
      actuation_work_ += 0.5 * (driven_.hinge_energy(increment.to, s_.u) - hinge_energy_ +
                                end - driven_.hinge_energy(s_.t, u));
      hinge_energy_ = end;
    }
    if (full_) {  // the next step's damping stiffness: this step's end tangent
      k_.swap(next_k_);
      k_values_.swap(next_k_values_);
      // The factorisation held is of the damping this step had: chord iterations with it
      // would converge only linearly, Newton's iterations take over from the start.
      factorised_dt_ = 0.0;
    }
    s_.t = increment.to;
    s_.u = u;
    s_.v.swap(v_);
    s_.a.swap(a_);
    s_.internal = internal;
    s_.damping.swap(damping_);
    s_.load.swap(next_load_);
    record_motion(s_.v, 0.5 * s_.v.dot(masses_.cwiseProduct(s_.v)), step.energy(), dissipated_,
                  work_, actuation_work_);
  }

 private:
  assembly::SparseMatrix k_;       // the damping's stiffness (K0, or the step start's tangent)
  std::vector<double> k_values_;   // the same in the solver's pattern
  assembly::Workspace* full_;      // every DOF's tangent, for the current tangent's damping
  assembly::SparseMatrix next_k_;  // the recorded step's tangent, its values and force
  std::vector<double> next_k_values_;
  VectorX next_force_;
  StepStart s_;
  double alpha_, beta_, gamma_;
  const VectorX& masses_;
  StepTerms terms_;
  bool chords_allowed_;
  VectorX next_load_;         // f(t_{n+1}) of the step under way
  VectorX a_, v_, damping_, du_;  // an accepted step's, kept to allocate nothing per step
  VectorX chord_force_, chord_trial_;  // the chord iterations
  double factorised_dt_ = 0;  // the dt whose effective tangent the solver holds (0: none)
  int negative_ = -1;         // the stability that factorisation reported
  double dissipated_ = 0.0, work_ = 0.0, actuation_work_ = 0.0;
  double hinge_energy_;  // the hinges' energy at the step's start (an actuation's work)
};

}  // namespace

void check_motion_input(const model::Model& model, const VectorX& masses, const TimeLoad& load,
                        const VectorX& u0, const VectorX& v0) {
  const Index n = model.num_dofs();
  auto check_vector = [&](const char* name, const VectorX& x, bool allow_empty) {
    if ((allow_empty && x.size() == 0)) return;
    if (x.size() != n || !x.allFinite()) {
      throw std::invalid_argument(std::string(name) + ": must have one finite entry per DOF (" +
                                  std::to_string(n) + ")");
    }
  };
  check_vector("masses", masses, false);
  for (const auto& term : load.terms) check_vector("forces", term.forces, false);
  check_vector("initial displacement", u0, true);
  check_vector("initial velocity", v0, true);
  for (Index i = 0; i < n; ++i) {
    if (!model.fixed()[i] && !(masses[i] > 0.0)) {
      throw std::invalid_argument("masses: DOF " + std::to_string(i) + " (node " +
                                  std::to_string(i / 3) + ") is free and has mass " +
                                  format_number(masses[i]) + ": every free DOF needs a mass > 0");
    }
  }
}

VectorX TimeLoad::at(double t, Index n) const {
  VectorX out;
  at(t, n, out);
  return out;
}

void TimeLoad::at(double t, Index n, VectorX& out) const {
  out.setZero(n);
  for (const auto& term : terms) {
    const double f = term.factor ? term.factor(t) : 1.0;
    if (!std::isfinite(f)) throw std::invalid_argument("load_factor: not finite at t = " + format_number(t));
    out += f * term.forces;
  }
}

TimeHistory integrate_newmark(const model::Model& model, const VectorX& masses,
                              const VectorX& forces, const std::function<double(double)>& load_factor,
                              const TimeIntegrationOptions& options, const VectorX& u0,
                              const VectorX& v0) {
  return integrate_newmark(model, masses, TimeLoad{{{forces, load_factor}}}, options, u0, v0);
}

TimeHistory integrate_newmark(const model::Model& model, const VectorX& masses,
                              const TimeLoad& time_load, const TimeIntegrationOptions& options,
                              const VectorX& u0, const VectorX& v0) {
  check_options(options);
  check_motion_input(model, masses, time_load, u0, v0);
  refuse_stiffness_damping_with_changing_elements(model, options);
  const Index n = model.num_dofs();
  // The start's rest angles (the model's own without an actuation).
  DrivenRestAngles driven(model, options.actuation);
  const model::Model& start_model = driven.model_at(0.0);
  assembly::Assembler assembler(model, assembly::unmasked_dofs(model.fixed()), options.shift,
                                assembly::Storage::Lower);
  assembler.rebind(start_model);
  TangentSolver solver(options.newton.cholesky);
  StepStart s;
  s.u = held_at_zero(model, u0);
  s.v = held_at_zero(model, v0);
  // Stiffness-proportional damping needs the initial stiffness: of every DOF (for C v) and
  // in the solver's pattern (its share of the tangent). Without it neither is built (a
  // workspace of every DOF and two tangent assemblies: a small model's run pays for them
  // as for several steps).
  const bool stiffness_damped = options.stiffness_damping != 0.0;
  VectorX force;
  assembly::SparseMatrix k0;
  std::vector<double> k0_values;
  std::optional<assembly::Workspace> full;
  if (stiffness_damped) {
    full.emplace(model, assembly::all_dofs(n), 0.0, assembly::Storage::Lower);
    damping_stiffness(start_model, *full, assembler, s.u, force, k0, k0_values);
  } else {
    assembler.assemble(s.u, force, false);
  }
  s.internal = force;
  s.load = time_load.at(0.0, n);
  s.damping = options.mass_damping * masses.cwiseProduct(s.v);
  if (stiffness_damped) {
    const VectorX kv = k0.selfadjointView<Eigen::Lower>() * s.v;
    s.damping += options.stiffness_damping * kv;
  }
  // a0 from the equation of motion at the start, M a0 = f(0) - C v0 - f_int(u0).
  s.a = VectorX::Zero(n);
  for (Index i = 0; i < n; ++i) {
    if (!model.fixed()[i]) s.a[i] = (s.load[i] - s.damping[i] - s.internal[i]) / masses[i];
  }
  VectorX u = s.u;
  NewmarkControl control(model, time_load, masses, options, std::move(s), std::move(k0),
                         std::move(k0_values), full ? &*full : nullptr);
  HalvedTimeSteps policy(options.time_step, options.duration, options.max_halvings);
  FollowOptions follow;
  follow.newton = options.newton;
  follow.stop = options.stop;
  PathResult path;
  follow_path(control, assembler, solver, u, policy, follow, path);
  TimeHistory h = std::move(control.history);
  h.path = std::move(path);
  h.time_step = options.time_step;
  return h;
}

}  // namespace kresling::solvers
