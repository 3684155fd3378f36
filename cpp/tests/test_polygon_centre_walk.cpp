// The walk to the N5B8 centre of a large planar polygon against trying every crossing of
// two diagonals (the rule's exact minimiser, used up to kCrossingCorners corners), and
// against the centre symmetry fixes.

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "kresling/model/panel_centre.hpp"
#include "kresling/model/polygon_centre_walk.hpp"

using namespace kresling;

namespace {

// A star-shaped polygon of m corners (random radii at increasing angles), turned into a
// random plane through a random point: convex or not, never self-intersecting.
std::vector<Vector3> random_polygon(std::size_t m, std::mt19937& rng, double size) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Eigen::Quaterniond turn = Eigen::Quaterniond::UnitRandom();
  const Vector3 shift(size * unit(rng), size * unit(rng), size * unit(rng));
  std::vector<Vector3> corners;
  for (std::size_t k = 0; k < m; ++k) {
    const double angle = 2 * M_PI * (k + 0.8 * unit(rng)) / m;
    const double radius = size * (0.4 + 0.6 * unit(rng));
    corners.push_back(shift + turn * Vector3(radius * std::cos(angle), radius * std::sin(angle), 0));
  }
  return corners;
}

std::vector<Vector3> regular_polygon(std::size_t m, double radius) {
  std::vector<Vector3> corners;
  for (std::size_t k = 0; k < m; ++k) {
    corners.emplace_back(radius * std::cos(2 * M_PI * k / m), radius * std::sin(2 * M_PI * k / m), 0);
  }
  return corners;
}

}  // namespace

TEST(PolygonCentreWalk, ReachesTheLowestCrossingOfEverySmallPolygon) {
  std::mt19937 rng(20240529);
  for (std::size_t m = 5; m <= model::kCrossingCorners; ++m) {
    for (int trial = 0; trial < 6; ++trial) {
      const double size = trial % 2 ? 1e-2 : 50.0;
      const auto corners = random_polygon(m, rng, size);
      const double exact = model::polygon_centre_objective(corners, model::polygon_optimal_centre(corners));
      const Vector3 walked = model::planar_polygon_centre_walk(corners);
      // The same minimum to rounding: the objective sums D terms of size ~1, each exact to
      // ~1e-16 relative, and the walk's point lies in its own fit of the plane.
      EXPECT_NEAR(model::polygon_centre_objective(corners, walked), exact, 1e-10 * exact)
          << m << " corners, trial " << trial;
    }
  }
}

TEST(PolygonCentreWalk, LargeRegularPolygonsAreCentred) {
  // By symmetry a regular polygon's centre is its middle (its long diagonals cross there
  // when m is even; for odd m the objective is symmetric and convex).
  for (std::size_t m : {25, 64, 101, 300}) {
    const Vector3 c = model::polygon_optimal_centre(regular_polygon(m, 40.0));
    EXPECT_LT(c.norm(), 1e-9 * 40.0) << m << " corners: " << c.transpose();
  }
}

TEST(PolygonCentreWalk, AboveTheLimitTheWalkIsTheCentre) {
  std::mt19937 rng(7);
  const auto corners = random_polygon(model::kCrossingCorners + 16, rng, 30.0);
  const Vector3 c = model::polygon_optimal_centre(corners);
  const double best = model::polygon_centre_objective(corners, c);
  // A minimum: no step in the plane or out of it lowers the objective.
  Vector3 normal = Vector3::Zero();
  for (std::size_t k = 0; k < corners.size(); ++k) {
    normal += corners[k].cross(corners[(k + 1) % corners.size()]);
  }
  const Vector3 e1 = (corners[0] - c).normalized(), e2 = normal.normalized().cross(e1);
  for (double angle = 0; angle < 2 * M_PI; angle += M_PI / 18) {
    const Vector3 step = 1e-4 * (std::cos(angle) * e1 + std::sin(angle) * e2);
    EXPECT_GE(model::polygon_centre_objective(corners, c + step), best * (1 - 1e-14));
  }
  EXPECT_GT(model::polygon_centre_objective(corners, c + 1e-4 * normal.normalized()), best);
}
