#pragma once
/// \file assembler.hpp
/// Global internal force, tangent stiffness and energy of a model.
///
/// The sparsity pattern and a slot map (for every element entry, its position in the
/// matrix's value array) are built once per model and row numbering; each call then only
/// refills values. Rows are chosen by a DOF numbering: `rows[dof]` is the row of that DOF in
/// the assembled matrix, or -1 to leave it out (a fixed or imposed DOF). The tangent is
/// symmetrised element by element and shifted by `shift` on the diagonal, as MERLIN2 does.
/// It is stored either whole or as its lower triangle only (what the factorisations read:
/// half the scatter work). Hinges of zero stiffness contribute nothing and are skipped.
/// Cables (if the model has any) are assembled after bars and hinges; a model without
/// cables runs exactly the bar and hinge loops it always did.

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

class Assembler {
 public:
  /// `model` must outlive the assembler.
  Assembler(const model::Model& model, std::vector<Index> rows, double shift = 1e-8,
            Storage storage = Storage::Full);

  Index size() const { return size_; }
  const model::Model& model() const { return *model_; }

  /// True if `model` has the same nodes count and elements (node for node, in order) as the
  /// model this assembler was built for: then `rebind` can reuse the pattern and slots.
  bool same_connectivity(const model::Model& model) const;
  /// Evaluate `model` from now on (same connectivity required; throws otherwise). `model`
  /// must outlive the assembler or the next rebind.
  void rebind(const model::Model& model);
  const std::vector<Index>& rows() const { return rows_; }

  /// Evaluate at displacement u (length num_dofs): `force` gets the internal force of every
  /// DOF (resized to num_dofs); if `with_matrix`, the tangent's values are refilled.
  Energies assemble(const VectorX& u, VectorX& force, bool with_matrix);

  /// The tangent from the last assemble(..., true) call: size() x size(), symmetric, whole
  /// or its lower triangle (see Storage).
  const SparseMatrix& matrix() const { return matrix_; }

 private:
  const model::Model* model_;
  std::vector<Index> connectivity_;  // every element's nodes, bars, hinges, then cables
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
