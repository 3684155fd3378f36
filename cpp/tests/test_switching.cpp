#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

#include "kresling/analyses/switching.hpp"

using kresling::analyses::CreaseGroup;
using kresling::analyses::SwitchingOptions;
using kresling::analyses::switching;
using kresling::geometry::Design;

// Design(n, R, lambda, Lc): the thesis's figure 3.16 design, bistable and level.
TEST(Switching, ValleysSwitchTheCellAndItLandsInTheSnapThroughState) {
  const auto r = switching(Design(8, 30.0, 0.8, 30.0));
  ASSERT_TRUE(r.snap.bistable) << r.snap.bistability;
  ASSERT_EQ(r.forward.size(), 4u);
  const auto& valley = r.forward[0];
  EXPECT_EQ(valley.group, CreaseGroup::Valley);
  ASSERT_TRUE(valley.switched) << valley.message;
  // Released, it rests in the contracted state the snap-through test finds (both are
  // minima found by descent to a step of 1e-8 mm).
  EXPECT_NEAR(valley.landing_height, r.snap.stable_height, 1e-6);
  // The work of the actuation is the energy it adds (trapezoids: measured 4e-6 relative).
  EXPECT_NEAR(valley.work, valley.snap_energy - valley.start_energy, 1e-3 * valley.work);
  // The bracket of the snap is narrowed to the resolution.
  EXPECT_LE(valley.resolution, SwitchingOptions{}.resolution);
  // Back from the contracted state, the valleys land in the built extended state.
  ASSERT_TRUE(r.backward[0].switched) << r.backward[0].message;
  EXPECT_NEAR(r.backward[0].landing_height, r.snap.extended_height, 1e-6);
  // Cut mountain creases have no stiffness: nothing to drive.
  EXPECT_EQ(r.forward[1].creases, 0);
  EXPECT_FALSE(r.forward[1].switched);
}

TEST(Switching, BadOptionsAreRefused) {
  SwitchingOptions o;
  o.resolution = 2 * o.scan_step;
  EXPECT_THROW(switching(Design(8, 30.0, 0.8, 30.0), o), std::invalid_argument);
  o = SwitchingOptions{};
  o.max_change = 4.0;
  EXPECT_THROW(switching(Design(8, 30.0, 0.8, 30.0), o), std::invalid_argument);
}
