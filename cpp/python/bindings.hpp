#pragma once
/// \file bindings.hpp
/// One binding file per folder of cpp/kresling: bind_<folder>.cpp fills the submodule
/// kresling._core.<folder> with what that folder declares.

#include <pybind11/pybind11.h>

#include <Eigen/SparseCore>

#include "kresling/core/types.hpp"
#include "kresling/elements/bar_laws.hpp"
#include "kresling/elements/spring_laws.hpp"

namespace kresling::python {

/// Newton's controls of an options struct with a `newton` member (solvers::NewtonOptions)
/// as the flat properties `tolerance` and `max_iterations`, as every solver's and analysis's
/// options show them in Python.
template <typename Options>
pybind11::class_<Options>& def_newton_controls(pybind11::class_<Options>& options) {
  return options
      .def_property(
          "tolerance", [](const Options& o) { return o.newton.tolerance; },
          [](Options& o, double v) { o.newton.tolerance = v; })
      .def_property(
          "max_iterations", [](const Options& o) { return o.newton.max_iterations; },
          [](Options& o, int v) { o.newton.max_iterations = v; })
      .def_property(
          "give_up_after", [](const Options& o) { return o.newton.give_up_after; },
          [](Options& o, int v) { o.newton.give_up_after = v; });
}

/// A sparse matrix as scipy.sparse.csc_matrix's arguments: (data, indices, indptr), shape
/// (copies: the Python side owns its arrays).
pybind11::tuple csc(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& K);

void bind_geometry(pybind11::module_& m);
void bind_elements(pybind11::module_& m);
void bind_model(pybind11::module_& m);
void bind_assembly(pybind11::module_& m);
void bind_solvers(pybind11::module_& m);
void bind_analyses(pybind11::module_& m);
void bind_kinematics(pybind11::module_& m);

}  // namespace kresling::python
