// kresling._core.model: what kresling/model/kresling_specimen.hpp declares.
#include "model/model_bindings.hpp"
#include "kresling/model/kresling_design_derivative.hpp"
#include "kresling/model/kresling_specimen.hpp"
#include "kresling/model/model.hpp"

namespace kresling::python {

namespace {

// Kresling specimens (model/kresling_specimen.hpp): their parameters, the built specimen.
void bind_specimen(py::module_& m) {
  using model::SpecimenParameters;
  // The element families of a specimen by their codes: kresling.model.EDGE_FAMILIES reads
  // its names from here.
  py::enum_<model::EdgeFamily>(m, "EdgeFamily", "What an edge of a Kresling specimen is")
      .value("valley", model::EdgeFamily::Valley)
      .value("mountain", model::EdgeFamily::Mountain)
      .value("polygon_edge", model::EdgeFamily::PolygonEdge)
      .value("polygon_spoke", model::EdgeFamily::PolygonSpoke);
  py::class_<SpecimenParameters>(m, "SpecimenParameters")
      .def(py::init<>())
      .def_readwrite("kf", &SpecimenParameters::kf)
      .def_readwrite("valley_factor", &SpecimenParameters::valley_factor)
      .def_readwrite("polygon_edge_factor", &SpecimenParameters::polygon_edge_factor)
      .def_readwrite("spoke_factor", &SpecimenParameters::spoke_factor)
      .def_readwrite("mountain_factor", &SpecimenParameters::mountain_factor)
      .def_readwrite("modulus_factor", &SpecimenParameters::modulus_factor)
      .def_readwrite("material_area", &SpecimenParameters::material_area)
      .def_readwrite("mountain_area", &SpecimenParameters::mountain_area)
      .def_readwrite("theta1", &SpecimenParameters::theta1)
      .def_readwrite("theta2", &SpecimenParameters::theta2)
      .def_property(
          "bar_law", [](const SpecimenParameters& p) { return static_cast<int>(p.bar_law); },
          [](SpecimenParameters& p, int law) { p.bar_law = elements::bar_law_kind(law, "bar_law"); })
      .def_readwrite("duplicate_shared_edges", &SpecimenParameters::duplicate_shared_edges)
      .def_readwrite("hinge_angle", &SpecimenParameters::hinge_angle);

  py::class_<model::KreslingSpecimen>(
      m, "KreslingSpecimen", "A Kresling stack's model with its element families and levels")
      .def_readonly("model", &model::KreslingSpecimen::model)
      .def_property_readonly(
          "bar_family", [](const model::KreslingSpecimen& s) { return families(s.bar_family); },
          "edge family code per bar (B,)")
      .def_property_readonly(
          "hinge_family", [](const model::KreslingSpecimen& s) { return families(s.hinge_family); },
          "edge family code of each hinge's axis (H,)")
      .def_readonly("level_height", &model::KreslingSpecimen::level_height, "z of each level [mm]")
      .def_readonly("level_angle", &model::KreslingSpecimen::level_angle,
                    "theta of each level [rad]")
      .def_readonly("n", &model::KreslingSpecimen::n)
      .def_readonly("cells", &model::KreslingSpecimen::cells);
}

// Building a specimen and its derivative by a design variable.
void bind_specimen_builders(py::module_& m) {
  using model::SpecimenParameters;
  m.def(
      "build_kresling_specimen",
      [](const geometry::Design& design, const std::vector<int>& states,
         const std::vector<int>& chirality, const SpecimenParameters& parameters,
         const std::vector<std::uint8_t>& fixed) {
        return model::build_kresling_specimen(design, states, chirality, parameters, fixed);
      },
      py::arg("design"), py::arg("states"), py::arg("chirality"), py::arg("parameters"),
      py::arg("fixed"));
  m.attr("MAX_SPECIMEN_NODES") = model::kMaxSpecimenNodes;
  m.def(
      "specimen_design_derivative",
      [](const model::KreslingSpecimen& specimen, const geometry::Design& design,
         const std::vector<int>& states, const std::vector<int>& chirality,
         const SpecimenParameters& parameters, const std::string& variable) {
        const model::SpecimenDesignDerivative d = model::specimen_design_derivative(
            specimen, design, states, chirality, parameters, variable);
        return py::make_tuple(d.positions, d.bar_area, d.bar_modulus, d.hinge_stiffness);
      },
      py::arg("specimen"), py::arg("design"), py::arg("states"), py::arg("chirality"),
      py::arg("parameters"), py::arg("variable"),
      "(dX/dv (3N), d area/dv (bars), d modulus/dv (bars), d stiffness/dv (hinges)) of a "
      "Kresling specimen by a design variable (lam, Lc, R, thickness, kf)");
  m.attr("FACET_THICKNESS") = model::kFacetThickness;
}

}  // namespace

void bind_kresling_specimen(py::module_& m) {
  bind_specimen(m);
  bind_specimen_builders(m);
}

}  // namespace kresling::python
