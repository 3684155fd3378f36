#pragma once
/// \file assembler.hpp
/// A model and a workspace taken together for one computation, and per-element states.
///
/// An Assembler is what the solvers' loops call: the model being solved, bound to a
/// Workspace (workspace.hpp) checked once to fit it. It keeps a pointer to that model, so it
/// lives on the stack of the computation that made it (a solve), or is emptied when that
/// computation returns; what outlives a computation - a reusable solver, a test run over many
/// designs - keeps the Workspace alone, which holds no reference to any model.

#include <memory>
#include <vector>

#include "kresling/assembly/workspace.hpp"
#include "kresling/core/types.hpp"
#include "kresling/model/model.hpp"

namespace kresling::assembly {

class Assembler {
 public:
  /// Bind `model` to `workspace` (which must fit it; throws std::invalid_argument
  /// otherwise). Both must outlive the assembler.
  Assembler(const model::Model& model, Workspace& workspace);
  /// Bind `model` to a workspace of its own, built here (a one-off computation). `model`
  /// must outlive the assembler.
  Assembler(const model::Model& model, std::vector<Index> rows, double shift = 1e-8,
            Storage storage = Storage::Full);

  Index size() const { return workspace_->size(); }
  const model::Model& model() const { return *model_; }
  const std::vector<Index>& rows() const { return workspace_->rows(); }
  Workspace& workspace() { return *workspace_; }

  /// True if `model` has the connectivity of the workspace (see Workspace::fits).
  bool same_connectivity(const model::Model& model) const { return workspace_->fits(model); }
  /// Evaluate `model` from now on (same connectivity required; throws otherwise). `model`
  /// must outlive the assembler or the next rebind.
  void rebind(const model::Model& model);

  /// assemble(model(), workspace(), u, force, with_matrix), the fit checked at binding.
  Energies assemble(const VectorX& u, VectorX& force, bool with_matrix) {
    return assemble_unchecked(*model_, *workspace_, u, force, with_matrix);
  }

  /// The tangent from the last assemble(..., true) call (see Workspace::matrix).
  const SparseMatrix& matrix() const { return workspace_->matrix(); }

 private:
  const model::Model* model_;
  std::unique_ptr<Workspace> owned_;  // the workspace of the one-off form, else empty
  Workspace* workspace_;
};

/// Per-element state at displacement u: bar strains and hinge angles (for post-processing).
struct ElementState {
  VectorX bar_strain;     ///< Green-Lagrange strain per bar
  VectorX bar_force;      ///< axial force per bar, A S(E) l / L (tension positive)
  VectorX bar_stress;     ///< second Piola-Kirchhoff stress S(E) per bar
  VectorX bar_energy;     ///< stored energy per bar, A L W(E)
  VectorX hinge_angle;    ///< dihedral angle per hinge [rad]
  VectorX hinge_moment;   ///< L0 M(theta) per hinge
  VectorX hinge_energy;   ///< stored energy per hinge
  VectorX cable_length;   ///< total length of each cable's path [mm]
  VectorX cable_tension;  ///< tension per cable (0 when slack) [N]
  VectorX cable_energy;   ///< stored energy per cable
};
ElementState element_state(const model::Model& model, const VectorX& u);

}  // namespace kresling::assembly
