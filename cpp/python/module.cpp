#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "kresling/core/interrupt.hpp"

namespace py = pybind11;

namespace {

// Each submodule is filled by python/<folder>/bind_<header>.cpp with what each header
// declares, in this order (a type is bound before a signature that takes it).
void add_geometry(py::module_& m) {
  auto geometry = m.def_submodule("geometry", "Generalized Kresling cell geometry");
  kresling::python::bind_design(geometry);
  kresling::python::bind_design_derivative(geometry);
  kresling::python::bind_design_table(geometry);
}

void add_elements(py::module_& m) {
  auto elements = m.def_submodule("elements", "Element kernels: bars, dihedral angles, springs");
  kresling::python::bind_bar_laws(elements);
  kresling::python::bind_spring_laws(elements);
  kresling::python::bind_dihedral(elements);
  kresling::python::bind_corner_angle(elements);
  kresling::python::bind_bar(elements);
  kresling::python::bind_hinge(elements);
}

void add_contact(py::module_& m) {
  auto contact = m.def_submodule(
      "contact", "Contact kernels: distances, barriers, collision detection, the broad phase");
  kresling::python::bind_contact_distance(contact);
  kresling::python::bind_contact_mollifier(contact);
  kresling::python::bind_contact_barrier(contact);
  kresling::python::bind_contact_barrier_stiffness(contact);
  kresling::python::bind_contact_ccd(contact);
  kresling::python::bind_contact_broad_phase(contact);
}

void add_model(py::module_& m) {
  auto model = m.def_submodule(
      "model", "Bar-and-hinge models, the panel topology, Kresling specimens and the arm");
  kresling::python::bind_model(model);
  kresling::python::bind_family_registry(model);
  kresling::python::bind_topology(model);
  kresling::python::bind_panel_elements(model);
  kresling::python::bind_calibration(model);
  kresling::python::bind_merlin2_rest_angle(model);
  kresling::python::bind_panel_centre(model);
  kresling::python::bind_kresling_specimen(model);
  kresling::python::bind_arm(model);
}

void add_assembly(py::module_& m) {
  auto assembly = m.def_submodule("assembly", "Global force, tangent and energy of a model");
  kresling::python::bind_workspace(assembly);
  kresling::python::bind_assembler(assembly);
  kresling::python::bind_parameter_jacobian(assembly);
  kresling::python::bind_shape_jacobian(assembly);
}

void add_solvers(py::module_& m) {
  auto solvers = m.def_submodule("solvers", "Nonlinear and linear solvers");
  kresling::python::bind_sensitivity(solvers);
  kresling::python::bind_path(solvers);
  kresling::python::bind_limits(solvers);
  kresling::python::bind_displacement_control(solvers);
  kresling::python::bind_force_control(solvers);
  kresling::python::bind_mgdcm(solvers);
  kresling::python::bind_fold(solvers);
  kresling::python::bind_time_integration(solvers);
  kresling::python::bind_explicit_dynamics(solvers);
  kresling::python::bind_stable_time_step(solvers);
  kresling::python::bind_linear_stiffness(solvers);
  kresling::python::bind_supernodal_cholesky(solvers);
}

void add_analyses(py::module_& m) {
  auto analyses = m.def_submodule(
      "analyses", "The thesis's tests on specimens and the arm's load and pull analyses");
  kresling::python::bind_bending_test(analyses);
  kresling::python::bind_snap_through(analyses);
  kresling::python::bind_arm_analysis(analyses);
  kresling::python::bind_switching(analyses);
  kresling::python::bind_arm_crease_switching(analyses);
  kresling::python::bind_linear_bending(analyses);
}

void add_kinematics(py::module_& m) {
  auto kinematics = m.def_submodule(
      "kinematics", "Constant-curvature manipulator kinematics (thesis ch. 4, Appendix E)");
  kresling::python::bind_module_transform(kinematics);
  kresling::python::bind_constant_curvature(kinematics);
  kresling::python::bind_chain(kinematics);
  kresling::python::bind_inverse(kinematics);
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  // Ctrl-C stops a long C++ call: the core's loops run Python's signal handlers (with the
  // GIL; they run on the main thread only), and an exception they raise (KeyboardInterrupt)
  // unwinds the call and is raised in Python.
  kresling::set_interrupt_check([] {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  });
  m.doc() = "kresling's C++ core (geometry, bar-and-hinge solver, kinematics). "
            "Use the Python API in the kresling package; this module is internal.";
  // One submodule per folder of cpp/kresling (the folder `core` has nothing to bind).
  add_geometry(m);
  add_elements(m);
  add_contact(m);
  add_model(m);
  add_assembly(m);
  add_solvers(m);
  add_analyses(m);
  add_kinematics(m);
}
