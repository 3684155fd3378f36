// kresling._core.geometry: what kresling/geometry/design_table.hpp declares.
#include "geometry/geometry_bindings.hpp"
#include "kresling/geometry/design.hpp"
#include "kresling/geometry/design_table.hpp"

namespace kresling::python {

void bind_design_table(py::module_& m) {
  m.def(
      "derive_table",
      [](py::array_t<int, py::array::c_style | py::array::forcecast> n,
         py::array_t<double, py::array::c_style | py::array::forcecast> R,
         py::array_t<double, py::array::c_style | py::array::forcecast> lam,
         py::array_t<double, py::array::c_style | py::array::forcecast> Lc) {
        const py::ssize_t count = n.size();
        if (R.size() != count || lam.size() != count || Lc.size() != count) {
          throw std::invalid_argument("derive_table: n, R, lam and Lc must have equal sizes");
        }
        const auto width = static_cast<py::ssize_t>(kresling::geometry::kDerivedNames.size());
        py::array_t<double> out({count, width});
        const int* pn = n.data();
        const double *pR = R.data(), *plam = lam.data(), *pLc = Lc.data();
        double* po = out.mutable_data();
        {
          py::gil_scoped_release release;
          kresling::geometry::derive_table(pn, pR, plam, pLc, static_cast<std::size_t>(count),
                                           po);
        }
        return out;
      },
      py::arg("n"), py::arg("R"), py::arg("lam"), py::arg("Lc"),
      "Derived quantities of many designs: 1-D inputs of equal length -> (count, "
      "len(DERIVED_NAMES)) array.");
}

}  // namespace kresling::python
