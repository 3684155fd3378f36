#include "kresling/analyses/bending_test.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <stdexcept>

#include "kresling/analyses/cell_checks.hpp"
#include "kresling/core/check.hpp"
#include "kresling/solvers/limits.hpp"

namespace kresling::analyses {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<int> alternating(int cells) {
  std::vector<int> chirality(cells);
  for (int i = 0; i < cells; ++i) chirality[i] = (i % 2 == 0) ? 1 : -1;
  return chirality;
}

void check(int n, const BendingOptions& o) {
  if (n % 2 != 0) {
    throw_invalid("n", n,
                  "even for the bending test: each end is pinned at vertices 0 and n/2, which "
                  "must be opposite");
  }
  check_bending_cells(n, o.cells);
  require_finite("deflection", o.deflection);
  require_finite("deflection_angle", o.deflection_angle);
  if (std::abs(o.deflection_angle) >= 1.0) {
    throw_invalid("deflection_angle", o.deflection_angle, "smaller than 1 rad in magnitude");
  }
  solvers::check_steps("steps", o.steps);
}

}  // namespace

double slope_through_origin(const std::vector<double>& x, const std::vector<double>& y) {
  double xy = 0.0, xx = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) xy += x[i] * y[i], xx += x[i] * x[i];
  return xx > 0.0 ? xy / xx : kNaN;
}

BendingTest::BendingTest(int n, BendingOptions options)
    : options_((check(n, options), options)),
      builder_(n, alternating(options.cells), options.specimen),
      solver_(options.solver) {
  // Supports: vertices 0 and n/2 and the centre of the end polygons, x y z.
  const int num_nodes = (options_.cells + 1) * (n + 1);
  fixed_.assign(static_cast<std::size_t>(3 * num_nodes), 0);
  for (int level : {0, options_.cells}) {
    for (int j : {0, n / 2, n}) {
      for (int k = 0; k < 3; ++k) fixed_[3 * (level * (n + 1) + j) + k] = 1;
    }
  }
}

void check_bending_cells(int n, int cells) {
  if (cells < 2 || cells % 2 != 0) {
    throw_invalid("cells", cells, "an even number >= 2 (the load acts on the middle polygon)");
  }
  const long long nodes = (static_cast<long long>(cells) + 1) * (static_cast<long long>(n) + 1);
  if (nodes > kMaxBendingNodes) {
    long long most = kMaxBendingNodes / (n + 1) - 1;
    most -= most % 2;  // the largest even count
    throw_invalid("cells", cells,
                  "small enough that the specimen's (cells + 1) (n + 1) nodes stay <= " +
                      std::to_string(kMaxBendingNodes) + " (n = " + std::to_string(n) +
                      ": cells <= " + std::to_string(most) + ")");
  }
}

void check_bending_state(const geometry::Design& design, int state) {
  if (state != 0 && state != 1) throw_invalid("state", state, "0 (contracted) or 1 (extended)");
  // At Lc = 0 the contracted cells fold flat (module length 0, no bending stiffness to
  // measure); nearly flat, their hinge angles are not resolved (cell_checks.hpp).
  check_not_flat(design, state,
                 state == 0 ? "the bending test in the contracted state"
                            : "the bending test in the extended state");
}

double bending_drive(const geometry::Design& design, int state, const BendingOptions& o) {
  check(design.parameters().n, o);
  check_bending_state(design, state);
  const double module_length = 2.0 * design.height(static_cast<geometry::State>(state));
  const double deflection = o.deflection_angle != 0.0
                                ? module_length * std::tan(o.deflection_angle)
                                : o.deflection;
  if (deflection == 0.0 || std::abs(deflection) >= design.parameters().R) {
    throw_invalid(o.deflection_angle != 0.0 ? "deflection (L tan(deflection_angle))" : "deflection",
                  deflection,
                  "non-zero and smaller than the polygon's radius R = " +
                      format_number(design.parameters().R) + " mm");
  }
  return deflection;
}

DriveSetup BendingTest::setup(const geometry::Design& design, int state) {
  const BendingOptions& o = options_;
  if (design.parameters().n != builder_.n()) {
    throw_invalid("design.n", design.parameters().n,
                  "the test's n = " + std::to_string(builder_.n()));
  }
  const double deflection = bending_drive(design, state, o);
  DriveSetup s{builder_.build(design, std::vector<int>(o.cells, state), fixed_), VectorX()};
  s.prescribed = VectorX::Zero(s.specimen.model.num_dofs());
  for (int j = 0; j <= design.parameters().n; ++j) {
    s.prescribed[3 * s.specimen.node(o.cells / 2, j) + 1] = -deflection;
  }
  return s;
}

BendingResult BendingTest::run(const geometry::Design& design, int state) {
  const BendingOptions& o = options_;
  const DriveSetup drive = setup(design, state);
  const model::KreslingSpecimen& specimen = drive.specimen;
  const double module_length = 2.0 * design.height(static_cast<geometry::State>(state));
  const int n = design.parameters().n;
  const int middle = o.cells / 2;

  const solvers::PathResult path = solver_.solve(specimen.model, drive.prescribed, o.steps);

  BendingResult r;
  r.module_length = module_length;
  r.completed = path.completed;
  r.message = path.message;
  r.num_dofs = static_cast<int>(specimen.model.num_dofs());
  int held = 0;
  for (auto f : specimen.model.fixed()) held += f;
  r.num_free_dofs = r.num_dofs - held - (n + 1);
  const Index centre_y = 3 * specimen.node(middle, n) + 1;
  for (const auto& step : path.steps) {
    const double y = -step.displacement[centre_y];
    const double F = step.constraint_force.sum();
    r.deflection.push_back(y);
    r.force.push_back(F);
    r.angle.push_back(std::atan2(y, r.module_length));
    r.moment.push_back(F * r.module_length * 1e-3);
    r.iterations.push_back(step.iterations);
    r.negative_eigenvalues.push_back(step.negative_eigenvalues);
  }
  if (!path.steps.empty()) r.final_displacement = path.steps.back().displacement;
  r.stiffness = slope_through_origin(r.angle, r.moment);
  // Least squares with intercept (a lab fit); undefined with fewer than two points.
  const std::size_t m = r.angle.size();
  if (m >= 2) {
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < m; ++i) {
      sx += r.angle[i], sy += r.moment[i], sxx += r.angle[i] * r.angle[i];
      sxy += r.angle[i] * r.moment[i];
    }
    const double det = m * sxx - sx * sx;
    r.stiffness_intercept = det > 0 ? (m * sxy - sx * sy) / det : kNaN;
    r.intercept = det > 0 ? (sy - r.stiffness_intercept * sx) / m : kNaN;
  } else {
    r.stiffness_intercept = r.intercept = kNaN;
  }
  return r;
}

BendingResult bending_test(const geometry::Design& design, int state, const BendingOptions& o) {
  return BendingTest(design.parameters().n, o).run(design, state);
}

}  // namespace kresling::analyses
