#include "kresling/model/spring_family.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "kresling/core/check.hpp"
#include "kresling/elements/anchor_spring.hpp"

namespace kresling::model {

std::vector<Index> SpringFamily::element_dofs(std::size_t e) const {
  const Index n = springs_[e].node;
  return {3 * n, 3 * n + 1, 3 * n + 2};
}

void SpringFamily::check(const NodeMatrix& X, double) const {
  for (std::size_t i = 0; i < springs_.size(); ++i) {
    const AnchorSpring& s = springs_[i];
    require_element_nodes(*this, i, &s.node, 1, X.rows());
    for (int k = 0; k < 3; ++k) {
      require_element_positive(*this, i, "stiffness", s.stiffness[k], /*allow_zero=*/true);
      if (!std::isfinite(s.anchor[k])) {
        require_finite(element_name(i) + ": anchor", s.anchor[k]);
      }
    }
  }
}

double SpringFamily::assemble(const NodeMatrix& X, const VectorX& u, AssemblyTarget& target) const {
  double energy = 0.0;
  for (std::size_t e = 0; e < springs_.size(); ++e) {
    const AnchorSpring& s = springs_[e];
    const auto r = elements::anchor_spring_response(position(X, u, s.node), s.anchor, s.stiffness);
    energy += r.energy;
    add_local_force(r.force, element_dofs(e), target.force);
    if (target.values) scatter_local_tangent(r.stiffness, *target.slots, e, target.values);
  }
  return energy;
}

void SpringFamily::add_state(const NodeMatrix& x, ElementState& state) const {
  const auto n = static_cast<Index>(springs_.size());
  VectorX extension(n), force(n), energy(n);
  for (Index e = 0; e < n; ++e) {
    const AnchorSpring& s = springs_[e];
    const auto r = elements::anchor_spring_response(x.row(s.node).transpose(), s.anchor,
                                                    s.stiffness);
    extension[e] = (x.row(s.node).transpose() - s.anchor).norm();
    force[e] = r.force.norm();
    energy[e] = r.energy;
  }
  state.add("spring_extension", extension);
  state.add("spring_force", force);
  state.add("spring_energy", energy);
}

void SpringFamily::mark_grounded_dofs(std::vector<std::uint8_t>& grounded) const {
  for (const AnchorSpring& s : springs_) {
    for (int k = 0; k < 3; ++k) {
      if (s.stiffness[k] > 0.0) grounded[static_cast<std::size_t>(3 * s.node + k)] = 1;
    }
  }
}

Table SpringFamily::table() const {
  std::vector<Index> nodes;
  std::vector<double> k, anchor;
  for (const AnchorSpring& s : springs_) {
    nodes.push_back(s.node);
    k.insert(k.end(), s.stiffness.data(), s.stiffness.data() + 3);
    anchor.insert(anchor.end(), s.anchor.data(), s.anchor.data() + 3);
  }
  return {{"nodes", index_column(nodes)}, {"stiffness", real_column(k, 3)},
          {"anchor", real_column(anchor, 3)}};
}

FamilyPtr SpringFamily::from_table(const Table& t) {
  require_known_columns(t, "springs", {"nodes", "stiffness", "anchor"});
  const Index n = column_rows(t, "springs", "nodes", true, 1);
  const auto& nodes = require_column(t, "springs", "nodes", true, 1).indices;
  const auto& k = require_column(t, "springs", "stiffness", false, 3, n).reals;
  const auto& anchor = require_column(t, "springs", "anchor", false, 3, n).reals;
  std::vector<AnchorSpring> springs(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) {
    springs[i].node = nodes[i];
    springs[i].stiffness = Vector3(k[3 * i], k[3 * i + 1], k[3 * i + 2]);
    springs[i].anchor = Vector3(anchor[3 * i], anchor[3 * i + 1], anchor[3 * i + 2]);
  }
  return std::make_shared<SpringFamily>(std::move(springs));
}

std::vector<std::string> SpringFamily::parameters() const { return {"stiffness", "anchor"}; }

void SpringFamily::parameter_derivative(const NodeMatrix& X, const VectorX& u,
                                        const std::string& name, ParameterDerivative& out) const {
  if (name != "stiffness" && name != "anchor") throw_unknown_parameter(*this, name);
  // E = 1/2 sum_k k_k (x_k - a_k)^2: df_k/dk_k = x_k - a_k, dE/dk_k = (x_k - a_k)^2 / 2;
  // df_k/da_k = -k_k, dE/da_k = -k_k (x_k - a_k). Entry 3 e + k, as the columns store them.
  const bool stiffness = name == "stiffness";
  out.reset(static_cast<Index>(3 * springs_.size()));
  for (std::size_t e = 0; e < springs_.size(); ++e) {
    const AnchorSpring& s = springs_[e];
    const Vector3 stretch = position(X, u, s.node) - s.anchor;
    for (int k = 0; k < 3; ++k) {
      const std::array<Index, 1> dof = {3 * s.node + k};
      const std::array<double, 1> local = {stiffness ? stretch[k] : -s.stiffness[k]};
      const double energy = stiffness ? 0.5 * stretch[k] * stretch[k] : -s.stiffness[k] * stretch[k];
      out.add(static_cast<Index>(3 * e + k), local, dof, energy);
    }
  }
}

}  // namespace kresling::model
