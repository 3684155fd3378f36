#include "kresling/model/bar_family.hpp"

#include <stdexcept>

#include "kresling/elements/bar.hpp"

namespace kresling::model {

std::vector<Index> BarFamily::element_dofs(std::size_t e) const {
  const auto d = node_dofs(bars_[e].nodes);
  return {d.begin(), d.end()};
}

void BarFamily::check(const NodeMatrix& X, double scale) const {
  for (std::size_t i = 0; i < bars_.size(); ++i) {
    const Bar& bar = bars_[i];
    require_element_nodes(*this, i, bar.nodes.data(), 2, X.rows());
    require_element_positive(*this, i, "area", bar.area);
    require_element_positive(*this, i, "rest length", bar.rest_length);
    require_element_positive(*this, i, "modulus", bar.law.modulus);
    const double l = (X.row(bar.nodes[1]) - X.row(bar.nodes[0])).norm();
    if (!(l > 1e-12 * scale)) {
      throw std::invalid_argument(element_name(i) + ": zero length (its two nodes coincide)");
    }
  }
}

double BarFamily::assemble(const NodeMatrix& X, const VectorX& u, AssemblyTarget& target) const {
  const bool with_matrix = target.values != nullptr;
  double energy = 0.0;
  for (std::size_t e = 0; e < bars_.size(); ++e) {
    const Bar& bar = bars_[e];
    const auto r = elements::bar_response(position(X, u, bar.nodes[0]), position(X, u, bar.nodes[1]),
                                          bar.area, bar.rest_length, bar.law, with_matrix);
    energy += r.energy;
    add_local_force(r.force, node_dofs(bar.nodes), target.force);
    if (with_matrix) scatter_local_tangent(r.stiffness, *target.slots, e, target.values);
  }
  return energy;
}

void BarFamily::add_state(const NodeMatrix& x, ElementState& state) const {
  const auto n = static_cast<Index>(bars_.size());
  VectorX strain(n), force(n), stress(n), energy(n);
  for (Index e = 0; e < n; ++e) {
    const Bar& bar = bars_[e];
    const Vector3 x1 = x.row(bar.nodes[0]), x2 = x.row(bar.nodes[1]);
    const double L = bar.rest_length;
    strain[e] = elements::bar_strain(x1, x2, L);
    const double stretch = (x2 - x1).norm() / L;
    // Axial (Cauchy-like) force: S is per reference area along the deformed direction.
    const elements::StressResponse r = bar.law.evaluate(strain[e], stretch);
    force[e] = bar.area * r.stress * stretch;
    stress[e] = r.stress;
    energy[e] = bar.area * L * r.energy_density;
  }
  state.add("bar_strain", strain);
  state.add("bar_force", force);
  state.add("bar_stress", stress);
  state.add("bar_energy", energy);
}

Table BarFamily::table() const {
  std::vector<Index> nodes, law;
  std::vector<double> area, rest, modulus;
  for (const Bar& b : bars_) {
    nodes.insert(nodes.end(), b.nodes.begin(), b.nodes.end());
    area.push_back(b.area);
    rest.push_back(b.rest_length);
    law.push_back(static_cast<Index>(b.law.kind));
    modulus.push_back(b.law.modulus);
  }
  return {{"nodes", index_column(nodes, 2)}, {"area", real_column(area)},
          {"rest_length", real_column(rest)}, {"law", index_column(law)},
          {"modulus", real_column(modulus)}};
}

FamilyPtr BarFamily::from_table(const Table& t) {
  require_known_columns(t, "bars", {"nodes", "area", "rest_length", "law", "modulus"});
  const Index n = column_rows(t, "bars", "nodes", true, 2);
  const auto& nodes = require_column(t, "bars", "nodes", true, 2).indices;
  const auto& area = require_column(t, "bars", "area", false, 1, n).reals;
  const auto& rest = require_column(t, "bars", "rest_length", false, 1, n).reals;
  const auto& law = require_column(t, "bars", "law", true, 1, n).indices;
  const auto& modulus = require_column(t, "bars", "modulus", false, 1, n).reals;
  std::vector<Bar> bars(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) {
    bars[i].nodes = {nodes[2 * i], nodes[2 * i + 1]};
    bars[i].area = area[i];
    bars[i].rest_length = rest[i];
    bars[i].law = {elements::bar_law_kind(law[i], "bars.law"), modulus[i]};
  }
  return std::make_shared<BarFamily>(std::move(bars));
}

std::vector<std::string> BarFamily::parameters() const { return {"area", "rest_length", "modulus"}; }

void BarFamily::parameter_derivative(const NodeMatrix& X, const VectorX& u, const std::string& name,
                                     ParameterDerivative& out) const {
  std::vector<ParameterDerivative> outs;
  parameter_derivatives(X, u, {name}, outs);
  out = std::move(outs.front());
}

void BarFamily::parameter_derivatives(const NodeMatrix& X, const VectorX& u,
                                      const std::vector<std::string>& names,
                                      std::vector<ParameterDerivative>& outs) const {
  enum Column { Area, RestLength, Modulus };
  std::vector<Column> which;
  for (const std::string& name : names) {
    if (name == "area") which.push_back(Area);
    else if (name == "rest_length") which.push_back(RestLength);
    else if (name == "modulus") which.push_back(Modulus);
    else throw_unknown_parameter(*this, name);
  }
  outs.resize(names.size());
  for (auto& out : outs) out.reset(static_cast<Index>(bars_.size()));
  for (std::size_t e = 0; e < bars_.size(); ++e) {
    const Bar& bar = bars_[e];
    const auto d = elements::bar_parameter_derivatives(position(X, u, bar.nodes[0]),
                                                       position(X, u, bar.nodes[1]), bar.area,
                                                       bar.rest_length, bar.law);
    const auto dofs = node_dofs(bar.nodes);
    const auto entry = static_cast<Index>(e);
    for (std::size_t i = 0; i < which.size(); ++i) {
      switch (which[i]) {
        case Area: outs[i].add(entry, d.force_area, dofs, d.energy_area); break;
        case Modulus: outs[i].add(entry, d.force_modulus, dofs, d.energy_modulus); break;
        case RestLength: outs[i].add(entry, d.force_rest_length, dofs, d.energy_rest_length); break;
      }
    }
  }
}

void BarFamily::reference_geometry_derivative(
    const NodeMatrix& X, const std::string& name,
    std::vector<ParameterDerivative::Triplet>& out) const {
  if (name != "area" && name != "rest_length" && name != "modulus") throw_unknown_parameter(*this, name);
  if (name != "rest_length") return;  // a section and a material are not geometry
  for (std::size_t e = 0; e < bars_.size(); ++e) {
    const Bar& bar = bars_[e];
    const Vector3 d = X.row(bar.nodes[1]) - X.row(bar.nodes[0]);
    const double length = d.norm();
    if (length == 0.0 || !holds_reference_geometry(bar.rest_length, length)) continue;
    // dL/dX = [-n, n] with n the unit vector from the first node to the second.
    const Vector3 n = d / length;
    const auto entry = static_cast<int>(e);
    for (int k = 0; k < 3; ++k) {
      out.emplace_back(entry, static_cast<int>(3 * bar.nodes[0] + k), -n[k]);
      out.emplace_back(entry, static_cast<int>(3 * bar.nodes[1] + k), n[k]);
    }
  }
}

}  // namespace kresling::model
