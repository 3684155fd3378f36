#include "kresling/solvers/cable_pull_control.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "kresling/core/check.hpp"

namespace kresling::solvers {

CablePullControl::CablePullControl(const model::Model& model, std::vector<double> slack,
                                   std::vector<double> pulls_from, std::vector<double> pulls_to,
                                   VectorX forces_from, VectorX forces_to)
    : base_(model),
      slack_(std::move(slack)),
      from_(std::move(pulls_from)),
      to_(std::move(pulls_to)),
      forces_from_(std::move(forces_from)),
      forces_to_(std::move(forces_to)) {
  const std::size_t n = model.cables().size();
  if (slack_.size() != n || from_.size() != n || to_.size() != n) {
    throw std::invalid_argument("pulls: need one slack length and two pulls per cable (" +
                                std::to_string(n) + ")");
  }
  if (forces_from_.size() != model.num_dofs() || forces_to_.size() != model.num_dofs()) {
    throw std::invalid_argument("forces: must have one entry per DOF (" +
                                std::to_string(model.num_dofs()) + ")");
  }
}

std::vector<double> CablePullControl::pulls_at(double t) const {
  std::vector<double> pulls(from_.size());
  for (std::size_t i = 0; i < pulls.size(); ++i) pulls[i] = from_[i] + t * (to_[i] - from_[i]);
  return pulls;
}

std::vector<double> CablePullControl::rest_lengths(double t) const {
  std::vector<double> rest = pulls_at(t);
  for (std::size_t i = 0; i < rest.size(); ++i) rest[i] = slack_[i] - rest[i];
  return rest;
}

const model::Model& CablePullControl::model_at(double t) {
  current_.emplace(base_.with_cable_rest_lengths(rest_lengths(t)));
  return *current_;
}

void CablePullControl::apply(double t, VectorX&, VectorX& external) {
  external = forces_from_ + t * (forces_to_ - forces_from_);
}

std::vector<Index> CablePullControl::recorded_dofs() const { return supported_dofs(base_); }

std::string CablePullControl::failure_message(int k, int steps, double t, int max_bisections,
                                              const std::string& reason) const {
  return "pull increment " + std::to_string(k) + " (of " + std::to_string(steps) + ", at " +
         format_rounded(t) + " of the pulls) failed after " + std::to_string(max_bisections) +
         " bisections; at full size: " + reason;
}

ControlRates CablePullControl::rates(double t, const VectorX& u) {
  double largest = 0.0;  // of the pulls' change over the path [mm]
  for (std::size_t i = 0; i < to_.size(); ++i) largest = std::max(largest, std::abs(to_[i] - from_[i]));
  ControlRates r;
  if (largest == 0.0) {
    r.internal = VectorX::Zero(u.size());
    r.energies = VectorX::Zero(static_cast<Index>(base_.families().size()));
  } else {
    // Rest lengths moved by +-1e-6 mm at most (a cable's force is smooth in its rest
    // length away from slack; the kink itself is located, not differentiated across).
    auto cables_at = [&](double at) -> model::FamilyPtr {
      const model::Model m = base_.with_cable_rest_lengths(rest_lengths(at));
      for (const auto& family : m.families()) {
        if (std::string(family->name()) == "cables") return family;
      }
      return nullptr;  // not reached: family_rates asks only for a family the model has
    };
    r = family_rates(base_, "cables", cables_at, t, 1e-6 / largest, u);
  }
  r.held = VectorX::Zero(u.size());
  r.external = forces_to_ - forces_from_;
  return r;
}

}  // namespace kresling::solvers
