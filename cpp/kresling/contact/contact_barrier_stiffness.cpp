// IPC's initial barrier stiffness (contact_barrier_stiffness.hpp).

#include "kresling/contact/contact_barrier_stiffness.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "kresling/core/check.hpp"
#include "kresling/contact/contact_barrier.hpp"

namespace kresling::contact {

BarrierStiffness initial_barrier_stiffness(double bbox_diagonal, double d_hat,
                                           double average_mass,
                                           const Eigen::Ref<const VectorX>& energy_gradient,
                                           const Eigen::Ref<const VectorX>& barrier_gradient,
                                           double min_stiffness_scale) {
  require_positive("bbox_diagonal", bbox_diagonal);
  require_positive("d_hat", d_hat);
  require_positive("average_mass", average_mass);
  require_positive("min_stiffness_scale", min_stiffness_scale);
  if (energy_gradient.size() != barrier_gradient.size()) {
    throw std::invalid_argument(
        "barrier_gradient has " + std::to_string(barrier_gradient.size()) +
        " entries: must have as many as energy_gradient (" +
        std::to_string(energy_gradient.size()) + ")");
  }
  const double s_hat = d_hat * d_hat;
  double s0 = 1e-8 * bbox_diagonal;
  s0 *= s0;
  if (s0 >= s_hat) s0 = 0.5 * s_hat;
  BarrierStiffness out;
  out.min_stiffness =
      min_stiffness_scale * average_mass / (4 * s0 * log_barrier(s0, s_hat).second);
  out.max_stiffness = 100 * out.min_stiffness;
  double kappa = 1.0;
  const double norm2 = barrier_gradient.squaredNorm();
  if (norm2 > 0) kappa = -barrier_gradient.dot(energy_gradient) / norm2;
  out.stiffness = std::clamp(kappa, out.min_stiffness, out.max_stiffness);
  return out;
}

}  // namespace kresling::contact
