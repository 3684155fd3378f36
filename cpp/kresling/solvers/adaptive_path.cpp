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

}  // namespace

PathResult follow_adaptive(PathControl& control, assembly::Assembler& assembler,
                           assembly::Assembler& full, TangentSolver& solver,
                           const VectorX& start, int steps, const AdaptiveOptions& options) {
  check_steps("steps", steps);
  check_bisections(options.max_bisections);
  PathResult result;
  const std::vector<Index> recorded = control.recorded_dofs();
  const double sign = control.recorded_sign();
  result.constraint_dofs = recorded;
  result.families = family_names(control.model_at(0.0));
  // Rebinds both assemblers to the model at t (for a control that changes it).
  auto bind = [&](double t) {
    if (!control.changes_model()) return;
    const model::Model& at = control.model_at(t);
    assembler.rebind(at);
    full.rebind(at);
  };
  bind(0.0);
  VectorX external = VectorX::Zero(start.size());
  const int budget = options.reject_iterations;
  // Newton stops at max_iterations even where reject_iterations would allow more.
  const int newton_limit = budget > 0 ? std::min(budget, options.newton.max_iterations) : 0;
  auto accepted = [&](const NewtonOutcome& o) {
    return o.converged && (budget <= 0 || o.iterations < budget);
  };
  const double spacing = 1.0 / steps;
  const double smallest = std::ldexp(spacing, -options.max_bisections);
  const double event_width = kEventWidth * spacing;
  auto sample_at = [&](int k) { return k == steps ? 1.0 : k * spacing; };
  // Newton at t from w; `from` (the last equilibrium) when the drive's held DOFs move from
  // there, checked against the barriers first (start_within_barriers: a prescribed jump the
  // barriers cannot shorten).
  const std::vector<Index> held = control.held_dofs();
  auto newton = [&](VectorX& w, double t, const VectorX* from = nullptr) {
    bind(t);
    control.apply(t, w, external);
    if (from != nullptr && !start_within_barriers(assembler.model(), *from, w, held)) {
      NewtonOutcome blocked;
      blocked.failure = kHeldMoveBlocked;
      return blocked;
    }
    const NewtonOutcome outcome = newton_equilibrium(assembler, solver, w, external,
                                                     options.newton, newton_limit);
    result.newton_iterations += outcome.iterations;
    return outcome;
  };
  auto why = [&](const NewtonOutcome& o) {
    return o.failure.empty() ? "Newton needed " + std::to_string(o.iterations) + " iterations"
                             : o.failure;
  };
  // A converged point's forces, energies, stability, law pieces and path derivatives.
  auto complete = [&](PathPoint& p) {
    if (!path_derivatives(assembler, full, solver, control, recorded, sign, p)) {
      p.outcome.failure =
          "the converged state's internal force, energy or path tangent is not finite (an "
          "element's law is singular there, e.g. a hinge folded flat)";
      return false;
    }
    p.negative = p.outcome.negative_eigenvalues;
    p.pieces = law_pieces(assembler.model(), p.u);
    return true;
  };
  // A converged point as a sample.
  auto as_step = [&](const PathPoint& p) {
    PathStep step;
    step.load_factor = p.t;
    step.displacement = p.u;
    step.constraint_force = p.force;
    step.energies = p.energy;
    step.iterations = p.outcome.iterations;
    step.negative_eigenvalues = p.outcome.negative_eigenvalues;
    return step;
  };
  // The monitored quantity's largest magnitude on the path so far.
  double monitored_scale = 0.0;
  auto monitored = [&](const PathPoint& p) { return control.monitored(p.force, p.energy); };

  // The start, brought to equilibrium (it usually is one: one iteration).
  PathPoint a;
  a.t = 0.0;
  a.u = start;
  a.outcome = newton(a.u, 0.0);
  ++result.attempted_increments;
  if (!accepted(a.outcome) || !complete(a)) {
    result.failed_increment = 1;
    result.message = "the starting state has no equilibrium nearby: " + why(a.outcome);
    return result;
  }
  PathPoint previous;  // the point before a (t = -1: none yet)
  previous.t = -1.0;

  double h = spacing;            // the next increment by the error estimate
  double event_end = kInfinity;  // an event (stability change, law kink) lies in (a.t, this]
  PathPoint event_point;         // the converged point there
  int predictions = 0;           // aimed location steps towards the present event
  int next = 1;                  // the next sample to record
  std::string first_failure;     // why the increment from a failed at full size
  while (next <= steps) {
    check_interrupt();
    // The increment's end: a bisection towards a known event, else the error estimate's
    // size, snapped to a sample within a millionth of the spacing (so that a sample is not
    // left a sliver away from a converged point). An increment with no error estimate (the
    // first, the first past an event) ends at the next sample at the latest.
    double t1;
    const bool locating = event_end < kInfinity;
    // Located: the event's converged point is within the width, and is the increment's end.
    const bool located = locating && event_end - a.t <= event_width;
    if (located) {
      t1 = event_end;
    } else if (locating) {
      // A law kink: aimed at just past (or before) the predicted crossing, on the side away
      // from the nearer end of the bracket, so that the next step closes it to the width
      // (two solves per kink where bisection from a few spacings takes ~12). Bisection for
      // a stability change, or when four aimed steps have not closed it.
      t1 = a.t + 0.5 * (event_end - a.t);
      const double kink = predictions < 4 ? predicted_kink(assembler.model(), a, event_point)
                                          : std::numeric_limits<double>::quiet_NaN();
      if (std::isfinite(kink)) {
        const double aim = kink - a.t <= event_end - kink ? kink + 0.4 * event_width
                                                          : kink - 0.4 * event_width;
        if (aim > a.t + 0.01 * event_width && aim < event_end - 0.01 * event_width) {
          t1 = aim;
          ++predictions;
        }
      }
    } else {
      t1 = previous.t < 0.0 ? std::min(a.t + h, sample_at(next)) : std::min(1.0, a.t + h);
      const double k = std::round(t1 * steps);
      if (std::abs(t1 - k * spacing) < 1e-6 * spacing) t1 = sample_at(static_cast<int>(k));
    }
    PathPoint b;
    VectorX predicted;
    if (located) {
      b = std::move(event_point);  // converged and completed when the event was found
      predicted = b.u;
    } else {
      ++result.attempted_increments;
      b.t = t1;
      predicted = previous.t >= 0.0 ? hermite_u(previous, a, t1)
                                    : VectorX(a.u + (t1 - a.t) * a.velocity);
      b.u = predicted;
      shorten_to_barriers(assembler.model(), a.u, b.u);  // no pair crosses on the way there
      b.outcome = newton(b.u, t1, &a.u);
    }
    // Past a bifurcation a predicted start may land on a less stable branch than the one
    // the last equilibrium leads on to (the branch the fixed-step path follows): retry from
    // there and keep the more stable.
    if (!located && accepted(b.outcome) && a.negative >= 0 &&
        b.outcome.negative_eigenvalues > a.negative) {
      VectorX plain = a.u;
      const NewtonOutcome retry = newton(plain, t1, &a.u);
      if (accepted(retry) && retry.negative_eigenvalues >= 0 &&
          retry.negative_eigenvalues < b.outcome.negative_eigenvalues) {
        b.u = plain;
        b.outcome = retry;
      }
    }
    bool ok = located || (accepted(b.outcome) && complete(b));
    const double length = t1 - a.t;
    double error_factor = 4.0;  // how far the increment may grow by the force error
    if (ok) {
      const bool event = b.negative != a.negative || b.pieces != a.pieces;
      if (event && length > event_width) {
        if (!locating) predictions = 0;
        event_end = t1;  // locate it before stepping on
        event_point = std::move(b);
        continue;
      }
      // The dense output's error, on the monitored quantity G (the drive's force under
      // displacement control: how it is shared among the driven DOFs is determined only to
      // the Newton tolerance, stiff bars redistributing it, so the estimate is not held to
      // that): its Hermite curve through the previous increment, extrapolated to b, misses
      // b's by D/24 (b-p)^2 (b-a)^2 (D: its fourth derivative); the interpolant on (a, b)
      // errs by at most D/24 ((b-a)/2)^4, that times (b-a)^2 / (16 (b-p)^2).
      const bool inside = next <= steps && sample_at(next) < b.t;
      monitored_scale =
          std::max({monitored_scale, std::abs(monitored(b)), std::abs(monitored(a))});
      const double allowed = options.tolerance * monitored_scale;
      if (previous.t >= 0.0) {
        const VectorX extrapolated = hermite<VectorX>(previous.t, previous.force,
                                                      previous.force_rate, a.t, a.force,
                                                      a.force_rate, b.t);
        const VectorX extrapolated_energy =
            hermite<VectorX>(previous.t, previous.energy, previous.energy_rate, a.t, a.energy,
                             a.energy_rate, b.t);
        const double span = b.t - previous.t;
        const double estimate =
            std::abs(control.monitored(b.force - extrapolated, b.energy - extrapolated_energy)) *
            length * length / (16.0 * span * span);
        error_factor = estimate > 0.0 ? 0.9 * std::pow(allowed / estimate, 0.25) : 4.0;
        if (inside && estimate > allowed && length > event_width) {
          // Never shorter than to the next sample: an increment with no sample inside has
          // no dense output error, so the path moves on at least as the fixed steps do.
          h = std::max(length * std::clamp(error_factor, 0.2, 0.9), sample_at(next) - a.t);
          event_end = kInfinity;
          continue;
        }
      } else if (inside) {
        ok = false;  // no estimate yet (only after a failed first increment): shorter
        b.outcome.failure = "no error estimate for the first increment";
      }
    }
    if (ok) {
      // The samples in (a.t, b.t]: b itself, or the Hermite curves (displacements, forces,
      // energies) between a and b; across a located event, Newton at the sample.
      // With a barrier (contact) a curve between two states that are apart may still pass
      // a pair through each other: each sample is then solved by Newton from it instead,
      // its start shortened from a as every move is.
      const bool same_stability = a.negative == b.negative;
      const bool interpolate = same_stability && !families_limit_steps(assembler.model());
      while (next <= steps && sample_at(next) <= b.t) {
        const double ts = sample_at(next);
        PathStep step;
        if (ts == b.t) {
          step = as_step(b);
        } else if (interpolate) {
          step.load_factor = ts;
          step.displacement = hermite_u(a, b, ts);
          control.apply(ts, step.displacement, external);  // the held DOFs exactly
          step.constraint_force =
              hermite<VectorX>(a.t, a.force, a.force_rate, b.t, b.force, b.force_rate, ts);
          step.energies = hermite<VectorX>(a.t, a.energy, a.energy_rate, b.t, b.energy,
                                           b.energy_rate, ts);
          step.iterations = 0;
          step.negative_eigenvalues = b.negative;
        } else {
          ++result.attempted_increments;
          VectorX w = hermite_u(a, b, ts);
          shorten_to_barriers(assembler.model(), a.u, w);
          const NewtonOutcome o = newton(w, ts, &a.u);
          if (!accepted(o)) {
            ok = false;
            b.outcome.failure = "a sample inside the increment: " + why(o);
            break;
          }
          step = record_step(assembler, w, ts, o, recorded, sign);
          if (!finite_step(step)) {
            ok = false;
            b.outcome.failure = "a sample inside the increment: its force is not finite";
            break;
          }
        }
        result.steps.push_back(std::move(step));
        ++next;
        if (options.stop && options.stop(result.steps.back())) {
          result.completed = true;
          return result;
        }
      }
    }
    if (!ok) {
      if (first_failure.empty()) first_failure = why(b.outcome);
      h = 0.5 * length;
      event_end = kInfinity;
      if (h < smallest) {
        result.failed_increment = result.attempted_increments;
        result.message = "increment " + std::to_string(next) + " (of " + std::to_string(steps) +
                         ", at " + format_number(a.t) + " of " + control.parameter_name() +
                         ") failed: the adaptive increment fell below 1/2^" +
                         std::to_string(options.max_bisections) +
                         " of a sample spacing; at full size: " + first_failure;
        return result;
      }
      continue;
    }
    first_failure.clear();
    // The next increment: by the force error, and so that the displacement predictor stays
    // within kPredictorError (Newton then converges in one or two iterations); its error
    // grows like the length to the power 4 (cubic Hermite; 2 for the first, linear one).
    // Increments cut short (by an event or the path's end) do not set it.
    const double u_error = (b.u - predicted).lpNorm<Eigen::Infinity>();
    const double order = previous.t >= 0.0 ? 4.0 : 2.0;
    double factor = u_error > 0.0 ? 0.9 * std::pow(kPredictorError / u_error, 1.0 / order) : 4.0;
    factor = std::clamp(std::min(factor, error_factor), 0.2, 4.0);
    if (b.outcome.iterations > 4) factor = std::min(factor, 0.5);
    const bool cut_short = locating || t1 < std::min(1.0, a.t + h) - 1e-6 * spacing;
    h = cut_short ? (factor < 1.0 ? std::min(h, length * factor) : h) : length * factor;
    if (next <= steps) h = std::max(h, sample_at(next) - b.t);  // to the next sample at least
    h = std::max(h, smallest);
    // The bracket is closed at its end, or by a short step across the event (nothing left
    // to locate between b and the event's point when their pieces and stability agree).
    if (event_end <= b.t ||
        (locating && b.negative == event_point.negative && b.pieces == event_point.pieces)) {
      event_end = kInfinity;
    }
    // Across an event (a law kink, a stability change) the path's derivatives jump: a cubic
    // through points on either side, extrapolated, misses by the jump times the length (it
    // sent Newton to 25 iterations and halvings after every kink). The path goes on from b
    // alone (linear predictor, its one-sided tangent), as from the start. So it does after
    // an increment much shorter than the next (the end of a location): a cubic through two
    // close points, extrapolated far, magnifies their tangents' errors (the Newton
    // tolerance's) by the ratio of the lengths squared.
    const bool crossed = b.negative != a.negative || b.pieces != a.pieces;
    const bool too_close = 8.0 * (b.t - a.t) < h;
    previous = std::move(a);
    if (crossed || too_close) previous.t = -1.0;
    a = std::move(b);
  }
  result.completed = true;
  return result;
}

}  // namespace kresling::solvers
