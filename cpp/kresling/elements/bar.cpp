#include "kresling/elements/bar.hpp"

#include <cmath>

namespace kresling::elements {

double bar_strain(const Vector3& x1, const Vector3& x2, double rest_length) {
  const double L2 = rest_length * rest_length;
  return ((x2 - x1).squaredNorm() - L2) / (2.0 * L2);
}

Vector6 bar_strain_gradient(const Vector3& x1, const Vector3& x2, double rest_length) {
  const Vector3 d = (x2 - x1) / (rest_length * rest_length);
  Vector6 g;
  g << -d, d;
  return g;
}

Matrix6 bar_strain_hessian(double rest_length) {
  const Matrix3 I = Matrix3::Identity() / (rest_length * rest_length);
  Matrix6 h;
  h << I, -I, -I, I;
  return h;
}

BarResponse bar_response(const Vector3& x1, const Vector3& x2, double area, double rest_length,
                         const BarLaw& law, bool with_stiffness) {
  BarResponse r;
  const double L2 = rest_length * rest_length;
  const double l2 = (x2 - x1).squaredNorm();
  r.strain = (l2 - L2) / (2.0 * L2);
  const StressResponse s = law.evaluate(r.strain, std::sqrt(l2) / rest_length);
  const double volume = area * rest_length;
  r.energy = volume * s.energy_density;
  const Vector6 g = bar_strain_gradient(x1, x2, rest_length);
  r.force = (volume * s.stress) * g;
  if (with_stiffness) {
    // The stiffness has the block pattern [[K, -K], [-K, K]] with K = c d d^T + S I / L^2
    // (g = [-d, d]; S d2E/dx2 = S [[I, -I], [-I, I]] / L^2): one 3 x 3 block, signed.
    const Vector3 d = g.tail<3>();
    Matrix3 K = (volume * s.modulus) * (d * d.transpose());
    K.diagonal().array() += volume * s.stress / L2;
    r.stiffness << K, -K, -K, K;
  }
  return r;
}

BarParameterDerivatives bar_parameter_derivatives(const Vector3& x1, const Vector3& x2,
                                                  double area, double rest_length,
                                                  const BarLaw& law) {
  const double L = rest_length, L2 = L * L;
  const double l2 = (x2 - x1).squaredNorm();
  const double strain = (l2 - L2) / (2.0 * L2);
  const double stretch = std::sqrt(l2) / L;
  const StressResponse s = law.evaluate(strain, stretch);
  const StressResponse unit = BarLaw{law.kind, 1.0}.evaluate(strain, stretch);
  const Vector6 g = bar_strain_gradient(x1, x2, L);
  const double strain_by_length = -l2 / (L2 * L);  // dE/dL at fixed positions
  BarParameterDerivatives r;
  r.force_area = (L * s.stress) * g;
  r.energy_area = L * s.energy_density;
  r.force_modulus = (area * L * unit.stress) * g;
  r.energy_modulus = area * L * unit.energy_density;
  // g L^2 = [-d, d]: the force (A S / L) [-d, d] differentiated in L through S and 1/L.
  r.force_rest_length = (-area * (s.modulus * l2 / L2 + s.stress)) * g;
  r.energy_rest_length = area * s.energy_density + area * L * s.stress * strain_by_length;
  return r;
}

}  // namespace kresling::elements
