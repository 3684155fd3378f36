// kresling._core.model: what kresling/model/calibration.hpp declares.
#include "model/model_bindings.hpp"
#include "kresling/model/calibration.hpp"

namespace kresling::python {

void bind_calibration(py::module_& m) {
  py::class_<model::SheetMaterial>(m, "SheetMaterial")
      .def(py::init<>())
      .def_readwrite("youngs_modulus", &model::SheetMaterial::youngs_modulus)
      .def_readwrite("poisson_ratio", &model::SheetMaterial::poisson_ratio)
      .def_readwrite("thickness", &model::SheetMaterial::thickness)
      .def_readwrite("length_scale", &model::SheetMaterial::length_scale);

  py::class_<model::SheetStiffness>(m, "SheetStiffness")
      .def_property_readonly("bar_area",
                             [](const model::SheetStiffness& s) { return vector_array(s.bar_area); })
      .def_property_readonly("fold_stiffness",
                             [](const model::SheetStiffness& s) { return vector_array(s.fold_stiffness); })
      .def_property_readonly("bend_stiffness",
                             [](const model::SheetStiffness& s) { return vector_array(s.bend_stiffness); })
      .def_readonly("length_scale", &model::SheetStiffness::length_scale);

  m.def("calibrate_sheet", &model::calibrate_sheet, py::arg("elements"), py::arg("panels"),
        py::arg("material"), py::arg("merlin2_compat"));
}

}  // namespace kresling::python
