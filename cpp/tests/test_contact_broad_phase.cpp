// The contact broad phase against brute force on random meshes, the exclusion rule, and
// the completeness that the narrow phase relies on (every pair closer than d is a
// candidate).

#include <algorithm>
#include <set>
#include <stdexcept>

#include <gtest/gtest.h>

#include "contact_test_helpers.hpp"
#include "kresling/contact/contact_broad_phase.hpp"
#include "kresling/contact/contact_distance.hpp"

using namespace kresling;
using namespace kresling::contact;
using namespace kresling::contact_test;

namespace {

using Pair = std::array<Index, 2>;

struct Mesh {
  NodeMatrix nodes;
  TriangleMatrix triangles;
};

// Sheets of m x m nodes (two triangles a cell), each jittered, crumpled in z, rotated and
// placed so that they cross one another, plus a few triangles between random nodes.
Mesh random_mesh(std::mt19937& rng, int sheets, int m) {
  Mesh mesh;
  mesh.nodes.resize(sheets * m * m, 3);
  mesh.triangles.resize(sheets * 2 * (m - 1) * (m - 1) + 10, 3);
  std::uniform_real_distribution<double> u(-1, 1);
  Index t = 0;
  for (int s = 0; s < sheets; ++s) {
    const Matrix3 Q = random_rotation(rng);
    const Vector3 shift = random_point(rng, 0.3 * m);
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < m; ++j) {
        const Vector3 local(i + 0.2 * u(rng), j + 0.2 * u(rng), 0.3 * u(rng));
        mesh.nodes.row((s * m + i) * m + j) = (Q * local + shift).transpose();
      }
    }
    for (int i = 0; i + 1 < m; ++i) {
      for (int j = 0; j + 1 < m; ++j) {
        const Index a = (s * m + i) * m + j, b = a + m, c = a + 1, d = b + 1;
        mesh.triangles.row(t++) << a, b, c;
        mesh.triangles.row(t++) << c, b, d;
      }
    }
  }
  std::uniform_int_distribution<Index> node(0, mesh.nodes.rows() - 1);
  while (t < mesh.triangles.rows()) {
    const Index a = node(rng), b = node(rng), c = node(rng);
    if (a != b && b != c && a != c) mesh.triangles.row(t++) << a, b, c;
  }
  return mesh;
}

// Brute force with the documented rule: the box of one primitive grown by d overlaps the box
// of the other (boxes over x and x + dx when a displacement is given).
struct Box {
  Vector3 lo, hi;
};

Box box(const Mesh& mesh, const NodeMatrix* dx, std::initializer_list<Index> ids) {
  Box b{Vector3::Constant(1e300), Vector3::Constant(-1e300)};
  for (Index i : ids) {
    for (int end = 0; end < (dx ? 2 : 1); ++end) {
      const Vector3 p = mesh.nodes.row(i).transpose() +
                        (end ? Vector3(dx->row(i).transpose()) : Vector3::Zero());
      b.lo = b.lo.cwiseMin(p);
      b.hi = b.hi.cwiseMax(p);
    }
  }
  return b;
}

bool within(const Box& a, const Box& b, double d) {
  for (int k = 0; k < 3; ++k) {
    if (a.lo[k] - d > b.hi[k] || b.lo[k] - d > a.hi[k]) return false;
  }
  return true;
}

ContactCandidates brute_force(const Mesh& mesh, const EdgeMatrix& edges, double d,
                              const NodeMatrix* dx) {
  ContactCandidates out;
  std::set<Index> points;
  for (Index t = 0; t < mesh.triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) points.insert(mesh.triangles(t, k));
  }
  for (Index v : points) {
    for (Index t = 0; t < mesh.triangles.rows(); ++t) {
      const auto tri = mesh.triangles.row(t);
      if (tri(0) == v || tri(1) == v || tri(2) == v) continue;
      if (within(box(mesh, dx, {v}), box(mesh, dx, {tri(0), tri(1), tri(2)}), d)) {
        out.point_triangle.push_back({v, t});
      }
    }
  }
  for (Index a = 0; a < edges.rows(); ++a) {
    for (Index b = a + 1; b < edges.rows(); ++b) {
      const std::set<Index> ends = {edges(a, 0), edges(a, 1), edges(b, 0), edges(b, 1)};
      if (ends.size() < 4) continue;
      if (within(box(mesh, dx, {edges(a, 0), edges(a, 1)}),
                 box(mesh, dx, {edges(b, 0), edges(b, 1)}), d)) {
        out.edge_edge.push_back({a, b});
      }
    }
  }
  return out;
}

}  // namespace

TEST(ContactBroadPhase, TriangleEdgesAreUniqueAndSorted) {
  TriangleMatrix triangles(2, 3);
  triangles << 0, 1, 2, 2, 1, 3;
  EdgeMatrix expected(5, 2);
  expected << 0, 1, 0, 2, 1, 2, 1, 3, 2, 3;
  EXPECT_EQ(triangle_edges(triangles), expected);
}

TEST(ContactBroadPhase, MatchesBruteForceOnRandomMeshes) {
  std::mt19937 rng(51);
  for (int trial = 0; trial < 6; ++trial) {
    const Mesh mesh = random_mesh(rng, 3, 7);
    const EdgeMatrix edges = triangle_edges(mesh.triangles);
    for (double d : {0.0, 0.1, 0.7}) {
      const auto found = contact_candidates(mesh.nodes, mesh.triangles, edges, d);
      const auto expected = brute_force(mesh, edges, d, nullptr);
      EXPECT_EQ(found.point_triangle, expected.point_triangle) << trial << " d " << d;
      EXPECT_EQ(found.edge_edge, expected.edge_edge) << trial << " d " << d;
      EXPECT_GT(expected.point_triangle.size(), 0u);
      // The swept boxes of a random step.
      NodeMatrix dx(mesh.nodes.rows(), 3);
      for (Index i = 0; i < dx.rows(); ++i) dx.row(i) = 0.5 * random_point(rng).transpose();
      const auto swept = contact_candidates(mesh.nodes, mesh.triangles, edges, d, dx);
      const auto expected_swept = brute_force(mesh, edges, d, &dx);
      EXPECT_EQ(swept.point_triangle, expected_swept.point_triangle) << trial;
      EXPECT_EQ(swept.edge_edge, expected_swept.edge_edge) << trial;
      EXPECT_GT(swept.point_triangle.size(), found.point_triangle.size());
    }
  }
}

TEST(ContactBroadPhase, EveryPairCloserThanTheDistanceIsACandidate) {
  std::mt19937 rng(52);
  const Mesh mesh = random_mesh(rng, 4, 6);
  const EdgeMatrix edges = triangle_edges(mesh.triangles);
  const double d = 0.4;
  const auto found = contact_candidates(mesh.nodes, mesh.triangles, edges, d);
  const std::set<Pair> pt(found.point_triangle.begin(), found.point_triangle.end());
  const std::set<Pair> ee(found.edge_edge.begin(), found.edge_edge.end());
  const auto x = [&](Index i) -> Vector3 { return mesh.nodes.row(i).transpose(); };
  int close = 0;
  for (Index v = 0; v < mesh.nodes.rows(); ++v) {
    for (Index t = 0; t < mesh.triangles.rows(); ++t) {
      const auto tri = mesh.triangles.row(t);
      if (tri(0) == v || tri(1) == v || tri(2) == v) continue;
      if (point_triangle_distance(x(v), x(tri(0)), x(tri(1)), x(tri(2)), false).value < d * d) {
        ++close;
        EXPECT_TRUE(pt.count({v, t})) << v << " " << t;
      }
    }
  }
  for (Index a = 0; a < edges.rows(); ++a) {
    for (Index b = a + 1; b < edges.rows(); ++b) {
      if (std::set<Index>{edges(a, 0), edges(a, 1), edges(b, 0), edges(b, 1)}.size() < 4) continue;
      if (edge_edge_distance(x(edges(a, 0)), x(edges(a, 1)), x(edges(b, 0)), x(edges(b, 1)),
                             false)
              .value < d * d) {
        ++close;
        EXPECT_TRUE(ee.count({a, b})) << a << " " << b;
      }
    }
  }
  EXPECT_GT(close, 50);
}

TEST(ContactBroadPhase, ACreaseIsNoContactButAFoldedCornerMeetsItsNeighbour) {
  // Two panels (0, 1, 2) and (1, 0, 3) on the crease 0-1, folded nearly shut: corner 2 lies
  // 0.01 above panel (1, 0, 3).
  NodeMatrix x(4, 3);
  x << 0, 0, 0, 1, 0, 0, 0.3, 0.5, 0.01, 0.4, 0.4, 0;
  TriangleMatrix triangles(2, 3);
  triangles << 0, 1, 2, 1, 0, 3;
  const EdgeMatrix edges = triangle_edges(triangles);
  const auto found = contact_candidates(x, triangles, edges, 0.15);
  const std::vector<Pair> expected_pt = {{2, 1}, {3, 0}};
  EXPECT_EQ(found.point_triangle, expected_pt);
  // Edges 0-2 / 1-3 and 0-3 / 1-2 share no node; every other pair does.
  ASSERT_EQ(edges.rows(), 5);
  const std::vector<Pair> expected_ee = {{1, 4}, {2, 3}};  // rows: 01 02 03 12 13
  EXPECT_EQ(found.edge_edge, expected_ee);
}

TEST(ContactBroadPhase, TheTwoSidesOfACutJoinedAreNoContact) {
  // The same two panels cut apart along 0-1: panel (4, 5, 3) holds copies 4, 5 of nodes 1,
  // 0 at their places. Unjoined, the copies touch the other panel (distance 0): candidates.
  // Joined (4 ~ 1, 5 ~ 0), they are excluded as the crease's were; corner 2 still meets
  // the other panel.
  NodeMatrix x(6, 3);
  x << 0, 0, 0, 1, 0, 0, 0.3, 0.5, 0.01, 0.4, 0.4, 0, 1, 0, 0, 0, 0, 0;
  TriangleMatrix triangles(2, 3);
  triangles << 0, 1, 2, 4, 5, 3;
  const EdgeMatrix edges = triangle_edges(triangles);
  const auto apart = contact_candidates(x, triangles, edges, 0.15);
  EXPECT_GT(apart.point_triangle.size(), 2u);
  const JoinedNodes joined = {0, 1, 2, 3, 1, 0};
  const auto cut = contact_candidates(x, triangles, edges, 0.15, joined);
  const std::vector<Pair> expected_pt = {{2, 1}, {3, 0}};
  EXPECT_EQ(cut.point_triangle, expected_pt);
  for (const auto& [a, b] : cut.edge_edge) {  // no two edges with a joined end
    std::set<Index> ends = {joined[edges(a, 0)], joined[edges(a, 1)]};
    EXPECT_FALSE(ends.count(joined[edges(b, 0)]) || ends.count(joined[edges(b, 1)]));
  }
  EXPECT_THROW(contact_candidates(x, triangles, edges, 0.15, JoinedNodes{0, 1}),
               std::invalid_argument);
}

TEST(ContactBroadPhase, BadMeshesAreRejected) {
  NodeMatrix x = NodeMatrix::Zero(3, 3);
  TriangleMatrix t(1, 3);
  t << 0, 1, 3;
  EXPECT_THROW(check_contact_mesh(x, t, triangle_edges(t), 0.1), std::invalid_argument);
  t << 0, 1, 1;
  EXPECT_THROW(check_contact_mesh(x, t, triangle_edges(t), 0.1), std::invalid_argument);
  t << 0, 1, 2;
  EXPECT_THROW(check_contact_mesh(x, t, triangle_edges(t), -0.1), std::invalid_argument);
  EXPECT_NO_THROW(check_contact_mesh(x, t, triangle_edges(t), 0.1));
  EXPECT_THROW(contact_candidates(x, t, triangle_edges(t), 0.1, NodeMatrix::Zero(2, 3)),
               std::invalid_argument);
}
