#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "kresling/analyses/bending_test.hpp"
#include "kresling/analyses/snap_through.hpp"
#include "kresling/model/kresling_specimen.hpp"

namespace py = pybind11;
using kresling::geometry::Design;
using kresling::model::SpecimenParameters;

namespace kresling::python {

namespace {

std::vector<int> families(const std::vector<model::EdgeFamily>& f) {
  std::vector<int> out(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) out[i] = static_cast<int>(f[i]);
  return out;
}

// A copy of `v` as a numpy array (the Python side owns its arrays).
template <typename T>
py::array_t<T> array(const std::vector<T>& v) {
  return py::array_t<T>(v.size(), v.data());
}

py::dict bending_result_dict(const analyses::BendingResult& r) {
  py::dict out;
  out["stiffness"] = r.stiffness;
  out["stiffness_intercept"] = r.stiffness_intercept;
  out["intercept"] = r.intercept;
  out["module_length"] = r.module_length;
  out["deflection"] = array(r.deflection);
  out["force"] = array(r.force);
  out["angle"] = array(r.angle);
  out["moment"] = array(r.moment);
  out["iterations"] = array(r.iterations);
  out["negative_eigenvalues"] = array(r.negative_eigenvalues);
  out["final_displacement"] =
      py::array_t<double>(r.final_displacement.size(), r.final_displacement.data());
  out["completed"] = r.completed;
  out["message"] = r.message;
  out["num_dofs"] = r.num_dofs;
  out["num_free_dofs"] = r.num_free_dofs;
  return out;
}

py::dict snap_result_dict(const analyses::SnapThroughResult& r) {
  py::dict out;
  out["snap_force"] = r.snap_force;
  out["snap_displacement"] = r.snap_displacement;
  out["unstable_displacement"] = r.unstable_displacement;
  out["energy_barrier"] = r.energy_barrier;
  out["minimum_force"] = r.minimum_force;
  out["bistable"] = r.bistable;
  out["stable_displacement"] = r.stable_displacement;
  out["stable_height"] = r.stable_height;
  out["stable_energy"] = r.stable_energy;
  out["stable_tilt"] = r.stable_tilt;
  out["stable_negative_eigenvalues"] = r.stable_negative_eigenvalues;
  out["bistability"] = r.bistability;
  out["extended_height"] = r.extended_height;
  out["contracted_height"] = r.contracted_height;
  out["displacement"] = array(r.displacement);
  out["force"] = array(r.force);
  out["energy"] = array(r.energy);
  out["iterations"] = array(r.iterations);
  out["completed"] = r.completed;
  out["message"] = r.message;
  return out;
}

}  // namespace

void bind_analyses(py::module_& m) {
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
          [](SpecimenParameters& p, int law) {
            if (law != 0 && law != 1) throw std::invalid_argument("bar_law: unknown law code");
            p.bar_law = static_cast<elements::BarLawKind>(law);
          })
      .def_readwrite("duplicate_shared_edges", &SpecimenParameters::duplicate_shared_edges);

  m.def(
      "build_kresling_specimen",
      [](const Design& design, const std::vector<int>& states, const std::vector<int>& chirality,
         const SpecimenParameters& parameters, const std::vector<std::uint8_t>& fixed) {
        auto s = model::build_kresling_specimen(design, states, chirality, parameters, fixed);
        py::dict info;
        info["bar_family"] = families(s.bar_family);
        info["hinge_family"] = families(s.hinge_family);
        info["level_height"] = s.level_height;
        info["level_angle"] = s.level_angle;
        return py::make_tuple(std::move(s.model), info);
      },
      py::arg("design"), py::arg("states"), py::arg("chirality"), py::arg("parameters"),
      py::arg("fixed"));

  py::class_<analyses::BendingTest>(m, "BendingTest")
      .def(py::init([](int n, double deflection, double deflection_angle, int steps, int cells,
                       const SpecimenParameters& parameters,
                       const solvers::DisplacementControlOptions& solver) {
             analyses::BendingOptions o;
             o.deflection = deflection;
             o.deflection_angle = deflection_angle;
             o.steps = steps;
             o.cells = cells;
             o.specimen = parameters;
             o.solver = solver;
             return analyses::BendingTest(n, o);
           }),
           py::arg("n"), py::arg("deflection"), py::arg("deflection_angle"), py::arg("steps"),
           py::arg("cells"),
           py::arg("parameters"), py::arg("solver"))
      .def(
          "run",
          [](analyses::BendingTest& test, const Design& design, int state) {
            analyses::BendingResult r;
            {
              py::gil_scoped_release release;
              r = test.run(design, state);
            }
            return bending_result_dict(r);
          },
          py::arg("design"), py::arg("state"));

  m.def(
      "bending_drive",
      [](const Design& design, int state, int cells, double deflection, double deflection_angle,
         int steps) {
        analyses::BendingOptions o;
        o.deflection = deflection;
        o.deflection_angle = deflection_angle;
        o.steps = steps;
        o.cells = cells;
        return analyses::bending_drive(design, state, o);
      },
      py::arg("design"), py::arg("state"), py::arg("cells"), py::arg("deflection"),
      py::arg("deflection_angle"), py::arg("steps"),
      "The bending test's checks of its inputs; returns the imposed motion [mm].");
  m.attr("MAX_SPECIMEN_NODES") = model::kMaxSpecimenNodes;
  m.def("check_snap_design", &analyses::check_snap_design, py::arg("design"));
  m.def("check_bending_state", &analyses::check_bending_state, py::arg("design"),
        py::arg("state"));

  py::class_<analyses::SnapThroughTest>(m, "SnapThroughTest")
      .def(py::init([](int n, int steps, const SpecimenParameters& parameters,
                       const solvers::DisplacementControlOptions& solver) {
             analyses::SnapThroughOptions o;
             o.steps = steps;
             o.specimen = parameters;
             o.solver = solver;
             return analyses::SnapThroughTest(n, o);
           }),
           py::arg("n"), py::arg("steps"), py::arg("parameters"), py::arg("solver"))
      .def(
          "run",
          [](analyses::SnapThroughTest& test, const Design& design) {
            analyses::SnapThroughResult r;
            {
              py::gil_scoped_release release;
              r = test.run(design);
            }
            return snap_result_dict(r);
          },
          py::arg("design"));
}

}  // namespace kresling::python
