#pragma once
/// \file displacement_control.hpp
/// Displacement control as MERLIN2 runs it (the thesis's mode; docs/model.md, 'Solvers').
///
/// The prescribed displacement vector is reached in `steps` equal increments; only its
/// non-zero components are imposed (zero components stay free). Each increment moves the
/// imposed DOFs, then Newton runs on the free DOFs until ||du_free||_2 <= tolerance. An
/// increment that needs `reject_iterations` or more iterations (or fails) is rejected and
/// retried as two halves, recursively, down to `max_bisections` levels. Optionally the free
/// DOFs start from an extrapolation of the path (see `extrapolation`).

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "kresling/assembly/assembler.hpp"
#include "kresling/model/model.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/path.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::solvers {

struct DisplacementControlOptions {
  NewtonOptions newton;
  int reject_iterations = 25;  ///< MERLIN2 rejects an increment needing >= 25 iterations
  int max_bisections = 10;     ///< an increment may be cut to 1/2^10 of its size
  double shift = 1e-8;         ///< diagonal shift of the tangent (MERLIN2's)
  /// Starting guess of each increment's free DOFs: 0 = the previous equilibrium (MERLIN2's
  /// Newton sequence, iteration for iteration); 1 = linear, 2 = quadratic, 3 = cubic
  /// extrapolation along the path through the last 2, 3 or 4 accepted equilibria. The
  /// equilibrium found is the same (to the Newton tolerance); a good guess only saves
  /// iterations (MERLIN2's GMiura point load, 200 increments: 1,877, 626 and 481 for 0, 2
  /// and 3, as Newton converges only linearly on its nearly flat panels). Where several
  /// equilibria exist (past a bifurcation), an increment whose extrapolated start converges
  /// to a less stable one than the last is retried from the last equilibrium; so is one
  /// whose extrapolated start fails (past a snap), before it is halved.
  int extrapolation = 0;
  /// MERLIN2 v1.1's step control instead of bisection (docs/model.md, 'Displacement
  /// control'): a rejected increment halves the step factor (after 10 rejections in a row it
  /// grows it by 1.5 and damps Newton by 0.75 instead), each accepted one moves it 10 %
  /// back towards 1, and the path runs while the accumulated fraction is <= 1, so it may
  /// end past the prescribed motion (11 increments of 1/10, say) exactly as MERLIN2's does.
  /// The path ends after 21 rejections in a row. Ignores max_bisections and extrapolation.
  bool merlin2_steps = false;
  /// Adaptive increments with dense output (docs/model.md, 'Displacement control'): the
  /// path is followed in increments chosen by an error estimate of the cubic Hermite curves
  /// between converged points (which carry their exact path derivatives), never across a
  /// change of the tangent's negative-eigenvalue count or a hinge crossing a limit of the
  /// enhanced linear law (both located to 1e-3 of a sample spacing first); the `steps`
  /// equal samples inside an increment are read off those curves (displacements, constraint
  /// forces, energies; 0 iterations), a sample at an increment's end is the converged
  /// point. An increment whose estimated error of the drive's force (sum_k F_k U_k / max|U|:
  /// the summed reaction of a uniform drive) exceeds `adaptive_tolerance` times its largest
  /// value so far is retried shorter, down to the next sample (which it then ends on). How
  /// that force is shared among the driven DOFs is determined only to the Newton tolerance,
  /// here as in the fixed steps (on the 0.001 rad bending protocol two fixed-step starting
  /// guesses give shares 1e-4 apart). Measured against the fixed steps on the Table 3
  /// designs (bending, both protocols and states; snap-through): summed forces within
  /// 4.2e-9 of the largest. A cable going taut or slack (its kink) is located like a law
  /// kink (adaptive_path.hpp). A path the adaptive increments cannot finish is followed again in fixed
  /// steps (from `extrapolation`'s start), whose result is returned (attempts of both runs
  /// counted). merlin2_steps takes precedence.
  bool adaptive = false;
  /// Estimated error of an adaptive sample's drive force, relative to its largest value on
  /// the path so far (in (0, 1e-4]). 1e-9: ten times below the stated 1e-8; a tighter one
  /// meets the converged forces' own rounding (~4e-12 of the largest) and shortens the
  /// increments to single samples.
  double adaptive_tolerance = 1e-9;
  StopRule stop;  ///< ends the path early (completed) when it returns true
  /// Adaptive only: keep the converged points the samples were read from
  /// (PathResult::knots), which the path's sensitivities differentiate instead of every
  /// sample (sensitivity.hpp).
  bool keep_knots = false;
};

/// A reusable displacement-control solver. Solving models of identical connectivity under
/// identical constraints one after another (a parametric sweep) reuses the sparsity
/// pattern, the slot map and the symbolic factorisation of the first.
class DisplacementControl {
 public:
  explicit DisplacementControl(DisplacementControlOptions options = {});

  /// Trace the path. `prescribed` has one entry per DOF; `initial` (empty = zero) is the
  /// starting displacement. Throws std::invalid_argument for bad input (sizes, a prescribed
  /// DOF that is also fixed, nothing prescribed, steps < 1, free rigid-body motions).
  PathResult solve(const model::Model& model, const VectorX& prescribed, int steps,
                   const VectorX& initial = VectorX());

 private:
  DisplacementControlOptions options_;
  // Kept from one solve to the next, with no reference to any model: the workspace
  // (pattern, slot map) and the symbolic factorisation.
  std::unique_ptr<assembly::Workspace> workspace_;
  std::unique_ptr<TangentSolver> solver_;
  // Every DOF, unshifted, lower triangle: the path derivatives of the adaptive mode.
  // The workspace is kept between solves (no model reference); the binding to the model
  // is made by solve and emptied when it returns.
  std::unique_ptr<assembly::Workspace> full_workspace_;
  std::optional<assembly::Assembler> full_assembler_;
  std::vector<std::uint8_t> held_;  // constraints the cached pattern was built for
  // The model of the solve under way bound to workspace_; emptied when solve returns.
  std::optional<assembly::Assembler> assembler_;
};

/// One-off solve (see DisplacementControl::solve).
PathResult solve_displacement_control(const model::Model& model, const VectorX& prescribed,
                                      int steps, const DisplacementControlOptions& options = {},
                                      const VectorX& initial = VectorX());

}  // namespace kresling::solvers
