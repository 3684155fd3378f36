#pragma once
/// \file linear_bending.hpp
/// The linearised (infinitesimal) bending test: the Schenk-Guest model of the thesis's
/// Appendix A on the bending specimen (docs/thesis_equations.md, 'Bending test').
///
/// At a stable state every element is stress-free, so the tangent there is the linear
/// bar-and-hinge stiffness K. The supports and the load are imposed on it as linear
/// constraints u = T q, and the stiffness seen by a uniform unit motion e of the middle
/// polygon along the load, every other coordinate free, is the Schur complement
///
///     F = e^T (K_pp - K_pf K_ff^-1 K_fp) e        [N/mm]
///     K_B = F L^2 1e-3                           [N m/rad]
///
/// with L the module length (two cells). The bending axis can be turned by `angle` beta
/// about the specimen's axis: the middle polygon moves along (-sin beta, cos beta, 0) (its
/// nodes free across the load and in z), and each end is pinned at its centre and at the
/// two points where the line at beta + pin_offset crosses its perimeter; a point on an edge
/// is held by fixing the weighted mean (1 - s) u_j + s u_{j+1} of the edge's nodes (the
/// node of the larger weight is eliminated), a vertex when the line meets one.

#include <cstdint>
#include <memory>
#include <vector>

#include "kresling/assembly/assembler.hpp"
#include "kresling/geometry/design.hpp"
#include "kresling/model/kresling_specimen.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::analyses {

/// One evaluation's numbers.
struct LinearBendingResult {
  double stiffness = 0.0;           ///< K_B [N m/rad]; NaN if F is not finite
  double condensed_force = 0.0;     ///< F, the force per unit motion [N/mm]
  double module_length = 0.0;       ///< L = two cells' height [mm]
  /// e^T K_pp e, of which F is the small remainder [N/mm]: F is resolved only where it is
  /// well above the rounding of this term (~1e-16 of it).
  double cancelled = 0.0;
};

/// The linearised test for one polygon size, reusable across designs: the specimen's
/// topology is built once, and the factorisation plan is kept while the pattern of the
/// free block stays the same (the pins' edges depend on the design's twist).
class LinearBendingTest {
 public:
  /// Throws std::invalid_argument (naming the parameter) for odd n or n < 4, or a cell
  /// count that is odd, < 2, or too large a specimen.
  LinearBendingTest(int n, int cells = 4, model::SpecimenParameters parameters = {});

  /// K_B of `design` (n must be this test's) in `state` (0 contracted, 1 extended), the
  /// bending axis at `angle` [rad] and the pin line turned further by `pin_offset` [rad].
  /// Throws std::invalid_argument for a design of another n, a flat state, or angles that
  /// are not finite. A mechanism or a singular free block gives a condensed force that is
  /// not positive (or NaN): the caller decides what to say.
  LinearBendingResult run(const geometry::Design& design, int state, double angle = 0.0,
                          double pin_offset = 0.0);

  int n() const { return n_; }
  int cells() const { return cells_; }

 private:
  int n_, cells_;
  model::KreslingSpecimenBuilder builder_;
  // The assembly workspace (pattern, slot map) of the last run: the next design of this n
  // has the same elements, so it is reused instead of rebuilt (most of a run's cost). It
  // keeps no reference to the run's specimen, which lives only as long as the run.
  std::unique_ptr<assembly::Workspace> workspace_;
  std::unique_ptr<solvers::TangentSolver> solver_;
  std::vector<int> pattern_outer_, pattern_inner_;  // of the free block the solver was planned on
};

}  // namespace kresling::analyses
