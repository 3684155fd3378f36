#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "kresling/core/interrupt.hpp"

namespace py = pybind11;

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
  // One submodule per folder of cpp/kresling, filled by python/bind_<folder>.cpp with what
  // that folder declares (the folder `core` has nothing to bind).
  auto geometry = m.def_submodule("geometry", "Generalized Kresling cell geometry");
  kresling::python::bind_geometry(geometry);
  auto elements = m.def_submodule("elements", "Element kernels: bars, dihedral angles, springs");
  kresling::python::bind_elements(elements);
  auto model = m.def_submodule(
      "model", "Bar-and-hinge models, the panel topology, Kresling specimens and the arm");
  kresling::python::bind_model(model);
  auto assembly = m.def_submodule("assembly", "Global force, tangent and energy of a model");
  kresling::python::bind_assembly(assembly);
  auto solvers = m.def_submodule("solvers", "Nonlinear and linear solvers");
  kresling::python::bind_solvers(solvers);
  auto analyses = m.def_submodule(
      "analyses", "The thesis's tests on specimens and the arm's load and pull analyses");
  kresling::python::bind_analyses(analyses);
  auto kinematics = m.def_submodule(
      "kinematics", "Constant-curvature manipulator kinematics (thesis ch. 4, Appendix E)");
  kresling::python::bind_kinematics(kinematics);
}
