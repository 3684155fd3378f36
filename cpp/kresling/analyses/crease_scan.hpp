#pragma once
/// \file crease_scan.hpp
/// Driving a group of creases' rest angles until the state they start from ceases to exist
/// (a snap), then releasing them: the path the switching of a cell (switching.hpp) and of an
/// arm's module (arm_crease_switching.hpp) both follow.
///
/// The rest angles theta0_i of the driven creases move by one change Delta, each in its
/// direction s_i (targets theta0_i + sign s_i Delta). Each increment of Delta is one solve of
/// the fold solver (solvers::solve_fold) from the previous equilibrium; the state is followed
/// while it stays on its branch: converged, stable (positive-definite tangent) and no node
/// moving by more than `jump` in one increment. The first increment that leaves the branch
/// brackets the limit point (the snap), which bisection narrows to `resolution`; if the
/// bracket's upper end is then reached from its lower one, the branch was steep, not ending,
/// and the scan goes on. Held `overshoot` past the snap, energy descent
/// (solvers::minimize_energy) finds where the structure snaps to; the rest angles are set
/// back (released) and a second descent finds where it comes to rest.
///
/// Recorded along the path (SwitchResult): the summed moment m = - sum_i s_i M_i of the
/// driven creases in the driving sense, the largest |M_i|, the work W = integral of the rest
/// angles' generalised force f = sum_i s_i dE/dtheta0_i over Delta (trapezoids; = m while
/// every crease stays inside the law's linear range), the strain energy and a height that
/// the caller defines.

#include <functional>
#include <string>

#include "kresling/analyses/switching.hpp"
#include "kresling/model/model.hpp"
#include "kresling/solvers/energy_minimum.hpp"

namespace kresling::analyses {

/// The driven creases: hinge indices, their stress-free rest angles and directions (+-1).
struct CreaseDrive {
  std::vector<Index> hinges;
  VectorX rest, direction;
};

/// Throws std::invalid_argument for scan options out of range (SwitchingOptions' scan_step,
/// max_change, resolution, overshoot and Newton's controls).
void check_scan_options(const SwitchingOptions& options);

/// The hinges of `model` among `candidates`, their rest angles and directions: the sign of
/// (to_angles - from_angles), the short way round (both per hinge of the model, e.g. its
/// angles in the start state and in the other stable state). Per crease, not per family: a
/// family's hinges need not share an orientation. Hinges without stiffness are skipped
/// (cut creases exert no moment).
CreaseDrive make_crease_drive(const model::Model& model, const std::vector<Index>& candidates,
                              const VectorX& from_angles, const VectorX& to_angles);

/// A hinge's dihedral angle in [0, 2 pi) at displacement u [rad].
double hinge_angle(const model::Model& model, const VectorX& u, Index hinge);

class CreaseScan {
 public:
  using Height = std::function<double(const VectorX&)>;
  /// `model`, `options` must outlive the scan. `jump` [mm]: a node moving by more than this
  /// in one increment has left the branch. `height(u)` is what the path records [mm].
  /// `descent`: the energy descents' controls after the snap.
  CreaseScan(const model::Model& model, const SwitchingOptions& options, double jump,
             Height height, const solvers::EnergyMinimumOptions& descent);

  /// Drive `drive` with `sign` (+1: along the directions, -1: against them) from the
  /// equilibrium `start`. The result's landing fields are set when the structure snapped;
  /// `landing` (if given) receives the displacement where it came to rest, `snap` the last
  /// state on the branch. landing_tilt is left to the caller.
  SwitchResult run(CreaseGroup group, const CreaseDrive& drive, double sign, const VectorX& start,
                   VectorX* snap = nullptr, VectorX* landing = nullptr);

 private:
  bool probe(const CreaseDrive& d, double sign, double delta, VectorX& u,
             solvers::PathStep& step);
  void record(SwitchResult& r, const CreaseDrive& d, double sign, double delta, const VectorX& u,
              const solvers::PathStep& step);
  void land(SwitchResult& r, const CreaseDrive& d, double sign, VectorX& u);
  void narrow(SwitchResult& r, const CreaseDrive& d, double sign, double& lo, double& hi,
              VectorX& u, solvers::PathStep& step);
  double change_range(const CreaseDrive& d, double sign) const;

  const model::Model& model_;
  const SwitchingOptions& o_;
  double jump_;
  Height height_;
  solvers::EnergyMinimumOptions descent_;
  double last_force_ = 0.0;  // the rest angles' generalised force at the last record
  std::string failure_;      // why the last probe that failed did
};

}  // namespace kresling::analyses
