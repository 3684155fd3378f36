// kresling._core.analyses: what kresling/analyses/arm_analysis.hpp declares.
#include "analyses/analyses_bindings.hpp"
#include "kresling/analyses/arm_analysis.hpp"
#include "kresling/analyses/bending_test.hpp"

namespace kresling::python {

namespace {

// The solver's options and what it returns: states, paths, a release.
void bind_arm_states(py::module_& m) {
  py::class_<ArmOptions> arm_options(m, "ArmOptions");
  arm_options.def(py::init<>());
  def_newton_controls(arm_options)
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
}

void bind_arm_solver(py::module_& m) {
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
}

// The tests on the arm: a tip load, pulling until a module snaps, the load capacity.
void bind_arm_tests(py::module_& m) {
  py::class_<ArmLoadResult>(m, "ArmLoadResult")
      .def_readonly("path", &ArmLoadResult::path)
      .def_readonly("pretensioned", &ArmLoadResult::pretensioned)
      .def_readonly("pretension_pulls", &ArmLoadResult::pretension_pulls)
      .def_readonly("completed", &ArmLoadResult::completed)
      .def_readonly("message", &ArmLoadResult::message);
  m.attr("DEFAULT_PRETENSION") = kDefaultPretension;
  m.attr("MAX_BENDING_NODES") = kresling::analyses::kMaxBendingNodes;
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

// The manipulator as one structure: tip loads, pulls, capacity.
void bind_arm_analysis(py::module_& m) {
  bind_arm_states(m);
  bind_arm_solver(m);
  bind_arm_tests(m);
}

}  // namespace kresling::python
