#include "kresling/model/topology.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Geometry>

namespace kresling::model {

namespace {

using Edge = std::pair<Index, Index>;  // ascending

Edge make_edge(Index a, Index b) { return a < b ? Edge{a, b} : Edge{b, a}; }

struct Splitter {
  std::vector<Vector3> points;                   // all nodes, growing with centre nodes
  std::vector<std::array<Index, 3>> triangles;
  std::vector<Index> triangle_panel;
  std::set<Edge> bend_edges;

  void add_triangle(Index a, Index b, Index c, Index panel) {
    triangles.push_back({a, b, c});
    triangle_panel.push_back(panel);
  }

  double distance(Index a, Index b) const { return (points[a] - points[b]).norm(); }

  // N4B5: a triangle stays; otherwise cut along the shortest diagonal and recurse.
  void split_shortest_diagonal(std::vector<Index> polygon, Index panel) {
    const std::size_t n = polygon.size();
    if (n == 3) {
      add_triangle(polygon[0], polygon[1], polygon[2], panel);
      return;
    }
    std::size_t best_i = 0, best_j = 2;
    double best = INFINITY;
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 2; j < n; ++j) {
        if (i == 0 && j == n - 1) continue;  // adjacent around the polygon
        const double d = distance(polygon[i], polygon[j]);
        if (d < best) best = d, best_i = i, best_j = j;
      }
    }
    bend_edges.insert(make_edge(polygon[best_i], polygon[best_j]));
    std::vector<Index> first(polygon.begin() + best_i, polygon.begin() + best_j + 1);
    std::vector<Index> second(polygon.begin() + best_j, polygon.end());
    second.insert(second.end(), polygon.begin(), polygon.begin() + best_i + 1);
    split_shortest_diagonal(first, panel);
    split_shortest_diagonal(second, panel);
  }

  // N5B8: a new node at the vertex mean, spokes to every vertex.
  void split_around_centre(const std::vector<Index>& polygon, Index panel) {
    Vector3 centre = Vector3::Zero();
    for (Index v : polygon) centre += points[v];
    centre /= static_cast<double>(polygon.size());
    const Index c = static_cast<Index>(points.size());
    points.push_back(centre);
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Index a = polygon[i], b = polygon[(i + 1) % polygon.size()];
      add_triangle(a, b, c, panel);
      bend_edges.insert(make_edge(a, c));
    }
  }
};

Index third_vertex(const std::array<Index, 3>& t, const Edge& e) {
  for (Index v : t) {
    if (v != e.first && v != e.second) return v;
  }
  return -1;
}

// Angle of each wing around the edge, in the plane perpendicular to it.
std::vector<std::size_t> order_around_edge(const Splitter& s, const Edge& e,
                                           const std::vector<Index>& wings) {
  const Vector3 a = s.points[e.first];
  const Vector3 axis = (s.points[e.second] - a).normalized();
  const Vector3 w0 = s.points[wings[0]] - a;
  const Vector3 x = (w0 - w0.dot(axis) * axis).normalized();
  const Vector3 y = axis.cross(x);
  std::vector<std::pair<double, std::size_t>> angles;
  for (std::size_t k = 0; k < wings.size(); ++k) {
    const Vector3 r = s.points[wings[k]] - a;
    angles.emplace_back(std::atan2(r.dot(y), r.dot(x)), k);
  }
  std::sort(angles.begin(), angles.end());
  std::vector<std::size_t> order;
  for (const auto& p : angles) order.push_back(p.second);
  // Rotate so that the widest opening lies between the last and the first.
  std::size_t widest = 0;
  double widest_gap = -1;
  for (std::size_t k = 0; k < angles.size(); ++k) {
    const double next = k + 1 < angles.size() ? angles[k + 1].first
                                              : angles[0].first + 6.28318530717958647692;
    if (next - angles[k].first > widest_gap) widest_gap = next - angles[k].first, widest = k;
  }
  std::rotate(order.begin(), order.begin() + (widest + 1) % order.size(), order.end());
  return order;
}

}  // namespace

Topology build_topology(const NodeMatrix& nodes, const std::vector<std::vector<Index>>& panels,
                        PanelSplit split, bool duplicate_shared_edges) {
  Splitter s;
  for (Index i = 0; i < nodes.rows(); ++i) s.points.emplace_back(nodes.row(i).transpose());
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const auto& panel = panels[p];
    const std::string name = "panel " + std::to_string(p);
    if (panel.size() < 3) {
      throw std::invalid_argument(name + ": has " + std::to_string(panel.size()) +
                                  " nodes, must have at least 3");
    }
    for (std::size_t k = 0; k < panel.size(); ++k) {
      if (panel[k] < 0 || panel[k] >= nodes.rows()) {
        throw std::invalid_argument(name + ": node " + std::to_string(panel[k]) +
                                    " is out of range [0, " + std::to_string(nodes.rows()) + ")");
      }
      for (std::size_t j = 0; j < k; ++j) {
        if (panel[j] == panel[k]) throw std::invalid_argument(name + ": a node appears twice");
      }
    }
    if (panel.size() == 3) {
      s.add_triangle(panel[0], panel[1], panel[2], static_cast<Index>(p));
    } else if (split == PanelSplit::N5B8) {
      s.split_around_centre(panel, static_cast<Index>(p));
    } else {
      s.split_shortest_diagonal(panel, static_cast<Index>(p));
    }
  }

  // Canonical triangle order (MERLIN2's): sorted nodes, sorted rows.
  std::vector<std::size_t> order(s.triangles.size());
  for (auto& t : s.triangles) std::sort(t.begin(), t.end());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t i, std::size_t j) { return s.triangles[i] < s.triangles[j]; });

  Topology topo;
  topo.nodes.resize(static_cast<Index>(s.points.size()), 3);
  for (std::size_t i = 0; i < s.points.size(); ++i) topo.nodes.row(i) = s.points[i].transpose();
  for (std::size_t i : order) {
    topo.triangles.push_back(s.triangles[i]);
    topo.triangle_panel.push_back(s.triangle_panel[i]);
  }

  // Triangles around every edge, in canonical triangle order.
  std::vector<std::pair<Edge, Index>> incidence;
  for (std::size_t t = 0; t < topo.triangles.size(); ++t) {
    const auto& tri = topo.triangles[t];
    for (int k = 0; k < 3; ++k) {
      incidence.emplace_back(make_edge(tri[k], tri[(k + 1) % 3]), static_cast<Index>(t));
    }
  }
  std::sort(incidence.begin(), incidence.end());

  struct Pair {
    Index t1, t2;
    Edge edge;
  };
  std::vector<Pair> pairs;
  std::vector<Edge> boundary, unique_edges;
  for (std::size_t i = 0; i < incidence.size();) {
    std::size_t j = i;
    std::vector<Index> tris;
    while (j < incidence.size() && incidence[j].first == incidence[i].first) {
      tris.push_back(incidence[j++].second);
    }
    const Edge e = incidence[i].first;
    unique_edges.push_back(e);
    if (tris.size() == 1) boundary.push_back(e);
    if (duplicate_shared_edges || tris.size() == 2) {
      for (std::size_t p = 0; p < tris.size(); ++p) {
        for (std::size_t q = p + 1; q < tris.size(); ++q) pairs.push_back({tris[p], tris[q], e});
      }
    } else if (tris.size() > 2) {
      std::vector<Index> wings;
      for (Index t : tris) wings.push_back(third_vertex(topo.triangles[t], e));
      const auto around = order_around_edge(s, e, wings);
      for (std::size_t k = 0; k + 1 < around.size(); ++k) {
        const Index t1 = tris[around[k]], t2 = tris[around[k + 1]];
        pairs.push_back({std::min(t1, t2), std::max(t1, t2), e});
      }
    }
    i = j;
  }
  // MERLIN2 lists the shared-edge pairs by second triangle, then first.
  std::stable_sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) {
    return std::make_pair(x.t2, x.t1) < std::make_pair(y.t2, y.t1);
  });
  for (const Pair& p : pairs) {
    topo.hinges.push_back({p.edge.first, p.edge.second, third_vertex(topo.triangles[p.t1], p.edge),
                           third_vertex(topo.triangles[p.t2], p.edge)});
    topo.hinge_is_bend.push_back(s.bend_edges.count(p.edge) ? 1 : 0);
    if (duplicate_shared_edges) topo.bars.push_back({p.edge.first, p.edge.second});
  }
  if (duplicate_shared_edges) {
    for (const Edge& e : boundary) topo.bars.push_back({e.first, e.second});
  } else {
    for (const Edge& e : unique_edges) topo.bars.push_back({e.first, e.second});
  }
  return topo;
}

}  // namespace kresling::model
