#include "kresling/solvers/force_control.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "kresling/assembly/assembler.hpp"
#include "kresling/core/check.hpp"
#include "kresling/core/interrupt.hpp"
#include "kresling/solvers/increments.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/path_follower.hpp"
#include "kresling/solvers/rigid_body.hpp"

namespace kresling::solvers {

namespace {

std::vector<Index> fixed_dofs(const model::Model& model) {
  std::vector<Index> dofs;
  for (Index i = 0; i < model.num_dofs(); ++i) {
    if (model.fixed()[i]) dofs.push_back(i);
  }
  return dofs;
}

void check_inputs(const model::Model& model, const VectorX& forces, const VectorX& initial) {
  const Index n = model.num_dofs();
  if (forces.size() != n) {
    throw std::invalid_argument("forces: has " + std::to_string(forces.size()) +
                                " entries, must have one per DOF (" + std::to_string(n) + ")");
  }
  if (!forces.allFinite()) throw std::invalid_argument("forces: contains NaN or inf");
  bool any = false;
  for (Index i = 0; i < n; ++i) any |= (forces[i] != 0.0 && !model.fixed()[i]);
  if (!any) throw std::invalid_argument("forces: no force acts on a free DOF");
  if (initial.size() != 0 && (initial.size() != n || !initial.allFinite())) {
    throw std::invalid_argument("initial: must be empty or one finite entry per DOF");
  }
  require_rigid_body_constrained(model, model.fixed());
}


}  // namespace

PathResult solve_force_control(const model::Model& model, const VectorX& forces, int steps,
                               const ForceControlOptions& options, const VectorX& initial) {
  check_inputs(model, forces, initial);
  check_steps("steps", steps);
  check_newton(options.newton);
  check_bisections(options.max_bisections);
  check_shift(options.shift);
  assembly::Assembler assembler(model, assembly::unmasked_dofs(model.fixed()), options.shift,
                                assembly::Storage::Lower);
  TangentSolver solver(options.newton.cholesky);
  VectorX u = initial.size() ? initial : VectorX::Zero(model.num_dofs());
  // Load steps: the path follower under lambda * forces, every converged step accepted.
  LoadControl control(model, forces);
  FollowOptions follow;
  follow.newton = options.newton;
  follow.max_bisections = options.max_bisections;
  follow.stop = options.stop;
  PathResult result;
  follow_path(control, assembler, solver, u, steps, follow, result);
  return result;
}

PathResult solve_mgdcm(const model::Model& model, const VectorX& forces,
                       const MgdcmOptions& options, const VectorX& initial) {
  check_inputs(model, forces, initial);
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
  assembly::Assembler assembler(model, assembly::unmasked_dofs(model.fixed()), options.shift,
                                assembly::Storage::Lower);
  TangentSolver solver(options.newton.cholesky);
  const VectorX F = gather_rows(assembler, forces);
  VectorX u = initial.size() ? initial : VectorX::Zero(model.num_dofs());
  double lambda = 0.0;
  double step_factor = options.initial_load_factor;
  // Direction state, committed only when an increment is accepted.
  double direction = 1.0;
  VectorX previous_predictor;
  double gsp_reference = 0.0;  // dup . dup of the first increment

  PathResult result;
  result.constraint_dofs = fixed_dofs(model);
  result.families = family_names(model);
  VectorX force;
  while (static_cast<int>(result.steps.size()) < options.max_increments) {
    ++result.attempted_increments;
    VectorX trial = u;
    double l_trial = lambda;
    double trial_direction = direction;
    VectorX predictor;  // this increment's first-iteration dup
    NewtonOutcome outcome;
    while (outcome.iterations < options.newton.max_iterations) {
      check_interrupt();
      ++outcome.iterations;
      assembler.assemble(trial, force, /*with_matrix=*/true);
      follow_pattern(assembler, solver);
      const FactorizeInfo info = solver.factorize(assembler.matrix());
      if (!info.ok) {
        outcome.failure = "the tangent stiffness is singular";
        break;
      }
      outcome.negative_eigenvalues = info.negative_eigenvalues;
      const VectorX dup = solver.solve(F);
      double dl;
      VectorX du;
      if (outcome.iterations == 1) {
        if (previous_predictor.size()) {
          trial_direction = direction * (previous_predictor.dot(dup) < 0.0 ? -1.0 : 1.0);
        }
        if (gsp_reference == 0.0) {
          gsp_reference = dup.dot(dup);
          dl = step_factor;
        } else {
          dl = trial_direction * step_factor * std::sqrt(gsp_reference / dup.dot(dup));
        }
        predictor = dup;
        du = dl * dup;
      } else {
        const VectorX dur = solver.solve(VectorX(l_trial * F - gather_rows(assembler, force)));
        dl = -predictor.dot(dur) / predictor.dot(dup);
        du = dl * dup + dur;
      }
      if (!du.allFinite() || !std::isfinite(dl)) {
        outcome.failure = "the iteration produced NaN";
        break;
      }
      scatter_add_rows(assembler, du, trial);
      l_trial += dl;
      const double err = du.norm();
      if (err <= options.newton.tolerance) {
        outcome.converged = true;
        break;
      }
      if (err > 1e8) {
        outcome.failure = "the iteration diverged";
        break;
      }
    }
    result.newton_iterations += outcome.iterations;
    PathStep step;
    if (outcome.converged && outcome.iterations <= options.shrink_above_iterations) {
      step = record_step(assembler, trial, l_trial, outcome, result.constraint_dofs, 1.0);
      if (!finite_step(step)) {
        outcome.converged = false;
        outcome.failure = kStepNotFinite;
      }
    }
    if (outcome.converged && outcome.iterations <= options.shrink_above_iterations) {
      u = trial;
      lambda = l_trial;
      direction = trial_direction;
      previous_predictor = predictor;
      result.steps.push_back(std::move(step));
      if (outcome.iterations < options.grow_below_iterations) {
        step_factor = std::copysign(std::min(std::abs(step_factor) * 1.5, options.max_step_factor),
                                    step_factor);
      }
      const bool load_reached = std::abs(lambda) > options.max_load_factor;
      const bool motion_reached = options.monitor_dof >= 0 &&
                                  std::abs(u[options.monitor_dof]) > options.max_displacement;
      const bool rule_reached = options.stop && options.stop(result.steps.back());
      if (load_reached || motion_reached || rule_reached) {
        result.completed = true;
        return result;
      }
      continue;
    }
    step_factor *= 0.5;
    if (std::abs(step_factor) < options.min_load_factor) {
      result.failed_increment = result.attempted_increments;
      result.message = "MGDCM increment " + std::to_string(result.steps.size() + 1) +
                       " failed with the step factor reduced to " + format_number(step_factor) +
                       ": " + (outcome.failure.empty() ? "too many iterations" : outcome.failure);
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
