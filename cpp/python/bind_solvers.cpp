#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>

#include "bindings.hpp"
#include "kresling/assembly/assembler.hpp"
#include "kresling/solvers/displacement_control.hpp"
#include "kresling/solvers/force_control.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/linear_stiffness.hpp"

namespace py = pybind11;
using kresling::model::Model;
using namespace kresling::solvers;

namespace kresling::python {

namespace {

py::tuple csc(const assembly::SparseMatrix& K) {
  // Copies: the Python side owns its arrays.
  py::array_t<int> indptr(K.outerSize() + 1, K.outerIndexPtr());
  py::array_t<int> indices(K.nonZeros(), K.innerIndexPtr());
  py::array_t<double> data(K.nonZeros(), K.valuePtr());
  return py::make_tuple(data, indices, indptr, py::make_tuple(K.rows(), K.cols()));
}

py::dict path_to_dict(const PathResult& r, Index num_dofs) {
  const auto s = static_cast<Index>(r.steps.size());
  const auto nc = static_cast<Index>(r.constraint_dofs.size());
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> u(s, num_dofs), f(s, nc);
  VectorX lam(s), eb(s), eh(s);
  Eigen::VectorXi iters(s), neg(s);
  for (Index k = 0; k < s; ++k) {
    const PathStep& p = r.steps[k];
    u.row(k) = p.displacement.transpose();
    f.row(k) = p.constraint_force.transpose();
    lam[k] = p.load_factor;
    eb[k] = p.energy_bars;
    eh[k] = p.energy_hinges;
    iters[k] = p.iterations;
    neg[k] = p.negative_eigenvalues;
  }
  py::dict out;
  out["load_factor"] = lam;
  out["displacement"] = u;
  out["constraint_force"] = f;
  out["constraint_dofs"] = r.constraint_dofs;
  out["energy_bars"] = eb;
  out["energy_hinges"] = eh;
  out["iterations"] = iters;
  out["negative_eigenvalues"] = neg;
  out["completed"] = r.completed;
  out["message"] = r.message;
  out["failed_increment"] = r.failed_increment;
  out["attempted_increments"] = r.attempted_increments;
  return out;
}

// A Python callable `stop(load_factor, displacement) -> bool` as a solver's stopping rule.
// The solvers run without the GIL: the call takes it back, and so does the release of the
// callable when the last copy of the rule goes.
StopRule stop_rule(const py::object& callable) {
  if (callable.is_none()) return {};
  if (!PyCallable_Check(callable.ptr())) {
    throw std::invalid_argument("stop: must be None or a callable");
  }
  std::shared_ptr<py::object> f(new py::object(callable), [](py::object* o) {
    py::gil_scoped_acquire gil;
    delete o;
  });
  return [f](const PathStep& s) {
    py::gil_scoped_acquire gil;
    return py::cast<bool>((*f)(s.load_factor, s.displacement));
  };
}

// Checked by the solvers (kresling/solvers/limits.hpp).
NewtonOptions newton(double tolerance, int max_iterations) { return {tolerance, max_iterations}; }

}  // namespace

void bind_solvers(py::module_& m) {
  // The documented bounds of the solvers' controls (kresling/solvers/limits.hpp).
  m.attr("MAX_STEPS") = kMaxSteps;
  m.attr("MAX_BISECTIONS") = kMaxBisections;
  m.attr("MAX_ITERATIONS") = kMaxIterations;
  m.attr("MAX_SHIFT") = kMaxShift;
  m.def(
      "assemble",
      [](const Model& model, const VectorX& u, double shift, bool with_matrix) {
        assembly::Assembler assembler(model, assembly::all_dofs(model.num_dofs()), shift);
        VectorX force;
        assembly::Energies e;
        {
          py::gil_scoped_release release;
          e = assembler.assemble(u, force, with_matrix);
        }
        py::object K = with_matrix ? py::object(csc(assembler.matrix())) : py::none();
        return py::make_tuple(e.bars, e.hinges, force, K);
      },
      py::arg("model"), py::arg("u"), py::arg("shift"), py::arg("with_matrix"));

  m.def(
      "element_state",
      [](const Model& model, const VectorX& u) {
        const auto s = assembly::element_state(model, u);
        py::dict out;
        out["bar_strain"] = s.bar_strain;
        out["bar_force"] = s.bar_force;
        out["hinge_angle"] = s.hinge_angle;
        out["hinge_moment"] = s.hinge_moment;
        out["bar_stress"] = s.bar_stress;
        out["bar_energy"] = s.bar_energy;
        out["hinge_energy"] = s.hinge_energy;
        out["cable_length"] = s.cable_length;
        out["cable_tension"] = s.cable_tension;
        out["cable_energy"] = s.cable_energy;
        return out;
      },
      py::arg("model"), py::arg("u"));

  py::class_<DisplacementControlOptions>(m, "DisplacementControlOptions")
      .def(py::init<>())
      .def_property(
          "tolerance", [](const DisplacementControlOptions& o) { return o.newton.tolerance; },
          [](DisplacementControlOptions& o, double v) { o.newton.tolerance = v; })
      .def_property(
          "max_iterations", [](const DisplacementControlOptions& o) { return o.newton.max_iterations; },
          [](DisplacementControlOptions& o, int v) { o.newton.max_iterations = v; })
      .def_readwrite("reject_iterations", &DisplacementControlOptions::reject_iterations)
      .def_readwrite("max_bisections", &DisplacementControlOptions::max_bisections)
      .def_readwrite("shift", &DisplacementControlOptions::shift)
      .def_readwrite("extrapolation", &DisplacementControlOptions::extrapolation)
      .def_readwrite("merlin2_steps", &DisplacementControlOptions::merlin2_steps)
      .def_property(
          "stop", [](const DisplacementControlOptions& o) { return static_cast<bool>(o.stop); },
          [](DisplacementControlOptions& o, const py::object& f) { o.stop = stop_rule(f); });

  m.def(
      "displacement_control",
      [](const Model& model, const VectorX& prescribed, int steps,
         const DisplacementControlOptions& options, const VectorX& initial) {
        PathResult r;
        {
          py::gil_scoped_release release;
          r = solve_displacement_control(model, prescribed, steps, options, initial);
        }
        return path_to_dict(r, model.num_dofs());
      },
      py::arg("model"), py::arg("prescribed"), py::arg("steps"), py::arg("options"),
      py::arg("initial"));

  m.def(
      "force_control",
      [](const Model& model, const VectorX& forces, int steps, double tolerance,
         int max_iterations, int max_bisections, double shift, const VectorX& initial,
         const py::object& stop) {
        ForceControlOptions o;
        o.stop = stop_rule(stop);
        o.newton = newton(tolerance, max_iterations);
        o.max_bisections = max_bisections;
        o.shift = shift;
        PathResult r;
        {
          py::gil_scoped_release release;
          r = solve_force_control(model, forces, steps, o, initial);
        }
        return path_to_dict(r, model.num_dofs());
      },
      py::arg("model"), py::arg("forces"), py::arg("steps"), py::arg("tolerance"),
      py::arg("max_iterations"), py::arg("max_bisections"), py::arg("shift"), py::arg("initial"),
      py::arg("stop") = py::none());

  m.def(
      "mgdcm",
      [](const Model& model, const VectorX& forces, double initial_load_factor, int max_increments,
         double max_load_factor, Index monitor_dof, double max_displacement,
         double max_step_factor, double tolerance, int max_iterations, double shift,
         const VectorX& initial, const py::object& stop) {
        MgdcmOptions o;
        o.stop = stop_rule(stop);
        o.newton = newton(tolerance, max_iterations);
        o.initial_load_factor = initial_load_factor;
        o.max_increments = max_increments;
        o.max_load_factor = max_load_factor;
        o.monitor_dof = monitor_dof;
        o.max_displacement = max_displacement;
        o.max_step_factor = max_step_factor;
        o.shift = shift;
        PathResult r;
        {
          py::gil_scoped_release release;
          r = solve_mgdcm(model, forces, o, initial);
        }
        return path_to_dict(r, model.num_dofs());
      },
      py::arg("model"), py::arg("forces"), py::arg("initial_load_factor"),
      py::arg("max_increments"), py::arg("max_load_factor"), py::arg("monitor_dof"),
      py::arg("max_displacement"), py::arg("max_step_factor"), py::arg("tolerance"),
      py::arg("max_iterations"), py::arg("shift"), py::arg("initial"),
      py::arg("stop") = py::none());

  m.def(
      "condensed_stiffness",
      [](const Model& model, const VectorX& u, const std::vector<Index>& dofs) {
        bool singular = false;
        Eigen::MatrixXd S;
        {
          py::gil_scoped_release release;
          S = condensed_stiffness(model, u, dofs, &singular);
        }
        return py::make_tuple(S, singular);
      },
      py::arg("model"), py::arg("u"), py::arg("dofs"));
}

}  // namespace kresling::python
