// kresling._core.elements: what kresling/elements/bar.hpp declares.
#include "elements/elements_bindings.hpp"
#include "kresling/elements/bar.hpp"

namespace kresling::python {

void bind_bar(py::module_& m) {
  m.def(
      "bar_response",
      [](const Vector3& x1, const Vector3& x2, double area, double rest_length, int law,
         double modulus) {
        const auto r = bar_response(x1, x2, area, rest_length,
                                    BarLaw{bar_law_kind(law, "law"), modulus}, true);
        return py::make_tuple(r.energy, r.force, r.stiffness);
      },
      py::arg("x1"), py::arg("x2"), py::arg("area"), py::arg("rest_length"), py::arg("law"),
      py::arg("modulus"));
}

}  // namespace kresling::python
