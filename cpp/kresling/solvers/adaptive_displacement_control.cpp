/// \file adaptive_displacement_control.cpp
/// Displacement control with adaptive increments and dense output
/// (DisplacementControlOptions::adaptive; docs/model.md, 'Displacement control').
///
/// The path u(t), t in [0, 1] the fraction of the prescribed motion, is followed in
/// increments whose size comes from an error estimate; the protocol's samples t_k = k/steps
/// are taken between converged points. Each converged point carries its exact path
/// derivatives (du/dt, the constraint forces' dF/dt, the energies' rates), so between two
/// of them the displacements, forces and energies are cubic Hermite curves: the predictor
/// of the next increment (extrapolated) and the samples inside (interpolated, no
/// iteration). The force curve's error is estimated from how far the previous increment's
/// curve, extrapolated, misses the new converged forces; an increment whose estimate is
/// above the tolerance is retried shorter, but never shorter than to the next sample (which
/// it then ends on, converged by Newton as in the fixed-step mode).

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <string>
#include <vector>

#include "kresling/core/check.hpp"
#include "kresling/core/interrupt.hpp"
#include "kresling/elements/dihedral.hpp"
#include "kresling/solvers/displacement_control.hpp"
#include "kresling/solvers/newton.hpp"

namespace kresling::solvers {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// An increment's displacement predictor may miss its converged point by this much [mm]
// (max-norm): Newton then converges in one or two iterations.
constexpr double kPredictorError = 1e-4;
// Stability changes and law kinks are located to this fraction of a sample spacing.
constexpr double kEventWidth = 1e-3;

// A converged equilibrium of the path with its derivatives along the path.
struct PathPoint {
  double t = 0.0;
  VectorX u;           // all DOFs
  VectorX velocity;    // du/dt, all DOFs (at the imposed ones, the prescribed motion)
  VectorX force;       // constraint forces (-f_int at the imposed DOFs)
  VectorX force_rate;  // their derivative d/dt
  VectorX energy;       // per element family, in the model's order
  VectorX energy_rate;  // d/dt
  int negative = -1;  // negative eigenvalues of the tangent there
  // Per hinge, which piece of its law applies: -1 below the enhanced linear law's lower
  // limit, 1 above its upper one, 0 in between (and for the other laws, which have no kink).
  std::vector<signed char> pieces;
  NewtonOutcome outcome;
};

std::vector<signed char> law_pieces(const model::Model& model, const VectorX& u) {
  const auto& hinges = model.hinges();
  std::vector<signed char> pieces(hinges.size(), 0);
  const NodeMatrix& X = model.nodes();
  auto at = [&](Index node) -> Vector3 {
    return X.row(node).transpose() + u.segment<3>(3 * node);
  };
  for (std::size_t h = 0; h < hinges.size(); ++h) {
    const model::Hinge& hinge = hinges[h];
    if (hinge.law.kind != elements::SpringLawKind::EnhancedLinear || hinge.stiffness == 0.0) {
      continue;
    }
    const auto& n = hinge.nodes;
    const double theta = elements::dihedral_angle(at(n[0]), at(n[1]), at(n[2]), at(n[3]));
    pieces[h] = theta < hinge.law.theta1 ? -1 : theta > hinge.law.theta2 ? 1 : 0;
  }
  return pieces;
}

// Where along the path, between a converged point `a` and a converged `e` past an event,
// the first hinge whose law piece differs between them reaches the limit in between: for
// each such hinge a Newton step on theta(t) = limit from each end (exact dtheta/dt there:
// its gradient times the path tangent; the law's M and dM/dtheta are continuous at its
// limits, so theta(t) is smooth to second order across), the one from the nearer end.
// NaN when the event is a stability change or no estimate lies in (a.t, e.t).
double predicted_kink(const model::Model& model, const PathPoint& a, const PathPoint& e) {
  const double none = std::numeric_limits<double>::quiet_NaN();
  if (a.negative != e.negative || a.pieces.size() != e.pieces.size()) return none;
  const NodeMatrix& X = model.nodes();
  // theta - limit and its rate at p for hinge h.
  auto offset = [&](const PathPoint& p, const model::Hinge& hinge, double limit) {
    auto at = [&](Index node) -> Vector3 {
      return X.row(node).transpose() + p.u.segment<3>(3 * node);
    };
    const auto& n = hinge.nodes;
    const elements::DihedralDerivatives d = elements::dihedral_angle_derivatives(
        at(n[0]), at(n[1]), at(n[2]), at(n[3]), /*with_hessian=*/false);
    double rate = 0.0;
    for (int j = 0; j < 4; ++j) {
      rate += d.gradient.segment<3>(3 * j).dot(p.velocity.segment<3>(3 * n[j]));
    }
    return std::make_pair(d.angle - limit, rate);
  };
  double first = none;
  for (std::size_t h = 0; h < a.pieces.size(); ++h) {
    const int from = a.pieces[h], to = e.pieces[h];
    if (from == to) continue;
    const model::Hinge& hinge = model.hinges()[h];
    // The limit next to a's piece on e's side.
    const double limit = to > from ? (from < 0 ? hinge.law.theta1 : hinge.law.theta2)
                                   : (from > 0 ? hinge.law.theta2 : hinge.law.theta1);
    const auto [ga, ra] = offset(a, hinge, limit);
    const auto [ge, re] = offset(e, hinge, limit);
    const double from_a = a.t - ga / ra, from_e = e.t - ge / re;
    const bool a_ok = from_a > a.t && from_a < e.t, e_ok = from_e > a.t && from_e < e.t;
    double t = none;
    if (a_ok && e_ok) {
      t = (from_a - a.t <= e.t - from_e) ? from_a : from_e;
    } else if (a_ok) {
      t = from_a;
    } else if (e_ok) {
      t = from_e;
    }
    if (std::isfinite(t) && !(t >= first)) first = t;  // the smallest (first is NaN at first)
  }
  return first;
}

// The cubic Hermite curve through (ta, ya, da) and (tb, yb, db) (values and derivatives)
// at t: interpolation for t in [ta, tb], extrapolation beyond.
template <typename V>
V hermite(double ta, const V& ya, const V& da, double tb, const V& yb, const V& db, double t) {
  const double h = tb - ta;
  const double s = (t - ta) / h, s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * ya + ((s3 - 2 * s2 + s) * h) * da + (3 * s2 - 2 * s3) * yb +
         ((s3 - s2) * h) * db;
}

VectorX hermite_u(const PathPoint& a, const PathPoint& b, double t) {
  return hermite<VectorX>(a.t, a.u, a.velocity, b.t, b.u, b.velocity, t);
}

// The state and path derivatives at the converged p.u, exactly (no finite differences of
// forces: where bars are 1e5 times stiffer than hinges, those lose ~6 digits). One assembly
// of every DOF (`full`, unshifted, lower triangle) gives the constraint forces, the
// energies and K. K_ff v_f = -K_fi p is solved with the free tangent factorised last (at
// p.u or within the Newton tolerance of it: a relative error of up to ~1e-6) and refined
// with K's products until the constraint forces' rate dF/dt = -(K v)_imposed changes by
// less than 1e-10 of itself (its rounding: ~3e-12). Each family's energy rate is its own
// internal force dotted with v (assembly::energy_rates). Returns false when a value is not
// finite.
bool path_derivatives(assembly::Assembler& assembler, assembly::Assembler& full,
                      const TangentSolver& solver, const VectorX& prescribed,
                      const std::vector<Index>& imposed, PathPoint& p) {
  VectorX force;
  const assembly::Energies energies = full.assemble(p.u, force, /*with_matrix=*/true);
  p.force.resize(static_cast<Index>(imposed.size()));
  for (std::size_t k = 0; k < imposed.size(); ++k) {
    p.force[static_cast<Index>(k)] = -force[imposed[k]];
  }
  p.energy = energies.vector();
  if (!p.force.allFinite() || !p.energy.allFinite()) return false;
  const auto K = full.matrix().selfadjointView<Eigen::Lower>();
  VectorX direction = VectorX::Zero(p.u.size());
  for (Index i : imposed) direction[i] = prescribed[i];
  VectorX force_rate(static_cast<Index>(imposed.size()));
  for (int round = 0; round < 6; ++round) {
    const VectorX product = K * direction;
    for (std::size_t k = 0; k < imposed.size(); ++k) {
      force_rate[static_cast<Index>(k)] = -product[imposed[k]];
    }
    if (round > 1 && (force_rate - p.force_rate).lpNorm<Eigen::Infinity>() <=
                         1e-10 * force_rate.lpNorm<Eigen::Infinity>()) {
      break;
    }
    p.force_rate = force_rate;
    const VectorX correction = solver.solve(VectorX(-gather_rows(assembler, product)));
    if (!correction.allFinite()) return false;
    scatter_add_rows(assembler, correction, direction);
  }
  p.force_rate = force_rate;
  p.velocity = direction;
  p.energy_rate = assembly::energy_rates(full.model(), p.u, direction);
  return p.force_rate.allFinite() && p.energy_rate.allFinite();
}

}  // namespace

PathResult DisplacementControl::solve_adaptive(const VectorX& prescribed, int steps,
                                               const std::vector<Index>& imposed,
                                               const VectorX& start) {
  PathResult result;
  result.constraint_dofs = imposed;
  const model::Model& model = assembler_->model();
  result.families = family_names(model);
  const double spacing = 1.0 / steps;
  const double smallest = std::ldexp(spacing, -options_.max_bisections);
  const double event_width = kEventWidth * spacing;
  auto sample_at = [&](int k) { return k == steps ? 1.0 : k * spacing; };
  auto newton = [&](VectorX& w, double t) {
    const NewtonOutcome outcome = equilibrium_at(w, t, start, prescribed, imposed);
    result.newton_iterations += outcome.iterations;
    return outcome;
  };
  auto why = [&](const NewtonOutcome& o) {
    return o.failure.empty() ? "Newton needed " + std::to_string(o.iterations) + " iterations"
                             : o.failure;
  };
  // A converged point's forces, energies, stability, law pieces and path derivatives.
  auto complete = [&](PathPoint& p) {
    if (!path_derivatives(*assembler_, *full_assembler_, *solver_, prescribed, imposed, p)) {
      p.outcome.failure =
          "the converged state's internal force, energy or path tangent is not finite (an "
          "element's law is singular there, e.g. a hinge folded flat)";
      return false;
    }
    p.negative = p.outcome.negative_eigenvalues;
    p.pieces = law_pieces(model, p.u);
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
  double force_scale = 0.0;  // largest |drive force| of the path so far [N]
  // The drive's force G = sum_k F_k U_k / max|U| of constraint forces F.
  double largest_motion = 0.0;
  for (Index i : imposed) largest_motion = std::max(largest_motion, std::abs(prescribed[i]));
  auto drive_force = [&](const VectorX& F) {
    double g = 0.0;
    for (std::size_t k = 0; k < imposed.size(); ++k) {
      g += F[static_cast<Index>(k)] * prescribed[imposed[k]];
    }
    return g / largest_motion;
  };

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
      const double kink = predictions < 4 ? predicted_kink(model, a, event_point)
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
      b.outcome = newton(b.u, t1);
    }
    // Past a bifurcation a predicted start may land on a less stable branch than the one
    // the last equilibrium leads on to (the branch the fixed-step path follows): retry from
    // there and keep the more stable.
    if (!located && accepted(b.outcome) && a.negative >= 0 &&
        b.outcome.negative_eigenvalues > a.negative) {
      VectorX plain = a.u;
      const NewtonOutcome retry = newton(plain, t1);
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
      // The dense output's error, on the drive's force G = sum_k F_k U_k / max|U| (the
      // force conjugate to the prescribed motion; the summed reaction of a uniform drive):
      // its Hermite curve through the previous increment, extrapolated to b, misses b's by
      // D/24 (b-p)^2 (b-a)^2 (D: its fourth derivative); the interpolant on (a, b) errs by at
      // most D/24 ((b-a)/2)^4, that times (b-a)^2 / (16 (b-p)^2). How the drive's force is
      // shared among the driven DOFs is determined only to the Newton tolerance (stiff bars
      // redistribute it), in the fixed steps as here, so the estimate is not held to it.
      const bool inside = next <= steps && sample_at(next) < b.t;
      force_scale = std::max({force_scale, std::abs(drive_force(b.force)),
                              std::abs(drive_force(a.force))});
      const double allowed = options_.adaptive_tolerance * force_scale;
      if (previous.t >= 0.0) {
        const VectorX extrapolated = hermite<VectorX>(previous.t, previous.force,
                                                      previous.force_rate, a.t, a.force,
                                                      a.force_rate, b.t);
        const double span = b.t - previous.t;
        const double estimate = std::abs(drive_force(b.force - extrapolated)) * length *
                                length / (16.0 * span * span);
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
      const bool same_stability = a.negative == b.negative;
      while (next <= steps && sample_at(next) <= b.t) {
        const double ts = sample_at(next);
        PathStep step;
        if (ts == b.t) {
          step = as_step(b);
        } else if (same_stability) {
          step.load_factor = ts;
          step.displacement = hermite_u(a, b, ts);
          for (Index i : imposed) step.displacement[i] = start[i] + ts * prescribed[i];
          step.constraint_force =
              hermite<VectorX>(a.t, a.force, a.force_rate, b.t, b.force, b.force_rate, ts);
          step.energies = hermite<VectorX>(a.t, a.energy, a.energy_rate, b.t, b.energy,
                                           b.energy_rate, ts);
          step.iterations = 0;
          step.negative_eigenvalues = b.negative;
        } else {
          ++result.attempted_increments;
          VectorX w = hermite_u(a, b, ts);
          const NewtonOutcome o = newton(w, ts);
          if (!accepted(o)) {
            ok = false;
            b.outcome.failure = "a sample inside the increment: " + why(o);
            break;
          }
          step = record_step(*assembler_, w, ts, o, imposed, -1.0);
          if (!finite_step(step)) {
            ok = false;
            b.outcome.failure = "a sample inside the increment: its force is not finite";
            break;
          }
        }
        result.steps.push_back(std::move(step));
        ++next;
        if (options_.stop && options_.stop(result.steps.back())) {
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
                         ", at " + format_number(a.t) + " of the prescribed motion) failed: " +
                         "the adaptive increment fell below 1/2^" +
                         std::to_string(options_.max_bisections) +
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
