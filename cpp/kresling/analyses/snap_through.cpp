#include "kresling/analyses/snap_through.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "kresling/analyses/cell_checks.hpp"
#include "kresling/analyses/curve_features.hpp"
#include "kresling/core/check.hpp"
#include "kresling/solvers/energy_minimum.hpp"
#include "kresling/solvers/limits.hpp"

namespace kresling::analyses {

namespace {

const SnapThroughOptions& checked(const SnapThroughOptions& o) {
  solvers::check_steps("steps", o.steps);
  return o;
}

// The bottom polygon (level 0: nodes 0..n) held in x, y, z.
std::vector<std::uint8_t> bottom_fixed(int n) {
  std::vector<std::uint8_t> fixed(static_cast<std::size_t>(6 * (n + 1)), 0);
  std::fill(fixed.begin(), fixed.begin() + 3 * (n + 1), 1);
  return fixed;
}

constexpr double kPi = 3.14159265358979323846;
// A rest state with less energy than this fraction of the barrier is the extended state.
constexpr double kExtendedEnergy = 1e-6;

std::string mm(double value) { return format_number(std::round(value * 1e3) / 1e3) + " mm"; }

}  // namespace

double top_polygon_tilt(const model::Model& model, const VectorX& u, int n) {
  Vector3 normal = Vector3::Zero();
  auto position = [&](int j) -> Vector3 {
    const Index node = (n + 1) + j;
    return model.nodes().row(node).transpose() + u.segment<3>(3 * node);
  };
  for (int j = 0; j < n; ++j) normal += position(j).cross(position((j + 1) % n));  // Newell
  return std::acos(std::min(1.0, std::abs(normal.z()) / normal.norm()));
}

void check_snap_design(const geometry::Design& design) {
  // The drive runs from the extended state to the contracted one: neither may be flat (at
  // Lc = 0 it would end with the cell folded flat, where the hinges' law is infinite).
  check_not_flat(design, 0, "the snap-through test");
  check_not_flat(design, 1, "the snap-through test");
}

SnapThroughTest::SnapThroughTest(int n, SnapThroughOptions options)
    : options_(checked(options)),
      builder_(n, {1}, options_.specimen),
      solver_(options_.solver),
      fixed_(bottom_fixed(n)) {}

DriveSetup SnapThroughTest::setup(const geometry::Design& design) {
  const int n = builder_.n();
  if (design.parameters().n != n) {
    throw_invalid("design.n", design.parameters().n, "the test's n = " + std::to_string(n));
  }
  check_snap_design(design);
  const double travel = design.height(geometry::State::Extended) -
                        design.height(geometry::State::Contracted);
  DriveSetup s{builder_.build(design, {1}, fixed_), VectorX()};
  s.prescribed = VectorX::Zero(s.specimen.model.num_dofs());
  for (int j = 0; j <= n; ++j) s.prescribed[3 * s.specimen.node(1, j) + 2] = -travel;
  return s;
}

SnapThroughResult SnapThroughTest::run(const geometry::Design& design) {
  const int n = builder_.n();
  const DriveSetup drive = setup(design);
  const model::KreslingSpecimen& specimen = drive.specimen;
  SnapThroughResult r;
  r.extended_height = design.height(geometry::State::Extended);
  r.contracted_height = design.height(geometry::State::Contracted);
  const solvers::PathResult path =
      solver_.solve(specimen.model, drive.prescribed, options_.steps);
  r.completed = path.completed;
  r.message = path.message;

  const Index top_z = 3 * specimen.node(1, n) + 2;
  r.displacement = {0.0}, r.force = {0.0}, r.energy = {0.0}, r.iterations = {0};
  for (const auto& step : path.steps) {
    r.displacement.push_back(-step.displacement[top_z]);
    r.force.push_back(step.constraint_force.sum());
    r.energy.push_back(step.energy());
    r.iterations.push_back(step.iterations);
  }
  const auto& d = r.displacement;
  const auto& F = r.force;
  const LocalMaximum peak = first_local_maximum(d, F, 1);
  if (!peak.found) {
    r.bistability = "no local maximum of the force: no snap-through";
    return r;
  }
  r.snap_force = peak.y;
  r.snap_displacement = peak.x;
  r.minimum_force = *std::min_element(F.begin() + peak.index, F.end());
  const Crossing unstable = first_crossing(d, F, peak.index, /*downward=*/true);
  if (!unstable.found) {
    r.bistability = "the force stays positive after the peak (minimum " +
                    format_number(std::round(r.minimum_force * 1e4) / 1e4) +
                    " N): no unstable equilibrium, the released cell springs back (monostable)";
    return r;
  }
  const std::size_t i = unstable.index;
  r.unstable_displacement = unstable.x;
  r.energy_barrier =
      hermite(d[i - 1], d[i], r.energy[i - 1], r.energy[i], F[i - 1], F[i], unstable.x);
  const Crossing stable = first_crossing(d, F, i, /*downward=*/false);
  if (!stable.found) {
    r.bistability = path.completed
                        ? "the force is still negative at the contracted height: no second "
                          "stable state within the drive's travel"
                        : "the path stopped before the force rose back through zero";
    return r;
  }
  // Release from the interpolated state at the second zero (path.steps is offset by one).
  const std::size_t j = stable.index;
  const VectorX& before = path.steps[j - 2].displacement;
  const VectorX start = before + stable.fraction * (path.steps[j - 1].displacement - before);
  release(specimen.model, start, top_z, r);
  return r;
}

void SnapThroughTest::release(const model::Model& model, const VectorX& start, Index top_z,
                              SnapThroughResult& r) {
  // Every DOF but the bottom polygon's free; no shift, so a zero-stiffness mode is not
  // hidden from the inertia.
  if (!(release_workspace_ && release_workspace_->fits(model))) {
    release_workspace_ = std::make_unique<assembly::Workspace>(
        model, assembly::unmasked_dofs(fixed_), 0.0, assembly::Storage::Lower);
  }
  assembly::Assembler assembler(model, *release_workspace_);
  VectorX u = start;
  const solvers::EnergyMinimum rest = solvers::minimize_energy(assembler, u);
  if (!rest.converged) {
    r.bistability = "released at d = " + mm(-start[top_z]) +
                    ", the cell found no stable equilibrium: " + rest.failure;
    return;
  }
  r.stable_negative_eigenvalues = rest.negative_eigenvalues;
  // The perimeter's mean travel: released, the top polygon's centre node may dome out of
  // its plane (it hangs on the spokes alone), so it no longer tells the cell's height.
  double travel = 0.0;
  for (int j = 0; j < builder_.n(); ++j) travel -= u[3 * ((builder_.n() + 1) + j) + 2];
  r.stable_displacement = travel / builder_.n();
  r.stable_height = r.extended_height - r.stable_displacement;
  r.stable_energy = rest.energy;
  r.stable_state = u;
  r.stable_tilt = top_polygon_tilt(model, u, builder_.n());
  // The extended state is the only stress-free one: coming to rest anywhere else (level,
  // tilted or warped, even short of the level path's barrier) is a second stable state.
  r.bistable = r.stable_energy > kExtendedEnergy * r.energy_barrier;
  const double tilt_degrees = std::round(r.stable_tilt * 1800 / kPi) / 10;
  const std::string pose =
      tilt_degrees > 0 ? "tilted " + format_number(tilt_degrees) + " degrees" : "level";
  r.bistability = r.bistable ? "second stable state at height " + mm(r.stable_height) + ", " + pose
                             : "released, the cell returned to its extended state";
}

SnapThroughResult snap_through(const geometry::Design& design, const SnapThroughOptions& options) {
  return SnapThroughTest(design.parameters().n, options).run(design);
}

}  // namespace kresling::analyses
