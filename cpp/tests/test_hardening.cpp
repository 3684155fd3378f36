// Reproducers of the defects a fuzzing audit found in the core (each must stay fixed): a
// subnormal in a message, bisection counts past 30, the tangent's shift unchecked, the
// enhanced linear law at a flat fold, the tests at Lc = 0, step counts without a bound, long
// loops that could not be interrupted, and oversized specimens.

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "kresling/analyses/bending_test.hpp"
#include "kresling/analyses/snap_through.hpp"
#include "kresling/core/check.hpp"
#include "kresling/core/interrupt.hpp"
#include "kresling/elements/dihedral.hpp"
#include "kresling/elements/spring_laws.hpp"
#include "kresling/geometry/design.hpp"
#include "kresling/model/calibration.hpp"
#include "kresling/model/kresling_specimen.hpp"
#include "kresling/model/panel_elements.hpp"
#include "kresling/solvers/displacement_control.hpp"
#include "kresling/solvers/force_control.hpp"
#include "kresling/solvers/mgdcm.hpp"
#include "kresling/solvers/increments.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/path_control.hpp"

using namespace kresling;
using geometry::Design;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The message of the std::invalid_argument `f` throws ("" if it throws none).
template <typename F>
std::string invalid_message(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

// One cell, bottom polygon held, top polygon driven down by `travel` in z (the snap test).
struct DrivenCell {
  model::KreslingSpecimen specimen;
  VectorX prescribed;
};

DrivenCell driven_cell(const Design& d, double travel) {
  const int n = d.parameters().n;
  std::vector<std::uint8_t> fixed(static_cast<std::size_t>(6 * (n + 1)), 0);
  std::fill(fixed.begin(), fixed.begin() + 3 * (n + 1), 1);
  DrivenCell c{model::build_kresling_specimen(d, {1}, {1}, {}, fixed), VectorX()};
  c.prescribed = VectorX::Zero(c.specimen.model.num_dofs());
  for (int j = 0; j <= n; ++j) c.prescribed[3 * c.specimen.node(1, j) + 2] = -travel;
  return c;
}

}  // namespace

// std::stod threw std::out_of_range (Python: IndexError) for a subnormal; the message
// builder now reads numbers back with strtod and shows a subnormal with its few digits.
TEST(Hardening, SubnormalValuesAreFormatted) {
  EXPECT_EQ(format_number(-1e-310), "-1e-310");
  EXPECT_EQ(format_number(5e-324), "5e-324");
  EXPECT_EQ(format_number(0.9), "0.9");
  EXPECT_EQ(format_number(30.0), "30");
  const std::string message = invalid_message([] { Design(10, 30.0, 0.8, -1e-310); });
  EXPECT_EQ(message, "Lc = -1e-310 is invalid: must be >= 0");
}

// 1 << max_bisections was undefined behaviour from 31 on (31 looped forever, 32 gave up at
// once, 47 acted like 15). The count is now checked against a documented bound.
TEST(Hardening, BisectionsBeyondTheBoundAreRefused) {
  for (int bisections : {-1, 31, 32, 47}) {
    const std::string message =
        invalid_message([&] { solvers::EqualIncrements policy(1, bisections); });
    EXPECT_EQ(message, "max_bisections = " + std::to_string(bisections) +
                           " is invalid: must be an integer in [0, 30]");
  }
}

// At the bound the smallest increment is 1/2^30 of a nominal one: equal increments that
// never succeed try the full increment and 30 halvings, then stop.
TEST(Hardening, ThirtyBisectionsStopAfterThirtyOneAttempts) {
  const DrivenCell c = driven_cell(Design(4, 30.0, 0.7, 30.0), 1.0);
  solvers::LoadControl control(c.specimen.model, VectorX::Zero(c.specimen.model.num_dofs()));
  solvers::EqualIncrements policy(1, solvers::kMaxBisections);
  solvers::PathResult r;
  solvers::Increment increment;
  int attempts = 0;
  double smallest = 1.0;
  while (policy.next(increment)) {
    ++attempts;
    ++r.attempted_increments;
    smallest = increment.to - increment.from;
    if (!policy.rejected(increment, attempts == 1 ? "first" : "later")) break;
  }
  policy.finish(control, r);
  EXPECT_FALSE(r.completed);
  EXPECT_EQ(attempts, solvers::kMaxBisections + 1);
  EXPECT_EQ(smallest, std::ldexp(1.0, -solvers::kMaxBisections));
  EXPECT_EQ(r.failed_increment, attempts);
  EXPECT_EQ(r.message,
            "no equilibrium found beyond load factor 0 (load step 1 of 1, 30 bisections; a "
            "limit point? use MGDCM); at full size: first; at the smallest size tried "
            "(9.31e-10): later");
}

// Path fractions reached by bisections print to the digits that mean something.
TEST(Hardening, FailureMessagesRoundThePathParameter) {
  EXPECT_EQ(format_rounded(0.67128906250000009), "0.671289");
  EXPECT_EQ(format_rounded(0.5), "0.5");
  EXPECT_EQ(format_rounded(69.2871, 3), "69.3");
}

TEST(Hardening, StepCountsHaveAnUpperBound) {
  const DrivenCell c = driven_cell(Design(4, 30.0, 0.7, 30.0), 1.0);
  const std::string message = invalid_message([&] {
    solvers::solve_displacement_control(c.specimen.model, c.prescribed, 1000000000);
  });
  EXPECT_EQ(message, "steps = 1000000000 is invalid: must be an integer in [1, 100000]");
  solvers::MgdcmOptions o;
  o.max_increments = solvers::kMaxSteps + 1;
  EXPECT_NE(invalid_message([&] {
              solvers::solve_mgdcm(c.specimen.model, c.prescribed, o);
            }).find("max_increments = 100001 is invalid"),
            std::string::npos);
  solvers::DisplacementControlOptions too_many;
  too_many.newton.max_iterations = solvers::kMaxIterations + 1;
  EXPECT_NE(invalid_message([&] { solvers::DisplacementControl{too_many}; })
                .find("max_iterations = 10001 is invalid"),
            std::string::npos);
}

// A shift of 1e9 (or inf, or -1e9) made the free DOFs' corrections vanish: the first
// iteration "converged" with the wrong answer and completed = true.
TEST(Hardening, ShiftMustBeASmallNonNegativeNumber) {
  for (double shift : {1e9, std::numeric_limits<double>::infinity(), -1e9, -1e-12, 2e-3}) {
    solvers::DisplacementControlOptions o;
    o.shift = shift;
    EXPECT_NE(invalid_message([&] { solvers::DisplacementControl{o}; }).find("shift = "),
              std::string::npos)
        << shift;
    solvers::ForceControlOptions f;
    f.shift = shift;
    const DrivenCell c = driven_cell(Design(4, 30.0, 0.7, 30.0), 1.0);
    EXPECT_NE(invalid_message([&] {
                solvers::solve_force_control(c.specimen.model, c.prescribed, 2, f);
              }).find("shift = "),
              std::string::npos)
        << shift;
  }
  solvers::DisplacementControlOptions ok;
  ok.shift = 0.0;
  EXPECT_NO_THROW(solvers::DisplacementControl{ok});
  ok.shift = solvers::kMaxShift;
  EXPECT_NO_THROW(solvers::DisplacementControl{ok});
}

// At a hinge folded flat (theta = 0 or 2 pi) the enhanced linear law's tan gave finite
// rounding noise of either sign (|M| ~ 1e16 kp); it is infinite there, and finite inside.
TEST(Hardening, EnhancedLinearLawIsInfiniteAtAFlatFold) {
  const double t1 = 5 * kPi / 180, t2 = 355 * kPi / 180;
  for (double theta : {0.0, 2 * kPi, -1e-3, 2 * kPi + 1e-3}) {
    const auto r = elements::enhanced_linear_spring(theta, kPi, 1.0, t1, t2);
    EXPECT_TRUE(std::isinf(r.moment) && std::isinf(r.stiffness) && std::isinf(r.energy)) << theta;
    EXPECT_EQ(r.moment < 0, theta < kPi) << theta;
  }
  for (double theta : {1e-6, 0.01, kPi, 2 * kPi - 1e-6}) {
    const auto r = elements::enhanced_linear_spring(theta, kPi, 1.0, t1, t2);
    EXPECT_TRUE(std::isfinite(r.moment) && std::isfinite(r.stiffness) && std::isfinite(r.energy))
        << theta;
  }
}

// Driving a traditional cell (Lc = 0) all the way flat ended a "completed" path on a
// -3.9e14 N force (and the snap test reported a 4.9e13 N snap force). The flat state is
// now refused by the law: the path stops before it, every step it keeps finite.
TEST(Hardening, APathStopsBeforeAFlatFold) {
  const Design d(4, 30.0, 0.6, 0.0);
  const DrivenCell c = driven_cell(d, d.height(geometry::State::Extended));
  solvers::DisplacementControlOptions o;
  o.extrapolation = 2;
  const solvers::PathResult r = solvers::solve_displacement_control(c.specimen.model,
                                                                    c.prescribed, 100, o);
  EXPECT_FALSE(r.completed);
  EXPECT_NE(r.message.find("increment 100"), std::string::npos) << r.message;
  ASSERT_FALSE(r.steps.empty());
  for (const auto& step : r.steps) {
    EXPECT_TRUE(solvers::finite_step(step));
    EXPECT_LT(step.constraint_force.cwiseAbs().maxCoeff(), 1e6);
  }
}

// The tests that reach a flat fold say so before they start, naming Lc.
TEST(Hardening, TestsAtLcZeroNameLc) {
  const Design flat(4, 30.0, 0.6, 0.0);
  EXPECT_EQ(invalid_message([&] { analyses::snap_through(flat); }).rfind("Lc = 0 is invalid", 0),
            0u);
  EXPECT_EQ(invalid_message([&] { analyses::bending_test(flat, 0); })
                .rfind("Lc = 0 is invalid: must be > 0 for the bending test in the contracted", 0),
            0u);
  analyses::BendingOptions o;
  o.deflection_angle = 0.001;
  o.deflection = 0.0;
  EXPECT_EQ(invalid_message([&] { analyses::bending_test(flat, 0, o); }).rfind("Lc = 0", 0), 0u);
  EXPECT_NO_THROW(analyses::bending_drive(flat, 1, o));  // the extended cell is not flat
}

TEST(Hardening, SpecimenSizeIsBounded) {
  EXPECT_EQ(invalid_message([] { model::KreslingSpecimenBuilder(2000000000, {1}); })
                .rfind("n = 2000000000 is invalid: must be an integer in [3, 1000000]", 0),
            0u);
  EXPECT_NE(invalid_message([] {
              model::KreslingSpecimenBuilder(1000, std::vector<int>(2000, 1));
            }).find("must have at most 1000000"),
            std::string::npos);
}

namespace {
int g_checks = 0;
struct Stop {};
void stop_on_first_check() {
  ++g_checks;
  throw Stop{};
}
}  // namespace

// Long loops ask the host's check (the Python module's runs the signal handlers, so Ctrl-C
// raises KeyboardInterrupt); whatever it throws unwinds the solver call.
TEST(Hardening, LongLoopsCallTheInterruptCheck) {
  const DrivenCell c = driven_cell(Design(4, 30.0, 0.7, 30.0), 1.0);
  set_interrupt_check(&stop_on_first_check);
  g_checks = 0;
  EXPECT_THROW(solvers::solve_displacement_control(c.specimen.model, c.prescribed, 10), Stop);
  EXPECT_EQ(g_checks, 1);
  set_interrupt_check(nullptr);
  EXPECT_TRUE(solvers::solve_displacement_control(c.specimen.model, c.prescribed, 10).completed);
}

// A hinge folded flat on the 2 pi side: 2 pi - theta rounded to 2 pi itself, an angle the
// model refuses (a specimen of Design(3, 0.75, 6e-8) failed to build).
TEST(Hardening, FlatHingeAnglesStayBelowTwoPi) {
  const Vector3 a(0, 0, 0), b(1, 0, 0), c(0.5, 1, 0), d(0.5, 1, -1e-17);
  const double theta = elements::dihedral_angle(a, b, c, d);
  EXPECT_GE(theta, 0.0);
  EXPECT_LT(theta, 2 * kPi);
  EXPECT_NO_THROW(model::build_kresling_specimen(Design(3, 30.0, 0.75, 5.960464477539063e-08),
                                                 {0}, {1}));
}

// Cells flat to within the model's resolution (Psi < 1e-6 rad) are refused by the tests,
// naming Lc (contracted) or lam (extended): their forces were noise (2.5e12 N spikes).
TEST(Hardening, NearlyFlatCellsAreRefusedByTheTests) {
  EXPECT_EQ(invalid_message([] { analyses::snap_through(Design(3, 67.0, 0.5 + 1e-16, 2.2e-311)); })
                .rfind("Lc = 2.2e-311 is invalid: must be > 0 for the snap-through test, and "
                       "large enough that the contracted cell is not flat",
                       0),
            0u);
  EXPECT_EQ(invalid_message([] { analyses::check_bending_state(Design(4, 30.0, 0.5 + 1e-16, 0.0), 1); })
                .rfind("lam = ", 0),
            0u);
  EXPECT_NO_THROW(analyses::check_snap_design(Design(4, 30.0, 0.6, 1e-3)));
}

// MERLIN2's quad calibration gives the spokes zero area at nu = 0: the error names the
// Poisson ratio, not a bar of zero area the model cannot explain.
TEST(Hardening, CalibrationWithZeroAreaNamesThePoissonRatio) {
  NodeMatrix X(4, 3);
  X << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0;
  const std::vector<std::vector<Index>> panels = {{0, 1, 2, 3}};
  const auto elements = model::build_panel_elements(X, panels, model::PanelSplit::N5B8);
  model::SheetMaterial material;
  material.youngs_modulus = 1.0;
  material.thickness = 1.0;
  material.poisson_ratio = 0.0;
  EXPECT_EQ(invalid_message([&] { model::calibrate_sheet(elements, panels, material, false); })
                .rfind("poisson_ratio = 0 is invalid for this pattern", 0),
            0u);
  material.poisson_ratio = 0.3;
  EXPECT_NO_THROW(model::calibrate_sheet(elements, panels, material, false));
}

// A degenerate pentagon (its corner 1 on its side 4-0) whose optimal centre lands on a
// corner: the model refused "bar 0 (nodes 6, 0): rest length = 0"; the panel is now named.
TEST(Hardening, DegeneratePanelFanNamesThePanel) {
  NodeMatrix X(5, 3);
  X << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 0, 0;
  EXPECT_EQ(invalid_message([&] {
              model::build_panel_elements(X, {{0, 1, 2, 3, 4}}, model::PanelSplit::N5B8);
            }).rfind("panel 0: two of its sides cross or touch", 0),
            0u);
  EXPECT_NO_THROW(model::build_panel_elements(X.topRows(4), {{0, 1, 2, 3}},
                                              model::PanelSplit::N5B8));
}
