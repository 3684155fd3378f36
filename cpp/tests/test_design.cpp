#include <cmath>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "kresling/geometry/design.hpp"
#include "kresling/geometry/design_table.hpp"

using kresling::geometry::Design;
using kresling::geometry::State;

namespace {
constexpr double kPi = 3.14159265358979323846;
}

// docs/thesis_equations.md, 'Geometry': the exact value the thesis's Appendix E code uses.
TEST(Design, ExtendedHeightOfTheOptimum) {
  const Design d(10, 30.0, 0.9, 15.0);
  EXPECT_NEAR(d.derived().Le, 55.8194667799374, 1e-9);
}

TEST(Design, ExtendedHeightsListedInNotes) {
  EXPECT_NEAR(Design(8, 30.0, 0.8, 30.0).derived().Le, 55.317649, 1e-6);
  EXPECT_NEAR(Design(8, 30.0, 0.8, 15.0).derived().Le, 48.836895, 1e-6);
  EXPECT_NEAR(Design(4, 30.0, 0.7, 30.0).derived().Le, 41.068587, 1e-6);
}

// A MERLIN2 reference model (n=4, Lc=30, lambda=0.7, extended) lists the as-built angle of
// its first polygon-edge hinge, which is Psi_ext (docs/thesis_equations.md, 'Geometry').
TEST(Design, FacetAngleMatchesMerlinGoldenHinge) {
  EXPECT_NEAR(Design(4, 30.0, 0.7, 30.0).derived().psi_ext, 1.2878022801111912, 1e-12);
}

TEST(Design, KinematicPathPassesThroughBothStableStates) {
  const Design d(10, 30.0, 0.9, 15.0);
  const auto& q = d.derived();
  EXPECT_NEAR(d.height_at(q.alpha0), 15.0, 1e-12);
  EXPECT_NEAR(d.height_at(q.alpha_e), q.Le, 1e-12);
  EXPECT_NEAR(d.mountain_length_at(q.alpha0), q.Mg, 1e-12);
  EXPECT_NEAR(d.mountain_length_at(q.alpha_e), q.Mg, 1e-12);
  EXPECT_NEAR(d.facet_angle_at(q.alpha_e), q.psi_ext, 1e-14);
  EXPECT_DOUBLE_EQ(d.height(State::Extended), q.Le);
  EXPECT_DOUBLE_EQ(d.twist(State::Contracted), q.alpha0);
}

TEST(Design, TraditionalLimit) {
  // lambda -> 1 with Lc = 0: Le = M = 2 R cos(pi/n).
  for (int n : {3, 4, 6, 10, 24}) {
    const Design d(n, 30.0, 1.0 - 1e-12, 0.0);
    EXPECT_NEAR(d.derived().Le, 2 * 30.0 * std::cos(kPi / n), 1e-8) << "n=" << n;
    EXPECT_NEAR(d.derived().M, 2 * 30.0 * std::cos(kPi / n), 1e-8) << "n=" << n;
  }
}

TEST(Design, RejectsParametersOutsideTheDesignSpace) {
  EXPECT_THROW(Design(2, 30, 0.9, 15), std::invalid_argument);
  EXPECT_THROW(Design(10, 0, 0.9, 15), std::invalid_argument);
  EXPECT_THROW(Design(10, 30, 0.5, 15), std::invalid_argument);
  EXPECT_THROW(Design(10, 30, 1.0, 15), std::invalid_argument);
  EXPECT_THROW(Design(10, 30, 0.9, -1), std::invalid_argument);
  EXPECT_THROW(Design(10, 30, std::nan(""), 15), std::invalid_argument);
  EXPECT_THROW(Design(10, 30, 0.9, INFINITY), std::invalid_argument);
  EXPECT_THROW(Design(10, 30, 0.9, 15, 0), std::invalid_argument);
  try {
    Design(10, 30, 1.2, 15);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "lam = 1.2 is invalid: must be in the open interval (0.5, 1)");
  }
}

TEST(Design, HeightBeyondThePathThrows) {
  const Design d(10, 30.0, 0.9, 0.0);
  // Past alpha0 the valley bars would have to pass below the base: L^2 < 0.
  EXPECT_THROW(d.height_at(d.derived().alpha0 + 0.1), std::invalid_argument);
}

TEST(DesignTable, MatchesSingleDesignsAndNamesTheBadEntry) {
  const std::vector<int> n = {4, 10};
  const std::vector<double> R = {30, 30}, lam = {0.7, 0.9}, Lc = {30, 15};
  std::vector<double> out(2 * kresling::geometry::kDerivedNames.size());
  kresling::geometry::derive_table(n.data(), R.data(), lam.data(), Lc.data(), 2, out.data());
  const auto row1 = kresling::geometry::derived_as_array(Design(10, 30, 0.9, 15).derived());
  for (std::size_t k = 0; k < row1.size(); ++k) {
    EXPECT_EQ(out[kresling::geometry::kDerivedNames.size() + k], row1[k]);
  }
  const std::vector<double> bad_lam = {0.7, 0.4};
  try {
    kresling::geometry::derive_table(n.data(), R.data(), bad_lam.data(), Lc.data(), 2,
                                     out.data());
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("lam[1] = 0.4"), std::string::npos) << e.what();
  }
}
