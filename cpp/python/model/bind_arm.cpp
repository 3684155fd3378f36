// kresling._core.model: what kresling/model/arm.hpp declares.
#include "model/model_bindings.hpp"
#include "kresling/model/arm.hpp"
#include "kresling/model/kresling_specimen.hpp"

namespace kresling::python {

namespace {

// The manipulator as one structure (model/arm.hpp): modules, guide plates, tendons.
void bind_arm_model(py::module_& m) {
  using model::Arm;
  using model::ArmParameters;
  py::class_<ArmParameters>(m, "ArmParameters")
      .def(py::init<>())
      .def_readwrite("specimen", &ArmParameters::specimen)
      .def_readwrite("tendon_radius", &ArmParameters::tendon_radius)
      .def_readwrite("guide_radius", &ArmParameters::guide_radius)
      .def_readwrite("guide_factor", &ArmParameters::guide_factor)
      .def_readwrite("tendon_stiffness", &ArmParameters::tendon_stiffness)
      .def_readwrite("contact_distance", &ArmParameters::contact_distance)
      .def_readwrite("contact_stiffness", &ArmParameters::contact_stiffness);

  py::class_<Arm>(m, "Arm")
      .def_readonly("model", &Arm::model)
      .def_readonly("n", &Arm::n)
      .def_readonly("modules", &Arm::modules)
      .def_readonly("states", &Arm::states)
      .def_readonly("cell_states", &Arm::cell_states)
      .def_readonly("chirality", &Arm::chirality)
      .def_readonly("level_height", &Arm::level_height)
      .def_readonly("level_angle", &Arm::level_angle)
      .def_readonly("cell_bars", &Arm::cell_bars)
      .def_readonly("cell_hinges", &Arm::cell_hinges)
      .def_readonly("holes", &Arm::holes)
      .def_readonly("slack_length", &Arm::slack_length)
      .def_readonly("cell_extended", &Arm::cell_extended)
      .def_readonly("cell_contracted", &Arm::cell_contracted)
      .def_property_readonly("tip_node", &Arm::tip_node)
      .def("node", &Arm::node, py::arg("level"), py::arg("j"))
      .def("guide_level", &Arm::guide_level, py::arg("guide"));

  m.def("parse_configuration", &model::parse_configuration, py::arg("configuration"),
        py::arg("modules") = 0);
  m.def("build_arm", &model::build_arm, py::arg("design"), py::arg("states"),
        py::arg("parameters"));
}

}  // namespace

void bind_arm(py::module_& m) {
  bind_arm_model(m);
}

}  // namespace kresling::python
