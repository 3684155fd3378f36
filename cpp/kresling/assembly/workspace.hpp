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
/// half the scatter work). The model's element families (model/element_family.hpp) are
/// evaluated one after another in the model's order, each through its own part of the slot
/// map; nothing here knows what a family is.
///
/// A family whose elements change with the state (contact pairs: changes_elements()) is
/// asked for its active elements at every assembly with a tangent; when one is not among
/// those the pattern was built for (or these are more than twice as many as are active),
/// the pattern, the slot map and pattern_id() are renewed (a solver then analyses the new
/// pattern: TangentSolver::set_pattern). A model without such a family never asks, and its
/// pattern never changes.
///
/// The solvers' other per-state data, the symbolic factorisation of the tangent, lives
/// beside the workspace in the solver that owns both (solvers::TangentSolver).

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/SparseCore>

#include "kresling/core/types.hpp"
#include "kresling/model/model.hpp"

namespace kresling::assembly {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Most element families a model may hold.
constexpr std::size_t kMaxFamilies = 8;

/// Stored energy by element family, in the order of the model's families().
struct Energies {
  std::array<double, kMaxFamilies> values{};
  std::size_t count = 0;
  double operator[](std::size_t family) const { return values[family]; }
  /// The sum, family by family in order.
  double total() const {
    double sum = 0.0;
    for (std::size_t i = 0; i < count; ++i) sum += values[i];
    return sum;
  }
  /// As a vector of `count` entries.
  VectorX vector() const { return Eigen::Map<const VectorX>(values.data(), static_cast<Index>(count)); }
};

using model::ScatterEntry;

/// Which part of the symmetric tangent is stored.
enum class Storage { Full, Lower };

/// The numbering that assembles every DOF (rows[i] = i).
std::vector<Index> all_dofs(Index num_dofs);

/// The numbering of the DOFs whose mask entry is 0, consecutively; the others get -1.
std::vector<Index> unmasked_dofs(const std::vector<std::uint8_t>& mask);

class Workspace;

/// Evaluate `model` at displacement u (length num_dofs) through `workspace`: `force` gets
/// the internal force of every DOF (resized to num_dofs); if `with_matrix`, the workspace's
/// tangent values are refilled (read them with workspace.matrix()), each family's own or,
/// with `definite`, positive semi-definite where a family can make it so
/// (ElementFamily::adapts_tangent). Throws
/// std::invalid_argument if the workspace was built for another connectivity, or for a u of
/// the wrong size.
Energies assemble(const model::Model& model, Workspace& workspace, const VectorX& u,
                  VectorX& force, bool with_matrix, bool definite = false);

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

  /// Identifies the current pattern: a new value (unique across workspaces) whenever the
  /// pattern is built or rebuilt for a changed set of active elements.
  std::uint64_t pattern_id() const { return pattern_id_; }

  /// The tangent from the last assemble(..., true) through this workspace: size() x size(),
  /// symmetric, whole or its lower triangle (see Storage).
  const SparseMatrix& matrix() const { return matrix_; }
  /// Add d[dof] to the diagonal of the last assembled tangent at every assembled DOF's row
  /// (`d` has one entry per DOF): how terms outside the model (a time step's lumped mass)
  /// enter the tangent without a pattern of their own.
  void add_to_diagonal(const VectorX& d);
  /// Multiply the last assembled tangent's values by `factor` (the diagonal shift included).
  void scale_matrix(double factor);
  /// Add `factor` times `values` (a copy of matrix()'s value array, of the same pattern) to
  /// the last assembled tangent: a constant matrix of this pattern (an initial stiffness).
  void add_matrix_values(const std::vector<double>& values, double factor);

 private:
  friend Energies assemble_unchecked(const model::Model& model, Workspace& workspace,
                                     const VectorX& u, VectorX& force, bool with_matrix,
                                     bool definite);

  std::vector<Index> connectivity_;  // see connectivity_of
  std::vector<Index> rows_;
  Index size_ = 0;
  double shift_ = 0.0;
  Storage storage_ = Storage::Full;
  SparseMatrix matrix_;
  // The slot map of each family of the model, in the model's order.
  std::vector<model::FamilySlots> slots_;
  std::vector<int> diagonal_slots_;
  // The active elements the pattern was built for, per family (empty for families whose
  // elements do not change), the indices of the families that change, and the pattern's id.
  std::vector<model::ActiveElements> active_;
  std::vector<std::size_t> changing_;
  std::uint64_t pattern_id_ = 0;

  void build_pattern(const model::Model& model);
  // Renew the active elements of the changing families at u; rebuild the pattern if they
  // differ from the pattern's.
  void update_active(const model::Model& model, const VectorX& u);
};

/// assemble() without the connectivity check, for a caller that made it once for many
/// evaluations (an Assembler checks when it is bound). `workspace.fits(model)` is required.
Energies assemble_unchecked(const model::Model& model, Workspace& workspace, const VectorX& u,
                            VectorX& force, bool with_matrix, bool definite = false);

}  // namespace kresling::assembly
