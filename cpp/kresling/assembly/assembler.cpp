#include "kresling/assembly/assembler.hpp"

#include <cmath>
#include <stdexcept>

#include "kresling/elements/bar.hpp"
#include "kresling/elements/cable.hpp"
#include "kresling/elements/dihedral.hpp"
#include "kresling/elements/hinge.hpp"

namespace kresling::assembly {

Assembler::Assembler(const model::Model& model, Workspace& workspace)
    : model_(&model), workspace_(&workspace) {
  workspace.require_fits(model);
}

Assembler::Assembler(const model::Model& model, std::vector<Index> rows, double shift,
                     Storage storage)
    : model_(&model),
      owned_(std::make_unique<Workspace>(model, std::move(rows), shift, storage)),
      workspace_(owned_.get()) {}

void Assembler::rebind(const model::Model& model) {
  workspace_->require_fits(model);
  model_ = &model;
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
