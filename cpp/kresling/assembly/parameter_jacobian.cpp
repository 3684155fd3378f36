#include "kresling/assembly/parameter_jacobian.hpp"

#include <stdexcept>

#include "kresling/core/check.hpp"

namespace kresling::assembly {

ParameterJacobian parameter_jacobian(const model::Model& model, const VectorX& u,
                                     const std::string& family, const std::string& parameter) {
  if (u.size() != model.num_dofs()) {
    throw std::invalid_argument("u has " + std::to_string(u.size()) + " entries: must have " +
                                std::to_string(model.num_dofs()) + " (3 per node)");
  }
  const model::ElementFamily* f = model.family(family);
  if (f == nullptr) {
    std::string known;
    for (const auto& g : model.families()) known += (known.empty() ? "" : ", ") + std::string(g->name());
    throw std::invalid_argument("the model has no element family '" + family +
                                "': it has " + (known.empty() ? "none" : known));
  }
  model::ParameterDerivative d;
  f->parameter_derivative(model.nodes(), u, parameter, d);
  ParameterJacobian j;
  j.force.resize(model.num_dofs(), d.energy.size());
  j.force.setFromTriplets(d.force.begin(), d.force.end());
  j.energy = std::move(d.energy);
  return j;
}

}  // namespace kresling::assembly
