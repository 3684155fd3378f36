#pragma once
/// \file hinge_family.hpp
/// Rotational-spring hinges on the dihedral angle of four nodes (kernel: elements/hinge.hpp).

#include <array>
#include <string>
#include <vector>

#include "kresling/elements/dihedral.hpp"
#include "kresling/elements/spring_laws.hpp"
#include "kresling/model/element_family.hpp"

namespace kresling::model {

/// A rotational spring about the axis nodes[0] -> nodes[1] with wings nodes[2], nodes[3].
struct Hinge {
  std::array<Index, 4> nodes{};
  double stiffness = 0.0;   ///< kp, moment per radian per unit length
  double rest_angle = 0.0;  ///< theta0 in [0, 2 pi)
  double length = 0.0;      ///< L0, multiplies the law (the rest length of the axis)
  elements::SpringLaw law;
  /// How the angle is computed: exactly (atan2), or as MERLIN2 does to reproduce its runs.
  elements::DihedralForm form = elements::DihedralForm::Exact;

  /// The hinge's dihedral angle with the nodes at `x` (rows of node positions).
  double angle(const NodeMatrix& x) const;
};

/// Throw std::invalid_argument (naming hinge `index`) when its nodes are out of range or
/// repeated, its axis has zero length, or a wing lies on the axis line: the dihedral angle
/// is undefined there. `scale` is the model's extent (the length the tolerances scale with).
void check_hinge_geometry(const NodeMatrix& X, const std::array<Index, 4>& nodes,
                          std::size_t index, double scale);

/// Table columns: nodes (4 per hinge), stiffness, rest_angle, length, law (the
/// SpringLawKind's code), theta1, theta2 (the enhanced linear law's limits), and optionally
/// angle_form (the DihedralForm's code; absent: every angle exact).
class HingeFamily final : public ElementFamily {
 public:
  explicit HingeFamily(std::vector<Hinge> hinges) : hinges_(std::move(hinges)) {}
  static FamilyPtr from_table(const Table& table);

  const std::vector<Hinge>& elements() const { return hinges_; }
  const char* name() const override { return "hinges"; }
  std::size_t size() const override { return hinges_.size(); }
  std::vector<Index> element_dofs(std::size_t e) const override;
  void check(const NodeMatrix& X, double scale) const override;
  double assemble(const NodeMatrix& X, const VectorX& u, AssemblyTarget& target) const override;
  void add_state(const NodeMatrix& x, ElementState& state) const override;
  Table table() const override;
  std::vector<std::string> parameters() const override;
  void parameter_derivative(const NodeMatrix& X, const VectorX& u, const std::string& name,
                            ParameterDerivative& out) const override;
  void parameter_derivatives(const NodeMatrix& X, const VectorX& u,
                             const std::vector<std::string>& names,
                             std::vector<ParameterDerivative>& outs) const override;
  void reference_geometry_derivative(const NodeMatrix& X, const std::string& name,
                                     std::vector<ParameterDerivative::Triplet>& out) const override;

 private:
  std::vector<Hinge> hinges_;
};

}  // namespace kresling::model
