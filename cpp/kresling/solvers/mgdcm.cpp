#include "kresling/solvers/mgdcm.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "kresling/assembly/assembler.hpp"
#include "kresling/core/check.hpp"
#include "kresling/core/interrupt.hpp"
#include "kresling/solvers/force_control.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/newton.hpp"

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

bool stalled(const std::vector<double>& corrections, double tolerance) {
  if (corrections.size() <= kStallIterations) return false;
  const auto recent = corrections.end() - static_cast<std::ptrdiff_t>(kStallIterations);
  const double before = *std::min_element(corrections.begin(), recent);
  const double latest = *std::min_element(recent, corrections.end());
  return std::min(before, latest) <= kFloorFactor * tolerance && latest >= 0.5 * before;
}

std::vector<Index> fixed_dofs(const model::Model& model) {
  std::vector<Index> dofs;
  for (Index i = 0; i < model.num_dofs(); ++i) {
    if (model.fixed()[i]) dofs.push_back(i);
  }
  return dofs;
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
  if (options.monitor_dof < -1 || options.monitor_dof >= model.num_dofs()) {
    throw_invalid("monitor_dof", static_cast<double>(options.monitor_dof), "a DOF of the model");
  }
}

// The last accepted equilibrium and the direction data MGDCM carries between increments.
struct PathPoint {
  VectorX u;                     // all DOFs
  double lambda = 0.0;
  double direction = 1.0;        // sign of the step along the path
  VectorX predictor;             // the first iteration's K^-1 F of the increment to it
};

struct Attempt {
  PathPoint end;
  NewtonOutcome outcome;
  std::vector<double> corrections;  // the norm of every iteration's correction [mm]
};

class Increments {
 public:
  Increments(const model::Model& model, const VectorX& forces, const MgdcmOptions& options)
      : options_(options),
        assembler_(model, assembly::unmasked_dofs(model.fixed()), options.shift,
                   assembly::Storage::Lower),
        solver_(options.newton.cholesky),
        F_(gather_rows(assembler_, forces)) {}

  assembly::Assembler& assembler() { return assembler_; }

  /// One increment from `start` with step factor `step`.
  Attempt attempt(const PathPoint& start, double step);

 private:
  // The first iteration's load increment: the step factor, scaled after the first
  // increment by the generalized stiffness parameter, its sign set by the direction.
  double first_increment(const PathPoint& start, const VectorX& dup, double step,
                         double& direction);

  const MgdcmOptions& options_;
  assembly::Assembler assembler_;
  TangentSolver solver_;
  VectorX F_;
  VectorX force_;
  double gsp_reference_ = 0.0;  // dup . dup of the first increment's first iteration
};

double Increments::first_increment(const PathPoint& start, const VectorX& dup, double step,
                                   double& direction) {
  if (start.predictor.size()) {
    direction = start.direction * (start.predictor.dot(dup) < 0.0 ? -1.0 : 1.0);
  }
  if (gsp_reference_ == 0.0) {
    gsp_reference_ = dup.dot(dup);
    return step;
  }
  return direction * step * std::sqrt(gsp_reference_ / dup.dot(dup));
}

Attempt Increments::attempt(const PathPoint& start, double step) {
  Attempt a{start, {}, {}};
  PathPoint& end = a.end;
  NewtonOutcome& outcome = a.outcome;
  const NewtonOptions& newton = options_.newton;
  while (outcome.iterations < newton.max_iterations) {
    check_interrupt();
    ++outcome.iterations;
    assembler_.assemble(end.u, force_, /*with_matrix=*/true);
    follow_pattern(assembler_, solver_);
    const FactorizeInfo info = solver_.factorize(assembler_.matrix());
    if (!info.ok) {
      outcome.failure = "the tangent stiffness is singular";
      break;
    }
    outcome.negative_eigenvalues = info.negative_eigenvalues;
    const VectorX dup = solver_.solve(F_);
    double dl;
    VectorX du;
    if (outcome.iterations == 1) {
      dl = first_increment(start, dup, step, end.direction);
      end.predictor = dup;
      du = dl * dup;
    } else {
      const VectorX dur = solver_.solve(VectorX(end.lambda * F_ - gather_rows(assembler_, force_)));
      dl = -end.predictor.dot(dur) / end.predictor.dot(dup);
      du = dl * dup + dur;
    }
    if (!du.allFinite() || !std::isfinite(dl)) {
      outcome.failure = "the iteration produced NaN";
      break;
    }
    scatter_add_rows(assembler_, du, end.u);
    end.lambda += dl;
    const double err = du.norm();
    a.corrections.push_back(err);
    if (err <= newton.tolerance) {
      outcome.converged = true;
      break;
    }
    if (err > 1e8) {
      outcome.failure = "the iteration diverged";
      break;
    }
    // Rejected already: stop once the corrections have stalled (more iterations only
    // wander at the floor).
    if (outcome.iterations > options_.shrink_above_iterations &&
        stalled(a.corrections, newton.tolerance)) {
      break;
    }
  }
  return a;
}

std::string short_number(double value) {
  std::ostringstream out;
  out << std::setprecision(3) << value;
  return out.str();
}

// Why a stalled increment cannot go on, with the floor its corrections reached.
std::string stall_message(int increment, double lambda, const Attempt& a, double tolerance,
                          const std::string& cause) {
  const double floor = *std::min_element(a.corrections.begin(), a.corrections.end());
  return "MGDCM increment " + std::to_string(increment) + " (from load factor " +
         short_number(lambda) + "): Newton's corrections stall at " + short_number(floor) +
         " mm, above the tolerance " + short_number(tolerance) +
         " mm (rounding near a singular tangent: a bifurcation or limit point), and " + cause +
         "; a tolerance of " + short_number(10.0 * floor) + " mm or more clears this floor";
}

bool stop_reached(const MgdcmOptions& options, const PathPoint& point, const PathStep& step) {
  const bool load_reached = std::abs(point.lambda) > options.max_load_factor;
  const bool motion_reached = options.monitor_dof >= 0 &&
                              std::abs(point.u[options.monitor_dof]) > options.max_displacement;
  return load_reached || motion_reached || (options.stop && options.stop(step));
}

}  // namespace

PathResult solve_mgdcm(const model::Model& model, const VectorX& forces,
                       const MgdcmOptions& options, const VectorX& initial) {
  check_load_inputs(model, forces, initial);
  check_options(model, options);
  Increments increments(model, forces, options);
  PathPoint point;
  point.u = initial.size() ? initial : VectorX::Zero(model.num_dofs());
  double step_factor = options.initial_load_factor;
  int jumps = 0;  // longer retries of the current increment after a stall
  PathResult result;
  result.constraint_dofs = fixed_dofs(model);
  result.families = family_names(model);
  while (static_cast<int>(result.steps.size()) < options.max_increments) {
    ++result.attempted_increments;
    Attempt a = increments.attempt(point, step_factor);
    result.newton_iterations += a.outcome.iterations;
    const int next = static_cast<int>(result.steps.size()) + 1;
    if (a.outcome.converged && a.outcome.iterations <= options.shrink_above_iterations) {
      PathStep step = record_step(increments.assembler(), a.end.u, a.end.lambda, a.outcome,
                                  result.constraint_dofs, 1.0);
      if (finite_step(step)) {
        point = std::move(a.end);
        jumps = 0;
        result.steps.push_back(std::move(step));
        if (a.outcome.iterations < options.grow_below_iterations) {
          step_factor = std::copysign(
              std::min(std::abs(step_factor) * 1.5, options.max_step_factor), step_factor);
        }
        if (stop_reached(options, point, result.steps.back())) {
          result.completed = true;
          return result;
        }
        continue;
      }
      a.outcome.converged = false;
      a.outcome.failure = kStepNotFinite;
    }
    if (!a.outcome.converged && a.outcome.failure.empty() &&
        stalled(a.corrections, options.newton.tolerance)) {
      const double longer = std::abs(step_factor) * kJumpFactor;
      std::string cause;
      if (jumps == kMaxJumps) {
        cause = "steps up to " + short_number(std::pow(kJumpFactor, kMaxJumps)) +
                " times longer stall too";
      } else if (longer > options.max_step_factor) {
        cause = "a longer step would exceed max_step_factor (" +
                format_number(options.max_step_factor) + ")";
      }
      if (!cause.empty()) {
        result.failed_increment = result.attempted_increments;
        result.message =
            stall_message(next, point.lambda, a, options.newton.tolerance, cause);
        return result;
      }
      ++jumps;
      step_factor = std::copysign(longer, step_factor);
      continue;
    }
    step_factor *= 0.5;
    if (std::abs(step_factor) < options.min_load_factor) {
      result.failed_increment = result.attempted_increments;
      result.message = "MGDCM increment " + std::to_string(next) +
                       " failed with the step factor reduced to " + format_number(step_factor) +
                       ": " + (a.outcome.failure.empty() ? "too many iterations" : a.outcome.failure);
      return result;
    }
  }
  // A caller's rule is an optional early stop: running out of increments before it fires
  // completes the path as it would without it.
  const bool has_criterion = std::isfinite(options.max_load_factor) || options.monitor_dof >= 0;
  result.completed = !has_criterion;
  if (has_criterion) {
    result.message = "the step budget (" + std::to_string(options.max_increments) +
                     " increments) ran out before the stopping criterion was reached";
  }
  return result;
}

}  // namespace kresling::solvers
