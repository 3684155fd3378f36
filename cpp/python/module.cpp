#include <pybind11/pybind11.h>

#include "bindings.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "kresling's C++ core (geometry, bar-and-hinge solver, kinematics). "
            "Use the Python API in the kresling package; this module is internal.";
  auto geometry = m.def_submodule("geometry", "Generalized Kresling cell geometry");
  kresling::python::bind_geometry(geometry);
  auto elements = m.def_submodule("elements", "Element kernels: bars, dihedral angles, springs");
  kresling::python::bind_elements(elements);
  auto model = m.def_submodule("model", "Bar-and-hinge models and the panel topology");
  kresling::python::bind_model(model);
  auto solvers = m.def_submodule("solvers", "Assembly and nonlinear solvers");
  kresling::python::bind_solvers(solvers);
  auto analyses = m.def_submodule("analyses", "Kresling specimens and the thesis's analyses");
  kresling::python::bind_analyses(analyses);
  auto kinematics = m.def_submodule(
      "kinematics", "Constant-curvature manipulator kinematics (thesis ch. 4, Appendix E)");
  kresling::python::bind_kinematics(kinematics);
}
