#include "kresling/elements/hinge.hpp"

#include "kresling/elements/dihedral.hpp"

namespace kresling::elements {

HingeResponse hinge_response(const Vector3& a, const Vector3& b, const Vector3& c,
                             const Vector3& d, double kp, double rest_angle, double length,
                             const SpringLaw& law, bool with_stiffness, DihedralForm form) {
  const DihedralDerivatives theta = dihedral_angle_derivatives(a, b, c, d, with_stiffness, form);
  const SpringResponse s = law.evaluate(theta.angle, rest_angle, kp);
  HingeResponse r;
  r.angle = theta.angle;
  r.moment = length * s.moment;
  r.energy = length * s.energy;
  r.force = r.moment * theta.gradient;
  if (with_stiffness) {
    r.stiffness.noalias() = (length * s.stiffness) * (theta.gradient * theta.gradient.transpose());
    r.stiffness.noalias() += r.moment * theta.hessian;
  }
  return r;
}

HingeParameterDerivatives hinge_parameter_derivatives(const Vector3& a, const Vector3& b,
                                                      const Vector3& c, const Vector3& d,
                                                      double kp, double rest_angle, double length,
                                                      const SpringLaw& law, DihedralForm form) {
  const DihedralDerivatives theta = dihedral_angle_derivatives(a, b, c, d, false, form);
  const SpringResponse s = law.evaluate(theta.angle, rest_angle, kp);
  const SpringResponse unit = law.evaluate(theta.angle, rest_angle, 1.0);
  const RestAngleDerivative rest = law.rest_angle_derivative(theta.angle, rest_angle, kp);
  HingeParameterDerivatives r;
  r.force_stiffness = (length * unit.moment) * theta.gradient;
  r.energy_stiffness = length * unit.energy;
  r.force_rest_angle = (length * rest.moment) * theta.gradient;
  r.energy_rest_angle = length * rest.energy;
  r.force_length = s.moment * theta.gradient;
  r.energy_length = s.energy;
  return r;
}

}  // namespace kresling::elements
