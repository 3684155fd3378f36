#include "kresling/assembly/workspace.hpp"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <stdexcept>
#include <string>

namespace kresling::assembly {

namespace {

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

void add_pattern(const std::vector<Index>& dofs, const std::vector<Index>& rows, Storage storage,
                 std::vector<Eigen::Triplet<double, int>>& entries) {
  for (Index a : dofs) {
    for (Index b : dofs) {
      if (stored(rows[a], rows[b], storage)) entries.emplace_back(rows[a], rows[b], 0.0);
    }
  }
}

void add_slots(const std::vector<Index>& dofs, const std::vector<Index>& rows, Storage storage,
               const SparseMatrix& m, model::FamilySlots& slots) {
  // Only the entries the matrix stores: a compact list instead of a branch per entry of
  // the element matrix (half of which the lower-triangle storage skips).
  const std::size_t D = dofs.size();
  for (std::size_t b = 0; b < D; ++b) {
    for (std::size_t a = 0; a < D; ++a) {
      if (stored(rows[dofs[a]], rows[dofs[b]], storage)) {
        slots.entries.push_back({find_slot(m, rows[dofs[a]], rows[dofs[b]]),
                                 static_cast<std::uint16_t>(b * D + a),
                                 static_cast<std::uint16_t>(a * D + b)});
      }
    }
  }
  slots.offsets.push_back(static_cast<int>(slots.entries.size()));
}

// The node count, then per family its name's length and characters, its size and each
// element's DOF count and DOFs: what two models must share for one workspace to serve both.
std::vector<Index> connectivity_of(const model::Model& model) {
  std::vector<Index> c{model.num_nodes()};
  for (const auto& family : model.families()) {
    const std::string name = family->name();
    c.push_back(static_cast<Index>(name.size()));
    c.insert(c.end(), name.begin(), name.end());
    c.push_back(static_cast<Index>(family->size()));
    for (std::size_t e = 0; e < family->size(); ++e) {
      const std::vector<Index> dofs = family->element_dofs(e);
      c.push_back(static_cast<Index>(dofs.size()));
      c.insert(c.end(), dofs.begin(), dofs.end());
    }
  }
  return c;
}

// Whether every element of `now` (nodes and kind) is one of `built`'s.
bool holds_all(const model::ActiveElements& built, const model::ActiveElements& now) {
  if (now.size() == 0) return true;
  if (built.width != now.width) return false;
  const int w = built.width;
  auto key = [w](const model::ActiveElements& a, std::size_t e) {
    std::vector<Index> k(a.nodes.begin() + static_cast<std::ptrdiff_t>(e) * w,
                         a.nodes.begin() + static_cast<std::ptrdiff_t>(e + 1) * w);
    k.push_back(a.kinds[e]);
    return k;
  };
  std::vector<std::vector<Index>> keys(built.size());
  for (std::size_t e = 0; e < built.size(); ++e) keys[e] = key(built, e);
  std::sort(keys.begin(), keys.end());
  for (std::size_t e = 0; e < now.size(); ++e) {
    if (!std::binary_search(keys.begin(), keys.end(), key(now, e))) return false;
  }
  return true;
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
  if (model.families().size() > kMaxFamilies) {
    throw std::invalid_argument("model: holds " + std::to_string(model.families().size()) +
                                " element families, at most " + std::to_string(kMaxFamilies) +
                                " are assembled");
  }
  for (Index r : rows_) size_ = std::max(size_, r + 1);
  active_.resize(model.families().size());
  for (std::size_t f = 0; f < model.families().size(); ++f) {
    if (!model.families()[f]->changes_elements()) continue;
    changing_.push_back(f);
    model.families()[f]->active_elements(model.nodes(), VectorX::Zero(model.num_dofs()),
                                         active_[f]);
  }
  build_pattern(model);
  connectivity_ = connectivity_of(model);
}

void Workspace::build_pattern(const model::Model& model) {
  static std::atomic<std::uint64_t> patterns{0};
  // Every element's DOFs, family by family (asked once: a family may compute them).
  std::vector<std::vector<std::vector<Index>>> dofs(model.families().size());
  std::size_t count = static_cast<std::size_t>(size_);
  for (std::size_t f = 0; f < dofs.size(); ++f) {
    const auto& family = *model.families()[f];
    for (std::size_t e = 0; e < family.size(); ++e) {
      dofs[f].push_back(family.element_dofs(e));
      count += dofs[f].back().size() * dofs[f].back().size();
    }
    for (std::size_t e = 0; e < active_[f].size(); ++e) {
      dofs[f].push_back(active_[f].dofs(e));
      count += dofs[f].back().size() * dofs[f].back().size();
    }
  }
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(count);
  for (const auto& family : dofs) {
    for (const auto& element : family) add_pattern(element, rows_, storage_, entries);
  }
  for (Index i = 0; i < size_; ++i) entries.emplace_back(i, i, 0.0);
  matrix_.resize(size_, size_);
  matrix_.setFromTriplets(entries.begin(), entries.end());
  matrix_.makeCompressed();

  slots_.assign(dofs.size(), {});
  for (std::size_t f = 0; f < dofs.size(); ++f) {
    slots_[f].offsets.push_back(0);
    for (const auto& element : dofs[f]) add_slots(element, rows_, storage_, matrix_, slots_[f]);
  }
  diagonal_slots_.clear();
  for (Index i = 0; i < size_; ++i) diagonal_slots_.push_back(find_slot(matrix_, i, i));
  pattern_id_ = ++patterns;
}

void Workspace::update_active(const model::Model& model, const VectorX& u) {
  bool changed = false;
  model::ActiveElements now;
  for (std::size_t f : changing_) {
    model.families()[f]->active_elements(model.nodes(), u, now);
    // The pattern's elements may stay while they hold every active one and are not many
    // more: those no longer active add zeros (a pair beyond d_hat has no energy), and the
    // pattern and its symbolic analysis are not redone at each pair that comes and goes.
    if (holds_all(active_[f], now) && active_[f].size() <= 2 * now.size() + 16) continue;
    std::swap(active_[f], now);
    changed = true;
  }
  if (changed) build_pattern(model);
}

bool Workspace::fits(const model::Model& model) const {
  // Cheap beside one evaluation of the elements.
  return connectivity_of(model) == connectivity_;
}

void Workspace::require_fits(const model::Model& model) const {
  if (fits(model)) return;
  const std::string built =
      std::to_string(connectivity_.empty() ? 0 : connectivity_.front()) + " nodes";
  std::string elements;
  for (const auto& family : model.families()) {
    elements += ", " + std::to_string(family->size()) + " " + family->name();
  }
  throw std::invalid_argument(
      "workspace: was built for a model of another connectivity (" + built + ") than this "
      "model's (" + std::to_string(model.num_nodes()) + " nodes" + elements +
      "): a workspace serves models with the same nodes count and elements, node for "
      "node, in order; build one for this model");
}

void Workspace::add_to_diagonal(const VectorX& d) {
  if (d.size() != static_cast<Index>(rows_.size())) {
    throw std::invalid_argument("d: has " + std::to_string(d.size()) +
                                " entries, must have one per DOF (" +
                                std::to_string(rows_.size()) + ")");
  }
  double* values = matrix_.valuePtr();
  for (std::size_t dof = 0; dof < rows_.size(); ++dof) {
    if (rows_[dof] >= 0) values[diagonal_slots_[rows_[dof]]] += d[static_cast<Index>(dof)];
  }
}

void Workspace::scale_matrix(double factor) {
  double* values = matrix_.valuePtr();
  for (Index i = 0; i < matrix_.nonZeros(); ++i) values[i] *= factor;
}

void Workspace::add_matrix_values(const std::vector<double>& values, double factor) {
  if (static_cast<Index>(values.size()) != matrix_.nonZeros()) {
    throw std::invalid_argument("values: has " + std::to_string(values.size()) +
                                " entries, the tangent stores " +
                                std::to_string(matrix_.nonZeros()));
  }
  double* v = matrix_.valuePtr();
  for (std::size_t i = 0; i < values.size(); ++i) v[i] += factor * values[i];
}

Energies assemble(const model::Model& model, Workspace& workspace, const VectorX& u,
                  VectorX& force, bool with_matrix, bool definite) {
  workspace.require_fits(model);
  return assemble_unchecked(model, workspace, u, force, with_matrix, definite);
}

Energies assemble_unchecked(const model::Model& model, Workspace& w, const VectorX& u,
                            VectorX& force, bool with_matrix, bool definite) {
  if (u.size() != model.num_dofs()) {
    throw std::invalid_argument("u: has " + std::to_string(u.size()) + " entries, must have " +
                                std::to_string(model.num_dofs()));
  }
  force.setZero(model.num_dofs());
  if (with_matrix && !w.changing_.empty()) w.update_active(model, u);
  double* values = w.matrix_.valuePtr();
  if (with_matrix) std::fill(values, values + w.matrix_.nonZeros(), 0.0);

  Energies energies;
  const auto& families = model.families();
  energies.count = families.size();
  for (std::size_t f = 0; f < families.size(); ++f) {
    model::AssemblyTarget target{force, with_matrix ? values : nullptr, &w.slots_[f]};
    target.definite = definite;
    // Without a tangent the family finds its active elements itself (those of the pattern
    // may belong to another state).
    if (with_matrix && families[f]->changes_elements()) target.active = &w.active_[f];
    energies.values[f] = families[f]->assemble(model.nodes(), u, target);
  }
  if (with_matrix) {
    for (int slot : w.diagonal_slots_) values[slot] += w.shift_;
  }
  return energies;
}

}  // namespace kresling::assembly
