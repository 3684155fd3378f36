#pragma once
/// \file contact_barrier.hpp
/// IPC's log barrier (Li et al. 2020, Eq. 6) and the contact energy of one primitive pair
/// with its exact gradient and Hessian (pure kernels, no allocation).
///
///     b(s)
///      |  *
///      |   *
///      |     *
///      |        *
///      +-------------*-------- s      b(s) = -(s - s_hat)^2 ln(s / s_hat)  for 0 < s < s_hat,
///      0            s_hat             0 beyond; s = d^2, s_hat = d_hat^2
///
/// Convention (as IPC's implementations): the barrier is a function of the *squared*
/// distance s = d^2 with the threshold s_hat = d_hat^2, so the pair energy is
/// kappa b(d(x)^2, d_hat^2). b, b' and b'' all vanish at s_hat, so the energy is twice
/// continuously differentiable where a pair enters or leaves the barrier's range; b grows
/// without bound as s -> 0 and is positive, decreasing and convex on (0, s_hat). b carries
/// length^4, so the barrier stiffness kappa carries energy / length^4 (N / mm^3 for forces
/// in N and lengths in mm).
///
/// Pairs: point-triangle (p, t0, t1, t2) and edge-edge (ea0, ea1, eb0, eb1) with 12
/// coordinates, point-rigid plane with 3. The edge-edge energy is mollified,
/// m(x) kappa b(s) (contact_mollifier.hpp).
///
/// Thickness: with an offset t > 0 (the panels' thickness for two panels, half of it for a
/// panel and a plane) the barrier acts on the gap between the offset surfaces, s = (d - t)^2
/// (contact_offset.hpp): it acts while d < t + d_hat and grows without bound as d -> t. The
/// mollifier multiplies the offset barrier as it does the plain one: it depends on the
/// edges' directions alone, so the product stays continuously differentiable where two
/// edges turn parallel at any distance.

#include "kresling/core/types.hpp"
#include "kresling/contact/contact_distance.hpp"

namespace kresling::contact {

/// b(s), b'(s), b''(s) at one squared distance.
struct BarrierValue {
  double value = 0.0;
  double first = 0.0;
  double second = 0.0;
};

/// The log barrier and its first two derivatives in s, for squared distance s and threshold
/// s_hat > 0: zero for s >= s_hat; +inf value (and -inf, +inf derivatives) for s <= 0,
/// where primitives touch or cross.
BarrierValue log_barrier(double s, double s_hat);

/// What a pair energy computes besides its value and gradient.
enum class BarrierHessian {
  None,       ///< no Hessian (left zero): line searches, energy checks
  Exact,      ///< the exact Hessian (indefinite in general)
  Projected,  ///< the exact Hessian with its negative eigenvalues set to zero (for Newton)
};

/// kappa b(s(x)) for a squared distance s(x) with derivatives: gradient kappa b' grad s,
/// Hessian kappa (b'' grad s grad s^T + b' hess s). Zero when s >= d_hat^2; when s <= 0
/// (primitives touching or crossing) the value is +inf and the derivatives are left zero.
template <int N>
ScalarDerivatives<N> barrier_energy(const ScalarDerivatives<N>& distance, double d_hat,
                                    double stiffness, BarrierHessian hessian);

/// Contact energy of a point and a triangle at distance d_hat > 0 and stiffness kappa, the
/// barrier on the gap beyond `offset` >= 0 (0: the distance itself).
ScalarDerivatives<12> point_triangle_barrier(const Vector3& p, const Vector3& t0,
                                             const Vector3& t1, const Vector3& t2,
                                             double d_hat, double stiffness,
                                             BarrierHessian hessian = BarrierHessian::Exact,
                                             double offset = 0.0);

/// Contact energy of two edges, mollified with threshold eps_x > 0
/// (edge_edge_mollifier_threshold of the edges at rest).
ScalarDerivatives<12> edge_edge_barrier(const Vector3& ea0, const Vector3& ea1,
                                        const Vector3& eb0, const Vector3& eb1, double eps_x,
                                        double d_hat, double stiffness,
                                        BarrierHessian hessian = BarrierHessian::Exact,
                                        double offset = 0.0);

/// Contact energy of a point and a rigid plane (origin, normal of any non-zero length), in
/// the point's 3 coordinates. Unsigned: a point is kept on the side where it starts, at
/// least `offset` >= 0 from the plane.
ScalarDerivatives<3> point_plane_barrier(const Vector3& p, const Vector3& origin,
                                         const Vector3& normal, double d_hat, double stiffness,
                                         BarrierHessian hessian = BarrierHessian::Exact,
                                         double offset = 0.0);

/// The symmetric matrix nearest to `matrix` (in the Frobenius norm) that is positive
/// semi-definite: its eigen-decomposition with negative eigenvalues set to zero.
template <int N>
Eigen::Matrix<double, N, N> project_to_psd(const Eigen::Matrix<double, N, N>& matrix);

/// Throw std::invalid_argument unless d_hat > 0 and stiffness >= 0 (both finite): the
/// checks a caller makes once before evaluating pairs.
void check_barrier_parameters(double d_hat, double stiffness);

}  // namespace kresling::contact
