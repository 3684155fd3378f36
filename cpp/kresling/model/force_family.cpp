#include "kresling/model/force_family.hpp"

#include <array>
#include <string>

#include "kresling/core/check.hpp"

namespace kresling::model {

std::vector<Index> ForceFamily::element_dofs(std::size_t e) const {
  const Index n = forces_[e].node;
  return {3 * n, 3 * n + 1, 3 * n + 2};
}

void ForceFamily::check(const NodeMatrix& X, double) const {
  for (std::size_t i = 0; i < forces_.size(); ++i) {
    require_element_nodes(*this, i, &forces_[i].node, 1, X.rows());
    for (int k = 0; k < 3; ++k) require_finite(element_name(i) + ": force", forces_[i].force[k]);
  }
}

double ForceFamily::assemble(const NodeMatrix& X, const VectorX& u, AssemblyTarget& target) const {
  // E = -f . u: the internal force is dE/du = -f; the tangent has nothing of it.
  double energy = 0.0;
  for (std::size_t e = 0; e < forces_.size(); ++e) {
    const HeldForce& f = forces_[e];
    energy -= f.force.dot(position(X, u, f.node) - X.row(f.node).transpose());
    const Vector3 internal = -f.force;
    add_local_force(internal, element_dofs(e), target.force);
  }
  return energy;
}

void ForceFamily::add_state(const NodeMatrix&, ElementState& state) const {
  const auto n = static_cast<Index>(forces_.size());
  VectorX magnitude(n);
  for (Index e = 0; e < n; ++e) magnitude[e] = forces_[e].force.norm();
  state.add("held_force", magnitude);
}

Table ForceFamily::table() const {
  std::vector<Index> nodes;
  std::vector<double> force;
  for (const HeldForce& f : forces_) {
    nodes.push_back(f.node);
    force.insert(force.end(), f.force.data(), f.force.data() + 3);
  }
  return {{"nodes", index_column(nodes)}, {"force", real_column(force, 3)}};
}

FamilyPtr ForceFamily::from_table(const Table& t) {
  require_known_columns(t, "forces", {"nodes", "force"});
  const Index n = column_rows(t, "forces", "nodes", true, 1);
  const auto& nodes = require_column(t, "forces", "nodes", true, 1).indices;
  const auto& force = require_column(t, "forces", "force", false, 3, n).reals;
  std::vector<HeldForce> forces(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) {
    forces[i].node = nodes[i];
    forces[i].force = Vector3(force[3 * i], force[3 * i + 1], force[3 * i + 2]);
  }
  return std::make_shared<ForceFamily>(std::move(forces));
}

std::vector<std::string> ForceFamily::parameters() const { return {"force"}; }

void ForceFamily::parameter_derivative(const NodeMatrix& X, const VectorX& u,
                                       const std::string& name, ParameterDerivative& out) const {
  if (name != "force") throw_unknown_parameter(*this, name);
  // f_int = -f: d f_int_k / d f_k = -1; E = -f . u: dE/df_k = -u_k. Entry 3 e + k.
  out.reset(static_cast<Index>(3 * forces_.size()));
  for (std::size_t e = 0; e < forces_.size(); ++e) {
    const HeldForce& f = forces_[e];
    const Vector3 moved = position(X, u, f.node) - X.row(f.node).transpose();
    for (int k = 0; k < 3; ++k) {
      const std::array<Index, 1> dof = {3 * f.node + k};
      const std::array<double, 1> local = {-1.0};
      out.add(static_cast<Index>(3 * e + k), local, dof, -moved[k]);
    }
  }
}

}  // namespace kresling::model
