// The contact broad phase (contact_broad_phase.hpp).

#include "kresling/contact/contact_broad_phase.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "kresling/core/check.hpp"
#include "kresling/contact/contact_box_tree.hpp"

namespace kresling::contact {

namespace {

// The box of some nodes at x (and at x + dx when given), grown by `grow`.
template <int K>
AxisBox box_of(const Eigen::Ref<const NodeMatrix>& x, const Eigen::Ref<const NodeMatrix>* dx,
               const std::array<Index, K>& ids, double grow) {
  AxisBox b{x.row(ids[0]).transpose(), x.row(ids[0]).transpose()};
  for (const Index i : ids) {
    const Vector3 p = x.row(i).transpose();
    b.lo = b.lo.cwiseMin(p);
    b.hi = b.hi.cwiseMax(p);
    if (dx != nullptr) {
      const Vector3 q = p + dx->row(i).transpose();
      b.lo = b.lo.cwiseMin(q);
      b.hi = b.hi.cwiseMax(q);
    }
  }
  b.lo.array() -= grow;
  b.hi.array() += grow;
  return b;
}

ContactCandidates find_candidates(const Eigen::Ref<const NodeMatrix>& x,
                                  const Eigen::Ref<const TriangleMatrix>& triangles,
                                  const Eigen::Ref<const EdgeMatrix>& edges, double distance,
                                  const Eigen::Ref<const NodeMatrix>* dx,
                                  const JoinedNodes& joined) {
  if (!joined.empty() && static_cast<Index>(joined.size()) != x.rows()) {
    throw std::invalid_argument("joined nodes: " + std::to_string(joined.size()) +
                                " entries, must have one per node (" +
                                std::to_string(x.rows()) + ")");
  }
  auto id = [&joined](Index i) { return joined.empty() ? i : joined[static_cast<std::size_t>(i)]; };
  ContactCandidates out;
  // Points: the nodes on some triangle; their boxes carry the whole growth d.
  std::vector<char> on_triangle(static_cast<std::size_t>(x.rows()), 0);
  std::vector<AxisBox> triangle_boxes(static_cast<std::size_t>(triangles.rows()));
  for (Index t = 0; t < triangles.rows(); ++t) {
    const std::array<Index, 3> ids = {triangles(t, 0), triangles(t, 1), triangles(t, 2)};
    for (const Index i : ids) on_triangle[static_cast<std::size_t>(i)] = 1;
    triangle_boxes[static_cast<std::size_t>(t)] = box_of<3>(x, dx, ids, 0.0);
  }
  const BoxTree triangle_tree(std::move(triangle_boxes));
  for (Index v = 0; v < x.rows(); ++v) {
    if (!on_triangle[static_cast<std::size_t>(v)]) continue;
    const Index p = id(v);
    triangle_tree.for_each_overlap(box_of<1>(x, dx, {v}, distance), [&](Index t) {
      if (id(triangles(t, 0)) != p && id(triangles(t, 1)) != p && id(triangles(t, 2)) != p) {
        out.point_triangle.push_back({v, t});
      }
    });
  }
  // Edges: the tree holds them at their own size, each query grown by d; a < b keeps each
  // pair once.
  std::vector<AxisBox> edge_boxes(static_cast<std::size_t>(edges.rows()));
  for (Index e = 0; e < edges.rows(); ++e) {
    edge_boxes[static_cast<std::size_t>(e)] = box_of<2>(x, dx, {edges(e, 0), edges(e, 1)}, 0.0);
  }
  const BoxTree edge_tree(edge_boxes);
  for (Index a = 0; a < edges.rows(); ++a) {
    AxisBox query = edge_boxes[static_cast<std::size_t>(a)];
    query.lo.array() -= distance;
    query.hi.array() += distance;
    const Index a0 = id(edges(a, 0)), a1 = id(edges(a, 1));
    edge_tree.for_each_overlap(query, [&](Index b) {
      if (b <= a) return;
      const Index b0 = id(edges(b, 0)), b1 = id(edges(b, 1));
      if (a0 != b0 && a0 != b1 && a1 != b0 && a1 != b1) out.edge_edge.push_back({a, b});
    });
  }
  std::sort(out.point_triangle.begin(), out.point_triangle.end());
  std::sort(out.edge_edge.begin(), out.edge_edge.end());
  return out;
}

template <typename Rows>
void check_indices(const std::string& name, const Rows& rows, Index node_count) {
  for (Index r = 0; r < rows.rows(); ++r) {
    for (Index c = 0; c < rows.cols(); ++c) {
      const Index i = rows(r, c);
      if (i < 0 || i >= node_count) {
        throw std::invalid_argument(name + "[" + std::to_string(r) + ", " + std::to_string(c) +
                                    "] = " + std::to_string(i) +
                                    " is invalid: must be a node index in [0, " +
                                    std::to_string(node_count) + ")");
      }
    }
  }
}

}  // namespace

EdgeMatrix triangle_edges(const Eigen::Ref<const TriangleMatrix>& triangles) {
  std::vector<std::array<Index, 2>> all;
  all.reserve(static_cast<std::size_t>(3 * triangles.rows()));
  for (Index t = 0; t < triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const Index i = triangles(t, k), j = triangles(t, (k + 1) % 3);
      all.push_back({std::min(i, j), std::max(i, j)});
    }
  }
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  EdgeMatrix edges(static_cast<Index>(all.size()), 2);
  for (std::size_t e = 0; e < all.size(); ++e) {
    edges(static_cast<Index>(e), 0) = all[e][0];
    edges(static_cast<Index>(e), 1) = all[e][1];
  }
  return edges;
}

ContactCandidates contact_candidates(const Eigen::Ref<const NodeMatrix>& nodes,
                                     const Eigen::Ref<const TriangleMatrix>& triangles,
                                     const Eigen::Ref<const EdgeMatrix>& edges, double distance,
                                     const JoinedNodes& joined) {
  return find_candidates(nodes, triangles, edges, distance, nullptr, joined);
}

ContactCandidates contact_candidates(const Eigen::Ref<const NodeMatrix>& nodes,
                                     const Eigen::Ref<const TriangleMatrix>& triangles,
                                     const Eigen::Ref<const EdgeMatrix>& edges, double distance,
                                     const Eigen::Ref<const NodeMatrix>& displacement,
                                     const JoinedNodes& joined) {
  if (displacement.rows() != nodes.rows()) {
    throw std::invalid_argument("displacement has " + std::to_string(displacement.rows()) +
                                " rows: must have one per node (" +
                                std::to_string(nodes.rows()) + ")");
  }
  return find_candidates(nodes, triangles, edges, distance, &displacement, joined);
}

void check_contact_mesh(const Eigen::Ref<const NodeMatrix>& nodes,
                        const Eigen::Ref<const TriangleMatrix>& triangles,
                        const Eigen::Ref<const EdgeMatrix>& edges, double distance) {
  require_positive("distance", distance, true);
  if (!nodes.allFinite()) {
    throw std::invalid_argument("nodes: every coordinate must be finite");
  }
  check_indices("triangles", triangles, nodes.rows());
  check_indices("edges", edges, nodes.rows());
  for (Index t = 0; t < triangles.rows(); ++t) {
    if (triangles(t, 0) == triangles(t, 1) || triangles(t, 1) == triangles(t, 2) ||
        triangles(t, 0) == triangles(t, 2)) {
      throw std::invalid_argument("triangles[" + std::to_string(t) +
                                  "] repeats a node: a triangle needs three distinct nodes");
    }
  }
}

}  // namespace kresling::contact
