// The zero-length anchor spring (elements/anchor_spring.hpp) and its family
// (model/spring_family.hpp): the kernel against finite differences and its closed form, and
// the family through a model, the assembly and a solve.
//
// Tolerances: the energy is quadratic, so central differences are exact up to rounding
// (~eps |E| / h with h = 1e-4 on O(1) data: ~1e-12); 1e-8 relative leaves room for rounding
// and catches any wrong term (those are O(1) relative).

#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "kresling/assembly/assembler.hpp"
#include "kresling/elements/anchor_spring.hpp"
#include "kresling/model/family_registry.hpp"
#include "kresling/model/model.hpp"
#include "kresling/model/spring_family.hpp"
#include "kresling/solvers/force_control.hpp"

using namespace kresling;

namespace {

constexpr double kStep = 1e-4;
constexpr double kRelTol = 1e-8;

Vector3 random_vector(std::mt19937& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  return {u(rng), u(rng), u(rng)};
}

}  // namespace

TEST(AnchorSpring, GradientAndHessianMatchFiniteDifferences) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    const Vector3 x = random_vector(rng, -2.0, 2.0), a = random_vector(rng, -2.0, 2.0);
    const Vector3 k = random_vector(rng, 0.0, 5.0);
    const auto r = elements::anchor_spring_response(x, a, k);
    Vector3 g_fd;
    Matrix3 h_fd;
    for (int i = 0; i < 3; ++i) {
      Vector3 xp = x, xm = x;
      xp[i] += kStep;
      xm[i] -= kStep;
      const auto rp = elements::anchor_spring_response(xp, a, k);
      const auto rm = elements::anchor_spring_response(xm, a, k);
      g_fd[i] = (rp.energy - rm.energy) / (2 * kStep);
      h_fd.col(i) = (rp.force - rm.force) / (2 * kStep);
    }
    EXPECT_LE((r.force - g_fd).norm(), kRelTol * std::max(1.0, r.force.norm())) << trial;
    EXPECT_LE((r.stiffness - h_fd).norm(), kRelTol * std::max(1.0, r.stiffness.norm())) << trial;
  }
}

TEST(AnchorSpring, ClosedForm) {
  const Vector3 k(1.0, 2.0, 3.0), a(1.0, -1.0, 0.5), x(2.0, 1.0, 0.0);
  const auto r = elements::anchor_spring_response(x, a, k);
  EXPECT_DOUBLE_EQ(r.energy, 0.5 * (1.0 * 1.0 + 2.0 * 4.0 + 3.0 * 0.25));
  EXPECT_EQ(r.force, Vector3(1.0, 4.0, -1.5));
  EXPECT_EQ(r.stiffness, Matrix3(k.asDiagonal()));
  // At its anchor the spring stores nothing and pulls nothing, whatever its stiffness.
  const auto rest = elements::anchor_spring_response(a, a, k);
  EXPECT_EQ(rest.energy, 0.0);
  EXPECT_EQ(rest.force, Vector3::Zero());
}

TEST(SpringFamily, IsRegisteredAndRoundTripsItsTable) {
  const auto& kind = model::family_kind("springs");
  model::SpringFamily springs({{2, Vector3(1.0, 2.0, 3.0), Vector3(0.0, 0.5, 1.0)}});
  const auto rebuilt = kind.from_table(springs.table());
  EXPECT_EQ(rebuilt->table().at("stiffness").reals, springs.table().at("stiffness").reals);
  EXPECT_EQ(rebuilt->table().at("anchor").reals, springs.table().at("anchor").reals);
  EXPECT_EQ(rebuilt->element_dofs(0), (std::vector<Index>{6, 7, 8}));
}

TEST(SpringFamily, ANodeOnSpringsDeflectsByForceOverStiffness) {
  // One node on three springs to its own position, loaded by F: u = F / k per axis (the
  // springs are linear, so force control reaches it in one step).
  NodeMatrix X(1, 3);
  X << 1.0, 2.0, 3.0;
  const Vector3 k(10.0, 20.0, 40.0);
  auto springs = std::make_shared<model::SpringFamily>(
      std::vector<model::AnchorSpring>{{0, k, Vector3(1.0, 2.0, 3.0)}});
  const model::Model m(X, std::vector<std::uint8_t>(3, 0), {springs});
  ASSERT_NE(m.family("springs"), nullptr);
  EXPECT_EQ(m.families().back()->name(), std::string("springs"));
  const VectorX F = Vector3(1.0, -2.0, 4.0);
  const auto path = solvers::solve_force_control(m, F, 1);
  ASSERT_TRUE(path.completed) << path.message;
  const VectorX u = path.steps.back().displacement;
  EXPECT_NEAR(u[0], 0.1, 1e-12);
  EXPECT_NEAR(u[1], -0.1, 1e-12);
  EXPECT_NEAR(u[2], 0.1, 1e-12);
  // The springs' energy is reported as their own family's, F.u / 2 at equilibrium.
  ASSERT_EQ(path.families.back(), "springs");
  EXPECT_NEAR(path.steps.back().energies[3], 0.5 * F.dot(u), 1e-12);
  const auto state = assembly::element_state(m, u);
  EXPECT_NEAR(state["spring_force"][0], F.norm(), 1e-12);
}

TEST(SpringFamily, RefusesBadData) {
  NodeMatrix X(1, 3);
  X << 0.0, 0.0, 0.0;
  auto make = [&](model::AnchorSpring s) {
    return model::Model(X, std::vector<std::uint8_t>(3, 0),
                        {std::make_shared<model::SpringFamily>(std::vector<model::AnchorSpring>{s})});
  };
  EXPECT_THROW(make({1, Vector3::Ones(), Vector3::Zero()}), std::invalid_argument);
  EXPECT_THROW(make({0, Vector3(1.0, -1.0, 1.0), Vector3::Zero()}), std::invalid_argument);
  EXPECT_THROW(make({0, Vector3::Ones(), Vector3(0.0, NAN, 0.0)}), std::invalid_argument);
  try {
    make({0, Vector3(1.0, -1.0, 1.0), Vector3::Zero()});
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("spring 0 (nodes 0): stiffness"), std::string::npos)
        << e.what();
  }
}
