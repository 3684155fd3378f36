#pragma once
/// \file face_angle_family.hpp
/// Springs on the interior angles of the model's triangles (kernel:
/// elements/corner_angle.hpp): the panels' in-plane shear stiffness beside their bars, as
/// Origami Simulator models its faces. Each element is one triangle with its three corners'
/// rest angles and one stiffness.

#include <array>
#include <string>
#include <vector>

#include "kresling/model/element_family.hpp"

namespace kresling::model {

/// A triangle whose three interior angles are held near their rest values.
struct FaceAngles {
  std::array<Index, 3> nodes{};
  std::array<double, 3> rest_angle{};  ///< at nodes[0], nodes[1], nodes[2], in (0, pi) [rad]
  double stiffness = 0.0;              ///< k per corner [N mm/rad^2], >= 0
};

/// Table columns: nodes (3 per triangle), rest_angle (3), stiffness (1).
class FaceAngleFamily final : public ElementFamily {
 public:
  explicit FaceAngleFamily(std::vector<FaceAngles> faces) : faces_(std::move(faces)) {}
  static FamilyPtr from_table(const Table& table);

  const std::vector<FaceAngles>& elements() const { return faces_; }
  const char* name() const override { return "face_angles"; }
  std::size_t size() const override { return faces_.size(); }
  std::vector<Index> element_dofs(std::size_t e) const override;
  /// Nodes in range and distinct, the triangle not degenerate in X (its smallest angle above
  /// 1e-6 rad), rest angles in (0, pi), stiffness finite and >= 0.
  void check(const NodeMatrix& X, double scale) const override;
  double assemble(const NodeMatrix& X, const VectorX& u, AssemblyTarget& target) const override;
  /// Columns: face_angle_change (per triangle, the largest |alpha - alpha0| of its corners
  /// [rad]) and face_angle_energy [N mm].
  void add_state(const NodeMatrix& x, ElementState& state) const override;
  Table table() const override;
  std::vector<std::string> parameters() const override;
  void parameter_derivative(const NodeMatrix& X, const VectorX& u, const std::string& name,
                            ParameterDerivative& out) const override;
  void reference_geometry_derivative(const NodeMatrix& X, const std::string& name,
                                     std::vector<ParameterDerivative::Triplet>& out) const override;

 private:
  std::vector<FaceAngles> faces_;
};

}  // namespace kresling::model
