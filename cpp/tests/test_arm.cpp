// The arm as a model: topology, guides, tendons, stress-free as built, bad input.

#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "kresling/assembly/assembler.hpp"
#include "kresling/geometry/design.hpp"
#include "kresling/model/arm.hpp"

using namespace kresling;

namespace {

geometry::Design optimum() { return geometry::Design(10, 30.0, 0.9, 15.0); }

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(ArmModel, ConfigurationStrings) {
  EXPECT_EQ(model::parse_configuration("010"), (std::vector<int>{0, 1, 0}));
  EXPECT_EQ(model::parse_configuration("1", 1), (std::vector<int>{1}));
  EXPECT_EQ(model::configuration_string({1, 1, 0}), "110");
  EXPECT_NE(error_of([] { model::parse_configuration("01a"); }).find("configuration = '01a'"),
            std::string::npos);
  EXPECT_NE(error_of([] { model::parse_configuration(""); }).find("configuration"), std::string::npos);
  EXPECT_NE(error_of([] { model::parse_configuration("01", 3); }).find("modules = 3"),
            std::string::npos);
}

TEST(ArmModel, StressFreeAsBuiltInEveryConfigurationWithTheTipAtTheSumOfHeights) {
  const auto design = optimum();
  const double Le = design.height(geometry::State::Extended);
  const double Lc = design.height(geometry::State::Contracted);
  for (const std::string config : {"0", "1", "01", "10", "011", "110", "000", "111"}) {
    const auto arm = model::build_arm(design, model::parse_configuration(config));
    const int m = static_cast<int>(config.size());
    ASSERT_EQ(arm.modules, m);
    double height = 0.0;
    for (char c : config) height += 2.0 * (c == '1' ? Le : Lc);
    const Vector3 tip = arm.model.nodes().row(arm.tip_node());
    EXPECT_NEAR(tip.z(), height, 1e-9) << config;
    EXPECT_NEAR(tip.head<2>().norm(), 0.0, 1e-9) << config;
    // Stress-free: zero internal force and energy at u = 0, tendons just taut (tension 0).
    const model::Model& mm = arm.model;
    assembly::Assembler a(mm, assembly::all_dofs(mm.num_dofs()), 0.0);
    VectorX f;
    const auto e = a.assemble(VectorX::Zero(mm.num_dofs()), f, false);
    EXPECT_LT(f.cwiseAbs().maxCoeff(), 1e-9) << config;
    EXPECT_LT(e.total(), 1e-12) << config;
    const auto s = assembly::element_state(mm, VectorX::Zero(mm.num_dofs()));
    ASSERT_EQ(s["cable_tension"].size(), 3);
    for (int t = 0; t < 3; ++t) {
      EXPECT_EQ(s["cable_tension"][t], 0.0);
      EXPECT_NEAR(s["cable_length"][t], height, 1e-9) << config;  // straight, vertical
      EXPECT_NEAR(arm.slack_length[t], height, 1e-9);
    }
  }
}

TEST(ArmModel, GuidesCarryTheHolesAtTheTendonRadiusAndTheBaseIsFixed) {
  const auto arm = model::build_arm(optimum(), {1, 0});
  const auto& X = arm.model.nodes();
  ASSERT_EQ(arm.holes.size(), 3u);
  for (int g = 0; g <= 2; ++g) {
    const double z = arm.level_height[arm.guide_level(g)];
    for (int t = 0; t < 3; ++t) {
      const Vector3 h = X.row(arm.holes[g][t]);
      const double angle = 2.0 * 3.14159265358979323846 * t / 3.0;
      EXPECT_NEAR(h.x(), 32.0 * std::cos(angle), 1e-12);
      EXPECT_NEAR(h.y(), 32.0 * std::sin(angle), 1e-12);
      EXPECT_NEAR(h.z(), z, 1e-12);
    }
    EXPECT_NEAR(arm.level_angle[arm.guide_level(g)], 0.0, 1e-12);  // twists cancel per module
  }
  const auto& fixed = arm.model.fixed();
  for (int j = 0; j <= arm.n; ++j) EXPECT_TRUE(fixed[3 * arm.node(0, j) + 2]);
  for (Index h : arm.holes[0]) EXPECT_TRUE(fixed[3 * h] && fixed[3 * h + 1] && fixed[3 * h + 2]);
  for (Index i = 3 * arm.node(1, 0); i < arm.model.num_dofs(); ++i) {
    bool base_hole = false;
    for (Index h : arm.holes[0]) base_hole |= (i / 3 == h);
    if (!base_hole) EXPECT_FALSE(fixed[i]) << i;
  }
  // Tendon t runs through hole t of every guide, base first.
  ASSERT_EQ(arm.model.cables().size(), 3u);
  for (int t = 0; t < 3; ++t) {
    const auto& c = arm.model.cables()[t];
    ASSERT_EQ(c.nodes.size(), 3u);
    for (int g = 0; g <= 2; ++g) EXPECT_EQ(c.nodes[g], arm.holes[g][t]);
    EXPECT_EQ(c.stiffness, 500.0);
  }
  // Guide spokes are stiff, the mid level's keep the thesis's 10 kf.
  int stiff = 0, mid = 0;
  for (std::size_t i = 0; i < arm.cell_hinges; ++i) {
    if (arm.hinge_family[i] != model::EdgeFamily::PolygonSpoke) continue;
    const auto& h = arm.model.hinges()[i];
    const int level = static_cast<int>(h.nodes[0] / (arm.n + 1));
    if (level % 2 == 0) {
      EXPECT_DOUBLE_EQ(h.stiffness, 1e4 * 0.047);
      ++stiff;
    } else {
      EXPECT_DOUBLE_EQ(h.stiffness, 10 * 0.047);
      ++mid;
    }
  }
  EXPECT_EQ(stiff, 3 * arm.n);
  EXPECT_EQ(mid, 2 * arm.n);
}

TEST(ArmModel, BadInputNamesTheParameter) {
  const auto design = optimum();
  model::ArmParameters p;
  p.tendon_radius = 45.0;  // outside the 40 mm guide
  EXPECT_NE(error_of([&] { model::build_arm(design, {1}, p); }).find("tendon_radius = 45"),
            std::string::npos);
  p.tendon_radius = 0.0;
  EXPECT_NE(error_of([&] { model::build_arm(design, {1}, p); }).find("tendon_radius"),
            std::string::npos);
  p = {};
  p.guide_radius = 20.0;
  EXPECT_NE(error_of([&] { model::build_arm(design, {1}, p); }).find("guide_radius"),
            std::string::npos);
  p = {};
  p.tendon_stiffness = -1.0;
  EXPECT_NE(error_of([&] { model::build_arm(design, {1}, p); }).find("tendon_stiffness"),
            std::string::npos);
  EXPECT_NE(error_of([&] { model::build_arm(design, {}); }).find("states"), std::string::npos);
  EXPECT_NE(error_of([&] { model::build_arm(design, {2}); }).find("states[0]"), std::string::npos);
  // A hole on a perimeter vertex is that vertex.
  p = {};
  p.tendon_radius = 30.0;
  const auto arm = model::build_arm(design, {1}, p);
  EXPECT_EQ(arm.holes[1][0], arm.node(2, 0));
  EXPECT_NE(arm.holes[1][1], arm.node(2, 3));
}
