#include "kresling/solvers/time_integration.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "kresling/assembly/assembler.hpp"
#include "kresling/core/check.hpp"
#include "kresling/core/interrupt.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/rigid_body.hpp"

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
  StepTerms(const StepStart& start, double dt, double alpha, double beta, double gamma,
            const VectorX& masses, double mass_damping, double stiffness_damping,
            const assembly::SparseMatrix& k0_full, const std::vector<double>& k0_values)
      : s_(start), dt_(dt), alpha_(alpha), beta_(beta), gamma_(gamma), m_(masses),
        am_(mass_damping), bk_(stiffness_damping), k0_(k0_full), k0_values_(k0_values) {}

  VectorX acceleration(const VectorX& u) const {
    return (u - s_.u - dt_ * s_.v) / (beta_ * dt_ * dt_) - (0.5 / beta_ - 1.0) * s_.a;
  }
  VectorX velocity(const VectorX& a) const {
    return s_.v + dt_ * ((1.0 - gamma_) * s_.a + gamma_ * a);
  }
  VectorX damping_force(const VectorX& v) const {
    VectorX c = am_ * m_.cwiseProduct(v);
    if (bk_ != 0.0) {
      const VectorX kv = k0_.selfadjointView<Eigen::Lower>() * v;
      c += bk_ * kv;
    }
    return c;
  }

  void add_force(const VectorX& u, VectorX& force) override {
    const VectorX a = acceleration(u);
    const VectorX v = velocity(a);
    force = (1.0 + alpha_) * (force + damping_force(v)) + m_.cwiseProduct(a) -
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
  double dt_, alpha_, beta_, gamma_;
  const VectorX& m_;
  double am_, bk_;
  const assembly::SparseMatrix& k0_;
  const std::vector<double>& k0_values_;
};

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

// Chord iterations a step tries with the factorisation kept from an earlier step before it
// refactorises (Newton's method).
constexpr int kChordIterations = 6;

// One step's equilibrium from the predictor u. The effective tangent (K + M / (beta dt^2)
// + damping) changes little from step to step, so with `reuse` the step first iterates
// with the factorisation an earlier step of the same dt left in `solver` (chord
// iterations: a force evaluation and a solve each, no assembly of the tangent, no
// factorisation); as soon as a correction shrinks less than by half (the tangent has
// drifted) or after kChordIterations, Newton's method takes over from there. A chord
// correction below the tolerance ends the step: its contraction (below 1/2) leaves an
// error smaller than the correction itself.
NewtonOutcome solve_step(assembly::Assembler& assembler, TangentSolver& solver, VectorX& u,
                         const VectorX& external, const NewtonOptions& options,
                         StepTerms& terms, bool reuse, bool& refactorised) {
  int chords = 0;
  refactorised = false;
  if (reuse) {
    VectorX force, trial = u;
    double previous = INFINITY;
    while (chords < std::min(kChordIterations, options.max_iterations - 1)) {
      check_interrupt();
      assembler.assemble(trial, force, /*with_matrix=*/false);
      terms.add_force(trial, force);
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
        return out;
      }
      previous = size;
    }
  }
  refactorised = true;
  NewtonOutcome out = newton_equilibrium(assembler, solver, u, external, options,
                                         options.max_iterations - chords, &terms);
  out.iterations += chords;
  return out;
}

// Whether a model's elements limit Newton's corrections (a barrier): its steps then take
// Newton's own iterations, which respect the limits, every time.
bool limits_steps(const model::Model& model) {
  for (const auto& family : model.families()) {
    if (family->limits_steps()) return true;
  }
  return false;
}

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
  VectorX out = VectorX::Zero(n);
  for (const auto& term : terms) {
    const double f = term.factor ? term.factor(t) : 1.0;
    if (!std::isfinite(f)) throw std::invalid_argument("load_factor: not finite at t = " + format_number(t));
    out += f * term.forces;
  }
  return out;
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
  for (const auto& family : model.families()) {
    // The damping matrix bk K0 is added in the tangent's first pattern, which changes as
    // contact pairs come and go.
    if (family->changes_elements() && options.stiffness_damping != 0.0) {
      throw std::invalid_argument(
          "stiffness_damping = " + format_number(options.stiffness_damping) + " is invalid "
          "with the element family " + family->name() + ": must be 0 (use mass_damping)");
    }
  }
  const Index n = model.num_dofs();

  const double alpha = options.hht_alpha;
  const double beta = 0.25 * (1.0 - alpha) * (1.0 - alpha), gamma = 0.5 - alpha;
  assembly::Assembler assembler(model, assembly::unmasked_dofs(model.fixed()), options.shift,
                                assembly::Storage::Lower);
  TangentSolver solver(options.newton.cholesky);

  StepStart s;
  s.u = u0.size() ? u0 : VectorX::Zero(n);
  s.v = v0.size() ? v0 : VectorX::Zero(n);
  for (Index i = 0; i < n; ++i) {
    if (model.fixed()[i]) s.u[i] = s.v[i] = 0.0;
  }
  // The initial stiffness: of every DOF (for C v) and in the solver's pattern (its tangent).
  assembly::Workspace full(model, assembly::all_dofs(n), 0.0, assembly::Storage::Lower);
  VectorX force;
  assembly::assemble(model, full, s.u, force, true);
  const assembly::SparseMatrix k0 = full.matrix();
  assembler.assemble(s.u, force, true);
  const std::vector<double> k0_values(assembler.matrix().valuePtr(),
                                      assembler.matrix().valuePtr() + assembler.matrix().nonZeros());
  s.internal = force;
  s.load = time_load.at(0.0, n);
  {
    StepTerms none(s, 1.0, 0.0, 0.25, 0.5, masses, options.mass_damping, options.stiffness_damping,
                   k0, k0_values);
    s.damping = none.damping_force(s.v);
  }
  // a0 from the equation of motion at the start, M a0 = f(0) - C v0 - f_int(u0).
  s.a = VectorX::Zero(n);
  for (Index i = 0; i < n; ++i) {
    if (!model.fixed()[i]) s.a[i] = (s.load[i] - s.damping[i] - s.internal[i]) / masses[i];
  }

  TimeHistory h;
  h.time_step = options.time_step;
  std::vector<Index> supported;
  for (Index i = 0; i < n; ++i) {
    if (model.fixed()[i]) supported.push_back(i);
  }
  h.path.constraint_dofs = supported;
  h.path.families = family_names(model);
  auto kinetic = [&](const VectorX& v) { return 0.5 * v.dot(masses.cwiseProduct(v)); };
  double dissipated = 0.0, work = 0.0;

  const double nominal = options.time_step;
  const double smallest = std::ldexp(nominal, -options.max_halvings);
  double dt = nominal;
  const double end = options.duration;
  // The dt whose effective tangent the solver holds factorised (0: none), and the
  // stability that factorisation reported.
  double factorised_dt = 0.0;
  int negative = -1;
  const bool chords_allowed = !limits_steps(model);
  while (s.t < end * (1.0 - 1e-12)) {
    check_interrupt();
    dt = std::min(dt, end - s.t);
    ++h.path.attempted_increments;
    StepTerms terms(s, dt, alpha, beta, gamma, masses, options.mass_damping,
                    options.stiffness_damping, k0, k0_values);
    const double t_new = s.t + dt;
    const VectorX load = time_load.at(t_new, n);
    const VectorX external = (1.0 + alpha) * load - alpha * s.load;
    VectorX u = s.u + dt * s.v + (0.5 - beta) * dt * dt * s.a;  // the step's predictor
    if (!chords_allowed) {  // a predictor beyond a barrier would leave Newton on its far side
      u = s.u + std::min(1.0, barrier_step_fraction(model, s.u, u - s.u)) * (u - s.u);
    }
    bool refactorised = false;
    NewtonOutcome out = solve_step(assembler, solver, u, external, options.newton, terms,
                                   chords_allowed && factorised_dt == dt, refactorised);
    h.path.newton_iterations += out.iterations;
    if (refactorised) {  // the solver now holds a factorisation of this dt's tangent
      factorised_dt = dt;
      negative = out.negative_eigenvalues;
    }
    out.negative_eigenvalues = negative;
    PathStep step;
    if (out.converged) {
      step = record_step(assembler, u, t_new, out, supported, 1.0, &force);
      if (!finite_step(step)) {
        out.converged = false;
        out.failure = kStepNotFinite;
      }
    }
    if (!out.converged) {
      factorised_dt = 0.0;
      dt *= 0.5;
      if (dt < smallest) {
        h.path.failed_increment = h.path.attempted_increments;
        h.path.message = "time step at t = " + format_number(s.t) + " s failed after " +
                         std::to_string(options.max_halvings) + " halvings: " + out.failure;
        return h;
      }
      continue;
    }
    const VectorX a = terms.acceleration(u);
    const VectorX v = terms.velocity(a);
    // Energy balance of the step (exact for the average acceleration scheme on linear
    // models): u_{n+1} - u_n times the mean damping and external forces.
    const VectorX du = u - s.u;
    const VectorX damping = terms.damping_force(v);
    dissipated += 0.5 * du.dot(s.damping + damping);
    work += 0.5 * du.dot(s.load + load);
    s.t = t_new;
    s.u = u;
    s.v = v;
    s.a = a;
    s.internal = force;
    s.damping = damping;
    s.load = load;
    h.path.steps.push_back(std::move(step));
    h.velocity.push_back(v);
    h.kinetic.push_back(kinetic(v));
    h.strain.push_back(h.path.steps.back().energy());
    h.dissipated.push_back(dissipated);
    h.work.push_back(work);
    if (options.stop && options.stop(h.path.steps.back())) break;
    dt = std::min(2.0 * dt, nominal);  // grown back after a halving
  }
  h.path.completed = true;
  return h;
}

}  // namespace kresling::solvers
