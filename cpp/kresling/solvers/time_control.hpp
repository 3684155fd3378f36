#pragma once
/// \file time_control.hpp
/// Time as a path's parameter (path_control.hpp): the control of the time integrators
/// (time_integration.hpp, explicit_dynamics.hpp), which the path follower steps like any
/// other. The model is the same at every time but for the rest angles of the creases an
/// actuation drives (DrivenRestAngles), its supports hold their DOFs at zero and their
/// reactions are recorded, and the load is a TimeLoad. What a scheme adds (its
/// inertia and damping terms, its corrector, the velocity and acceleration it carries from
/// step to step) its own control supplies through the hooks of PathControl; the motion it
/// records per step (velocity and energies) goes into `history`.

#include <optional>
#include <string>
#include <vector>

#include "kresling/model/model.hpp"
#include "kresling/solvers/path_control.hpp"
#include "kresling/solvers/time_integration.hpp"

namespace kresling::solvers {

/// A model whose hinges' rest angles follow a RestAngleSchedule (the model as given
/// without one). The schedule is checked here: each term one start and one delta per
/// hinge, all finite, every hinge one of the model's (std::invalid_argument otherwise).
class DrivenRestAngles {
 public:
  /// `model` and `schedule` are kept by reference.
  DrivenRestAngles(const model::Model& model, const RestAngleSchedule& schedule);
  bool driven() const { return !schedule_.empty(); }
  /// The model at t [s]; the reference stays valid until the next call.
  const model::Model& model_at(double t);
  /// The hinges' energy at displacement u with the rest angles at t [N mm].
  double hinge_energy(double t, const VectorX& u);

 private:
  void set_rest_angles(double t);

  const model::Model& base_;
  const RestAngleSchedule& schedule_;
  std::vector<model::Hinge> scratch_;  // the base's hinges, rest angles set per t
  std::optional<model::Model> current_;
  VectorX force_;                      // hinge_energy's unused force
};

class TimeControl : public PathControl {
 public:
  /// `model`, `load` and `actuation` are kept by reference.
  TimeControl(const model::Model& model, const TimeLoad& load,
              const RestAngleSchedule& actuation = kNoActuation);
  const model::Model& model_at(double t) override { return driven_.model_at(t); }
  bool changes_model() const override { return driven_.driven(); }
  /// The time control holds no DOFs and its load enters through advance(): nothing here.
  void apply(double, VectorX&, VectorX&) override {}
  std::vector<Index> recorded_dofs() const override { return supported_; }
  double recorded_sign() const override { return 1.0; }
  /// "time step at t = <t> s failed after <max_bisections> halvings: <reason>".
  std::string failure_message(int k, int steps, double t, int max_bisections,
                              const std::string& reason) const override;
  std::string parameter_name() const override { return "the time"; }

  /// The motion of every recorded step: velocity, kinetic, strain, dissipated and work
  /// (path, stable_time_step and time_step are the integrator's to set).
  TimeHistory history;

 protected:
  /// Append one recorded step's motion to `history`.
  void record_motion(const VectorX& velocity, double kinetic, double strain, double dissipated,
                     double work, double actuation_work = 0.0);

  /// No creases driven.
  static const RestAngleSchedule kNoActuation;

  const model::Model& model_;
  const TimeLoad& load_;
  std::vector<Index> supported_;
  DrivenRestAngles driven_;
};

}  // namespace kresling::solvers
