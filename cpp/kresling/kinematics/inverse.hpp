#pragma once
/// \file inverse.hpp
/// Inverse kinematics of one configuration: the tendon lengths (l1, l2, l3), shared by every
/// flexible module as in the thesis's protocol, that put the tip on a target point.
///
/// Projected damped least squares (Levenberg-Marquardt) on the box lower <= l_i <= upper,
/// started from the grid samples of the box nearest the target. Whether the target was
/// reached is a value in the result, never an exception.

#include <vector>

#include <Eigen/Core>

#include "kresling/kinematics/chain.hpp"

namespace kresling::kinematics {

/// Allowed tendon lengths of a flexible module [mm].
struct TendonBounds {
  double lower = 0.0;
  double upper = 0.0;
};

/// Throw unless 0 <= lower < upper (finite) and every length in the box is realisable by an
/// arc (checked at the box's corners, where Q, a convex quadratic, is largest).
void validate(const TendonBounds& bounds, const TendonLayout& layout);

/// Parameters of the solver, public fields as in DOLFINx's NewtonSolver.
struct InverseKinematicsOptions {
  double tolerance = 1e-10;      ///< stop when |tip - target| < tolerance [mm]
  int max_iterations = 100;      ///< per start
  double initial_damping = 1.0;  ///< lambda of (J J^T + lambda^2 I) [mm/mm]
  int grid_points = 7;           ///< seed grid: grid_points^3 samples of the box
  int starts = 3;                ///< nearest grid samples each solved from
};

/// Outcome of one solve.
struct InverseKinematicsResult {
  Eigen::Vector3d tendon_lengths = Eigen::Vector3d::Zero();  ///< l1, l2, l3 [mm]
  Eigen::Vector3d position = Eigen::Vector3d::Zero();        ///< tip at those lengths [mm]
  double distance = 0.0;  ///< |position - target| [mm]
  int iterations = 0;     ///< over all starts
  bool converged = false; ///< distance < tolerance
};

/// Tip positions over a grid of the box: `grid_points`^3 rows of (l1, l2, l3) and the
/// matching tip positions, each (grid_points^3, 3). A configuration without flexible modules
/// has one row (its fixed tip; tendon lengths reported as the box's midpoint).
void sample_workspace(const ChainModel& model, const Configuration& configuration,
                      const TendonBounds& bounds, int grid_points, Eigen::MatrixX3d& lengths,
                      Eigen::MatrixX3d& positions);

/// Solve for `target` [mm] from the grid samples nearest to it.
InverseKinematicsResult solve_inverse_kinematics(const ChainModel& model,
                                                 const Configuration& configuration,
                                                 const Eigen::Vector3d& target,
                                                 const TendonBounds& bounds,
                                                 const InverseKinematicsOptions& options = {});

/// solve_inverse_kinematics for many targets (rows of `targets`), sampling the box once.
std::vector<InverseKinematicsResult> solve_inverse_kinematics_batch(
    const ChainModel& model, const Configuration& configuration, const Eigen::MatrixX3d& targets,
    const TendonBounds& bounds, const InverseKinematicsOptions& options = {});

/// The outcomes of many solves as columns: row i of each is target i's (the fields of
/// InverseKinematicsResult, stacked).
struct InverseKinematicsTable {
  Eigen::MatrixX3d tendon_lengths;                    ///< (n, 3): l1, l2, l3 [mm]
  Eigen::MatrixX3d position;                          ///< (n, 3): tip at those lengths [mm]
  Eigen::VectorXd distance;                           ///< (n,): |position - target| [mm]
  Eigen::VectorXi iterations;                         ///< (n,): over all starts
  Eigen::Matrix<bool, Eigen::Dynamic, 1> converged;  ///< (n,): distance < tolerance
};
InverseKinematicsTable as_table(const std::vector<InverseKinematicsResult>& results);

/// Solve one damped-least-squares run from `start` (clamped into the box).
InverseKinematicsResult solve_from(const ChainModel& model, const Configuration& configuration,
                                   const Eigen::Vector3d& target, const TendonBounds& bounds,
                                   const Eigen::Vector3d& start,
                                   const InverseKinematicsOptions& options);

}  // namespace kresling::kinematics
