#include "kresling/analyses/crease_scan.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "kresling/assembly/assembler.hpp"
#include "kresling/core/check.hpp"
#include "kresling/elements/hinge.hpp"
#include "kresling/solvers/energy_minimum.hpp"
#include "kresling/solvers/fold.hpp"
#include "kresling/solvers/limits.hpp"

namespace kresling::analyses {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;
constexpr double kDegree = 3.14159265358979323846 / 180.0;

// A hinge's angle and moment at displacement u with the rest angle `rest_angle`.
elements::HingeResponse response(const model::Model& m, const VectorX& u, Index h,
                                 double rest_angle) {
  const model::Hinge& hinge = m.hinges()[static_cast<std::size_t>(h)];
  auto x = [&](int k) -> Vector3 {
    const Index node = hinge.nodes[static_cast<std::size_t>(k)];
    return m.nodes().row(node).transpose() + u.segment<3>(3 * node);
  };
  return elements::hinge_response(x(0), x(1), x(2), x(3), hinge.stiffness, rest_angle,
                                  hinge.length, hinge.law, false);
}

VectorX targets(const CreaseDrive& d, double sign, double delta) {
  return d.rest + (sign * delta) * d.direction;
}

}  // namespace

void check_scan_options(const SwitchingOptions& o) {
  solvers::check_newton(o.newton);
  auto positive = [](const char* name, double value, double most) {
    require_finite(name, value);
    if (!(value > 0.0 && value <= most)) {
      throw_invalid(name, value, "in (0, " + format_number(most) + "] rad");
    }
  };
  positive("max_change", o.max_change, 3.0);
  positive("scan_step", o.scan_step, o.max_change);
  positive("resolution", o.resolution, o.scan_step);
  positive("overshoot", o.overshoot, o.scan_step);
}

double hinge_angle(const model::Model& model, const VectorX& u, Index hinge) {
  return response(model, u, hinge, 0.0).angle;
}

CreaseDrive make_crease_drive(const model::Model& model, const std::vector<Index>& candidates,
                              const VectorX& from_angles, const VectorX& to_angles) {
  const auto& hinges = model.hinges();
  std::vector<Index> chosen;
  std::vector<double> rest, direction;
  for (Index h : candidates) {
    const model::Hinge& hinge = hinges[static_cast<std::size_t>(h)];
    if (hinge.stiffness == 0.0) continue;
    chosen.push_back(h);
    rest.push_back(hinge.rest_angle);
    direction.push_back(std::remainder(to_angles[h] - from_angles[h], kTwoPi) >= 0.0 ? 1.0 : -1.0);
  }
  CreaseDrive d;
  d.hinges = chosen;
  d.rest = Eigen::Map<VectorX>(rest.data(), static_cast<Index>(rest.size()));
  d.direction = Eigen::Map<VectorX>(direction.data(), static_cast<Index>(direction.size()));
  return d;
}

CreaseScan::CreaseScan(const model::Model& model, const SwitchingOptions& options, double jump,
                       Height height, const solvers::EnergyMinimumOptions& descent)
    : model_(model), o_(options), jump_(jump), height_(std::move(height)), descent_(descent) {}

// Rest angles stay in (0, 2 pi): the largest change tried, a scan step short of where the
// first would leave (room for the overshoot past a snap).
double CreaseScan::change_range(const CreaseDrive& d, double sign) const {
  double range = o_.max_change;
  for (Index i = 0; i < d.rest.size(); ++i) {
    const double room = sign * d.direction[i] > 0 ? kTwoPi - d.rest[i] : d.rest[i];
    range = std::min(range, room - o_.scan_step);
  }
  return range;
}

// One increment to change `delta` from u (the previous equilibrium), kept if it stays on the
// branch: converged, stable and no node jumping.
bool CreaseScan::probe(const CreaseDrive& d, double sign, double delta, VectorX& u,
                       solvers::PathStep& step) {
  const VectorX t = targets(d, sign, delta);
  if (!(t.minCoeff() > 0.0 && t.maxCoeff() < kTwoPi)) {
    failure_ = "a rest angle would leave (0, 360) degrees";
    return false;
  }
  solvers::FoldOptions fo;
  fo.newton = o_.newton;
  fo.max_bisections = 0;  // the bracket is this analysis's to narrow
  const solvers::PathResult p = solvers::solve_fold(
      model_, {solvers::FoldStage{d.hinges, t}}, 1, VectorX::Zero(model_.num_dofs()), fo, u);
  if (!p.completed || p.steps.size() != 1) {
    failure_ = "no equilibrium was found (" + p.message + ")";
    return false;
  }
  const solvers::PathStep& next = p.steps.back();
  if (next.negative_eigenvalues != 0) {
    failure_ = "the equilibrium found is not stable";
    return false;
  }
  if ((next.displacement - u).lpNorm<Eigen::Infinity>() > jump_) {
    failure_ = "the equilibrium found is on another branch (a node jumped)";
    return false;
  }
  u = next.displacement;
  step = next;
  return true;
}

void CreaseScan::record(SwitchResult& r, const CreaseDrive& d, double sign, double delta,
                        const VectorX& u, const solvers::PathStep& step) {
  const VectorX t = targets(d, sign, delta);
  double m = 0.0, force = 0.0, largest = 0.0;
  constexpr double h = 1e-6;  // [rad]: the central difference's error is O(h^2)
  for (Index i = 0; i < t.size(); ++i) {
    const Index hinge = d.hinges[static_cast<std::size_t>(i)];
    const double M = response(model_, u, hinge, t[i]).moment;
    m -= sign * d.direction[i] * M;
    largest = std::max(largest, std::abs(M));
    // The generalised force of the rest angle, dE/dtheta0: -M in the law's linear range;
    // beyond its limits (theta1, theta2) the law stiffens and the two differ.
    const double dE = (response(model_, u, hinge, t[i] + h).energy -
                       response(model_, u, hinge, t[i] - h).energy) / (2 * h);
    force += sign * d.direction[i] * dE;
  }
  if (!r.change.empty()) {
    r.work += 0.5 * (force + last_force_) * (delta - r.change.back());
  }
  last_force_ = force;
  r.change.push_back(delta);
  r.moments.push_back(m);
  r.energy.push_back(step.energy());
  r.height.push_back(height_(u));
  r.snap_change = delta, r.moment = m, r.max_crease_moment = largest;
  r.snap_energy = step.energy(), r.snap_height = r.height.back();
}

void CreaseScan::land(SwitchResult& r, const CreaseDrive& d, double sign, VectorX& u) {
  assembly::Workspace workspace(model_, assembly::unmasked_dofs(model_.fixed()), 0.0,
                                assembly::Storage::Lower);
  // Held just past the snap: where the structure snaps to.
  const model::Model held = solvers::folded_rest_model(
      model_, {solvers::FoldStage{d.hinges, targets(d, sign, r.snap_change + o_.overshoot)}});
  assembly::Assembler snapping(held, workspace);
  const solvers::EnergyMinimum snapped = solvers::minimize_energy(snapping, u, descent_);
  // Released: the stress-free rest angles back.
  assembly::Assembler released(model_, workspace);
  const solvers::EnergyMinimum rest =
      snapped.converged ? solvers::minimize_energy(released, u, descent_) : snapped;
  if (!rest.converged) {
    r.message = "the structure found no rest after the snap: " + rest.failure;
    return;
  }
  r.landing_height = height_(u);
  r.landing_energy = rest.energy;
  r.landing_negative_eigenvalues = rest.negative_eigenvalues;
  r.switched = std::abs(r.landing_height - r.start_height) > jump_;
  r.message = r.switched ? "snapped and landed at height " +
                               format_number(std::round(r.landing_height * 1e6) / 1e6) + " mm"
                         : "snapped, but released it returned to its start state (past the end of the "
                           "branch, " + failure_ + ")";
}

// Bisect the bracket [lo, hi] (lo on the branch at u, hi off it) to the resolution.
void CreaseScan::narrow(SwitchResult& r, const CreaseDrive& d, double sign, double& lo,
                        double& hi, VectorX& u, solvers::PathStep& step) {
  while (hi - lo > o_.resolution) {
    const double mid = 0.5 * (lo + hi);
    if (probe(d, sign, mid, u, step)) {
      lo = mid;
      record(r, d, sign, lo, u, step);
    } else {
      hi = mid;
    }
  }
}

SwitchResult CreaseScan::run(CreaseGroup group, const CreaseDrive& d, double sign,
                             const VectorX& start, VectorX* snap, VectorX* landing) {
  SwitchResult r;
  r.group = group;
  r.forward = sign > 0;
  r.creases = static_cast<int>(d.hinges.size());
  r.start_height = height_(start);
  if (d.hinges.empty()) {
    r.message = "no crease of this group has stiffness (cut creases exert no moment)";
    return r;
  }
  const double range = change_range(d, sign);
  VectorX u = start;
  solvers::PathStep step;
  step.energies = VectorX::Zero(1);
  r.work = 0.0;
  // The start's own equilibrium (and energy) at Delta = 0.
  if (!probe(d, sign, 0.0, u, step)) {
    r.message = "the start is not a stable equilibrium: the solve from it with the creases "
                "at rest found none nearby";
    return r;
  }
  record(r, d, sign, 0.0, u, step);
  r.start_energy = step.energy();
  double lo = 0.0, hi = NAN;
  while (std::isnan(hi) && lo < range) {
    const double next = std::min(lo + o_.scan_step, range);
    if (probe(d, sign, next, u, step)) {
      lo = next;
      record(r, d, sign, lo, u, step);
      continue;
    }
    hi = next;
    narrow(r, d, sign, lo, hi, u, step);
    // From the bracket's lower end the upper one may be reached after all (the branch was
    // steep, not ending): then follow on.
    if (probe(d, sign, hi, u, step)) {
      lo = hi, hi = NAN;
      record(r, d, sign, lo, u, step);
    }
  }
  if (snap) *snap = u;
  if (std::isnan(hi)) {
    r.message = "the start state persists up to a change of " +
                format_number(std::round(range / kDegree * 1e3) / 1e3) + " degrees" +
                (range < o_.max_change ? " (where a rest angle would leave (0, 360) degrees)"
                                       : "") + ": no snap";
    return r;
  }
  r.resolution = hi - lo;
  land(r, d, sign, u);
  if (landing) *landing = u;
  return r;
}

}  // namespace kresling::analyses
