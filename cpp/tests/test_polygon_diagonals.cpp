// Panels that are not convex, or have straight (180 deg) corners, split into triangles:
// which segments are interior diagonals, which centres a fan can use, and that the split
// covers the panel exactly (its triangles' areas, all turning its way, add up to its area).

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "kresling/model/panel_elements.hpp"
#include "kresling/model/polygon_diagonals.hpp"

using namespace kresling;
using model::PanelSplit;
using model::PlanarPolygon;

namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<Vector3> corners_of(std::initializer_list<std::array<double, 2>> xy) {
  std::vector<Vector3> out;
  for (const auto& p : xy) out.emplace_back(p[0], p[1], 0.0);
  return out;
}

NodeMatrix as_rows(const std::vector<Vector3>& points) {
  NodeMatrix X(static_cast<Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i) X.row(static_cast<Index>(i)) = points[i];
  return X;
}

std::vector<Index> first_n(std::size_t n) {
  std::vector<Index> panel(n);
  for (std::size_t k = 0; k < n; ++k) panel[k] = static_cast<Index>(k);
  return panel;
}

double polygon_area(const std::vector<Vector3>& p) {  // in the xy plane, counter-clockwise
  double twice = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Vector3& a = p[k];
    const Vector3& b = p[(k + 1) % p.size()];
    twice += a.x() * b.y() - a.y() * b.x();
  }
  return 0.5 * twice;
}

// The split covers the panel: every triangle has an area (none degenerate) and together
// they have the panel's, so none overlaps another or pokes outside (for a planar panel).
void expect_exact_cover(const model::PanelElements& e, double area, const std::string& what) {
  double sum = 0.0;
  for (const auto& t : e.triangles) {
    const Vector3 a = e.nodes.row(t[0]), b = e.nodes.row(t[1]), c = e.nodes.row(t[2]);
    const double piece = 0.5 * (b - a).cross(c - a).norm();
    EXPECT_GT(piece, 1e-9 * area) << what;
    sum += piece;
  }
  EXPECT_NEAR(sum, area, 1e-12 * area) << what;
}

}  // namespace

TEST(PolygonDiagonals, AnLShapedPanelsDiagonalsInsideAndOutside) {
  const PlanarPolygon l_shape(corners_of({{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {0, 2}}));
  EXPECT_TRUE(l_shape.is_simple());
  EXPECT_TRUE(l_shape.is_interior_diagonal(2, 5));
  EXPECT_TRUE(l_shape.is_interior_diagonal(2, 4));
  EXPECT_FALSE(l_shape.is_interior_diagonal(1, 3));  // around the reflex corner, outside
  EXPECT_FALSE(l_shape.is_interior_diagonal(0, 4));  // through the reflex corner 2
  EXPECT_FALSE(l_shape.is_interior_diagonal(0, 1));  // a side
  EXPECT_FALSE(l_shape.is_star_centre(Vector3(1, 1, 0)));    // the reflex corner itself
  EXPECT_TRUE(l_shape.is_star_centre(Vector3(0.5, 1.5, 0)));  // in the square both arms see
  EXPECT_FALSE(l_shape.is_star_centre(Vector3(1.8, 1.2, 0)));  // cannot see corner 0's sides
}

TEST(PolygonDiagonals, AStraightCornerIsNoPlaceForADiagonalOrACentre) {
  // Corner 1 is straight: 0-2 runs along two sides; the quads' diagonals cross at corner 1.
  const PlanarPolygon quad(corners_of({{0, 0}, {1, 0}, {2, 0}, {1, 1}}));
  EXPECT_TRUE(quad.is_simple());
  EXPECT_FALSE(quad.is_interior_diagonal(0, 2));
  EXPECT_TRUE(quad.is_interior_diagonal(1, 3));
  EXPECT_FALSE(quad.is_star_centre(Vector3(1, 0, 0)));
  EXPECT_TRUE(quad.is_star_centre(Vector3(1, 0.25, 0)));
  // Nearly straight (1e-7 rad off): cutting it off would leave a triangle with a 1e-7 rad
  // corner, and a centre 1e-7 off a side's line a fan triangle as sharp; neither is used.
  const PlanarPolygon nearly(corners_of({{0, 0}, {1, -1e-7}, {2, 0}, {1, 1}}));
  EXPECT_FALSE(nearly.is_interior_diagonal(0, 2));
  EXPECT_TRUE(nearly.is_interior_diagonal(1, 3));
  EXPECT_FALSE(nearly.is_star_centre(Vector3(1, -0.9e-7, 0)));
}

TEST(PolygonDiagonals, SelfIntersectingAndPinchedPanelsAreNotSimple) {
  EXPECT_FALSE(PlanarPolygon(corners_of({{0, 0}, {1, 1}, {1, 0}, {0, 1}})).is_simple());
  // A corner on another side (the pentagon's corner 1 lies on side 4-0).
  EXPECT_FALSE(
      PlanarPolygon(corners_of({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}})).is_simple());
  // A pentagram winds twice about its centre: no fan.
  std::vector<Vector3> star;
  for (int k = 0; k < 5; ++k) star.emplace_back(std::cos(4 * kPi * k / 5), std::sin(4 * kPi * k / 5), 0);
  const PlanarPolygon pentagram(star);
  EXPECT_FALSE(pentagram.is_simple());
  EXPECT_FALSE(pentagram.is_star_centre(Vector3::Zero()));
  EXPECT_THROW(PlanarPolygon(corners_of({{0, 0}, {1, 0}, {2, 0}})), std::invalid_argument);
}

TEST(PanelElements, ADartQuadIsCutAlongItsInteriorDiagonal) {
  // Corner 3 is reflex; the shorter diagonal 0-2 (length 2) lies outside, 1-3 (2.8) inside.
  const auto dart = corners_of({{0, 0}, {3, 1}, {0, 2}, {0.2, 1}});
  const auto n4b5 = model::build_panel_elements(as_rows(dart), {first_n(4)}, PanelSplit::N4B5);
  ASSERT_EQ(n4b5.bends.size(), 1u);
  EXPECT_EQ(n4b5.bends[0], (std::array<Index, 4>{1, 3, 0, 2}));
  expect_exact_cover(n4b5, polygon_area(dart), "dart N4B5");
  // N5B8: MERLIN2's centre (where the diagonals' lines cross, (0, 1)) lies outside; the
  // corners' mean (0.8, 1) sees every side, so the fan is built there.
  const auto n5b8 = model::build_panel_elements(as_rows(dart), {first_n(4)}, PanelSplit::N5B8);
  ASSERT_EQ(n5b8.panel_centre[0], 4);
  EXPECT_LE((Vector3(n5b8.nodes.row(4)) - Vector3(0.8, 1, 0)).norm(), 1e-15);
  expect_exact_cover(n5b8, polygon_area(dart), "dart N5B8");
}

TEST(PanelElements, AQuadWithAStraightCornerSplitsInBothWays) {
  const auto quad = corners_of({{0, 0}, {1, 0}, {2, 0}, {1, 1}});
  const auto n4b5 = model::build_panel_elements(as_rows(quad), {first_n(4)}, PanelSplit::N4B5);
  EXPECT_EQ(n4b5.bends[0], (std::array<Index, 4>{1, 3, 0, 2}));  // not along the sides
  expect_exact_cover(n4b5, 1.0, "straight corner N4B5");
  const auto n5b8 = model::build_panel_elements(as_rows(quad), {first_n(4)}, PanelSplit::N5B8);
  EXPECT_EQ(n5b8.panel_centre[0], 4);  // at the mean: MERLIN2's lands on corner 1
  expect_exact_cover(n5b8, 1.0, "straight corner N5B8");
}

TEST(PanelElements, AnLShapedPanelWithNoCentreIsCutInN5B8Too) {
  // The L's corners' mean is its reflex corner: no fan there; MERLIN2's centre is tried
  // first. Whichever is used, the panel is covered exactly.
  const auto l_shape = corners_of({{0, 0}, {1, 0}, {1, 1}, {2, 1}, {2, 2}, {0, 2}});
  for (PanelSplit split : {PanelSplit::N4B5, PanelSplit::N5B8}) {
    const auto e = model::build_panel_elements(as_rows(l_shape), {first_n(6)}, split);
    expect_exact_cover(e, 3.0, split == PanelSplit::N4B5 ? "L N4B5" : "L N5B8");
  }
}

TEST(PanelElements, RandomStarShapedPanelsAreCoveredExactly) {
  // Corners at increasing angles and random radii (convex or not, never self-intersecting),
  // some on straight lines between their neighbours; both splits, at three scales.
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> radius(0.3, 1.0), unit(0.0, 1.0);
  for (double scale : {1e-3, 1.0, 1e3}) {
    for (int trial = 0; trial < 200; ++trial) {
      const int m = 4 + trial % 9;
      std::vector<Vector3> corners;
      for (int k = 0; k < m; ++k) {
        const double angle = 2 * kPi * (k + 0.8 * unit(rng)) / m;
        const double r = scale * radius(rng);
        corners.emplace_back(r * std::cos(angle), r * std::sin(angle), 0.0);
      }
      // A straight corner where corners 0 and 2 are less than pi apart about the centre (the
      // chord between them then stays on their side of it).
      if (trial % 3 == 0 && m >= 6) corners[1] = 0.5 * (corners[0] + corners[2]);
      const double area = polygon_area(corners);
      for (PanelSplit split : {PanelSplit::N4B5, PanelSplit::N5B8}) {
        const auto e = model::build_panel_elements(as_rows(corners), {first_n(m)}, split);
        expect_exact_cover(e, area, "trial " + std::to_string(trial));
      }
    }
  }
}

TEST(PanelElements, ASelfIntersectingPanelIsRefusedByName) {
  const auto bowtie = corners_of({{0, 0}, {1, 1}, {1, 0}, {0, 1}});
  for (PanelSplit split : {PanelSplit::N4B5, PanelSplit::N5B8}) {
    try {
      model::build_panel_elements(as_rows(bowtie), {first_n(4)}, split);
      ADD_FAILURE() << "a bowtie was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind("panel 0: two of its sides cross", 0), 0u) << e.what();
    }
  }
}
