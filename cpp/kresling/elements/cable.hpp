#pragma once
/// \file cable.hpp
/// Sliding-cable element kernels: a tendon through a sequence of guide nodes, without
/// friction, tension only.
///
///     x0 o                         x0: anchor (start), x_{k-1}: anchor (end),
///         \  l_0                   x1 .. x_{k-2}: frictionless guides the cable
///          \                       slides through; one tension T along its length
///       x1 o------------o x2
///                l_1      \  l_2
///                          o x3    l = l_0 + l_1 + l_2 (total length)
///
/// One axial rigidity EA [N] and one rest length L [mm] (the actuation input: pulling the
/// tendon shortens L). The strain is the Green-Lagrange strain of the total length,
/// E = (l^2 - L^2) / (2 L^2), with a linear, tension-only law: the energy is EA L E^2 / 2
/// for E > 0 and zero otherwise (a slack cable carries nothing). A straight two-node cable
/// in tension is exactly a linear bar with C0 A = EA.
///
/// With g = dl/dx (the unit vectors of the segments, summed at each node) and
/// H = d2l/dx2 (per segment the block pattern [[P, -P], [-P, P]], P = (I - e e^T) / l_s):
///
///     tension  T = EA E l / L                 (the bar's axial force A S(E) l / L)
///     force    f = T g                        (the same T on both sides of every guide)
///     tangent  K = (EA / L) (l^2 / L^2 + E) g g^T + T H
///
/// Vectors are ordered (x0, x1, ..., x_{k-1}), 3 k entries; k >= 2. The tangent couples
/// every node of the cable (the g g^T term), so it is a dense 3k x 3k matrix. Consecutive
/// nodes must not coincide (a zero-length segment has no direction); Model checks this.

#include <vector>

#include <Eigen/Core>

#include "kresling/core/types.hpp"

namespace kresling::elements {

using MatrixX = Eigen::MatrixXd;

/// Positions of a cable's nodes, one row per node, in cable order.
using CablePoints = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// Total length l = sum of the segment lengths.
double cable_length(const CablePoints& x);

/// dl/dx (3 k): at node i, the unit vector of the segment arriving minus that of the segment
/// leaving (the sum of the unit vectors pointing away from it along the cable).
VectorX cable_length_gradient(const CablePoints& x);

/// d2l/dx2 (3 k x 3 k, symmetric, block tridiagonal).
MatrixX cable_length_hessian(const CablePoints& x);

/// Energy, internal force and tangent stiffness of one cable.
struct CableResponse {
  double length = 0.0;   ///< l [mm]
  double strain = 0.0;   ///< E (negative when slack)
  double tension = 0.0;  ///< T = EA E l / L when taut, 0 when slack [N]
  double energy = 0.0;   ///< EA L E^2 / 2 when taut, 0 when slack [N mm]
  bool taut = false;     ///< E > 0
  VectorX force;         ///< T dl/dx (zero when slack)
  MatrixX stiffness;     ///< tangent (zero when slack); left empty without stiffness
};

/// Evaluate a cable of axial rigidity `stiffness` (EA) and rest length `rest_length`.
/// `with_stiffness = false` skips the tangent.
CableResponse cable_response(const CablePoints& x, double stiffness, double rest_length,
                             bool with_stiffness = true);

/// The partial derivatives of one cable's force and energy with respect to its rigidity EA
/// and rest length L, at fixed positions (zero when slack). With T = EA E l / L and
/// dE/dL = -l^2 / L^3:
///
///     df/dEA = (E l / L) dl/dx                 dW/dEA = L E^2 / 2
///     df/dL  = -EA l (l^2 / L^4 + E / L^2) dl/dx
///                                              dW/dL  = EA E (E / 2 - l^2 / L^2)
struct CableParameterDerivatives {
  VectorX force_stiffness, force_rest_length;  ///< 3 k each
  double energy_stiffness = 0.0, energy_rest_length = 0.0;
};

CableParameterDerivatives cable_parameter_derivatives(const CablePoints& x, double stiffness,
                                                      double rest_length);

}  // namespace kresling::elements
