#pragma once
/// \file snap_through.hpp
/// Bistability strength (thesis section 3.5; docs/thesis_equations.md, 'Snap-through test').
///
/// One cell built stress-free in its extended state; the bottom polygon's n+1 nodes fixed in
/// x, y, z; the top polygon's n+1 nodes driven down in z by Le - Lc in equal increments
/// (their x and y free, so the top can twist and shift) by displacement control, which holds
/// the unstable branch where the force falls. F = the summed reaction at the driven nodes
/// (positive: the cell resists compression); d = the drive's travel [mm].
///
///   snap force         the first local maximum of F(d) (parabola through the peak sample and
///                      its neighbours), the thesis's measure of bistability [N]
///   unstable state     the first zero of F after the peak (F falls through 0): the top of
///                      the energy barrier when the drive is released
///   energy barrier     the strain energy there, the work the drive does from the extended
///                      state to it, E = integral of F dd (the energy is sampled at every
///                      step; cubic Hermite with E' = F locates it between samples) [N mm]
///   bistable           F rises back through 0 (a second zero), and the cell released there
///                      (every top DOF free, no load) comes to rest somewhere other than its
///                      extended state: energy descent (solvers::minimize_energy) from the
///                      released state reaches a minimum (positive-definite tangent, bottom
///                      polygon held) with strain energy above 1e-6 of the barrier (the
///                      extended state is the only stress-free one). The drive keeps the top
///                      level; released, it may tilt: the optimum's level contracted
///                      equilibrium is a saddle and it rests tilted
///
/// A cell whose force stays positive after the peak is monostable: released anywhere, it
/// springs back; its energy barrier and second state are NaN. The cell is stress-free only
/// in its extended state, so the force at the contracted height is not zero.

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "kresling/assembly/assembler.hpp"
#include "kresling/geometry/design.hpp"
#include "kresling/analyses/drive_setup.hpp"
#include "kresling/model/kresling_specimen.hpp"
#include "kresling/solvers/displacement_control.hpp"

namespace kresling::analyses {

/// Displacement-control options with quadratic extrapolation of each increment's start
/// (about one Newton iteration per increment; the same equilibria as without).
inline solvers::DisplacementControlOptions extrapolating_solver_options() {
  solvers::DisplacementControlOptions o;
  o.extrapolation = 2;
  return o;
}

struct SnapThroughOptions {
  /// Increments from Le to Lc. 100 puts the snap force within 1e-4 (relative) and its
  /// displacement within 0.01 mm of the converged values on the thesis's designs.
  int steps = 100;
  model::SpecimenParameters specimen;
  solvers::DisplacementControlOptions solver = extrapolating_solver_options();
};

struct SnapThroughResult {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double snap_force = kNaN;             ///< first local maximum of F [N]; NaN if none
  double snap_displacement = kNaN;      ///< d at that maximum [mm]
  double unstable_displacement = kNaN;  ///< first zero of F after the peak [mm]
  double energy_barrier = kNaN;         ///< strain energy at the unstable state [N mm]
  double minimum_force = kNaN;          ///< smallest F after the peak [N]
  bool bistable = false;
  /// Travel of the second stable state: the mean of the top polygon's perimeter nodes [mm]
  double stable_displacement = kNaN;
  double stable_height = kNaN;          ///< its cell height, Le - d [mm]
  double stable_energy = kNaN;          ///< its strain energy [N mm]
  double stable_tilt = kNaN;            ///< its top polygon's tilt from horizontal [rad]
  int stable_negative_eigenvalues = -1; ///< of its tangent (0 when found; -1: not reached)
  VectorX stable_state;                 ///< its displacement, every DOF [mm]; empty if none
  std::string bistability;              ///< why the cell is (not) bistable, in words
  double extended_height = 0.0;         ///< Le [mm]
  double contracted_height = 0.0;       ///< Lc [mm]
  /// The path, starting with the built extended state (d = 0, F = 0, E = 0).
  std::vector<double> displacement;     ///< d [mm]
  std::vector<double> force;            ///< F [N]
  std::vector<double> energy;           ///< strain energy [N mm]
  std::vector<int> iterations;          ///< Newton iterations per increment (0 at the start)
  bool completed = false;               ///< the drive reached Lc
  std::string message;                  ///< why the path stopped early
};

/// The test for one polygon size, reusable across designs: the topology, the sparsity
/// patterns and the symbolic factorisations are built once (a sweep runs many designs of one
/// n through one SnapThroughTest).
/// Throw std::invalid_argument unless `design` can be driven by the snap-through test:
/// neither state folded flat (check_not_flat: Lc > 0, or the drive would end with the cell
/// folded flat, where the hinge law is infinite; Psi of both states >= 1e-6 rad).
void check_snap_design(const geometry::Design& design);

class SnapThroughTest {
 public:
  /// Throws std::invalid_argument for n < 3, steps < 1 or bad specimen or solver options.
  explicit SnapThroughTest(int n, SnapThroughOptions options = {});

  /// Run on `design` (its n must be this test's; its chirality does not matter: the mirror
  /// image responds identically). Numerical failures are reported in the result.
  SnapThroughResult run(const geometry::Design& design);
  /// One cell built extended, its bottom polygon fixed, its top polygon's prescribed
  /// motion down to the contracted height (-z, free to twist), after every check run()
  /// makes.
  DriveSetup setup(const geometry::Design& design);

  const SnapThroughOptions& options() const { return options_; }

 private:
  /// Free the drive at `start` and find where the cell comes to rest; `top_z` is the top
  /// centre's z DOF.
  void release(const model::Model& model, const VectorX& start, Index top_z,
               SnapThroughResult& r);

  SnapThroughOptions options_;
  model::KreslingSpecimenBuilder builder_;
  solvers::DisplacementControl solver_;
  std::vector<std::uint8_t> fixed_;
  // The release's pattern and slot map, kept across runs (no reference to any model).
  std::unique_ptr<assembly::Workspace> release_workspace_;
};

/// Angle between the z axis and the normal (Newell's) of the top polygon of a one-cell
/// specimen of polygon size n at displacement u [rad].
double top_polygon_tilt(const model::Model& model, const VectorX& u, int n);

/// Run the test once (see SnapThroughTest).
SnapThroughResult snap_through(const geometry::Design& design,
                               const SnapThroughOptions& options = {});

}  // namespace kresling::analyses
