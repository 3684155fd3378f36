// The sliding-cable kernel against finite differences, rigid motions, the slack/taut switch,
// the linear bar it must equal when straight, and the frictionless guide's equal tensions.
//
// Tolerances as in test_elements.cpp: central differences with h = 1e-6 on O(1)-O(10)
// geometry are accurate to ~1e-9 of the derivative's scale, so 1e-6 relative leaves
// headroom and still catches any wrong term (those are O(1) relative).

#include <cmath>
#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "finite_differences.hpp"
#include "kresling/elements/bar.hpp"
#include "kresling/elements/cable.hpp"

using namespace kresling;
using namespace kresling::elements;

namespace {

constexpr double kStep = 1e-6;
constexpr double kRelTol = 1e-6;

CablePoints random_cable(std::mt19937& rng, int nodes, double scale = 10.0) {
  std::uniform_real_distribution<double> u(-scale, scale);
  CablePoints x(nodes, 3);
  for (int i = 0; i < nodes; ++i) x.row(i) << u(rng), u(rng), u(rng);
  return x;
}

CablePoints unflatten(const VectorX& v) {
  return Eigen::Map<const CablePoints>(v.data(), v.size() / 3, 3);
}

VectorX flatten(const CablePoints& x) { return Eigen::Map<const VectorX>(x.data(), x.size()); }

// The rest length that stretches the cable's path by `stretch` (l / L).
double rest_for(const CablePoints& x, double stretch) { return cable_length(x) / stretch; }

}  // namespace

TEST(CableKernel, LengthGradientAndHessianMatchFiniteDifferences) {
  std::mt19937 rng(11);
  for (int nodes : {2, 3, 5}) {
    const CablePoints x = random_cable(rng, nodes);
    const VectorX v = flatten(x);
    const VectorX g = cable_length_gradient(x);
    const Eigen::MatrixXd H = cable_length_hessian(x);
    VectorX g_fd(v.size());
    Eigen::MatrixXd H_fd(v.size(), v.size());
    for (Index i = 0; i < v.size(); ++i) {
      VectorX p = v, m = v;
      p[i] += kStep, m[i] -= kStep;
      g_fd[i] = (cable_length(unflatten(p)) - cable_length(unflatten(m))) / (2 * kStep);
      H_fd.col(i) = (cable_length_gradient(unflatten(p)) - cable_length_gradient(unflatten(m))) /
                    (2 * kStep);
    }
    EXPECT_LT((g - g_fd).norm(), kRelTol * g.norm()) << nodes << " nodes";
    EXPECT_LT((H - H_fd).norm(), kRelTol * H.norm()) << nodes << " nodes";
    EXPECT_LT((H - H.transpose()).norm(), 1e-14 * H.norm());
  }
}

TEST(CableKernel, ForceAndTangentMatchFiniteDifferencesWhenTaut) {
  std::mt19937 rng(12);
  const double EA = 250.0;
  for (int nodes : {2, 3, 4, 6}) {
    const CablePoints x = random_cable(rng, nodes);
    const double L = rest_for(x, 1.05);  // 5 % stretch: taut
    const CableResponse r = cable_response(x, EA, L);
    ASSERT_TRUE(r.taut);
    const VectorX v = flatten(x);
    VectorX f_fd(v.size());
    Eigen::MatrixXd K_fd(v.size(), v.size());
    for (Index i = 0; i < v.size(); ++i) {
      VectorX p = v, m = v;
      p[i] += kStep, m[i] -= kStep;
      const CableResponse rp = cable_response(unflatten(p), EA, L);
      const CableResponse rm = cable_response(unflatten(m), EA, L);
      f_fd[i] = (rp.energy - rm.energy) / (2 * kStep);
      K_fd.col(i) = (rp.force - rm.force) / (2 * kStep);
    }
    EXPECT_LT((r.force - f_fd).norm(), kRelTol * r.force.norm()) << nodes << " nodes";
    EXPECT_LT((r.stiffness - K_fd).norm(), kRelTol * r.stiffness.norm()) << nodes << " nodes";
    EXPECT_LT((r.stiffness - r.stiffness.transpose()).norm(), 1e-12 * r.stiffness.norm());
    // The force without the tangent is the same.
    const CableResponse no_k = cable_response(x, EA, L, false);
    EXPECT_EQ(no_k.stiffness.size(), 0);
    EXPECT_LT((no_k.force - r.force).norm(), 1e-14 * r.force.norm());
  }
}

TEST(CableKernel, RigidMotionsLeaveTheResponseUnchanged) {
  std::mt19937 rng(13);
  const CablePoints x = random_cable(rng, 5);
  const double EA = 80.0, L = rest_for(x, 1.02);
  const CableResponse r = cable_response(x, EA, L);
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(0.7, Vector3(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  const Vector3 t(3.0, -1.0, 7.0);
  CablePoints y = x;
  for (Index i = 0; i < x.rows(); ++i) y.row(i) = (Q * x.row(i).transpose() + t).transpose();
  const CableResponse ry = cable_response(y, EA, L);
  EXPECT_NEAR(ry.energy, r.energy, 1e-12 * r.energy);
  EXPECT_NEAR(ry.tension, r.tension, 1e-12 * r.tension);
  // Forces turn with the cable; they are self-equilibrated (no net force, no net moment).
  Vector3 sum = Vector3::Zero(), moment = Vector3::Zero();
  for (Index i = 0; i < x.rows(); ++i) {
    const Vector3 fi = r.force.segment<3>(3 * i);
    EXPECT_LT((ry.force.segment<3>(3 * i) - Q * fi).norm(), 1e-12 * r.force.norm());
    sum += fi;
    moment += x.row(i).transpose().cross(fi);
  }
  EXPECT_LT(sum.norm(), 1e-12 * r.force.norm());
  EXPECT_LT(moment.norm(), 1e-12 * r.force.norm() * 10.0);
  // The tangent has no stiffness against a translation; against an infinitesimal rotation
  // w x x it returns w x f (the stress's rotation), as any prestressed element must.
  const Vector3 w(0.3, -0.2, 0.9);
  VectorX translation(3 * x.rows()), rotation(3 * x.rows()), turned(3 * x.rows());
  for (Index i = 0; i < x.rows(); ++i) {
    translation.segment<3>(3 * i) = t;
    rotation.segment<3>(3 * i) = w.cross(Vector3(x.row(i).transpose()));
    turned.segment<3>(3 * i) = w.cross(Vector3(r.force.segment<3>(3 * i)));
  }
  EXPECT_LT((r.stiffness * translation).norm(), 1e-10 * r.stiffness.norm());
  EXPECT_LT((r.stiffness * rotation - turned).norm(), 1e-10 * r.stiffness.norm() * 10.0);
}

TEST(CableKernel, SlackCarriesNothingAndTautIsContinuousAtTheSwitch) {
  std::mt19937 rng(14);
  const CablePoints x = random_cable(rng, 4);
  const double EA = 100.0, l = cable_length(x);
  for (double L : {1.01 * l, 1.5 * l, l}) {  // longer than the path, and exactly its length
    const CableResponse r = cable_response(x, EA, L);
    EXPECT_FALSE(r.taut) << L;
    EXPECT_EQ(r.energy, 0.0);
    EXPECT_EQ(r.tension, 0.0);
    EXPECT_EQ(r.force.norm(), 0.0);
    EXPECT_EQ(r.stiffness.norm(), 0.0);
    EXPECT_EQ(r.force.size(), 12);
    EXPECT_EQ(r.stiffness.rows(), 12);
  }
  // Just taut: energy ~ E^2 and force ~ E vanish continuously at the switch.
  const CableResponse just = cable_response(x, EA, l / (1.0 + 1e-9));
  EXPECT_TRUE(just.taut);
  EXPECT_LT(just.energy, 1e-12);
  EXPECT_LT(just.force.norm(), 1e-5);
  EXPECT_NEAR(just.tension, EA * 1e-9, 1e-12);
  // Taut: the tension is the linear law's EA E l / L.
  const double L = l / 1.1;
  const CableResponse taut = cable_response(x, EA, L);
  const double E = (l * l - L * L) / (2 * L * L);
  EXPECT_NEAR(taut.tension, EA * E * l / L, 1e-12 * taut.tension);
  EXPECT_NEAR(taut.energy, 0.5 * EA * L * E * E, 1e-12 * taut.energy);
}

TEST(CableKernel, StraightTautCableEqualsALinearBarOfTheSameStiffness) {
  const double EA = 470.0;
  const Vector3 a(1.0, 2.0, -1.0), b(4.0, -2.0, 11.0);
  CablePoints x(2, 3);
  x.row(0) = a.transpose();
  x.row(1) = b.transpose();
  const double L = 0.97 * (b - a).norm();
  const CableResponse c = cable_response(x, EA, L);
  const BarResponse bar = bar_response(a, b, 1.0, L, BarLaw{BarLawKind::Linear, EA});
  EXPECT_NEAR(c.energy, bar.energy, 1e-12 * bar.energy);
  EXPECT_NEAR(c.strain, bar.strain, 1e-15);
  EXPECT_LT((c.force - bar.force).norm(), 1e-12 * bar.force.norm());
  EXPECT_LT((c.stiffness - Eigen::MatrixXd(bar.stiffness)).norm(), 1e-12 * bar.stiffness.norm());
  // The bar's reported axial force A S(E) l / L is the cable's tension.
  const double s = (b - a).norm() / L;
  EXPECT_NEAR(c.tension, EA * bar.strain * s, 1e-12 * c.tension);

  // A straight cable through collinear guides: the ends see the same bar of the full length.
  CablePoints y(4, 3);
  y.row(0) = a.transpose();
  y.row(1) = (a + 0.2 * (b - a)).transpose();
  y.row(2) = (a + 0.7 * (b - a)).transpose();
  y.row(3) = b.transpose();
  const CableResponse through = cable_response(y, EA, L);
  EXPECT_NEAR(through.energy, bar.energy, 1e-12 * bar.energy);
  EXPECT_LT((through.force.head<3>() - bar.force.head<3>()).norm(), 1e-12 * bar.force.norm());
  EXPECT_LT((through.force.tail<3>() - bar.force.tail<3>()).norm(), 1e-12 * bar.force.norm());
  // The guides on the straight line carry no force.
  EXPECT_LT(through.force.segment<6>(3).norm(), 1e-12 * bar.force.norm());
}

TEST(CableKernel, FrictionlessGuideCarriesEqualTensionOnBothSides) {
  // Over a guide at the apex of a bend: the pull of each side on the guide is T along that
  // side, and both anchors are pulled with the same T.
  const double EA = 300.0;
  CablePoints x(3, 3);
  x.row(0) << 0.0, 0.0, 0.0;
  x.row(1) << 3.0, 4.0, 0.0;   // guide; first side of length 5
  x.row(2) << 3.0, 4.0, 12.0;  // second side of length 12, at right angles
  const CableResponse r = cable_response(x, EA, 15.0);
  ASSERT_TRUE(r.taut);
  const double T = r.tension;
  const Vector3 f0 = r.force.segment<3>(0), f1 = r.force.segment<3>(3), f2 = r.force.segment<3>(6);
  EXPECT_NEAR(f0.norm(), T, 1e-12 * T);  // anchor 0 pulled towards the guide with T
  EXPECT_NEAR(f2.norm(), T, 1e-12 * T);  // anchor 2 likewise
  const Vector3 e1 = Vector3(3.0, 4.0, 0.0) / 5.0, e2 = Vector3(0.0, 0.0, 1.0);
  // Internal force = -(force on the node): the guide is pulled along both sides with T.
  EXPECT_LT((f1 - T * (e1 - e2)).norm(), 1e-12 * T);
  EXPECT_NEAR(f1.norm(), std::sqrt(2.0) * T, 1e-12 * T);
  // No friction: moving the guide along the bisector e1 + e2 or out of the plane of the two
  // sides keeps the length to first order, so the guide feels no force in those directions.
  EXPECT_LT(std::abs(f1.dot(e1.cross(e2))), 1e-12 * T);
  EXPECT_LT(std::abs(f1.dot((e1 + e2).normalized())), 1e-12 * T);
}

// ---------------------------------------------------------------------------------------
// Cables in a model and its assembly.

#include "kresling/assembly/assembler.hpp"
#include "kresling/model/model.hpp"

namespace {

// A square frame of four bars in the plane z = 0 with two diagonals, and a cable from corner
// 0 over corners 1 and 2 to corner 3, pulled 4 % shorter than its path (taut).
model::Model cable_frame(double pull = 0.96) {
  NodeMatrix X(5, 3);
  X << 0, 0, 0, 10, 0, 1, 10, 10, 0, 0, 10, 2, 5, 5, 6;
  std::vector<model::Bar> bars;
  const std::vector<std::array<Index, 2>> edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2},
                                                   {1, 3}, {0, 4}, {1, 4}, {2, 4}, {3, 4}};
  for (const auto& e : edges) {
    bars.push_back({e, 1.0, (X.row(e[1]) - X.row(e[0])).norm(), {elements::BarLawKind::Linear, 50.0}});
  }
  model::Cable cable{{0, 1, 2, 3}, 40.0, 0.0};
  CablePoints p(4, 3);
  for (int i = 0; i < 4; ++i) p.row(i) = X.row(cable.nodes[i]);
  cable.rest_length = pull * cable_length(p);
  return model::Model(X, bars, {}, std::vector<std::uint8_t>(15, 0), {cable});
}

}  // namespace

TEST(CableAssembly, ForceAndTangentMatchFiniteDifferences) {
  const model::Model m = cable_frame();
  assembly::Assembler a(m, assembly::all_dofs(m.num_dofs()), 0.0);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  VectorX u(m.num_dofs());
  for (Index i = 0; i < u.size(); ++i) u[i] = jitter(rng);
  VectorX f;
  const auto e = a.assemble(u, f, true);
  EXPECT_GT(e[2], 0.0);
  EXPECT_NEAR(e.total(), e[0] + e[1] + e[2], 1e-15);
  const Eigen::MatrixXd K = Eigen::MatrixXd(a.matrix());
  const double h = 1e-6 * 10.0;
  const auto [f_fd, K_fd] = test::central_differences(
      [&](const VectorX& y) {
        VectorX fy;
        const double energy = a.assemble(y, fy, false).total();
        return std::make_pair(energy, fy);
      },
      u, h);
  EXPECT_LT((f - f_fd).norm(), kRelTol * f.norm());
  EXPECT_LT((K - K_fd).norm(), kRelTol * K.norm());
  // The cable's share of the force is the kernel's, scattered to its nodes.
  const model::Model no_cable(m.nodes(), m.bars(), m.hinges(), m.fixed());
  assembly::Assembler b(no_cable, assembly::all_dofs(m.num_dofs()), 0.0);
  VectorX f_bars;
  b.assemble(u, f_bars, false);
  CablePoints x(4, 3);
  const NodeMatrix xu = m.deformed(u);
  for (int i = 0; i < 4; ++i) x.row(i) = xu.row(i);
  const auto r = cable_response(x, 40.0, m.cables()[0].rest_length, false);
  EXPECT_LT(((f - f_bars).head<12>() - r.force).norm(), 1e-12 * r.force.norm());
  EXPECT_LT((f - f_bars).tail<3>().norm(), 1e-12 * r.force.norm());  // node 4: no cable
}

TEST(CableAssembly, SlackCablesAddNothingAndRestLengthsRebind) {
  const model::Model taut = cable_frame(0.96);
  const model::Model slack = taut.with_cable_rest_lengths({1.2 * taut.cables()[0].rest_length});
  EXPECT_EQ(slack.cables()[0].rest_length, 1.2 * taut.cables()[0].rest_length);
  EXPECT_EQ(taut.cables()[0].rest_length, cable_frame(0.96).cables()[0].rest_length);
  assembly::Assembler a(taut, assembly::all_dofs(taut.num_dofs()), 0.0, assembly::Storage::Lower);
  ASSERT_TRUE(a.same_connectivity(slack));
  const VectorX u = VectorX::Zero(taut.num_dofs());
  VectorX f_taut, f_slack;
  EXPECT_GT(a.assemble(u, f_taut, true)[2], 0.0);  // the cable
  a.rebind(slack);
  const auto e = a.assemble(u, f_slack, true);
  EXPECT_EQ(e[2], 0.0);
  // Built stress-free: with the cable slack, nothing is stressed (to the rounding of the
  // bars' rest lengths, ~1e-15 of their ~50 N forces).
  EXPECT_LT(e[0], 1e-25);
  EXPECT_LT(f_slack.norm(), 1e-12);
  EXPECT_GT(f_taut.norm(), 1.0);
  // A model with other cables (or none) has another connectivity.
  const model::Model none(taut.nodes(), taut.bars(), taut.hinges(), taut.fixed());
  EXPECT_FALSE(a.same_connectivity(none));
  model::Model other(taut.nodes(), taut.bars(), taut.hinges(), taut.fixed(),
                     {{{0, 1, 3}, 40.0, 25.0}});
  EXPECT_FALSE(a.same_connectivity(other));
  // Element state: the cable's length, tension and energy.
  const auto s = assembly::element_state(taut, u);
  ASSERT_EQ(s["cable_tension"].size(), 1);
  CablePoints x(4, 3);
  for (int i = 0; i < 4; ++i) x.row(i) = taut.nodes().row(i);
  const auto r = cable_response(x, 40.0, taut.cables()[0].rest_length);
  EXPECT_NEAR(s["cable_length"][0], r.length, 1e-12);
  EXPECT_NEAR(s["cable_tension"][0], r.tension, 1e-12);
  EXPECT_NEAR(s["cable_energy"][0], r.energy, 1e-12);
  EXPECT_EQ(assembly::element_state(slack, u)["cable_tension"][0], 0.0);
}

TEST(CableAssembly, ModelRejectsBadCablesNamingThem) {
  const model::Model m = cable_frame();
  auto build = [&](model::Cable c) {
    return model::Model(m.nodes(), m.bars(), m.hinges(), m.fixed(), {m.cables()[0], c});
  };
  auto message = [&](model::Cable c) {
    try {
      build(c);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({{0}, 1.0, 1.0}).find("cable 1: has 1 nodes"), std::string::npos);
  EXPECT_NE(message({{0, 7}, 1.0, 1.0}).find("cable 1 (nodes 0, 7): node 7 is out of range"),
            std::string::npos);
  EXPECT_NE(message({{0, 1, 0}, 1.0, 1.0}).find("a node appears twice"), std::string::npos);
  EXPECT_NE(message({{0, 1}, 0.0, 1.0}).find("cable 1 (nodes 0, 1): stiffness"), std::string::npos);
  EXPECT_NE(message({{0, 1}, 1.0, -1.0}).find("rest length"), std::string::npos);
  EXPECT_NO_THROW(build({{0, 1}, 1.0, 1.0}));
  NodeMatrix X = m.nodes();
  X.row(4) = X.row(1);
  EXPECT_THROW(model::Model(X, {}, {}, m.fixed(), {{{0, 1, 4}, 1.0, 1.0}}), std::invalid_argument);
  EXPECT_THROW(m.with_cable_rest_lengths({}), std::invalid_argument);
  EXPECT_THROW(m.with_cable_rest_lengths({0.0}), std::invalid_argument);
}
