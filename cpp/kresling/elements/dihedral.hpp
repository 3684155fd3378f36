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
/// m = r_ac x e and n = e x r_db, the angle is the one from m to n about the axis: pi when
/// the two triangles are coplanar and open (flat sheet), towards 0 or 2 pi as the hinge
/// closes one way or the other (MERLIN2's convention, docs/model.md, 'Hinges').
///
/// Two forms compute it (DihedralForm). The exact one takes atan2 of the normals' cross and
/// dot products, accurate to rounding at every angle, flat (pi) and folded flat (0, 2 pi)
/// included. MERLIN2's takes arccos(m.n / |m||n|), on the far side of pi when
/// n . r_ac < -1e-8; near 0 and pi the arccosine turns the last bits of its argument into up
/// to ~1e-8 rad, which is what a nearly flat sheet's Newton iterations then see as noise. It
/// is kept to reproduce MERLIN2's runs to rounding. The derivatives are the same for both.

#include "kresling/core/types.hpp"

namespace kresling::elements {

/// How a dihedral angle is computed from its hinge's two normals.
enum class DihedralForm : int {
  Exact = 0,    ///< atan2: accurate to rounding everywhere (the default)
  Merlin2 = 1,  ///< MERLIN2's arccosine, ~1e-8 rad of rounding near 0 and pi
};

/// The form coded `code` (0 exact, 1 MERLIN2's); std::invalid_argument naming `what`
/// otherwise.
DihedralForm dihedral_form(long long code, const char* what);

/// Dihedral angle in [0, 2 pi).
double dihedral_angle(const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d,
                      DihedralForm form = DihedralForm::Exact);

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
                                               bool with_hessian = true,
                                               DihedralForm form = DihedralForm::Exact);

}  // namespace kresling::elements
