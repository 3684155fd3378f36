#pragma once
/// \file model.hpp
/// A bar-and-hinge model: nodes, bars, rotational-spring hinges, optional sliding cables and
/// supports. Immutable once built; the constructor validates everything and names the
/// offending element.

#include <array>
#include <cstdint>
#include <vector>

#include "kresling/core/types.hpp"
#include "kresling/elements/bar_laws.hpp"
#include "kresling/elements/spring_laws.hpp"

namespace kresling::model {

/// An axial bar between two nodes.
struct Bar {
  std::array<Index, 2> nodes{};
  double area = 1.0;         ///< cross-section A
  double rest_length = 0.0;  ///< L
  elements::BarLaw law;      ///< law and modulus C0 (axial stiffness EA = C0 A)
};

/// A rotational spring about the axis nodes[0] -> nodes[1] with wings nodes[2], nodes[3].
struct Hinge {
  std::array<Index, 4> nodes{};
  double stiffness = 0.0;   ///< kp, moment per radian per unit length
  double rest_angle = 0.0;  ///< theta0 in [0, 2 pi)
  double length = 0.0;      ///< L0, multiplies the law (the rest length of the axis)
  elements::SpringLaw law;
};

/// A tendon through nodes[0] (anchor), nodes[1..k-2] (frictionless guides) and nodes[k-1]
/// (anchor): tension only, energy from its total length (elements/cable.hpp).
struct Cable {
  std::vector<Index> nodes;  ///< k >= 2 distinct nodes, in the order the cable runs
  double stiffness = 0.0;    ///< axial rigidity EA [N]
  double rest_length = 0.0;  ///< L [mm]: the actuation input (pulling shortens it)
};

/// Most nodes a cable may pass through (its 3k x 3k tangent's entries are indexed in 16 bits).
constexpr std::size_t kMaxCableNodes = 85;

/// Throw std::invalid_argument (naming hinge `index`) when its nodes are out of range or
/// repeated, its axis has zero length, or a wing lies on the axis line: the dihedral angle
/// is undefined there. Model validates every hinge with it; callers that compute angles
/// before a Model exists (default rest angles) use it too.
void check_hinge_geometry(const NodeMatrix& X, const std::array<Index, 4>& nodes,
                          std::size_t index);
/// The same check at a given length scale (`node_extent(X)`): a caller checking many
/// hinges computes the scale once (per hinge it costs a pass over every node).
void check_hinge_geometry_at_scale(const NodeMatrix& X, const std::array<Index, 4>& nodes,
                                   std::size_t index, double scale);
/// The length scale of the geometry checks: the diagonal of the nodes' bounding box [mm].
double node_extent(const NodeMatrix& X);

class Model {
 public:
  /// `fixed` has one entry per DOF (3 per node, x y z): nonzero = supported (u = 0).
  /// Throws std::invalid_argument naming the element and the problem for: non-finite or
  /// out-of-range data, repeated nodes in an element, zero-length bars, hinges whose wing
  /// lies on the axis line, negative or non-finite stiffness, bad spring limits; cables with
  /// fewer than 2 or more than kMaxCableNodes nodes, repeated nodes, coincident consecutive
  /// nodes, or a stiffness or rest length that is not positive.
  Model(NodeMatrix nodes, std::vector<Bar> bars, std::vector<Hinge> hinges,
        std::vector<std::uint8_t> fixed, std::vector<Cable> cables = {});

  Index num_nodes() const { return nodes_.rows(); }
  Index num_dofs() const { return 3 * nodes_.rows(); }
  const NodeMatrix& nodes() const { return nodes_; }
  const std::vector<Bar>& bars() const { return bars_; }
  const std::vector<Hinge>& hinges() const { return hinges_; }
  const std::vector<std::uint8_t>& fixed() const { return fixed_; }
  const std::vector<Cable>& cables() const { return cables_; }

  /// A copy with the cables' rest lengths replaced (one per cable, positive): how a tendon
  /// is pulled. Same elements, so an Assembler can rebind to it.
  Model with_cable_rest_lengths(const std::vector<double>& rest_lengths) const;

  /// Node coordinates X + u, with u ordered like the DOFs.
  NodeMatrix deformed(const VectorX& u) const;

 private:
  NodeMatrix nodes_;
  std::vector<Bar> bars_;
  std::vector<Hinge> hinges_;
  std::vector<std::uint8_t> fixed_;
  std::vector<Cable> cables_;
};

}  // namespace kresling::model
