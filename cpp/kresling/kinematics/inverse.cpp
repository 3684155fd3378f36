#include "kresling/kinematics/inverse.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Cholesky>

#include "kresling/core/check.hpp"
#include "kresling/core/interrupt.hpp"

namespace kresling::kinematics {

namespace {

constexpr double kMinDamping = 1e-12;
constexpr double kMaxDamping = 1e8;
// Seed grid: grid_points^3 samples (a million at most); Levenberg-Marquardt iterations.
constexpr int kMaxGridPoints = 100;
constexpr int kMaxIterations = 100000;

void check_grid_points(int grid_points) {
  require_integer_in("grid_points", grid_points, 2, kMaxGridPoints);
}

Eigen::Vector3d clamp_to(const Eigen::Vector3d& l, const TendonBounds& bounds) {
  return l.cwiseMax(bounds.lower).cwiseMin(bounds.upper);
}

void validate(const InverseKinematicsOptions& options) {
  require_positive("tolerance", options.tolerance);
  require_integer_in("max_iterations", options.max_iterations, 1, kMaxIterations);
  require_positive("initial_damping", options.initial_damping);
  check_grid_points(options.grid_points);
  if (options.starts < 1) throw_invalid("starts", options.starts, "an integer >= 1");
}

InverseKinematicsResult solve_from_samples(const ChainModel& model,
                                           const Configuration& configuration,
                                           const Eigen::Vector3d& target,
                                           const TendonBounds& bounds,
                                           const InverseKinematicsOptions& options,
                                           const Eigen::MatrixX3d& lengths,
                                           const Eigen::MatrixX3d& positions) {
  const Eigen::Index count = positions.rows();
  std::vector<Eigen::Index> order(static_cast<std::size_t>(count));
  std::iota(order.begin(), order.end(), Eigen::Index{0});
  const auto starts = std::min<Eigen::Index>(options.starts, count);
  std::partial_sort(order.begin(), order.begin() + starts, order.end(),
                    [&](Eigen::Index i, Eigen::Index j) {
                      return (positions.row(i).transpose() - target).squaredNorm() <
                             (positions.row(j).transpose() - target).squaredNorm();
                    });
  InverseKinematicsResult best;
  best.distance = INFINITY;
  int iterations = 0;
  for (Eigen::Index k = 0; k < starts; ++k) {
    const Eigen::Vector3d start = lengths.row(order[k]).transpose();
    InverseKinematicsResult run = solve_from(model, configuration, target, bounds, start, options);
    iterations += run.iterations;
    if (run.distance < best.distance) best = run;
    if (best.converged) break;
  }
  best.iterations = iterations;
  return best;
}

}  // namespace

void validate(const TendonBounds& bounds, const TendonLayout& layout) {
  require_positive("tendon_bounds.lower", bounds.lower, /*allow_zero=*/true);
  require_finite("tendon_bounds.upper", bounds.upper);
  if (!(bounds.upper > bounds.lower)) {
    throw_invalid("tendon_bounds.upper", bounds.upper,
                  "> tendon_bounds.lower = " + format_number(bounds.lower));
  }
  for (int corner = 0; corner < 8; ++corner) {
    Eigen::Vector3d l;
    for (int i = 0; i < 3; ++i) l[i] = (corner >> i) & 1 ? bounds.upper : bounds.lower;
    if (l.sum() > 0.0) decompose_tendons(l, layout, " (a corner of tendon_bounds)");
  }
}

void sample_workspace(const ChainModel& model, const Configuration& configuration,
                      const TendonBounds& bounds, int grid_points, Eigen::MatrixX3d& lengths,
                      Eigen::MatrixX3d& positions) {
  validate_configuration(model, configuration);
  validate(bounds, model.tendons);
  check_grid_points(grid_points);
  if (flexible_count(configuration) == 0) {  // all rigid: one reachable point
    lengths.resize(1, 3);
    lengths.row(0).setConstant(0.5 * (bounds.lower + bounds.upper));
    positions.resize(1, 3);
    positions.row(0) = tip_position(model, configuration, lengths.row(0).transpose()).transpose();
    return;
  }
  const int g = grid_points;
  lengths.resize(g * g * g, 3);
  positions.resize(g * g * g, 3);
  const double step = (bounds.upper - bounds.lower) / (g - 1);
  int row = 0;
  for (int i = 0; i < g; ++i) {
    for (int j = 0; j < g; ++j) {
      check_interrupt();
      for (int k = 0; k < g; ++k, ++row) {
        const Eigen::Vector3d l(bounds.lower + i * step, bounds.lower + j * step,
                                bounds.lower + k * step);
        lengths.row(row) = l.transpose();
        positions.row(row) = tip_position(model, configuration, l).transpose();
      }
    }
  }
}

InverseKinematicsResult solve_from(const ChainModel& model, const Configuration& configuration,
                                   const Eigen::Vector3d& target, const TendonBounds& bounds,
                                   const Eigen::Vector3d& start,
                                   const InverseKinematicsOptions& options) {
  InverseKinematicsResult out;
  out.tendon_lengths = clamp_to(start, bounds);
  out.position = tip_position(model, configuration, out.tendon_lengths);
  out.distance = (target - out.position).stableNorm();
  if (flexible_count(configuration) == 0) {
    out.converged = out.distance < options.tolerance;
    return out;
  }
  double damping = options.initial_damping;
  while (out.distance >= options.tolerance && out.iterations < options.max_iterations) {
    check_interrupt();
    ++out.iterations;
    const Eigen::Vector3d error = target - out.position;
    Eigen::Matrix3d J = tip_jacobian(model, configuration, out.tendon_lengths);
    // A length held at a bound by a descent direction pointing out of the box drops out of
    // the step (projected Levenberg-Marquardt with an active set).
    const Eigen::Vector3d descent = J.transpose() * error;
    for (int i = 0; i < 3; ++i) {
      const double l = out.tendon_lengths[i];
      if ((l <= bounds.lower && descent[i] < 0.0) || (l >= bounds.upper && descent[i] > 0.0)) {
        J.col(i).setZero();
      }
    }
    bool improved = false;
    while (!improved && damping <= kMaxDamping) {
      // (J^T J + lambda^2 I) dl = J^T e: the damped step, zero in the dropped lengths.
      const Eigen::Matrix3d normal =
          J.transpose() * J + damping * damping * Eigen::Matrix3d::Identity();
      const Eigen::Vector3d step = normal.ldlt().solve(J.transpose() * error);
      const Eigen::Vector3d trial = clamp_to(out.tendon_lengths + step, bounds);
      const Eigen::Vector3d position = tip_position(model, configuration, trial);
      const double distance = (target - position).stableNorm();
      if (distance < out.distance) {
        out.tendon_lengths = trial;
        out.position = position;
        out.distance = distance;
        damping = std::max(0.1 * damping, kMinDamping);
        improved = true;
      } else {
        damping *= 10.0;
      }
    }
    if (!improved) break;  // no step shortens the distance: a local minimum in the box
  }
  out.converged = out.distance < options.tolerance;
  return out;
}

InverseKinematicsResult solve_inverse_kinematics(const ChainModel& model,
                                                 const Configuration& configuration,
                                                 const Eigen::Vector3d& target,
                                                 const TendonBounds& bounds,
                                                 const InverseKinematicsOptions& options) {
  return solve_inverse_kinematics_batch(model, configuration, target.transpose(), bounds,
                                        options)
      .front();
}

std::vector<InverseKinematicsResult> solve_inverse_kinematics_batch(
    const ChainModel& model, const Configuration& configuration, const Eigen::MatrixX3d& targets,
    const TendonBounds& bounds, const InverseKinematicsOptions& options) {
  validate(options);
  for (Eigen::Index i = 0; i < targets.rows(); ++i) {
    for (int c = 0; c < 3; ++c) {
      require_finite("target[" + std::to_string(i) + "][" + std::to_string(c) + "]",
                     targets(i, c));
    }
  }
  Eigen::MatrixX3d lengths, positions;
  sample_workspace(model, configuration, bounds, options.grid_points, lengths, positions);
  std::vector<InverseKinematicsResult> results;
  results.reserve(static_cast<std::size_t>(targets.rows()));
  for (Eigen::Index i = 0; i < targets.rows(); ++i) {
    results.push_back(solve_from_samples(model, configuration, targets.row(i).transpose(), bounds,
                                         options, lengths, positions));
  }
  return results;
}

InverseKinematicsTable as_table(const std::vector<InverseKinematicsResult>& results) {
  const auto n = static_cast<Eigen::Index>(results.size());
  InverseKinematicsTable t{Eigen::MatrixX3d(n, 3), Eigen::MatrixX3d(n, 3), Eigen::VectorXd(n),
                           Eigen::VectorXi(n), Eigen::Matrix<bool, Eigen::Dynamic, 1>(n)};
  for (Eigen::Index i = 0; i < n; ++i) {
    const InverseKinematicsResult& r = results[static_cast<std::size_t>(i)];
    t.tendon_lengths.row(i) = r.tendon_lengths.transpose();
    t.position.row(i) = r.position.transpose();
    t.distance[i] = r.distance;
    t.iterations[i] = r.iterations;
    t.converged[i] = r.converged;
  }
  return t;
}

}  // namespace kresling::kinematics
