#include "kresling/solvers/path_follower.hpp"

#include <algorithm>
#include <string>

#include "kresling/solvers/increments.hpp"

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


}  // namespace

void follow_path(PathControl& control, assembly::Assembler& assembler, TangentSolver& solver,
                 VectorX& u, int steps, const FollowOptions& options, PathResult& result) {
  const std::vector<Index> recorded = control.recorded_dofs();
  const double sign = control.recorded_sign();
  result.constraint_dofs = recorded;
  result.families = family_names(control.model_at(0.0));
  if (control.changes_model()) assembler.rebind(control.model_at(0.0));
  VectorX external = VectorX::Zero(u.size());
  const int budget = options.reject_iterations;
  // Newton stops at max_iterations even when an increment may take more before it is
  // rejected (reject_iterations above max_iterations).
  const int newton_limit = budget > 0 ? std::min(budget, options.newton.max_iterations) : 0;
  auto accepted = [&](const NewtonOutcome& o) {
    return o.converged && (budget <= 0 || o.iterations < budget);
  };
  auto solve_at = [&](VectorX& trial, double t) {
    control.apply(t, trial, external);
    const NewtonOutcome outcome = newton_equilibrium(assembler, solver, trial, external,
                                                     options.newton, newton_limit, options.extra);
    result.newton_iterations += outcome.iterations;
    return outcome;
  };
  // The last accepted points of the path, for the extrapolated starting guess.
  std::vector<double> path_t{0.0};
  std::vector<VectorX> path_u{u};
  int previous_negative = 0;  // stability of the last accepted equilibrium
  march(steps, options.max_bisections, result,
        [&](double, double t_new, std::string& failure) {
          if (control.changes_model()) assembler.rebind(control.model_at(t_new));
          VectorX trial = u;
          NewtonOutcome outcome;
          if (options.extrapolation > 0) {
            extrapolate(path_t, path_u, options.extrapolation, t_new, trial);
            outcome = solve_at(trial, t_new);
            // Two cases where the previous equilibrium is the better start (MERLIN2's): past a
            // limit point of the driven motion (a snap) the extrapolated guess lies beyond the
            // end of the branch and Newton fails, where from the previous equilibrium it
            // reaches the branch the structure snaps to; past a bifurcation the guess can land
            // on an unstable branch where the previous equilibrium leads on along a stable
            // one. Retry from there (before the increment is halved), and keep the result if
            // it converged where the guess did not, or is more stable.
            const bool failed = !accepted(outcome);
            if (failed || outcome.negative_eigenvalues > previous_negative) {
              VectorX plain = u;
              const NewtonOutcome retry = solve_at(plain, t_new);
              if (accepted(retry) &&
                  (failed || (retry.negative_eigenvalues >= 0 &&
                              retry.negative_eigenvalues < outcome.negative_eigenvalues))) {
                trial = plain;
                outcome = retry;
              }
            }
          } else {
            outcome = solve_at(trial, t_new);
          }
          if (!accepted(outcome)) {
            failure = outcome.failure.empty()
                          ? "Newton needed " + std::to_string(outcome.iterations) + " iterations"
                          : outcome.failure;
            return false;
          }
          PathStep step = record_step(assembler, trial, t_new, outcome, recorded, sign);
          if (!finite_step(step)) {
            failure = kStepNotFinite;
            return false;
          }
          u = trial;
          if (outcome.negative_eigenvalues >= 0) previous_negative = outcome.negative_eigenvalues;
          result.steps.push_back(std::move(step));
          path_t.push_back(t_new);
          path_u.push_back(u);
          if (path_t.size() > 4) {  // the cubic's four points at most
            path_t.erase(path_t.begin());
            path_u.erase(path_u.begin());
          }
          return true;
        },
        [&] { return options.stop && options.stop(result.steps.back()); },
        [&](int k, double t, const std::string& reason) {
          return control.failure_message(k, steps, t, options.max_bisections, reason);
        });
}

}  // namespace kresling::solvers
