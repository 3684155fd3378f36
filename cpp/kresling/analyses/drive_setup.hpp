#pragma once
/// \file drive_setup.hpp
/// What a displacement-driven test of a Kresling specimen solves: the specimen with its
/// supports and the prescribed motion. The bending and snap-through tests build theirs
/// once (BendingTest::setup, SnapThroughTest::setup), for their own runs and for anyone
/// who follows the same path keeping more of it (the views' whole paths).

#include "kresling/core/types.hpp"
#include "kresling/model/kresling_specimen.hpp"

namespace kresling::analyses {

struct DriveSetup {
  model::KreslingSpecimen specimen;  ///< with the test's supports
  VectorX prescribed;                ///< one entry per DOF [mm]; non-zero entries are driven
};

}  // namespace kresling::analyses
