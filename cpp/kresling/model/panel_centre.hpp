#pragma once
/// \file panel_centre.hpp
/// Where the N5B8 split puts a panel's centre node (docs/model.md, 'Topology').
///
///   quad p0 p1 p2 p3:            polygon p0 ... p(m-1), m > 4:
///
///     p3 ------- p2                 the point X minimising, over non-adjacent corner
///      |  \   /  |                  pairs (i, j),
///      |    X    |                    sum |(p_j - X) x (p_i - X)| / |p_j - p_i|^2
///      |  /   \  |                  (twice the area of the triangle X p_i p_j, scaled by
///     p0 ------- p1                 the squared diagonal length)
///
/// A quad's centre lies on its shorter diagonal where the other diagonal's line comes
/// closest (for a planar quad: where the diagonals cross), so a warped quad bends along its
/// shorter diagonal. The polygon objective is convex; for a planar polygon it is piecewise
/// linear and its minimum lies where two diagonal lines cross, so every crossing is a
/// candidate and the best is exact (beyond kCrossingCorners corners the lowest crossing is
/// walked to instead of every one tried); a warped polygon's minimum is refined from the
/// best crossing by iteratively reweighted least squares.

#include <cstddef>
#include <vector>

#include "kresling/core/types.hpp"

namespace kresling::model {

/// The N5B8 centre of a quad (corners in order around it). Throws std::invalid_argument
/// when its diagonals are parallel or of zero length.
Vector3 quad_centre(const Vector3& p0, const Vector3& p1, const Vector3& p2, const Vector3& p3);

/// The objective the N5B8 centre of a polygon with more than 4 corners minimises at `x`.
double polygon_centre_objective(const std::vector<Vector3>& corners, const Vector3& x);

/// Largest polygon whose centre is chosen among every crossing of two of its diagonal lines
/// (D^3 / 2 operations for D diagonals: 8e6 at 24 corners); a larger one walks to the
/// lowest crossing (polygon_centre_walk.hpp), in O(D log D) per move.
inline constexpr std::size_t kCrossingCorners = 24;

/// The N5B8 centre of a polygon with more than 4 corners (in order around it).
Vector3 polygon_optimal_centre(const std::vector<Vector3>& corners);

}  // namespace kresling::model
