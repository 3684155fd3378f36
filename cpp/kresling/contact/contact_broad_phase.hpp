#pragma once
/// \file contact_broad_phase.hpp
/// The contact broad phase: the point-triangle and edge-edge pairs of a triangle mesh that
/// may be closer than a distance d, found in O(n log n) with a bounding-volume hierarchy
/// (contact_box_tree.hpp), for the exact distances and barriers to be evaluated on.
///
///          t2                      A pair is a candidate when the axis-aligned box of one
///         /  \     o p             primitive, grown by d on every side, overlaps the box
///        /    \                    of the other: every pair closer than d is one.
///      t0 ---- t1
///
/// Excluded, so that a crease is not a contact: a node against a triangle it belongs to and
/// two edges with a common end (their distance is zero by construction). A panel's free
/// corner still meets the face of its neighbour across a crease, and so do edges of
/// neighbouring panels that share no node. The points are the nodes of the triangles
/// (nodes on no triangle take no part); the edges are the triangles' edges, each once.
/// With a displacement, each box covers the primitive at x and at x + dx (a swept box), so
/// that the candidates cover a linear step from x to x + dx for continuous collision
/// detection.

#include <array>
#include <vector>

#include "kresling/core/types.hpp"

namespace kresling::contact {

/// Triangles as rows of three node indices.
using TriangleMatrix = Eigen::Matrix<Index, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// Edges as rows of two node indices.
using EdgeMatrix = Eigen::Matrix<Index, Eigen::Dynamic, 2, Eigen::RowMajor>;

/// The edges of the triangles, each once, as rows (i, j) with i < j in increasing order.
EdgeMatrix triangle_edges(const Eigen::Ref<const TriangleMatrix>& triangles);

/// Candidate pairs, each once, sorted.
struct ContactCandidates {
  std::vector<std::array<Index, 2>> point_triangle;  ///< (node, triangle row)
  std::vector<std::array<Index, 2>> edge_edge;       ///< (edge row a, edge row b), a < b
};

/// Nodes that count as one for the exclusions above: `joined[i]` is node i's
/// representative (the two sides of a cut, coincident at rest, are one node there, so that
/// a cut is not a contact either). Empty: every node is its own.
using JoinedNodes = std::vector<Index>;

/// The candidates at positions `nodes` (n x 3) for distance d >= 0. `edges` must be
/// triangle_edges(triangles) (passed in so that a caller builds it once per mesh).
ContactCandidates contact_candidates(const Eigen::Ref<const NodeMatrix>& nodes,
                                     const Eigen::Ref<const TriangleMatrix>& triangles,
                                     const Eigen::Ref<const EdgeMatrix>& edges, double distance,
                                     const JoinedNodes& joined = {});

/// The candidates for a linear step from `nodes` to `nodes + displacement` (swept boxes).
ContactCandidates contact_candidates(const Eigen::Ref<const NodeMatrix>& nodes,
                                     const Eigen::Ref<const TriangleMatrix>& triangles,
                                     const Eigen::Ref<const EdgeMatrix>& edges, double distance,
                                     const Eigen::Ref<const NodeMatrix>& displacement,
                                     const JoinedNodes& joined = {});

/// Throw std::invalid_argument naming the argument unless every triangle and edge names
/// nodes in [0, node_count), no triangle repeats a node, the distance is finite and >= 0
/// and the positions are finite.
void check_contact_mesh(const Eigen::Ref<const NodeMatrix>& nodes,
                        const Eigen::Ref<const TriangleMatrix>& triangles,
                        const Eigen::Ref<const EdgeMatrix>& edges, double distance);

}  // namespace kresling::contact
