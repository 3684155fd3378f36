#include "kresling/model/kresling_specimen.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "kresling/core/check.hpp"
#include "kresling/elements/dihedral.hpp"
#include "kresling/model/topology.hpp"

namespace kresling::model {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;

using Edge = std::pair<Index, Index>;
Edge edge(Index a, Index b) { return a < b ? Edge{a, b} : Edge{b, a}; }

void check_parameters(const SpecimenParameters& p) {
  require_positive("kf", p.kf);
  require_positive("valley_factor", p.valley_factor, true);
  require_positive("polygon_edge_factor", p.polygon_edge_factor, true);
  require_positive("spoke_factor", p.spoke_factor, true);
  require_positive("mountain_factor", p.mountain_factor, true);
  require_positive("modulus_factor", p.modulus_factor);
  require_positive("material_area", p.material_area);
  require_positive("mountain_area", p.mountain_area);
  if (!(p.theta1 > 0 && p.theta1 < p.theta2 && p.theta2 < kTwoPi)) {
    throw std::invalid_argument("theta1, theta2 = " + format_number(p.theta1) + ", " +
                                format_number(p.theta2) +
                                " are invalid: must satisfy 0 < theta1 < theta2 < 2 pi");
  }
}

Index node_index(int n, int level, int j) { return static_cast<Index>(level) * (n + 1) + j; }

}  // namespace

double hinge_factor(EdgeFamily f, const SpecimenParameters& p) {
  switch (f) {
    case EdgeFamily::Valley: return p.valley_factor;
    case EdgeFamily::Mountain: return p.mountain_factor;
    case EdgeFamily::PolygonEdge: return p.polygon_edge_factor;
    case EdgeFamily::PolygonSpoke: return p.spoke_factor;
  }
  return 0.0;
}

KreslingSpecimenBuilder::KreslingSpecimenBuilder(int n, std::vector<int> chirality,
                                                 SpecimenParameters parameters)
    : n_(n), chirality_(std::move(chirality)), parameters_(parameters) {
  require_integer_in("n", n_, 3, kMaxSpecimenNodes);
  if (chirality_.empty()) throw std::invalid_argument("chirality: the specimen needs at least one cell");
  // 64-bit: (cells + 1) (n + 1) overflows an int long before memory runs out.
  const long long nodes = (static_cast<long long>(chirality_.size()) + 1) * (n_ + 1LL);
  if (nodes > kMaxSpecimenNodes) {
    throw std::invalid_argument(
        "n, cells = " + std::to_string(n_) + ", " + std::to_string(chirality_.size()) +
        " are invalid: a specimen of (cells + 1) (n + 1) = " + std::to_string(nodes) +
        " nodes; must have at most " + std::to_string(kMaxSpecimenNodes));
  }
  for (std::size_t i = 0; i < chirality_.size(); ++i) {
    if (chirality_[i] != 1 && chirality_[i] != -1) {
      throw_invalid("chirality[" + std::to_string(i) + "]", chirality_[i], "+1 or -1");
    }
  }
  check_parameters(parameters_);

  // Panels and edge families from the node numbering alone.
  std::vector<std::pair<Edge, EdgeFamily>> families;
  for (int k = 0; k <= cells(); ++k) {
    for (int j = 0; j < n_; ++j) {
      const Index centre = node_index(n_, k, n_), a = node_index(n_, k, j),
                  b = node_index(n_, k, (j + 1) % n_);
      panels_.push_back({centre, a, b});
      families.emplace_back(edge(a, b), EdgeFamily::PolygonEdge);
      families.emplace_back(edge(centre, a), EdgeFamily::PolygonSpoke);
    }
  }
  for (int i = 0; i < cells(); ++i) {
    for (int j = 0; j < n_; ++j) {
      const int j1 = (j + 1) % n_;
      const Index bj = node_index(n_, i, j), bj1 = node_index(n_, i, j1);
      const Index tj = node_index(n_, i + 1, j), tj1 = node_index(n_, i + 1, j1);
      if (chirality_[i] > 0) {
        panels_.push_back({bj, bj1, tj1});
        panels_.push_back({bj, tj1, tj});
        families.emplace_back(edge(bj, tj1), EdgeFamily::Valley);
      } else {
        panels_.push_back({bj, bj1, tj});
        panels_.push_back({bj1, tj1, tj});
        families.emplace_back(edge(bj1, tj), EdgeFamily::Valley);
      }
      families.emplace_back(edge(bj, tj), EdgeFamily::Mountain);
    }
  }
  std::sort(families.begin(), families.end());
  families_ = std::move(families);

  if (parameters_.duplicate_shared_edges) {
    // The duplicated topology depends on node numbers only: build it once.
    NodeMatrix placeholder = NodeMatrix::Zero((cells() + 1) * (n_ + 1), 3);
    build_topology_for(placeholder, bars_, bar_family_, hinges_, hinge_family_);
    cached_ = true;
  }
}

void KreslingSpecimenBuilder::build_topology_for(const NodeMatrix& X,
                                                 std::vector<std::array<Index, 2>>& bars,
                                                 std::vector<EdgeFamily>& bar_family,
                                                 std::vector<std::array<Index, 4>>& hinges,
                                                 std::vector<EdgeFamily>& hinge_family) const {
  const Topology topo =
      build_topology(X, panels_, PanelSplit::N4B5, parameters_.duplicate_shared_edges);
  auto family_of = [&](Index a, Index b) {
    const Edge e = edge(a, b);
    const auto it = std::lower_bound(families_.begin(), families_.end(), std::make_pair(e, EdgeFamily::Valley));
    return it->second;
  };
  bars = topo.bars;
  hinges = topo.hinges;
  bar_family.clear();
  hinge_family.clear();
  for (const auto& b : bars) bar_family.push_back(family_of(b[0], b[1]));
  for (const auto& h : hinges) hinge_family.push_back(family_of(h[0], h[1]));
}

NodeMatrix KreslingSpecimenBuilder::place_nodes(const geometry::Design& design,
                                                const std::vector<int>& states,
                                                std::vector<double>& heights,
                                                std::vector<double>& angles) const {
  const double R = design.parameters().R;
  heights.assign(cells() + 1, 0.0);
  angles.assign(cells() + 1, 0.0);
  for (int i = 0; i < cells(); ++i) {
    const auto state = static_cast<geometry::State>(states[i]);
    heights[i + 1] = heights[i] + design.height(state);
    angles[i + 1] = angles[i] + chirality_[i] * design.twist(state);
  }
  NodeMatrix X((cells() + 1) * (n_ + 1), 3);
  for (int k = 0; k <= cells(); ++k) {
    for (int j = 0; j < n_; ++j) {
      const double a = angles[k] + kTwoPi * j / n_;
      X.row(node_index(n_, k, j)) << R * std::cos(a), R * std::sin(a), heights[k];
    }
    X.row(node_index(n_, k, n_)) << 0.0, 0.0, heights[k];
  }
  return X;
}

KreslingSpecimen KreslingSpecimenBuilder::build(const geometry::Design& design,
                                                const std::vector<int>& states,
                                                std::vector<std::uint8_t> fixed) const {
  if (design.parameters().n != n_) {
    throw_invalid("design.n", design.parameters().n, "the builder's n = " + std::to_string(n_));
  }
  if (static_cast<int>(states.size()) != cells()) {
    throw std::invalid_argument("states: has " + std::to_string(states.size()) +
                                " entries but chirality has " + std::to_string(cells()) +
                                "; give one per cell");
  }
  for (std::size_t i = 0; i < states.size(); ++i) {
    if (states[i] != 0 && states[i] != 1) {
      throw_invalid("states[" + std::to_string(i) + "]", states[i], "0 (contracted) or 1 (extended)");
    }
  }
  KreslingSpecimen s{Model(NodeMatrix::Zero(1, 3), {}, {}, {0, 0, 0}), {}, {}, {}, {}, n_, cells()};
  NodeMatrix X = place_nodes(design, states, s.level_height, s.level_angle);

  std::vector<std::array<Index, 2>> bar_nodes;
  std::vector<std::array<Index, 4>> hinge_nodes;
  if (cached_) {
    bar_nodes = bars_, hinge_nodes = hinges_;
    s.bar_family = bar_family_, s.hinge_family = hinge_family_;
  } else {
    build_topology_for(X, bar_nodes, s.bar_family, hinge_nodes, s.hinge_family);
  }

  const SpecimenParameters& p = parameters_;
  const double modulus = p.modulus_factor * p.kf;
  std::vector<Bar> bars(bar_nodes.size());
  for (std::size_t i = 0; i < bars.size(); ++i) {
    const auto& b = bar_nodes[i];
    const double area = s.bar_family[i] == EdgeFamily::Mountain ? p.mountain_area : p.material_area;
    bars[i] = {b, area, (X.row(b[1]) - X.row(b[0])).norm(), {p.bar_law, modulus}};
  }
  const elements::SpringLaw law{elements::SpringLawKind::EnhancedLinear, p.theta1, p.theta2};
  std::vector<Hinge> hinges(hinge_nodes.size());
  for (std::size_t i = 0; i < hinges.size(); ++i) {
    const auto& h = hinge_nodes[i];
    const double angle = elements::dihedral_angle(X.row(h[0]), X.row(h[1]), X.row(h[2]),
                                                  X.row(h[3]), p.hinge_angle);
    hinges[i] = {h, hinge_factor(s.hinge_family[i], p) * p.kf, angle,
                 (X.row(h[1]) - X.row(h[0])).norm(), law, p.hinge_angle};
  }
  if (fixed.empty()) fixed.assign(static_cast<std::size_t>(3 * X.rows()), 0);
  s.model = Model(std::move(X), std::move(bars), std::move(hinges), std::move(fixed));
  return s;
}

KreslingSpecimen build_kresling_specimen(const geometry::Design& design,
                                         const std::vector<int>& states,
                                         const std::vector<int>& chirality,
                                         const SpecimenParameters& parameters,
                                         std::vector<std::uint8_t> fixed) {
  if (states.empty()) throw std::invalid_argument("states: the specimen needs at least one cell");
  if (chirality.size() != states.size()) {
    throw std::invalid_argument("chirality: has " + std::to_string(chirality.size()) +
                                " entries but states has " + std::to_string(states.size()) +
                                "; give one per cell");
  }
  return KreslingSpecimenBuilder(design.parameters().n, chirality, parameters)
      .build(design, states, std::move(fixed));
}

}  // namespace kresling::model
