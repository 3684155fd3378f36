#pragma once
/// \file cable_family.hpp
/// Sliding cables (tendons) through guide nodes, tension only (kernel: elements/cable.hpp).

#include <string>
#include <vector>

#include "kresling/model/element_family.hpp"

namespace kresling::model {

/// A tendon through nodes[0] (anchor), nodes[1..k-2] (frictionless guides) and nodes[k-1]
/// (anchor): tension only, energy from its total length (elements/cable.hpp).
struct Cable {
  std::vector<Index> nodes;  ///< k >= 2 distinct nodes, in the order the cable runs
  double stiffness = 0.0;    ///< axial rigidity EA [N]
  double rest_length = 0.0;  ///< L [mm]: the actuation input (pulling shortens it)
};

/// Most nodes a cable may pass through (its 3k x 3k tangent's entries are indexed in 16 bits).
constexpr std::size_t kMaxCableNodes = 85;

/// Table columns: nodes (every cable's nodes, one after another), node_count (per cable),
/// stiffness, rest_length.
class CableFamily final : public ElementFamily {
 public:
  explicit CableFamily(std::vector<Cable> cables) : cables_(std::move(cables)) {}
  static FamilyPtr from_table(const Table& table);

  const std::vector<Cable>& elements() const { return cables_; }
  const char* name() const override { return "cables"; }
  std::size_t size() const override { return cables_.size(); }
  std::vector<Index> element_dofs(std::size_t e) const override { return node_dofs(cables_[e].nodes); }
  void check(const NodeMatrix& X, double scale) const override;
  double assemble(const NodeMatrix& X, const VectorX& u, AssemblyTarget& target) const override;
  void add_state(const NodeMatrix& x, ElementState& state) const override;
  Table table() const override;
  std::vector<std::string> parameters() const override;
  void parameter_derivative(const NodeMatrix& X, const VectorX& u, const std::string& name,
                            ParameterDerivative& out) const override;

 private:
  std::vector<Cable> cables_;
};

}  // namespace kresling::model
