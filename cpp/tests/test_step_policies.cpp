// The path follower's step policies on their own (step_policy.hpp): the increments each
// proposes as attempts are accepted or rejected, against the rules their headers state.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "kresling/solvers/halving_steps.hpp"
#include "kresling/solvers/merlin2_steps.hpp"
#include "kresling/solvers/time_control.hpp"
#include "kresling/solvers/time_steps.hpp"
#include "oscillator_test_helpers.hpp"

using namespace kresling;
using solvers::Increment;

// MERLIN2's rule: ten rejections in a row halve the step factor; the next ten grow it by
// 1.5 (from at least 1) and damp Newton by 0.75 each; the 21st in a row ends the path.
TEST(StepPolicies, Merlin2HalvesThenGrowsAndDampsThenGivesUp) {
  solvers::Merlin2Steps policy(10, 50);
  Increment inc;
  std::vector<double> sizes, dampings;
  while (policy.next(inc)) {
    sizes.push_back(inc.size);
    dampings.push_back(inc.damping);
    policy.rejected(inc, "no");
  }
  ASSERT_EQ(sizes.size(), 21u);
  for (int k = 0; k <= 10; ++k) EXPECT_EQ(sizes[k], std::ldexp(1.0, -k));
  EXPECT_EQ(sizes[11], 1.5);
  EXPECT_EQ(dampings[11], 0.75);
  EXPECT_EQ(sizes[12], 2.25);
  EXPECT_EQ(dampings[12], 0.75 * 0.75);
  // An increment is rejected at ((factor > 1) + 1) max_iterations / (damping + 1)
  // iterations: 25 of 50 for a plain one (MERLIN2's), more for a bold, damped one.
  solvers::Merlin2Steps fresh(10, 50);
  ASSERT_TRUE(fresh.next(inc));
  EXPECT_EQ(inc.reject_at, 25.0);
  EXPECT_EQ(inc.newton_limit, 25);
  EXPECT_EQ(inc.to, 0.1);
  for (int k = 0; k < 11; ++k) fresh.rejected(inc, "no");
  ASSERT_TRUE(fresh.next(inc));
  EXPECT_EQ(inc.reject_at, 2.0 * 50 / 1.75);
  EXPECT_EQ(inc.newton_limit, 50);
}

// After a rejection, accepted increments move the factor 10 % back towards 1, and the path
// runs while the accumulated fraction is <= 1 (it may end past it, as MERLIN2's does).
TEST(StepPolicies, Merlin2RecoversTowardsOneAndMayOvershoot) {
  solvers::Merlin2Steps policy(4, 50);
  Increment inc;
  ASSERT_TRUE(policy.next(inc));
  policy.rejected(inc, "no");
  ASSERT_TRUE(policy.next(inc));
  EXPECT_EQ(inc.size, 0.5);
  policy.accepted(inc);
  ASSERT_TRUE(policy.next(inc));
  EXPECT_DOUBLE_EQ(inc.size, 0.55);
  double last = 0.0;
  int accepted = 1;
  while (policy.next(inc)) {
    last = inc.to;
    policy.accepted(inc);
    ++accepted;
  }
  EXPECT_GT(last, 1.0);
  // Fractions 0.125, 0.1375, 0.15125, 0.166, 0.183, 0.201, 0.221: the seventh passes 1.
  EXPECT_EQ(accepted, 7);
}

// Halving steps: halved on failure, doubled back (to 1/steps at most) on success; a failure
// at 1/2^max_bisections of 1/steps ends the path with the failed increment's end.
TEST(StepPolicies, HalvingStepsHalveDoubleAndEnd) {
  solvers::HalvingSteps policy(4, 2);
  Increment inc;
  ASSERT_TRUE(policy.next(inc));
  EXPECT_EQ(inc.to, 0.25);
  EXPECT_TRUE(policy.rejected(inc, "a"));
  ASSERT_TRUE(policy.next(inc));
  EXPECT_EQ(inc.to, 0.125);
  policy.accepted(inc);
  ASSERT_TRUE(policy.next(inc));
  EXPECT_EQ(inc.to, 0.375);  // doubled back to the nominal 0.25
  EXPECT_TRUE(policy.rejected(inc, "b"));
  ASSERT_TRUE(policy.next(inc));
  EXPECT_TRUE(policy.rejected(inc, "c"));
  ASSERT_TRUE(policy.next(inc));
  EXPECT_EQ(inc.to, 0.125 + 0.0625);
  EXPECT_FALSE(policy.rejected(inc, "d"));  // at 1/2^2 of the nominal: the end
  EXPECT_FALSE(policy.next(inc));
  EXPECT_EQ(policy.failed_at(), 0.1875);
  EXPECT_EQ(policy.reason(), "d");
}

// Time steps of the implicit schemes: the nominal dt, the last one cut to end at the
// duration; halved on failure, grown back by 2 (to dt at most) on success; a failure whose
// halving would go below dt / 2^max_halvings ends the run, worded by the time control at
// the last accepted time. Steps are powers of two here, so every sum is exact.
TEST(StepPolicies, HalvedTimeStepsHalveGrowBackAndEnd) {
  solvers::HalvedTimeSteps policy(0.25, 0.625, 2);
  Increment inc;
  ASSERT_TRUE(policy.next(inc));
  EXPECT_EQ(inc.from, 0.0);
  EXPECT_EQ(inc.to, 0.25);
  EXPECT_EQ(inc.size, 0.25);
  EXPECT_TRUE(policy.rejected(inc, "a"));
  ASSERT_TRUE(policy.next(inc));
  EXPECT_EQ(inc.size, 0.125);
  policy.accepted(inc);
  ASSERT_TRUE(policy.next(inc));
  EXPECT_EQ(inc.size, 0.25);  // grown back to the nominal step
  EXPECT_EQ(inc.to, 0.375);
  policy.accepted(inc);
  ASSERT_TRUE(policy.next(inc));
  EXPECT_EQ(inc.size, 0.25);  // 0.375 + 0.25 = 0.625: the duration
  policy.accepted(inc);
  EXPECT_FALSE(policy.next(inc));
  solvers::PathResult done;
  const model::Model model = test::oscillator(1.0);
  const solvers::TimeLoad load;
  solvers::TimeControl control(model, load);
  policy.finish(control, done);
  EXPECT_TRUE(done.completed);

  solvers::HalvedTimeSteps failing(0.25, 1.0, 1);
  ASSERT_TRUE(failing.next(inc));
  EXPECT_TRUE(failing.rejected(inc, "a"));   // 0.125 = 0.25 / 2^1: still allowed
  ASSERT_TRUE(failing.next(inc));
  EXPECT_FALSE(failing.rejected(inc, "b"));  // 0.0625 would be below it
  EXPECT_FALSE(failing.next(inc));
  solvers::PathResult failed;
  failed.attempted_increments = 2;
  failing.finish(control, failed);
  EXPECT_FALSE(failed.completed);
  EXPECT_EQ(failed.failed_increment, 2);
  EXPECT_EQ(failed.message, "time step at t = 0 s failed after 1 halvings: b");
}

// The explicit scheme's steps: dt = duration / steps, grouped `group` to an increment (the
// last the remainder), the last ending at the duration itself; a rejection ends the run with
// the step's reason.
TEST(StepPolicies, FixedTimeStepsGroupStepsAndEndAtTheDuration) {
  const double duration = 0.7;  // dt = 0.1 is not exact in binary: the end must be 0.7 itself
  solvers::FixedTimeSteps policy(7, duration, 3);
  Increment inc;
  std::vector<double> sizes, ends;
  while (policy.next(inc)) {
    sizes.push_back(inc.size);
    ends.push_back(inc.to);
    policy.accepted(inc);
  }
  EXPECT_EQ(sizes, (std::vector<double>{3.0, 3.0, 1.0}));
  ASSERT_EQ(ends.size(), 3u);
  EXPECT_EQ(ends[0], 3 * (duration / 7));
  EXPECT_EQ(ends[2], duration);
  const model::Model model = test::oscillator(1.0);
  const solvers::TimeLoad load;
  solvers::TimeControl control(model, load);
  solvers::PathResult done;
  policy.finish(control, done);
  EXPECT_TRUE(done.completed);

  solvers::FixedTimeSteps unstable(7, duration, 3);
  ASSERT_TRUE(unstable.next(inc));
  EXPECT_FALSE(unstable.rejected(inc, "unstable"));
  EXPECT_FALSE(unstable.next(inc));
  solvers::PathResult failed;
  failed.attempted_increments = 1;
  unstable.finish(control, failed);
  EXPECT_FALSE(failed.completed);
  EXPECT_EQ(failed.message, "unstable");
}
