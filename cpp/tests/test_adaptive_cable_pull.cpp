// The adaptive increments (adaptive_path.hpp) under cable actuation (cable_pull_control.hpp)
// against the same path in fixed fine increments.
//
// A cable runs from a support at (-10, 0, 0) through node 1 to a support at (10, 0, 0);
// node 1 starts at (0, -4, 0), moves along y only and hangs on a linear bar (EA = 10 N,
// 10 mm long) from a support at (0, -14, 0). The cable starts 0.5 mm slack; its pull goes
// from 0 to 3 mm: it goes taut at a pull of 0.5 mm (a kink of the path the adaptive
// increments locate) and then lifts node 1, stretching the bar; with or without a downward
// force on node 1 that ramps from 0 to 0.5 N (external as well as internal rates).

#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "kresling/assembly/assembler.hpp"
#include "kresling/solvers/adaptive_path.hpp"
#include "kresling/solvers/cable_pull_control.hpp"
#include "kresling/solvers/path_follower.hpp"

using namespace kresling;

namespace {

constexpr Index kNodeY = 3 * 1 + 1;

struct Hanger {
  model::Model model;
  std::vector<double> slack;
};

Hanger hanger() {
  NodeMatrix X(4, 3);
  X << -10, 0, 0, 0, -4, 0, 10, 0, 0, 0, -14, 0;
  std::vector<model::Bar> bars = {{{1, 3}, 1.0, 10.0, {elements::BarLawKind::Linear, 10.0}}};
  std::vector<std::uint8_t> fixed(12, 1);
  fixed[kNodeY] = 0;
  const double length = 2.0 * std::hypot(10.0, 4.0);
  const double slack = length + 0.5;
  return {model::Model(X, bars, {}, fixed, {{{0, 1, 2}, 100.0, slack}}), {slack}};
}

solvers::CablePullControl pull_control(const Hanger& h, double load) {
  VectorX force = VectorX::Zero(h.model.num_dofs());
  force[kNodeY] = -load;
  return solvers::CablePullControl(h.model, h.slack, {0.0}, {3.0},
                                   VectorX::Zero(h.model.num_dofs()), force);
}

}  // namespace

TEST(AdaptiveCablePull, SamplesAgreeWithFixedFineIncrements) {
  const Hanger h = hanger();
  const model::Model& m = h.model;
  const VectorX start = VectorX::Zero(m.num_dofs());
  // 400 samples, against fixed increments five times finer (every fifth is a sample).
  constexpr int kSamples = 400, kFine = 2000;
  for (const double load : {0.0, 0.5}) {
    SCOPED_TRACE("load " + std::to_string(load) + " N");
    solvers::CablePullControl adaptive_control = pull_control(h, load);
    assembly::Assembler assembler(m, assembly::unmasked_dofs(m.fixed()), 1e-8,
                                  assembly::Storage::Lower);
    assembly::Assembler full(m, assembly::all_dofs(m.num_dofs()), 0.0,
                             assembly::Storage::Lower);
    solvers::TangentSolver solver;
    const solvers::AdaptiveOptions options;  // tolerance 1e-9 of the largest energy
    const solvers::PathResult adaptive = solvers::follow_adaptive(
        adaptive_control, assembler, full, solver, start, kSamples, options);
    ASSERT_TRUE(adaptive.completed) << adaptive.message;
    ASSERT_EQ(adaptive.steps.size(), static_cast<std::size_t>(kSamples));

    solvers::CablePullControl fixed_control = pull_control(h, load);
    assembly::Assembler fixed_assembler(m, assembly::unmasked_dofs(m.fixed()), 1e-8,
                                        assembly::Storage::Lower);
    solvers::TangentSolver fixed_solver;
    VectorX u = start;
    solvers::PathResult fine;
    solvers::follow_path(fixed_control, fixed_assembler, fixed_solver, u, kFine, {}, fine);
    ASSERT_TRUE(fine.completed) << fine.message;
    ASSERT_EQ(fine.steps.size(), static_cast<std::size_t>(kFine));

    double largest_energy = 0.0;
    for (const auto& s : fine.steps) largest_energy = std::max(largest_energy, s.energies.sum());
    ASSERT_GT(largest_energy, 1.0);  // the cable went taut and pulled (~7.6 N mm)
    int interpolated = 0;
    for (int k = 0; k < kSamples; ++k) {
      const auto& a = adaptive.steps[k];
      const auto& f = fine.steps[(k + 1) * (kFine / kSamples) - 1];
      ASSERT_NEAR(a.load_factor, f.load_factor, 1e-12);
      interpolated += a.iterations == 0;
      // The dense output is held to 1e-9 of the largest energy so far by an estimate (not
      // a bound): twice that (measured: 6.4e-10). The fine path's own error is far below:
      // Newton leaves its states within ~1e-12 mm, the energy within ~1e-12 N mm.
      EXPECT_NEAR(a.energies.sum(), f.energies.sum(), 2e-9 * largest_energy) << "sample " << k;
      // Node 1 moves 2 mm over the pull, 5e-3 mm per sample: 1e-8 mm (measured 7e-10 mm)
      // is far below what a sample at the wrong parameter or a misplaced kink would show.
      EXPECT_NEAR(a.displacement[kNodeY], f.displacement[kNodeY], 1e-8) << "sample " << k;
      // The supports' reactions, on Hermite curves like the energy's: 1e-8 of the last
      // (measured: 1.8e-10 of it).
      EXPECT_LT((a.constraint_force - f.constraint_force).norm(),
                1e-8 * fine.steps.back().constraint_force.norm())
          << "sample " << k;
    }
    // Most samples come from the Hermite curves between converged points, not from Newton.
    EXPECT_GT(interpolated, kSamples / 2);
  }
}
