// The triangle's corner springs (elements/corner_angle.hpp) and their family
// (model/face_angle_family.hpp): the kernel against finite differences, rigid motions and
// scaling, and the family through a model against a closed-form equilibrium.
//
// Tolerances: central differences of step h = 1e-6 on O(1) triangles have truncation
// error ~h^2 |third derivative| ~ 1e-12 and rounding ~eps / h ~ 1e-10 relative; 1e-7
// relative leaves room for both and catches any wrong term (those are O(1) relative).

#include <cmath>
#include <memory>
#include <random>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "finite_differences.hpp"
#include "kresling/assembly/assembler.hpp"
#include "kresling/elements/corner_angle.hpp"
#include "kresling/model/bar_family.hpp"
#include "kresling/model/face_angle_family.hpp"
#include "kresling/model/family_registry.hpp"
#include "kresling/model/model.hpp"
#include "kresling/solvers/force_control.hpp"

using namespace kresling;

namespace {

constexpr double kStep = 1e-6;
constexpr double kRelTol = 1e-7;
constexpr double kPi = 3.14159265358979323846;

Vector3 random_vector(std::mt19937& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  return {u(rng), u(rng), u(rng)};
}

elements::CornerAngleResponse response(const elements::Vector9& x,
                                       const std::array<double, 3>& rest, double k) {
  return elements::corner_angle_response(x.segment<3>(0), x.segment<3>(3), x.segment<3>(6),
                                         rest, k);
}

}  // namespace

TEST(CornerAngles, GradientAndHessianMatchFiniteDifferences) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> rest_angle(0.3, 1.5), stiffness(0.1, 3.0);
  for (int trial = 0; trial < 50; ++trial) {
    elements::Vector9 x;
    for (int n = 0; n < 3; ++n) x.segment<3>(3 * n) = random_vector(rng, -1.0, 1.0);
    const std::array<double, 3> rest = {rest_angle(rng), rest_angle(rng), rest_angle(rng)};
    const double k = stiffness(rng);
    const auto r = response(x, rest, k);
    const auto [g_fd, h_fd] = test::energy_differences(
        [&](const elements::Vector9& y) { return response(y, rest, k); }, x, kStep);
    EXPECT_LE((r.force - g_fd).norm(), kRelTol * std::max(1.0, r.force.norm())) << trial;
    EXPECT_LE((r.stiffness - h_fd).norm(), kRelTol * std::max(1.0, r.stiffness.norm())) << trial;
    EXPECT_LE((r.stiffness - r.stiffness.transpose()).norm(), 1e-12 * r.stiffness.norm());
  }
}

TEST(CornerAngles, SumToPiAndDoNotChangeUnderRigidMotionsOrScaling) {
  std::mt19937 rng(12);
  for (int trial = 0; trial < 20; ++trial) {
    const Vector3 a = random_vector(rng, -1, 1), b = random_vector(rng, -1, 1),
                  c = random_vector(rng, -1, 1);
    const auto angles = elements::corner_angles(a, b, c);
    EXPECT_NEAR(angles[0] + angles[1] + angles[2], kPi, 1e-13);
    const Matrix3 turn = Eigen::AngleAxisd(0.7 + trial, random_vector(rng, -1, 1).normalized())
                             .toRotationMatrix();
    const Vector3 shift = random_vector(rng, -5, 5);
    const double scale = 0.01 + trial;
    const auto moved = elements::corner_angles(scale * turn * a + shift, scale * turn * b + shift,
                                               scale * turn * c + shift);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(moved[i], angles[i], 1e-12);
  }
  // A right isosceles triangle: pi / 2 at its right angle, pi / 4 at the others.
  const auto right = elements::corner_angles(Vector3(0, 0, 0), Vector3(2, 0, 0), Vector3(0, 2, 0));
  EXPECT_NEAR(right[0], kPi / 2, 1e-15);
  EXPECT_NEAR(right[1], kPi / 4, 1e-15);
  EXPECT_NEAR(right[2], kPi / 4, 1e-15);
}

TEST(CornerAngles, AtRestStoreAndPullNothingAndTheTangentIsPositiveSemiDefinite) {
  const Vector3 a(0, 0, 0), b(1, 0, 0), c(0.3, 0.8, 0.1);
  const auto rest = elements::corner_angles(a, b, c);
  const auto r = elements::corner_angle_response(a, b, c, rest, 2.0);
  EXPECT_LE(r.energy, 1e-28);        // the rest angles measured the same way, to rounding
  EXPECT_LE(r.force.norm(), 1e-14);
  // At rest the tangent is k grad grad^T per corner: semi-definite, and zero on the seven
  // motions that keep the angles (three translations, three rotations, a scaling).
  const Eigen::SelfAdjointEigenSolver<elements::Matrix9> eig(r.stiffness);
  EXPECT_GT(eig.eigenvalues().minCoeff(), -1e-12 * eig.eigenvalues().maxCoeff());
  EXPECT_EQ((eig.eigenvalues().array() > 1e-9 * eig.eigenvalues().maxCoeff()).count(), 2);
}

TEST(FaceAngleFamily, IsRegisteredAndRoundTripsItsTable) {
  const auto& kind = model::family_kind("face_angles");
  model::FaceAngleFamily faces({{{0, 1, 2}, {1.0, 1.1, kPi - 2.1}, 0.5}});
  const auto rebuilt = kind.from_table(faces.table());
  EXPECT_EQ(rebuilt->table().at("rest_angle").reals, faces.table().at("rest_angle").reals);
  EXPECT_EQ(rebuilt->table().at("stiffness").reals, faces.table().at("stiffness").reals);
  EXPECT_EQ(rebuilt->element_dofs(0), (std::vector<Index>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
}

TEST(FaceAngleFamily, AShearedRightTriangleBalancesItsLoadInClosedForm) {
  // a = (0, 0) and b = (1, 0) held; c = (0, 1) on a bar from a, stiff enough to keep
  // |ac| = 1 to 1e-7 (its tension ~0.1 N over EA = 1e6 N), free in the plane. A force F along x turns c by delta
  // about a: the angle at a closes to pi/2 - delta, those at b and c open to pi/4 + delta/2
  // each, so E = k (delta^2 + 2 (delta/2)^2) / 2 = 3 k delta^2 / 4 and, with c moving by
  // cos(delta) d delta along x, equilibrium is F cos(delta) = 3 k delta / 2.
  NodeMatrix X(3, 3);
  X << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  const double k = 2.0, delta = 0.2;
  auto faces = std::make_shared<model::FaceAngleFamily>(std::vector<model::FaceAngles>{
      {{0, 1, 2}, {kPi / 2, kPi / 4, kPi / 4}, k}});
  model::Bar bar;
  bar.nodes = {0, 2};
  bar.rest_length = 1.0;
  bar.law = {elements::BarLawKind::Linear, 1e6};
  auto bars = std::make_shared<model::BarFamily>(std::vector<model::Bar>{bar});
  std::vector<std::uint8_t> fixed(9, 1);
  fixed[6] = fixed[7] = 0;  // c moves in the plane
  const model::Model m(X, fixed, {bars, faces});
  VectorX F = VectorX::Zero(9);
  F[6] = 1.5 * k * delta / std::cos(delta);
  const auto path = solvers::solve_force_control(m, F, 4);
  ASSERT_TRUE(path.completed) << path.message;
  const VectorX& u = path.steps.back().displacement;
  // Within 1e-6: the bar's stretch (1e-7) and Newton's tolerance (1e-6 mm on the last
  // correction, which leaves ~1e-12) are below it; a wrong term would be O(delta).
  EXPECT_NEAR(u[6], std::sin(delta), 1e-6);
  EXPECT_NEAR(1.0 + u[7], std::cos(delta), 1e-6);
  ASSERT_EQ(path.families.back(), "face_angles");
  EXPECT_NEAR(path.steps.back().energies[path.families.size() - 1], 0.75 * k * delta * delta, 1e-6);
  const auto state = assembly::element_state(m, u);
  EXPECT_NEAR(state["face_angle_change"][0], delta, 1e-6);
}

TEST(FaceAngleFamily, RefusesBadData) {
  NodeMatrix X(3, 3);
  X << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  auto make = [&](model::FaceAngles f, const NodeMatrix& nodes) {
    return model::Model(nodes, std::vector<std::uint8_t>(9, 0),
                        {std::make_shared<model::FaceAngleFamily>(std::vector<model::FaceAngles>{f})});
  };
  const std::array<double, 3> rest = {kPi / 2, kPi / 4, kPi / 4};
  EXPECT_THROW(make({{0, 1, 3}, rest, 1.0}, X), std::invalid_argument);
  EXPECT_THROW(make({{0, 1, 1}, rest, 1.0}, X), std::invalid_argument);
  EXPECT_THROW(make({{0, 1, 2}, rest, -1.0}, X), std::invalid_argument);
  EXPECT_THROW(make({{0, 1, 2}, {kPi, 0.0, 0.0}, 1.0}, X), std::invalid_argument);
  NodeMatrix line(3, 3);
  line << 0, 0, 0, 1, 0, 0, 2, 0, 0;
  try {
    make({{0, 1, 2}, rest, 1.0}, line);
    ADD_FAILURE() << "a collinear triangle was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("degenerate"), std::string::npos) << e.what();
  }
}

