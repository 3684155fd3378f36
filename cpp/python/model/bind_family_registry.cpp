// kresling._core.model: what kresling/model/family_registry.hpp declares.
#include "model/model_bindings.hpp"
#include "kresling/model/family_registry.hpp"

namespace kresling::python {

void bind_family_registry(py::module_& m) {
  m.def("family_kinds", [] {
    std::vector<std::pair<std::string, std::string>> kinds;
    for (const auto& k : model::family_kinds()) kinds.emplace_back(k.name, k.description);
    return kinds;
  }, "the registered element families: (name, description), in assembly order");
}

}  // namespace kresling::python
