#include "kresling/solvers/stable_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "kresling/core/check.hpp"
#include "kresling/core/interrupt.hpp"
#include "kresling/solvers/energy_minimum.hpp"
#include "kresling/solvers/newton.hpp"

namespace kresling::solvers {

namespace {

// The energy must fall by at least kAccept of the quadratic model's predicted fall for a
// step to be taken; a fall of at least kGood of it is a good step (the shift shrinks, the
// radius may grow), anything less shrinks the radius.
constexpr double kAccept = 0.1;
constexpr double kGood = 0.75;
constexpr double kShiftFactor = 4.0;
// Shifts relative to the tangent's largest diagonal entry: the first one tried where the
// tangent itself has no Cholesky (then raised by kShiftFactor until one exists), the one
// below which a shrinking shift becomes 0, and the largest tried.
constexpr double kFirstShift = 1e-6;
constexpr double kZeroShift = 1e-9;
constexpr double kLargestShift = 1e12;
// Inverse iterations for the most negative curvature's direction at a saddle, and the
// halvings of the step along it.
constexpr int kInverseIterations = 6;
constexpr int kEscapeHalvings = 12;
// Halvings of the shift towards the most negative eigenvalue before the inverse iterations.
constexpr int kTightenings = 30;
// The trust region's radius starts at the longest step and may grow to this many of it.
constexpr double kLongestRadius = 100.0;

struct State {
  double energy = 0.0;
  VectorX gradient;  // on the assembler's rows
  SparseMatrix tangent;
};

double work(const VectorX* external, const VectorX& u) {
  return external ? external->dot(u) : 0.0;
}

bool evaluate(assembly::Assembler& assembler, TangentSolver& solver, const VectorX& u,
              const VectorX* external, State& s) {
  VectorX force;
  s.energy = assembler.assemble(u, force, /*with_matrix=*/true).total() - work(external, u);
  s.gradient = gather_rows(assembler, external ? VectorX(force - *external) : force);
  follow_pattern(assembler, solver);
  s.tangent = assembler.matrix();
  return std::isfinite(s.energy) && s.gradient.allFinite();
}

double energy_at(assembly::Assembler& assembler, const VectorX& u, const VectorX* external) {
  VectorX force;
  return assembler.assemble(u, force, /*with_matrix=*/false).total() - work(external, u);
}

// u moved by `step` (on the assembler's rows).
VectorX moved(const assembly::Assembler& assembler, const VectorX& u, const VectorX& step) {
  VectorX out = u;
  scatter_add_rows(assembler, step, out);
  return out;
}

bool factorize_shifted(TangentSolver& solver, const SparseMatrix& K, double mu) {
  if (mu == 0.0) return solver.factorize(K, /*cholesky_only=*/true).ok;
  SparseMatrix shifted = K;
  shifted.diagonal().array() += mu;
  return solver.factorize(shifted, /*cholesky_only=*/true).ok;
}

// The smallest shift, halving from `mu` (whose Cholesky exists), at which K + shift I still
// has one; the solver is left holding that factorisation. Near it, K + shift I is nearly
// singular along the most negative curvature alone, which inverse iteration then finds in
// a few solves.
double tightest_shift(TangentSolver& solver, const SparseMatrix& K, double mu) {
  for (int k = 0; k < kTightenings; ++k) {
    if (!factorize_shifted(solver, K, 0.5 * mu)) break;
    mu *= 0.5;
  }
  factorize_shifted(solver, K, mu);
  return mu;
}

// At a saddle (no step, the tangent indefinite, its shifted Cholesky in `solver`): step
// along the most negative curvature's direction, found by inverse iteration, to lower
// energy. False when no such direction or no lower energy is found.
bool escape_saddle(assembly::Assembler& assembler, TangentSolver& solver, const State& s,
                   VectorX& u, const VectorX* external, double length, double& curvature) {
  const Index n = s.gradient.size();
  // A start with a component along every eigenvector (deterministic, not symmetric).
  VectorX x(n);
  for (Index i = 0; i < n; ++i) x[i] = std::sin(1.0 + 0.7 * static_cast<double>(i));
  for (int k = 0; k < kInverseIterations; ++k) {
    x = solver.solve(x);
    const double norm = x.norm();
    if (!(norm > 0.0) || !x.allFinite()) {
      curvature = NAN;
      return false;
    }
    x /= norm;
  }
  curvature = x.dot(s.tangent.selfadjointView<Eigen::Lower>() * x);
  if (!(curvature < 0.0)) return false;
  for (int k = 0; k < kEscapeHalvings; ++k, length *= 0.5) {
    const VectorX forward = moved(assembler, u, length * x);
    const VectorX backward = moved(assembler, u, -length * x);
    const double ef = energy_at(assembler, forward, external);
    const double eb = energy_at(assembler, backward, external);
    const double best =
        std::min(std::isfinite(ef) ? ef : INFINITY, std::isfinite(eb) ? eb : INFINITY);
    if (best < s.energy) {
      u = best == ef ? forward : backward;
      return true;
    }
  }
  return false;
}

// The energy at `trial` after one chord step (the factorisation in `solver`) from it, which
// `trial` is moved by when it lowers the energy: a step along a mechanism that is straight
// where the mechanism turns (a panel rotating about a crease) stretches the stiff bars to
// second order, and the chord step takes that stretch back (a second-order correction),
// so that the step is judged by where the soft motion leads, not by the bars' stretch.
double corrected(assembly::Assembler& assembler, TangentSolver& solver, VectorX& trial,
                 const VectorX* external, double max_step) {
  VectorX force;
  const double e =
      assembler.assemble(trial, force, /*with_matrix=*/false).total() - work(external, trial);
  if (!std::isfinite(e)) return e;
  VectorX chord =
      -solver.solve(gather_rows(assembler, external ? VectorX(force - *external) : force));
  if (!chord.allFinite()) return e;
  const double length = chord.norm();
  if (length > max_step) chord *= max_step / length;
  VectorX move = VectorX::Zero(trial.size());
  scatter_add_rows(assembler, chord, move);
  chord *= std::min(1.0, barrier_step_fraction(assembler.model(), trial, move));
  VectorX better = moved(assembler, trial, chord);
  const double e_better = energy_at(assembler, better, external);
  if (!(std::isfinite(e_better) && e_better < e)) return e;
  trial = std::move(better);
  return e_better;
}

// The relaxation's loop as named steps over the state they share: the point u and its
// energy, gradient and tangent (s_), the shift mu_ of the tangent the solver holds, the trust
// region's radius.
class Relaxer {
 public:
  Relaxer(assembly::Assembler& assembler, TangentSolver& solver, VectorX& u,
          const RelaxationOptions& o, const VectorX* external)
      : assembler_(assembler), solver_(solver), u_(u), o_(o), external_(external),
        radius_(o.max_step) {}

  Relaxation run() {
    if (!evaluated()) return out_;
    largest_ = s_.tangent.diagonal().cwiseAbs().maxCoeff();
    while (out_.iterations < o_.max_iterations) {
      check_interrupt();
      out_.energy = s_.energy;
      ++out_.iterations;
      if (!iterate()) return out_;
    }
    out_.failure = "no stable equilibrium within " + std::to_string(o_.max_iterations) +
                   " iterations";
    return out_;
  }

 private:
  bool fail(const std::string& why) {
    out_.failure = why;
    return false;
  }

  bool evaluated() {
    if (evaluate(assembler_, solver_, u_, external_, s_)) return true;
    return fail("the energy or its derivatives are not finite (an element degenerated)");
  }

  // One iteration; false when the relaxation ends (converged, or failed: out_ says which).
  bool iterate() {
    if (!factorized_ && !factorize_shifted(solver_, s_.tangent, mu_)) return raise_shift();
    factorized_ = true;
    VectorX step = -solver_.solve(s_.gradient);
    if (!step.allFinite()) return fail("the relaxation's step is not finite");
    if (step.norm() <= o_.tolerance) return short_step(step);
    return trust_step(step);
  }

  // The shifted tangent has no Cholesky: shift it further.
  bool raise_shift() {
    if (mu_ == 0.0) indefinite_ = true;
    mu_ = std::max(kShiftFactor * mu_, kFirstShift * largest_);
    if (mu_ > kLargestShift * largest_) {
      return fail("no shift of the tangent made it positive definite");
    }
    return true;
  }

  // A step below the tolerance: converged at a stable equilibrium (no shift), or the shift
  // held the steps back (drop it), or a saddle (leave it).
  bool short_step(const VectorX& step) {
    if (mu_ == 0.0) {  // Newton's last correction at a stable equilibrium
      u_ = moved(assembler_, u_, step);
      out_.converged = true;
      return false;
    }
    if (!indefinite_) {  // the shift may be all that holds the steps back
      mu_ = 0.0;
      factorized_ = false;
      return true;
    }
    return escape();
  }

  // The step within the trust region, taken where the energy falls enough of what the
  // quadratic model predicts; the region and the shift follow how well it predicted.
  bool trust_step(VectorX step) {
    const double length = step.norm();
    if (length > radius_) step *= radius_ / length;
    VectorX move = VectorX::Zero(u_.size());
    scatter_add_rows(assembler_, step, move);
    step *= std::min(1.0, barrier_step_fraction(assembler_.model(), u_, move));
    const double predicted = -(s_.gradient.dot(step) +
                               0.5 * step.dot(s_.tangent.selfadjointView<Eigen::Lower>() * step));
    const double taken = step.norm();
    VectorX trial = moved(assembler_, u_, step);
    const double e = corrected(assembler_, solver_, trial, external_, radius_);
    const double fall = s_.energy - e;
    // A step whose predicted change is below the energy's rounding is judged by the model.
    const bool rounding = std::abs(predicted) <= 1e-12 * std::max(1.0, std::abs(s_.energy));
    const bool good = std::isfinite(e) && (fall >= kGood * predicted || rounding);
    if (std::isfinite(e) && predicted > 0.0 && (fall >= kAccept * predicted || rounding)) {
      if (!accept(trial, good, taken)) return false;
    }
    if (!good) radius_ = 0.25 * std::min(radius_, taken);
    if (radius_ > o_.tolerance) return true;
    // No lower energy along the shifted step, however short: a ridge or saddle, where only
    // the negative curvature leads down (or, where there is none, rounding).
    if (!(indefinite_ && mu_ > 0.0)) {
      return fail("the relaxation's steps shrank below the tolerance without a lower energy");
    }
    return escape();
  }

  bool accept(VectorX& trial, bool good, double taken) {
    u_ = trial;
    ++out_.steps;
    if (!evaluated()) return false;
    largest_ = std::max(largest_, s_.tangent.diagonal().cwiseAbs().maxCoeff());
    indefinite_ = false;
    factorized_ = false;
    // A good step lets the next be twice as long where this one was held by the radius, and
    // the shift shrink (to 0: Newton's steps).
    if (good && taken >= 0.99 * radius_) {
      radius_ = std::min(2.0 * radius_, kLongestRadius * o_.max_step);
    }
    if (good) {
      mu_ /= kShiftFactor;
      if (mu_ < kZeroShift * largest_) mu_ = 0.0;
    }
    return true;
  }

  // Leave a saddle along its most negative curvature (the solver holding K + mu I at u).
  bool escape() {
    mu_ = tightest_shift(solver_, s_.tangent, mu_);
    double curvature = 0.0;
    if (!escape_saddle(assembler_, solver_, s_, u_, external_, o_.escape_step, curvature)) {
      // Where the steps vanish with a large out-of-balance force, the shift that made the
      // tangent definite is what held them: its curvature is sharply negative there, as
      // where an element nears a singular state (a panel's triangle flattened to a line).
      return fail("the relaxation stopped where no step lowers the energy (out-of-balance "
                  "force " + format_rounded(s_.gradient.norm()) + " N, most negative "
                  "curvature " + format_rounded(curvature) + " N/mm, shift " +
                  format_rounded(mu_) + " N/mm: a saddle, or an element near a singular "
                  "state such as a panel's triangle flattened to a line)");
    }
    ++out_.steps;
    if (!evaluated()) return false;
    indefinite_ = false;
    factorized_ = false;
    radius_ = o_.max_step;
    return true;
  }

  assembly::Assembler& assembler_;
  TangentSolver& solver_;
  VectorX& u_;
  const RelaxationOptions& o_;
  const VectorX* external_;
  Relaxation out_;
  State s_;
  double largest_ = 0.0;
  double mu_ = 0.0;
  double radius_;            // the trust region's
  bool indefinite_ = false;  // the tangent at u itself has no Cholesky
  bool factorized_ = false;  // the solver holds K + mu I at u
};

}  // namespace

Relaxation relax_to_stable(assembly::Assembler& assembler, TangentSolver& solver, VectorX& u,
                           const RelaxationOptions& o, const VectorX* external) {
  check_descent(o.tolerance, o.max_step, o.escape_step, o.max_iterations);
  return Relaxer(assembler, solver, u, o, external).run();
}

}  // namespace kresling::solvers
