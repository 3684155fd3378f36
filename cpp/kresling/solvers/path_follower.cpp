#include "kresling/solvers/path_follower.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include "kresling/core/interrupt.hpp"
#include "kresling/model/model.hpp"
#include "kresling/solvers/damped_newton.hpp"
#include "kresling/solvers/energy_minimum.hpp"
#include "kresling/solvers/increments.hpp"
#include "kresling/solvers/stable_relaxation.hpp"

namespace kresling::solvers {

namespace {

// Lagrange extrapolation of the free DOFs to path parameter t from the last (order + 1)
// accepted points (t_i, u_i); held DOFs are overwritten by the control.
void extrapolate(const std::vector<double>& ts, const std::vector<VectorX>& us, int order,
                 double t, VectorX& u) {
  const int points = std::min<int>(order + 1, static_cast<int>(ts.size()));
  if (points < 2) return;  // nothing to extrapolate from: keep the previous equilibrium
  const std::size_t first = ts.size() - points;
  u.setZero();
  for (std::size_t i = first; i < ts.size(); ++i) {
    double weight = 1.0;
    for (std::size_t j = first; j < ts.size(); ++j) {
      if (j != i) weight *= (t - ts[j]) / (ts[i] - ts[j]);
    }
    u += weight * us[i];
  }
}


// The relaxation's options from the snap's descent's (the same tolerance, lengths and
// budget).
RelaxationOptions relaxation(const EnergyMinimumOptions& descent) {
  RelaxationOptions out;
  out.tolerance = descent.tolerance;
  out.max_iterations = descent.max_iterations;
  out.max_step = descent.max_step;
  out.escape_step = descent.escape_step;
  return out;
}

}  // namespace

void follow_path(PathControl& control, assembly::Assembler& assembler, TangentSolver& solver,
                 VectorX& u, StepPolicy& policy, const FollowOptions& options,
                 PathResult& result) {
  const std::vector<Index> recorded = control.recorded_dofs();
  const double sign = control.recorded_sign();
  result.constraint_dofs = recorded;
  result.families = family_names(control.model_at(0.0));
  if (control.changes_model()) assembler.rebind(control.model_at(0.0));
  VectorX external = VectorX::Zero(u.size());
  const int budget = options.reject_iterations;
  // Newton stops at max_iterations even when an increment may take more before it is
  // rejected (reject_iterations above max_iterations).
  const int default_limit = budget > 0 ? std::min(budget, options.newton.max_iterations) : 0;
  const double default_reject =
      budget > 0 ? static_cast<double>(budget) : std::numeric_limits<double>::infinity();
  Increment increment;
  auto accepted = [&](const NewtonOutcome& o) {
    const double reject = increment.reject_at > 0.0 ? increment.reject_at : default_reject;
    return o.converged && o.iterations < reject;
  };
  const std::vector<Index> held = control.held_dofs();
  auto solve_at = [&](VectorX& trial) {
    control.advance(increment, u, trial, external);
    // The drive's move of its held DOFs is checked on its own (the barriers cannot shorten
    // it): an increment whose prescribed motion would close a contact fails and is halved,
    // so a path never jumps through a pair the free DOFs' corrections would keep apart.
    if (!start_within_barriers(assembler.model(), u, trial, held)) {
      NewtonOutcome blocked;
      blocked.failure = kHeldMoveBlocked;
      return blocked;
    }
    const int limit = increment.newton_limit > 0 ? increment.newton_limit : default_limit;
    ExtraTerms* own = control.extra_terms(increment);
    const NewtonOutcome outcome =
        increment.damping == 1.0
            ? control.correct(increment, assembler, solver, trial, external, options.newton,
                              limit, own ? own : options.extra)
            : damped_newton(assembler, solver, trial, options.newton, increment.damping);
    result.newton_iterations += outcome.iterations;
    return outcome;
  };
  // Relaxed increments (FollowOptions::relax) until a relaxation fails; then the path is
  // followed as without them up to the next accepted increment.
  bool relax_failed = false;
  auto relaxing = [&]() { return options.relax && !relax_failed; };
  // The last accepted points of the path, for the extrapolated starting guess (kept only
  // when extrapolating).
  const bool extrapolating = options.extrapolation > 0;
  std::vector<double> path_t{0.0};
  std::vector<VectorX> path_u;
  if (extrapolating) path_u.push_back(u);
  VectorX internal;  // the internal force at an accepted increment's end (control.accepted)
  int previous_negative = 0;  // stability of the last accepted equilibrium
  // The secant start's last two equilibria: the one before u and the increment between.
  VectorX previous_u;
  double previous_size = 0.0;
  // Take a recorded step (from `outcome`, at `trial`) as the path's next point.
  auto keep = [&](PathStep step, const VectorX& trial, const NewtonOutcome& outcome) {
    u = trial;
    if (outcome.negative_eigenvalues >= 0) previous_negative = outcome.negative_eigenvalues;
    result.steps.push_back(std::move(step));
    control.accepted(increment, u, result.steps.back(), internal);
  };
  auto attempt = [&](std::string& failure) {
    const double t_new = increment.to;
    if (control.changes_model()) assembler.rebind(control.model_at(t_new));
    VectorX trial = u;
    NewtonOutcome outcome;
    if (options.secant_start) {
      if (previous_size > 0.0) trial += (increment.size / previous_size) * (u - previous_u);
      shorten_to_barriers(assembler.model(), u, trial);
      outcome = solve_at(trial);
    } else if (options.extrapolation > 0 && increment.damping == 1.0) {
      extrapolate(path_t, path_u, options.extrapolation, t_new, trial);
      shorten_to_barriers(assembler.model(), u, trial);
      outcome = solve_at(trial);
      // Two cases where the previous equilibrium is the better start (MERLIN2's): past a
      // limit point of the driven motion (a snap) the extrapolated guess lies beyond the
      // end of the branch and Newton fails, where from the previous equilibrium it reaches
      // the branch the structure snaps to; past a bifurcation the guess can land on an
      // unstable branch where the previous equilibrium leads on along a stable one. Retry
      // from there (before the increment is halved), and keep the result if it converged
      // where the guess did not, or is more stable.
      // (A relaxed path relaxes such an increment instead: FollowOptions::relax.)
      const bool failed = !accepted(outcome);
      if (!relaxing() && (failed || outcome.negative_eigenvalues > previous_negative)) {
        VectorX plain = u;
        const NewtonOutcome retry = solve_at(plain);
        if (accepted(retry) &&
            (failed || (retry.negative_eigenvalues >= 0 &&
                        retry.negative_eigenvalues < outcome.negative_eigenvalues))) {
          trial = plain;
          outcome = retry;
        }
      }
    } else {
      outcome = solve_at(trial);
    }
    if (!accepted(outcome)) {
      failure = outcome.failure.empty()
                    ? "Newton needed " + std::to_string(outcome.iterations) + " iterations"
                    : outcome.failure;
      return false;
    }
    if (relaxing() && outcome.negative_eigenvalues > 0) {
      failure = "the equilibrium is unstable (" + std::to_string(outcome.negative_eigenvalues) +
                " negative eigenvalues)";
      return false;
    }
    if (options.check) {
      failure = options.check(increment, trial, outcome);
      if (!failure.empty()) return false;
    }
    // Where the increment ended: t_new, unless the corrector solved for the parameter.
    const double reached = increment.to;
    PathStep step = control.record(assembler, trial, reached, outcome, recorded, sign, internal);
    if (!finite_step(step)) {
      failure = kStepNotFinite;
      return false;
    }
    if (options.secant_start) {
      previous_u = u;
      previous_size = increment.size;
    }
    keep(std::move(step), trial, outcome);
    if (extrapolating) {
      path_t.push_back(reached);
      path_u.push_back(u);
      if (path_t.size() > 4) {  // the cubic's four points at most
        path_t.erase(path_t.begin());
        path_u.erase(path_u.begin());
      }
    }
    return true;
  };
  // Past a limit point the structure snaps: at the failed increment's end, the energy
  // descends from the last equilibrium to a stable one, which becomes the path's next step.
  // The descent's steps are bounded by the model's size (not in mm), so it follows the
  // landscape at any scale.
  std::string relax_failure;  // why the last relaxation found no stable state
  // `whole`: an increment relaxed instead of halved (FollowOptions::relax_iterations), else
  // a snap at the smallest increment.
  auto snap = [&](bool whole) {
    if (control.changes_model()) assembler.rebind(control.model_at(increment.to));
    VectorX trial = u;
    control.advance(increment, u, trial, external);
    if (!start_within_barriers(assembler.model(), u, trial, held)) return false;
    const double size = model::node_extent(assembler.model().nodes());
    EnergyMinimumOptions descent;
    descent.tolerance = options.newton.tolerance;
    descent.max_iterations = 2000;
    descent.max_step = 0.01 * size;
    descent.escape_step = 1e-3 * size;
    NewtonOutcome outcome;
    if (options.relax) {
      RelaxationOptions relax = relaxation(descent);
      if (whole) relax.max_iterations = options.relax_iterations;
      const Relaxation rest = relax_to_stable(assembler, solver, trial, relax, &external);
      result.newton_iterations += rest.iterations;
      if (!rest.converged) {
        relax_failure = rest.failure;
        return false;
      }
      outcome.iterations = rest.iterations;
      outcome.negative_eigenvalues = 0;
    } else {
      // Dense eigen-decompositions up to kMaxSnapDofs, shifted sparse Cholesky beyond.
      const EnergyMinimum rest =
          assembler.size() > kMaxSnapDofs
              ? minimize_energy_sparse(assembler, solver, trial, descent, &external)
              : minimize_energy(assembler, trial, descent, &external);
      result.newton_iterations += rest.iterations;
      if (!rest.converged) return false;
      outcome.iterations = rest.iterations;
      outcome.negative_eigenvalues = rest.negative_eigenvalues;
    }
    outcome.converged = true;
    PathStep step =
        control.record(assembler, trial, increment.to, outcome, recorded, sign, internal);
    if (!finite_step(step)) return false;
    step.snapped = true;
    keep(std::move(step), trial, outcome);
    // The path jumped: nothing before the snap extrapolates past it.
    previous_size = 0.0;
    if (extrapolating) {
      path_t.assign(1, increment.to);
      path_u.assign(1, u);
    }
    return true;
  };
  while (policy.next(increment)) {
    check_interrupt();
    ++result.attempted_increments;
    std::string failure;
    relax_failure.clear();
    const bool accepted_now = attempt(failure) || (relaxing() && snap(true));
    if (!relax_failure.empty()) {  // said, and the increment's parts followed unrelaxed
      failure += "; relaxed, " + relax_failure;
      relax_failed = true;
    }
    if (accepted_now) {
      relax_failed = false;
      policy.accepted(increment);
    } else if (policy.rejected(increment, failure)) {
      continue;  // tried again smaller
    } else if (!(options.snap && snap(false) && policy.resume(increment))) {
      break;
    }
    if (options.stop && options.stop(result.steps.back())) {
      result.completed = true;
      return;
    }
  }
  policy.finish(control, result);
}

void follow_path(PathControl& control, assembly::Assembler& assembler, TangentSolver& solver,
                 VectorX& u, int steps, const FollowOptions& options, PathResult& result) {
  EqualIncrements policy(steps, options.max_bisections);
  follow_path(control, assembler, solver, u, policy, options, result);
}

}  // namespace kresling::solvers
