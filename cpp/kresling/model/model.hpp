#pragma once
/// \file model.hpp
/// A bar-and-hinge model: nodes, supports and element families (bars, rotational-spring
/// hinges, sliding cables, and any other registered family; element_family.hpp). Immutable
/// once built; the constructor validates everything and names the offending element.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "kresling/core/types.hpp"
#include "kresling/model/bar_family.hpp"
#include "kresling/model/cable_family.hpp"
#include "kresling/model/element_family.hpp"
#include "kresling/model/hinge_family.hpp"

namespace kresling::model {

/// check_hinge_geometry with the tolerances scaled by the extent of X: for callers that
/// compute angles before a Model exists (default rest angles). Model validates every hinge
/// with the same rule.
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
  /// A model of any families (at most one of each name). They are held in the registry's
  /// order (family_registry.hpp), unregistered ones after it in the order given; bars,
  /// hinges and cables are always present (empty when not given). Validates as above and
  /// with every family's own check.
  Model(NodeMatrix nodes, std::vector<std::uint8_t> fixed, std::vector<FamilyPtr> families);

  Index num_nodes() const { return nodes_.rows(); }
  Index num_dofs() const { return 3 * nodes_.rows(); }
  const NodeMatrix& nodes() const { return nodes_; }
  const std::vector<std::uint8_t>& fixed() const { return fixed_; }

  /// Every family the model holds, in assembly order.
  const std::vector<FamilyPtr>& families() const { return families_; }
  /// The family named `name`, or null.
  const ElementFamily* family(const std::string& name) const;
  /// The first family of type F, or null.
  template <typename F>
  const F* find() const {
    for (const auto& f : families_) {
      if (const auto* typed = dynamic_cast<const F*>(f.get())) return typed;
    }
    return nullptr;
  }

  const std::vector<Bar>& bars() const { return bars_->elements(); }
  const std::vector<Hinge>& hinges() const { return hinges_->elements(); }
  const std::vector<Cable>& cables() const { return cables_->elements(); }

  /// A copy with the family of `family`'s name replaced by it (or added), validated.
  Model with_family(FamilyPtr family) const;
  /// A copy with the cables' rest lengths replaced (one per cable, positive): how a tendon
  /// is pulled. Same elements, so an Assembler can rebind to it.
  Model with_cable_rest_lengths(const std::vector<double>& rest_lengths) const;

  /// Node coordinates X + u, with u ordered like the DOFs.
  NodeMatrix deformed(const VectorX& u) const;

 private:
  void adopt(std::vector<FamilyPtr> families);
  void validate() const;

  NodeMatrix nodes_;
  std::vector<std::uint8_t> fixed_;
  std::vector<FamilyPtr> families_;
  // The built-in families, also in families_ (never null).
  const BarFamily* bars_ = nullptr;
  const HingeFamily* hinges_ = nullptr;
  const CableFamily* cables_ = nullptr;
};

}  // namespace kresling::model
