#include "kresling/analyses/switching.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

#include "kresling/analyses/crease_scan.hpp"
#include "kresling/solvers/limits.hpp"

namespace kresling::analyses {

namespace {

constexpr CreaseGroup kGroups[] = {CreaseGroup::Valley, CreaseGroup::Mountain,
                                   CreaseGroup::PolygonEdge, CreaseGroup::Folds};

// Cell height: Le plus the top polygon's mean perimeter z displacement [mm].
double height(const model::KreslingSpecimen& s, const VectorX& u) {
  double z = 0.0;
  for (int j = 0; j < s.n; ++j) z += u[3 * s.node(1, j) + 2];
  return s.level_height[1] + z / s.n;
}

// The stiff creases of `group`, each driven towards its angle in `contracted` (the
// contracted stable state).
CreaseDrive make_drive(const model::KreslingSpecimen& s, CreaseGroup group,
                       const VectorX& contracted) {
  std::vector<Index> candidates;
  const Index count = static_cast<Index>(s.model.hinges().size());
  VectorX rest(count), angles(count);
  for (Index h = 0; h < count; ++h) {
    rest[h] = s.model.hinges()[static_cast<std::size_t>(h)].rest_angle;
    angles[h] = hinge_angle(s.model, contracted, h);
    if (in_crease_group(s.hinge_family[static_cast<std::size_t>(h)], group)) candidates.push_back(h);
  }
  return make_crease_drive(s.model, candidates, rest, angles);
}

}  // namespace

bool in_crease_group(model::EdgeFamily f, CreaseGroup g) {
  switch (g) {
    case CreaseGroup::Valley: return f == model::EdgeFamily::Valley;
    case CreaseGroup::Mountain: return f == model::EdgeFamily::Mountain;
    case CreaseGroup::PolygonEdge: return f == model::EdgeFamily::PolygonEdge;
    case CreaseGroup::Folds: return f != model::EdgeFamily::PolygonSpoke;
  }
  return false;
}

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
  solvers::check_steps("snap_through_steps", options.snap_through_steps);
  check_scan_options(options);
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
  solvers::EnergyMinimumOptions descent;
  descent.max_iterations = 2000;  // a snap travels far in steps of at most max_step
  CreaseScan scan(s.model, options, jump, [&s](const VectorX& u) { return height(s, u); },
                  descent);
  const VectorX extended = VectorX::Zero(s.model.num_dofs());
  auto run = [&](CreaseGroup g, const CreaseDrive& d, double sign, const VectorX& start) {
    VectorX landing;
    SwitchResult r = scan.run(g, d, sign, start, nullptr, &landing);
    if (!std::isnan(r.landing_height)) r.landing_tilt = top_polygon_tilt(s.model, landing, s.n);
    return r;
  };
  for (CreaseGroup g : kGroups) {
    const CreaseDrive d = make_drive(s, g, out.snap.stable_state);
    out.forward.push_back(run(g, d, +1.0, extended));
    out.backward.push_back(run(g, d, -1.0, out.snap.stable_state));
  }
  return out;
}

}  // namespace kresling::analyses
