#pragma once
/// \file time_steps.hpp
/// The step policies of time integration (step_policy.hpp), whose path parameter is the
/// time t [s] from 0 to the duration:
/// - HalvedTimeSteps (the implicit schemes): steps of the nominal dt, the last one cut to
///   end at the duration; a failed step is halved, down to dt / 2^max_halvings, and each
///   accepted step lets the next grow back by a factor 2 up to dt;
/// - FixedTimeSteps (the explicit scheme): `steps` equal steps that cannot fail and be
///   retried, grouped `group` to an increment (the recorded steps): a failure ends the run.

#include <string>

#include "kresling/solvers/step_policy.hpp"

namespace kresling::solvers {

class HalvedTimeSteps final : public StepPolicy {
 public:
  /// time_step and duration [s] > 0 and max_halvings >= 0, checked by the caller.
  HalvedTimeSteps(double time_step, double duration, int max_halvings);
  /// increment.from: the accepted time, to: from + size, size: the step dt [s].
  bool next(Increment& increment) override;
  void accepted(const Increment& increment) override;
  bool rejected(const Increment& increment, const std::string& reason) override;
  /// The message of a failed run is the control's (PathControl::failure_message, with the
  /// accepted time and max_halvings).
  void finish(const PathControl& control, PathResult& result) const override;

 private:
  double nominal_, end_, smallest_;
  int max_halvings_;
  double t_ = 0.0, dt_;
  bool failed_ = false;
  std::string reason_;
};

class FixedTimeSteps final : public StepPolicy {
 public:
  /// `steps` >= 1 of dt = duration / steps, the last one ending at `duration` exactly;
  /// `group` >= 1 steps per increment (the last increment the remainder).
  FixedTimeSteps(long long steps, double duration, long long group);
  /// increment.size: the number of steps it takes; to: the time at its last step.
  bool next(Increment& increment) override;
  void accepted(const Increment& increment) override;
  bool rejected(const Increment& increment, const std::string& reason) override;
  /// A failed run's message is the reason its step gave.
  void finish(const PathControl& control, PathResult& result) const override;

  /// The time at step k [s].
  double time_at(long long k) const;

 private:
  long long steps_, group_;
  double duration_, dt_;
  long long k_ = 0;  // steps taken
  bool failed_ = false;
  std::string reason_;
};

}  // namespace kresling::solvers
