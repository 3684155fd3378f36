#pragma once
/// \file workspace.hpp
/// The per-state data of assembly, apart from the model (the Model/Data split of rigid-body
/// libraries such as pinocchio): a model is immutable and may be shared; a Workspace holds
/// what assembling it needs besides the model - the sparsity pattern of the tangent, the slot
/// map and the matrix's values - and no reference to any model. `assemble(model, workspace,
/// u, ...)` evaluates a model through a workspace built for it or for any model of the same
/// connectivity (same node count and elements, node for node, in order: the geometry, areas,
/// stiffnesses and laws may differ), and refuses one of another connectivity.
///
/// The pattern and slot map (for every element entry, its position in the matrix's value
/// array) are built once per connectivity and row numbering; each evaluation then only
/// refills values. Rows are chosen by a DOF numbering: `rows[dof]` is the row of that DOF in
/// the assembled matrix, or -1 to leave it out (a fixed or imposed DOF). The tangent is
/// symmetrised element by element and shifted by `shift` on the diagonal, as MERLIN2 does.
/// It is stored either whole or as its lower triangle only (what the factorisations read:
/// half the scatter work). Hinges of zero stiffness contribute nothing and are skipped.
/// Cables (if the model has any) are assembled after bars and hinges; a model without
/// cables runs exactly the bar and hinge loops it always did.
///
/// The solvers' other per-state data, the symbolic factorisation of the tangent, lives
/// beside the workspace in the solver that owns both (solvers::TangentSolver).

#include <cstdint>
#include <vector>

#include <Eigen/SparseCore>

#include "kresling/core/types.hpp"
#include "kresling/model/model.hpp"

namespace kresling::assembly {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Stored energy by element family.
struct Energies {
  double bars = 0.0;
  double hinges = 0.0;
  double cables = 0.0;
  double total() const { return bars + hinges + cables; }
};

/// Where one entry of an element matrix goes: its slot in the matrix's value array and the
/// positions (column-major) of the entry and its transpose in the element matrix.
struct ScatterEntry {
  int slot;
  std::uint16_t local;
  std::uint16_t transposed;
};

/// Which part of the symmetric tangent is stored.
enum class Storage { Full, Lower };

/// The numbering that assembles every DOF (rows[i] = i).
std::vector<Index> all_dofs(Index num_dofs);

/// The numbering of the DOFs whose mask entry is 0, consecutively; the others get -1.
std::vector<Index> unmasked_dofs(const std::vector<std::uint8_t>& mask);

class Workspace;

/// Evaluate `model` at displacement u (length num_dofs) through `workspace`: `force` gets
/// the internal force of every DOF (resized to num_dofs); if `with_matrix`, the workspace's
/// tangent values are refilled (read them with workspace.matrix()). Throws
/// std::invalid_argument if the workspace was built for another connectivity, or for a u of
/// the wrong size.
Energies assemble(const model::Model& model, Workspace& workspace, const VectorX& u,
                  VectorX& force, bool with_matrix);

class Workspace {
 public:
  /// The pattern and slot map of `model`'s connectivity under the numbering `rows` (one
  /// entry per DOF). Keeps nothing of `model` but its connectivity.
  Workspace(const model::Model& model, std::vector<Index> rows, double shift = 1e-8,
            Storage storage = Storage::Full);

  /// Rows (and columns) of the assembled matrix.
  Index size() const { return size_; }
  const std::vector<Index>& rows() const { return rows_; }
  Storage storage() const { return storage_; }
  /// Added to the tangent's diagonal; a setting, not part of the pattern, so it may change.
  double shift() const { return shift_; }
  void set_shift(double shift) { shift_ = shift; }

  /// True if `model` has the connectivity this workspace was built for (same node count and
  /// elements, node for node, in order).
  bool fits(const model::Model& model) const;
  /// Throws std::invalid_argument, saying what differs, unless fits(model).
  void require_fits(const model::Model& model) const;

  /// The tangent from the last assemble(..., true) through this workspace: size() x size(),
  /// symmetric, whole or its lower triangle (see Storage).
  const SparseMatrix& matrix() const { return matrix_; }

 private:
  friend Energies assemble_unchecked(const model::Model& model, Workspace& workspace,
                                     const VectorX& u, VectorX& force, bool with_matrix);

  std::vector<Index> connectivity_;  // node count, every element's nodes, bars, hinges, cables
  std::vector<Index> rows_;
  Index size_ = 0;
  double shift_ = 0.0;
  Storage storage_ = Storage::Full;
  SparseMatrix matrix_;
  // The stored entries of each element matrix: element e's are [offsets[e], offsets[e+1]).
  std::vector<ScatterEntry> bar_entries_, hinge_entries_;
  std::vector<int> bar_offsets_, hinge_offsets_;
  std::vector<ScatterEntry> cable_entries_;
  std::vector<int> cable_offsets_;
  std::vector<std::vector<Index>> cable_dofs_;
  std::vector<int> diagonal_slots_;
};

/// assemble() without the connectivity check, for a caller that made it once for many
/// evaluations (an Assembler checks when it is bound). `workspace.fits(model)` is required.
Energies assemble_unchecked(const model::Model& model, Workspace& workspace, const VectorX& u,
                            VectorX& force, bool with_matrix);

}  // namespace kresling::assembly
