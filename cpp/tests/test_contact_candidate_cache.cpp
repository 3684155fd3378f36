// The broad phase's kept list (contact/contact_candidate_cache.hpp) against brute force:
// at positions moved from where the list was found, its clearance is below every pair's
// distance, and its kept distances pass over no pair within the distance asked for.
//
// The brute force measures every pair that is not excluded with the distance kernels
// (contact_distance.hpp), independently of the list and of its closest-point distances.
// The bounds are inequalities with no tolerance: the list's bound already leaves 1e-9 of
// the coordinates for rounding, far above the kernels' ~1e-15 here.

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>

#include <gtest/gtest.h>

#include "contact_test_helpers.hpp"
#include "kresling/contact/contact_broad_phase.hpp"
#include "kresling/contact/contact_candidate_cache.hpp"
#include "kresling/contact/contact_distance.hpp"

using namespace kresling;
using namespace kresling::contact;
using namespace kresling::contact_test;

namespace {

using Pair = std::array<Index, 2>;

// Three sheets of 6 x 6 nodes, jittered and crumpled, stacked 0.45 apart: the nearest pairs
// (across neighbouring sheets) are about 0.25 apart, many within 0.3.
void crumpled_sheets(std::mt19937& rng, NodeMatrix& nodes, TriangleMatrix& triangles) {
  const int sheets = 3, m = 6;
  nodes.resize(sheets * m * m, 3);
  triangles.resize(sheets * 2 * (m - 1) * (m - 1), 3);
  std::uniform_real_distribution<double> u(-1, 1);
  Index t = 0;
  for (int s = 0; s < sheets; ++s) {
    const Vector3 shift(0.5 * u(rng), 0.5 * u(rng), 0.45 * s);
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < m; ++j) {
        const Vector3 local(i + 0.2 * u(rng), j + 0.2 * u(rng), 0.1 * u(rng));
        nodes.row((s * m + i) * m + j) = (local + shift).transpose();
      }
    }
    for (int i = 0; i + 1 < m; ++i) {
      for (int j = 0; j + 1 < m; ++j) {
        const Index a = (s * m + i) * m + j, b = a + m, c = a + 1, d = b + 1;
        triangles.row(t++) << a, b, c;
        triangles.row(t++) << c, b, d;
      }
    }
  }
}

// Every pair that is not excluded and its distance at x, by the kernels.
struct AllPairs {
  std::map<Pair, double> point_triangle, edge_edge;
  double nearest = std::numeric_limits<double>::infinity();
};

AllPairs all_pairs(const NodeMatrix& x, const TriangleMatrix& tri, const EdgeMatrix& edges) {
  AllPairs out;
  const auto at = [&](Index i) -> Vector3 { return x.row(i).transpose(); };
  for (Index v = 0; v < x.rows(); ++v) {
    for (Index t = 0; t < tri.rows(); ++t) {
      if (tri(t, 0) == v || tri(t, 1) == v || tri(t, 2) == v) continue;
      const double d = std::sqrt(
          point_triangle_distance(at(v), at(tri(t, 0)), at(tri(t, 1)), at(tri(t, 2)), false).value);
      out.point_triangle[{v, t}] = d;
      out.nearest = std::min(out.nearest, d);
    }
  }
  for (Index a = 0; a < edges.rows(); ++a) {
    for (Index b = a + 1; b < edges.rows(); ++b) {
      const Index n[4] = {edges(a, 0), edges(a, 1), edges(b, 0), edges(b, 1)};
      if (n[0] == n[2] || n[0] == n[3] || n[1] == n[2] || n[1] == n[3]) continue;
      const double d = std::sqrt(
          edge_edge_distance(at(n[0]), at(n[1]), at(n[2]), at(n[3]), false).value);
      out.edge_edge[{a, b}] = d;
      out.nearest = std::min(out.nearest, d);
    }
  }
  return out;
}

}  // namespace

TEST(ContactCandidateCache, ClearanceAndKeptDistancesHoldAfterTheNodesMove) {
  std::mt19937 rng(61);
  const double distance = 0.3, skin = 0.3;
  int cleared = 0, passed_over = 0, within = 0;
  for (int trial = 0; trial < 4; ++trial) {
    NodeMatrix X;
    TriangleMatrix triangles;
    crumpled_sheets(rng, X, triangles);
    const EdgeMatrix edges = triangle_edges(triangles);
    const ContactCandidateCache cache(distance, skin);
    ASSERT_TRUE(cache.candidates(X, triangles, edges).list);
    for (double move : {0.0, 0.02, 0.07, 0.149}) {
      // Every node moved by at most `move` (below skin / 2: the list is kept).
      NodeMatrix x = X;
      for (Index i = 0; i < x.rows(); ++i) {
        const Vector3 r = random_point(rng);
        x.row(i) += (move * r / std::max(r.norm(), 1.0)).transpose();
      }
      const KeptView view = cache.candidates(x, triangles, edges);
      ASSERT_TRUE(view.list);
      // Kept, not found anew: the move is measured from X (to its rounding, 1e-12).
      EXPECT_LE(view.moved, move * (1.0 + 1e-12));
      EXPECT_GE(view.moved, 0.5 * move);
      const AllPairs truth = all_pairs(x, triangles, edges);
      // The clearance bounds every pair's distance, those outside the list too.
      EXPECT_LE(view.clearance(), truth.nearest) << trial << " move " << move;
      if (view.clearance() > 0.0) ++cleared;
      // A pair within the distance at x is in the list, and its kept distance does not
      // pass it over; pairs passed over are farther, as the filter claims.
      std::map<Pair, double> kept_pt, kept_ee;
      const KeptCandidates& k = *view.list;
      for (std::size_t i = 0; i < k.pairs.point_triangle.size(); ++i) {
        kept_pt[k.pairs.point_triangle[i]] = k.point_triangle_distance[i];
      }
      for (std::size_t i = 0; i < k.pairs.edge_edge.size(); ++i) {
        kept_ee[k.pairs.edge_edge[i]] = k.edge_edge_distance[i];
      }
      for (const auto* kind : {&truth.point_triangle, &truth.edge_edge}) {
        const auto& kept = kind == &truth.point_triangle ? kept_pt : kept_ee;
        for (const auto& [pair, d] : *kind) {
          const auto found = kept.find(pair);
          if (d < distance) {
            ++within;
            ASSERT_NE(found, kept.end()) << pair[0] << " " << pair[1];
            EXPECT_TRUE(view.may_be_within(found->second, distance)) << pair[0] << " " << pair[1];
          } else if (found != kept.end() && !view.may_be_within(found->second, distance)) {
            ++passed_over;
          }
        }
      }
    }
  }
  // The checks above are not empty: pairs within the distance, pairs passed over, and a
  // clearance that bounds something.
  EXPECT_GT(within, 50);
  EXPECT_GT(passed_over, 50);
  EXPECT_GT(cleared, 0);
}
