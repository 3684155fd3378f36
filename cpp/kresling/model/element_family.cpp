#include "kresling/model/element_family.hpp"

#include <cmath>
#include <cstddef>
#include <stdexcept>

#include "kresling/core/check.hpp"

namespace kresling::model {

const VectorX& ElementState::operator[](const std::string& name) const {
  for (const auto& [key, values] : columns) {
    if (key == name) return values;
  }
  throw std::invalid_argument("element state: no column " + name);
}

namespace {

// "bar 3 (nodes 1, 2)": a family's element as messages name it.
std::string named_element(const ElementFamily& family, std::size_t e, const std::vector<Index>& nodes) {
  std::string kind = family.name();
  if (!kind.empty() && kind.back() == 's') kind.pop_back();  // "bars" -> "bar"
  std::string s = kind + " " + std::to_string(e) + " (nodes";
  for (std::size_t k = 0; k < nodes.size(); ++k) s += (k ? ", " : " ") + std::to_string(nodes[k]);
  return s + ")";
}

}  // namespace

std::string ElementFamily::element_name(std::size_t e) const {
  std::vector<Index> nodes;
  const std::vector<Index> dofs = element_dofs(e);
  for (std::size_t k = 0; k < dofs.size(); k += 3) nodes.push_back(dofs[k] / 3);
  return named_element(*this, e, nodes);
}

std::vector<Index> ActiveElements::dofs(std::size_t e) const {
  const auto* first = nodes.data() + static_cast<std::ptrdiff_t>(e) * width;
  return node_dofs(std::vector<Index>(first, first + width));
}

std::vector<Index> node_dofs(const std::vector<Index>& nodes) {
  std::vector<Index> dofs(3 * nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    for (int k = 0; k < 3; ++k) dofs[3 * i + k] = 3 * nodes[i] + k;
  }
  return dofs;
}

void require_element_positive(const ElementFamily& family, std::size_t e, const char* what,
                              double value, bool allow_zero) {
  if (std::isfinite(value) && (allow_zero ? value >= 0.0 : value > 0.0)) return;
  require_positive(family.element_name(e) + ": " + what, value, allow_zero);
}

void require_element_nodes(const ElementFamily& family, std::size_t e, const Index* nodes,
                           int count, Index num_nodes) {
  // element_name builds on the element's DOFs, which are only meaningful once its nodes
  // are in range: name the raw nodes here.
  auto name = [&] { return named_element(family, e, std::vector<Index>(nodes, nodes + count)); };
  for (int k = 0; k < count; ++k) {
    if (nodes[k] < 0 || nodes[k] >= num_nodes) {
      throw std::invalid_argument(name() + ": node " + std::to_string(nodes[k]) +
                                  " is out of range [0, " + std::to_string(num_nodes) + ")");
    }
    for (int j = 0; j < k; ++j) {
      if (nodes[j] == nodes[k]) throw std::invalid_argument(name() + ": a node appears twice");
    }
  }
}

void ElementFamily::parameter_derivatives(const NodeMatrix& X, const VectorX& u,
                                          const std::vector<std::string>& names,
                                          std::vector<ParameterDerivative>& outs) const {
  outs.resize(names.size());
  for (std::size_t i = 0; i < names.size(); ++i) parameter_derivative(X, u, names[i], outs[i]);
}

void ElementFamily::parameter_derivative(const NodeMatrix& /*X*/, const VectorX& /*u*/,
                                         const std::string& name,
                                         ParameterDerivative& /*out*/) const {
  throw_unknown_parameter(*this, name);
}

void throw_unknown_parameter(const ElementFamily& family, const std::string& name) {
  const std::vector<std::string> known = family.parameters();
  std::string message = "element family '" + std::string(family.name()) + "' has no parameter '" +
                        name + "'";
  if (known.empty()) {
    message += ": it has none to differentiate by";
  } else {
    message += ": must be one of ";
    for (std::size_t i = 0; i < known.size(); ++i) message += (i ? ", " : "") + known[i];
  }
  throw std::invalid_argument(message);
}

}  // namespace kresling::model
