// kresling._core.elements: what kresling/elements/bar_laws.hpp declares.
#include "elements/elements_bindings.hpp"
#include "kresling/elements/bar_laws.hpp"

namespace kresling::python {

void bind_bar_laws(py::module_& m) {
  // The law kinds, named as the Python API names them (kresling.laws derives its tables
  // from these: the names and codes are declared here once).
  py::enum_<BarLawKind>(m, "BarLawKind")
      .value("linear", BarLawKind::Linear)
      .value("ogden", BarLawKind::Ogden);
}

}  // namespace kresling::python
