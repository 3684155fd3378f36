#pragma once
/// \file merlin2_rest_angle.hpp
/// Rest angles of hinges exactly as MERLIN2 v1.1 computes them when it builds a model
/// (its FoldKe under GNU Octave), for reproducing its runs bit for bit.
///
/// The formula is the one of dihedral.hpp, but the two normals' lengths come from Octave's
/// overflow-safe 2-norm (a running scale and a sum of squared ratios) rather than from the
/// square root of a sum of squares. For a hinge of a flat panel the arccosine's argument
/// sits within a few ulps of -1, where the arccosine turns an ulp into ~1e-8 rad, so the two
/// rest angles can differ by that much. It matters for the super-linear bend law, whose
/// tangent grows like |dtheta|^(1/3): MERLIN2's panels start with that offset, and its
/// first Newton iterations with the tangent it gives.

#include <array>
#include <vector>

#include "kresling/core/types.hpp"

namespace kresling::model {

/// The rest angle in [0, 2 pi) of hinge (a, b, c, d) as MERLIN2 v1.1 computes it.
double merlin2_rest_angle(const Vector3& a, const Vector3& b, const Vector3& c,
                          const Vector3& d);

/// Rest angles of many hinges (node rows of `nodes`).
std::vector<double> merlin2_rest_angles(const NodeMatrix& nodes,
                                        const std::vector<std::array<Index, 4>>& hinges);

}  // namespace kresling::model
