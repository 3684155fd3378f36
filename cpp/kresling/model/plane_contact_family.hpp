#pragma once
/// \file plane_contact_family.hpp
/// Contact of nodes with rigid planes (a floor, a wall): IPC's barrier on each node's
/// distance from each plane (kernels: contact/contact_barrier.hpp, contact_ccd.hpp). The
/// energy is zero at distances of d_hat and more and grows without bound as a node reaches
/// a plane; a node stays on the side of each plane where it starts. Newton's corrections are
/// shortened by a continuous collision check (step_limit), so no step crosses a plane.
///
/// Thickness t >= 0 (the panels'): a node, on the panels' mid-surface, is kept t/2 off each
/// plane, the barrier acting on its distance less t/2 (contact_offset.hpp) while that is
/// below d_hat.

#include <vector>

#include "kresling/model/element_family.hpp"

namespace kresling::model {

struct ContactPlane {
  Vector3 origin = Vector3::Zero();  ///< a point of the plane [mm]
  Vector3 normal = Vector3::UnitZ(); ///< its normal (any non-zero length)
};

/// Elements: every (node, plane) pair, node-major. Table columns: nodes (the nodes that
/// touch), origin (3 per plane), normal (3 per plane), distance (d_hat [mm], one value),
/// stiffness (kappa [N/mm^3], one value), thickness (t [mm], one value; absent: 0).
class PlaneContactFamily final : public ElementFamily {
 public:
  PlaneContactFamily(std::vector<Index> nodes, std::vector<ContactPlane> planes, double d_hat,
                     double stiffness, double thickness = 0.0);
  static FamilyPtr from_table(const Table& table);

  const char* name() const override { return "contact"; }
  std::size_t size() const override { return nodes_.size() * planes_.size(); }
  std::vector<Index> element_dofs(std::size_t e) const override;
  void check(const NodeMatrix& X, double scale) const override;
  double assemble(const NodeMatrix& X, const VectorX& u, AssemblyTarget& target) const override;
  /// Columns: contact_gap (per pair, the node's distance from the plane less t/2 [mm]),
  /// contact_energy (per pair [N mm]) and contact_force (per pair, the plane's force on the
  /// node: 3 components [N]).
  void add_state(const NodeMatrix& x, ElementState& state) const override;
  Table table() const override;
  bool limits_steps() const override { return true; }
  double step_limit(const NodeMatrix& X, const VectorX& u, const VectorX& du) const override;

 private:
  std::vector<Index> nodes_;
  std::vector<ContactPlane> planes_;
  double d_hat_, stiffness_;
  double offset_;  // t/2: a node's smallest distance from a plane
};

}  // namespace kresling::model
