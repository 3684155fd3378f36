// kresling._core.elements: what kresling/elements/corner_angle.hpp declares.
#include "elements/elements_bindings.hpp"
#include "kresling/elements/corner_angle.hpp"

namespace kresling::python {

void bind_corner_angle(py::module_& m) {
  m.def(
      "triangle_angles",
      [](const Eigen::Ref<const NodeMatrix>& x,
         py::array_t<Index, py::array::c_style | py::array::forcecast> triangles) {
        if (triangles.ndim() != 2 || triangles.shape(1) != 3) {
          throw std::invalid_argument("triangles: expected shape (n, 3)");
        }
        auto t = triangles.unchecked<2>();
        NodeMatrix out(t.shape(0), 3);
        for (py::ssize_t i = 0; i < t.shape(0); ++i) {
          for (int k = 0; k < 3; ++k) {
            if (t(i, k) < 0 || t(i, k) >= x.rows()) {
              throw std::invalid_argument("triangles[" + std::to_string(i) + "]: node " +
                                          std::to_string(t(i, k)) + " is out of range [0, " +
                                          std::to_string(x.rows()) + ")");
            }
          }
          const auto a = corner_angles(x.row(t(i, 0)), x.row(t(i, 1)), x.row(t(i, 2)));
          out.row(i) << a[0], a[1], a[2];
        }
        return out;
      },
      py::arg("nodes"), py::arg("triangles"),
      "Interior angles [rad] of triangles (n, 3) of nodes (N, 3): (n, 3), at each corner");
}

}  // namespace kresling::python
