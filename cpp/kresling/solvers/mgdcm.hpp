#pragma once
/// \file mgdcm.hpp
/// The modified generalized displacement control method (MGDCM, Leon, Paulino et al. 2011):
/// path following under a reference load whose factor lambda is an unknown, through limit
/// points and snap-backs.
///
/// Each increment is Newton with two solves per iteration on one factorisation. The first
/// iteration's load increment is the step factor scaled by the generalized stiffness
/// parameter, its sign flipped where the predictor turns against the previous one (a limit
/// point); later iterations stay orthogonal to the first predictor. The step control is
/// MERLIN2's: the step factor grows by 1.5 after an increment of fewer than
/// `grow_below_iterations` iterations, an increment of more than `shrink_above_iterations`
/// is rejected and retried at half the step. One case is told apart: where Newton's
/// corrections stall at an accuracy floor above the tolerance (round-off near a singular
/// tangent, at a bifurcation or limit point), a shorter step cannot help, so the increment
/// is retried with a longer one, to land past the singular point; where that fails too the
/// path ends with the floor and the tolerance it would need. With a barrier among the
/// model's families (contact), each correction and its load increment are shortened
/// together to the fraction the collision check allows (barrier_step_fraction), so that no
/// iterate steps across it.
///
/// MGDCM is a configuration of the path follower (path_follower.hpp): MgdcmControl is the
/// control whose corrector solves each increment's load factor with the displacements, and
/// MgdcmSteps the step policy that sizes its step factor; follow_path does the stepping,
/// recording, stopping and failure bookkeeping as for every other path.
#include <limits>
#include <string>
#include <vector>

#include "kresling/model/model.hpp"
#include "kresling/solvers/path.hpp"
#include "kresling/solvers/path_control.hpp"
#include "kresling/solvers/step_policy.hpp"

namespace kresling::solvers {

struct MgdcmOptions {
  NewtonOptions newton;
  double initial_load_factor = 0.01;  ///< first increment of lambda (MERLIN2's b_lambda)
  int max_increments = 100;           ///< accepted increments
  /// Stop (completed) once |lambda| exceeds this.
  double max_load_factor = std::numeric_limits<double>::infinity();
  /// Stop (completed) once |u[monitor_dof]| exceeds max_displacement (monitor_dof >= 0).
  Index monitor_dof = -1;
  double max_displacement = std::numeric_limits<double>::infinity();
  int shrink_above_iterations = 15;  ///< more iterations: reject, halve the step factor
  int grow_below_iterations = 3;     ///< fewer iterations: step factor times 1.5
  double min_load_factor = 1e-14;    ///< give up when the step factor falls below this
  /// Cap on the step factor's growth (|b_lambda| <= this), for a finely resolved path.
  double max_step_factor = std::numeric_limits<double>::infinity();
  double shift = 1e-8;
  StopRule stop;  ///< a further stopping criterion (completed when it returns true)
};

/// MGDCM's control: the path parameter is the load factor lambda of the reference load
/// `forces` (one entry per DOF [N]), an unknown of each increment. Its corrector takes the
/// increment's step factor (Increment::size, signed) from increment.from and leaves
/// increment.to at the converged lambda; the supports' reactions are recorded. It keeps
/// the path's direction between increments: MgdcmSteps tells it (commit) when its last
/// attempt was accepted. No adaptive increments (no rates), no extra terms.
class MgdcmControl final : public PathControl {
 public:
  MgdcmControl(const model::Model& model, VectorX forces, const MgdcmOptions& options);
  const model::Model& model_at(double) override { return model_; }
  /// external = t * forces; no DOF is held.
  void apply(double t, VectorX& u, VectorX& external) override;
  std::vector<Index> recorded_dofs() const override { return supported_dofs(model_); }
  double recorded_sign() const override { return 1.0; }
  std::string failure_message(int k, int steps, double t, int max_bisections,
                              const std::string& reason) const override;
  std::string parameter_name() const override { return "the load factor"; }
  /// MGDCM's constrained Newton iterations (two solves on one factorisation each); throws
  /// std::invalid_argument when given extra terms.
  NewtonOutcome correct(Increment& increment, assembly::Assembler& assembler,
                        TangentSolver& solver, VectorX& u, const VectorX& external,
                        const NewtonOptions& options, int max_iterations,
                        ExtraTerms* extra) override;

  /// The last attempt ends the path's accepted part: its direction and predictor lead on.
  void commit();
  /// The outcome of the last attempt.
  const NewtonOutcome& last_outcome() const { return outcome_; }
  /// Whether the last attempt's corrections stalled at an accuracy floor above `tolerance`
  /// without an error (see the file's comment), and that floor, the smallest [mm].
  bool stalled(double tolerance) const;
  double floor() const;

 private:
  // The first iteration's load increment: the step factor, scaled after the first
  // increment by the generalized stiffness parameter, its sign set by the direction.
  double first_increment(const VectorX& dup, double step);

  const model::Model& model_;
  VectorX forces_;
  const MgdcmOptions& options_;
  double gsp_reference_ = 0.0;  // dup . dup of the first increment's first iteration
  double direction_ = 1.0;      // sign of the step along the path at the accepted state
  VectorX predictor_;           // the first iteration's K^-1 F of the increment to it
  // The last attempt: its direction and predictor, outcome, every correction's norm [mm].
  double trial_direction_ = 1.0;
  VectorX trial_predictor_;
  NewtonOutcome outcome_;
  std::vector<double> corrections_;
};

/// MGDCM's step control as a step policy: increments of step factor
/// options.initial_load_factor, grown by 1.5 (up to max_step_factor) after an increment
/// of fewer than grow_below_iterations iterations, halved after a rejected one (one of
/// more than shrink_above_iterations is rejected) down to min_load_factor, and made 4 then
/// 16 times longer after a stall; at most max_increments accepted ones. It reads the
/// corrector's last attempt from `control` and commits it when accepted.
class MgdcmSteps final : public StepPolicy {
 public:
  MgdcmSteps(MgdcmControl& control, const MgdcmOptions& options);
  bool next(Increment& increment) override;
  void accepted(const Increment& increment) override;
  bool rejected(const Increment& increment, const std::string& reason) override;
  /// The budget spent: completed unless a stopping criterion was set (then the message
  /// says it was not reached); a failure: its message, at the attempted increment.
  void finish(const PathControl& control, PathResult& result) const override;

 private:
  MgdcmControl& control_;
  const MgdcmOptions& options_;
  double lambda_ = 0.0;  // the accepted load factor
  double step_factor_;
  int accepted_ = 0;
  int jumps_ = 0;  // longer retries of the current increment after a stall
  bool failed_ = false;
  std::string message_;
};

/// The stopping rule of `options`: |lambda| > max_load_factor, |u[monitor_dof]| >
/// max_displacement, or options.stop.
StopRule mgdcm_stop_rule(const MgdcmOptions& options);

/// Follow the equilibrium path of lambda * `forces` (one entry per DOF [N]) from `initial`
/// (all DOFs; empty: zero) by MGDCM: follow_path with MgdcmControl and MgdcmSteps. Steps
/// record the supports' reactions.
PathResult solve_mgdcm(const model::Model& model, const VectorX& forces,
                       const MgdcmOptions& options = {}, const VectorX& initial = VectorX());

}  // namespace kresling::solvers
