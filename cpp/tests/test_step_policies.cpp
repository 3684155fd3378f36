// The path follower's step policies on their own (step_policy.hpp): the increments each
// proposes as attempts are accepted or rejected, against the rules their headers state.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "kresling/solvers/halving_steps.hpp"
#include "kresling/solvers/merlin2_steps.hpp"

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
