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

// The increments of one path (follow_path), as named steps over the state they share:
// the accepted state u, the increment being tried and the last equilibria (for the
// extrapolated or secant start).
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

// With relaxation to fall back on, Newton gives up once a correction exceeds this many times
// its first: its iterates are wandering off instead of closing in on the equilibrium near
// the increment's start. Measured on box-pleated sheets folded in Origami Simulator's
// material: the solves that went on to converge stayed within 2 times their first
// correction, those that wandered reached 10 to 800 times it within a few iterations and
// never converged in their budget.
constexpr double kRelaxedWandering = 10.0;

class PathFollower {
 public:
  PathFollower(PathControl& control, assembly::Assembler& assembler, TangentSolver& solver,
               VectorX& u, const FollowOptions& options, PathResult& result);
  /// False when the caller's stop rule ended the path (completed).
  bool run(StepPolicy& policy);

 private:
  bool accepted(const NewtonOutcome& o) const;
  NewtonOutcome solve_at(VectorX& trial);
  bool attempt(std::string& failure);
  NewtonOutcome solve_extrapolated(VectorX& trial);
  bool take(const VectorX& trial, const NewtonOutcome& outcome, std::string& failure);
  void keep(PathStep step, const VectorX& trial, const NewtonOutcome& outcome);
  void remember(double reached);
  // `whole`: an increment relaxed instead of halved (FollowOptions::relax_iterations), else
  // a snap at the smallest increment.
  bool snap(bool whole);
  // Relaxed increments (FollowOptions::relax) until a relaxation fails; then the path is
  // followed as without them up to the next accepted increment that is stable.
  bool relaxing() const { return options_.relax && !relax_failed_; }

  PathControl& control_;
  assembly::Assembler& assembler_;
  TangentSolver& solver_;
  VectorX& u_;
  const FollowOptions& options_;
  PathResult& result_;
  const std::vector<Index> recorded_;
  const double sign_;
  VectorX external_;
  const int default_limit_;
  const double default_reject_;
  const std::vector<Index> held_;
  Increment increment_;
  // The last accepted points of the path, for the extrapolated starting guess (kept only
  // when extrapolating).
  const bool extrapolating_;
  // The corrector's options while relaxing: with the relaxation to fall back on, Newton
  // gives an increment up once its corrections stop contracting (a wandering solve would
  // spend its whole budget before the relaxation, which converges there, is tried).
  NewtonOptions relaxed_newton_;
  std::vector<double> path_t_{0.0};
  std::vector<VectorX> path_u_;
  VectorX internal_;  // the internal force at an accepted increment's end (control.accepted)
  int previous_negative_ = 0;  // stability of the last accepted equilibrium
  // The secant start's last two equilibria: the one before u and the increment between.
  VectorX previous_u_;
  double previous_size_ = 0.0;
  bool relax_failed_ = false;
  std::string relax_failure_;  // why the last relaxation found no stable state
};

// Newton stops at max_iterations even when an increment may take more before it is
// rejected (reject_iterations above max_iterations).
PathFollower::PathFollower(PathControl& control, assembly::Assembler& assembler,
                           TangentSolver& solver, VectorX& u, const FollowOptions& options,
                           PathResult& result)
    : control_(control),
      assembler_(assembler),
      solver_(solver),
      u_(u),
      options_(options),
      result_(result),
      recorded_(control.recorded_dofs()),
      sign_(control.recorded_sign()),
      external_(VectorX::Zero(u.size())),
      default_limit_(options.reject_iterations > 0
                         ? std::min(options.reject_iterations, options.newton.max_iterations)
                         : 0),
      default_reject_(options.reject_iterations > 0
                          ? static_cast<double>(options.reject_iterations)
                          : std::numeric_limits<double>::infinity()),
      held_(control.held_dofs()),
      extrapolating_(options.extrapolation > 0),
      relaxed_newton_(options.newton) {
  relaxed_newton_.give_up_wandering = kRelaxedWandering;
  result_.constraint_dofs = recorded_;
  result_.families = family_names(control.model_at(0.0));
  if (control.changes_model()) assembler.rebind(control.model_at(0.0));
  if (extrapolating_) path_u_.push_back(u);
}

bool PathFollower::accepted(const NewtonOutcome& o) const {
  const double reject = increment_.reject_at > 0.0 ? increment_.reject_at : default_reject_;
  return o.converged && o.iterations < reject;
}

// The control's corrector (or damped Newton) from `trial`. The drive's move of its held
// DOFs is checked on its own (the barriers cannot shorten it): an increment whose
// prescribed motion would close a contact fails and is halved, so a path never jumps
// through a pair the free DOFs' corrections would keep apart.
NewtonOutcome PathFollower::solve_at(VectorX& trial) {
  control_.advance(increment_, u_, trial, external_);
  if (!start_within_barriers(assembler_.model(), u_, trial, held_)) {
    NewtonOutcome blocked;
    blocked.failure = kHeldMoveBlocked;
    return blocked;
  }
  const int limit = increment_.newton_limit > 0 ? increment_.newton_limit : default_limit_;
  ExtraTerms* own = control_.extra_terms(increment_);
  const NewtonOutcome outcome =
      increment_.damping == 1.0
          ? control_.correct(increment_, assembler_, solver_, trial, external_,
                             relaxing() ? relaxed_newton_ : options_.newton, limit,
                             own ? own : options_.extra)
          : damped_newton(assembler_, solver_, trial, options_.newton, increment_.damping);
  result_.newton_iterations += outcome.iterations;
  return outcome;
}

// One increment from its starting guess (the secant, an extrapolation or the previous
// equilibrium); false with the reason when it is not accepted.
bool PathFollower::attempt(std::string& failure) {
  const double t_new = increment_.to;
  if (control_.changes_model()) assembler_.rebind(control_.model_at(t_new));
  VectorX trial = u_;
  NewtonOutcome outcome;
  if (options_.secant_start) {
    if (previous_size_ > 0.0) trial += (increment_.size / previous_size_) * (u_ - previous_u_);
    shorten_to_barriers(assembler_.model(), u_, trial);
    outcome = solve_at(trial);
  } else if (options_.extrapolation > 0 && increment_.damping == 1.0) {
    outcome = solve_extrapolated(trial);
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
  return take(trial, outcome, failure);
}

// From the extrapolated guess. Two cases where the previous equilibrium is the better start
// (MERLIN2's): past a limit point of the driven motion (a snap) the extrapolated guess lies
// beyond the end of the branch and Newton fails, where from the previous equilibrium it
// reaches the branch the structure snaps to; past a bifurcation the guess can land on an
// unstable branch where the previous equilibrium leads on along a stable one. Retry from
// there (before the increment is halved), and keep the result if it converged where the
// guess did not, or is more stable.
NewtonOutcome PathFollower::solve_extrapolated(VectorX& trial) {
  extrapolate(path_t_, path_u_, options_.extrapolation, increment_.to, trial);
  shorten_to_barriers(assembler_.model(), u_, trial);
  NewtonOutcome outcome = solve_at(trial);
  // (A relaxed path relaxes such an increment instead: FollowOptions::relax.)
  const bool failed = !accepted(outcome);
  if (!relaxing() && (failed || outcome.negative_eigenvalues > previous_negative_)) {
    VectorX plain = u_;
    const NewtonOutcome retry = solve_at(plain);
    if (accepted(retry) &&
        (failed || (retry.negative_eigenvalues >= 0 &&
                    retry.negative_eigenvalues < outcome.negative_eigenvalues))) {
      trial = plain;
      outcome = retry;
    }
  }
  return outcome;
}

// A converged increment, past the caller's check and recorded, becomes the path's next
// point; false with the reason when the check refuses it or its step is not finite.
bool PathFollower::take(const VectorX& trial, const NewtonOutcome& outcome,
                        std::string& failure) {
  if (options_.check) {
    failure = options_.check(increment_, trial, outcome);
    if (!failure.empty()) return false;
  }
  // Where the increment ended: t_new, unless the corrector solved for the parameter.
  const double reached = increment_.to;
  PathStep step =
      control_.record(assembler_, trial, reached, outcome, recorded_, sign_, internal_);
  if (!finite_step(step)) {
    failure = kStepNotFinite;
    return false;
  }
  if (options_.secant_start) {
    previous_u_ = u_;
    previous_size_ = increment_.size;
  }
  keep(std::move(step), trial, outcome);
  remember(reached);
  return true;
}

// Take a recorded step (from `outcome`, at `trial`) as the path's next point.
void PathFollower::keep(PathStep step, const VectorX& trial, const NewtonOutcome& outcome) {
  u_ = trial;
  if (outcome.negative_eigenvalues >= 0) previous_negative_ = outcome.negative_eigenvalues;
  result_.steps.push_back(std::move(step));
  control_.accepted(increment_, u_, result_.steps.back(), internal_);
}

// The accepted point among the last four the extrapolation goes through.
void PathFollower::remember(double reached) {
  if (!extrapolating_) return;
  path_t_.push_back(reached);
  path_u_.push_back(u_);
  if (path_t_.size() > 4) {  // the cubic's four points at most
    path_t_.erase(path_t_.begin());
    path_u_.erase(path_u_.begin());
  }
}

// Past a limit point the structure snaps: at the failed increment's end, the energy
// descends from the last equilibrium to a stable one, which becomes the path's next step.
// The descent's steps are bounded by the model's size (not in mm), so it follows the
// landscape at any scale.
bool PathFollower::snap(bool whole) {
  if (control_.changes_model()) assembler_.rebind(control_.model_at(increment_.to));
  VectorX trial = u_;
  control_.advance(increment_, u_, trial, external_);
  if (!start_within_barriers(assembler_.model(), u_, trial, held_)) return false;
  const double size = model::node_extent(assembler_.model().nodes());
  EnergyMinimumOptions descent;
  descent.tolerance = options_.newton.tolerance;
  descent.max_iterations = 2000;
  descent.max_step = 0.01 * size;
  descent.escape_step = 1e-3 * size;
  NewtonOutcome outcome;
  if (options_.relax) {
    RelaxationOptions relax = relaxation(descent);
    if (whole) relax.max_iterations = options_.relax_iterations;
    const Relaxation rest = relax_to_stable(assembler_, solver_, trial, relax, &external_);
    result_.newton_iterations += rest.iterations;
    if (!rest.converged) {
      relax_failure_ = rest.failure;
      return false;
    }
    outcome.iterations = rest.iterations;
    outcome.negative_eigenvalues = 0;
  } else {
    // Dense eigen-decompositions up to kMaxSnapDofs, shifted sparse Cholesky beyond.
    const EnergyMinimum rest =
        assembler_.size() > kMaxSnapDofs
            ? minimize_energy_sparse(assembler_, solver_, trial, descent, &external_)
            : minimize_energy(assembler_, trial, descent, &external_);
    result_.newton_iterations += rest.iterations;
    if (!rest.converged) return false;
    outcome.iterations = rest.iterations;
    outcome.negative_eigenvalues = rest.negative_eigenvalues;
  }
  outcome.converged = true;
  PathStep step =
      control_.record(assembler_, trial, increment_.to, outcome, recorded_, sign_, internal_);
  if (!finite_step(step)) return false;
  step.snapped = true;
  keep(std::move(step), trial, outcome);
  // The path jumped: nothing before the snap extrapolates past it.
  previous_size_ = 0.0;
  if (extrapolating_) {
    path_t_.assign(1, increment_.to);
    path_u_.assign(1, u_);
  }
  return true;
}

bool PathFollower::run(StepPolicy& policy) {
  while (policy.next(increment_)) {
    check_interrupt();
    ++result_.attempted_increments;
    std::string failure;
    relax_failure_.clear();
    const bool accepted_now = attempt(failure) || (relaxing() && snap(true));
    if (!relax_failure_.empty()) {  // said, and the increment's parts followed unrelaxed
      failure += "; relaxed, " + relax_failure_;
      relax_failed_ = true;
    }
    if (accepted_now) {
      // Relax again once the path is stable again: along an unstable stretch (no stable
      // state near it) each relaxation would fail again, at its whole budget per increment.
      if (previous_negative_ <= 0) relax_failed_ = false;
      policy.accepted(increment_);
    } else if (policy.rejected(increment_, failure)) {
      continue;  // tried again smaller
    } else if (!(options_.snap && snap(false) && policy.resume(increment_))) {
      break;
    }
    if (options_.stop && options_.stop(result_.steps.back())) {
      result_.completed = true;
      return false;
    }
  }
  return true;
}

}  // namespace

void follow_path(PathControl& control, assembly::Assembler& assembler, TangentSolver& solver,
                 VectorX& u, StepPolicy& policy, const FollowOptions& options,
                 PathResult& result) {
  PathFollower follower(control, assembler, solver, u, options, result);
  if (follower.run(policy)) policy.finish(control, result);
}

void follow_path(PathControl& control, assembly::Assembler& assembler, TangentSolver& solver,
                 VectorX& u, int steps, const FollowOptions& options, PathResult& result) {
  EqualIncrements policy(steps, options.max_bisections);
  follow_path(control, assembler, solver, u, policy, options, result);
}

}  // namespace kresling::solvers
