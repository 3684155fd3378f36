#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "kresling/geometry/design.hpp"
#include "kresling/geometry/design_derivative.hpp"
#include "kresling/geometry/design_table.hpp"

namespace py = pybind11;
using kresling::geometry::Design;
using kresling::geometry::State;

namespace kresling::python {

namespace {

// Apply a scalar member of Design elementwise to an array of twists.
template <typename F>
py::array_t<double> map_alpha(const Design& design, py::array_t<double, py::array::forcecast> alpha,
                              F f) {
  py::buffer_info in = alpha.request();
  py::array_t<double> out(in.shape);
  const auto* a = static_cast<const double*>(in.ptr);
  auto* o = static_cast<double*>(out.request().ptr);
  for (py::ssize_t i = 0; i < in.size; ++i) o[i] = (design.*f)(a[i]);
  return out;
}

State to_state(int state) {
  if (state != 0 && state != 1) {
    throw std::invalid_argument("state = " + std::to_string(state) +
                                " is invalid: must be 0 (contracted) or 1 (extended)");
  }
  return static_cast<State>(state);
}

}  // namespace

void bind_geometry(py::module_& m) {
  py::class_<Design>(m, "Design")
      .def(py::init<int, double, double, double, int>(), py::arg("n"), py::arg("R"),
           py::arg("lam"), py::arg("Lc"), py::arg("chirality") = 1)
      .def_property_readonly("n", [](const Design& d) { return d.parameters().n; })
      .def_property_readonly("R", [](const Design& d) { return d.parameters().R; })
      .def_property_readonly("lam", [](const Design& d) { return d.parameters().lam; })
      .def_property_readonly("Lc", [](const Design& d) { return d.parameters().Lc; })
      .def_property_readonly("chirality", [](const Design& d) { return d.parameters().chirality; })
      .def("derived",
           [](const Design& d) {
             const auto values = kresling::geometry::derived_as_array(d.derived());
             py::dict out;
             for (std::size_t k = 0; k < values.size(); ++k) {
               out[kresling::geometry::kDerivedNames[k]] = values[k];
             }
             return out;
           })
      .def("twist", [](const Design& d, int state) { return d.twist(to_state(state)); })
      .def("height", [](const Design& d, int state) { return d.height(to_state(state)); })
      .def("height_at", [](const Design& d, py::array_t<double, py::array::forcecast> a) {
        return map_alpha(d, a, &Design::height_at);
      })
      .def("mountain_length_at", [](const Design& d, py::array_t<double, py::array::forcecast> a) {
        return map_alpha(d, a, &Design::mountain_length_at);
      })
      .def("facet_angle_at", [](const Design& d, py::array_t<double, py::array::forcecast> a) {
        return map_alpha(d, a, &Design::facet_angle_at);
      });

  m.def(
      "state_derivative",
      [](const Design& design, int state, const std::string& variable) {
        if (state != 0 && state != 1) {
          throw std::invalid_argument("state = " + std::to_string(state) +
                                      " is invalid: must be 0 (contracted) or 1 (extended)");
        }
        const auto d = kresling::geometry::state_derivative(
            design, static_cast<kresling::geometry::State>(state),
            kresling::geometry::design_variable(variable));
        return py::make_tuple(d.height, d.twist);
      },
      py::arg("design"), py::arg("state"), py::arg("variable"),
      "(d height/dv [mm per unit], d twist/dv [rad per unit]) of a stable state by lam, Lc or R");

  py::tuple names(kresling::geometry::kDerivedNames.size());
  for (std::size_t k = 0; k < kresling::geometry::kDerivedNames.size(); ++k) {
    names[k] = kresling::geometry::kDerivedNames[k];
  }
  m.attr("DERIVED_NAMES") = names;

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
