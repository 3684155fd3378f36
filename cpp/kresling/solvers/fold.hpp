#pragma once
/// \file fold.hpp
/// Folding by crease actuation: the rest angles of chosen hinges are driven from where they
/// are to targets, in stages, each increment an equilibrium solve of the model with its
/// supports and loads (the path follower under a RestAngleControl). How a pattern folds
/// from flat, and the sign convention of fold angles, are the caller's (docs/folding.md);
/// here everything is a hinge's rest angle in [0, 2 pi).

#include <vector>

#include "kresling/model/model.hpp"
#include "kresling/solvers/path.hpp"

namespace kresling::solvers {

/// One stage: these hinges' rest angles go linearly to these targets [rad, in [0, 2 pi)].
struct FoldStage {
  std::vector<Index> hinges;
  VectorX targets;
};

struct FoldOptions {
  NewtonOptions newton;
  int max_bisections = 10;  ///< a failed increment is halved up to this many times
  /// Each increment's start: 0 = the previous equilibrium, 1-3 = a linear, quadratic or
  /// cubic extrapolation through the last 2-4 equilibria.
  int extrapolation = 0;
  double shift = 1e-8;
  /// Adaptive increments with dense output (adaptive_path.hpp): each stage's `steps` equal
  /// samples read off cubic Hermite curves between increments chosen by an error estimate
  /// of the stored energy, never across a stability change, a hinge crossing a limit of the
  /// enhanced linear law or a cable going slack. A stage the adaptive increments cannot
  /// finish is folded again in fixed increments (from `extrapolation`'s start), whose
  /// result is kept (the attempts of both counted).
  bool adaptive = false;
  /// The samples' estimated energy error relative to the largest stored energy so far, in
  /// (0, 1e-4].
  double adaptive_tolerance = 1e-9;
  /// Where the fold's equilibrium path ends (a limit point of the rest angles: no
  /// equilibrium near at the next increment), the sheet snaps to a stable state by an
  /// energy descent and the fold goes on from there (FollowOptions::snap).
  bool snap = false;
  /// Fold through stable states only, as a sheet actuated slowly comes to rest: an
  /// increment whose Newton solve fails or ends at an unstable equilibrium (a negative
  /// eigenvalue of the tangent) is relaxed whole instead, from the last equilibrium, to a
  /// stable state at its rest angles (FollowOptions::relax), and only where none is found
  /// halved (its parts then followed as without `relax`); snaps (`snap`) relax too. With `adaptive`, the fixed increments a
  /// stage falls back to relax.
  bool relax = false;
  /// A relaxed increment's budget of relaxation iterations (FollowOptions::relax_iterations).
  int relax_iterations = 200;
  StopRule stop;
};

/// Fold `model` through `stages`, one after another, `steps` increments each, from
/// `initial` (empty = zero displacement). A stage starts from the rest angles the model has
/// after the stages before it (the model's own for the first). The external load is
/// `forces` (one entry per DOF, may be zero) ramped from 0 to 1 over the first stage and
/// held through the others. Each step's load_factor is (stage - 1) + the fraction of that
/// stage (so stage k runs from k - 1 to k); its constraint forces are the support
/// reactions. Throws std::invalid_argument for bad input (sizes, a hinge out of range or
/// driven twice in a stage, targets outside [0, 2 pi), no stage, free rigid-body motions).
PathResult solve_fold(const model::Model& model, const std::vector<FoldStage>& stages, int steps,
                      const VectorX& forces, const FoldOptions& options = {},
                      const VectorX& initial = VectorX());

/// The model with the rest angles every stage leaves (the end of the fold).
model::Model folded_rest_model(const model::Model& model, const std::vector<FoldStage>& stages);

}  // namespace kresling::solvers
