#include "kresling/analyses/switching.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
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
constexpr CreaseGroup kGroups[] = {CreaseGroup::Valley, CreaseGroup::Mountain,
                                   CreaseGroup::PolygonEdge, CreaseGroup::Folds};

void check_options(const SwitchingOptions& o) {
  solvers::check_steps("snap_through_steps", o.snap_through_steps);
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

bool in_group(model::EdgeFamily f, CreaseGroup g) {
  switch (g) {
    case CreaseGroup::Valley: return f == model::EdgeFamily::Valley;
    case CreaseGroup::Mountain: return f == model::EdgeFamily::Mountain;
    case CreaseGroup::PolygonEdge: return f == model::EdgeFamily::PolygonEdge;
    case CreaseGroup::Folds: return f != model::EdgeFamily::PolygonSpoke;
  }
  return false;
}

// The driven creases of one group: hinge indices, stress-free rest angles and directions.
struct Drive {
  std::vector<Index> hinges;
  VectorX rest, direction;
};

// Every hinge's angle at displacement u (its dihedral angle, in [0, 2 pi)) and moment.
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

// The stiff creases of `group`, each driven towards its angle in `contracted` (the
// contracted stable state): the sign of (angle there - rest angle), the short way round.
// Per crease, not per family: a family's hinges need not share an orientation (a polygon
// edge's angle may be measured from either side).
Drive make_drive(const model::KreslingSpecimen& s, CreaseGroup group, const VectorX& contracted) {
  const auto& hinges = s.model.hinges();
  Drive d;
  std::vector<double> rest, direction;
  for (std::size_t h = 0; h < hinges.size(); ++h) {
    if (!in_group(s.hinge_family[h], group) || hinges[h].stiffness == 0.0) continue;
    const double angle = response(s.model, contracted, static_cast<Index>(h), 0.0).angle;
    d.hinges.push_back(static_cast<Index>(h));
    rest.push_back(hinges[h].rest_angle);
    direction.push_back(std::remainder(angle - hinges[h].rest_angle, kTwoPi) >= 0.0 ? 1.0 : -1.0);
  }
  d.rest = Eigen::Map<VectorX>(rest.data(), static_cast<Index>(rest.size()));
  d.direction = Eigen::Map<VectorX>(direction.data(), static_cast<Index>(direction.size()));
  return d;
}

// Cell height: Le plus the top polygon's mean perimeter z displacement [mm].
double height(const model::KreslingSpecimen& s, const VectorX& u) {
  double z = 0.0;
  for (int j = 0; j < s.n; ++j) z += u[3 * s.node(1, j) + 2];
  return s.level_height[1] + z / s.n;
}

// Rest angles stay in (0, 2 pi): the largest change tried, a scan step short of where the
// first would leave (room for the overshoot past a snap).
double change_range(const Drive& d, double sign, const SwitchingOptions& o) {
  double range = o.max_change;
  for (Index i = 0; i < d.rest.size(); ++i) {
    const double room = sign * d.direction[i] > 0 ? kTwoPi - d.rest[i] : d.rest[i];
    range = std::min(range, room - o.scan_step);
  }
  return range;
}

class Switcher {
 public:
  Switcher(const model::KreslingSpecimen& s, const SwitchingOptions& o, double jump)
      : s_(s), o_(o), jump_(jump) {}

  SwitchResult run(CreaseGroup group, const Drive& drive, double sign, const VectorX& start);

 private:
  // One increment to change `delta` from u (the previous equilibrium), kept if it stays on
  // the branch: converged, stable and no jump in height.
  bool probe(const Drive& d, double sign, double delta, VectorX& u, solvers::PathStep& step);
  void record(SwitchResult& r, const Drive& d, double sign, double delta, const VectorX& u,
              const solvers::PathStep& step);
  void land(SwitchResult& r, const Drive& d, double sign, const VectorX& u);
  // Bisect the bracket [lo, hi] (lo on the branch at u, hi off it) to the resolution.
  void narrow(SwitchResult& r, const Drive& d, double sign, double& lo, double& hi, VectorX& u,
              solvers::PathStep& step);

  const model::KreslingSpecimen& s_;
  const SwitchingOptions& o_;
  double jump_;
  double last_force_ = 0.0;  // the rest angles' generalised force at the last record
};

VectorX targets(const Drive& d, double sign, double delta) {
  return d.rest + (sign * delta) * d.direction;
}

bool Switcher::probe(const Drive& d, double sign, double delta, VectorX& u,
                     solvers::PathStep& step) {
  const VectorX t = targets(d, sign, delta);
  if (!(t.minCoeff() > 0.0 && t.maxCoeff() < kTwoPi)) return false;
  solvers::FoldOptions fo;
  fo.newton = o_.newton;
  fo.max_bisections = 0;  // the bracket is this analysis's to narrow
  const solvers::PathResult p = solvers::solve_fold(
      s_.model, {solvers::FoldStage{d.hinges, t}}, 1, VectorX::Zero(s_.model.num_dofs()), fo, u);
  if (!p.completed || p.steps.size() != 1) return false;
  const solvers::PathStep& next = p.steps.back();
  if (next.negative_eigenvalues != 0) return false;
  if ((next.displacement - u).lpNorm<Eigen::Infinity>() > jump_) return false;
  u = next.displacement;
  step = next;
  return true;
}

void Switcher::record(SwitchResult& r, const Drive& d, double sign, double delta,
                      const VectorX& u, const solvers::PathStep& step) {
  const VectorX t = targets(d, sign, delta);
  double m = 0.0, force = 0.0, largest = 0.0;
  constexpr double h = 1e-6;  // [rad]: the central difference's error is O(h^2)
  for (Index i = 0; i < t.size(); ++i) {
    const Index hinge = d.hinges[static_cast<std::size_t>(i)];
    const double M = response(s_.model, u, hinge, t[i]).moment;
    m -= sign * d.direction[i] * M;
    largest = std::max(largest, std::abs(M));
    // The generalised force of the rest angle, dE/dtheta0: -M in the law's linear range;
    // beyond its limits (theta1, theta2) the law stiffens and the two differ.
    const double dE = (response(s_.model, u, hinge, t[i] + h).energy -
                       response(s_.model, u, hinge, t[i] - h).energy) / (2 * h);
    force += sign * d.direction[i] * dE;
  }
  if (!r.change.empty()) {
    r.work += 0.5 * (force + last_force_) * (delta - r.change.back());
  }
  last_force_ = force;
  r.change.push_back(delta);
  r.moments.push_back(m);
  r.energy.push_back(step.energy());
  r.height.push_back(height(s_, u));
  r.snap_change = delta, r.moment = m, r.max_crease_moment = largest;
  r.snap_energy = step.energy(), r.snap_height = r.height.back();
}

void Switcher::land(SwitchResult& r, const Drive& d, double sign, const VectorX& u_snap) {
  assembly::Workspace workspace(s_.model, assembly::unmasked_dofs(s_.model.fixed()), 0.0,
                                assembly::Storage::Lower);
  // Held just past the snap: where the cell snaps to.
  const model::Model held = solvers::folded_rest_model(
      s_.model, {solvers::FoldStage{d.hinges, targets(d, sign, r.snap_change + o_.overshoot)}});
  VectorX u = u_snap;
  assembly::Assembler snapping(held, workspace);
  solvers::EnergyMinimumOptions descent;
  descent.max_iterations = 2000;  // a snap travels far in steps of at most max_step
  const solvers::EnergyMinimum snapped = solvers::minimize_energy(snapping, u, descent);
  // Released: the stress-free rest angles back.
  assembly::Assembler released(s_.model, workspace);
  const solvers::EnergyMinimum rest = snapped.converged ? solvers::minimize_energy(released, u, descent)
                                                        : snapped;
  if (!rest.converged) {
    r.message = "the cell found no rest after the snap: " + rest.failure;
    return;
  }
  r.landing_height = height(s_, u);
  r.landing_energy = rest.energy;
  r.landing_tilt = top_polygon_tilt(s_.model, u, s_.n);
  r.landing_negative_eigenvalues = rest.negative_eigenvalues;
  r.switched = std::abs(r.landing_height - r.start_height) > jump_;
  r.message = r.switched ? "snapped and landed at height " +
                               format_number(std::round(r.landing_height * 1e6) / 1e6) + " mm"
                         : "snapped, but released it returned to its start state";
}

void Switcher::narrow(SwitchResult& r, const Drive& d, double sign, double& lo, double& hi,
                      VectorX& u, solvers::PathStep& step) {
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

SwitchResult Switcher::run(CreaseGroup group, const Drive& d, double sign, const VectorX& start) {
  SwitchResult r;
  r.group = group;
  r.forward = sign > 0;
  r.creases = static_cast<int>(d.hinges.size());
  r.start_height = height(s_, start);
  if (d.hinges.empty()) {
    r.message = "no crease of this group has stiffness (cut creases exert no moment)";
    return r;
  }
  const double range = change_range(d, sign, o_);
  VectorX u = start;
  solvers::PathStep step;
  step.energies = VectorX::Zero(1);
  r.work = 0.0;
  probe(d, sign, 0.0, u, step);  // the start's own equilibrium (and energy) at Delta = 0
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
  if (std::isnan(hi)) {
    r.message = "the start state persists up to a change of " +
                format_number(std::round(range / kDegree * 1e3) / 1e3) + " degrees" +
                (range < o_.max_change ? " (where a rest angle would leave (0, 360) degrees)"
                                       : "") + ": no snap";
    return r;
  }
  r.resolution = hi - lo;
  land(r, d, sign, u);
  return r;
}

}  // namespace

const char* crease_group_name(CreaseGroup group) {
  switch (group) {
    case CreaseGroup::Valley: return "valley";
    case CreaseGroup::Mountain: return "mountain";
    case CreaseGroup::PolygonEdge: return "polygon";
    case CreaseGroup::Folds: return "fold";
  }
  return "";
}

SwitchingResult switching(const geometry::Design& design, const SwitchingOptions& options) {
  check_options(options);
  const int n = design.parameters().n;
  SnapThroughOptions so;
  so.steps = options.snap_through_steps;
  so.specimen = options.specimen;
  SwitchingResult out;
  SnapThroughTest test(n, so);
  out.snap = test.run(design);
  if (!out.snap.bistable) return out;
  std::vector<std::uint8_t> fixed(static_cast<std::size_t>(6 * (n + 1)), 0);
  std::fill(fixed.begin(), fixed.begin() + 3 * (n + 1), 1);
  const model::KreslingSpecimen s =
      model::KreslingSpecimenBuilder(n, {1}, options.specimen).build(design, {1}, fixed);
  // A node moving by a twentieth of the travel between the stable states in one increment
  // has jumped to another branch (along a branch, an increment of scan_step moves the nodes
  // by far less, and bisection's increments by less still).
  const double jump = 0.05 * std::abs(out.snap.extended_height - out.snap.stable_height);
  Switcher switcher(s, options, jump);
  const VectorX extended = VectorX::Zero(s.model.num_dofs());
  for (CreaseGroup g : kGroups) {
    const Drive d = make_drive(s, g, out.snap.stable_state);
    out.forward.push_back(switcher.run(g, d, +1.0, extended));
    out.backward.push_back(switcher.run(g, d, -1.0, out.snap.stable_state));
  }
  return out;
}

}  // namespace kresling::analyses
