#include "kresling/solvers/path_control.hpp"

#include <memory>
#include <stdexcept>

#include "kresling/core/check.hpp"

namespace kresling::solvers {

namespace {

std::vector<Index> supported_dofs(const model::Model& model) {
  std::vector<Index> dofs;
  for (Index i = 0; i < model.num_dofs(); ++i) {
    if (model.fixed()[i]) dofs.push_back(i);
  }
  return dofs;
}

}  // namespace

LoadControl::LoadControl(const model::Model& model, VectorX forces)
    : model_(model), forces_(std::move(forces)) {}

void LoadControl::apply(double t, VectorX&, VectorX& external) { external = t * forces_; }

std::vector<Index> LoadControl::recorded_dofs() const { return supported_dofs(model_); }

std::string LoadControl::failure_message(int k, int steps, double t, int max_bisections,
                                         const std::string& reason) const {
  return "no equilibrium found beyond load factor " + format_number(t) + " (load step " +
         std::to_string(k) + " of " + std::to_string(steps) + ", " +
         std::to_string(max_bisections) + " bisections; a limit point? use MGDCM); at full size: " +
         reason;
}

DisplacementDrive::DisplacementDrive(const model::Model& model, VectorX prescribed, VectorX start)
    : model_(model), prescribed_(std::move(prescribed)), start_(std::move(start)) {
  for (Index i = 0; i < prescribed_.size(); ++i) {
    if (prescribed_[i] != 0.0) imposed_.push_back(i);
  }
}

void DisplacementDrive::apply(double t, VectorX& u, VectorX& external) {
  for (Index i : imposed_) u[i] = start_[i] + t * prescribed_[i];
  external.setZero();
}

std::string DisplacementDrive::failure_message(int k, int steps, double t, int max_bisections,
                                               const std::string& reason) const {
  return "increment " + std::to_string(k) + " (of " + std::to_string(steps) + ", at " +
         format_number(t) + " of the prescribed motion) failed after " +
         std::to_string(max_bisections) + " bisections; at full size: " + reason;
}

RestAngleControl::RestAngleControl(const model::Model& model, std::vector<Index> hinges,
                                   VectorX from, VectorX to, VectorX forces, double load_from,
                                   double load_to)
    : base_(model),
      hinges_(std::move(hinges)),
      from_(std::move(from)),
      to_(std::move(to)),
      forces_(std::move(forces)),
      load_from_(load_from),
      load_to_(load_to),
      scratch_(model.hinges()) {
  const auto n = static_cast<Index>(hinges_.size());
  if (from_.size() != n || to_.size() != n) {
    throw std::invalid_argument("rest angles: need one start and one target per driven hinge (" +
                                std::to_string(n) + ")");
  }
  for (Index h : hinges_) {
    if (h < 0 || h >= static_cast<Index>(scratch_.size())) {
      throw std::invalid_argument("hinges: " + std::to_string(h) + " is not a hinge of the model (" +
                                  std::to_string(scratch_.size()) + " hinges)");
    }
  }
  if (forces_.size() != model.num_dofs()) {
    throw std::invalid_argument("forces: must have one entry per DOF (" +
                                std::to_string(model.num_dofs()) + ")");
  }
}

const model::Model& RestAngleControl::model_at(double t) {
  for (std::size_t i = 0; i < hinges_.size(); ++i) {
    const auto k = static_cast<Index>(i);
    scratch_[static_cast<std::size_t>(hinges_[i])].rest_angle = from_[k] + t * (to_[k] - from_[k]);
  }
  current_.emplace(base_.with_family(std::make_shared<model::HingeFamily>(scratch_)));
  return *current_;
}

void RestAngleControl::apply(double t, VectorX&, VectorX& external) {
  external = (load_from_ + t * (load_to_ - load_from_)) * forces_;
}

std::vector<Index> RestAngleControl::recorded_dofs() const { return supported_dofs(base_); }

std::string RestAngleControl::failure_message(int k, int steps, double t, int max_bisections,
                                              const std::string& reason) const {
  return "fold increment " + std::to_string(k) + " (of " + std::to_string(steps) + ", at " +
         format_number(t) + " of the crease actuation) failed after " +
         std::to_string(max_bisections) + " bisections; at full size: " + reason;
}

}  // namespace kresling::solvers
