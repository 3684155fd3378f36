#pragma once
/// \file arm_analysis.hpp
/// The manipulator as a structure (model/arm.hpp): equilibrium under tendon pulls and a tip
/// load, the tip compliance, switching by pulling, and the load capacity.
///
/// Inputs are the tendons' pulls (how much each tendon's rest length is shortened from its
/// slack length, the path length as built [mm]; a pull is never negative: a tendon cannot
/// push) and a force on the tip guide's centre [N]. A path ramps them along a straight line
/// from one point to another in increments; each increment is a Newton solve from the last
/// equilibrium with the tendons' rest lengths and the load of that point. An increment is
/// accepted when Newton converges, the tangent is positive definite (a stable equilibrium)
/// and every cell keeps its state (a cell is extended when its height, the distance between
/// the centroids of its two polygons, exceeds (Le + Lc) / 2). Otherwise it is halved, down
/// to 1/2^max_bisections of the nominal increment: what still fails there is where the arm
/// loses equilibrium (a module snaps), located to that resolution; the path ends there, a
/// result and not an error. Under pulls alone, the arm is then released (energy descent
/// from the last equilibrium with the pulls just past that point) to find where it lands.
/// A caller's event (a taut tendon going slack) ends the path the same way when it is
/// crossed; Newton may stall at a tendon's switch from taut to slack, so a failure where
/// the event is reached within the last increment (extrapolated) or within 1 % of its
/// starting value counts as the event, not as a snap.
///
/// Pretension: pulls such that every tendon carries a given tension with no tip load,
/// found by Newton's method on the pulls with the exact sensitivity of the tensions
/// (dT_i / dpull_j from the tangent: three solves).

#include <array>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "kresling/assembly/assembler.hpp"
#include "kresling/model/arm.hpp"
#include "kresling/solvers/path.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::analyses {

using Pulls = std::array<double, 3>;

struct ArmOptions {
  solvers::NewtonOptions newton{1e-6, 30};
  int steps = 10;            ///< nominal increments of a path
  int max_bisections = 12;   ///< an increment may be cut to 1/2^12 of its size
  double shift = 1e-8;       ///< diagonal shift of the tangent (MERLIN2's)
};

/// One equilibrium of the arm.
struct ArmState {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  VectorX displacement;               ///< every DOF [mm]
  Pulls pulls{};                      ///< [mm]
  Vector3 load = Vector3::Zero();     ///< tip load [N]
  Vector3 tip_position = Vector3::Zero();      ///< tip guide's centre [mm]
  Vector3 tip_displacement = Vector3::Zero();  ///< [mm]
  Pulls tension{};                    ///< per tendon [N] (0 when slack)
  Pulls tendon_length{};              ///< path length per tendon [mm]
  std::vector<double> cell_height;    ///< per cell: distance between its polygons' centroids
  std::vector<double> module_length;  ///< per module: distance between its guides' centres
  std::vector<int> cell_states;       ///< per cell: 1 extended, 0 contracted (by height)
  int negative_eigenvalues = -1;      ///< of the free tangent (0: stable)
  double energy = 0.0;                ///< strain energy incl. tendons [N mm]
  int iterations = 0;                 ///< Newton iterations of its increment
};

/// A path of equilibria along a ramp.
struct ArmPath {
  std::vector<double> parameter;  ///< t in [0, 1] of each accepted step (the start is t = 0)
  std::vector<ArmState> states;   ///< the equilibria, starting with the start
  bool completed = false;         ///< reached t = 1
  bool event = false;             ///< ended where the caller's event function crossed 0
  bool lost = false;              ///< ended where the equilibrium was lost (a snap)
  /// Where it ended early: between the last accepted t and this one (NaN if completed).
  double end_parameter = ArmState::kNaN;
  std::string message;            ///< why it ended early
  int attempted_increments = 0;
  /// Where equilibrium was lost: the cell that jumped to its other state within the last
  /// increment, or else the cell whose height changes most along the softest mode of the
  /// last equilibrium (the mode that is losing its stiffness); -1 otherwise.
  int critical_cell = -1;
};

/// Where a released arm comes to rest.
struct ArmRelease {
  bool converged = false;
  ArmState state;
  std::string message;
};

/// A caller's event: positive before it, <= 0 once it has happened (e.g. the smallest
/// tension of the tendons that were taut).
using ArmEvent = std::function<double(const ArmState&)>;

class ArmSolver {
 public:
  /// `arm` must outlive the solver. Throws std::invalid_argument for bad options.
  explicit ArmSolver(const model::Arm& arm, ArmOptions options = {});
  ~ArmSolver();

  const model::Arm& arm() const { return *arm_; }
  const ArmOptions& options() const { return options_; }

  /// The state at displacement u with these pulls and tip load (no solve).
  ArmState evaluate(const VectorX& u, const Pulls& pulls, const Vector3& load = Vector3::Zero());
  /// The built, unloaded arm (u = 0).
  ArmState built();

  /// Follow the straight ramp from (pulls_from, load_from) at `start` to (pulls_to,
  /// load_to). Here a pull may be negative (the tendon let out beyond its slack length: it
  /// is slack until the arm's motion takes it up), down to any positive rest length; throws
  /// std::invalid_argument naming `pulls` for a pull that leaves no rest length.
  ArmPath ramp(const ArmState& start, const Pulls& pulls_to, const Vector3& load_to,
               const ArmEvent& event = {});

  /// Release the arm at `from` with `pulls` and no tip load: energy descent to a minimum.
  ArmRelease release(const ArmState& from, const Pulls& pulls);

  /// Tip compliance at a state: d(tip displacement) / d(tip load) of the linearised
  /// equilibrium, 3 x 3 [mm/N] (symmetric: the tangent is).
  Eigen::Matrix3d tip_compliance(const ArmState& state);

  /// Per cell, the change of its height along the softest mode of the tangent at `state`
  /// (inverse iteration), the mode scaled to a largest DOF motion of 1 mm [mm].
  std::vector<double> softest_mode_heights(const ArmState& state);

  /// d tension_i / d pull_j at a state, 3 x 3 [N/mm] (tendons slack there: zero rows).
  Eigen::Matrix3d tension_sensitivity(const ArmState& state);

  /// Pulls that give every tendon the tension `tension` [N] with the tip load of `start`,
  /// from `start`; the path's last state is that equilibrium. Throws for tension <= 0.
  ArmPath pretension(const ArmState& start, double tension, double tolerance = 1e-9);

 private:
  struct Impl;
  const model::Arm* arm_;
  ArmOptions options_;
  std::unique_ptr<Impl> impl_;
};

/// Check pulls: finite and >= 0 (a negative pull would make the tendon longer than its
/// slack length) and below the slack length. Throws std::invalid_argument naming `name`.
void check_pulls(const Pulls& pulls, const model::Arm& arm, const std::string& name = "pulls");
/// Check only that every rest length stays positive (pulls below the slack lengths).
void check_rest_lengths(const Pulls& pulls, const model::Arm& arm, const std::string& name = "pulls");

// ---------------------------------------------------------------------------------------
// Analyses.

/// Tension each tendon is given before a tip load [N]. Just-taut tendons (0) respond
/// bilinearly (those on the side that shortens go slack at once), so the response to a
/// small load is neither linear nor symmetric; pretensioned, it is both. The thesis gives no
/// value; 1 N per tendon (3 N on the arm, a third of a cell's snap force) is an assumption.
constexpr double kDefaultPretension = 1.0;

/// Equilibrium under a tip load (and optional pulls), after pretensioning the tendons to
/// `pretension` N each (0: as built, just taut).
struct ArmLoadResult {
  ArmPath path;                  ///< the load ramp (its last state is the answer)
  ArmState pretensioned;         ///< the state before the load (the built one if none)
  Pulls pretension_pulls{};      ///< [mm]
  bool completed = false;
  std::string message;
};
ArmLoadResult arm_tip_load(ArmSolver& solver, const Vector3& load, const Pulls& pulls = {},
                           double pretension = kDefaultPretension);

/// Pull the tendons from `start` along `direction` (pulls, >= 0, largest 1) until a module
/// snaps or the pull reaches `max_pull` [mm].
struct ArmSnapResult {
  ArmPath path;                  ///< the pull ramp
  bool snapped = false;
  double pull = ArmState::kNaN;  ///< the largest tendon pull at the snap [mm]
  Pulls pulls{};                 ///< every tendon's pull at the snap (last stable state) [mm]
  Pulls tension{};               ///< tensions there [N]
  double tension_sum = ArmState::kNaN;  ///< their sum [N]
  int snapped_module = -1;       ///< the module whose cell changed state (0-based from the base)
  std::vector<int> snapped_cells;       ///< cells that changed state
  std::vector<int> cell_states_after;   ///< where the released arm came to rest
  std::string configuration_after;      ///< module states after ('0', '1'; '/' if split)
  ArmState after;                ///< the released arm's state
  bool release_converged = false;
  std::string message;
};
ArmSnapResult arm_pull_until_snap(ArmSolver& solver, const ArmState& start, const Pulls& direction,
                                  double max_pull);

/// The largest tip load along `direction` (a unit vector is taken from it) before a module
/// snaps or a tendon that was taut goes slack, from the pretensioned state.
struct ArmCapacityResult {
  double load = ArmState::kNaN;  ///< magnitude at the limit [N] (max_load if none reached)
  std::string limit;             ///< "snap", "slack", "none" or "failed"
  int tendon = -1;               ///< the tendon that went slack (0-based)
  int module = -1;               ///< the module that snapped (if known)
  ArmPath path;
  std::string message;
};
ArmCapacityResult arm_load_capacity(ArmSolver& solver, const ArmState& pretensioned,
                                    const Vector3& direction, double max_load);

}  // namespace kresling::analyses
