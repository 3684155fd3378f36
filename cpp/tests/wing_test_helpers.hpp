#pragma once
// One hinge's turning wing: the nodes and stiff bars both the fold-snap and the driven rest
// angle tests build their hinge on.

#include <vector>

#include "kresling/core/types.hpp"
#include "kresling/model/bar_family.hpp"

namespace kresling::test {

// Axis 0 -> 1 along x, the held wing's node 2 at -y, the turning wing's node 3 at +y (at
// radius 1 from the axis).
inline NodeMatrix wing_nodes() {
  NodeMatrix X(4, 3);
  X << 0, 0, 0, 1, 0, 0, 0.5, -1, 0, 0.5, 1, 0;
  return X;
}

// The turning wing's two bars to the axis' ends (linear, EA = 1e6 N: rigid beside the
// hinge), at their lengths in X.
inline std::vector<model::Bar> wing_bars(const NodeMatrix& X) {
  std::vector<model::Bar> bars(2);
  bars[0].nodes = {0, 3};
  bars[1].nodes = {1, 3};
  for (auto& b : bars) {
    b.rest_length = (X.row(b.nodes[1]) - X.row(b.nodes[0])).norm();
    b.law = {elements::BarLawKind::Linear, 1e6};
  }
  return bars;
}

}  // namespace kresling::test
