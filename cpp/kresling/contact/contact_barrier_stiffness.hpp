#pragma once
/// \file contact_barrier_stiffness.hpp
/// IPC's initial barrier stiffness (Li et al. 2020, Sec. 4.3; ipc-toolkit's
/// `initial_barrier_stiffness`), without a minimum separation:
///
///     s0      = (1e-8 l)^2               l: the diagonal of the scene's bounding box
///                                          (s0 = s_hat / 2 if that is not below s_hat)
///     kappa_min = c m / (4 s0 b''(s0))     c: a scale (1e11), m: an average nodal mass
///     kappa_max = 100 kappa_min
///     kappa   = clamp(-(grad B . grad E) / |grad B|^2, kappa_min, kappa_max)
///
/// with grad E the gradient of the elastic (and external) energy and grad B that of the
/// summed barrier energies at unit stiffness, both at the start of a solve (kappa = 1 before
/// clamping when grad B = 0). The unclamped value is the stiffness at which the barrier's
/// force best balances the elastic force along it (least squares). kappa_min is the
/// stiffness at which kappa 4 s0 b''(s0), the barrier's curvature (the Gauss-Newton part of
/// d2 b(d^2) / dd^2) at the smallest separation IPC considers resolvable, equals c m. IPC
/// minimises the incremental potential (x - x~)^T M (x - x~) / 2 + h^2 Psi + kappa B, whose
/// Hessian is M + h^2 K + kappa hess B, so m is a node's mass there; a static problem
/// minimises Psi + kappa B, and a caller passes a representative diagonal entry of the
/// elastic tangent K (energy / length^2), which takes M's place in the Newton matrix, as
/// `average_mass`.

#include "kresling/core/types.hpp"

namespace kresling::contact {

/// The initial stiffness and the bounds it was clamped to [energy / length^4].
struct BarrierStiffness {
  double stiffness = 0.0;
  double min_stiffness = 0.0;
  double max_stiffness = 0.0;
};

/// IPC's initial barrier stiffness (formula above). Throws std::invalid_argument unless
/// bbox_diagonal, d_hat, average_mass and min_stiffness_scale are positive and finite and
/// the two gradients have the same length.
BarrierStiffness initial_barrier_stiffness(double bbox_diagonal, double d_hat,
                                           double average_mass,
                                           const Eigen::Ref<const VectorX>& energy_gradient,
                                           const Eigen::Ref<const VectorX>& barrier_gradient,
                                           double min_stiffness_scale = 1e11);

}  // namespace kresling::contact
