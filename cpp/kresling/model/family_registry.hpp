#pragma once
/// \file family_registry.hpp
/// The element families a model can hold, by name: how a model is built from tables (the
/// Python binding, problem files) without naming any family in the code that builds it.

#include <string>
#include <vector>

#include "kresling/model/element_family.hpp"

namespace kresling::model {

struct FamilyKind {
  const char* name;                     ///< as ElementFamily::name() says it ("bars")
  FamilyPtr (*from_table)(const Table&);
  const char* description;              ///< one line, for documentation and messages
};

/// Every registered family, in the order a model holds them: the order of the assembly
/// loop (so of the floating-point sums), of energies and of element states.
const std::vector<FamilyKind>& family_kinds();

/// The registered family `name`; throws std::invalid_argument listing the registered ones.
const FamilyKind& family_kind(const std::string& name);

}  // namespace kresling::model
