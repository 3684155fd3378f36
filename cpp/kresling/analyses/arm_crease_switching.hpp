#pragma once
/// \file arm_crease_switching.hpp
/// Switching one module of the arm (model/arm.hpp) by its creases instead of by pulling the
/// tendons: the crease scan of a single cell (crease_scan.hpp, switching.hpp) on the whole
/// arm, with the creases of one module driven.
///
/// The driven creases are the stiff hinges of one crease group (valley, mountain, polygon
/// edges, or all folds) in the module's driven cells (both, or the one that is not yet in
/// the state the module is driven to, as in a module that a tendon pull half switched). Each is driven the way it turns from the
/// module's one state to the other, as built: to extend the module, the sign of (its angle in
/// the arm built with the module extended - its angle in the arm built with it contracted),
/// the short way round, per crease; the opposite to contract it. The start is any
/// equilibrium of the arm (the built arm, or one a tendon pull left, its module contracted
/// though built extended). The tendons are let out by `let_out` (their
/// rest lengths the slack lengths plus it), so that they carry nothing while the module
/// changes length: a module extended by its creases lengthens the tendons' paths, which
/// just-taut tendons would resist. The scan follows the arm's equilibrium with the fold
/// solver until the module's start state ceases to exist, the arm snaps with the actuation
/// held just past it, and, released, comes to rest (energy descent). The height the scan
/// records is the module's length (the distance between its guides' centres); a node that
/// moves by more than a twentieth of (Le - Lc) in one increment has left the branch.

#include <limits>
#include <string>
#include <vector>

#include "kresling/analyses/arm_analysis.hpp"
#include "kresling/analyses/switching.hpp"
#include "kresling/geometry/design.hpp"
#include "kresling/model/arm.hpp"

namespace kresling::analyses {

struct ArmCreaseSwitchOptions {
  /// The scan's controls (scan_step, max_change, resolution, overshoot, newton); its
  /// specimen and snap_through_steps are not used (the arm's parameters hold the cells').
  SwitchingOptions scan;
  CreaseGroup group = CreaseGroup::Folds;
  /// How far each tendon is let out beyond its slack length [mm]; NaN: 3 (Le - Lc), one and
  /// a half times a module's travel.
  double let_out = std::numeric_limits<double>::quiet_NaN();
};

struct ArmCreaseSwitchResult {
  int module = -1;                   ///< the driven module, 0-based from the base
  bool forward = true;               ///< towards contracted (false: towards extended)
  double let_out = 0.0;              ///< tendon let-out [mm]
  std::vector<Index> hinges;         ///< the driven hinges
  SwitchResult scan;                 ///< the crease path (heights: the module's length)
  ArmState start, snap, after;       ///< as built, at the snap (last on the branch), released
  std::string configuration_before, configuration_after;  ///< 'x': a half-switched module
};

/// Drive the creases of `options.group` in cells `cells` (of module `module`: 2 module and/or
/// 2 module + 1) in the arm of `design`, `states`
/// (per module, base first, as built) and `parameters`, from the equilibrium at
/// displacement `start` (empty: the built arm), towards the module's extended state if
/// `extend`, else its contracted one. Throws std::invalid_argument naming the parameter for
/// a module out of range, cells not of it, a start of the wrong size or bad options; a group with no stiff
/// crease gets a result whose message says so.
ArmCreaseSwitchResult arm_crease_switch(const geometry::Design& design,
                                        const std::vector<int>& states,
                                        const model::ArmParameters& parameters, int module,
                                        const std::vector<int>& cells, const VectorX& start,
                                        bool extend, const ArmCreaseSwitchOptions& options = {});

}  // namespace kresling::analyses
