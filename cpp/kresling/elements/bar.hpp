#pragma once
/// \file bar.hpp
/// Bar element kernels: pure functions of the two end positions.
///
///     x1 o-----------o x2        rest length L, area A, law S(E)
///
/// Vectors of 6 are ordered (x1, x2). The strain is Green-Lagrange,
/// E = (|x2 - x1|^2 - L^2) / (2 L^2), so dE/dx is linear in x and d2E/dx2 is constant.

#include "kresling/core/types.hpp"
#include "kresling/elements/bar_laws.hpp"

namespace kresling::elements {

/// Green-Lagrange strain of the bar.
double bar_strain(const Vector3& x1, const Vector3& x2, double rest_length);

/// dE/dx, ordered (x1, x2).
Vector6 bar_strain_gradient(const Vector3& x1, const Vector3& x2, double rest_length);

/// d2E/dx2 = [[I, -I], [-I, I]] / L^2 (independent of the positions).
Matrix6 bar_strain_hessian(double rest_length);

/// Energy, internal force and tangent stiffness of one bar.
struct BarResponse {
  double strain = 0.0;  ///< E
  double energy = 0.0;  ///< A L W(E)
  Vector6 force;        ///< A L S dE/dx
  Matrix6 stiffness;    ///< A L (dS/dE dE/dx dE/dx^T + S d2E/dx2)
};

/// Evaluate a bar. `with_stiffness = false` skips the 6 x 6 tangent (left unset).
BarResponse bar_response(const Vector3& x1, const Vector3& x2, double area, double rest_length,
                         const BarLaw& law, bool with_stiffness = true);

/// The partial derivatives of one bar's force and energy with respect to its parameters,
/// at fixed positions. With g = dE/dx = [-d, d] / L^2 (d = x2 - x1, l = |d|), the force is
/// f = A L S(E) g = (A S / L) [-d, d], linear in the area and in the modulus (both laws'
/// S and W are C0 times a function of the strain), and dE/dL = -l^2 / L^3:
///
///     df/dA  = L S g                          dW_bar/dA  = L W
///     df/dC0 = A L S1 g                       dW_bar/dC0 = A L W1      (S1, W1: C0 = 1)
///     df/dL  = -(A / L^2) (C l^2 / L^2 + S) [-d, d]
///                                             dW_bar/dL  = A W + A L S dE/dL
///
/// with C = dS/dE. Vectors of 6, ordered (x1, x2).
struct BarParameterDerivatives {
  Vector6 force_area, force_modulus, force_rest_length;
  double energy_area = 0.0, energy_modulus = 0.0, energy_rest_length = 0.0;
};

BarParameterDerivatives bar_parameter_derivatives(const Vector3& x1, const Vector3& x2,
                                                  double area, double rest_length,
                                                  const BarLaw& law);

}  // namespace kresling::elements
