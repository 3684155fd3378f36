#include "kresling/kinematics/chain.hpp"

#include <stdexcept>

#include <unsupported/Eigen/AutoDiff>

#include "kresling/core/check.hpp"

namespace kresling::kinematics {

namespace {

// Tip of the chain with every flexible module at tendon lengths l; Scalar is double or an
// AutoDiffScalar (then the derivatives are the Jacobian's rows).
template <typename Scalar>
Eigen::Matrix<Scalar, 3, 1> tip_of_identical_modules(const ChainModel& model,
                                                     const Configuration& configuration,
                                                     const Eigen::Matrix<Scalar, 3, 1>& l) {
  Eigen::Matrix<Scalar, 3, 3> R = Eigen::Matrix<Scalar, 3, 3>::Identity();
  Eigen::Matrix<Scalar, 3, 1> p = Eigen::Matrix<Scalar, 3, 1>::Zero();
  bool have_flexible_motion = false;
  RigidMotion<Scalar> flexible;
  for (int state : configuration) {
    if (state == 1) {
      p += R.col(2) * Scalar(model.extended_length);
    } else {
      if (!have_flexible_motion) {  // identical modules: one evaluation serves them all
        flexible = twist_free_motion_from_tendons(l, model.tendons);
        have_flexible_motion = true;
      }
      p += R * flexible.translation;
      R = R * flexible.rotation;
    }
  }
  return p;
}

}  // namespace

void validate(const ChainModel& model) {
  if (model.modules < 1 || model.modules > kMaxModules) {
    throw_invalid("m", model.modules,
                  "an integer >= 1 and <= " + std::to_string(kMaxModules) + " (number of modules)");
  }
  require_positive("L", model.extended_length);
  validate(model.tendons);
}

void validate_configuration(const ChainModel& model, const Configuration& configuration) {
  validate(model);
  if (static_cast<int>(configuration.size()) != model.modules) {
    throw std::invalid_argument("configuration has " + std::to_string(configuration.size()) +
                                " entries: must have one per module (m = " +
                                std::to_string(model.modules) + ")");
  }
  for (std::size_t j = 0; j < configuration.size(); ++j) {
    if (configuration[j] != 0 && configuration[j] != 1) {
      throw_invalid("configuration[" + std::to_string(j) + "]", configuration[j],
                    "0 (contracted, flexible) or 1 (extended, rigid)");
    }
  }
}

int flexible_count(const Configuration& configuration) {
  int count = 0;
  for (int state : configuration) count += (state == 0);
  return count;
}

Eigen::MatrixX3d module_arcs(const ChainModel& model, const Configuration& configuration,
                             const Eigen::MatrixX3d& flexible_tendon_lengths) {
  validate_configuration(model, configuration);
  const int flexible = flexible_count(configuration);
  if (flexible_tendon_lengths.rows() != flexible) {
    throw std::invalid_argument(
        "tendon lengths have " + std::to_string(flexible_tendon_lengths.rows()) +
        " rows: must have one row (l1, l2, l3) per flexible module (" + std::to_string(flexible) +
        " in this configuration)");
  }
  Eigen::MatrixX3d arcs(model.modules, 3);
  double phi_previous = 0.0;  // Jones: how far the current frame is turned from the guides
  int row = 0;
  for (int j = 0; j < model.modules; ++j) {
    if (configuration[j] == 1) {
      arcs.row(j) << model.extended_length, 0.0, 0.0;
      continue;
    }
    const Eigen::Vector3d l = flexible_tendon_lengths.row(row).transpose();
    Eigen::Vector3d arc =
        arc_from_tendons(l, model.tendons, "[module " + std::to_string(j + 1) + "]");
    ++row;
    if (model.convention == FrameConvention::Jones) {
      const double phi = arc[2];
      arc[2] = phi - phi_previous;
      phi_previous = phi;
    }
    arcs.row(j) = arc.transpose();
  }
  return arcs;
}

std::vector<Eigen::Matrix4d> module_end_frames(const ChainModel& model,
                                               const Configuration& configuration,
                                               const Eigen::MatrixX3d& arcs) {
  validate_configuration(model, configuration);
  if (arcs.rows() != model.modules) {
    throw std::invalid_argument("arcs have " + std::to_string(arcs.rows()) +
                                " rows: must have one (s, kappa, phi) per module");
  }
  std::vector<Eigen::Matrix4d> frames{Eigen::Matrix4d::Identity()};
  frames.reserve(model.modules + 1);
  for (int j = 0; j < model.modules; ++j) {
    const Eigen::Matrix4d A =
        configuration[j] == 1
            ? rigid_module_transform(model.extended_length)
            : flexible_module_transform(arcs(j, 0), arcs(j, 1), arcs(j, 2), model.convention);
    frames.push_back(frames.back() * A);
  }
  return frames;
}

Eigen::MatrixX3d frame_origins(const std::vector<Eigen::Matrix4d>& frames) {
  Eigen::MatrixX3d out(static_cast<Eigen::Index>(frames.size()), 3);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    out.row(static_cast<Eigen::Index>(i)) = frames[i].block<3, 1>(0, 3).transpose();
  }
  return out;
}

Eigen::MatrixX3d backbone_points(const ChainModel& model, const Configuration& configuration,
                                 const Eigen::MatrixX3d& arcs, int per_module) {
  validate(model);
  // m * per_module in 64 bits: in int it overflows (a negative size, std::bad_alloc).
  const long long max_per_module = (kMaxBackbonePoints - 1) / model.modules;
  if (per_module < 1 || per_module > max_per_module) {
    throw_invalid("per_module", per_module,
                  "an integer >= 1 and <= " + std::to_string(max_per_module) + " (at most " +
                      std::to_string(kMaxBackbonePoints) + " points for m = " +
                      std::to_string(model.modules) + " modules)");
  }
  const auto frames = module_end_frames(model, configuration, arcs);
  Eigen::MatrixX3d points(model.modules * per_module + 1, 3);
  points.row(0).setZero();
  for (int j = 0; j < model.modules; ++j) {
    for (int k = 1; k <= per_module; ++k) {
      const double fraction = static_cast<double>(k) / per_module;
      // A partial arc keeps kappa and phi and shortens s; a rigid link shortens L.
      const Eigen::Matrix4d partial =
          configuration[j] == 1
              ? rigid_module_transform(fraction * model.extended_length)
              : flexible_module_transform(fraction * arcs(j, 0), arcs(j, 1), arcs(j, 2),
                                          model.convention);
      points.row(j * per_module + k) = (frames[j] * partial).block<3, 1>(0, 3).transpose();
    }
  }
  return points;
}

Eigen::Vector3d tip_position(const ChainModel& model, const Configuration& configuration,
                             const Eigen::Vector3d& l) {
  validate_configuration(model, configuration);
  if (flexible_count(configuration) > 0) decompose_tendons(l, model.tendons);
  return tip_of_identical_modules<double>(model, configuration, l);
}

Eigen::Matrix3d tip_jacobian(const ChainModel& model, const Configuration& configuration,
                             const Eigen::Vector3d& l) {
  validate_configuration(model, configuration);
  if (flexible_count(configuration) > 0) decompose_tendons(l, model.tendons);
  using Dual = Eigen::AutoDiffScalar<Eigen::Vector3d>;
  Eigen::Matrix<Dual, 3, 1> seeded;
  for (int i = 0; i < 3; ++i) seeded[i] = Dual(l[i], 3, i);
  const Eigen::Matrix<Dual, 3, 1> tip = tip_of_identical_modules<Dual>(model, configuration, seeded);
  Eigen::Matrix3d J;
  for (int r = 0; r < 3; ++r) J.row(r) = tip[r].derivatives().transpose();
  return J;
}

}  // namespace kresling::kinematics
