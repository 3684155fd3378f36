#include "kresling/assembly/assembler.hpp"

#include <algorithm>
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

Assembler::Assembler(const model::Model& model, std::vector<Index> rows, double shift,
                     Storage storage)
    : model_(&model), rows_(std::move(rows)), shift_(shift), storage_(storage) {
  if (static_cast<Index>(rows_.size()) != model_->num_dofs()) {
    throw std::invalid_argument("rows: has " + std::to_string(rows_.size()) +
                                " entries, must have one per DOF (" +
                                std::to_string(model_->num_dofs()) + ")");
  }
  for (Index r : rows_) size_ = std::max(size_, r + 1);

  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(36 * model_->bars().size() + 144 * model_->hinges().size() + size_);
  for (const auto& bar : model_->bars()) add_pattern(element_dofs(bar.nodes), rows_, storage_, entries);
  for (const auto& h : model_->hinges()) add_pattern(element_dofs(h.nodes), rows_, storage_, entries);
  for (const auto& c : model_->cables()) {
    cable_dofs_.push_back(cable_dofs(c.nodes));
    add_pattern(cable_dofs_.back(), rows_, storage_, entries);
  }
  for (Index i = 0; i < size_; ++i) entries.emplace_back(i, i, 0.0);
  matrix_.resize(size_, size_);
  matrix_.setFromTriplets(entries.begin(), entries.end());
  matrix_.makeCompressed();

  bar_offsets_.push_back(0);
  for (const auto& bar : model_->bars()) {
    add_slots(element_dofs(bar.nodes), rows_, storage_, matrix_, bar_entries_, bar_offsets_);
  }
  hinge_offsets_.push_back(0);
  for (const auto& h : model_->hinges()) {
    add_slots(element_dofs(h.nodes), rows_, storage_, matrix_, hinge_entries_, hinge_offsets_);
  }
  cable_offsets_.push_back(0);
  for (const auto& dofs : cable_dofs_) {
    add_slots(dofs, rows_, storage_, matrix_, cable_entries_, cable_offsets_);
  }
  for (Index i = 0; i < size_; ++i) diagonal_slots_.push_back(find_slot(matrix_, i, i));
  connectivity_ = connectivity_of(*model_);
}

bool Assembler::same_connectivity(const model::Model& model) const {
  return connectivity_ == connectivity_of(model);
}

void Assembler::rebind(const model::Model& model) {
  if (!same_connectivity(model)) {
    throw std::invalid_argument("Assembler::rebind: the model's elements differ from the pattern's");
  }
  model_ = &model;
}

Energies Assembler::assemble(const VectorX& u, VectorX& force, bool with_matrix) {
  if (u.size() != model_->num_dofs()) {
    throw std::invalid_argument("u: has " + std::to_string(u.size()) + " entries, must have " +
                                std::to_string(model_->num_dofs()));
  }
  const NodeMatrix& X = model_->nodes();
  auto position = [&](Index node) -> Vector3 {
    return X.row(node).transpose() + u.segment<3>(3 * node);
  };
  force.setZero(model_->num_dofs());
  double* values = matrix_.valuePtr();
  if (with_matrix) std::fill(values, values + matrix_.nonZeros(), 0.0);

  Energies energies;
  const auto& bars = model_->bars();
  for (std::size_t e = 0; e < bars.size(); ++e) {
    const auto& bar = bars[e];
    const auto r = elements::bar_response(position(bar.nodes[0]), position(bar.nodes[1]),
                                          bar.area, bar.rest_length, bar.law, with_matrix);
    energies.bars += r.energy;
    add_force<6>(r.force, element_dofs(bar.nodes), force);
    if (with_matrix) {
      scatter<6>(r.stiffness, bar_entries_.data() + bar_offsets_[e],
                 bar_entries_.data() + bar_offsets_[e + 1], values);
    }
  }
  const auto& hinges = model_->hinges();
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
      scatter<12>(r.stiffness, hinge_entries_.data() + hinge_offsets_[e],
                  hinge_entries_.data() + hinge_offsets_[e + 1], values);
    }
  }
  const auto& cables = model_->cables();
  for (std::size_t e = 0; e < cables.size(); ++e) {
    const auto& c = cables[e];
    elements::CablePoints x(static_cast<Index>(c.nodes.size()), 3);
    for (std::size_t i = 0; i < c.nodes.size(); ++i) x.row(static_cast<Index>(i)) = position(c.nodes[i]);
    const auto r = elements::cable_response(x, c.stiffness, c.rest_length, with_matrix);
    if (!r.taut) continue;  // slack: no energy, force or stiffness
    energies.cables += r.energy;
    const auto& dofs = cable_dofs_[e];
    for (std::size_t a = 0; a < dofs.size(); ++a) force[dofs[a]] += r.force[static_cast<Index>(a)];
    if (with_matrix) {
      const double* k = r.stiffness.data();
      for (const ScatterEntry* s = cable_entries_.data() + cable_offsets_[e];
           s != cable_entries_.data() + cable_offsets_[e + 1]; ++s) {
        values[s->slot] += 0.5 * (k[s->local] + k[s->transposed]);
      }
    }
  }
  if (with_matrix) {
    for (int slot : diagonal_slots_) values[slot] += shift_;
  }
  return energies;
}

ElementState element_state(const model::Model& model, const VectorX& u) {
  const NodeMatrix x = model.deformed(u);
  ElementState s;
  const auto& bars = model.bars();
  s.bar_strain.resize(static_cast<Index>(bars.size()));
  s.bar_force.resize(static_cast<Index>(bars.size()));
  s.bar_stress.resize(static_cast<Index>(bars.size()));
  s.bar_energy.resize(static_cast<Index>(bars.size()));
  for (std::size_t e = 0; e < bars.size(); ++e) {
    const Vector3 x1 = x.row(bars[e].nodes[0]), x2 = x.row(bars[e].nodes[1]);
    const double L = bars[e].rest_length;
    const double strain = elements::bar_strain(x1, x2, L);
    const double stretch = (x2 - x1).norm() / L;
    s.bar_strain[e] = strain;
    // Axial (Cauchy-like) force: S is per reference area along the deformed direction.
    const elements::StressResponse r = bars[e].law.evaluate(strain, stretch);
    s.bar_force[e] = bars[e].area * r.stress * stretch;
    s.bar_stress[e] = r.stress;
    s.bar_energy[e] = bars[e].area * L * r.energy_density;
  }
  const auto& hinges = model.hinges();
  s.hinge_angle.resize(static_cast<Index>(hinges.size()));
  s.hinge_moment.resize(static_cast<Index>(hinges.size()));
  s.hinge_energy.resize(static_cast<Index>(hinges.size()));
  for (std::size_t e = 0; e < hinges.size(); ++e) {
    const auto& h = hinges[e];
    const double theta = elements::dihedral_angle(x.row(h.nodes[0]), x.row(h.nodes[1]),
                                                  x.row(h.nodes[2]), x.row(h.nodes[3]));
    s.hinge_angle[e] = theta;
    const elements::SpringResponse r = h.law.evaluate(theta, h.rest_angle, h.stiffness);
    s.hinge_moment[e] = h.length * r.moment;
    s.hinge_energy[e] = h.length * r.energy;
  }
  const auto& cables = model.cables();
  const auto nc = static_cast<Index>(cables.size());
  s.cable_length.resize(nc);
  s.cable_tension.resize(nc);
  s.cable_energy.resize(nc);
  for (Index e = 0; e < nc; ++e) {
    const auto& c = cables[e];
    elements::CablePoints p(static_cast<Index>(c.nodes.size()), 3);
    for (std::size_t i = 0; i < c.nodes.size(); ++i) p.row(static_cast<Index>(i)) = x.row(c.nodes[i]);
    const auto r = elements::cable_response(p, c.stiffness, c.rest_length, false);
    s.cable_length[e] = r.length;
    s.cable_tension[e] = r.tension;
    s.cable_energy[e] = r.energy;
  }
  return s;
}

}  // namespace kresling::assembly
