#include "kresling/kinematics/module_transform.hpp"

#include "kresling/core/check.hpp"

namespace kresling::kinematics {

Eigen::Matrix4d flexible_module_transform(double s, double kappa, double phi,
                                          FrameConvention convention) {
  require_positive("s", s, /*allow_zero=*/true);
  require_positive("kappa", kappa, /*allow_zero=*/true);
  require_finite("phi", phi);
  const double theta = s * kappa;  // bend angle of the arc
  const double c = std::cos(theta), sn = std::sin(theta);
  const double cp = std::cos(phi), sp = std::sin(phi);
  // (1 - cos theta) / kappa = s theta B(theta^2),  sin(theta) / kappa = s A(theta^2).
  const double sideways = s * theta * versine_of_square(theta * theta);
  const double along = s * sinc_of_square(theta * theta);
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  T.block<3, 3>(0, 0) << cp, -sp * c, sp * sn,
                         sp, cp * c, -cp * sn,
                         0.0, sn, c;
  T.block<3, 1>(0, 3) << sp * sideways, -cp * sideways, along;
  if (convention == FrameConvention::TwistFree) {
    Eigen::Matrix3d undo_phi;  // Rz(-phi)
    undo_phi << cp, sp, 0.0,
                -sp, cp, 0.0,
                0.0, 0.0, 1.0;
    T.block<3, 3>(0, 0) = T.block<3, 3>(0, 0) * undo_phi;
  }
  return T;
}

Eigen::Matrix4d rigid_module_transform(double length) {
  require_positive("L", length, /*allow_zero=*/true);
  Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
  T(2, 3) = length;
  return T;
}

}  // namespace kresling::kinematics
