#pragma once
/// \file hinge.hpp
/// Rotational-spring hinge element: a spring law acting on the dihedral angle of four nodes
/// (see dihedral.hpp for the node order a, b (axis), c, d (wings)).

#include "kresling/core/types.hpp"
#include "kresling/elements/dihedral.hpp"
#include "kresling/elements/spring_laws.hpp"

namespace kresling::elements {

/// Energy, internal force and tangent stiffness of one hinge.
struct HingeResponse {
  double angle = 0.0;   ///< dihedral angle theta in [0, 2 pi)
  double moment = 0.0;  ///< L0 M(theta)
  double energy = 0.0;  ///< L0 E(theta)
  Vector12 force;       ///< L0 M dtheta/dx
  Matrix12 stiffness;   ///< L0 (k g g^T + M d2theta/dx2)
};

/// Evaluate a hinge of length L0 with stiffness kp per unit length and rest angle theta0.
/// `with_stiffness = false` skips the 12 x 12 tangent (left unset); `form` computes the
/// angle (dihedral.hpp).
HingeResponse hinge_response(const Vector3& a, const Vector3& b, const Vector3& c,
                             const Vector3& d, double kp, double rest_angle, double length,
                             const SpringLaw& law, bool with_stiffness = true,
                             DihedralForm form = DihedralForm::Exact);

/// The partial derivatives of one hinge's force and energy with respect to its parameters,
/// at fixed positions. The force is f = L0 M(theta; theta0, kp) dtheta/dx, and every law's
/// moment and energy are kp times a function of theta (and the limits), so
///
///     df/dkp     = L0 M1 dtheta/dx              dE/dkp     = L0 E1     (M1, E1: kp = 1)
///     df/dtheta0 = L0 dM/dtheta0 dtheta/dx      dE/dtheta0 = L0 dE/dtheta0 of the law
///     df/dL0     = M dtheta/dx                  dE/dL0     = E
///
/// (SpringLaw::rest_angle_derivative). Vectors of 12, ordered (a, b, c, d).
struct HingeParameterDerivatives {
  Vector12 force_stiffness, force_rest_angle, force_length;
  double energy_stiffness = 0.0, energy_rest_angle = 0.0, energy_length = 0.0;
};

HingeParameterDerivatives hinge_parameter_derivatives(const Vector3& a, const Vector3& b,
                                                      const Vector3& c, const Vector3& d,
                                                      double kp, double rest_angle, double length,
                                                      const SpringLaw& law,
                                                      DihedralForm form = DihedralForm::Exact);

}  // namespace kresling::elements
