// kresling._core.geometry: what kresling/geometry/design.hpp declares.
#include "geometry/geometry_bindings.hpp"
#include "kresling/geometry/design.hpp"

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

void bind_design(py::module_& m) {
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

  py::tuple names(kresling::geometry::kDerivedNames.size());
  for (std::size_t k = 0; k < kresling::geometry::kDerivedNames.size(); ++k) {
    names[k] = kresling::geometry::kDerivedNames[k];
  }
  m.attr("DERIVED_NAMES") = names;
}

}  // namespace kresling::python
