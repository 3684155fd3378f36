#include "kresling/assembly/workspace.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "kresling/elements/bar.hpp"
#include "kresling/elements/cable.hpp"
#include "kresling/elements/dihedral.hpp"
#include "kresling/elements/hinge.hpp"

namespace kresling::assembly {

namespace {

// The 3 k DOFs of an element's nodes, in element order.
template <std::size_t N>
std::array<Index, 3 * N> element_dofs(const std::array<Index, N>& nodes) {
  std::array<Index, 3 * N> dofs{};
  for (std::size_t i = 0; i < N; ++i) {
    for (int k = 0; k < 3; ++k) dofs[3 * i + k] = 3 * nodes[i] + k;
  }
  return dofs;
}

int find_slot(const SparseMatrix& m, Index row, Index col) {
  const int* begin = m.innerIndexPtr() + m.outerIndexPtr()[col];
  const int* end = m.innerIndexPtr() + m.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(begin, end, static_cast<int>(row));
  return static_cast<int>(it - m.innerIndexPtr());
}

// Whether the entry (row r, column c) of the assembled matrix is stored.
bool stored(Index r, Index c, Storage storage) {
  return r >= 0 && c >= 0 && (storage == Storage::Full || r >= c);
}

template <typename Dofs>
void add_pattern(const Dofs& dofs, const std::vector<Index>& rows,
                 Storage storage, std::vector<Eigen::Triplet<double, int>>& entries) {
  for (Index a : dofs) {
    for (Index b : dofs) {
      if (stored(rows[a], rows[b], storage)) entries.emplace_back(rows[a], rows[b], 0.0);
    }
  }
}

template <typename Dofs>
void add_slots(const Dofs& dofs, const std::vector<Index>& rows,
               Storage storage, const SparseMatrix& m, std::vector<ScatterEntry>& entries,
               std::vector<int>& offsets) {
  // Only the entries the matrix stores: a compact list instead of a branch per entry of
  // the element matrix (half of which the lower-triangle storage skips).
  const std::size_t D = dofs.size();
  for (std::size_t b = 0; b < D; ++b) {
    for (std::size_t a = 0; a < D; ++a) {
      if (stored(rows[dofs[a]], rows[dofs[b]], storage)) {
        entries.push_back({find_slot(m, rows[dofs[a]], rows[dofs[b]]),
                           static_cast<std::uint16_t>(b * D + a),
                           static_cast<std::uint16_t>(a * D + b)});
      }
    }
  }
  offsets.push_back(static_cast<int>(entries.size()));
}

template <int D>
void scatter(const Eigen::Matrix<double, D, D>& local, const ScatterEntry* begin,
             const ScatterEntry* end, double* values) {
  // Symmetrised on the way in: 0.5 (K(a, b) + K(b, a)); column-major local indices.
  const double* k = local.data();
  for (const ScatterEntry* e = begin; e != end; ++e) values[e->slot] += 0.5 * (k[e->local] + k[e->transposed]);
}

template <int D>
void add_force(const Eigen::Matrix<double, D, 1>& local, const std::array<Index, D>& dofs,
               VectorX& force) {
  for (int a = 0; a < D; ++a) force[dofs[a]] += local[a];
}

// The 3 k DOFs of a cable's nodes, in cable order.
std::vector<Index> cable_dofs(const std::vector<Index>& nodes) {
  std::vector<Index> dofs(3 * nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    for (int k = 0; k < 3; ++k) dofs[3 * i + k] = 3 * nodes[i] + k;
  }
  return dofs;
}

}  // namespace

namespace {

std::vector<Index> connectivity_of(const model::Model& model) {
  std::vector<Index> c;
  c.reserve(2 * model.bars().size() + 4 * model.hinges().size() + 1);
  c.push_back(model.num_nodes());
  for (const auto& b : model.bars()) c.insert(c.end(), b.nodes.begin(), b.nodes.end());
  for (const auto& h : model.hinges()) c.insert(c.end(), h.nodes.begin(), h.nodes.end());
  c.push_back(static_cast<Index>(model.bars().size()));
  for (const auto& cable : model.cables()) {  // each cable's length, then its nodes
    c.push_back(static_cast<Index>(cable.nodes.size()));
    c.insert(c.end(), cable.nodes.begin(), cable.nodes.end());
  }
  return c;
}

}  // namespace

std::vector<Index> all_dofs(Index num_dofs) {
  std::vector<Index> rows(num_dofs);
  for (Index i = 0; i < num_dofs; ++i) rows[i] = i;
  return rows;
}

std::vector<Index> unmasked_dofs(const std::vector<std::uint8_t>& mask) {
  std::vector<Index> rows(mask.size(), -1);
  Index next = 0;
  for (std::size_t i = 0; i < mask.size(); ++i) {
    if (!mask[i]) rows[i] = next++;
  }
  return rows;
}

Workspace::Workspace(const model::Model& model, std::vector<Index> rows, double shift,
                     Storage storage)
    : rows_(std::move(rows)), shift_(shift), storage_(storage) {
  if (static_cast<Index>(rows_.size()) != model.num_dofs()) {
    throw std::invalid_argument("rows: has " + std::to_string(rows_.size()) +
                                " entries, must have one per DOF (" +
                                std::to_string(model.num_dofs()) + ")");
  }
  for (Index r : rows_) size_ = std::max(size_, r + 1);

  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(36 * model.bars().size() + 144 * model.hinges().size() + size_);
  for (const auto& bar : model.bars()) add_pattern(element_dofs(bar.nodes), rows_, storage_, entries);
  for (const auto& h : model.hinges()) add_pattern(element_dofs(h.nodes), rows_, storage_, entries);
  for (const auto& c : model.cables()) {
    cable_dofs_.push_back(cable_dofs(c.nodes));
    add_pattern(cable_dofs_.back(), rows_, storage_, entries);
  }
  for (Index i = 0; i < size_; ++i) entries.emplace_back(i, i, 0.0);
  matrix_.resize(size_, size_);
  matrix_.setFromTriplets(entries.begin(), entries.end());
  matrix_.makeCompressed();

  bar_offsets_.push_back(0);
  for (const auto& bar : model.bars()) {
    add_slots(element_dofs(bar.nodes), rows_, storage_, matrix_, bar_entries_, bar_offsets_);
  }
  hinge_offsets_.push_back(0);
  for (const auto& h : model.hinges()) {
    add_slots(element_dofs(h.nodes), rows_, storage_, matrix_, hinge_entries_, hinge_offsets_);
  }
  cable_offsets_.push_back(0);
  for (const auto& dofs : cable_dofs_) {
    add_slots(dofs, rows_, storage_, matrix_, cable_entries_, cable_offsets_);
  }
  for (Index i = 0; i < size_; ++i) diagonal_slots_.push_back(find_slot(matrix_, i, i));
  connectivity_ = connectivity_of(model);
}

bool Workspace::fits(const model::Model& model) const {
  // Compared in place, element by element (no copy of the model's connectivity): cheap
  // beside one evaluation of the elements.
  const std::vector<Index>& c = connectivity_;
  std::size_t k = 0;
  auto next = [&](Index v) { return k < c.size() && c[k++] == v; };
  if (!next(model.num_nodes())) return false;
  for (const auto& b : model.bars()) {
    for (Index node : b.nodes) if (!next(node)) return false;
  }
  for (const auto& h : model.hinges()) {
    for (Index node : h.nodes) if (!next(node)) return false;
  }
  if (!next(static_cast<Index>(model.bars().size()))) return false;
  for (const auto& cable : model.cables()) {
    if (!next(static_cast<Index>(cable.nodes.size()))) return false;
    for (Index node : cable.nodes) if (!next(node)) return false;
  }
  return k == c.size();
}

void Workspace::require_fits(const model::Model& model) const {
  if (fits(model)) return;
  const std::string built =
      std::to_string(connectivity_.empty() ? 0 : connectivity_.front()) + " nodes";
  throw std::invalid_argument(
      "workspace: was built for a model of another connectivity (" + built + ") than this "
      "model's (" + std::to_string(model.num_nodes()) + " nodes, " +
      std::to_string(model.bars().size()) + " bars, " + std::to_string(model.hinges().size()) +
      " hinges, " + std::to_string(model.cables().size()) +
      " cables): a workspace serves models with the same nodes count and elements, node for "
      "node, in order; build one for this model");
}

Energies assemble(const model::Model& model, Workspace& workspace, const VectorX& u,
                  VectorX& force, bool with_matrix) {
  workspace.require_fits(model);
  return assemble_unchecked(model, workspace, u, force, with_matrix);
}

Energies assemble_unchecked(const model::Model& model, Workspace& w, const VectorX& u,
                            VectorX& force, bool with_matrix) {
  if (u.size() != model.num_dofs()) {
    throw std::invalid_argument("u: has " + std::to_string(u.size()) + " entries, must have " +
                                std::to_string(model.num_dofs()));
  }
  const NodeMatrix& X = model.nodes();
  auto position = [&](Index node) -> Vector3 {
    return X.row(node).transpose() + u.segment<3>(3 * node);
  };
  force.setZero(model.num_dofs());
  double* values = w.matrix_.valuePtr();
  if (with_matrix) std::fill(values, values + w.matrix_.nonZeros(), 0.0);

  Energies energies;
  const auto& bars = model.bars();
  for (std::size_t e = 0; e < bars.size(); ++e) {
    const auto& bar = bars[e];
    const auto r = elements::bar_response(position(bar.nodes[0]), position(bar.nodes[1]),
                                          bar.area, bar.rest_length, bar.law, with_matrix);
    energies.bars += r.energy;
    add_force<6>(r.force, element_dofs(bar.nodes), force);
    if (with_matrix) {
      scatter<6>(r.stiffness, w.bar_entries_.data() + w.bar_offsets_[e],
                 w.bar_entries_.data() + w.bar_offsets_[e + 1], values);
    }
  }
  const auto& hinges = model.hinges();
  for (std::size_t e = 0; e < hinges.size(); ++e) {
    const auto& h = hinges[e];
    if (h.stiffness == 0.0) continue;  // every spring law vanishes with kp (cut creases)
    const auto r = elements::hinge_response(position(h.nodes[0]), position(h.nodes[1]),
                                            position(h.nodes[2]), position(h.nodes[3]),
                                            h.stiffness, h.rest_angle, h.length, h.law,
                                            with_matrix);
    energies.hinges += r.energy;
    add_force<12>(r.force, element_dofs(h.nodes), force);
    if (with_matrix) {
      scatter<12>(r.stiffness, w.hinge_entries_.data() + w.hinge_offsets_[e],
                  w.hinge_entries_.data() + w.hinge_offsets_[e + 1], values);
    }
  }
  const auto& cables = model.cables();
  for (std::size_t e = 0; e < cables.size(); ++e) {
    const auto& c = cables[e];
    elements::CablePoints x(static_cast<Index>(c.nodes.size()), 3);
    for (std::size_t i = 0; i < c.nodes.size(); ++i) x.row(static_cast<Index>(i)) = position(c.nodes[i]);
    const auto r = elements::cable_response(x, c.stiffness, c.rest_length, with_matrix);
    if (!r.taut) continue;  // slack: no energy, force or stiffness
    energies.cables += r.energy;
    const auto& dofs = w.cable_dofs_[e];
    for (std::size_t a = 0; a < dofs.size(); ++a) force[dofs[a]] += r.force[static_cast<Index>(a)];
    if (with_matrix) {
      const double* k = r.stiffness.data();
      for (const ScatterEntry* s = w.cable_entries_.data() + w.cable_offsets_[e];
           s != w.cable_entries_.data() + w.cable_offsets_[e + 1]; ++s) {
        values[s->slot] += 0.5 * (k[s->local] + k[s->transposed]);
      }
    }
  }
  if (with_matrix) {
    for (int slot : w.diagonal_slots_) values[slot] += w.shift_;
  }
  return energies;
}

}  // namespace kresling::assembly
