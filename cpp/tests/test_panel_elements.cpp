// Model building from panels by MERLIN2's rules: the N4B5 cuts, the N5B8 centres, the
// element lists, the sheet calibration against hand calculations, and the two pieces of
// Octave arithmetic that make models agree with MERLIN2's to the last bit.

#include <cmath>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "kresling/elements/dihedral.hpp"
#include "kresling/model/calibration.hpp"
#include "kresling/model/merlin2_rest_angle.hpp"
#include "kresling/model/octave_arithmetic.hpp"
#include "kresling/model/panel_centre.hpp"
#include "kresling/model/panel_elements.hpp"

using namespace kresling;
using model::PanelSplit;

namespace {

constexpr double kPi = 3.14159265358979323846;

NodeMatrix rows(std::initializer_list<std::array<double, 3>> points) {
  NodeMatrix X(static_cast<Index>(points.size()), 3);
  Index i = 0;
  for (const auto& p : points) X.row(i++) << p[0], p[1], p[2];
  return X;
}

}  // namespace

TEST(PanelElements, QuadN4B5CutsTheShorterDiagonal) {
  const NodeMatrix kite = rows({{0, 0, 0}, {3, -1, 0}, {5, 0, 0}, {3, 1, 0}});  // 1-3 shorter
  const auto e = model::build_panel_elements(kite, {{0, 1, 2, 3}}, PanelSplit::N4B5);
  ASSERT_EQ(e.bends.size(), 1u);
  EXPECT_EQ(e.bends[0], (std::array<Index, 4>{1, 3, 0, 2}));
  EXPECT_EQ(e.triangles.size(), 2u);
  EXPECT_EQ(e.bars().size(), 5u);  // the cut and the four sides (boundary)
  EXPECT_TRUE(e.folds.empty());
}

TEST(PanelElements, PolygonCutsTieBreakColumnByColumn) {
  // A regular hexagon: all six short diagonals tie; MERLIN2 visits pairs (i, j) column by
  // column (j outer), so the first short one is (0, 2), then each side recursively.
  std::vector<Vector3> hexagon;
  for (int k = 0; k < 6; ++k) hexagon.emplace_back(std::cos(k * kPi / 3), std::sin(k * kPi / 3), 0);
  const auto cuts = model::polygon_diagonal_cuts(hexagon);
  ASSERT_EQ(cuts.size(), 3u);
  EXPECT_EQ(cuts[0], (std::array<Index, 2>{0, 2}));
  for (const auto& c : cuts) EXPECT_LT(c[0], c[1]);
}

TEST(PanelCentre, PlanarQuadCentreIsTheDiagonalsCrossing) {
  const Vector3 p0(0, 0, 0), p1(4, 0, 0), p2(5, 3, 0), p3(1, 2, 0);
  const Vector3 c = model::quad_centre(p0, p1, p2, p3);
  // On both diagonals: zero distance from each line.
  EXPECT_NEAR((c - p0).cross(p2 - p0).norm(), 0.0, 1e-12);
  EXPECT_NEAR((c - p1).cross(p3 - p1).norm(), 0.0, 1e-12);
  EXPECT_THROW(model::quad_centre(p0, p1, p0, p3), std::invalid_argument);
}

TEST(PanelCentre, PolygonCentreOfASymmetricHexagonIsExact) {
  // MERLIN2's polygon test: its three long diagonals meet at (30, 10, 0).
  const std::vector<Vector3> hexagon = {{0, 0, 0},  {0, 20, 0}, {24, 30, 0},
                                        {60, 20, 0}, {60, 0, 0}, {36, -10, 0}};
  const Vector3 c = model::polygon_optimal_centre(hexagon);
  EXPECT_EQ(c, Vector3(30, 10, 0));
  // Any small step away raises the (convex) objective.
  const double best = model::polygon_centre_objective(hexagon, c);
  for (const Vector3& step : {Vector3(1e-3, 0, 0), Vector3(0, -1e-3, 0), Vector3(0, 0, 1e-3)}) {
    EXPECT_GT(model::polygon_centre_objective(hexagon, c + step), best);
  }
}

TEST(Calibration, TriangleAndRectangleMatchTheFormulas) {
  const model::SheetMaterial m{1000.0, 0.3, 0.25, 0.0};
  const double D = 1000.0 * std::pow(0.25, 3) / (12 * (1 - 0.09));
  const NodeMatrix triangle = rows({{0, 0, 0}, {3, 0, 0}, {0, 4, 0}});
  auto e = model::build_panel_elements(triangle, {{0, 1, 2}}, PanelSplit::N5B8);
  auto s = model::calibrate_sheet(e, {{0, 1, 2}}, m, false);
  for (double a : s.bar_area) EXPECT_NEAR(a, 0.25 * 2 * 6 / (12 * 0.7), 1e-15);

  const NodeMatrix rectangle = rows({{0, 0, 0}, {8, 0, 0}, {8, 5, 0}, {0, 5, 0}});
  e = model::build_panel_elements(rectangle, {{0, 1, 2, 3}}, PanelSplit::N5B8);
  s = model::calibrate_sheet(e, {{0, 1, 2, 3}}, m, false);
  const double diagonal = std::hypot(8.0, 5.0);
  for (double k : s.bend_stiffness) {
    EXPECT_NEAR(k, D * std::cbrt(diagonal / 0.25) / diagonal, 1e-15);
  }
  EXPECT_THROW(model::calibrate_sheet(e, {{0, 1, 2, 3}}, {1000.0, 0.7, 0.25, 0.0}, false),
               std::invalid_argument);
}

TEST(OctaveArithmetic, NormAndLeastSquares) {
  // The scaled 2-norm is a 2-norm (to rounding), also where squares would overflow.
  EXPECT_NEAR(model::octave_norm(Vector3(3, 4, 12)), 13.0, 1e-14);
  EXPECT_NEAR(model::octave_norm(Vector3(3e200, 4e200, 0)) / 5e200, 1.0, 1e-15);
  // dgelsd solves a consistent 3 x 2 system exactly (to rounding).
  Eigen::Matrix<double, 3, 2> A;
  A << 1, 0, 0, 1, 1, 1;
  Eigen::Vector2d x;
  ASSERT_TRUE(model::octave_least_squares(A, Vector3(2, 3, 5), x));
  EXPECT_NEAR(x[0], 2.0, 1e-14);
  EXPECT_NEAR(x[1], 3.0, 1e-14);
}

TEST(Merlin2RestAngle, AgreesWithTheKernelBeyondTheArccosineLimit) {
  // Away from 0 and pi both arccosines are well conditioned: they agree to ~1e-14; near pi
  // each is within ~1e-7 of the other (an ulp at the arccosine's argument).
  const Vector3 a(0, 0, 0), b(1, 0, 0);
  for (double angle : {0.4, 1.3, 2.5, 3.9, 5.6}) {
    const Vector3 c(0.3, 1, 0), d(0.6, std::cos(angle), std::sin(angle));
    EXPECT_NEAR(model::merlin2_rest_angle(a, b, c, d), elements::dihedral_angle(a, b, c, d),
                1e-12);
  }
  const Vector3 c(0.3, 1, 0), d(0.6, -1, 1e-12);
  EXPECT_NEAR(model::merlin2_rest_angle(a, b, c, d), kPi, 1e-7);
}
