// The chain of modules (eqn 25), the thesis's protocol and Appendix E, the tip Jacobian
// and the inverse kinematics.
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "kresling/kinematics/chain.hpp"
#include "kresling/kinematics/inverse.hpp"

using namespace kresling::kinematics;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kExtended = 2 * 55.8194667799374;  // a module is two cells: L = 2 Le

ChainModel thesis_model(FrameConvention convention = FrameConvention::TwistFree) {
  return ChainModel{3, kExtended, TendonLayout{32.0, 1}, convention};
}

// Section 4.3's inputs for one flexible module at step k.
Eigen::Vector3d protocol(double k) { return {30.0 - 2 * k, 30.0 + k, 30.0 + k}; }

Eigen::MatrixX3d repeated(const Eigen::Vector3d& l, int rows) {
  Eigen::MatrixX3d out(rows, 3);
  out.rowwise() = l.transpose();
  return out;
}

Eigen::MatrixX3d markers(const ChainModel& model, const Configuration& c,
                         const Eigen::MatrixX3d& lengths) {
  return frame_origins(module_end_frames(model, c, module_arcs(model, c, lengths)));
}

}  // namespace

// Appendix E: configuration (1 0 1) at L1 = 10 (k = 10). Under the protocol the flexible
// module's marker-to-marker chord is 30 mm and its bend 2 asin(k/32), so the markers follow
// by hand: up L, across the chord at half the bend, then L along the bent axis.
TEST(Chain, AppendixEConfiguration101) {
  const double k = 10, theta = 2 * std::asin(k / 32.0);
  for (auto convention : {FrameConvention::Jones, FrameConvention::TwistFree}) {
    const Eigen::MatrixX3d p = markers(thesis_model(convention), {1, 0, 1}, repeated(protocol(k), 1));
    Eigen::MatrixX3d expected(4, 3);
    expected << 0, 0, 0,
                0, 0, kExtended,
                30 * std::sin(theta / 2), 0, kExtended + 30 * std::cos(theta / 2),
                30 * std::sin(theta / 2) + kExtended * std::sin(theta), 0,
                kExtended + 30 * std::cos(theta / 2) + kExtended * std::cos(theta);
    EXPECT_LT((p - expected).norm(), 1e-10);
  }
}

TEST(Chain, AllExtendedTipIsThreeModuleLengths) {
  const Eigen::MatrixX3d p = markers(thesis_model(), {1, 1, 1}, Eigen::MatrixX3d(0, 3));
  EXPECT_NEAR(p(3, 2), 3 * 111.6389335598748, 1e-9);
  EXPECT_NEAR(p(3, 2), 3 * 111.6389, 1e-3);  // the thesis's rounded figure
  EXPECT_EQ((p.block<4, 2>(0, 0).norm()), 0.0);
}

// Why the chord stays 30 mm: for N = 1 each tendon is a straight chord of the arc at
// radius 1/kappa - d sin(phi - sigma_i); the three offsets d sin(phi - sigma_i) sum to zero
// (tendons 120 degrees apart), so the backbone chord 2 sin(theta/2) / kappa is the mean
// tendon length, and the protocol (-2k, +k, +k) keeps that mean at 30 mm. Its bend is
// theta = 2 asin(sqrt(Q) / 3d) with sqrt(Q) = 3k.
TEST(Chain, ProtocolKeepsEveryFlexibleChordAndBendsBy2AsinKOver32) {
  const ChainModel model = thesis_model();
  for (const Configuration& c : {Configuration{0, 0, 0}, Configuration{0, 1, 0},
                                 Configuration{1, 1, 0}}) {
    const int f = flexible_count(c);
    for (int k = 1; k <= 10; ++k) {
      const auto frames = module_end_frames(model, c, module_arcs(model, c, repeated(protocol(k), f)));
      for (int j = 0; j < 3; ++j) {
        const double length = (frames[j + 1].col(3) - frames[j].col(3)).norm();
        const double bend = std::acos(std::clamp(frames[j].col(2).dot(frames[j + 1].col(2)), -1.0, 1.0));
        if (c[j] == 0) {
          EXPECT_NEAR(length, 30.0, 1e-11) << "k=" << k;
          EXPECT_NEAR(bend, 2 * std::asin(k / 32.0), 1e-7) << "k=" << k;  // acos: ~sqrt(eps)
        } else {
          EXPECT_NEAR(length, kExtended, 1e-11);
          EXPECT_NEAR(bend, 0.0, 1e-7);
        }
      }
      // The whole arm stays in the x-z plane of tendon 1.
      EXPECT_LT(frame_origins(frames).col(1).cwiseAbs().maxCoeff(), 1e-12);
    }
  }
}

// Both conventions, used consistently, give the same markers and axes for arbitrary
// (non-identical) modules; using eqn 26's phi raw in every module of the Jones chain does not.
TEST(Chain, FrameConventionsAgreeWhenUsedConsistently) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> length(12.0, 40.0);
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::MatrixX3d l(3, 3);
    for (int i = 0; i < 9; ++i) l(i / 3, i % 3) = length(rng);
    const Configuration c{0, 0, 0};
    const auto jones = thesis_model(FrameConvention::Jones);
    const auto free = thesis_model(FrameConvention::TwistFree);
    const auto fj = module_end_frames(jones, c, module_arcs(jones, c, l));
    const auto ff = module_end_frames(free, c, module_arcs(free, c, l));
    for (int j = 0; j <= 3; ++j) {
      EXPECT_LT((fj[j].col(3) - ff[j].col(3)).norm(), 1e-10);
      EXPECT_LT((fj[j].col(2) - ff[j].col(2)).norm(), 1e-12);
    }
    // The raw use: eqn 26 with the tendon phi in every module.
    Eigen::MatrixX3d raw = module_arcs(free, c, l);
    const auto fr = module_end_frames(jones, c, raw);
    EXPECT_GT((fr[3].col(3) - ff[3].col(3)).norm(), 1e-3);
  }
}

TEST(Chain, BackbonePassesThroughTheMarkers) {
  const ChainModel model = thesis_model(FrameConvention::Jones);
  const Configuration c{0, 1, 0};
  const Eigen::MatrixX3d arcs = module_arcs(model, c, repeated(Eigen::Vector3d(22, 35, 31), 2));
  const Eigen::MatrixX3d points = backbone_points(model, c, arcs, 8);
  const Eigen::MatrixX3d p = frame_origins(module_end_frames(model, c, arcs));
  ASSERT_EQ(points.rows(), 25);
  for (int j = 0; j <= 3; ++j) EXPECT_LT((points.row(8 * j) - p.row(j)).norm(), 1e-12);
}

TEST(Chain, BackboneRefusesMorePointsThanItsBound) {
  // m * per_module overflowed int (3 * 2^30: a negative size, std::bad_alloc).
  const ChainModel model = thesis_model();
  const Configuration c{0, 1, 0};
  const Eigen::MatrixX3d arcs = module_arcs(model, c, repeated(Eigen::Vector3d(22, 35, 31), 2));
  EXPECT_THROW(backbone_points(model, c, arcs, 1 << 30), std::invalid_argument);
  EXPECT_THROW(backbone_points(model, c, arcs, 0), std::invalid_argument);
  const int most = static_cast<int>((kMaxBackbonePoints - 1) / 3);
  EXPECT_THROW(backbone_points(model, c, arcs, most + 1), std::invalid_argument);
}

// Forward-mode derivatives against central differences. Step h = 1e-5 mm: the difference
// quotient's error is ~h^2 |p'''| / 6 ~ 1e-11 plus rounding ~eps |p| / h ~ 1e-9, hence 1e-7.
TEST(Chain, TipJacobianMatchesCentralDifferencesIncludingTheStraightCase) {
  const ChainModel model = thesis_model();
  const double h = 1e-5;
  for (const Configuration& c : {Configuration{0, 0, 0}, Configuration{1, 0, 1}}) {
    for (const Eigen::Vector3d& l : {Eigen::Vector3d(30, 30, 30), Eigen::Vector3d(14, 38, 36),
                                     Eigen::Vector3d(30 + 2e-4, 30 - 1e-4, 30 - 1e-4)}) {
      const Eigen::Matrix3d J = tip_jacobian(model, c, l);
      for (int i = 0; i < 3; ++i) {
        Eigen::Vector3d plus = l, minus = l;
        plus[i] += h;
        minus[i] -= h;
        const Eigen::Vector3d fd = (tip_position(model, c, plus) - tip_position(model, c, minus)) / (2 * h);
        EXPECT_LT((J.col(i) - fd).norm(), 1e-7) << "l=" << l.transpose() << " i=" << i;
      }
    }
  }
}

TEST(InverseKinematics, ReachesTargetsSampledFromForwardKinematics) {
  const ChainModel model = thesis_model();
  const TendonBounds bounds{10.0, 40.0};
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> length(bounds.lower, bounds.upper);
  for (const Configuration& c : {Configuration{0, 0, 0}, Configuration{1, 0, 1},
                                 Configuration{0, 1, 1}}) {
    Eigen::MatrixX3d targets(25, 3);
    for (int t = 0; t < 25; ++t) {
      const Eigen::Vector3d l(length(rng), length(rng), length(rng));
      targets.row(t) = tip_position(model, c, l).transpose();
    }
    const auto results = solve_inverse_kinematics_batch(model, c, targets, bounds);
    for (int t = 0; t < 25; ++t) {
      const auto& r = results[t];
      EXPECT_TRUE(r.converged) << "config " << c[0] << c[1] << c[2] << " target " << t;
      EXPECT_LT((tip_position(model, c, r.tendon_lengths) - targets.row(t).transpose()).norm(), 1e-6);
      EXPECT_GE(r.tendon_lengths.minCoeff(), bounds.lower);
      EXPECT_LE(r.tendon_lengths.maxCoeff(), bounds.upper);
    }
  }
}

TEST(InverseKinematics, TheTableStacksEachSolveInItsRow) {
  // What the Python binding returns: row t of each column is exactly results[t]'s field.
  const ChainModel model = thesis_model();
  const TendonBounds bounds{10.0, 40.0};
  const Configuration c{1, 0, 1};
  Eigen::MatrixX3d targets(3, 3);
  targets.row(0) = tip_position(model, c, Eigen::Vector3d(20, 30, 35)).transpose();
  targets.row(1) = Eigen::RowVector3d(0, 0, 1000);  // out of reach: not converged
  targets.row(2) = tip_position(model, c, Eigen::Vector3d(12, 39, 25)).transpose();
  const auto results = solve_inverse_kinematics_batch(model, c, targets, bounds);
  const InverseKinematicsTable table = as_table(results);
  ASSERT_EQ(table.distance.size(), 3);
  for (int t = 0; t < 3; ++t) {
    EXPECT_EQ(table.tendon_lengths.row(t), results[t].tendon_lengths.transpose());
    EXPECT_EQ(table.position.row(t), results[t].position.transpose());
    EXPECT_EQ(table.distance[t], results[t].distance);
    EXPECT_EQ(table.iterations[t], results[t].iterations);
    EXPECT_EQ(table.converged[t], results[t].converged);
  }
  EXPECT_TRUE(table.converged[0] && !table.converged[1] && table.converged[2]);
  EXPECT_EQ(as_table({}).position.rows(), 0);
}

TEST(InverseKinematics, FarTargetIsAResultNotAnException) {
  const ChainModel model = thesis_model();
  const TendonBounds bounds{10.0, 40.0};
  const auto r = solve_inverse_kinematics(model, {0, 0, 0}, Eigen::Vector3d(0, 0, 1000), bounds);
  EXPECT_FALSE(r.converged);
  // The nearest point of (000) to a target far up the axis: straight, tendons at the upper bound.
  EXPECT_NEAR(r.position.z(), 120.0, 1e-6);
  EXPECT_NEAR(r.distance, 880.0, 1e-6);
}

TEST(Chain, RejectsBadModelsAndConfigurations) {
  ChainModel model = thesis_model();
  EXPECT_THROW(module_arcs(model, {0, 2, 1}, Eigen::MatrixX3d::Constant(1, 3, 30.0)), std::invalid_argument);
  EXPECT_THROW(module_arcs(model, {0, 1}, Eigen::MatrixX3d::Constant(1, 3, 30.0)), std::invalid_argument);
  EXPECT_THROW(module_arcs(model, {0, 1, 1}, Eigen::MatrixX3d::Constant(2, 3, 30.0)), std::invalid_argument);
  model.modules = 0;
  EXPECT_THROW(validate(model), std::invalid_argument);
  model.modules = kMaxModules + 1;  // 2^31 - 1 modules exhausted memory in the callers
  EXPECT_THROW(validate(model), std::invalid_argument);
  model.modules = kMaxModules;
  EXPECT_NO_THROW(validate(model));
  EXPECT_THROW(validate(TendonBounds{10.0, 10.0}, TendonLayout{32.0, 1}), std::invalid_argument);
  // A box whose corner (0, 500, 500) no arc with d = 32 realises.
  EXPECT_THROW(validate(TendonBounds{0.0, 500.0}, TendonLayout{32.0, 1}), std::invalid_argument);
}
