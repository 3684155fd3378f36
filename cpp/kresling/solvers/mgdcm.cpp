#include "kresling/solvers/mgdcm.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "kresling/assembly/assembler.hpp"
#include "kresling/core/check.hpp"
#include "kresling/core/interrupt.hpp"
#include "kresling/solvers/force_control.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/path_follower.hpp"

namespace kresling::solvers {

namespace {

// Newton's corrections have stalled at an accuracy floor when the smallest is within
// kFloorFactor of the tolerance and none of the last kStallIterations is below half the
// smallest before them. Near a singular tangent the corrections' noise is the residual's
// rounding divided by the smallest eigenvalue: on a one-layer Kresling at a double
// bifurcation (eigenvalue 9e-6 N/mm) it is 1e-9 mm, and a tolerance of 1e-10 mm cannot be
// met within ~1e-2 mm of that point whatever the step. A step too long for Newton instead
// shows corrections far above the tolerance or still shrinking.
constexpr double kFloorFactor = 1e3;
constexpr std::size_t kStallIterations = 5;
// A stalled increment is retried with its step factor kJumpFactor times longer, at most
// kMaxJumps times (up to 16 times the stalled step), to land where the tangent is
// far enough from singular for the tolerance (the floor falls as the distance grows).
constexpr double kJumpFactor = 4.0;
constexpr int kMaxJumps = 2;

bool stalled_at_floor(const std::vector<double>& corrections, double tolerance) {
  if (corrections.size() <= kStallIterations) return false;
  const auto recent = corrections.end() - static_cast<std::ptrdiff_t>(kStallIterations);
  const double before = *std::min_element(corrections.begin(), recent);
  const double latest = *std::min_element(recent, corrections.end());
  return std::min(before, latest) <= kFloorFactor * tolerance && latest >= 0.5 * before;
}

void check_options(const model::Model& model, const MgdcmOptions& options) {
  require_finite("initial_load_factor", options.initial_load_factor);
  if (options.initial_load_factor == 0.0) {
    throw_invalid("initial_load_factor", 0.0, "non-zero (its sign sets the loading direction)");
  }
  check_steps("max_increments", options.max_increments);
  check_newton(options.newton);
  check_shift(options.shift);
  if (!(options.max_load_factor > 0.0)) {
    throw_invalid("max_load_factor", options.max_load_factor, "> 0 (inf: no limit)");
  }
  if (!(options.max_displacement > 0.0)) {
    throw_invalid("max_displacement", options.max_displacement, "> 0 (inf: no limit)");
  }
  if (!(options.max_step_factor >= std::abs(options.initial_load_factor))) {
    throw_invalid("max_step_factor", options.max_step_factor, ">= |initial_load_factor|");
  }
  if (options.shrink_above_iterations < 1) {
    throw_invalid("shrink_above_iterations", options.shrink_above_iterations, ">= 1");
  }
  if (options.monitor_dof < -1 || options.monitor_dof >= model.num_dofs()) {
    throw_invalid("monitor_dof", static_cast<double>(options.monitor_dof), "a DOF of the model");
  }
}

// Why a stalled increment cannot go on, with the floor its corrections reached.
std::string stall_message(int increment, double lambda, double floor, double tolerance,
                          const std::string& cause) {
  return "MGDCM increment " + std::to_string(increment) + " (from load factor " +
         format_rounded(lambda, 3) + "): Newton's corrections stall at " + format_rounded(floor, 3) +
         " mm, above the tolerance " + format_rounded(tolerance, 3) +
         " mm (rounding near a singular tangent: a bifurcation or limit point), and " + cause +
         "; a tolerance of " + format_rounded(10.0 * floor, 3) + " mm or more clears this floor";
}

// A correction orthogonal to the predictor, the load factor's change (returned) solved
// with it: du = dl dup + dur, from the load and residual directions dup and dur.
double orthogonal_correction(const TangentSolver& solver, const assembly::Assembler& assembler,
                             const VectorX& F, const VectorX& force, double lambda,
                             const VectorX& predictor, const VectorX& dup, VectorX& du) {
  const VectorX dur = solver.solve(VectorX(lambda * F - gather_rows(assembler, force)));
  const double dl = -predictor.dot(dur) / predictor.dot(dup);
  du = dl * dup + dur;
  return dl;
}

// The internal force and tangent at u assembled and the tangent factorised (its stability
// into `outcome`); false, saying so, when it is singular.
bool factorize_at(assembly::Assembler& assembler, TangentSolver& solver, const VectorX& u,
                  VectorX& force, NewtonOutcome& outcome) {
  assembler.assemble(u, force, /*with_matrix=*/true);
  const FactorizeInfo info = factorize_tangent(assembler, solver, u, force);
  if (!info.ok) {
    outcome.failure = "the tangent stiffness is singular";
    return false;
  }
  outcome.negative_eigenvalues = info.negative_eigenvalues;
  return true;
}

}  // namespace

MgdcmControl::MgdcmControl(const model::Model& model, VectorX forces,
                           const MgdcmOptions& options)
    : model_(model), forces_(std::move(forces)), options_(options) {}

void MgdcmControl::apply(double t, VectorX&, VectorX& external) { external = t * forces_; }

std::string MgdcmControl::failure_message(int k, int, double t, int,
                                          const std::string& reason) const {
  return "MGDCM increment " + std::to_string(k) + " (from load factor " + format_rounded(t, 3) +
         ") failed: " + reason;
}

double MgdcmControl::first_increment(const VectorX& dup, double step) {
  if (predictor_.size()) {
    trial_direction_ = direction_ * (predictor_.dot(dup) < 0.0 ? -1.0 : 1.0);
  }
  if (gsp_reference_ == 0.0) {
    gsp_reference_ = dup.dot(dup);
    return step;
  }
  return trial_direction_ * step * std::sqrt(gsp_reference_ / dup.dot(dup));
}

NewtonOutcome MgdcmControl::correct(Increment& increment, assembly::Assembler& assembler,
                                    TangentSolver& solver, VectorX& u, const VectorX&,
                                    const NewtonOptions& newton, int max_iterations,
                                    ExtraTerms* extra) {
  if (extra) throw std::invalid_argument("MGDCM: its corrector takes no extra terms");
  const int limit = max_iterations > 0 ? max_iterations : newton.max_iterations;
  const VectorX F = gather_rows(assembler, forces_);
  const bool limited = families_limit_steps(assembler.model());
  VectorX force;
  double lambda = increment.from;
  trial_direction_ = direction_;
  outcome_ = NewtonOutcome{};
  corrections_.clear();
  while (outcome_.iterations < limit) {
    check_interrupt();
    ++outcome_.iterations;
    if (!factorize_at(assembler, solver, u, force, outcome_)) break;
    const VectorX dup = solver.solve(F);
    double dl;
    VectorX du;
    if (outcome_.iterations == 1) {  // the predictor: along the path's direction
      dl = first_increment(dup, increment.size);
      trial_predictor_ = dup;
      du = dl * dup;
    } else {
      dl = orthogonal_correction(solver, assembler, F, force, lambda, trial_predictor_, dup, du);
    }
    if (!du.allFinite() || !std::isfinite(dl)) {
      outcome_.failure = "the iteration produced NaN";
      break;
    }
    // A barrier must not be stepped across: the correction and its load increment are
    // shortened together (the point moves along the same line of (u, lambda)), while the
    // full correction's size decides convergence, as in Newton's own.
    const double fraction = add_correction_within_barriers(assembler, du, u, limited);
    lambda += fraction < 1.0 ? fraction * dl : dl;
    const double err = du.norm();
    corrections_.push_back(err);
    if (err <= newton.tolerance) {
      outcome_.converged = true;
      break;
    }
    if (err > 1e8) {
      outcome_.failure = "the iteration diverged";
      break;
    }
    // Rejected already: stop once the corrections have stalled (more iterations only
    // wander at the floor).
    if (outcome_.iterations > options_.shrink_above_iterations &&
        stalled_at_floor(corrections_, newton.tolerance)) {
      break;
    }
  }
  increment.to = lambda;
  return outcome_;
}

void MgdcmControl::commit() {
  direction_ = trial_direction_;
  predictor_ = std::move(trial_predictor_);
  trial_predictor_ = VectorX();
}

bool MgdcmControl::stalled(double tolerance) const {
  return !outcome_.converged && outcome_.failure.empty() &&
         stalled_at_floor(corrections_, tolerance);
}

double MgdcmControl::floor() const {
  return *std::min_element(corrections_.begin(), corrections_.end());
}

MgdcmSteps::MgdcmSteps(MgdcmControl& control, const MgdcmOptions& options)
    : control_(control), options_(options), step_factor_(options.initial_load_factor) {}

bool MgdcmSteps::next(Increment& increment) {
  if (failed_ || accepted_ >= options_.max_increments) return false;
  increment = Increment{};
  increment.from = lambda_;
  increment.to = lambda_;  // the corrector finds where it ends
  increment.size = step_factor_;
  // A converged increment of more than shrink_above_iterations iterations is rejected.
  increment.reject_at = options_.shrink_above_iterations + 1.0;
  return true;
}

void MgdcmSteps::accepted(const Increment& increment) {
  lambda_ = increment.to;
  ++accepted_;
  jumps_ = 0;
  control_.commit();
  if (control_.last_outcome().iterations < options_.grow_below_iterations) {
    step_factor_ = std::copysign(
        std::min(std::abs(step_factor_) * 1.5, options_.max_step_factor), step_factor_);
  }
}

bool MgdcmSteps::rejected(const Increment&, const std::string& reason) {
  const NewtonOutcome& outcome = control_.last_outcome();
  const double tolerance = options_.newton.tolerance;
  if (control_.stalled(tolerance)) {
    const double longer = std::abs(step_factor_) * kJumpFactor;
    std::string cause;
    if (jumps_ == kMaxJumps) {
      cause = "steps up to " + format_rounded(std::pow(kJumpFactor, kMaxJumps), 3) +
              " times longer stall too";
    } else if (longer > options_.max_step_factor) {
      cause = "a longer step would exceed max_step_factor (" +
              format_number(options_.max_step_factor) + ")";
    }
    if (!cause.empty()) {
      failed_ = true;
      message_ = stall_message(accepted_ + 1, lambda_, control_.floor(), tolerance, cause);
      return false;
    }
    ++jumps_;
    step_factor_ = std::copysign(longer, step_factor_);
    return true;
  }
  step_factor_ *= 0.5;
  if (std::abs(step_factor_) < options_.min_load_factor) {
    // Newton's own failure; else too many iterations, or the follower's reason (a state
    // that is not finite) for an increment that converged within the budget.
    const bool too_many = !outcome.converged ||
                          outcome.iterations > options_.shrink_above_iterations;
    const std::string cause = !outcome.failure.empty() ? outcome.failure
                              : too_many              ? std::string("too many iterations")
                                                      : reason;
    failed_ = true;
    message_ = "MGDCM increment " + std::to_string(accepted_ + 1) +
               " failed with the step factor reduced to " + format_number(step_factor_) +
               ": " + cause;
    return false;
  }
  return true;
}

void MgdcmSteps::finish(const PathControl&, PathResult& result) const {
  if (failed_) {
    result.failed_increment = result.attempted_increments;
    result.message = message_;
    return;
  }
  // A caller's rule is an optional early stop: running out of increments before it fires
  // completes the path as it would without it.
  const bool has_criterion = std::isfinite(options_.max_load_factor) || options_.monitor_dof >= 0;
  result.completed = !has_criterion;
  if (has_criterion) {
    result.message = "the step budget (" + std::to_string(options_.max_increments) +
                     " increments) ran out before the stopping criterion was reached";
  }
}

StopRule mgdcm_stop_rule(const MgdcmOptions& options) {
  return [&options](const PathStep& step) {
    const bool load_reached = std::abs(step.load_factor) > options.max_load_factor;
    const bool motion_reached =
        options.monitor_dof >= 0 &&
        std::abs(step.displacement[options.monitor_dof]) > options.max_displacement;
    return load_reached || motion_reached || (options.stop && options.stop(step));
  };
}

PathResult solve_mgdcm(const model::Model& model, const VectorX& forces,
                       const MgdcmOptions& options, const VectorX& initial) {
  check_load_inputs(model, forces, initial);
  check_options(model, options);
  assembly::Assembler assembler(model, assembly::unmasked_dofs(model.fixed()), options.shift,
                                assembly::Storage::Lower);
  TangentSolver solver(options.newton.cholesky);
  MgdcmControl control(model, forces, options);
  MgdcmSteps steps(control, options);
  FollowOptions follow;
  follow.newton = options.newton;
  follow.stop = mgdcm_stop_rule(options);
  VectorX u = initial.size() ? initial : VectorX::Zero(model.num_dofs());
  PathResult result;
  follow_path(control, assembler, solver, u, steps, follow, result);
  return result;
}

}  // namespace kresling::solvers
