#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "kresling/analyses/arm_analysis.hpp"
#include "kresling/analyses/bending_test.hpp"
#include "kresling/analyses/snap_through.hpp"
#include "kresling/model/kresling_specimen.hpp"

namespace py = pybind11;
using kresling::geometry::Design;
using kresling::model::SpecimenParameters;
using kresling::model::Arm;
using namespace kresling::analyses;

namespace kresling::python {

namespace {

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

// Every path-following call runs without the GIL (the interrupt check takes it back).
template <typename F>
auto unlocked(F&& f) {
  py::gil_scoped_release release;
  return f();
}

// The manipulator as one structure (analyses/arm_analysis.hpp): tip loads, pulls, capacity.
void bind_arm_analysis(py::module_& m) {
  py::class_<ArmOptions>(m, "ArmOptions")
      .def(py::init<>())
      .def_property(
          "tolerance", [](const ArmOptions& o) { return o.newton.tolerance; },
          [](ArmOptions& o, double v) { o.newton.tolerance = v; })
      .def_property(
          "max_iterations", [](const ArmOptions& o) { return o.newton.max_iterations; },
          [](ArmOptions& o, int v) { o.newton.max_iterations = v; })
      .def_readwrite("steps", &ArmOptions::steps)
      .def_readwrite("max_bisections", &ArmOptions::max_bisections)
      .def_readwrite("shift", &ArmOptions::shift);

  py::class_<ArmState>(m, "ArmState")
      .def_readonly("displacement", &ArmState::displacement)
      .def_readonly("pulls", &ArmState::pulls)
      .def_readonly("load", &ArmState::load)
      .def_readonly("tip_position", &ArmState::tip_position)
      .def_readonly("tip_displacement", &ArmState::tip_displacement)
      .def_readonly("tension", &ArmState::tension)
      .def_readonly("tendon_length", &ArmState::tendon_length)
      .def_readonly("cell_height", &ArmState::cell_height)
      .def_readonly("module_length", &ArmState::module_length)
      .def_readonly("cell_states", &ArmState::cell_states)
      .def_readonly("negative_eigenvalues", &ArmState::negative_eigenvalues)
      .def_readonly("energy", &ArmState::energy)
      .def_readonly("iterations", &ArmState::iterations);

  py::class_<ArmPath>(m, "ArmPath")
      .def_readonly("parameter", &ArmPath::parameter)
      .def_readonly("states", &ArmPath::states)
      .def_readonly("completed", &ArmPath::completed)
      .def_readonly("event", &ArmPath::event)
      .def_readonly("lost", &ArmPath::lost)
      .def_readonly("end_parameter", &ArmPath::end_parameter)
      .def_readonly("message", &ArmPath::message)
      .def_readonly("attempted_increments", &ArmPath::attempted_increments)
      .def_readonly("critical_cell", &ArmPath::critical_cell);

  py::class_<ArmRelease>(m, "ArmRelease")
      .def_readonly("converged", &ArmRelease::converged)
      .def_readonly("state", &ArmRelease::state)
      .def_readonly("message", &ArmRelease::message);

  py::class_<ArmSolver>(m, "ArmSolver")
      .def(py::init<const Arm&, ArmOptions>(), py::arg("arm"), py::arg("options"),
           py::keep_alive<1, 2>())
      .def("built", [](ArmSolver& s) { return unlocked([&] { return s.built(); }); })
      .def(
          "evaluate",
          [](ArmSolver& s, const VectorX& u, const Pulls& pulls, const Vector3& load) {
            return unlocked([&] { return s.evaluate(u, pulls, load); });
          },
          py::arg("u"), py::arg("pulls"), py::arg("load"))
      .def(
          "ramp",
          [](ArmSolver& s, const ArmState& start, const Pulls& pulls, const Vector3& load) {
            return unlocked([&] { return s.ramp(start, pulls, load); });
          },
          py::arg("start"), py::arg("pulls"), py::arg("load"))
      .def(
          "release",
          [](ArmSolver& s, const ArmState& from, const Pulls& pulls) {
            return unlocked([&] { return s.release(from, pulls); });
          },
          py::arg("start"), py::arg("pulls"))
      .def(
          "tip_compliance",
          [](ArmSolver& s, const ArmState& state) {
            return unlocked([&] { return Eigen::Matrix3d(s.tip_compliance(state)); });
          },
          py::arg("state"))
      .def(
          "tension_sensitivity",
          [](ArmSolver& s, const ArmState& state) {
            return unlocked([&] { return Eigen::Matrix3d(s.tension_sensitivity(state)); });
          },
          py::arg("state"))
      .def(
          "pretension",
          [](ArmSolver& s, const ArmState& start, double tension) {
            return unlocked([&] { return s.pretension(start, tension); });
          },
          py::arg("start"), py::arg("tension"));

  py::class_<ArmLoadResult>(m, "ArmLoadResult")
      .def_readonly("path", &ArmLoadResult::path)
      .def_readonly("pretensioned", &ArmLoadResult::pretensioned)
      .def_readonly("pretension_pulls", &ArmLoadResult::pretension_pulls)
      .def_readonly("completed", &ArmLoadResult::completed)
      .def_readonly("message", &ArmLoadResult::message);
  m.attr("DEFAULT_PRETENSION") = kDefaultPretension;
  m.def(
      "arm_tip_load",
      [](ArmSolver& s, const Vector3& load, const Pulls& pulls, double pretension) {
        return unlocked([&] { return arm_tip_load(s, load, pulls, pretension); });
      },
      py::arg("solver"), py::arg("load"), py::arg("pulls"), py::arg("pretension"));

  py::class_<ArmSnapResult>(m, "ArmSnapResult")
      .def_readonly("path", &ArmSnapResult::path)
      .def_readonly("snapped", &ArmSnapResult::snapped)
      .def_readonly("pull", &ArmSnapResult::pull)
      .def_readonly("pulls", &ArmSnapResult::pulls)
      .def_readonly("tension", &ArmSnapResult::tension)
      .def_readonly("tension_sum", &ArmSnapResult::tension_sum)
      .def_readonly("snapped_module", &ArmSnapResult::snapped_module)
      .def_readonly("snapped_cells", &ArmSnapResult::snapped_cells)
      .def_readonly("cell_states_after", &ArmSnapResult::cell_states_after)
      .def_readonly("configuration_after", &ArmSnapResult::configuration_after)
      .def_readonly("after", &ArmSnapResult::after)
      .def_readonly("release_converged", &ArmSnapResult::release_converged)
      .def_readonly("message", &ArmSnapResult::message);
  m.def(
      "arm_pull_until_snap",
      [](ArmSolver& s, const ArmState& start, const Pulls& direction, double max_pull) {
        return unlocked([&] { return arm_pull_until_snap(s, start, direction, max_pull); });
      },
      py::arg("solver"), py::arg("start"), py::arg("direction"), py::arg("max_pull"));

  py::class_<ArmCapacityResult>(m, "ArmCapacityResult")
      .def_readonly("load", &ArmCapacityResult::load)
      .def_readonly("limit", &ArmCapacityResult::limit)
      .def_readonly("tendon", &ArmCapacityResult::tendon)
      .def_readonly("module", &ArmCapacityResult::module)
      .def_readonly("path", &ArmCapacityResult::path)
      .def_readonly("message", &ArmCapacityResult::message);
  m.def(
      "arm_load_capacity",
      [](ArmSolver& s, const ArmState& start, const Vector3& direction, double max_load) {
        return unlocked([&] { return arm_load_capacity(s, start, direction, max_load); });
      },
      py::arg("solver"), py::arg("start"), py::arg("direction"), py::arg("max_load"));
}

}  // namespace

void bind_analyses(py::module_& m) {
  bind_arm_analysis(m);
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
