// Model validation (bad input names the element and the problem) and the topology builder
// (panels to bars and hinges, as MERLIN2 builds them).

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "kresling/model/model.hpp"
#include "kresling/model/topology.hpp"

using namespace kresling;
using model::Bar;
using model::Hinge;
using model::PanelSplit;
using Kind = elements::SpringLawKind;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kPi = 3.14159265358979323846;

NodeMatrix square() {
  NodeMatrix X(4, 3);
  X << 0, 0, 0, 1, 0, 0, 1, 1, 0.2, 0, 1, 0;
  return X;
}

// The square folded along 0-2: five bars, one hinge; each test breaks one thing.
struct Parts {
  NodeMatrix X = square();
  std::vector<Bar> bars;
  std::vector<Hinge> hinges;
  std::vector<std::uint8_t> fixed = std::vector<std::uint8_t>(12, 0);

  Parts() {
    const elements::BarLaw law{elements::BarLawKind::Linear, 100.0};
    for (auto e : {std::array<Index, 2>{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}}) {
      bars.push_back({e, 1.0, (X.row(e[1]) - X.row(e[0])).norm(), law});
    }
    const elements::SpringLaw linear{Kind::Linear, 0, 0};
    hinges.push_back({{0, 2, 1, 3}, 1.0, 3.0, std::sqrt(2.0), linear});
  }
  model::Model build() const { return model::Model(X, bars, hinges, fixed); }
};

// `make` must throw std::invalid_argument with `expected` in its message; any other
// exception escapes and fails the test too.
template <typename Make>
void expect_invalid(Make&& make, const std::string& expected) {
  try {
    make();
    ADD_FAILURE() << "no exception; expected one saying: " << expected;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos)
        << "message: " << e.what() << "\nexpected it to contain: " << expected;
  }
}

template <typename Change>
void expect_invalid_model(Change&& change, const std::string& expected) {
  Parts p;
  change(p);
  expect_invalid([&] { p.build(); }, expected);
}

std::size_t count_bars(const model::Topology& t, Index a, Index b) {
  return std::count(t.bars.begin(), t.bars.end(), std::array<Index, 2>{a, b});
}
std::size_t count_hinges_on(const model::Topology& t, Index a, Index b) {
  return std::count_if(t.hinges.begin(), t.hinges.end(),
                       [&](const auto& h) { return h[0] == a && h[1] == b; });
}

}  // namespace

TEST(Model, ValidModelBuilds) {
  const model::Model m = Parts().build();
  EXPECT_EQ(m.num_nodes(), 4);
  EXPECT_EQ(m.num_dofs(), 12);
  EXPECT_EQ(m.bars().size(), 5u);
}

TEST(Model, InvalidElementsAreNamed) {
  const std::string hinge = "hinge 0 (nodes 0, 2, 1, 3): ";
  expect_invalid_model([](Parts& p) { p.X.row(1) = p.X.row(0); },
                       "bar 0 (nodes 0, 1): zero length");
  expect_invalid_model([](Parts& p) { p.X.row(3) << 2, 2, 0.4; },  // on the line 0-2
                       hinge + "wing node 3 lies on the axis line");
  expect_invalid_model([](Parts& p) { p.bars[1].nodes = {1, 7}; },
                       "bar 1 (nodes 1, 7): node 7 is out of range [0, 4)");
  expect_invalid_model([](Parts& p) { p.hinges[0].nodes = {0, 2, 1, -1}; },
                       "hinge 0 (nodes 0, 2, 1, -1): node -1 is out of range [0, 4)");
  expect_invalid_model([](Parts& p) { p.bars[2].nodes = {3, 3}; },
                       "bar 2 (nodes 3, 3): a node appears twice");
  expect_invalid_model([](Parts& p) { p.hinges[0].stiffness = -0.5; },
                       hinge + "stiffness = -0.5 is invalid: must be >= 0");
  expect_invalid_model([](Parts& p) { p.bars[3].area = -1.0; },
                       "bar 3 (nodes 3, 0): area = -1 is invalid: must be > 0");
  expect_invalid_model([](Parts& p) { p.bars[4].law.modulus = -100.0; },
                       "bar 4 (nodes 0, 2): modulus = -100 is invalid: must be > 0");
  expect_invalid_model([](Parts& p) { p.hinges[0].rest_angle = 7.0; },
                       hinge + "rest angle = 7 is invalid: must be in [0, 2 pi)");
  expect_invalid_model([](Parts& p) { p.hinges[0].law = {Kind::EnhancedLinear, 0.2, 0.1}; },
                       hinge + "spring limits (0.2, 0.1) are invalid");
  expect_invalid_model([](Parts& p) { p.fixed.pop_back(); }, "fixed: has 11 entries");
}

TEST(Model, NaNIsRejectedWhereverItIs) {
  const std::string hinge = "hinge 0 (nodes 0, 2, 1, 3): ";
  expect_invalid_model([](Parts& p) { p.X(2, 1) = kNaN; },
                       "node 2: coordinate 1 = nan is not finite");
  expect_invalid_model([](Parts& p) { p.bars[0].law.modulus = kNaN; },
                       "bar 0 (nodes 0, 1): modulus = nan is invalid: must be a finite number");
  expect_invalid_model([](Parts& p) { p.bars[1].rest_length = kNaN; },
                       "bar 1 (nodes 1, 2): rest length = nan is invalid: must be a finite number");
  expect_invalid_model([](Parts& p) { p.hinges[0].stiffness = kNaN; },
                       hinge + "stiffness = nan is invalid: must be a finite number");
  expect_invalid_model([](Parts& p) { p.hinges[0].rest_angle = kNaN; },
                       hinge + "rest angle = nan is invalid: must be a finite number");
}

TEST(Model, HingeGeometryCheckNamesTheGivenIndex) {
  NodeMatrix X = square();
  X.row(1) << 0.5, 0.5, 0.1;  // on the line 0-2
  expect_invalid([&] { model::check_hinge_geometry(X, {0, 2, 1, 3}, 5); },
                 "hinge 5 (nodes 0, 2, 1, 3): wing node 1 lies on the axis line");
  EXPECT_NO_THROW(model::check_hinge_geometry(square(), {0, 2, 1, 3}, 5));
}

TEST(Topology, QuadSplitsOnItsShorterDiagonal) {
  NodeMatrix X = square();
  X.row(2) << 1.5, 1.5, 0;  // diagonal 1-3 (1.41) is shorter than 0-2 (2.12)
  auto t = model::build_topology(X, {{0, 1, 2, 3}}, PanelSplit::N4B5);
  EXPECT_EQ(t.triangles, (std::vector<std::array<Index, 3>>{{0, 1, 3}, {1, 2, 3}}));
  EXPECT_EQ(t.hinges, (std::vector<std::array<Index, 4>>{{1, 3, 0, 2}}));
  EXPECT_EQ(t.hinge_is_bend, std::vector<std::uint8_t>{1});
  EXPECT_EQ(t.bars.size(), 5u);  // N4B5: four edges and the diagonal
  EXPECT_EQ(count_bars(t, 1, 3), 1u);

  X.row(2) << 0.6, 0.6, 0;  // now 0-2 (0.85) is the shorter one
  t = model::build_topology(X, {{0, 1, 2, 3}}, PanelSplit::N4B5);
  EXPECT_EQ(t.hinges, (std::vector<std::array<Index, 4>>{{0, 2, 1, 3}}));
  EXPECT_EQ(count_bars(t, 0, 2), 1u);
  EXPECT_EQ(t.nodes.rows(), 4);
}

TEST(Topology, N5B8AddsACentreNode) {
  const auto t = model::build_topology(square(), {{0, 1, 2, 3}}, PanelSplit::N5B8);
  ASSERT_EQ(t.nodes.rows(), 5);
  EXPECT_LE((t.nodes.row(4) - square().colwise().mean()).norm(), 1e-15);  // the vertex mean
  EXPECT_EQ(t.triangles.size(), 4u);
  EXPECT_EQ(t.bars.size(), 8u);  // four edges, four spokes
  ASSERT_EQ(t.hinges.size(), 4u);
  for (const auto& h : t.hinges) EXPECT_EQ(h[1], 4);  // every hinge on a spoke
  EXPECT_EQ(std::count(t.hinge_is_bend.begin(), t.hinge_is_bend.end(), 1), 4);
}

TEST(Topology, HexagonSplitsIntoTrianglesEitherWay) {
  NodeMatrix X(6, 3);
  for (int i = 0; i < 6; ++i) X.row(i) << std::cos(kPi * i / 3), std::sin(kPi * i / 3), 0;
  const std::vector<std::vector<Index>> panel = {{0, 1, 2, 3, 4, 5}};
  const auto split = model::build_topology(X, panel, PanelSplit::N4B5);
  EXPECT_EQ(split.triangles.size(), 4u);
  EXPECT_EQ(split.bars.size(), 9u);  // six edges, three diagonals
  ASSERT_EQ(split.hinges.size(), 3u);
  for (const auto& h : split.hinges) {
    EXPECT_GT((X.row(h[1]) - X.row(h[0])).norm(), 1.5);  // a diagonal, never an edge (1.0)
    EXPECT_LT(h[0], h[1]);
  }
  const auto fan = model::build_topology(X, panel, PanelSplit::N5B8);
  EXPECT_EQ(fan.nodes.rows(), 7);
  EXPECT_EQ(fan.triangles.size(), 6u);
  EXPECT_EQ(fan.bars.size(), 12u);
  EXPECT_EQ(fan.hinges.size(), 6u);
  for (const auto& tri : fan.triangles) EXPECT_TRUE(std::is_sorted(tri.begin(), tri.end()));
  EXPECT_TRUE(std::is_sorted(fan.triangles.begin(), fan.triangles.end()));
}

TEST(Topology, SharedEdgesWithAndWithoutDuplicates) {
  // Two panels on one edge: a fold hinge and a bar, whichever the mode.
  for (bool duplicate : {true, false}) {
    const auto t =
        model::build_topology(square(), {{0, 1, 2}, {0, 2, 3}}, PanelSplit::N4B5, duplicate);
    EXPECT_EQ(t.bars.size(), 5u);
    EXPECT_EQ(t.hinges, (std::vector<std::array<Index, 4>>{{0, 2, 1, 3}}));
    EXPECT_EQ(t.hinge_is_bend, std::vector<std::uint8_t>{0});
  }
  // Edge 0-1 in three triangles: MERLIN2 puts a bar and a hinge on each pair (3 and 3); the
  // de-duplicated topology one bar and hinges only between neighbours around the edge.
  NodeMatrix X(5, 3);
  X << 0, 0, 0, 1, 0, 0, 0.5, 1, 0, 0.5, -1, 0, 0.5, 0, 1;
  const std::vector<std::vector<Index>> panels = {{0, 1, 2}, {0, 1, 3}, {0, 1, 4}};
  const auto dup = model::build_topology(X, panels, PanelSplit::N4B5, true);
  EXPECT_EQ(count_bars(dup, 0, 1), 3u);
  EXPECT_EQ(count_hinges_on(dup, 0, 1), 3u);
  EXPECT_EQ(dup.bars.size(), 9u);  // and the six boundary edges
  const auto dedup = model::build_topology(X, panels, PanelSplit::N4B5, false);
  EXPECT_EQ(count_bars(dedup, 0, 1), 1u);
  EXPECT_EQ(dedup.bars.size(), 7u);
  ASSERT_EQ(dedup.hinges.size(), 2u);
  // Around the edge: 2 at +y, 4 at +z, 3 at -y; the widest opening (3 back to 2, 180 deg)
  // carries no hinge.
  std::vector<std::array<Index, 2>> wings;
  for (const auto& h : dedup.hinges) wings.push_back({std::min(h[2], h[3]), std::max(h[2], h[3])});
  std::sort(wings.begin(), wings.end());
  EXPECT_EQ(wings, (std::vector<std::array<Index, 2>>{{2, 4}, {3, 4}}));
}

TEST(Topology, BadPanelsAreNamed) {
  const NodeMatrix X = square();
  auto build = [&](std::vector<std::vector<Index>> panels) {
    return [&X, panels] { model::build_topology(X, panels, PanelSplit::N4B5); };
  };
  expect_invalid(build({{0, 1, 2}, {0, 2, 2}}), "panel 1: a node appears twice");
  expect_invalid(build({{0, 1, 4}}), "panel 0: node 4 is out of range [0, 4)");
  expect_invalid(build({{0, -1, 2}}), "panel 0: node -1 is out of range [0, 4)");
  expect_invalid(build({{0, 1, 2}, {0, 2}}), "panel 1: has 2 nodes, must have at least 3");
}
