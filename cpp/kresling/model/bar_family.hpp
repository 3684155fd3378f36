#pragma once
/// \file bar_family.hpp
/// Axial bars between two nodes (kernel: elements/bar.hpp).

#include <array>
#include <string>
#include <vector>

#include "kresling/elements/bar_laws.hpp"
#include "kresling/model/element_family.hpp"

namespace kresling::model {

/// An axial bar between two nodes.
struct Bar {
  std::array<Index, 2> nodes{};
  double area = 1.0;         ///< cross-section A
  double rest_length = 0.0;  ///< L
  elements::BarLaw law;      ///< law and modulus C0 (axial stiffness EA = C0 A)
};

/// Table columns: nodes (2 per bar), area, rest_length, law (the BarLawKind's code),
/// modulus.
class BarFamily final : public ElementFamily {
 public:
  explicit BarFamily(std::vector<Bar> bars) : bars_(std::move(bars)) {}
  static FamilyPtr from_table(const Table& table);

  const std::vector<Bar>& elements() const { return bars_; }
  const char* name() const override { return "bars"; }
  std::size_t size() const override { return bars_.size(); }
  std::vector<Index> element_dofs(std::size_t e) const override;
  void check(const NodeMatrix& X, double scale) const override;
  double assemble(const NodeMatrix& X, const VectorX& u, AssemblyTarget& target) const override;
  void add_state(const NodeMatrix& x, ElementState& state) const override;
  Table table() const override;
  std::vector<std::string> parameters() const override;
  void parameter_derivative(const NodeMatrix& X, const VectorX& u, const std::string& name,
                            ParameterDerivative& out) const override;
  void parameter_derivatives(const NodeMatrix& X, const VectorX& u,
                             const std::vector<std::string>& names,
                             std::vector<ParameterDerivative>& outs) const override;
  void reference_geometry_derivative(const NodeMatrix& X, const std::string& name,
                                     std::vector<ParameterDerivative::Triplet>& out) const override;

 private:
  std::vector<Bar> bars_;
};

}  // namespace kresling::model
