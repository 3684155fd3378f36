#pragma once
/// \file solvers_bindings.hpp
/// What the binding files of kresling._core.solvers share (cpp/python/solvers/bind_<header>.cpp
/// binds what cpp/kresling/solvers/<header>.hpp declares).

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <functional>
#include <tuple>
#include <memory>

#include "bindings.hpp"
#include "kresling/solvers/displacement_control.hpp"
#include "kresling/solvers/explicit_dynamics.hpp"
#include "kresling/solvers/fold.hpp"
#include "kresling/solvers/force_control.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/linear_stiffness.hpp"
#include "kresling/solvers/mgdcm.hpp"
#include "kresling/solvers/sensitivity.hpp"
#include "kresling/solvers/stable_time_step.hpp"
#include "kresling/solvers/tangent_solver.hpp"
#include "kresling/solvers/time_integration.hpp"

namespace py = pybind11;
using kresling::model::Model;
using namespace kresling::solvers;

namespace kresling::python {

namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// A Python callable `stop(load_factor, displacement) -> bool` as a solver's stopping rule;
// one with a true attribute `takes_step` is called as `stop(load_factor, displacement,
// step)`, `step` a dict of the step's `iterations`, `energies` (by family, in the path's
// order), `constraint_force`, `negative_eigenvalues` and `snapped` (what a caller writing
// the path as it goes needs of each increment).
// The solvers run without the GIL: the call takes it back, and so does the release of the
// callable when the last copy of the rule goes.
StopRule stop_rule(const py::object& callable) {
  if (callable.is_none()) return {};
  if (!PyCallable_Check(callable.ptr())) {
    throw std::invalid_argument("stop: must be None or a callable");
  }
  const bool takes_step = py::bool_(py::getattr(callable, "takes_step", py::bool_(false)));
  std::shared_ptr<py::object> f(new py::object(callable), [](py::object* o) {
    py::gil_scoped_acquire gil;
    delete o;
  });
  return [f, takes_step](const PathStep& s) {
    py::gil_scoped_acquire gil;
    if (!takes_step) return py::cast<bool>((*f)(s.load_factor, s.displacement));
    py::dict step;
    step["iterations"] = s.iterations;
    step["energies"] = s.energies;
    step["constraint_force"] = s.constraint_force;
    step["negative_eigenvalues"] = s.negative_eigenvalues;
    step["snapped"] = s.snapped;
    return py::cast<bool>((*f)(s.load_factor, s.displacement, step));
  };
}

// 0 auto, 1 dense, 2 simplicial (CHOLMOD), 3 supernodal (Eigen kernels); checked in Python.
CholeskyChoice cholesky_choice(int v) {
  if (v < 0 || v > 3) throw std::invalid_argument("cholesky must be 0, 1, 2 or 3");
  return static_cast<CholeskyChoice>(v);
}

// The controls every path-following solver shares: Newton's (tolerance, iterations, the
// Cholesky used), the diagonal shift and the stopping rule.
template <typename Options>
py::class_<Options> bind_path_options(py::module_& m, const char* name) {
  py::class_<Options> options(m, name);
  options.def(py::init<>());
  def_newton_controls(options)
      .def_property(
          "cholesky", [](const Options& o) { return static_cast<int>(o.newton.cholesky); },
          [](Options& o, int v) { o.newton.cholesky = cholesky_choice(v); })
      .def_readwrite("shift", &Options::shift)
      .def_property(
          "stop", [](const Options& o) { return static_cast<bool>(o.stop); },
          [](Options& o, const py::object& f) { o.stop = stop_rule(f); });
  return options;
}

// A time function as the tuple (times, factors, amplitude, frequency_hz, end_frequency_hz,
// sweep_time) (solvers/time_function.hpp).
using TimeFunctionTuple = std::tuple<VectorX, VectorX, double, double, double, double>;
std::function<double(double)> time_factor_of(const TimeFunctionTuple& f) {
  const auto& [times, factors, amplitude, frequency, end_frequency, sweep_time] = f;
  TimeFunction out;
  out.times = times;
  out.factors = factors;
  out.amplitude = amplitude;
  out.frequency_hz = frequency;
  out.end_frequency_hz = end_frequency;
  out.sweep_time = sweep_time;
  return time_factor(out);
}

// A load of terms (forces, time function): the forces times the function's factor.
using LoadTerm = std::tuple<VectorX, TimeFunctionTuple>;
TimeLoad time_load(const std::vector<LoadTerm>& terms) {
  TimeLoad load;
  for (const auto& [forces, time] : terms) load.terms.push_back({forces, time_factor_of(time)});
  return load;
}

// A time integrator taking (model, masses, load terms, options, u0, v0), the GIL released
// while it runs.
template <typename Options, typename Integrate>
void bind_integrator(py::module_& m, const char* name, Integrate integrate, const char* doc) {
  m.def(
      name,
      [integrate](const Model& model, const VectorX& masses, const std::vector<LoadTerm>& terms,
                  const Options& options, const VectorX& u0, const VectorX& v0) {
        const TimeLoad load = time_load(terms);
        TimeHistory h;
        {
          py::gil_scoped_release release;
          h = integrate(model, masses, load, options, u0, v0);
        }
        return h;
      },
      py::arg("model"), py::arg("masses"), py::arg("terms"), py::arg("options"),
      py::arg("u0"), py::arg("v0"), doc);
}

}  // namespace

}  // namespace kresling::python
