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

std::vector<Index> CablePullControl::recorded_dofs() const {
  std::vector<Index> dofs;
  for (Index i = 0; i < base_.num_dofs(); ++i) {
    if (base_.fixed()[i]) dofs.push_back(i);
  }
  return dofs;
}

std::string CablePullControl::failure_message(int k, int steps, double t, int max_bisections,
                                              const std::string& reason) const {
  return "pull increment " + std::to_string(k) + " (of " + std::to_string(steps) + ", at " +
         format_number(t) + " of the pulls) failed after " + std::to_string(max_bisections) +
         " bisections; at full size: " + reason;
}

ControlRates CablePullControl::rates(double t, const VectorX& u) {
  const auto& families = base_.families();
  ControlRates r;
  r.held = VectorX::Zero(u.size());
  r.external = forces_to_ - forces_from_;
  r.internal = VectorX::Zero(u.size());
  r.energies = VectorX::Zero(static_cast<Index>(families.size()));
  double largest = 0.0;  // of the pulls' change over the path [mm]
  for (std::size_t i = 0; i < to_.size(); ++i) largest = std::max(largest, std::abs(to_[i] - from_[i]));
  if (largest == 0.0) return r;
  std::size_t index = 0;
  while (index < families.size() && std::string(families[index]->name()) != "cables") ++index;
  if (index == families.size()) return r;
  // Rest lengths moved by +-1e-6 mm at most (a cable's force is smooth in its rest length
  // away from slack; the kink itself is located, not differentiated across).
  const double h = 1e-6 / largest;
  auto evaluate = [&](double at, VectorX& force) {
    force.setZero(u.size());
    model::AssemblyTarget target{force};
    const model::Model m = base_.with_cable_rest_lengths(rest_lengths(at));
    return m.families()[index]->assemble(m.nodes(), u, target);
  };
  VectorX plus, minus;
  const double e_plus = evaluate(t + h, plus), e_minus = evaluate(t - h, minus);
  r.internal = (plus - minus) / (2.0 * h);
  r.energies[static_cast<Index>(index)] = (e_plus - e_minus) / (2.0 * h);
  return r;
}

}  // namespace kresling::solvers
