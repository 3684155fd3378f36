#include "kresling/model/panel_elements.hpp"

#include <algorithm>
#include <map>
#include <numeric>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "kresling/model/panel_centre.hpp"
#include "kresling/model/polygon_diagonals.hpp"

namespace kresling::model {

namespace {

using Edge = std::array<Index, 2>;  // ascending

Edge make_edge(Index a, Index b) { return a < b ? Edge{a, b} : Edge{b, a}; }

void check_panel(const std::vector<Index>& panel, std::size_t p, Index num_vertices) {
  const std::string name = "panel " + std::to_string(p);
  if (panel.size() < 3) {
    throw std::invalid_argument(name + ": has " + std::to_string(panel.size()) +
                                " vertices, must have at least 3");
  }
  for (std::size_t k = 0; k < panel.size(); ++k) {
    if (panel[k] < 0 || panel[k] >= num_vertices) {
      throw std::invalid_argument(name + ": vertex " + std::to_string(panel[k]) +
                                  " is out of range [0, " + std::to_string(num_vertices) + ")");
    }
    for (std::size_t j = 0; j < k; ++j) {
      if (panel[j] == panel[k]) {
        throw std::invalid_argument(name + ": vertex " + std::to_string(panel[k]) +
                                    " appears twice");
      }
    }
  }
}

// N4B5 bend hinges of one panel, in local corner indices.
std::vector<std::array<Index, 4>> local_n4b5_bends(const std::vector<Vector3>& p,
                                                   const PlanarPolygon& polygon) {
  if (p.size() == 4) {
    // The shorter diagonal (p0-p2 on a tie) is the bend axis, unless it lies outside the
    // panel (a non-convex quad) or along its sides (a straight corner).
    const bool shorter_13 = (p[0] - p[2]).norm() > (p[3] - p[1]).norm();
    const bool use_13 = shorter_13 ? polygon.is_interior_diagonal(1, 3)
                                   : !polygon.is_interior_diagonal(0, 2);
    if (use_13 && !polygon.is_interior_diagonal(1, 3)) {
      throw std::invalid_argument("neither diagonal lies inside the quad: it is "
                                  "self-intersecting or degenerate; must be a simple polygon");
    }
    if (use_13) return {{1, 3, 0, 2}};
    return {{0, 2, 1, 3}};
  }
  const Index m = static_cast<Index>(p.size());
  const auto cuts = polygon_diagonal_cuts(p);
  // Wings: the corners joined to both ends of the cut by a side or another cut.
  std::set<Edge> links;
  for (Index k = 0; k < m; ++k) links.insert(make_edge(k, (k + 1) % m));
  for (const Edge& c : cuts) links.insert(c);
  std::vector<std::array<Index, 4>> bends;
  for (const Edge& c : cuts) {
    std::array<Index, 4> bend{c[0], c[1], -1, -1};
    int found = 0;
    for (Index k = 0; k < m; ++k) {
      if (k == c[0] || k == c[1]) continue;
      if (links.count(make_edge(k, c[0])) && links.count(make_edge(k, c[1]))) {
        if (found < 2) bend[2 + found] = k;
        ++found;
      }
    }
    if (found != 2) throw std::invalid_argument("the panel cannot be split into triangles");
    bends.push_back(bend);
  }
  return bends;
}

}  // namespace

std::vector<std::array<Index, 2>> polygon_diagonal_cuts(const std::vector<Vector3>& corners) {
  const std::size_t m = corners.size();
  if (m <= 3) return {};
  const PlanarPolygon polygon(corners);
  // Diagonals column by column (j, then i), as MERLIN2 visits them, the shortest interior
  // one first; a stable sort by length keeps that order on ties.
  std::vector<std::array<std::size_t, 2>> candidates;
  for (std::size_t j = 2; j < m; ++j) {
    for (std::size_t i = 0; i + 2 <= j; ++i) {
      if (!(i == 0 && j == m - 1)) candidates.push_back({i, j});
    }
  }
  std::vector<double> length(candidates.size());
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    length[k] = (corners[candidates[k][1]] - corners[candidates[k][0]]).squaredNorm();
  }
  std::vector<std::size_t> order(candidates.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t x, std::size_t y) { return length[x] < length[y]; });
  std::size_t bi = m, bj = m;
  for (std::size_t k : order) {
    if (polygon.is_interior_diagonal(candidates[k][0], candidates[k][1])) {
      bi = candidates[k][0], bj = candidates[k][1];
      break;
    }
  }
  if (bi == m) {
    throw std::invalid_argument("no diagonal of the panel lies inside it: the panel is "
                                "self-intersecting or degenerate; must be a simple polygon");
  }
  std::vector<std::array<Index, 2>> cuts = {{static_cast<Index>(bi), static_cast<Index>(bj)}};
  // Recurse on the two sides, mapping their local corners back.
  std::vector<std::size_t> side1, side2;
  for (std::size_t k = 0; k <= bi; ++k) side1.push_back(k);
  for (std::size_t k = bj; k < m; ++k) side1.push_back(k);
  for (std::size_t k = bi; k <= bj; ++k) side2.push_back(k);
  for (const auto* side : {&side1, &side2}) {
    std::vector<Vector3> sub;
    for (std::size_t k : *side) sub.push_back(corners[k]);
    for (const auto& c : polygon_diagonal_cuts(sub)) {
      cuts.push_back({static_cast<Index>((*side)[c[0]]), static_cast<Index>((*side)[c[1]])});
    }
  }
  return cuts;
}

std::vector<std::array<Index, 2>> PanelElements::bars() const {
  std::vector<std::array<Index, 2>> out;
  out.reserve(bends.size() + folds.size() + boundary.size());
  for (const auto& h : bends) out.push_back({h[0], h[1]});
  for (const auto& h : folds) out.push_back({h[0], h[1]});
  for (const auto& e : boundary) out.push_back(e);
  return out;
}

namespace {

// The N5B8 centre of a panel: by the rule asked for (MERLIN2's, or the corners' mean), else
// the corners' mean, whichever the panel is star-shaped from (every fan triangle (centre,
// corner k, corner k + 1) turning its way with an area, so no spoke runs outside it: a
// non-convex panel, or a straight corner on MERLIN2's quad centre); none when neither is.
std::optional<Vector3> fan_centre(const std::vector<Vector3>& corners,
                                  const PlanarPolygon& polygon, CentreRule rule) {
  Vector3 mean = Vector3::Zero();
  for (const Vector3& corner : corners) mean += corner;
  mean /= static_cast<double>(corners.size());
  if (rule == CentreRule::Merlin2) {
    try {
      const Vector3 centre = corners.size() == 4
                                 ? quad_centre(corners[0], corners[1], corners[2], corners[3])
                                 : polygon_optimal_centre(corners);
      if (polygon.is_star_centre(centre)) return centre;
    } catch (const std::invalid_argument&) {
      // Parallel or degenerate diagonals (a straight corner): the mean is tried instead.
    }
  }
  if (polygon.is_star_centre(mean)) return mean;
  return std::nullopt;
}

}  // namespace

PanelElements build_panel_elements(const NodeMatrix& vertices,
                                   const std::vector<std::vector<Index>>& panels,
                                   PanelSplit split, CentreRule centre_rule) {
  PanelElements out;
  std::vector<Vector3> points;
  for (Index i = 0; i < vertices.rows(); ++i) points.emplace_back(vertices.row(i).transpose());
  std::vector<std::array<Index, 3>> pieces;

  for (std::size_t p = 0; p < panels.size(); ++p) {
    const auto& panel = panels[p];
    check_panel(panel, p, vertices.rows());
    const std::size_t m = panel.size();
    out.panel_centre.push_back(-1);
    if (m == 3) {
      pieces.push_back({panel[0], panel[1], panel[2]});
      continue;
    }
    std::vector<Vector3> corners;
    for (Index v : panel) corners.push_back(points[v]);
    const std::string name = "panel " + std::to_string(p);
    std::optional<PlanarPolygon> polygon;
    try {
      polygon.emplace(corners);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(name + ": " + e.what());
    }
    if (!polygon->is_simple()) {
      throw std::invalid_argument(name + ": two of its sides cross or touch: the panel is "
                                  "self-intersecting or degenerate; must be a simple polygon");
    }
    std::optional<Vector3> centre;
    if (split == PanelSplit::N5B8) centre = fan_centre(corners, *polygon, centre_rule);
    if (!centre) {
      // N4B5, or an N5B8 panel not star-shaped from any centre tried: cut along diagonals.
      try {
        for (const auto& b : local_n4b5_bends(corners, *polygon)) {
          out.bends.push_back({panel[b[0]], panel[b[1]], panel[b[2]], panel[b[3]]});
          out.bend_panel.push_back(static_cast<Index>(p));
        }
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(name + ": " + e.what());
      }
      continue;
    }
    const Index c = static_cast<Index>(points.size());
    points.push_back(*centre);
    out.panel_centre.back() = c;
    for (std::size_t k = 0; k < m; ++k) {
      out.bends.push_back({c, panel[k], panel[(k + m - 1) % m], panel[(k + 1) % m]});
      out.bend_panel.push_back(static_cast<Index>(p));
    }
  }

  out.nodes.resize(static_cast<Index>(points.size()), 3);
  for (std::size_t i = 0; i < points.size(); ++i) out.nodes.row(i) = points[i].transpose();

  // Triangles: the two sides of every bend hinge and the triangular panels.
  for (const auto& b : out.bends) {
    pieces.push_back({b[0], b[1], b[2]});
    pieces.push_back({b[0], b[1], b[3]});
  }
  for (auto& t : pieces) std::sort(t.begin(), t.end());
  std::sort(pieces.begin(), pieces.end());
  pieces.erase(std::unique(pieces.begin(), pieces.end()), pieces.end());
  out.triangles = pieces;

  std::map<Edge, std::vector<Index>> around;  // edge -> triangles, ascending
  for (std::size_t t = 0; t < pieces.size(); ++t) {
    const auto& tri = pieces[t];
    for (int k = 0; k < 3; ++k) {
      around[make_edge(tri[k], tri[(k + 1) % 3])].push_back(static_cast<Index>(t));
    }
  }
  std::set<Edge> bend_axes;
  for (const auto& b : out.bends) bend_axes.insert(make_edge(b[0], b[1]));
  struct Pair {
    Index lower, higher;
    Edge edge;
  };
  std::vector<Pair> pairs;
  for (const auto& [edge, tris] : around) {
    if (tris.size() == 1) out.boundary.push_back(edge);
    if (bend_axes.count(edge)) continue;
    for (std::size_t i = 0; i < tris.size(); ++i) {
      for (std::size_t j = i + 1; j < tris.size(); ++j) pairs.push_back({tris[i], tris[j], edge});
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) {
    return std::make_pair(x.higher, x.lower) < std::make_pair(y.higher, y.lower);
  });
  auto third = [](const std::array<Index, 3>& t, const Edge& e) {
    for (Index v : t) {
      if (v != e[0] && v != e[1]) return v;
    }
    return Index{-1};
  };
  for (const Pair& p : pairs) {
    out.folds.push_back({p.edge[0], p.edge[1], third(pieces[p.lower], p.edge),
                         third(pieces[p.higher], p.edge)});
  }
  return out;
}

}  // namespace kresling::model
