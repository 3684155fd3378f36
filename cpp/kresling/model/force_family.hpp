#pragma once
/// \file force_family.hpp
/// Forces held at nodes whatever the structure does (dead loads): the loads a stage of a
/// run leaves applied, carried into the stages after it as part of the model.

#include <string>
#include <vector>

#include "kresling/model/element_family.hpp"

namespace kresling::model {

/// A constant force on one node.
struct HeldForce {
  Index node = 0;
  Vector3 force = Vector3::Zero();  ///< [N]
};

/// Table columns: nodes (1 per force), force (3). The energy is the forces' potential,
/// E = -sum f . u; the internal force -f at each node; no stiffness.
class ForceFamily final : public ElementFamily {
 public:
  explicit ForceFamily(std::vector<HeldForce> forces) : forces_(std::move(forces)) {}
  static FamilyPtr from_table(const Table& table);

  const std::vector<HeldForce>& elements() const { return forces_; }
  const char* name() const override { return "forces"; }
  std::size_t size() const override { return forces_.size(); }
  std::vector<Index> element_dofs(std::size_t e) const override;
  void check(const NodeMatrix& X, double scale) const override;
  double assemble(const NodeMatrix& X, const VectorX& u, AssemblyTarget& target) const override;
  void add_state(const NodeMatrix& x, ElementState& state) const override;
  Table table() const override;
  std::vector<std::string> parameters() const override;
  void parameter_derivative(const NodeMatrix& X, const VectorX& u, const std::string& name,
                            ParameterDerivative& out) const override;

 private:
  std::vector<HeldForce> forces_;
};

}  // namespace kresling::model
