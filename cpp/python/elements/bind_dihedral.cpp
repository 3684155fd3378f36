// kresling._core.elements: what kresling/elements/dihedral.hpp declares.
#include "elements/elements_bindings.hpp"
#include "kresling/elements/dihedral.hpp"

namespace kresling::python {

void bind_dihedral(py::module_& m) {
  py::enum_<DihedralForm>(m, "DihedralForm")
      .value("exact", DihedralForm::Exact)
      .value("merlin2", DihedralForm::Merlin2);
  m.def(
      "dihedral_angle",
      [](const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d,
         DihedralForm form) { return dihedral_angle(a, b, c, d, form); },
      py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"),
      py::arg("form") = DihedralForm::Exact);
  m.def(
      "dihedral_angle_derivatives",
      [](const Vector3& a, const Vector3& b, const Vector3& c, const Vector3& d,
         DihedralForm form) {
        const auto r = dihedral_angle_derivatives(a, b, c, d, true, form);
        return py::make_tuple(r.angle, r.gradient, r.hessian);
      },
      py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"),
      py::arg("form") = DihedralForm::Exact);
  m.def(
      "dihedral_angles",
      [](const Eigen::Ref<const NodeMatrix>& x,
         py::array_t<Index, py::array::c_style | py::array::forcecast> hinges,
         DihedralForm form) {
        if (hinges.ndim() != 2 || hinges.shape(1) != 4) {
          throw std::invalid_argument("hinges: expected shape (n, 4)");
        }
        auto h = hinges.unchecked<2>();
        VectorX out(h.shape(0));
        const NodeMatrix X(x);
        const double scale = model::node_extent(X);  // once, not per hinge
        for (py::ssize_t i = 0; i < h.shape(0); ++i) {
          model::check_hinge_geometry_at_scale(X, {h(i, 0), h(i, 1), h(i, 2), h(i, 3)},
                                               static_cast<std::size_t>(i), scale);
          out[i] = dihedral_angle(x.row(h(i, 0)), x.row(h(i, 1)), x.row(h(i, 2)),
                                  x.row(h(i, 3)), form);
        }
        return out;
      },
      py::arg("nodes"), py::arg("hinges"), py::arg("form") = DihedralForm::Exact);
}

}  // namespace kresling::python
