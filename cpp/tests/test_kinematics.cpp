// Constant-curvature map (eqns 27-29), its inverse and the module transforms (eqns 26, 30).
#include <cmath>
#include <stdexcept>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "kresling/kinematics/constant_curvature.hpp"
#include "kresling/kinematics/module_transform.hpp"

using namespace kresling::kinematics;

namespace {

constexpr double kPi = 3.14159265358979323846;
const TendonLayout kThesis{32.0, 1};  // d = 32 mm, N = 1 (section 4.2)

double wrapped(double angle) { return std::remainder(angle, 2.0 * kPi); }

// Eqn 26 exactly as printed (only valid for kappa > 0).
Eigen::Matrix4d eqn26_literal(double s, double k, double p) {
  Eigen::Matrix4d H;
  H << std::cos(p), -std::sin(p) * std::cos(s * k), std::sin(p) * std::sin(s * k),
      std::sin(p) * (1 - std::cos(s * k)) / k,
      std::sin(p), std::cos(p) * std::cos(s * k), -std::cos(p) * std::sin(s * k),
      -std::cos(p) * (1 - std::cos(s * k)) / k,
      0, std::sin(s * k), std::cos(s * k), std::sin(s * k) / k,
      0, 0, 0, 1;
  return H;
}

}  // namespace

// Round trip: arc -> tendons -> arc to 1e-9 in all four quadrants of phi, N = 1 and
// N > 1. Tolerance: the map is well conditioned away from kappa = 0, so 1e-9 leaves a
// factor of ~1e5 over double rounding of lengths ~30 mm.
TEST(ConstantCurvature, ArcRoundTripInEveryQuadrantAndSegmentCount) {
  for (int N : {1, 2, 5}) {
    const TendonLayout layout{32.0, N};
    for (double phi : {0.4, 1.9, -2.6, -0.8, 0.5 * kPi, kPi, -0.5 * kPi, 0.0}) {
      for (double kappa : {1e-4, 0.004, 0.02}) {
        const Eigen::Vector3d arc(31.5, kappa, phi);
        const Eigen::Vector3d back = arc_from_tendons(tendons_from_arc(arc, layout), layout);
        EXPECT_NEAR(back[0], arc[0], 1e-9) << "N=" << N << " phi=" << phi << " k=" << kappa;
        EXPECT_NEAR(back[1], arc[1], 1e-9) << "N=" << N << " phi=" << phi << " k=" << kappa;
        EXPECT_NEAR(wrapped(back[2] - phi), 0.0, 1e-9) << "N=" << N << " phi=" << phi;
      }
    }
  }
}

TEST(ConstantCurvature, TendonRoundTripThroughTheStraightCase) {
  for (int N : {1, 3}) {
    const TendonLayout layout{32.0, N};
    for (double eps : {0.0, 1e-12, 1e-7, 1e-3, 1.0, 7.0}) {
      const Eigen::Vector3d l(30.0 - 2 * eps, 30.0 + 1.5 * eps, 30.0 + 0.5 * eps);
      const Eigen::Vector3d back = tendons_from_arc(arc_from_tendons(l, layout), layout);
      EXPECT_LT((back - l).norm(), 1e-12) << "N=" << N << " eps=" << eps;
    }
  }
}

TEST(ConstantCurvature, StraightCaseIsExact) {
  const Eigen::Vector3d arc = arc_from_tendons(Eigen::Vector3d(30, 30, 30), kThesis);
  EXPECT_EQ(arc[0], 30.0);
  EXPECT_EQ(arc[1], 0.0);
  EXPECT_EQ(arc[2], 0.0);
}

// Eqns 27-28 as printed agree with our rearranged forms away from the straight case, and
// atan2 agrees with the thesis's atan when l2 > l3 and turns the bend by pi when l2 < l3.
TEST(ConstantCurvature, MatchesEquations27To29AsPrinted) {
  const double d = 32.0, N = 1.0;
  for (const Eigen::Vector3d& l : {Eigen::Vector3d(22, 35, 33), Eigen::Vector3d(28, 24, 39),
                                   Eigen::Vector3d(40, 20, 30)}) {
    const double Q = l.squaredNorm() - l[0] * l[1] - l[1] * l[2] - l[0] * l[2];
    const double s = l.sum() * N * d / std::sqrt(Q) * std::asin(std::sqrt(Q) / (3 * N * d));
    const double kappa = 2 * std::sqrt(Q) / (d * l.sum());
    const double phi_thesis = std::atan(std::sqrt(3.0) / 3 * (l[2] + l[1] - 2 * l[0]) /
                                        (l[1] - l[2]));
    const Eigen::Vector3d arc = arc_from_tendons(l, kThesis);
    EXPECT_NEAR(arc[0], s, 1e-12);
    EXPECT_NEAR(arc[1], kappa, 1e-15);
    const double turn = l[1] > l[2] ? 0.0 : kPi;
    EXPECT_NEAR(std::abs(wrapped(arc[2] - phi_thesis - turn)), 0.0, 1e-12) << l.transpose();
  }
}

// Near the straight case s -> mean length smoothly: the series and closed form of
// asin(x)/x meet at y = 1e-3 without a jump (a jump would show as a difference well above
// rounding, ~1e-14 mm for s ~ 30 mm).
TEST(ConstantCurvature, ArcLengthIsContinuousAcrossTheSeriesSwitch) {
  const double x_switch = std::sqrt(1e-3);
  const double k_switch = x_switch * 32.0;  // sqrt(Q) = 3 k for the protocol, y = (k/32)^2
  for (double factor : {1.0 - 1e-9, 1.0 + 1e-9}) {
    const double k = k_switch * factor;
    const Eigen::Vector3d arc =
        arc_from_tendons(Eigen::Vector3d(30 - 2 * k, 30 + k, 30 + k), kThesis);
    const double expected = 30.0 / (k / 32.0) * std::asin(k / 32.0);  // eqn 27 directly
    EXPECT_NEAR(arc[0], expected, 1e-13);
  }
}

TEST(ModuleTransform, MatchesEquation26AndItsStraightLimit) {
  for (double phi : {0.3, 2.2, -1.2}) {
    const Eigen::Matrix4d T = flexible_module_transform(30.0, 0.02, phi, FrameConvention::Jones);
    EXPECT_LT((T - eqn26_literal(30.0, 0.02, phi)).norm(), 1e-12);
    // kappa -> 0: the limit is a translation by s along z, approached at O(s^2 kappa).
    const double s = 30.0, kappa = 1e-9;
    const Eigen::Matrix4d straight = flexible_module_transform(s, 0.0, phi, FrameConvention::Jones);
    EXPECT_EQ(straight(2, 3), s);
    EXPECT_EQ((straight.block<2, 1>(0, 3).norm()), 0.0);
    const Eigen::Matrix4d tiny = flexible_module_transform(s, kappa, phi, FrameConvention::Jones);
    EXPECT_LT((tiny - straight).norm(), s * s * kappa);
    // Where eqn 26 as printed cancels ((1 - cos 3e-8) / 1e-9 keeps no correct digit), the
    // safe form keeps full precision: sideways offset = s^2 kappa / 2 (1 - theta^2 / 12).
    EXPECT_NEAR(tiny(0, 3), std::sin(phi) * s * s * kappa / 2, 1e-18);
    EXPECT_NEAR(tiny(1, 3), -std::cos(phi) * s * s * kappa / 2, 1e-18);
  }
}

TEST(ModuleTransform, TwistFreeDiffersFromJonesOnlyByATurnAboutTheEndAxis) {
  const double s = 29.0, kappa = 0.015, phi = 2.4;
  const Eigen::Matrix4d jones = flexible_module_transform(s, kappa, phi, FrameConvention::Jones);
  const Eigen::Matrix4d free = flexible_module_transform(s, kappa, phi, FrameConvention::TwistFree);
  EXPECT_LT((jones.col(3) - free.col(3)).norm(), 1e-14);
  EXPECT_LT((jones.col(2) - free.col(2)).norm(), 1e-14);
  const Eigen::Matrix4d turn = free.inverse() * jones;  // = Rz(phi)
  EXPECT_NEAR(std::atan2(turn(1, 0), turn(0, 0)), phi, 1e-12);
  // Twist-free: the axis (cos phi, sin phi, 0) is the rotation axis, left fixed.
  const Eigen::Vector3d axis(std::cos(phi), std::sin(phi), 0.0);
  EXPECT_LT((free.block<3, 3>(0, 0) * axis - axis).norm(), 1e-14);
}

// The smooth tendon form equals eqn 26 (twist-free) evaluated at eqns 27-29, also at and
// near the straight case where phi is 0/0.
TEST(ModuleTransform, SmoothTendonFormMatchesTheArcForm) {
  for (int N : {1, 4}) {
    const TendonLayout layout{32.0, N};
    for (const Eigen::Vector3d& l :
         {Eigen::Vector3d(30, 30, 30), Eigen::Vector3d(30 - 2e-9, 30 + 1e-9, 30 + 1e-9),
          Eigen::Vector3d(10, 40, 40), Eigen::Vector3d(25, 33, 12), Eigen::Vector3d(38, 11, 29)}) {
      const Eigen::Vector3d arc = arc_from_tendons(l, layout);
      const Eigen::Matrix4d T =
          flexible_module_transform(arc[0], arc[1], arc[2], FrameConvention::TwistFree);
      const RigidMotion<double> motion = twist_free_motion_from_tendons<double>(l, layout);
      EXPECT_LT((motion.rotation - T.block<3, 3>(0, 0)).norm(), 1e-13) << l.transpose();
      EXPECT_LT((motion.translation - T.block<3, 1>(0, 3)).norm(), 1e-12) << l.transpose();
    }
  }
}

TEST(ConstantCurvature, RejectsLengthsNoArcRealises) {
  EXPECT_THROW(arc_from_tendons(Eigen::Vector3d(-1, 30, 30), kThesis), std::invalid_argument);
  EXPECT_THROW(arc_from_tendons(Eigen::Vector3d(NAN, 30, 30), kThesis), std::invalid_argument);
  EXPECT_THROW(arc_from_tendons(Eigen::Vector3d(0, 0, 0), kThesis), std::invalid_argument);
  // sqrt(Q) = 300 > 3 N d = 96: the tendons differ by more than any bend allows.
  try {
    arc_from_tendons(Eigen::Vector3d(0, 300, 300), kThesis);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("no constant-curvature arc with d = 32 mm"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(arc_from_tendons(Eigen::Vector3d(30, 30, 30), TendonLayout{0.0, 1}),
               std::invalid_argument);
  EXPECT_THROW(arc_from_tendons(Eigen::Vector3d(30, 30, 30), TendonLayout{32.0, 0}),
               std::invalid_argument);
  EXPECT_THROW(tendons_from_arc(Eigen::Vector3d(30, 0.2, 0.0), kThesis), std::invalid_argument);
  EXPECT_THROW(tendons_from_arc(Eigen::Vector3d(30, -0.01, 0.0), kThesis), std::invalid_argument);
}
