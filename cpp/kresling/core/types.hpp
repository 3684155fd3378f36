#pragma once
/// \file types.hpp
/// The few types every area shares. Node coordinates are row-major (n, 3) float64 arrays so
/// that numpy arrays cross the binding without copies; DOF 3 i + k is coordinate k of node i.

#include <cstdint>

#include <Eigen/Core>

namespace kresling {

using Vector3 = Eigen::Vector3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector12 = Eigen::Matrix<double, 12, 1>;
using Matrix12 = Eigen::Matrix<double, 12, 12>;
using Matrix3 = Eigen::Matrix3d;
using VectorX = Eigen::VectorXd;
using NodeMatrix = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// Index of a node or a DOF.
using Index = std::int64_t;

}  // namespace kresling
