#pragma once
/// \file bending_test.hpp
/// The thesis's three-point bending test (section 3.4, Appendix B; docs/thesis_equations.md,
/// 'Bending test').
///
/// A stack of cells (default four: two modules, chirality + - + -), all in one state.
/// Nodes 0, n/2 and the centre of the bottom and top polygons are fixed in x, y, z (each
/// end pinned along a line through its polygon, perpendicular to the load); all n+1 nodes of
/// the middle polygon are driven by u_y = -deflection in equal steps. From the summed
/// reaction F and the centre's deflection y: M = F L 1e-3 [N m], delta = atan(y / L),
/// with L the module length (two cells), and K_B = the least-squares slope of M on delta
/// through the origin (MATLAB's theta \ M in the thesis's code) [N m / rad].

#include <string>
#include <vector>

#include "kresling/geometry/design.hpp"
#include "kresling/analyses/drive_setup.hpp"
#include "kresling/model/kresling_specimen.hpp"
#include "kresling/solvers/displacement_control.hpp"

namespace kresling::analyses {

struct BendingOptions {
  double deflection = 5.0;  ///< prescribed transverse motion of the middle polygon [mm]
  /// When non-zero, the motion is instead L tan(deflection_angle) with L the module length
  /// of the design's state: the thesis's 0.001 rad protocol of the parametric study [rad].
  double deflection_angle = 0.0;
  int steps = 350;          ///< displacement increments (the thesis: 350 for 5 mm)
  int cells = 4;            ///< even, >= 2: the middle polygon is level cells / 2
  model::SpecimenParameters specimen;
  solvers::DisplacementControlOptions solver;
};

struct BendingResult {
  double stiffness = 0.0;            ///< K_B, slope through the origin [N m / rad]
  double stiffness_intercept = 0.0;  ///< K_B of the least-squares line with intercept
  double intercept = 0.0;            ///< that line's moment at delta = 0 [N m]
  double module_length = 0.0;        ///< L = two cells' height [mm]
  std::vector<double> deflection;    ///< centre of the middle polygon, downward [mm]
  std::vector<double> force;         ///< summed reaction at the driven nodes [N]
  std::vector<double> angle;         ///< delta [rad]
  std::vector<double> moment;        ///< M [N m]
  std::vector<int> iterations;       ///< Newton iterations per increment
  std::vector<int> negative_eigenvalues;
  /// Every DOF's displacement at the last converged step (empty if none) [mm].
  VectorX final_displacement;
  bool completed = false;
  std::string message;               ///< why the run stopped early
  int num_dofs = 0;
  int num_free_dofs = 0;
};

/// The test for one polygon size, reusable across designs: the specimen's topology, the
/// sparsity pattern and the symbolic factorisation are built once (a sweep over lambda and
/// Lc runs many designs of one n through one BendingTest).
class BendingTest {
 public:
  /// Throws std::invalid_argument for odd n, a bad cell count or bad options.
  BendingTest(int n, BendingOptions options = {});

  /// Run on `design` (its n must be this test's) in `state` (0 contracted, 1 extended).
  BendingResult run(const geometry::Design& design, int state);
  /// The specimen in `state` with the test's supports (vertices 0 and n/2 and the centre
  /// of the end polygons) and the middle polygon's prescribed motion (-y), after every
  /// check run() makes.
  DriveSetup setup(const geometry::Design& design, int state);

  const BendingOptions& options() const { return options_; }
  /// The polygon size the test is for.
  int n() const { return builder_.n(); }

 private:
  BendingOptions options_;
  model::KreslingSpecimenBuilder builder_;
  solvers::DisplacementControl solver_;
  std::vector<std::uint8_t> fixed_;
};

/// Run the test once on `design` in `state` (0 contracted, 1 extended). Throws
/// std::invalid_argument for odd n (the pins need opposite vertices), an odd or too small
/// cell count, a deflection that is zero, not finite or larger than the specimen's radius,
/// or steps < 1. A run that does not converge returns completed = false with the reason;
/// the stiffness is then fitted to the increments that did converge (NaN if none).
BendingResult bending_test(const geometry::Design& design, int state,
                           const BendingOptions& options = {});

/// Largest specimen of either bending test, (cells + 1) (n + 1) nodes: one assembly and
/// factorisation of 22,000 nodes takes ~10 s and ~800 MB (the thesis's specimen has 55),
/// and the specimen builder's own limit (a million nodes) would need ~36 GB.
inline constexpr long long kMaxBendingNodes = 20000;

/// Throw std::invalid_argument (naming `cells`) for a cell count that is odd, < 2, or
/// makes more than kMaxBendingNodes nodes with polygons of n sides.
void check_bending_cells(int n, int cells);

/// Throw std::invalid_argument unless `state` is 0 or 1 and the cells in that state are not
/// folded flat (check_not_flat: in the contracted state Lc > 0, a cell folded flat has no
/// module length to bend): the bending tests' (nonlinear and linearised) check.
void check_bending_state(const geometry::Design& design, int state);

/// The transverse motion of the middle polygon a test with `options` imposes on `design` in
/// `state` [mm], after every check of the inputs (the same the test makes): n even, the
/// cell count, the steps, the state, Lc > 0 in the contracted state (a flat-folded cell has
/// no module length), a deflection that is non-zero, finite and smaller than R. Throws
/// std::invalid_argument naming the parameter.
double bending_drive(const geometry::Design& design, int state, const BendingOptions& options);

/// Least-squares slope of y on x through the origin (NaN for an empty or all-zero x).
double slope_through_origin(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace kresling::analyses
