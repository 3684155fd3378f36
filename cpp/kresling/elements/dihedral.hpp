#pragma once
/// \file dihedral.hpp
/// Dihedral angle of a hinge and its first and second derivatives (pure kernels).
///
///              c  (wing 1)
///            .   .
///     a o-----------o b        axis a -> b
///            .   .
///              d  (wing 2)
///
/// Vectors of 12 are ordered (a, b, c, d). With e = b - a, r_ac = c - a, r_db = b - d,
/// m = r_ac x e and n = e x r_db, the angle is arccos(m.n / |m||n|), on the far side of
/// pi (2 pi minus it) when n . r_ac < -1e-8: pi when the two triangles are coplanar and
/// open (flat sheet), towards 0 or 2 pi as the hinge closes one way or the other. This is
/// MERLIN2's convention (docs/model.md, 'Hinges'), arccosine included, so that internal
/// forces agree with the reference runs to rounding; near 0 and pi the arccosine limits the
/// angle's absolute accuracy to about 1e-8 rad.

#include "kresling/core/types.hpp"

namespace kresling::elements {

/// Dihedral angle in [0, 2 pi).
double dihedral_angle(const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d);

/// d theta / d(a, b, c, d).
Vector12 dihedral_angle_gradient(const Vector3& a, const Vector3& b, const Vector3& c,
                                 const Vector3& d);

/// d2 theta / d(a, b, c, d)^2 (symmetric).
Matrix12 dihedral_angle_hessian(const Vector3& a, const Vector3& b, const Vector3& c,
                                const Vector3& d);

/// The angle and both derivatives from one evaluation of the shared terms.
struct DihedralDerivatives {
  double angle = 0.0;
  Vector12 gradient;
  Matrix12 hessian;  ///< left unset when not requested
};

/// Angle, gradient and (if `with_hessian`) Hessian. Degenerate hinges (a wing on the axis
/// line, or a zero-length axis) have no defined angle; callers validate geometry first.
DihedralDerivatives dihedral_angle_derivatives(const Vector3& a, const Vector3& b,
                                               const Vector3& c, const Vector3& d,
                                               bool with_hessian = true);

}  // namespace kresling::elements
