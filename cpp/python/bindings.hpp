#pragma once
/// \file bindings.hpp
/// One binding file per header of cpp/kresling: <folder>/bind_<header>.cpp binds what
/// kresling/<folder>/<header>.hpp declares into the submodule kresling._core.<folder>.

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

// kresling._core.geometry
void bind_design(pybind11::module_& m);
void bind_design_derivative(pybind11::module_& m);
void bind_design_table(pybind11::module_& m);

// kresling._core.elements
void bind_bar_laws(pybind11::module_& m);
void bind_spring_laws(pybind11::module_& m);
void bind_dihedral(pybind11::module_& m);
void bind_corner_angle(pybind11::module_& m);
void bind_bar(pybind11::module_& m);
void bind_hinge(pybind11::module_& m);

// kresling._core.contact
void bind_contact_distance(pybind11::module_& m);
void bind_contact_mollifier(pybind11::module_& m);
void bind_contact_barrier(pybind11::module_& m);
void bind_contact_barrier_stiffness(pybind11::module_& m);
void bind_contact_ccd(pybind11::module_& m);
void bind_contact_broad_phase(pybind11::module_& m);

// kresling._core.model
void bind_model(pybind11::module_& m);
void bind_family_registry(pybind11::module_& m);
void bind_topology(pybind11::module_& m);
void bind_panel_elements(pybind11::module_& m);
void bind_calibration(pybind11::module_& m);
void bind_merlin2_rest_angle(pybind11::module_& m);
void bind_panel_centre(pybind11::module_& m);
void bind_kresling_specimen(pybind11::module_& m);
void bind_arm(pybind11::module_& m);

// kresling._core.assembly
void bind_workspace(pybind11::module_& m);
void bind_assembler(pybind11::module_& m);
void bind_parameter_jacobian(pybind11::module_& m);
void bind_shape_jacobian(pybind11::module_& m);

// kresling._core.solvers
void bind_sensitivity(pybind11::module_& m);
void bind_path(pybind11::module_& m);
void bind_limits(pybind11::module_& m);
void bind_displacement_control(pybind11::module_& m);
void bind_force_control(pybind11::module_& m);
void bind_mgdcm(pybind11::module_& m);
void bind_fold(pybind11::module_& m);
void bind_time_integration(pybind11::module_& m);
void bind_explicit_dynamics(pybind11::module_& m);
void bind_stable_time_step(pybind11::module_& m);
void bind_linear_stiffness(pybind11::module_& m);
void bind_supernodal_cholesky(pybind11::module_& m);

// kresling._core.analyses
void bind_bending_test(pybind11::module_& m);
void bind_snap_through(pybind11::module_& m);
void bind_arm_analysis(pybind11::module_& m);
void bind_switching(pybind11::module_& m);
void bind_arm_crease_switching(pybind11::module_& m);
void bind_linear_bending(pybind11::module_& m);

// kresling._core.kinematics
void bind_module_transform(pybind11::module_& m);
void bind_constant_curvature(pybind11::module_& m);
void bind_chain(pybind11::module_& m);
void bind_inverse(pybind11::module_& m);

}  // namespace kresling::python
