#include "kresling/solvers/displacement_control.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kresling/core/check.hpp"
#include "kresling/core/interrupt.hpp"
#include "kresling/solvers/increments.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/path_follower.hpp"
#include "kresling/solvers/rigid_body.hpp"

namespace kresling::solvers {

namespace {

void check_options(const DisplacementControlOptions& o) {
  check_newton(o.newton);
  require_integer_in("reject_iterations", o.reject_iterations, 1, kMaxIterations);
  check_bisections(o.max_bisections);
  check_shift(o.shift);
  if (o.extrapolation < 0 || o.extrapolation > 3) {
    throw_invalid("extrapolation", o.extrapolation, "0, 1, 2 or 3");
  }
  require_finite("adaptive_tolerance", o.adaptive_tolerance);
  if (!(o.adaptive_tolerance > 0.0 && o.adaptive_tolerance <= 1e-4)) {
    throw_invalid("adaptive_tolerance", o.adaptive_tolerance,
                  "in (0, 1e-4]: the samples' force error relative to the path's largest force");
  }
}


}  // namespace

DisplacementControl::DisplacementControl(DisplacementControlOptions options)
    : options_(options) {
  check_options(options_);
}

PathResult DisplacementControl::solve(const model::Model& model, const VectorX& prescribed,
                                      int steps, const VectorX& initial) {
  const Index n = model.num_dofs();
  if (prescribed.size() != n) {
    throw std::invalid_argument("prescribed: has " + std::to_string(prescribed.size()) +
                                " entries, must have one per DOF (" + std::to_string(n) + ")");
  }
  if (!prescribed.allFinite()) throw std::invalid_argument("prescribed: contains NaN or inf");
  check_steps("steps", steps);
  if (initial.size() != 0 && initial.size() != n) {
    throw std::invalid_argument("initial: must be empty or have one entry per DOF");
  }
  if (!initial.allFinite()) throw std::invalid_argument("initial: contains NaN or inf");

  std::vector<std::uint8_t> held = model.fixed();
  std::vector<Index> imposed;
  for (Index i = 0; i < n; ++i) {
    if (prescribed[i] == 0.0) continue;
    if (model.fixed()[i]) {
      throw std::invalid_argument("prescribed: DOF " + std::to_string(i) + " (node " +
                                  std::to_string(i / 3) + ", " + "xyz"[i % 3] +
                                  ") is also fixed; a DOF is either supported or driven");
    }
    imposed.push_back(i);
    held[i] = 1;
  }
  if (imposed.empty()) throw std::invalid_argument("prescribed: every entry is zero");
  require_rigid_body_constrained(model, held);

  // Reuse the pattern and the symbolic factorisation when only the geometry changed.
  if (!(workspace_ && held == held_ && workspace_->fits(model))) {
    workspace_ = std::make_unique<assembly::Workspace>(model, assembly::unmasked_dofs(held),
                                                       options_.shift, assembly::Storage::Lower);
    solver_ = std::make_unique<TangentSolver>(options_.newton.cholesky);
    held_ = held;
  }
  // `model` is bound for this solve only: nothing here refers to it once solve returns.
  assembler_.emplace(model, *workspace_);
  struct Unbind {
    std::optional<assembly::Assembler>& assembler;
    std::optional<assembly::Assembler>& full;
    ~Unbind() {
      assembler.reset();
      full.reset();
    }
  } unbind{assembler_, full_assembler_};
  no_load_.setZero(n);
  VectorX u = initial.size() ? initial : VectorX::Zero(n);
  if (options_.merlin2_steps) return solve_merlin2_steps(prescribed, steps, imposed, u);
  int fallback_attempts = 0;  // of adaptive increments that could not finish the path
  long long fallback_iterations = 0;
  // Cables are tension-only: their slack kink is not located, so they keep fixed steps.
  if (options_.adaptive && model.cables().empty()) {
    if (!(full_workspace_ && full_workspace_->fits(model))) {
      full_workspace_ = std::make_unique<assembly::Workspace>(model, assembly::all_dofs(n), 0.0,
                                                              assembly::Storage::Lower);
    }
    full_assembler_.emplace(model, *full_workspace_);
    PathResult adaptive = solve_adaptive(prescribed, steps, imposed, u);
    if (adaptive.completed) return adaptive;
    // A path the adaptive increments cannot finish (their predictor sent past a snap that
    // the last equilibrium crosses, say) is followed again in fixed increments from the
    // start, so that they never complete less of it than fixed increments would: the result
    // is the fixed increments' own, with both runs' attempts counted.
    fallback_attempts = adaptive.attempted_increments;
    fallback_iterations = adaptive.newton_iterations;
  }
  // Fixed increments: the path follower under the prescribed motion from u.
  PathResult result;
  result.attempted_increments = fallback_attempts;
  result.newton_iterations = fallback_iterations;
  DisplacementDrive drive(model, prescribed, u);
  FollowOptions follow;
  follow.newton = options_.newton;
  follow.max_bisections = options_.max_bisections;
  follow.extrapolation = options_.extrapolation;
  follow.reject_iterations = options_.reject_iterations;
  follow.stop = options_.stop;
  follow_path(drive, *assembler_, *solver_, u, steps, follow, result);
  return result;
}

namespace {

// Newton with every correction scaled by `damping` (< 1), as MERLIN2 iterates after ten
// rejected increments in a row: converged once an undamped correction is <= tolerance.
NewtonOutcome damped_newton(assembly::Assembler& assembler, TangentSolver& solver, VectorX& u,
                            const NewtonOptions& options, double damping) {
  NewtonOutcome out;
  VectorX force;
  while (out.iterations < options.max_iterations) {
    check_interrupt();
    ++out.iterations;
    assembler.assemble(u, force, /*with_matrix=*/true);
    follow_pattern(assembler, solver);
    const FactorizeInfo info = solver.factorize(assembler.matrix());
    const VectorX du = info.ok ? solver.solve(gather_rows(assembler, -force)) : VectorX();
    if (!info.ok || !du.allFinite()) {
      out.failure = "the tangent stiffness is singular or the correction is not finite";
      return out;
    }
    out.negative_eigenvalues = info.negative_eigenvalues;
    scatter_add_rows(assembler, damping * du, u);
    if (du.norm() <= options.tolerance) {
      out.converged = true;
      return out;
    }
  }
  out.failure = "Newton did not converge in " + std::to_string(options.max_iterations) +
                " iterations";
  return out;
}

}  // namespace

PathResult DisplacementControl::solve_merlin2_steps(const VectorX& prescribed, int steps,
                                                    const std::vector<Index>& imposed,
                                                    VectorX u) {
  PathResult result;
  result.constraint_dofs = imposed;
  result.families = family_names(assembler_->model());
  const VectorX increment = prescribed / static_cast<double>(steps);
  const int max_iterations = options_.newton.max_iterations;
  double moved = 0.0;      // fraction of the prescribed motion reached
  double step_size = 1.0;  // in nominal increments
  double damping = 1.0;
  int rejections = 0;      // in a row
  std::string last_failure;
  while (moved <= 1.0 && rejections <= 20) {
    check_interrupt();
    ++result.attempted_increments;
    VectorX trial = u;
    for (Index i : imposed) trial[i] += step_size * increment[i];
    // MERLIN2 rejects an increment needing this many iterations (more for a bold step);
    // iterating past it cannot change the outcome.
    const double limit = ((step_size > 1.0) + 1.0) * max_iterations / (damping + 1.0);
    const int budget = std::min(max_iterations, static_cast<int>(std::ceil(limit)));
    const NewtonOutcome outcome =
        damping == 1.0 ? newton_equilibrium(*assembler_, *solver_, trial, no_load_,
                                            options_.newton, budget)
                       : damped_newton(*assembler_, *solver_, trial, options_.newton, damping);
    result.newton_iterations += outcome.iterations;
    PathStep step;
    bool finite = true;
    if (outcome.converged && outcome.iterations < limit) {
      step = record_step(*assembler_, trial, moved + step_size / steps, outcome, imposed, -1.0);
      finite = finite_step(step);
    }
    if (!outcome.converged || outcome.iterations >= limit || !finite) {
      last_failure = !outcome.converged ? outcome.failure
                     : !finite          ? std::string(kStepNotFinite)
                                        : "Newton needed " + std::to_string(outcome.iterations) +
                                              " iterations";
      ++rejections;
      if (rejections <= 10) {
        step_size *= 0.5;
      } else {
        step_size = std::max(step_size, 1.0) * 1.5;
        damping *= 0.75;
      }
      continue;
    }
    moved += step_size / steps;
    rejections = 0;
    damping = 1.0;
    step_size = step_size < 1.0 ? std::min(step_size * 1.1, 1.0) : std::max(step_size * 0.9, 1.0);
    u = trial;
    result.steps.push_back(std::move(step));
    if (options_.stop && options_.stop(result.steps.back())) {
      result.completed = true;
      return result;
    }
  }
  result.completed = moved > 1.0;
  if (!result.completed) {
    result.failed_increment = result.attempted_increments;
    result.message = "increment " + std::to_string(result.steps.size() + 1) + " (at " +
                     format_number(moved) + " of the prescribed motion) was rejected 21 times " +
                     "in a row; last: " + last_failure;
  }
  return result;
}

NewtonOutcome DisplacementControl::equilibrium_at(VectorX& u, double t, const VectorX& start,
                                                 const VectorX& prescribed,
                                                 const std::vector<Index>& imposed) {
  for (Index i : imposed) u[i] = start[i] + t * prescribed[i];
  // Newton stops at max_iterations even where reject_iterations would allow more.
  return newton_equilibrium(*assembler_, *solver_, u, no_load_, options_.newton,
                            std::min(options_.reject_iterations, options_.newton.max_iterations));
}

bool DisplacementControl::accepted(const NewtonOutcome& outcome) const {
  return outcome.converged && outcome.iterations < options_.reject_iterations;
}

PathResult solve_displacement_control(const model::Model& model, const VectorX& prescribed,
                                      int steps, const DisplacementControlOptions& options,
                                      const VectorX& initial) {
  return DisplacementControl(options).solve(model, prescribed, steps, initial);
}

}  // namespace kresling::solvers
