#pragma once
/// \file panel_elements.hpp
/// The bars and hinges of a crease pattern given as panels, built by the rules of MERLIN2
/// v1.1 (docs/model.md, 'Topology'), element for element and in its order, so that a model
/// built here can be compared with one MERLIN2 built.
///
/// Bend hinges come first, panel by panel:
/// - N4B5: a quad gets one bend hinge on its shorter diagonal, (d0, d1, w0, w1) with the
///   diagonal's corners d and the other two corners w (on a tie, the diagonal p0-p2); a
///   larger panel is cut recursively along its shortest diagonal and every cut is a bend
///   hinge with the two corners adjacent to both its ends as wings.
/// - N5B8: a quad or larger panel gets a centre node c (panel_centre.hpp) and one bend hinge
///   per corner k, (c, p_k, p_(k-1), p_(k+1)).
/// Triangles are then the panels' pieces, each sorted, de-duplicated and sorted by rows.
/// Every pair of triangles sharing an edge that is not a bend axis is a fold hinge
/// (a, b, c, d) with a < b, c in the lower-numbered triangle; pairs are listed by the
/// higher-numbered triangle, then the lower. Edges of one triangle are the boundary.
/// Bars lie on the bend axes, the fold axes and the boundary edges, in that order.

#include <array>
#include <vector>

#include "kresling/core/types.hpp"
#include "kresling/model/topology.hpp"

namespace kresling::model {

struct PanelElements {
  NodeMatrix nodes;                             ///< the pattern's vertices, then centre nodes
  std::vector<Index> panel_centre;              ///< centre node of each panel, -1 if none
  std::vector<std::array<Index, 3>> triangles;  ///< ascending rows, sorted, unique
  std::vector<std::array<Index, 4>> bends;      ///< bend hinges (axis, axis, wing, wing)
  std::vector<Index> bend_panel;                ///< the panel each bend hinge lies in
  std::vector<std::array<Index, 4>> folds;      ///< fold hinges, axis ascending
  std::vector<std::array<Index, 2>> boundary;   ///< edges of one triangle, ascending, sorted

  /// Bars: bend axes, fold axes, boundary edges (this order).
  std::vector<std::array<Index, 2>> bars() const;
};

/// Where N5B8 puts a panel's centre node: MERLIN2's rules (panel_centre.hpp) or the mean of
/// the panel's corners.
enum class CentreRule : int { Merlin2 = 0, Mean = 1 };

/// Build the elements. Panels list vertex indices in order around each panel (>= 3).
/// Throws std::invalid_argument naming the panel for one with fewer than 3 vertices, an
/// out-of-range or repeated vertex, or a quad whose diagonals are parallel or degenerate.
PanelElements build_panel_elements(const NodeMatrix& vertices,
                                   const std::vector<std::vector<Index>>& panels,
                                   PanelSplit split,
                                   CentreRule centre_rule = CentreRule::Merlin2);

/// MERLIN2's N4B5 cut of a polygon with more than 3 corners: its diagonals as local corner
/// pairs (i < j), the shortest first (the first in column order on a tie), recursively.
std::vector<std::array<Index, 2>> polygon_diagonal_cuts(const std::vector<Vector3>& corners);

}  // namespace kresling::model
