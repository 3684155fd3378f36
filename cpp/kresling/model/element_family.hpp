#pragma once
/// \file element_family.hpp
/// The interface every kind of element implements: bars, hinges, cables, springs, and any
/// family added later. A model holds a list of families; the workspace, the assembly, the
/// energies, the element states and every path result iterate over that list, so a new
/// family is a kernel (elements/), a family file (model/<name>_family.*) and one line in
/// model/family_registry.cpp, with no edit anywhere else (docs/adding_an_element.md).
///
/// A family is immutable and evaluates all its elements in one call (one virtual call per
/// family and evaluation, none per element): it adds its internal forces into the global
/// vector and, when asked, its element tangents into the matrix's values through the slot
/// map the workspace made from the DOFs each element touches.

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "kresling/core/types.hpp"
#include "kresling/model/family_table.hpp"
#include "kresling/model/parameter_derivative.hpp"

namespace kresling::model {

/// Where one entry of an element matrix goes: its slot in the matrix's value array and the
/// positions (column-major) of the entry and its transpose in the element matrix.
struct ScatterEntry {
  int slot;
  std::uint16_t local;
  std::uint16_t transposed;
};

/// The stored entries of a family's element matrices: element e's are
/// entries[offsets[e], offsets[e + 1]).
struct FamilySlots {
  std::vector<ScatterEntry> entries;
  std::vector<int> offsets;
};

/// The elements of a family whose elements depend on the state (contact pairs, found anew
/// as panels approach and part), at one state: each element `width` nodes (row-major in
/// `nodes`) and a kind code the family defines (point-triangle, edge-edge, ...). The
/// workspace keeps the set its tangent's pattern was built for and rebuilds the pattern only
/// when a new element is not in it (or it holds many more than are active): the family's
/// assemble must then give elements that have become inactive no energy.
struct ActiveElements {
  int width = 0;
  std::vector<Index> nodes;
  std::vector<std::uint8_t> kinds;
  std::size_t size() const { return kinds.size(); }
  /// The DOFs of element e (3 per node).
  std::vector<Index> dofs(std::size_t e) const;
};

/// What an evaluation writes into: the internal force of every DOF (accumulated), and, when
/// `values` is not null, the tangent's value array through `slots` (the family's own).
/// `active` (only for a family that changes_elements()) is the element set `slots` was made
/// for, at the state being evaluated; when null the family finds its elements itself.
/// `definite`: the solver asks for a positive semi-definite element tangent where the family
/// can give one in place of its own (a family that adapts_tangent()); others ignore it.
struct AssemblyTarget {
  VectorX& force;
  double* values = nullptr;
  const FamilySlots* slots = nullptr;
  const ActiveElements* active = nullptr;
  bool definite = false;
};

/// Per-element quantities by name ("bar_strain", "hinge_angle", ...), in the order the
/// families add them.
struct ElementState {
  std::vector<std::pair<std::string, VectorX>> columns;
  void add(std::string name, VectorX values) { columns.emplace_back(std::move(name), std::move(values)); }
  /// The column `name`; throws std::invalid_argument if there is none.
  const VectorX& operator[](const std::string& name) const;
};

class ElementFamily {
 public:
  virtual ~ElementFamily() = default;

  /// Plural and lower case ("bars"): how energies, states and tables name the family.
  virtual const char* name() const = 0;
  virtual std::size_t size() const = 0;
  /// The DOFs element e acts on, in the order of its local vectors (3 per node: x, y, z).
  virtual std::vector<Index> element_dofs(std::size_t e) const = 0;
  /// Throws std::invalid_argument, naming the element, for data that is out of range or
  /// degenerate in the reference configuration X (`scale`: the model's extent [mm]).
  virtual void check(const NodeMatrix& X, double scale) const = 0;
  /// The stored energy of all elements at X + u; adds their internal forces (the energy's
  /// gradient) into target.force and, when target.values, their tangents.
  virtual double assemble(const NodeMatrix& X, const VectorX& u, AssemblyTarget& target) const = 0;
  /// Append this family's per-element quantities at deformed positions x.
  virtual void add_state(const NodeMatrix& x, ElementState& state) const = 0;
  /// The family's data as columns (family_table.hpp); from_table of its registry entry
  /// rebuilds it.
  virtual Table table() const = 0;
  /// Mark (set to 1) the DOFs this family ties elastically to the ground, one entry per
  /// DOF: they block rigid-body motions as supports do (an anchor spring). None by default.
  virtual void mark_grounded_dofs(std::vector<std::uint8_t>& /*grounded*/) const {}
  /// True when the family limits Newton's corrections (step_limit): a barrier that must not
  /// be stepped across. False by default, and then Newton never asks.
  virtual bool limits_steps() const { return false; }
  /// The fraction in (0, 1] of the correction du (one entry per DOF) that may be taken from
  /// X + u without crossing what the family guards.
  virtual double step_limit(const NodeMatrix& /*X*/, const VectorX& /*u*/,
                            const VectorX& /*du*/) const {
    return 1.0;
  }
  /// True when the family's elements depend on the state (contact pairs): its fixed
  /// elements (size(), element_dofs) are then none, and active_elements says which act at
  /// a state. The workspace asks at every assembly with a tangent and rebuilds its pattern
  /// when the set changes. False by default, and then nothing is asked.
  virtual bool changes_elements() const { return false; }
  /// True when the family's tangent is its exact Jacobian unless the solver asks for a
  /// positive semi-definite one (AssemblyTarget::definite): the solvers assemble it exact,
  /// and again definite where the whole tangent turns out not to be positive definite
  /// (factorize_tangent, solvers/newton.hpp). False by default, and then nothing is redone.
  virtual bool adapts_tangent() const { return false; }
  /// The elements acting at X + u (for a family that changes_elements()); `out` is
  /// overwritten. assemble() may be handed a superset of them (target.active): the elements
  /// of an earlier state, which it must evaluate as they are at X + u (zero when inactive).
  virtual void active_elements(const NodeMatrix& /*X*/, const VectorX& /*u*/,
                               ActiveElements& out) const {
    out = ActiveElements{};
  }
  /// The real columns of table() this family differentiates by (parameter_derivative):
  /// its elements' physical parameters. None by default (contact barriers: their stiffness
  /// and distance are numerical, not a design's).
  virtual std::vector<std::string> parameters() const { return {}; }
  /// The partial derivatives of the force and energy at X + u with respect to the column
  /// `name` of parameters() (parameter_derivative.hpp); `out` is reset first. Throws
  /// std::invalid_argument naming the family and the parameters it has for any other name.
  virtual void parameter_derivative(const NodeMatrix& X, const VectorX& u, const std::string& name,
                                    ParameterDerivative& out) const;
  /// parameter_derivative for several columns at once (`outs` resized to `names`): one
  /// evaluation of each element for all of them where the family's kernel gives every column
  /// together (bars, hinges); by default one parameter_derivative call per column.
  virtual void parameter_derivatives(const NodeMatrix& X, const VectorX& u,
                                     const std::vector<std::string>& names,
                                     std::vector<ParameterDerivative>& outs) const;
  /// The derivative of the column `name`'s entries with respect to the reference positions
  /// X, for the entries that hold the reference geometry. A model built stress-free in X (a
  /// bar's rest length its length at X, a hinge's rest angle its angle at X) stays so when X
  /// moves, so those entries move with X; an entry set to anything else (a fold's target
  /// angle, a cable's pulled length, a stiffness) does not. Appends triplets (entry, DOF of
  /// X, d theta_entry / d X_DOF). Nothing by default: no column follows the geometry.
  virtual void reference_geometry_derivative(const NodeMatrix& X, const std::string& name,
                                             std::vector<ParameterDerivative::Triplet>& out) const {
    (void)X, (void)name, (void)out;
  }
  /// The name of element e in messages ("bar 3 (nodes 1, 2)").
  std::string element_name(std::size_t e) const;
};

using FamilyPtr = std::shared_ptr<const ElementFamily>;

/// The 3 N DOFs of N nodes, in node order.
template <std::size_t N>
std::array<Index, 3 * N> node_dofs(const std::array<Index, N>& nodes) {
  std::array<Index, 3 * N> dofs{};
  for (std::size_t i = 0; i < N; ++i) {
    for (int k = 0; k < 3; ++k) dofs[3 * i + k] = 3 * nodes[i] + k;
  }
  return dofs;
}
std::vector<Index> node_dofs(const std::vector<Index>& nodes);

/// Position X + u of `node`.
inline Vector3 position(const NodeMatrix& X, const VectorX& u, Index node) {
  return X.row(node).transpose() + u.segment<3>(3 * node);
}

/// Add an element's local force into the global force at its DOFs.
template <typename Local, typename Dofs>
void add_local_force(const Local& local, const Dofs& dofs, VectorX& force) {
  for (std::size_t a = 0; a < dofs.size(); ++a) force[dofs[a]] += local[static_cast<Index>(a)];
}

/// Add element e's tangent `local` (column-major, square) into the matrix values through
/// the family's slots, symmetrised on the way in: 0.5 (K(a, b) + K(b, a)).
template <typename Local>
void scatter_local_tangent(const Local& local, const FamilySlots& slots, std::size_t e,
                           double* values) {
  const double* k = local.data();
  const ScatterEntry* end = slots.entries.data() + slots.offsets[e + 1];
  for (const ScatterEntry* s = slots.entries.data() + slots.offsets[e]; s != end; ++s) {
    values[s->slot] += 0.5 * (k[s->local] + k[s->transposed]);
  }
}

/// require_positive with an element's name built only on failure (checks run for every
/// element of every model a sweep builds).
void require_element_positive(const ElementFamily& family, std::size_t e, const char* what,
                              double value, bool allow_zero = false);

/// Throws std::invalid_argument naming element e of `family` when one of its `count` nodes
/// is out of [0, num_nodes) or appears twice.
void require_element_nodes(const ElementFamily& family, std::size_t e, const Index* nodes,
                           int count, Index num_nodes);

/// Throws std::invalid_argument: `name` is not one of family's parameters().
[[noreturn]] void throw_unknown_parameter(const ElementFamily& family, const std::string& name);

}  // namespace kresling::model
