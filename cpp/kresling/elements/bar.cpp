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

}  // namespace kresling::elements
