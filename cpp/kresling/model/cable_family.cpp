#include "kresling/model/cable_family.hpp"

#include <stdexcept>
#include <string>

#include "kresling/elements/cable.hpp"

namespace kresling::model {

namespace {

elements::CablePoints cable_points(const Cable& c, const NodeMatrix& X, const VectorX* u) {
  elements::CablePoints x(static_cast<Index>(c.nodes.size()), 3);
  for (std::size_t i = 0; i < c.nodes.size(); ++i) {
    x.row(static_cast<Index>(i)) = u ? position(X, *u, c.nodes[i]) : Vector3(X.row(c.nodes[i]));
  }
  return x;
}

}  // namespace

void CableFamily::check(const NodeMatrix& X, double scale) const {
  for (std::size_t i = 0; i < cables_.size(); ++i) {
    const Cable& c = cables_[i];
    if (c.nodes.size() < 2 || c.nodes.size() > kMaxCableNodes) {
      throw std::invalid_argument("cable " + std::to_string(i) + ": has " +
                                  std::to_string(c.nodes.size()) + " nodes, must have 2 to " +
                                  std::to_string(kMaxCableNodes));
    }
    require_element_nodes(*this, i, c.nodes.data(), static_cast<int>(c.nodes.size()), X.rows());
    require_element_positive(*this, i, "stiffness", c.stiffness);
    require_element_positive(*this, i, "rest length", c.rest_length);
    for (std::size_t k = 0; k + 1 < c.nodes.size(); ++k) {
      if (!((X.row(c.nodes[k + 1]) - X.row(c.nodes[k])).norm() > 1e-12 * scale)) {
        throw std::invalid_argument(element_name(i) + ": nodes " + std::to_string(c.nodes[k]) +
                                    " and " + std::to_string(c.nodes[k + 1]) +
                                    " coincide (a segment needs a direction)");
      }
    }
  }
}

double CableFamily::assemble(const NodeMatrix& X, const VectorX& u, AssemblyTarget& target) const {
  const bool with_matrix = target.values != nullptr;
  double energy = 0.0;
  for (std::size_t e = 0; e < cables_.size(); ++e) {
    const Cable& c = cables_[e];
    const auto r = elements::cable_response(cable_points(c, X, &u), c.stiffness, c.rest_length,
                                            with_matrix);
    if (!r.taut) continue;  // slack: no energy, force or stiffness
    energy += r.energy;
    for (std::size_t i = 0; i < c.nodes.size(); ++i) {
      for (int k = 0; k < 3; ++k) {
        target.force[3 * c.nodes[i] + k] += r.force[static_cast<Index>(3 * i + k)];
      }
    }
    if (with_matrix) scatter_local_tangent(r.stiffness, *target.slots, e, target.values);
  }
  return energy;
}

void CableFamily::add_state(const NodeMatrix& x, ElementState& state) const {
  const auto n = static_cast<Index>(cables_.size());
  VectorX length(n), tension(n), energy(n);
  for (Index e = 0; e < n; ++e) {
    const Cable& c = cables_[e];
    const auto r = elements::cable_response(cable_points(c, x, nullptr), c.stiffness,
                                            c.rest_length, false);
    length[e] = r.length;
    tension[e] = r.tension;
    energy[e] = r.energy;
  }
  state.add("cable_length", length);
  state.add("cable_tension", tension);
  state.add("cable_energy", energy);
}

Table CableFamily::table() const {
  std::vector<Index> nodes, count;
  std::vector<double> k, rest;
  for (const Cable& c : cables_) {
    nodes.insert(nodes.end(), c.nodes.begin(), c.nodes.end());
    count.push_back(static_cast<Index>(c.nodes.size()));
    k.push_back(c.stiffness);
    rest.push_back(c.rest_length);
  }
  return {{"nodes", index_column(nodes)}, {"node_count", index_column(count)},
          {"stiffness", real_column(k)}, {"rest_length", real_column(rest)}};
}

FamilyPtr CableFamily::from_table(const Table& t) {
  require_known_columns(t, "cables", {"nodes", "node_count", "stiffness", "rest_length"});
  const Index n = column_rows(t, "cables", "node_count", true, 1);
  const auto& count = require_column(t, "cables", "node_count", true, 1).indices;
  const auto& nodes = require_column(t, "cables", "nodes", true, 1).indices;
  const auto& k = require_column(t, "cables", "stiffness", false, 1, n).reals;
  const auto& rest = require_column(t, "cables", "rest_length", false, 1, n).reals;
  std::vector<Cable> cables(static_cast<std::size_t>(n));
  std::size_t next = 0;
  for (Index i = 0; i < n; ++i) {
    if (count[i] < 0 || next + static_cast<std::size_t>(count[i]) > nodes.size()) {
      throw std::invalid_argument("cables.node_count: the counts need more nodes than "
                                  "cables.nodes holds (" + std::to_string(nodes.size()) + ")");
    }
    cables[i].nodes.assign(nodes.begin() + next, nodes.begin() + next + count[i]);
    next += static_cast<std::size_t>(count[i]);
    cables[i].stiffness = k[i];
    cables[i].rest_length = rest[i];
  }
  if (next != nodes.size()) {
    throw std::invalid_argument("cables.nodes: holds " + std::to_string(nodes.size()) +
                                " nodes, the counts use " + std::to_string(next));
  }
  return std::make_shared<CableFamily>(std::move(cables));
}

std::vector<std::string> CableFamily::parameters() const { return {"stiffness", "rest_length"}; }

void CableFamily::parameter_derivative(const NodeMatrix& X, const VectorX& u,
                                       const std::string& name, ParameterDerivative& out) const {
  if (name != "stiffness" && name != "rest_length") throw_unknown_parameter(*this, name);
  out.reset(static_cast<Index>(cables_.size()));
  for (std::size_t e = 0; e < cables_.size(); ++e) {
    const Cable& c = cables_[e];
    const auto d = elements::cable_parameter_derivatives(cable_points(c, X, &u), c.stiffness,
                                                         c.rest_length);
    const auto dofs = node_dofs(c.nodes);
    const auto entry = static_cast<Index>(e);
    if (name == "stiffness") out.add(entry, d.force_stiffness, dofs, d.energy_stiffness);
    else out.add(entry, d.force_rest_length, dofs, d.energy_rest_length);
  }
}

}  // namespace kresling::model
