#include "kresling/assembly/assembler.hpp"


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
  ElementState state;
  for (const auto& family : model.families()) family->add_state(x, state);
  return state;
}

VectorX energy_rates(const model::Model& model, const VectorX& u, const VectorX& v) {
  const auto& families = model.families();
  VectorX rates(static_cast<Index>(families.size()));
  VectorX force;
  for (std::size_t f = 0; f < families.size(); ++f) {
    force.setZero(model.num_dofs());
    model::AssemblyTarget target{force};
    families[f]->assemble(model.nodes(), u, target);
    rates[static_cast<Index>(f)] = force.dot(v);
  }
  return rates;
}

}  // namespace kresling::assembly
