#pragma once
/// \file spring_family.hpp
/// Zero-length springs tying nodes to fixed points, per axis (kernel:
/// elements/anchor_spring.hpp).

#include <string>
#include <vector>

#include "kresling/model/element_family.hpp"

namespace kresling::model {

/// A node tied elastically to a fixed position.
struct AnchorSpring {
  Index node = 0;
  Vector3 stiffness = Vector3::Zero();  ///< k_x, k_y, k_z >= 0 [N/mm]
  Vector3 anchor = Vector3::Zero();     ///< the fixed point [mm]
};

/// Table columns: nodes (1 per spring), stiffness (3), anchor (3).
class SpringFamily final : public ElementFamily {
 public:
  explicit SpringFamily(std::vector<AnchorSpring> springs) : springs_(std::move(springs)) {}
  static FamilyPtr from_table(const Table& table);

  const std::vector<AnchorSpring>& elements() const { return springs_; }
  const char* name() const override { return "springs"; }
  std::size_t size() const override { return springs_.size(); }
  std::vector<Index> element_dofs(std::size_t e) const override;
  void check(const NodeMatrix& X, double scale) const override;
  double assemble(const NodeMatrix& X, const VectorX& u, AssemblyTarget& target) const override;
  void add_state(const NodeMatrix& x, ElementState& state) const override;
  Table table() const override;
  std::vector<std::string> parameters() const override;
  void parameter_derivative(const NodeMatrix& X, const VectorX& u, const std::string& name,
                            ParameterDerivative& out) const override;
  /// A DOF whose spring stiffness is positive is held near its anchor.
  void mark_grounded_dofs(std::vector<std::uint8_t>& grounded) const override;

 private:
  std::vector<AnchorSpring> springs_;
};

}  // namespace kresling::model
