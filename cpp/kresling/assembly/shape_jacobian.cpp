#include "kresling/assembly/shape_jacobian.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "kresling/assembly/assembler.hpp"
#include "kresling/assembly/parameter_jacobian.hpp"

namespace kresling::assembly {

SparseMatrix reference_geometry_jacobian(const model::Model& model, const std::string& family,
                                         const std::string& column) {
  const model::ElementFamily* f = model.family(family);
  if (f == nullptr) {
    throw std::invalid_argument("the model has no element family '" + family + "'");
  }
  const std::vector<std::string> columns = f->parameters();
  if (std::find(columns.begin(), columns.end(), column) == columns.end()) {
    model::throw_unknown_parameter(*f, column);
  }
  std::vector<model::ParameterDerivative::Triplet> triplets;
  f->reference_geometry_derivative(model.nodes(), column, triplets);
  SparseMatrix R(static_cast<Index>(f->table().at(column).size()), model.num_dofs());
  R.setFromTriplets(triplets.begin(), triplets.end());
  return R;
}

ShapeJacobian shape_jacobian(const model::Model& model, const VectorX& u) {
  const Index n = model.num_dofs();
  if (u.size() != n) {
    throw std::invalid_argument("u has " + std::to_string(u.size()) + " entries: must have " +
                                std::to_string(n) + " (3 per node)");
  }
  ShapeJacobian j;
  // x = X + u: at fixed u the positions move with X, through the unshifted tangent.
  Assembler assembler(model, all_dofs(n), /*shift=*/0.0);
  assembler.assemble(u, j.energy, /*with_matrix=*/true);  // j.energy = f_int(u) so far
  j.force = assembler.matrix();
  for (const auto& family : model.families()) {
    for (const std::string& column : family->parameters()) {
      const SparseMatrix R = reference_geometry_jacobian(model, family->name(), column);
      if (R.nonZeros() == 0) continue;
      const ParameterJacobian g = parameter_jacobian(model, u, family->name(), column);
      j.force += g.force * R;
      j.energy += R.transpose() * g.energy;
    }
  }
  return j;
}

}  // namespace kresling::assembly
