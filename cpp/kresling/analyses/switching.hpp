#pragma once
/// \file switching.hpp
/// Switching one Kresling cell between its stable states by its creases (crease actuation;
/// docs/folding.md, 'Switching a Kresling cell by its creases').
///
/// The cell is snap_through's: one cell built stress-free in its extended state, the bottom
/// polygon's n+1 nodes fixed. A group of creases (the valley folds, the mountain folds, the
/// polygon edges, or all of them) has its rest angles driven away from their stress-free
/// values theta0 by the same change Delta, each crease i in the direction s_i = the sign of
/// (its angle in the contracted stable state - theta0), the direction that moves the cell
/// towards the contracted state (read off the contracted state that snap_through finds;
/// the opposite switch drives -s_i). Each increment of Delta is one solve of the fold solver
/// (solvers::solve_fold) from the previous equilibrium; the state is followed while it stays
/// on its branch: converged, stable (positive-definite tangent) and no node moving by more
/// than a twentieth of the travel between the stable states in one increment. The first increment that leaves the branch brackets the
/// limit point (the snap), which bisection narrows to `resolution`.
///
/// At the snap (the last converged state, Delta_snap):
///   moment   m = - sum_i s_i M_i, M_i = L0_i M(theta_i) the moment of crease i (k_p L0
///            (theta_i - theta0_i - s_i Delta) in the law's linear range): the summed moment
///            the actuation must hold against the creases [N mm]; also the largest |M_i|
///   work     W = integral_0^Delta_snap f dDelta (trapezoids over the followed path), f =
///            sum_i s_i dE/dtheta0_i the rest angles' generalised force (= m while every
///            crease is inside the law's linear range, theta1 to theta2): the energy the
///            actuation puts in. Along an equilibrium path with no load the stored energy's
///            derivative in Delta is f, so W equals the strain energy added (at the snap
///            minus at the start), to the quadrature's error: the moments and the energies
///            are computed independently, so this is the consistency check of the moments
///   barrier  snap_through's energy barrier E_b, for comparison only: W is not E_b and need
///            not be (it includes the energy of the driven creases strained against their
///            new rest angles, and the held actuation goes on doing work while the cell snaps)
/// Landing: the actuation held just past the snap (Delta_snap + overshoot), energy descent
/// (solvers::minimize_energy) finds where the cell snaps to; then the rest angles are set
/// back to theta0 (released) and a second descent finds where the cell comes to rest.

#include <limits>
#include <string>
#include <vector>

#include "kresling/analyses/snap_through.hpp"
#include "kresling/geometry/design.hpp"
#include "kresling/model/kresling_specimen.hpp"
#include "kresling/solvers/path.hpp"

namespace kresling::analyses {

/// The crease groups a switch can drive (Folds: valley, mountain and polygon edges together).
enum class CreaseGroup { Valley, Mountain, PolygonEdge, Folds };

/// "valley", "mountain", "polygon" or "fold".
const char* crease_group_name(CreaseGroup group);

/// Whether a crease of family `family` belongs to `group` (Folds: every family but the
/// polygon spokes).
bool in_crease_group(model::EdgeFamily family, CreaseGroup group);

struct SwitchingOptions {
  model::SpecimenParameters specimen;
  int snap_through_steps = 100;        ///< the snap-through test's increments
  double scan_step = 0.25 * 3.14159265358979323846 / 180.0;  ///< increment of Delta [rad]
  double max_change = 170.0 * 3.14159265358979323846 / 180.0;  ///< give up beyond [rad]
  double resolution = 1e-5 * 3.14159265358979323846 / 180.0; ///< of Delta at the snap [rad]
  double overshoot = 0.01 * 3.14159265358979323846 / 180.0;  ///< past the snap to land [rad]
  solvers::NewtonOptions newton;
};

struct SwitchResult {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  CreaseGroup group = CreaseGroup::Valley;
  bool forward = true;          ///< extended -> contracted (false: contracted -> extended)
  int creases = 0;              ///< driven creases (stiffness > 0)
  bool switched = false;        ///< the start state ceased to exist and the cell landed
  double snap_change = kNaN;    ///< Delta at the snap (last converged) [rad]
  double resolution = kNaN;     ///< Delta_snap lies within this below the true limit [rad]
  double moment = kNaN;         ///< m at the snap, summed over the driven creases [N mm]
  double max_crease_moment = kNaN;  ///< largest |M_i| there [N mm]
  double work = kNaN;           ///< integral of f dDelta up to the snap [N mm]
  double snap_energy = kNaN;    ///< strain energy at the snap (actuated) [N mm]
  double start_energy = kNaN;   ///< strain energy of the start state [N mm]
  double start_height = kNaN;   ///< cell height of the start state [mm]
  double snap_height = kNaN;    ///< cell height at the snap [mm]
  double landing_height = kNaN; ///< released, the cell's height at rest [mm]
  double landing_energy = kNaN; ///< its strain energy [N mm]
  double landing_tilt = kNaN;   ///< its top polygon's tilt [rad]
  int landing_negative_eigenvalues = -1;
  std::vector<double> change, moments, energy, height;  ///< the followed path (from 0)
  std::string message;          ///< what happened, in words
};

struct SwitchingResult {
  SnapThroughResult snap;                   ///< the cell's snap-through test
  std::vector<SwitchResult> forward, backward;  ///< one per group, in CreaseGroup order
};

/// Switch `design`'s cell by each crease group, both ways. Throws std::invalid_argument for
/// a design the snap-through test rejects or bad options; a cell that is not bistable gets
/// no switches (the snap result says why).
SwitchingResult switching(const geometry::Design& design, const SwitchingOptions& options = {});

}  // namespace kresling::analyses
