#include "kresling/model/face_angle_family.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kresling/core/check.hpp"
#include "kresling/elements/corner_angle.hpp"

namespace kresling::model {

namespace {

constexpr double kPi = 3.14159265358979323846;
// A corner below this angle [rad] in the reference state is a degenerate triangle: the
// angles' derivatives grow as 1 / sin(alpha).
constexpr double kSmallestAngle = 1e-6;

}  // namespace

std::vector<Index> FaceAngleFamily::element_dofs(std::size_t e) const {
  const auto d = node_dofs(faces_[e].nodes);
  return {d.begin(), d.end()};
}

void FaceAngleFamily::check(const NodeMatrix& X, double) const {
  for (std::size_t i = 0; i < faces_.size(); ++i) {
    const FaceAngles& f = faces_[i];
    require_element_nodes(*this, i, f.nodes.data(), 3, X.rows());
    require_element_positive(*this, i, "stiffness", f.stiffness, /*allow_zero=*/true);
    for (int k = 0; k < 3; ++k) {
      const double a = f.rest_angle[k];
      if (!(std::isfinite(a) && a > 0.0 && a < kPi)) {
        require_finite(element_name(i) + ": rest angle", a);
        throw_invalid(element_name(i) + ": rest angle", a, "in (0, pi)");
      }
    }
    const auto angles = elements::corner_angles(X.row(f.nodes[0]), X.row(f.nodes[1]),
                                                X.row(f.nodes[2]));
    if (!(*std::min_element(angles.begin(), angles.end()) > kSmallestAngle)) {
      throw std::invalid_argument(element_name(i) +
                                  ": the triangle is degenerate (its nodes are collinear)");
    }
  }
}

double FaceAngleFamily::assemble(const NodeMatrix& X, const VectorX& u,
                                 AssemblyTarget& target) const {
  const bool with_matrix = target.values != nullptr;
  double energy = 0.0;
  for (std::size_t e = 0; e < faces_.size(); ++e) {
    const FaceAngles& f = faces_[e];
    if (f.stiffness == 0.0) continue;
    const auto r = elements::corner_angle_response(position(X, u, f.nodes[0]),
                                                   position(X, u, f.nodes[1]),
                                                   position(X, u, f.nodes[2]), f.rest_angle,
                                                   f.stiffness, with_matrix);
    energy += r.energy;
    add_local_force(r.force, node_dofs(f.nodes), target.force);
    if (with_matrix) scatter_local_tangent(r.stiffness, *target.slots, e, target.values);
  }
  return energy;
}

void FaceAngleFamily::add_state(const NodeMatrix& x, ElementState& state) const {
  const auto n = static_cast<Index>(faces_.size());
  VectorX change(n), energy(n);
  for (Index e = 0; e < n; ++e) {
    const FaceAngles& f = faces_[e];
    const auto r = elements::corner_angle_response(x.row(f.nodes[0]), x.row(f.nodes[1]),
                                                   x.row(f.nodes[2]), f.rest_angle, f.stiffness,
                                                   /*with_tangent=*/false);
    double largest = 0.0;
    for (int k = 0; k < 3; ++k) largest = std::max(largest, std::abs(r.angle[k] - f.rest_angle[k]));
    change[e] = largest;
    energy[e] = r.energy;
  }
  state.add("face_angle_change", change);
  state.add("face_angle_energy", energy);
}

Table FaceAngleFamily::table() const {
  std::vector<Index> nodes;
  std::vector<double> rest, k;
  for (const FaceAngles& f : faces_) {
    nodes.insert(nodes.end(), f.nodes.begin(), f.nodes.end());
    rest.insert(rest.end(), f.rest_angle.begin(), f.rest_angle.end());
    k.push_back(f.stiffness);
  }
  return {{"nodes", index_column(nodes, 3)}, {"rest_angle", real_column(rest, 3)},
          {"stiffness", real_column(k)}};
}

FamilyPtr FaceAngleFamily::from_table(const Table& t) {
  require_known_columns(t, "face_angles", {"nodes", "rest_angle", "stiffness"});
  const Index n = column_rows(t, "face_angles", "nodes", true, 3);
  const auto& nodes = require_column(t, "face_angles", "nodes", true, 3).indices;
  const auto& rest = require_column(t, "face_angles", "rest_angle", false, 3, n).reals;
  const auto& k = require_column(t, "face_angles", "stiffness", false, 1, n).reals;
  std::vector<FaceAngles> faces(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) {
    FaceAngles& f = faces[i];
    f.nodes = {nodes[3 * i], nodes[3 * i + 1], nodes[3 * i + 2]};
    f.rest_angle = {rest[3 * i], rest[3 * i + 1], rest[3 * i + 2]};
    f.stiffness = k[i];
  }
  return std::make_shared<FaceAngleFamily>(std::move(faces));
}

std::vector<std::string> FaceAngleFamily::parameters() const { return {"rest_angle", "stiffness"}; }

void FaceAngleFamily::parameter_derivative(const NodeMatrix& X, const VectorX& u,
                                           const std::string& name,
                                           ParameterDerivative& out) const {
  if (name != "rest_angle" && name != "stiffness") throw_unknown_parameter(*this, name);
  const bool rest = name == "rest_angle";
  out.reset(static_cast<Index>((rest ? 3 : 1) * faces_.size()));
  for (std::size_t e = 0; e < faces_.size(); ++e) {
    const FaceAngles& f = faces_[e];
    const auto r = elements::corner_angle_response(position(X, u, f.nodes[0]),
                                                   position(X, u, f.nodes[1]),
                                                   position(X, u, f.nodes[2]), f.rest_angle,
                                                   f.stiffness, /*with_tangent=*/false);
    const auto dofs = node_dofs(f.nodes);
    if (!rest) {
      // E and f are k times a function of the positions.
      elements::Vector9 unit = elements::Vector9::Zero();
      double energy = 0.0;
      for (int i = 0; i < 3; ++i) {
        const double excess = r.angle[i] - f.rest_angle[i];
        unit += excess * r.gradients[i];
        energy += 0.5 * excess * excess;
      }
      out.add(static_cast<Index>(e), unit, dofs, energy);
      continue;
    }
    for (int i = 0; i < 3; ++i) {
      const elements::Vector9 local = -f.stiffness * r.gradients[i];
      out.add(static_cast<Index>(3 * e + i), local, dofs,
              -f.stiffness * (r.angle[i] - f.rest_angle[i]));
    }
  }
}

void FaceAngleFamily::reference_geometry_derivative(
    const NodeMatrix& X, const std::string& name,
    std::vector<ParameterDerivative::Triplet>& out) const {
  if (name != "rest_angle" && name != "stiffness") throw_unknown_parameter(*this, name);
  if (name != "rest_angle") return;
  const VectorX still = VectorX::Zero(3 * X.rows());
  for (std::size_t e = 0; e < faces_.size(); ++e) {
    const FaceAngles& f = faces_[e];
    const auto r = elements::corner_angle_response(position(X, still, f.nodes[0]),
                                                   position(X, still, f.nodes[1]),
                                                   position(X, still, f.nodes[2]), f.rest_angle,
                                                   f.stiffness, /*with_tangent=*/false);
    for (int i = 0; i < 3; ++i) {
      if (!holds_reference_geometry(f.rest_angle[i], r.angle[i])) continue;
      for (int a = 0; a < 3; ++a) {
        for (int k = 0; k < 3; ++k) {
          const double v = r.gradients[i][3 * a + k];
          if (v != 0.0) {
            out.emplace_back(static_cast<int>(3 * e + i), static_cast<int>(3 * f.nodes[a] + k), v);
          }
        }
      }
    }
  }
}

}  // namespace kresling::model
