#pragma once
/// \file cable_pull_control.hpp
/// Cable actuation, a model-parameter control (path_control.hpp): every cable's rest length
/// is its slack length minus a pull, the pulls moving linearly from `pulls_from` to
/// `pulls_to` [mm] (how tendons are pulled: analyses/arm_analysis.hpp), while the external
/// force goes linearly from `forces_from` to `forces_to` [N]; the supports' reactions are
/// recorded.

#include <optional>
#include <string>
#include <vector>

#include "kresling/solvers/path_control.hpp"

namespace kresling::solvers {

class CablePullControl final : public PathControl {
 public:
  /// One slack length and two pulls per cable of `model` (rest lengths slack - pull must
  /// stay positive: the caller checks), forces with one entry per DOF. Throws
  /// std::invalid_argument for sizes that do not fit.
  CablePullControl(const model::Model& model, std::vector<double> slack,
                   std::vector<double> pulls_from, std::vector<double> pulls_to,
                   VectorX forces_from, VectorX forces_to);
  const model::Model& model_at(double t) override;
  bool changes_model() const override { return true; }
  void apply(double t, VectorX& u, VectorX& external) override;
  std::vector<Index> recorded_dofs() const override;
  double recorded_sign() const override { return 1.0; }
  std::string failure_message(int k, int steps, double t, int max_bisections,
                              const std::string& reason) const override;
  /// The cables' force and energy rates by central differences of the cable family alone
  /// in t (their kink at the rest length is located by the adaptive increments).
  ControlRates rates(double t, const VectorX& u) override;
  std::string parameter_name() const override { return "the pulls"; }

  /// The pulls at t [mm], one per cable: from + t (to - from).
  std::vector<double> pulls_at(double t) const;

 private:
  std::vector<double> rest_lengths(double t) const;
  const model::Model& base_;
  std::vector<double> slack_, from_, to_;
  VectorX forces_from_, forces_to_;
  std::optional<model::Model> current_;
};

}  // namespace kresling::solvers
