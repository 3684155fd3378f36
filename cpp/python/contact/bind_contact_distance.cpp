// kresling._core.contact: what kresling/contact/contact_distance.hpp declares.
#include "contact/contact_bindings.hpp"
#include "kresling/contact/contact_distance.hpp"

namespace kresling::python {

void bind_contact_distance(py::module_& m) {
  m.def(
      "point_triangle_distance",
      [](const Vector3& p, const Vector3& t0, const Vector3& t1, const Vector3& t2) {
        require_finite_points({{"p", &p}, {"t0", &t0}, {"t1", &t1}, {"t2", &t2}});
        const auto d = point_triangle_distance(p, t0, t1, t2);
        return py::make_tuple(d.value, d.gradient, d.hessian,
                              static_cast<int>(point_triangle_distance_type(p, t0, t1, t2)));
      },
      py::arg("p"), py::arg("t0"), py::arg("t1"), py::arg("t2"));
  m.def(
      "edge_edge_distance",
      [](const Vector3& ea0, const Vector3& ea1, const Vector3& eb0, const Vector3& eb1) {
        require_finite_points({{"ea0", &ea0}, {"ea1", &ea1}, {"eb0", &eb0}, {"eb1", &eb1}});
        const auto d = edge_edge_distance(ea0, ea1, eb0, eb1);
        return py::make_tuple(d.value, d.gradient, d.hessian,
                              static_cast<int>(edge_edge_distance_type(ea0, ea1, eb0, eb1)));
      },
      py::arg("ea0"), py::arg("ea1"), py::arg("eb0"), py::arg("eb1"));
}

}  // namespace kresling::python
