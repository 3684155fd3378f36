#include "kresling/solvers/adaptive_path.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "kresling/core/check.hpp"
#include "kresling/core/interrupt.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/path_point.hpp"

namespace kresling::solvers {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// An increment's displacement predictor may miss its converged point by this much [mm]
// (max-norm): Newton then converges in one or two iterations.
constexpr double kPredictorError = 1e-4;
// Stability changes, law kinks and cables going slack are located to this fraction of a
// sample spacing.
constexpr double kEventWidth = 1e-3;

std::string why(const NewtonOutcome& o) {
  return o.failure.empty() ? "Newton needed " + std::to_string(o.iterations) + " iterations"
                           : o.failure;
}

// A converged point as a sample.
PathStep as_step(const PathPoint& p) {
  PathStep step;
  step.load_factor = p.t;
  step.displacement = p.u;
  step.constraint_force = p.force;
  step.energies = p.energy;
  step.iterations = p.outcome.iterations;
  step.negative_eigenvalues = p.outcome.negative_eigenvalues;
  return step;
}

// What becomes of an increment once its end has been tried.
enum class Verdict {
  kAccepted,  // its samples are taken; the path goes on from its end
  kEvent,     // an event lies inside: it is located before the path steps on
  kShorter,   // the error estimate asks for a shorter increment
  kFailed,    // its end (or a sample inside) did not converge: halved
  kStopped,   // the caller's stopping rule ended the path
};

// The adaptive increments of one path (follow_adaptive), as named steps over the state
// they share: the last converged point `a_` and the one before it, the next length, the
// event being located and the next sample to record.
class AdaptiveFollower {
 public:
  AdaptiveFollower(PathControl& control, assembly::Assembler& assembler,
                   assembly::Assembler& full, TangentSolver& solver, Index size, int steps,
                   const AdaptiveOptions& options);
  PathResult run(const VectorX& start);

 private:
  void bind(double t);
  bool accepted(const NewtonOutcome& o) const;
  NewtonOutcome newton(VectorX& w, double t, const VectorX* from = nullptr);
  bool complete(PathPoint& p);
  double sample_at(int k) const { return k == steps_ ? 1.0 : k * spacing_; }
  bool converge_start(const VectorX& start);
  double increment_end(bool locating, bool located);
  double aimed_at_kink(double t1);
  PathPoint converge_end(double t1, bool located, VectorX& predicted);
  void prefer_stable_branch(PathPoint& b, double t1);
  Verdict judge(PathPoint& b, bool locating, double length, double& error_factor);
  Verdict estimate_error(PathPoint& b, double length, double& error_factor);
  Verdict take_samples(PathPoint& b);
  PathStep interpolated_sample(const PathPoint& b, double ts);
  void keep_knot(const PathPoint& p);
  bool solved_sample(PathPoint& b, double ts, PathStep& step);
  bool halve(const PathPoint& b, double length);
  void set_next_length(const PathPoint& b, const VectorX& predicted, double length,
                       double error_factor, bool cut_short);
  void step_on(PathPoint& b, bool locating);

  PathControl& control_;
  assembly::Assembler& assembler_;
  assembly::Assembler& full_;
  TangentSolver& solver_;
  const int steps_;
  const AdaptiveOptions& options_;
  const std::vector<Index> recorded_;
  const double sign_;
  const std::vector<Index> held_;
  const int budget_;
  const int newton_limit_;
  const double spacing_;
  const double smallest_;
  const double event_width_;
  VectorX external_;
  PathResult result_;
  double monitored_scale_ = 0.0;  // the monitored quantity's largest magnitude so far
  PathPoint a_;                   // the last converged point
  PathPoint previous_;            // the point before a_ (t = -1: none to extrapolate from)
  double h_;                      // the next increment by the error estimate
  double event_end_ = kInfinity;  // an event (stability change, law kink) lies in (a_.t, this]
  PathPoint event_point_;         // the converged point there
  int predictions_ = 0;           // aimed location steps towards the present event
  int next_ = 1;                  // the next sample to record
  std::string first_failure_;     // why the increment from a_ failed at full size
  double first_length_ = 0.0;     // that size
};

AdaptiveFollower::AdaptiveFollower(PathControl& control, assembly::Assembler& assembler,
                                   assembly::Assembler& full, TangentSolver& solver, Index size,
                                   int steps, const AdaptiveOptions& options)
    : control_(control),
      assembler_(assembler),
      full_(full),
      solver_(solver),
      steps_(steps),
      options_(options),
      recorded_(control.recorded_dofs()),
      sign_(control.recorded_sign()),
      held_(control.held_dofs()),
      budget_(options.reject_iterations),
      // Newton stops at max_iterations even where reject_iterations would allow more.
      newton_limit_(budget_ > 0 ? std::min(budget_, options.newton.max_iterations) : 0),
      spacing_(1.0 / steps),
      smallest_(std::ldexp(spacing_, -options.max_bisections)),
      event_width_(kEventWidth * spacing_),
      external_(VectorX::Zero(size)),
      h_(spacing_) {
  result_.constraint_dofs = recorded_;
  result_.families = family_names(control.model_at(0.0));
  bind(0.0);
}

// Rebinds both assemblers to the model at t (for a control that changes it).
void AdaptiveFollower::bind(double t) {
  if (!control_.changes_model()) return;
  const model::Model& at = control_.model_at(t);
  assembler_.rebind(at);
  full_.rebind(at);
}

bool AdaptiveFollower::accepted(const NewtonOutcome& o) const {
  return o.converged && (budget_ <= 0 || o.iterations < budget_);
}

// Newton at t from w; `from` (the last equilibrium) when the drive's held DOFs move from
// there, checked against the barriers first (start_within_barriers: a prescribed jump the
// barriers cannot shorten).
NewtonOutcome AdaptiveFollower::newton(VectorX& w, double t, const VectorX* from) {
  bind(t);
  control_.apply(t, w, external_);
  if (from != nullptr && !start_within_barriers(assembler_.model(), *from, w, held_)) {
    NewtonOutcome blocked;
    blocked.failure = kHeldMoveBlocked;
    return blocked;
  }
  const NewtonOutcome outcome = newton_equilibrium(assembler_, solver_, w, external_,
                                                   options_.newton, newton_limit_);
  result_.newton_iterations += outcome.iterations;
  return outcome;
}

// A converged point's forces, energies, stability, law pieces and path derivatives.
bool AdaptiveFollower::complete(PathPoint& p) {
  if (!path_derivatives(assembler_, full_, solver_, control_, recorded_, sign_, p)) {
    p.outcome.failure =
        "the converged state's internal force, energy or path tangent is not finite (an "
        "element's law is singular there, e.g. a hinge folded flat)";
    return false;
  }
  p.negative = p.outcome.negative_eigenvalues;
  p.pieces = law_pieces(assembler_.model(), p.u);
  return true;
}

// The start, brought to equilibrium (it usually is one: one iteration).
bool AdaptiveFollower::converge_start(const VectorX& start) {
  a_.t = 0.0;
  a_.u = start;
  a_.outcome = newton(a_.u, 0.0);
  ++result_.attempted_increments;
  if (!accepted(a_.outcome) || !complete(a_)) {
    result_.failed_increment = 1;
    result_.message = "the starting state has no equilibrium nearby: " + why(a_.outcome);
    return false;
  }
  previous_.t = -1.0;
  keep_knot(a_);
  return true;
}

void AdaptiveFollower::keep_knot(const PathPoint& p) {
  if (options_.keep_knots) result_.knots.push_back(PathKnot{p.t, p.u, p.velocity});
}

// The increment's end: a bisection towards a known event, else the error estimate's size,
// snapped to a sample within a millionth of the spacing (so that a sample is not left a
// sliver away from a converged point). An increment with no error estimate (the first, the
// first past an event) ends at the next sample at the latest. Located: the event's
// converged point is within the width, and is the increment's end.
double AdaptiveFollower::increment_end(bool locating, bool located) {
  if (located) return event_end_;
  if (locating) return aimed_at_kink(a_.t + 0.5 * (event_end_ - a_.t));
  double t1 = previous_.t < 0.0 ? std::min(a_.t + h_, sample_at(next_))
                                : std::min(1.0, a_.t + h_);
  const double k = std::round(t1 * steps_);
  if (std::abs(t1 - k * spacing_) < 1e-6 * spacing_) t1 = sample_at(static_cast<int>(k));
  return t1;
}

// A law kink: aimed at just past (or before) the predicted crossing, on the side away from
// the nearer end of the bracket, so that the next step closes it to the width (two solves
// per kink where bisection from a few spacings takes ~12). The bisection `t1` for a
// stability change, or when four aimed steps have not closed it.
double AdaptiveFollower::aimed_at_kink(double t1) {
  const double kink = predictions_ < 4 ? predicted_kink(assembler_.model(), a_, event_point_)
                                       : std::numeric_limits<double>::quiet_NaN();
  if (!std::isfinite(kink)) return t1;
  const double aim = kink - a_.t <= event_end_ - kink ? kink + 0.4 * event_width_
                                                      : kink - 0.4 * event_width_;
  if (aim > a_.t + 0.01 * event_width_ && aim < event_end_ - 0.01 * event_width_) {
    ++predictions_;
    return aim;
  }
  return t1;
}

// The increment's end point: the located event's (converged and completed when the event
// was found), else Newton at t1 from the predictor (the Hermite curve through the last two
// points, or the tangent at a_), shortened so that no pair crosses on the way there.
PathPoint AdaptiveFollower::converge_end(double t1, bool located, VectorX& predicted) {
  PathPoint b;
  if (located) {
    b = std::move(event_point_);
    predicted = b.u;
    return b;
  }
  ++result_.attempted_increments;
  b.t = t1;
  predicted = previous_.t >= 0.0 ? hermite_u(previous_, a_, t1)
                                 : VectorX(a_.u + (t1 - a_.t) * a_.velocity);
  b.u = predicted;
  shorten_to_barriers(assembler_.model(), a_.u, b.u);
  b.outcome = newton(b.u, t1, &a_.u);
  prefer_stable_branch(b, t1);
  return b;
}

// Past a bifurcation a predicted start may land on a less stable branch than the one the
// last equilibrium leads on to (the branch the fixed-step path follows): retry from there
// and keep the more stable.
void AdaptiveFollower::prefer_stable_branch(PathPoint& b, double t1) {
  if (!accepted(b.outcome) || a_.negative < 0 ||
      b.outcome.negative_eigenvalues <= a_.negative) {
    return;
  }
  VectorX plain = a_.u;
  const NewtonOutcome retry = newton(plain, t1, &a_.u);
  if (accepted(retry) && retry.negative_eigenvalues >= 0 &&
      retry.negative_eigenvalues < b.outcome.negative_eigenvalues) {
    b.u = plain;
    b.outcome = retry;
  }
}

// A converged end: an event inside is located first; otherwise the error estimate decides.
// `error_factor` is how far the next increment may grow by the force error.
Verdict AdaptiveFollower::judge(PathPoint& b, bool locating, double length,
                                double& error_factor) {
  const bool event = b.negative != a_.negative || b.pieces != a_.pieces;
  if (event && length > event_width_) {
    if (!locating) predictions_ = 0;
    event_end_ = b.t;  // locate it before stepping on
    event_point_ = std::move(b);
    return Verdict::kEvent;
  }
  return estimate_error(b, length, error_factor);
}

// The dense output's error, on the monitored quantity G (the drive's force under
// displacement control: how it is shared among the driven DOFs is determined only to the
// Newton tolerance, stiff bars redistributing it, so the estimate is not held to that): its
// Hermite curve through the previous increment, extrapolated to b, misses b's by
// D/24 (b-p)^2 (b-a)^2 (D: its fourth derivative); the interpolant on (a, b) errs by at
// most D/24 ((b-a)/2)^4, that times (b-a)^2 / (16 (b-p)^2).
Verdict AdaptiveFollower::estimate_error(PathPoint& b, double length, double& error_factor) {
  const bool inside = next_ <= steps_ && sample_at(next_) < b.t;
  const auto monitored = [&](const PathPoint& p) {
    return control_.monitored(p.force, p.energy);
  };
  monitored_scale_ =
      std::max({monitored_scale_, std::abs(monitored(b)), std::abs(monitored(a_))});
  const double allowed = options_.tolerance * monitored_scale_;
  if (previous_.t < 0.0) {
    if (!inside) return Verdict::kAccepted;
    // No estimate yet (only after a failed first increment): shorter.
    b.outcome.failure = "no error estimate for the first increment";
    return Verdict::kFailed;
  }
  const VectorX extrapolated = hermite<VectorX>(previous_.t, previous_.force,
                                                previous_.force_rate, a_.t, a_.force,
                                                a_.force_rate, b.t);
  const VectorX extrapolated_energy =
      hermite<VectorX>(previous_.t, previous_.energy, previous_.energy_rate, a_.t, a_.energy,
                       a_.energy_rate, b.t);
  const double span = b.t - previous_.t;
  const double estimate =
      std::abs(control_.monitored(b.force - extrapolated, b.energy - extrapolated_energy)) *
      length * length / (16.0 * span * span);
  error_factor = estimate > 0.0 ? 0.9 * std::pow(allowed / estimate, 0.25) : 4.0;
  if (inside && estimate > allowed && length > event_width_) {
    // Never shorter than to the next sample: an increment with no sample inside has no
    // dense output error, so the path moves on at least as the fixed steps do.
    h_ = std::max(length * std::clamp(error_factor, 0.2, 0.9), sample_at(next_) - a_.t);
    event_end_ = kInfinity;
    return Verdict::kShorter;
  }
  return Verdict::kAccepted;
}

// The samples in (a.t, b.t]: b itself, or the Hermite curves (displacements, forces,
// energies) between a and b; across a located event, Newton at the sample. With a barrier
// (contact) a curve between two states that are apart may still pass a pair through each
// other: each sample is then solved by Newton from it instead, its start shortened from a
// as every move is.
Verdict AdaptiveFollower::take_samples(PathPoint& b) {
  const bool same_stability = a_.negative == b.negative;
  const bool interpolate = same_stability && !families_limit_steps(assembler_.model());
  while (next_ <= steps_ && sample_at(next_) <= b.t) {
    const double ts = sample_at(next_);
    PathStep step;
    if (ts == b.t) {
      step = as_step(b);
    } else if (interpolate) {
      step = interpolated_sample(b, ts);
    } else if (!solved_sample(b, ts, step)) {
      return Verdict::kFailed;
    }
    result_.steps.push_back(std::move(step));
    // Read off the curves ending at b, which becomes the next knot once accepted.
    if (options_.keep_knots) {
      result_.step_knot.push_back(interpolate ? static_cast<int>(result_.knots.size()) : -1);
    }
    ++next_;
    if (options_.stop && options_.stop(result_.steps.back())) return Verdict::kStopped;
  }
  return Verdict::kAccepted;
}

PathStep AdaptiveFollower::interpolated_sample(const PathPoint& b, double ts) {
  PathStep step;
  step.load_factor = ts;
  step.displacement = hermite_u(a_, b, ts);
  control_.apply(ts, step.displacement, external_);  // the held DOFs exactly
  step.constraint_force =
      hermite<VectorX>(a_.t, a_.force, a_.force_rate, b.t, b.force, b.force_rate, ts);
  step.energies =
      hermite<VectorX>(a_.t, a_.energy, a_.energy_rate, b.t, b.energy, b.energy_rate, ts);
  step.iterations = 0;
  step.negative_eigenvalues = b.negative;
  return step;
}

// A sample converged by Newton from the Hermite curve; false (with b's failure set) when it
// does not converge or its force is not finite.
bool AdaptiveFollower::solved_sample(PathPoint& b, double ts, PathStep& step) {
  ++result_.attempted_increments;
  VectorX w = hermite_u(a_, b, ts);
  shorten_to_barriers(assembler_.model(), a_.u, w);
  const NewtonOutcome o = newton(w, ts, &a_.u);
  if (!accepted(o)) {
    b.outcome.failure = "a sample inside the increment: " + why(o);
    return false;
  }
  step = record_step(assembler_, w, ts, o, recorded_, sign_);
  if (!finite_step(step)) {
    b.outcome.failure = "a sample inside the increment: its force is not finite";
    return false;
  }
  return true;
}

// A failed increment is halved; false when it falls below the smallest allowed, with the
// path's message.
bool AdaptiveFollower::halve(const PathPoint& b, double length) {
  if (first_failure_.empty()) {
    first_failure_ = why(b.outcome);
    first_length_ = length;
  }
  h_ = 0.5 * length;
  event_end_ = kInfinity;
  if (!(h_ < smallest_)) return true;
  result_.failed_increment = result_.attempted_increments;
  result_.message = "increment " + std::to_string(next_) + " (of " + std::to_string(steps_) +
                    ", at " + format_rounded(a_.t) + " of " + control_.parameter_name() +
                    ") failed: the adaptive increment fell below 1/2^" +
                    std::to_string(options_.max_bisections) + " of a sample spacing; at full size: " +
                    failure_at_sizes(first_failure_, length, why(b.outcome), length < first_length_);
  return false;
}

// The next increment: by the force error, and so that the displacement predictor stays
// within kPredictorError (Newton then converges in one or two iterations); its error grows
// like the length to the power 4 (cubic Hermite; 2 for the first, linear one). Increments
// cut short (by an event or the path's end) do not set it.
void AdaptiveFollower::set_next_length(const PathPoint& b, const VectorX& predicted,
                                       double length, double error_factor, bool cut_short) {
  const double u_error = (b.u - predicted).lpNorm<Eigen::Infinity>();
  const double order = previous_.t >= 0.0 ? 4.0 : 2.0;
  double factor = u_error > 0.0 ? 0.9 * std::pow(kPredictorError / u_error, 1.0 / order) : 4.0;
  factor = std::clamp(std::min(factor, error_factor), 0.2, 4.0);
  if (b.outcome.iterations > 4) factor = std::min(factor, 0.5);
  h_ = cut_short ? (factor < 1.0 ? std::min(h_, length * factor) : h_) : length * factor;
  if (next_ <= steps_) h_ = std::max(h_, sample_at(next_) - b.t);  // to the next sample at least
  h_ = std::max(h_, smallest_);
}

// The path moves on to b. The bracket is closed at its end, or by a short step across the
// event (nothing left to locate between b and the event's point when their pieces and
// stability agree). Across an event (a law kink, a stability change) the path's derivatives
// jump: a cubic through points on either side, extrapolated, misses by the jump times the
// length (it sent Newton to 25 iterations and halvings after every kink). The path goes on
// from b alone (linear predictor, its one-sided tangent), as from the start. So it does
// after an increment much shorter than the next (the end of a location): a cubic through
// two close points, extrapolated far, magnifies their tangents' errors (the Newton
// tolerance's) by the ratio of the lengths squared.
void AdaptiveFollower::step_on(PathPoint& b, bool locating) {
  if (event_end_ <= b.t ||
      (locating && b.negative == event_point_.negative && b.pieces == event_point_.pieces)) {
    event_end_ = kInfinity;
  }
  const bool crossed = b.negative != a_.negative || b.pieces != a_.pieces;
  const bool too_close = 8.0 * (b.t - a_.t) < h_;
  previous_ = std::move(a_);
  if (crossed || too_close) previous_.t = -1.0;
  a_ = std::move(b);
}

PathResult AdaptiveFollower::run(const VectorX& start) {
  if (!converge_start(start)) return std::move(result_);
  while (next_ <= steps_) {
    check_interrupt();
    const bool locating = event_end_ < kInfinity;
    const bool located = locating && event_end_ - a_.t <= event_width_;
    const double t1 = increment_end(locating, located);
    VectorX predicted;
    PathPoint b = converge_end(t1, located, predicted);
    const double length = t1 - a_.t;
    double error_factor = 4.0;  // how far the increment may grow by the force error
    Verdict verdict = located || (accepted(b.outcome) && complete(b))
                          ? judge(b, locating, length, error_factor)
                          : Verdict::kFailed;
    if (verdict == Verdict::kAccepted) verdict = take_samples(b);
    if (verdict == Verdict::kAccepted || verdict == Verdict::kStopped) keep_knot(b);
    if (verdict == Verdict::kStopped) break;
    if (verdict == Verdict::kFailed && !halve(b, length)) return std::move(result_);
    if (verdict != Verdict::kAccepted) continue;
    first_failure_.clear();
    const bool cut_short = locating || t1 < std::min(1.0, a_.t + h_) - 1e-6 * spacing_;
    set_next_length(b, predicted, length, error_factor, cut_short);
    step_on(b, locating);
  }
  result_.completed = true;
  return std::move(result_);
}

}  // namespace

PathResult follow_adaptive(PathControl& control, assembly::Assembler& assembler,
                           assembly::Assembler& full, TangentSolver& solver,
                           const VectorX& start, int steps, const AdaptiveOptions& options) {
  check_steps("steps", steps);
  check_bisections(options.max_bisections);
  AdaptiveFollower follower(control, assembler, full, solver, start.size(), steps, options);
  return follower.run(start);
}

}  // namespace kresling::solvers
