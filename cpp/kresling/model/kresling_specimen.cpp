#include "kresling/model/kresling_specimen.hpp"

#include <cmath>
#include <map>
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

double family_factor(EdgeFamily f, const SpecimenParameters& p) {
  switch (f) {
    case EdgeFamily::Valley: return p.valley_factor;
    case EdgeFamily::Mountain: return p.mountain_factor;
    case EdgeFamily::PolygonEdge: return p.polygon_edge_factor;
    case EdgeFamily::PolygonSpoke: return p.spoke_factor;
  }
  return 0.0;
}

}  // namespace

KreslingSpecimen build_kresling_specimen(const geometry::Design& design,
                                         const std::vector<int>& states,
                                         const std::vector<int>& chirality,
                                         const SpecimenParameters& parameters,
                                         std::vector<std::uint8_t> fixed) {
  const int cells = static_cast<int>(states.size());
  if (cells == 0) throw std::invalid_argument("states: the specimen needs at least one cell");
  if (chirality.size() != states.size()) {
    throw std::invalid_argument("chirality: has " + std::to_string(chirality.size()) +
                                " entries but states has " + std::to_string(cells) +
                                "; give one per cell");
  }
  for (int i = 0; i < cells; ++i) {
    if (states[i] != 0 && states[i] != 1) {
      throw_invalid("states[" + std::to_string(i) + "]", states[i], "0 (contracted) or 1 (extended)");
    }
    if (chirality[i] != 1 && chirality[i] != -1) {
      throw_invalid("chirality[" + std::to_string(i) + "]", chirality[i], "+1 or -1");
    }
  }
  check_parameters(parameters);

  const int n = design.parameters().n;
  const double R = design.parameters().R;
  KreslingSpecimen s{Model(NodeMatrix::Zero(1, 3), {}, {}, {0, 0, 0}), {}, {}, {}, {}, n, cells};
  s.level_height.assign(cells + 1, 0.0);
  s.level_angle.assign(cells + 1, 0.0);
  for (int i = 0; i < cells; ++i) {
    const auto state = static_cast<geometry::State>(states[i]);
    s.level_height[i + 1] = s.level_height[i] + design.height(state);
    s.level_angle[i + 1] = s.level_angle[i] + chirality[i] * design.twist(state);
  }

  NodeMatrix X((cells + 1) * (n + 1), 3);
  for (int k = 0; k <= cells; ++k) {
    for (int j = 0; j < n; ++j) {
      const double a = s.level_angle[k] + kTwoPi * j / n;
      X.row(s.node(k, j)) << R * std::cos(a), R * std::sin(a), s.level_height[k];
    }
    X.row(s.node(k, n)) << 0.0, 0.0, s.level_height[k];
  }

  std::vector<std::vector<Index>> panels;
  std::map<Edge, EdgeFamily> family;
  for (int k = 0; k <= cells; ++k) {
    for (int j = 0; j < n; ++j) {
      const int j1 = (j + 1) % n;
      panels.push_back({s.node(k, n), s.node(k, j), s.node(k, j1)});
      family[edge(s.node(k, j), s.node(k, j1))] = EdgeFamily::PolygonEdge;
      family[edge(s.node(k, n), s.node(k, j))] = EdgeFamily::PolygonSpoke;
    }
  }
  for (int i = 0; i < cells; ++i) {
    for (int j = 0; j < n; ++j) {
      const int j1 = (j + 1) % n;
      const Index bj = s.node(i, j), bj1 = s.node(i, j1), tj = s.node(i + 1, j), tj1 = s.node(i + 1, j1);
      if (chirality[i] > 0) {
        panels.push_back({bj, bj1, tj1});
        panels.push_back({bj, tj1, tj});
        family[edge(bj, tj1)] = EdgeFamily::Valley;
      } else {
        panels.push_back({bj, bj1, tj});
        panels.push_back({bj1, tj1, tj});
        family[edge(bj1, tj)] = EdgeFamily::Valley;
      }
      family[edge(bj, tj)] = EdgeFamily::Mountain;
    }
  }

  const Topology topo = build_topology(X, panels, PanelSplit::N4B5,
                                       parameters.duplicate_shared_edges);
  const double modulus = parameters.modulus_factor * parameters.kf;
  std::vector<Bar> bars;
  bars.reserve(topo.bars.size());
  for (const auto& b : topo.bars) {
    const EdgeFamily f = family.at(edge(b[0], b[1]));
    s.bar_family.push_back(f);
    const double area = f == EdgeFamily::Mountain ? parameters.mountain_area : parameters.material_area;
    bars.push_back({b, area, (X.row(b[1]) - X.row(b[0])).norm(), {parameters.bar_law, modulus}});
  }
  std::vector<Hinge> hinges;
  hinges.reserve(topo.hinges.size());
  const elements::SpringLaw law{elements::SpringLawKind::EnhancedLinear, parameters.theta1,
                                parameters.theta2};
  for (const auto& h : topo.hinges) {
    const EdgeFamily f = family.at(edge(h[0], h[1]));
    s.hinge_family.push_back(f);
    const double angle =
        elements::dihedral_angle(X.row(h[0]), X.row(h[1]), X.row(h[2]), X.row(h[3]));
    hinges.push_back({h, family_factor(f, parameters) * parameters.kf, angle,
                      (X.row(h[1]) - X.row(h[0])).norm(), law});
  }
  if (fixed.empty()) fixed.assign(static_cast<std::size_t>(3 * X.rows()), 0);
  s.model = Model(std::move(X), std::move(bars), std::move(hinges), std::move(fixed));
  return s;
}

}  // namespace kresling::model
