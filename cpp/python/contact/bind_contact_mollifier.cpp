// kresling._core.contact: what kresling/contact/contact_mollifier.hpp declares.
#include "contact/contact_bindings.hpp"
#include "kresling/contact/contact_mollifier.hpp"

namespace kresling::python {

void bind_contact_mollifier(py::module_& m) {
  m.def("edge_edge_mollifier_threshold", &edge_edge_mollifier_threshold, py::arg("ea0_rest"),
        py::arg("ea1_rest"), py::arg("eb0_rest"), py::arg("eb1_rest"));
}

}  // namespace kresling::python
