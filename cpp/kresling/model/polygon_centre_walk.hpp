#pragma once
/// \file polygon_centre_walk.hpp
/// The N5B8 centre of a planar polygon found by walking the arrangement of its diagonal
/// lines, for polygons too large to try every crossing of two diagonals.
///
/// For a planar polygon the centre objective (panel_centre.hpp) is, in the polygon's
/// plane, sum_k w_k |n_k . x - c_k| over its D = m (m - 3) / 2 diagonal lines (unit normals
/// n_k, weights w_k = 1 / |diagonal k|): convex and piecewise linear, least at a crossing of
/// two lines. Trying every crossing costs D^3 / 2 (a 64-gon: 4e9 operations, a 300-gon:
/// 1e9 candidates that do not fit in memory). The walk is the simplex method of this L1
/// problem instead: from the better of MERLIN2's two starting points it moves in the
/// steepest of the directions that can descend (along the lines through the current
/// point, across them where they are all parallel, down the gradient where there are
/// none), to the lowest point of that ray (a weighted median of its crossings, exact); it
/// stops where none of them descends, which on a convex piecewise linear function is the
/// minimum. Each move costs O(D log D); every move lowers the objective, so none repeats.

#include <vector>

#include "kresling/core/types.hpp"

namespace kresling::model {

/// The minimiser of the planar centre objective of `corners` (m >= 4, in order around the
/// polygon), computed in the plane through their mean with Newell's normal; corners off
/// that plane are projected onto it.
Vector3 planar_polygon_centre_walk(const std::vector<Vector3>& corners);

}  // namespace kresling::model
