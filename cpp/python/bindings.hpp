#pragma once
/// \file bindings.hpp
/// One binding file per C++ area; each fills one submodule of kresling._core.

#include <pybind11/pybind11.h>

namespace kresling::python {

void bind_geometry(pybind11::module_& m);
void bind_elements(pybind11::module_& m);
void bind_model(pybind11::module_& m);
void bind_solvers(pybind11::module_& m);
void bind_analyses(pybind11::module_& m);
void bind_kinematics(pybind11::module_& m);
void bind_arm(pybind11::module_& m);

}  // namespace kresling::python
