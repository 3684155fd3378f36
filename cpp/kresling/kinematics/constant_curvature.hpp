#pragma once
/// \file constant_curvature.hpp
/// Jones's constant-curvature map for a section driven by three tendons (thesis eqns 27-29;
/// docs/thesis_equations.md, 'Kinematics') and its inverse.
///
/// Tendon i (i = 1, 2, 3) runs parallel to the backbone at radius d, at angle
/// sigma_i = 2 pi (i - 1) / 3 in the section's base frame (tendon 1 on +x, tendon 2 at +120
/// degrees, tendon 3 at +240 degrees, counter-clockwise seen from +z):
///
///                 y
///          l2 o   ^
///              \  |
///               \ |
///                 +-------o l1 --> x        (tendon ring of radius d, backbone at +)
///               /
///              /
///          l3 o
///
/// The arc (s, kappa, phi): arc length s [mm], curvature kappa >= 0 [1/mm], and phi [rad],
/// the angle of eqn 26: the tip moves towards (sin phi, -cos phi, 0), i.e. the section bends
/// towards its shortest tendon at angle phi - pi/2. Equal tendons give kappa = 0 and, by
/// convention, phi = 0.
///
/// With N > 1 each tendon is N straight segments between N + 1 guides; tendon i then has
/// length  l_i = 2 N sin(s kappa / (2 N)) (1 / kappa - d sin(phi - sigma_i)).

#include <string>

#include <Eigen/Core>

namespace kresling::kinematics {

/// Tendons of a section: ring radius and number of straight segments per tendon.
struct TendonLayout {
  double radius = 0.0;  ///< d [mm], distance from the backbone to each tendon, > 0
  int segments = 1;     ///< N, straight tendon segments per section, >= 1
};

/// Throw std::invalid_argument unless radius > 0 (finite) and segments >= 1.
void validate(const TendonLayout& layout);

/// Angle sigma_i of tendon i (0-based: 0, 1, 2) in the section's base frame [rad].
double tendon_angle(int i);

/// The intermediate quantities of eqns 27-29 for tendon lengths l (mm):
/// mean length, the bend vector (a, b) with sqrt(Q) = |(a, b)|, sin phi = a / sqrt(Q),
/// cos phi = b / sqrt(Q), and y = Q / (3 N d)^2 = sin^2(theta / (2 N)).
struct TendonDecomposition {
  double mean = 0.0;
  double a = 0.0;  ///< (l2 + l3 - 2 l1) / 2
  double b = 0.0;  ///< sqrt(3) (l2 - l3) / 2
  double y = 0.0;  ///< Q / (3 N d)^2, <= 1 for realisable lengths
};

/// Decompose tendon lengths; throws std::invalid_argument for negative or non-finite
/// lengths, an all-zero triple, and lengths no arc can realise (y > 1). `suffix` is appended
/// to names in messages (e.g. "[4]" for a batch entry).
TendonDecomposition decompose_tendons(const Eigen::Vector3d& lengths, const TendonLayout& layout,
                                      const std::string& suffix = "");

/// Eqns 27-29: tendon lengths (l1, l2, l3) [mm] -> arc (s [mm], kappa [1/mm], phi [rad]),
/// phi in (-pi, pi] by atan2 (the thesis's one-argument atan turns the bend by pi whenever
/// l2 < l3). Safe at and near the straight case (no division by sqrt(Q)).
Eigen::Vector3d arc_from_tendons(const Eigen::Vector3d& lengths, const TendonLayout& layout,
                                 const std::string& suffix = "");

/// Inverse map: arc (s, kappa, phi) -> tendon lengths (l1, l2, l3) [mm]. Throws for s < 0,
/// kappa < 0, non-finite values, s kappa > N pi (beyond the branch eqn 27 inverts) and arcs
/// that would need a negative tendon length.
Eigen::Vector3d tendons_from_arc(const Eigen::Vector3d& arc, const TendonLayout& layout,
                                 const std::string& suffix = "");

}  // namespace kresling::kinematics
