#include "kresling/model/hinge_family.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Geometry>

#include "kresling/core/check.hpp"
#include "kresling/elements/dihedral.hpp"
#include "kresling/elements/hinge.hpp"

namespace kresling::model {

namespace {

constexpr double kTwoPi = 6.28318530717958647692;

std::string hinge_name(std::size_t index, const std::array<Index, 4>& nodes) {
  std::string s = "hinge " + std::to_string(index) + " (nodes";
  for (int k = 0; k < 4; ++k) s += (k ? ", " : " ") + std::to_string(nodes[k]);
  return s + ")";
}

}  // namespace

double Hinge::angle(const NodeMatrix& x) const {
  return elements::dihedral_angle(x.row(nodes[0]), x.row(nodes[1]), x.row(nodes[2]),
                                  x.row(nodes[3]), form);
}

void check_hinge_geometry(const NodeMatrix& X, const std::array<Index, 4>& nodes,
                          std::size_t index, double scale) {
  for (int k = 0; k < 4; ++k) {
    if (nodes[k] < 0 || nodes[k] >= X.rows()) {
      throw std::invalid_argument(hinge_name(index, nodes) + ": node " + std::to_string(nodes[k]) +
                                  " is out of range [0, " + std::to_string(X.rows()) + ")");
    }
    for (int j = 0; j < k; ++j) {
      if (nodes[j] == nodes[k]) {
        throw std::invalid_argument(hinge_name(index, nodes) + ": a node appears twice");
      }
    }
  }
  const Vector3 a = X.row(nodes[0]), b = X.row(nodes[1]);
  const Vector3 axis = b - a;
  const double axis_length = axis.norm();
  if (!(axis_length > 1e-12 * scale)) {
    throw std::invalid_argument(hinge_name(index, nodes) + ": zero-length axis");
  }
  for (int w = 2; w < 4; ++w) {
    const Vector3 x = X.row(nodes[w]);
    const double distance = (x - a).cross(axis).norm() / axis_length;
    if (!(distance > 1e-9 * scale)) {
      throw std::invalid_argument(hinge_name(index, nodes) + ": wing node " +
                                  std::to_string(nodes[w]) +
                                  " lies on the axis line (collinear hinge triangle)");
    }
  }
}

std::vector<Index> HingeFamily::element_dofs(std::size_t e) const {
  const auto d = node_dofs(hinges_[e].nodes);
  return {d.begin(), d.end()};
}

void HingeFamily::check(const NodeMatrix& X, double scale) const {
  for (std::size_t i = 0; i < hinges_.size(); ++i) {
    const Hinge& h = hinges_[i];
    check_hinge_geometry(X, h.nodes, i, scale);
    require_element_positive(*this, i, "stiffness", h.stiffness, /*allow_zero=*/true);
    require_element_positive(*this, i, "length", h.length);
    if (!(std::isfinite(h.rest_angle) && h.rest_angle >= 0.0 && h.rest_angle < kTwoPi)) {
      require_finite(element_name(i) + ": rest angle", h.rest_angle);
      throw_invalid(element_name(i) + ": rest angle", h.rest_angle, "in [0, 2 pi)");
    }
    if (h.law.kind == elements::SpringLawKind::EnhancedLinear &&
        !(h.law.theta1 > 0.0 && h.law.theta1 < h.law.theta2 && h.law.theta2 < kTwoPi)) {
      throw std::invalid_argument(element_name(i) + ": spring limits (" +
                                  format_number(h.law.theta1) + ", " + format_number(h.law.theta2) +
                                  ") are invalid: must satisfy 0 < theta1 < theta2 < 2 pi");
    }
  }
}

double HingeFamily::assemble(const NodeMatrix& X, const VectorX& u, AssemblyTarget& target) const {
  const bool with_matrix = target.values != nullptr;
  double energy = 0.0;
  for (std::size_t e = 0; e < hinges_.size(); ++e) {
    const Hinge& h = hinges_[e];
    if (h.stiffness == 0.0) continue;  // every spring law vanishes with kp (cut creases)
    const auto r = elements::hinge_response(position(X, u, h.nodes[0]), position(X, u, h.nodes[1]),
                                            position(X, u, h.nodes[2]), position(X, u, h.nodes[3]),
                                            h.stiffness, h.rest_angle, h.length, h.law,
                                            with_matrix, h.form);
    energy += r.energy;
    add_local_force(r.force, node_dofs(h.nodes), target.force);
    if (with_matrix) scatter_local_tangent(r.stiffness, *target.slots, e, target.values);
  }
  return energy;
}

void HingeFamily::add_state(const NodeMatrix& x, ElementState& state) const {
  const auto n = static_cast<Index>(hinges_.size());
  VectorX angle(n), moment(n), energy(n);
  for (Index e = 0; e < n; ++e) {
    const Hinge& h = hinges_[e];
    angle[e] = h.angle(x);
    const elements::SpringResponse r = h.law.evaluate(angle[e], h.rest_angle, h.stiffness);
    moment[e] = h.length * r.moment;
    energy[e] = h.length * r.energy;
  }
  state.add("hinge_angle", angle);
  state.add("hinge_moment", moment);
  state.add("hinge_energy", energy);
}

Table HingeFamily::table() const {
  std::vector<Index> nodes, law, form;
  std::vector<double> k, angle, length, t1, t2;
  for (const Hinge& h : hinges_) {
    form.push_back(static_cast<Index>(h.form));
    nodes.insert(nodes.end(), h.nodes.begin(), h.nodes.end());
    k.push_back(h.stiffness);
    angle.push_back(h.rest_angle);
    length.push_back(h.length);
    law.push_back(static_cast<Index>(h.law.kind));
    t1.push_back(h.law.theta1);
    t2.push_back(h.law.theta2);
  }
  return {{"nodes", index_column(nodes, 4)}, {"stiffness", real_column(k)},
          {"rest_angle", real_column(angle)}, {"length", real_column(length)},
          {"law", index_column(law)}, {"theta1", real_column(t1)}, {"theta2", real_column(t2)},
          {"angle_form", index_column(form)}};
}

FamilyPtr HingeFamily::from_table(const Table& t) {
  require_known_columns(t, "hinges",
                        {"nodes", "stiffness", "rest_angle", "length", "law", "theta1", "theta2",
                         "angle_form"});
  const Index n = column_rows(t, "hinges", "nodes", true, 4);
  const auto& nodes = require_column(t, "hinges", "nodes", true, 4).indices;
  const auto& k = require_column(t, "hinges", "stiffness", false, 1, n).reals;
  const auto& angle = require_column(t, "hinges", "rest_angle", false, 1, n).reals;
  const auto& length = require_column(t, "hinges", "length", false, 1, n).reals;
  const auto& law = require_column(t, "hinges", "law", true, 1, n).indices;
  const auto& t1 = require_column(t, "hinges", "theta1", false, 1, n).reals;
  const auto& t2 = require_column(t, "hinges", "theta2", false, 1, n).reals;
  const bool has_form = t.count("angle_form") > 0;
  const std::vector<Index> no_form;
  const auto& form =
      has_form ? require_column(t, "hinges", "angle_form", true, 1, n).indices : no_form;
  std::vector<Hinge> hinges(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) {
    Hinge& h = hinges[i];
    h.nodes = {nodes[4 * i], nodes[4 * i + 1], nodes[4 * i + 2], nodes[4 * i + 3]};
    h.stiffness = k[i];
    h.rest_angle = angle[i];
    h.length = length[i];
    h.law = {elements::spring_law_kind(law[i], "hinges.law"), t1[i], t2[i]};
    if (has_form) h.form = elements::dihedral_form(form[i], "hinges.angle_form");
  }
  return std::make_shared<HingeFamily>(std::move(hinges));
}

std::vector<std::string> HingeFamily::parameters() const {
  return {"stiffness", "rest_angle", "length"};
}

void HingeFamily::parameter_derivative(const NodeMatrix& X, const VectorX& u,
                                       const std::string& name, ParameterDerivative& out) const {
  std::vector<ParameterDerivative> outs;
  parameter_derivatives(X, u, {name}, outs);
  out = std::move(outs.front());
}

void HingeFamily::parameter_derivatives(const NodeMatrix& X, const VectorX& u,
                                        const std::vector<std::string>& names,
                                        std::vector<ParameterDerivative>& outs) const {
  enum Column { Stiffness, RestAngle, Length };
  std::vector<Column> which;
  for (const std::string& name : names) {
    if (name == "stiffness") which.push_back(Stiffness);
    else if (name == "rest_angle") which.push_back(RestAngle);
    else if (name == "length") which.push_back(Length);
    else throw_unknown_parameter(*this, name);
  }
  outs.resize(names.size());
  for (auto& out : outs) out.reset(static_cast<Index>(hinges_.size()));
  for (std::size_t e = 0; e < hinges_.size(); ++e) {
    const Hinge& h = hinges_[e];
    // A hinge of zero stiffness (a cut) has no force to change by its rest angle or length,
    // but its stiffness derivative is the unit law's: a cut's crease may be given stiffness.
    const auto d = elements::hinge_parameter_derivatives(
        position(X, u, h.nodes[0]), position(X, u, h.nodes[1]), position(X, u, h.nodes[2]),
        position(X, u, h.nodes[3]), h.stiffness, h.rest_angle, h.length, h.law, h.form);
    const auto dofs = node_dofs(h.nodes);
    const auto entry = static_cast<Index>(e);
    for (std::size_t i = 0; i < which.size(); ++i) {
      switch (which[i]) {
        case Stiffness: outs[i].add(entry, d.force_stiffness, dofs, d.energy_stiffness); break;
        case RestAngle: outs[i].add(entry, d.force_rest_angle, dofs, d.energy_rest_angle); break;
        case Length: outs[i].add(entry, d.force_length, dofs, d.energy_length); break;
      }
    }
  }
}

void HingeFamily::reference_geometry_derivative(
    const NodeMatrix& X, const std::string& name,
    std::vector<ParameterDerivative::Triplet>& out) const {
  if (name != "stiffness" && name != "rest_angle" && name != "length") {
    throw_unknown_parameter(*this, name);
  }
  if (name == "stiffness") return;
  for (std::size_t e = 0; e < hinges_.size(); ++e) {
    const Hinge& h = hinges_[e];
    const auto entry = static_cast<int>(e);
    if (name == "length") {
      const Vector3 d = X.row(h.nodes[1]) - X.row(h.nodes[0]);
      const double length = d.norm();
      if (length == 0.0 || !holds_reference_geometry(h.length, length)) continue;
      const Vector3 n = d / length;
      for (int k = 0; k < 3; ++k) {
        out.emplace_back(entry, static_cast<int>(3 * h.nodes[0] + k), -n[k]);
        out.emplace_back(entry, static_cast<int>(3 * h.nodes[1] + k), n[k]);
      }
      continue;
    }
    // The rest angle follows the hinge's own angle at X (in its own form, arccosine or
    // atan2, as the model that was built stress-free computed it).
    const auto theta = elements::dihedral_angle_derivatives(X.row(h.nodes[0]), X.row(h.nodes[1]),
                                                            X.row(h.nodes[2]), X.row(h.nodes[3]),
                                                            false, h.form);
    if (!holds_reference_geometry(h.rest_angle, theta.angle)) continue;
    for (int a = 0; a < 4; ++a) {
      for (int k = 0; k < 3; ++k) {
        const double v = theta.gradient[3 * a + k];
        if (v != 0.0) out.emplace_back(entry, static_cast<int>(3 * h.nodes[a] + k), v);
      }
    }
  }
}

}  // namespace kresling::model
