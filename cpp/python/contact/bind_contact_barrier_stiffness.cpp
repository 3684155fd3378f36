// kresling._core.contact: what kresling/contact/contact_barrier_stiffness.hpp declares.
#include "contact/contact_bindings.hpp"
#include "kresling/contact/contact_barrier_stiffness.hpp"

namespace kresling::python {

void bind_contact_barrier_stiffness(py::module_& m) {
  m.def(
      "initial_barrier_stiffness",
      [](double bbox_diagonal, double d_hat, double average_mass, const VectorX& energy_gradient,
         const VectorX& barrier_gradient, double min_stiffness_scale) {
        const auto k = initial_barrier_stiffness(bbox_diagonal, d_hat, average_mass,
                                                 energy_gradient, barrier_gradient,
                                                 min_stiffness_scale);
        return py::make_tuple(k.stiffness, k.min_stiffness, k.max_stiffness);
      },
      py::arg("bbox_diagonal"), py::arg("d_hat"), py::arg("average_mass"),
      py::arg("energy_gradient"), py::arg("barrier_gradient"),
      py::arg("min_stiffness_scale") = 1e11);
}

}  // namespace kresling::python
