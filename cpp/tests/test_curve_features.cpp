#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "kresling/analyses/curve_features.hpp"

using namespace kresling::analyses;

// On samples of a parabola the refined maximum is its vertex exactly, even with uneven
// spacing.
TEST(CurveFeatures, LocalMaximumOfAParabolaIsItsVertex) {
  const std::vector<double> x{0.0, 0.7, 1.1, 2.9, 3.0, 4.5};
  std::vector<double> y;
  for (double v : x) y.push_back(5.0 - 2.0 * (v - 1.3) * (v - 1.3));
  const LocalMaximum m = first_local_maximum(x, y);
  ASSERT_TRUE(m.found);
  EXPECT_EQ(m.index, 2u);
  EXPECT_NEAR(m.x, 1.3, 1e-12);
  EXPECT_NEAR(m.y, 5.0, 1e-12);
}

TEST(CurveFeatures, FirstOfTwoMaximaAndNoneOnAMonotonicCurve) {
  const std::vector<double> x{0, 1, 2, 3, 4, 5, 6};
  const LocalMaximum m = first_local_maximum(x, {0, 2, 1, 0, 3, 1, 0});
  ASSERT_TRUE(m.found);
  EXPECT_EQ(m.index, 1u);
  EXPECT_GT(m.x, 0.0);
  EXPECT_LT(m.x, 2.0);
  EXPECT_FALSE(first_local_maximum(x, {0, 1, 2, 2.5, 2.7, 3, 5}).found);
  // A maximum at the last sample is not a local maximum of the curve.
  EXPECT_FALSE(first_local_maximum(x, {0, 1, 2, 3, 4, 5, 6}).found);
  EXPECT_THROW(first_local_maximum(x, {0, 1}), std::invalid_argument);
}

TEST(CurveFeatures, CrossingsAreInterpolatedLinearly) {
  const std::vector<double> x{0, 1, 2, 3, 4};
  const std::vector<double> y{1, 3, -1, -2, 2};
  const Crossing down = first_crossing(x, y, 0, true);
  ASSERT_TRUE(down.found);
  EXPECT_EQ(down.index, 2u);
  EXPECT_DOUBLE_EQ(down.x, 1.75);
  const Crossing up = first_crossing(x, y, down.index, false);
  ASSERT_TRUE(up.found);
  EXPECT_EQ(up.index, 4u);
  EXPECT_DOUBLE_EQ(up.x, 3.5);
  EXPECT_FALSE(first_crossing(x, y, up.index, true).found);
}

TEST(CurveFeatures, HermiteIsExactForCubics) {
  auto e = [](double x) { return 2 * x * x * x - x * x + 0.5 * x - 3; };
  auto f = [](double x) { return 6 * x * x - 2 * x + 0.5; };
  for (double x : {-0.3, 0.1, 0.45, 0.8}) {
    EXPECT_NEAR(hermite(-0.5, 1.0, e(-0.5), e(1.0), f(-0.5), f(1.0), x), e(x), 1e-13);
  }
}
