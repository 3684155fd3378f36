#pragma once
/// \file path_point.hpp
/// A converged point of a path with its exact derivatives along the path, and what the
/// adaptive increments (adaptive_path.hpp) build from such points: cubic Hermite curves
/// between them, which piece of its law each element is on (hinges' enhanced linear
/// limits, cables taut or slack) and where a hinge crosses a limit in between.

#include <vector>

#include "kresling/assembly/assembler.hpp"
#include "kresling/model/model.hpp"
#include "kresling/solvers/newton.hpp"
#include "kresling/solvers/path_control.hpp"
#include "kresling/solvers/tangent_solver.hpp"

namespace kresling::solvers {

struct PathPoint {
  double t = 0.0;
  VectorX u;           ///< all DOFs
  VectorX velocity;    ///< du/dt, all DOFs (at the held ones, the control's motion)
  VectorX force;       ///< the recorded forces (PathControl::recorded_dofs)
  VectorX force_rate;  ///< their derivative d/dt
  VectorX energy;       ///< per element family, in the model's order
  VectorX energy_rate;  ///< d/dt
  int negative = -1;    ///< negative eigenvalues of the tangent there
  /// Per hinge, then per cable, which piece of its law applies: for a hinge -1 below the
  /// enhanced linear law's lower limit, 1 above its upper one, 0 in between (and for the
  /// other laws, which have no kink); for a cable 1 taut, 0 slack.
  std::vector<signed char> pieces;
  NewtonOutcome outcome;
};

/// The pieces (PathPoint::pieces) of the model's hinges and cables at u.
std::vector<signed char> law_pieces(const model::Model& model, const VectorX& u);

/// Where along the path, between a converged point `a` and a converged `e` past an event,
/// the first hinge whose law piece differs between them reaches the limit in between (a
/// Newton step on theta(t) = limit from each end, the one from the nearer end). NaN when
/// the event is a stability change, a cable's, or no estimate lies in (a.t, e.t).
double predicted_kink(const model::Model& model, const PathPoint& a, const PathPoint& e);

/// The cubic Hermite curve through (ta, ya, da) and (tb, yb, db) (values and derivatives)
/// at t: interpolation for t in [ta, tb], extrapolation beyond.
template <typename V>
V hermite(double ta, const V& ya, const V& da, double tb, const V& yb, const V& db, double t) {
  const double h = tb - ta;
  const double s = (t - ta) / h, s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * ya + ((s3 - 2 * s2 + s) * h) * da + (3 * s2 - 2 * s3) * yb +
         ((s3 - s2) * h) * db;
}

inline VectorX hermite_u(const PathPoint& a, const PathPoint& b, double t) {
  return hermite<VectorX>(a.t, a.u, a.velocity, b.t, b.u, b.velocity, t);
}

/// The recorded forces, energies and path derivatives at the converged p.u (p.t), exactly
/// (no finite differences of the assembled forces: where bars are 1e5 times stiffer than
/// hinges, those lose ~6 digits). `full` is bound to the model at p.t over every DOF
/// (unshifted, lower triangle); `assembler` to the free rows, with `solver` holding the
/// free tangent factorised last (at p.u or within the Newton tolerance of it). The path
/// tangent v solves K_ff v_f = (df_ext/dt - df_int/dt at fixed u)_f - K_fh v_h (the
/// control's rates; v_h its held DOFs' motion), refined with K's products until the
/// recorded forces' rate changes by less than 1e-10 of itself. Each family's energy rate
/// is its internal force dotted with v plus its explicit rate. Returns false when a value
/// is not finite.
bool path_derivatives(assembly::Assembler& assembler, assembly::Assembler& full,
                      const TangentSolver& solver, PathControl& control,
                      const std::vector<Index>& recorded, double sign, PathPoint& p);

}  // namespace kresling::solvers
