#include "kresling/solvers/path_control.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "kresling/core/check.hpp"

namespace kresling::solvers {

std::string failure_at_sizes(const std::string& at_full_size, double smallest_size,
                             const std::string& at_smallest, bool halved) {
  if (!halved || at_smallest.empty()) return at_full_size;
  return at_full_size + "; at the smallest size tried (" + format_rounded(smallest_size, 3) +
         "): " + at_smallest;
}

std::vector<Index> supported_dofs(const model::Model& model) {
  std::vector<Index> dofs;
  for (Index i = 0; i < model.num_dofs(); ++i) {
    if (model.fixed()[i]) dofs.push_back(i);
  }
  return dofs;
}

ControlRates family_rates(const model::Model& model, const std::string& family,
                          const std::function<model::FamilyPtr(double)>& family_at, double t,
                          double h, const VectorX& u) {
  const auto& families = model.families();
  ControlRates r;
  r.internal = VectorX::Zero(u.size());
  r.energies = VectorX::Zero(static_cast<Index>(families.size()));
  std::size_t index = 0;
  while (index < families.size() && families[index]->name() != family) ++index;
  if (index == families.size()) return r;
  auto evaluate = [&](double at, VectorX& force) {
    force.setZero(u.size());
    model::AssemblyTarget target{force};
    return family_at(at)->assemble(model.nodes(), u, target);
  };
  VectorX plus, minus;
  const double e_plus = evaluate(t + h, plus), e_minus = evaluate(t - h, minus);
  r.internal = (plus - minus) / (2.0 * h);
  r.energies[static_cast<Index>(index)] = (e_plus - e_minus) / (2.0 * h);
  return r;
}

ControlRates PathControl::rates(double, const VectorX&) {
  throw std::invalid_argument(
      "increments: this path cannot be followed in adaptive increments (its control has no "
      "path rates); use fixed increments");
}

double PathControl::monitored(const VectorX&, const VectorX& energies) const {
  double sum = 0.0;
  for (Index i = 0; i < energies.size(); ++i) sum += energies[i];
  return sum;
}

NewtonOutcome PathControl::correct(Increment&, assembly::Assembler& assembler,
                                   TangentSolver& solver, VectorX& u, const VectorX& external,
                                   const NewtonOptions& options, int max_iterations,
                                   ExtraTerms* extra) {
  return newton_equilibrium(assembler, solver, u, external, options, max_iterations, extra);
}

PathStep PathControl::record(assembly::Assembler& assembler, const VectorX& u, double t,
                             const NewtonOutcome& outcome, const std::vector<Index>& recorded,
                             double sign, VectorX& internal) {
  return record_step(assembler, u, t, outcome, recorded, sign, &internal);
}

LoadControl::LoadControl(const model::Model& model, VectorX forces)
    : model_(model), forces_(std::move(forces)) {}

void LoadControl::apply(double t, VectorX&, VectorX& external) { external = t * forces_; }

ControlRates LoadControl::rates(double, const VectorX&) {
  ControlRates r;
  r.held = VectorX::Zero(forces_.size());
  r.external = forces_;
  return r;
}

std::vector<Index> LoadControl::recorded_dofs() const { return supported_dofs(model_); }

std::string LoadControl::failure_message(int k, int steps, double t, int max_bisections,
                                         const std::string& reason) const {
  return "no equilibrium found beyond load factor " + format_rounded(t) + " (load step " +
         std::to_string(k) + " of " + std::to_string(steps) + ", " +
         std::to_string(max_bisections) + " bisections; a limit point? use MGDCM); at full size: " +
         reason;
}

DisplacementDrive::DisplacementDrive(const model::Model& model, VectorX prescribed, VectorX start,
                                     int accumulate_steps)
    : model_(model), prescribed_(std::move(prescribed)), start_(std::move(start)) {
  for (Index i = 0; i < prescribed_.size(); ++i) {
    if (prescribed_[i] != 0.0) imposed_.push_back(i);
  }
  if (accumulate_steps > 0) nominal_ = prescribed_ / static_cast<double>(accumulate_steps);
}

void DisplacementDrive::advance(const Increment& increment, const VectorX& accepted, VectorX& u,
                                VectorX& external) {
  if (nominal_.size() == 0) {
    apply(increment.to, u, external);
    return;
  }
  for (Index i : imposed_) u[i] = accepted[i] + increment.size * nominal_[i];
  external.setZero();
}

void DisplacementDrive::apply(double t, VectorX& u, VectorX& external) {
  for (Index i : imposed_) u[i] = start_[i] + t * prescribed_[i];
  external.setZero();
}

ControlRates DisplacementDrive::rates(double, const VectorX&) {
  ControlRates r;
  r.held = VectorX::Zero(prescribed_.size());
  for (Index i : imposed_) r.held[i] = prescribed_[i];
  return r;
}

double DisplacementDrive::monitored(const VectorX& forces, const VectorX&) const {
  double largest_motion = 0.0;
  for (Index i : imposed_) largest_motion = std::max(largest_motion, std::abs(prescribed_[i]));
  double g = 0.0;
  for (std::size_t k = 0; k < imposed_.size(); ++k) {
    g += forces[static_cast<Index>(k)] * prescribed_[imposed_[k]];
  }
  return g / largest_motion;
}

std::string DisplacementDrive::failure_message(int k, int steps, double t, int max_bisections,
                                               const std::string& reason) const {
  return "increment " + std::to_string(k) + " (of " + std::to_string(steps) + ", at " +
         format_rounded(t) + " of the prescribed motion) failed after " +
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

ControlRates RestAngleControl::rates(double t, const VectorX& u) {
  double largest = 0.0;  // of the rest angles' change over the path [rad]
  for (Index k = 0; k < to_.size(); ++k) largest = std::max(largest, std::abs(to_[k] - from_[k]));
  ControlRates r;
  if (largest == 0.0) {
    r.internal = VectorX::Zero(u.size());
    r.energies = VectorX::Zero(static_cast<Index>(base_.families().size()));
  } else {
    // Rest angles moved by +-1e-4 rad at most: the central difference is exact for a
    // moment affine in the rest angle, and its rounding is ~1e-16 (theta - theta0) / 1e-4
    // relative.
    std::vector<model::Hinge> hinges = base_.hinges();
    auto hinges_at = [&](double at) -> model::FamilyPtr {
      for (std::size_t i = 0; i < hinges_.size(); ++i) {
        const auto k = static_cast<Index>(i);
        hinges[static_cast<std::size_t>(hinges_[i])].rest_angle = from_[k] + at * (to_[k] - from_[k]);
      }
      return std::make_shared<model::HingeFamily>(hinges);
    };
    r = family_rates(base_, "hinges", hinges_at, t, 1e-4 / largest, u);
  }
  r.held = VectorX::Zero(u.size());
  r.external = (load_to_ - load_from_) * forces_;
  return r;
}

std::vector<Index> RestAngleControl::recorded_dofs() const { return supported_dofs(base_); }

std::string RestAngleControl::failure_message(int k, int steps, double t, int max_bisections,
                                              const std::string& reason) const {
  return "fold increment " + std::to_string(k) + " (of " + std::to_string(steps) + ", at " +
         format_rounded(t) + " of the crease actuation) failed after " +
         std::to_string(max_bisections) + " bisections; at full size: " + reason;
}

}  // namespace kresling::solvers
