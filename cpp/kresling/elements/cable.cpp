#include "kresling/elements/cable.hpp"

namespace kresling::elements {

double cable_length(const CablePoints& x) {
  double l = 0.0;
  for (Index s = 0; s + 1 < x.rows(); ++s) l += (x.row(s + 1) - x.row(s)).norm();
  return l;
}

VectorX cable_length_gradient(const CablePoints& x) {
  VectorX g = VectorX::Zero(3 * x.rows());
  for (Index s = 0; s + 1 < x.rows(); ++s) {
    const Vector3 d = (x.row(s + 1) - x.row(s)).transpose();
    const Vector3 e = d / d.norm();
    g.segment<3>(3 * s) -= e;
    g.segment<3>(3 * s + 3) += e;
  }
  return g;
}

namespace {

// Add T * d2l/dx2 into K (the segment blocks [[P, -P], [-P, P]], P = (I - e e^T) / l_s).
void add_length_hessian(const CablePoints& x, double factor, MatrixX& K) {
  for (Index s = 0; s + 1 < x.rows(); ++s) {
    const Vector3 d = (x.row(s + 1) - x.row(s)).transpose();
    const double ls = d.norm();
    const Vector3 e = d / ls;
    const Matrix3 P = factor * (Matrix3::Identity() - e * e.transpose()) / ls;
    K.block<3, 3>(3 * s, 3 * s) += P;
    K.block<3, 3>(3 * s + 3, 3 * s + 3) += P;
    K.block<3, 3>(3 * s, 3 * s + 3) -= P;
    K.block<3, 3>(3 * s + 3, 3 * s) -= P;
  }
}

}  // namespace

MatrixX cable_length_hessian(const CablePoints& x) {
  MatrixX H = MatrixX::Zero(3 * x.rows(), 3 * x.rows());
  add_length_hessian(x, 1.0, H);
  return H;
}

CableResponse cable_response(const CablePoints& x, double stiffness, double rest_length,
                             bool with_stiffness) {
  CableResponse r;
  const Index dofs = 3 * x.rows();
  const double L = rest_length, L2 = rest_length * rest_length;
  r.length = cable_length(x);
  r.strain = (r.length * r.length - L2) / (2.0 * L2);
  r.taut = r.strain > 0.0;
  if (!r.taut) {
    r.force = VectorX::Zero(dofs);
    if (with_stiffness) r.stiffness = MatrixX::Zero(dofs, dofs);
    return r;
  }
  r.tension = stiffness * r.strain * r.length / L;
  r.energy = 0.5 * stiffness * L * r.strain * r.strain;
  const VectorX g = cable_length_gradient(x);
  r.force = r.tension * g;
  if (with_stiffness) {
    r.stiffness = (stiffness / L * (r.length * r.length / L2 + r.strain)) * (g * g.transpose());
    add_length_hessian(x, r.tension, r.stiffness);
  }
  return r;
}

CableParameterDerivatives cable_parameter_derivatives(const CablePoints& x, double stiffness,
                                                      double rest_length) {
  const Index dofs = 3 * x.rows();
  const double L = rest_length, L2 = L * L;
  const double l = cable_length(x);
  const double strain = (l * l - L2) / (2.0 * L2);
  CableParameterDerivatives r;
  r.force_stiffness = VectorX::Zero(dofs);
  r.force_rest_length = VectorX::Zero(dofs);
  if (!(strain > 0.0)) return r;  // slack: no force or energy to change
  const VectorX g = cable_length_gradient(x);
  r.force_stiffness = (strain * l / L) * g;
  r.energy_stiffness = 0.5 * L * strain * strain;
  r.force_rest_length = (-stiffness * l * (l * l / (L2 * L2) + strain / L2)) * g;
  r.energy_rest_length = stiffness * strain * (0.5 * strain - l * l / L2);
  return r;
}

}  // namespace kresling::elements
