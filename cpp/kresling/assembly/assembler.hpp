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
  const Workspace& workspace() const { return *workspace_; }

  /// True if `model` has the connectivity of the workspace (see Workspace::fits).
  bool same_connectivity(const model::Model& model) const { return workspace_->fits(model); }
  /// Evaluate `model` from now on (same connectivity required; throws otherwise). `model`
  /// must outlive the assembler or the next rebind.
  void rebind(const model::Model& model);

  /// assemble(model(), workspace(), u, force, with_matrix, definite), the fit checked at
  /// binding.
  Energies assemble(const VectorX& u, VectorX& force, bool with_matrix, bool definite = false) {
    return assemble_unchecked(*model_, *workspace_, u, force, with_matrix, definite);
  }

  /// The tangent from the last assemble(..., true) call (see Workspace::matrix).
  const SparseMatrix& matrix() const { return workspace_->matrix(); }

 private:
  const model::Model* model_;
  std::unique_ptr<Workspace> owned_;  // the workspace of the one-off form, else empty
  Workspace* workspace_;
};

/// Per-element state at displacement u, family by family in the model's order: bar
/// strains, forces, stresses and energies; hinge angles, moments and energies; cable lengths,
/// tensions and energies; and whatever the other families report (for post-processing).
using model::ElementState;
ElementState element_state(const model::Model& model, const VectorX& u);

/// The rate of each family's stored energy (in the model's order) at displacement u moving
/// with velocity v (both one entry per DOF): the family's internal force dotted with v.
VectorX energy_rates(const model::Model& model, const VectorX& u, const VectorX& v);

}  // namespace kresling::assembly
