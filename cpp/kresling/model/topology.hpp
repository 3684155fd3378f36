#pragma once
/// \file topology.hpp
/// From panels to bars and hinges (docs/model.md, 'Topology': the rules as MERLIN2 applies them).
///
/// Panels are split into triangles: a triangle stays; a quad is split on its shorter
/// diagonal (N4B5) or around a new centre node (N5B8); a larger polygon is split recursively
/// along its shortest diagonal (N4B5) or fanned around a centre node (N5B8). Edges added
/// inside a panel carry *bend* hinges; edges between panels carry *fold* hinges.
///
/// Triangles are then put in canonical order (each triangle's nodes ascending, rows
/// ascending), and every pair of triangles sharing an edge gets one hinge and one bar; an
/// edge in k triangles therefore carries k(k-1)/2 coincident bars and hinges, which is what
/// MERLIN2 builds and what reproduces its numbers. The de-duplicated alternative puts one
/// bar on every edge and, on an edge of k > 2 triangles, hinges only between angularly
/// consecutive triangles, leaving out the pair across the widest opening.

#include <array>
#include <cstdint>
#include <vector>

#include "kresling/core/types.hpp"

namespace kresling::model {

enum class PanelSplit : int { N4B5 = 0, N5B8 = 1 };

struct Topology {
  NodeMatrix nodes;                            ///< the input nodes, then N5B8 centre nodes
  std::vector<std::array<Index, 3>> triangles; ///< canonical order
  std::vector<Index> triangle_panel;           ///< the panel each triangle came from
  std::vector<std::array<Index, 2>> bars;      ///< end nodes, ascending
  std::vector<std::array<Index, 4>> hinges;    ///< (a, b, c, d): axis a < b, wings c, d
  std::vector<std::uint8_t> hinge_is_bend;     ///< 1 for an edge added inside a panel
};

/// Build the topology. Panels list node indices in order around the panel (>= 3 each).
/// Throws std::invalid_argument for an empty or out-of-range panel or a repeated node.
Topology build_topology(const NodeMatrix& nodes, const std::vector<std::vector<Index>>& panels,
                        PanelSplit split, bool duplicate_shared_edges = true);

}  // namespace kresling::model
