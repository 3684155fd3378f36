#pragma once
/// \file path_control.hpp
/// What a path's parameter t in [0, 1] drives: the load factor (force control), the imposed
/// DOFs (displacement control), a model parameter (hinge rest angles: folding by crease
/// actuation), or time. A control says, for any t, which model is solved, which DOFs are
/// held where it puts them, what external force acts, and which forces a step records; the
/// path follower (path_follower.hpp) does the stepping for every control alike. A control
/// may also supply each increment's corrector: Newton at the prescribed parameter by
/// default; MGDCM's (mgdcm.hpp) solves the load factor with the displacements instead.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "kresling/core/types.hpp"
#include "kresling/assembly/assembler.hpp"
#include "kresling/model/model.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/step_policy.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::solvers {

/// How a control moves along the path at parameter t with the displacements held at u:
/// what the adaptive increments' path tangent needs (path_point.hpp). Empty vectors mean
/// none.
struct ControlRates {
  VectorX held;      ///< du/dt at the DOFs the control holds, zero elsewhere (one per DOF)
  VectorX internal;  ///< the internal force's rate at fixed u (a model parameter's change)
  VectorX external;  ///< the external force's rate df_ext/dt (one per DOF)
  VectorX energies;  ///< each family's energy rate at fixed u, in the model's order
};

/// The `reason` PathControl::failure_message gives after "at full size: ", for an increment
/// that failed at every size tried: why it failed at full size and, when it was halved, why
/// at the smallest size tried (that size in the path parameter, to 3 digits).
std::string failure_at_sizes(const std::string& at_full_size, double smallest_size,
                             const std::string& at_smallest, bool halved);

class PathControl {
 public:
  virtual ~PathControl() = default;

  /// The model at parameter t. The follower rebinds to it before every attempt when
  /// changes_model(); the reference stays valid until the next call.
  virtual const model::Model& model_at(double t) = 0;
  virtual bool changes_model() const { return false; }
  /// Put the held DOFs of u where the control prescribes them at t and set `external` (one
  /// entry per DOF, sized by the caller) to the external force there.
  virtual void apply(double t, VectorX& u, VectorX& external) = 0;
  /// The same for an attempted increment from the accepted state `accepted` (at
  /// increment.from): apply(increment.to) unless the control accumulates its increments.
  virtual void advance(const Increment& increment, const VectorX& /*accepted*/, VectorX& u,
                       VectorX& external) {
    apply(increment.to, u, external);
  }
  /// DOFs besides the supports that the control holds (the imposed ones), none by default.
  virtual std::vector<Index> held_dofs() const { return {}; }
  /// DOFs whose force each step records (PathStep::constraint_force) and its sign: the
  /// force on the actuator (-f_int, sign -1) or the support reactions (f_int, sign +1).
  virtual std::vector<Index> recorded_dofs() const = 0;
  virtual double recorded_sign() const = 0;
  /// The message when increment k of `steps` fails for good at parameter t.
  virtual std::string failure_message(int k, int steps, double t, int max_bisections,
                                      const std::string& reason) const = 0;
  /// The control's rates at (t, u) (ControlRates). A control without them cannot be
  /// followed in adaptive increments: the default throws std::invalid_argument.
  virtual ControlRates rates(double t, const VectorX& u);
  /// The scalar whose dense output the adaptive increments' error estimate follows, from a
  /// point's recorded forces and per-family energies (a linear function of both): by
  /// default the total stored energy [N mm].
  virtual double monitored(const VectorX& forces, const VectorX& energies) const;
  /// What the path parameter is a fraction of, for messages ("the prescribed motion").
  virtual std::string parameter_name() const { return "the path"; }

  // Hooks of a control that carries a state of its own along the path (a time integrator:
  // velocity and acceleration), or solves its parameter (MGDCM). Each default leaves the
  // follower's static behaviour.

  /// Terms added to every solve of `increment` (a time step's inertia and damping, built
  /// from the accepted state); nullptr: the follower's own (FollowOptions::extra). Called
  /// once per attempt, before correct(); the terms live until the next call.
  virtual ExtraTerms* extra_terms(const Increment& /*increment*/) { return nullptr; }
  /// The increment's corrector: iterate from `u` (all DOFs: the accepted state or a
  /// predictor, with advance() applied) to the equilibrium that ends `increment`, with at
  /// most `max_iterations` iterations (0: options.max_iterations) and the optional `extra`
  /// terms (extra_terms(), else the follower's). By default Newton at the prescribed
  /// parameter under `external` (newton_equilibrium). A control may supply its own: MGDCM's
  /// (an arc-length method) solves the parameter with the displacements and sets
  /// increment.to to where it converged (the step records that parameter and the policy
  /// hears it); an implicit time step's chord iterations keep the factorisation from the
  /// previous step; an explicit step's update solves nothing.
  virtual NewtonOutcome correct(Increment& increment, assembly::Assembler& assembler,
                                TangentSolver& solver, VectorX& u, const VectorX& external,
                                const NewtonOptions& options, int max_iterations,
                                ExtraTerms* extra);
  /// Record a converged increment at u as a path step (record_step, the internal force at
  /// u into `internal`); a control whose corrector already evaluated u may reuse that.
  virtual PathStep record(assembly::Assembler& assembler, const VectorX& u, double t,
                          const NewtonOutcome& outcome, const std::vector<Index>& recorded,
                          double sign, VectorX& internal);
  /// The increment was accepted at u (its recorded step and the internal force there),
  /// before the stop rule is asked: a time control updates its velocity, acceleration and
  /// energies here.
  virtual void accepted(const Increment& /*increment*/, const VectorX& /*u*/,
                        const PathStep& /*step*/, const VectorX& /*internal*/) {}
};

/// The model's supported DOFs, in order (whose reactions a load-driven path records).
std::vector<Index> supported_dofs(const model::Model& model);

/// The rates at fixed u of a model parameter that changes one family of `model` (named
/// `family`; `family_at(t)` builds it at parameter t): its internal force's and energy's
/// central differences in t with step h (held and external left empty). Zero rates when
/// the model has no such family.
ControlRates family_rates(const model::Model& model, const std::string& family,
                          const std::function<model::FamilyPtr(double)>& family_at, double t,
                          double h, const VectorX& u);

/// Force control: external = t * forces on the model, supports' reactions recorded.
class LoadControl final : public PathControl {
 public:
  LoadControl(const model::Model& model, VectorX forces);
  const model::Model& model_at(double) override { return model_; }
  void apply(double t, VectorX& u, VectorX& external) override;
  std::vector<Index> recorded_dofs() const override;
  double recorded_sign() const override { return 1.0; }
  std::string failure_message(int k, int steps, double t, int max_bisections,
                              const std::string& reason) const override;
  ControlRates rates(double t, const VectorX& u) override;
  std::string parameter_name() const override { return "the load"; }

 private:
  const model::Model& model_;
  VectorX forces_;
};

/// Displacement control: the non-zero entries of `prescribed` are imposed, at
/// start + t * prescribed; no external force; the actuator's force recorded. With
/// `accumulate_steps` > 0 (MERLIN2's steps, merlin2_steps.hpp) an increment instead adds
/// increment.size times prescribed / accumulate_steps to the accepted state's imposed DOFs,
/// as MERLIN2 accumulates its motion.
class DisplacementDrive final : public PathControl {
 public:
  DisplacementDrive(const model::Model& model, VectorX prescribed, VectorX start,
                    int accumulate_steps = 0);
  const model::Model& model_at(double) override { return model_; }
  void apply(double t, VectorX& u, VectorX& external) override;
  void advance(const Increment& increment, const VectorX& accepted, VectorX& u,
               VectorX& external) override;
  std::vector<Index> held_dofs() const override { return imposed_; }
  std::vector<Index> recorded_dofs() const override { return imposed_; }
  double recorded_sign() const override { return -1.0; }
  std::string failure_message(int k, int steps, double t, int max_bisections,
                              const std::string& reason) const override;
  ControlRates rates(double t, const VectorX& u) override;
  /// The drive's force sum_k F_k U_k / max|U| (the force conjugate to the prescribed
  /// motion; the summed reaction of a uniform drive) [N].
  double monitored(const VectorX& forces, const VectorX& energies) const override;
  std::string parameter_name() const override { return "the prescribed motion"; }

 private:
  const model::Model& model_;
  VectorX prescribed_, start_;
  VectorX nominal_;  // prescribed / accumulate_steps (empty: not accumulating)
  std::vector<Index> imposed_;
};

/// Crease actuation: the rest angles of `hinges` move linearly from `from` to `to` (one of
/// each per driven hinge [rad], in [0, 2 pi)); the external force goes from
/// load_from * forces to load_to * forces; the supports' reactions are recorded.
class RestAngleControl final : public PathControl {
 public:
  RestAngleControl(const model::Model& model, std::vector<Index> hinges, VectorX from, VectorX to,
                   VectorX forces, double load_from, double load_to);
  const model::Model& model_at(double t) override;
  bool changes_model() const override { return true; }
  void apply(double t, VectorX& u, VectorX& external) override;
  std::vector<Index> recorded_dofs() const override;
  double recorded_sign() const override { return 1.0; }
  std::string failure_message(int k, int steps, double t, int max_bisections,
                              const std::string& reason) const override;
  /// The hinges' force and energy rates by central differences of the hinge family alone
  /// in the rest angles (exact up to rounding: every hinge law's moment is affine in its
  /// rest angle, so its energy is quadratic in it).
  ControlRates rates(double t, const VectorX& u) override;
  std::string parameter_name() const override { return "the crease actuation"; }

 private:
  const model::Model& base_;
  std::vector<Index> hinges_;
  VectorX from_, to_, forces_;
  double load_from_, load_to_;
  std::vector<model::Hinge> scratch_;  // the base's hinges, rest angles set per t
  std::optional<model::Model> current_;
};

}  // namespace kresling::solvers
