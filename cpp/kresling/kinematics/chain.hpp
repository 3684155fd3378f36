#pragma once
/// \file chain.hpp
/// The manipulator as a chain of m modules (thesis eqn 25): each module contracted (state 0,
/// a constant-curvature arc driven by the three tendons) or extended (state 1, a rigid link
/// of length L). Markers sit at the base and at every module end, as in section 4.3.
///
/// Model and data are separate (as in pinocchio): ChainModel is the hardware, fixed for the
/// life of a manipulator; a configuration (0/1 per module, base first) and the tendon
/// lengths of each flexible module are the inputs of each evaluation.
///
/// Coordinates: the base frame of eqn 26, z along the undeformed axis (away from the base
/// plate), tendon 1 on +x. Units: mm and rad.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "kresling/kinematics/constant_curvature.hpp"
#include "kresling/kinematics/module_transform.hpp"

namespace kresling::kinematics {

/// Most modules a chain may have: far beyond any arm built (the thesis's has 3), and
/// small enough that every per-module array (frames, markers, arcs, the workspace's
/// sampled configuration) stays a few MB.
inline constexpr int kMaxModules = 10000;

/// Most points backbone_points returns (m * per_module + 1): 240 MB of coordinates.
inline constexpr long long kMaxBackbonePoints = 10000000;

/// The hardware of a manipulator.
struct ChainModel {
  int modules = 0;                ///< m, in [1, kMaxModules]
  double extended_length = 0.0;   ///< L of eqn 30 [mm], the length of an extended module, > 0
  TendonLayout tendons;           ///< d and N of the flexible modules
  FrameConvention convention = FrameConvention::TwistFree;
};

/// Module states, base first: 0 contracted (flexible), 1 extended (rigid).
using Configuration = std::vector<int>;

/// Throw std::invalid_argument for m outside [1, kMaxModules], L <= 0 or an invalid tendon
/// layout.
void validate(const ChainModel& model);

/// Throw unless `configuration` has m entries, each 0 or 1.
void validate_configuration(const ChainModel& model, const Configuration& configuration);

/// Number of flexible (state 0) modules.
int flexible_count(const Configuration& configuration);

/// Arc of every module in the model's convention, rows (s, kappa, phi), shape (m, 3).
/// `flexible_tendon_lengths` has one row (l1, l2, l3) per flexible module, base first.
/// Rigid modules get (L, 0, 0). In the Jones convention each flexible module's phi is
/// measured from the frame the previous one left turned (phi_jones = phi - phi_previous);
/// for identical modules this is Appendix E's phi = 0 after the first.
Eigen::MatrixX3d module_arcs(const ChainModel& model, const Configuration& configuration,
                             const Eigen::MatrixX3d& flexible_tendon_lengths);

/// Frames at the base and at every module end, eqn 25: (m + 1) transforms, base first
/// (the identity). `arcs` as returned by module_arcs (rigid rows are ignored).
std::vector<Eigen::Matrix4d> module_end_frames(const ChainModel& model,
                                               const Configuration& configuration,
                                               const Eigen::MatrixX3d& arcs);

/// Positions of the markers (base and module ends) from the frames, shape (m + 1, 3).
Eigen::MatrixX3d frame_origins(const std::vector<Eigen::Matrix4d>& frames);

/// Points along the backbone for drawing: `per_module` + 1 points per module (the shared end
/// points once), shape (m * per_module + 1, 3), at most kMaxBackbonePoints rows.
Eigen::MatrixX3d backbone_points(const ChainModel& model, const Configuration& configuration,
                                 const Eigen::MatrixX3d& arcs, int per_module);

/// Tip position when every flexible module has the same tendon lengths `l` (the thesis's
/// assumption, and the inverse kinematics' input), via the smooth twist-free form.
Eigen::Vector3d tip_position(const ChainModel& model, const Configuration& configuration,
                             const Eigen::Vector3d& l);

/// d(tip) / d(l1, l2, l3) of tip_position (forward-mode automatic differentiation), (3, 3).
Eigen::Matrix3d tip_jacobian(const ChainModel& model, const Configuration& configuration,
                             const Eigen::Vector3d& l);

}  // namespace kresling::kinematics
