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
#include "kresling/solvers/mgdcm.hpp"
#include "kresling/solvers/sensitivity.hpp"
#include "kresling/solvers/limits.hpp"
#include "kresling/solvers/linear_stiffness.hpp"
#include "kresling/solvers/stable_time_step.hpp"
#include "kresling/solvers/tangent_solver.hpp"
#include "kresling/solvers/time_integration.hpp"

namespace py = pybind11;
using kresling::model::Model;
using namespace kresling::solvers;

namespace kresling::python {

namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// One per-step quantity of a path as a (steps,) or (steps, k) numpy array.
template <typename Get>
VectorX per_step(const PathResult& r, Get&& get) {
  VectorX out(static_cast<Index>(r.steps.size()));
  for (std::size_t k = 0; k < r.steps.size(); ++k) out[static_cast<Index>(k)] = get(r.steps[k]);
  return out;
}

template <typename Get>
RowMatrix per_step_rows(const PathResult& r, Index width, Get&& get) {
  RowMatrix out(static_cast<Index>(r.steps.size()), width);
  for (std::size_t k = 0; k < r.steps.size(); ++k) {
    out.row(static_cast<Index>(k)) = get(r.steps[k]).transpose();
  }
  return out;
}

// The path every solver returns, bound field by field: the Python PathResult reads these
// (kresling/solvers/path.py documents them).
void bind_path_result(py::module_& m) {
  py::class_<PathResult>(m, "PathResult")
      .def_property_readonly("load_factor", [](const PathResult& r) {
        return per_step(r, [](const PathStep& s) { return s.load_factor; });
      })
      .def_property_readonly("displacement", [](const PathResult& r) {
        const Index n = r.steps.empty() ? 0 : r.steps.front().displacement.size();
        return per_step_rows(r, n, [](const PathStep& s) -> const VectorX& { return s.displacement; });
      })
      .def_property_readonly("constraint_dofs", [](const PathResult& r) { return r.constraint_dofs; })
      .def_property_readonly("constraint_force", [](const PathResult& r) {
        return per_step_rows(r, static_cast<Index>(r.constraint_dofs.size()),
                             [](const PathStep& s) -> const VectorX& { return s.constraint_force; });
      })
      .def_readonly("families", &PathResult::families)
      .def_property_readonly("energies", [](const PathResult& r) {
        return per_step_rows(r, static_cast<Index>(r.families.size()),
                             [](const PathStep& s) -> const VectorX& { return s.energies; });
      })
      .def_property_readonly("iterations", [](const PathResult& r) {
        Eigen::VectorXi out(static_cast<Index>(r.steps.size()));
        for (std::size_t k = 0; k < r.steps.size(); ++k) out[k] = r.steps[k].iterations;
        return out;
      })
      .def_property_readonly("negative_eigenvalues", [](const PathResult& r) {
        Eigen::VectorXi out(static_cast<Index>(r.steps.size()));
        for (std::size_t k = 0; k < r.steps.size(); ++k) out[k] = r.steps[k].negative_eigenvalues;
        return out;
      })
      .def_property_readonly("snapped", [](const PathResult& r) {
        Eigen::Matrix<bool, Eigen::Dynamic, 1> out(static_cast<Index>(r.steps.size()));
        for (std::size_t k = 0; k < r.steps.size(); ++k) out[k] = r.steps[k].snapped;
        return out;
      })
      .def_readonly("completed", &PathResult::completed)
      .def_readonly("message", &PathResult::message)
      .def_readonly("failed_increment", &PathResult::failed_increment)
      .def_readonly("attempted_increments", &PathResult::attempted_increments)
      .def_readonly("newton_iterations", &PathResult::newton_iterations);
}

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

// The load's time function: piecewise linear through the table [t, factor], constant
// beyond its ends (no table: empty, a factor of 1).
std::function<double(double)> table_factor(const VectorX& times, const VectorX& factors) {
  if (times.size() != factors.size()) {
    throw std::invalid_argument("load table: needs one factor per time");
  }
  if (!times.size()) return {};
  return [times, factors](double t) {
    if (t <= times[0]) return factors[0];
    for (Index i = 1; i < times.size(); ++i) {
      if (t <= times[i]) {
        const double s = (t - times[i - 1]) / (times[i] - times[i - 1]);
        return factors[i - 1] + s * (factors[i] - factors[i - 1]);
      }
    }
    return factors[times.size() - 1];
  };
}

// A load of terms (forces, times, factors, amplitude, frequency_hz): a harmonic factor
// amplitude sin(2 pi frequency_hz t) when frequency_hz > 0, else the table's.
using LoadTerm = std::tuple<VectorX, VectorX, VectorX, double, double>;
TimeLoad time_load(const std::vector<LoadTerm>& terms) {
  TimeLoad load;
  for (const auto& [forces, times, factors, amplitude, frequency] : terms) {
    if (frequency > 0.0) {
      const double w = 2.0 * 3.14159265358979323846 * frequency, a = amplitude;
      load.terms.push_back({forces, [w, a](double t) { return a * std::sin(w * t); }});
    } else {
      load.terms.push_back({forces, table_factor(times, factors)});
    }
  }
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

namespace {

// An equilibrium's factorised tangent for sensitivities (solvers/sensitivity.hpp).
void bind_equilibrium_sensitivity(py::module_& m) {
  py::class_<solvers::EquilibriumSensitivity>(
      m, "EquilibriumSensitivity",
      "An equilibrium's tangent factorised for sensitivities (solvers/sensitivity.hpp)")
      .def(py::init([](const Model& model, const VectorX& u, const std::vector<Index>& held) {
             py::gil_scoped_release release;
             return std::make_unique<solvers::EquilibriumSensitivity>(model, u, held);
           }),
           py::arg("model"), py::arg("u"), py::arg("held"))
      .def_property_readonly("ok", &solvers::EquilibriumSensitivity::ok)
      .def_property_readonly("negative_eigenvalues",
                             &solvers::EquilibriumSensitivity::negative_eigenvalues)
      .def_property_readonly("held_dofs", &solvers::EquilibriumSensitivity::held_dofs)
      .def("update", &solvers::EquilibriumSensitivity::update, py::arg("u"),
           py::call_guard<py::gil_scoped_release>())
      .def("tangent", [](const solvers::EquilibriumSensitivity& s) { return csc(s.tangent()); })
      .def_property_readonly("internal_force", &solvers::EquilibriumSensitivity::internal_force)
      .def(
          "tangent_times",
          [](const solvers::EquilibriumSensitivity& s, const Eigen::MatrixXd& M) {
            if (M.rows() != s.tangent().cols()) {
              throw std::invalid_argument("M has " + std::to_string(M.rows()) +
                                          " rows: must have " + std::to_string(s.tangent().cols()));
            }
            return Eigen::MatrixXd(s.tangent() * M);
          },
          py::arg("M"), "K M: the tangent times a 3N x P matrix")
      .def("displacement", &solvers::EquilibriumSensitivity::displacement, py::arg("dresidual"),
           py::arg("held_motion") = Eigen::MatrixXd(), py::call_guard<py::gil_scoped_release>())
      .def("held_force", &solvers::EquilibriumSensitivity::held_force, py::arg("dforce"),
           py::arg("du"), py::call_guard<py::gil_scoped_release>())
      .def("adjoint", &solvers::EquilibriumSensitivity::adjoint, py::arg("g"),
           py::call_guard<py::gil_scoped_release>());
  m.def(
      "path_sensitivity",
      [](const model::Model& model, const std::vector<VectorX>& states,
         const std::vector<double>& fractions, const std::vector<Index>& held,
         const Eigen::MatrixXd& positions, const std::vector<py::tuple>& columns,
         const Eigen::MatrixXd& drive) {
        std::vector<solvers::ColumnMotion> motions;
        for (const py::tuple& c : columns) {
          motions.push_back({c[0].cast<std::string>(), c[1].cast<std::string>(),
                             c[2].cast<Eigen::MatrixXd>()});
        }
        solvers::PathSensitivityResult r;
        {
          py::gil_scoped_release release;
          r = solvers::path_sensitivity(model, states, fractions, held, positions, motions, drive);
        }
        // (S, rows, P) arrays, row-major, from the per-state column-major matrices.
        auto stack = [](const std::vector<Eigen::MatrixXd>& blocks, py::ssize_t rows,
                        py::ssize_t cols) {
          py::array_t<double> out({static_cast<py::ssize_t>(blocks.size()), rows, cols});
          auto a = out.mutable_unchecked<3>();
          for (py::ssize_t k = 0; k < static_cast<py::ssize_t>(blocks.size()); ++k) {
            for (py::ssize_t i = 0; i < rows; ++i) {
              for (py::ssize_t j = 0; j < cols; ++j) a(k, i, j) = blocks[k](i, j);
            }
          }
          return out;
        };
        const py::ssize_t P = r.energy.cols();
        return py::make_tuple(r.held_dofs, stack(r.displacement, model.num_dofs(), P),
                              stack(r.held_force, static_cast<py::ssize_t>(r.held_dofs.size()), P),
                              r.energy);
      },
      py::arg("model"), py::arg("states"), py::arg("fractions"), py::arg("held"),
      py::arg("positions"), py::arg("columns"), py::arg("drive"),
      "(held_dofs, du/dp (S, 3N, P), held forces' derivatives (S, H, P), dE/dp (S, P)) of a "
      "path's states");
}

}  // namespace

void bind_solvers(py::module_& m) {
  bind_equilibrium_sensitivity(m);
  bind_path_result(m);
  // The documented bounds of the solvers' controls (kresling/solvers/limits.hpp).
  m.attr("MAX_STEPS") = kMaxSteps;
  m.attr("MAX_BISECTIONS") = kMaxBisections;
  m.attr("MAX_ITERATIONS") = kMaxIterations;
  m.attr("MAX_SHIFT") = kMaxShift;
  bind_path_options<DisplacementControlOptions>(m, "DisplacementControlOptions")
      .def_readwrite("reject_iterations", &DisplacementControlOptions::reject_iterations)
      .def_readwrite("max_bisections", &DisplacementControlOptions::max_bisections)
      .def_readwrite("extrapolation", &DisplacementControlOptions::extrapolation)
      .def_readwrite("merlin2_steps", &DisplacementControlOptions::merlin2_steps)
      .def_readwrite("adaptive", &DisplacementControlOptions::adaptive)
      .def_readwrite("adaptive_tolerance", &DisplacementControlOptions::adaptive_tolerance);

  m.def(
      "displacement_control",
      [](const Model& model, const VectorX& prescribed, int steps,
         const DisplacementControlOptions& options, const VectorX& initial) {
        PathResult r;
        {
          py::gil_scoped_release release;
          r = solve_displacement_control(model, prescribed, steps, options, initial);
        }
        return r;
      },
      py::arg("model"), py::arg("prescribed"), py::arg("steps"), py::arg("options"),
      py::arg("initial"));

  bind_path_options<ForceControlOptions>(m, "ForceControlOptions")
      .def_readwrite("max_bisections", &ForceControlOptions::max_bisections);

  m.def(
      "force_control",
      [](const Model& model, const VectorX& forces, int steps, const ForceControlOptions& options,
         const VectorX& initial) {
        PathResult r;
        {
          py::gil_scoped_release release;
          r = solve_force_control(model, forces, steps, options, initial);
        }
        return r;
      },
      py::arg("model"), py::arg("forces"), py::arg("steps"), py::arg("options"),
      py::arg("initial"));

  bind_path_options<MgdcmOptions>(m, "MgdcmOptions")
      .def_readwrite("initial_load_factor", &MgdcmOptions::initial_load_factor)
      .def_readwrite("max_increments", &MgdcmOptions::max_increments)
      .def_readwrite("max_load_factor", &MgdcmOptions::max_load_factor)
      .def_readwrite("monitor_dof", &MgdcmOptions::monitor_dof)
      .def_readwrite("max_displacement", &MgdcmOptions::max_displacement)
      .def_readwrite("max_step_factor", &MgdcmOptions::max_step_factor);

  m.def(
      "mgdcm",
      [](const Model& model, const VectorX& forces, const MgdcmOptions& options,
         const VectorX& initial) {
        PathResult r;
        {
          py::gil_scoped_release release;
          r = solve_mgdcm(model, forces, options, initial);
        }
        return r;
      },
      py::arg("model"), py::arg("forces"), py::arg("options"), py::arg("initial"));

  bind_path_options<FoldOptions>(m, "FoldOptions")
      .def_readwrite("max_bisections", &FoldOptions::max_bisections)
      .def_readwrite("extrapolation", &FoldOptions::extrapolation)
      .def_readwrite("adaptive", &FoldOptions::adaptive)
      .def_readwrite("adaptive_tolerance", &FoldOptions::adaptive_tolerance)
      .def_readwrite("snap", &FoldOptions::snap)
      .def_readwrite("relax", &FoldOptions::relax);

  m.def(
      "fold",
      [](const Model& model, const std::vector<std::pair<std::vector<Index>, VectorX>>& stages,
         int steps, const VectorX& forces, const FoldOptions& options, const VectorX& initial) {
        std::vector<FoldStage> list;
        for (const auto& [hinges, targets] : stages) list.push_back({hinges, targets});
        PathResult r;
        {
          py::gil_scoped_release release;
          r = solve_fold(model, list, steps, forces, options, initial);
        }
        return r;
      },
      py::arg("model"), py::arg("stages"), py::arg("steps"), py::arg("forces"),
      py::arg("options"), py::arg("initial"),
      "Fold by crease actuation: stages of (hinge indices, target rest angles [rad])");

  bind_path_options<TimeIntegrationOptions>(m, "TimeIntegrationOptions")
      .def_readwrite("time_step", &TimeIntegrationOptions::time_step)
      .def_readwrite("duration", &TimeIntegrationOptions::duration)
      .def_readwrite("hht_alpha", &TimeIntegrationOptions::hht_alpha)
      .def_readwrite("mass_damping", &TimeIntegrationOptions::mass_damping)
      .def_readwrite("stiffness_damping", &TimeIntegrationOptions::stiffness_damping)
      .def_readwrite("max_halvings", &TimeIntegrationOptions::max_halvings);
  py::class_<TimeHistory>(m, "TimeHistory")
      .def_readonly("path", &TimeHistory::path)
      .def_property_readonly("velocity", [](const TimeHistory& h) {
        const Index n = h.velocity.empty() ? 0 : h.velocity.front().size();
        RowMatrix out(static_cast<Index>(h.velocity.size()), n);
        for (std::size_t k = 0; k < h.velocity.size(); ++k) out.row(static_cast<Index>(k)) = h.velocity[k].transpose();
        return out;
      })
      .def_readonly("kinetic", &TimeHistory::kinetic)
      .def_readonly("strain", &TimeHistory::strain)
      .def_readonly("dissipated", &TimeHistory::dissipated)
      .def_readonly("work", &TimeHistory::work)
      .def_readonly("stable_time_step", &TimeHistory::stable_time_step)
      .def_readonly("time_step", &TimeHistory::time_step);

  py::class_<ExplicitOptions>(m, "ExplicitOptions")
      .def(py::init<>())
      .def_readwrite("time_step", &ExplicitOptions::time_step)
      .def_readwrite("duration", &ExplicitOptions::duration)
      .def_readwrite("mass_damping", &ExplicitOptions::mass_damping)
      .def_readwrite("stiffness_damping", &ExplicitOptions::stiffness_damping)
      .def_readwrite("record_every", &ExplicitOptions::record_every)
      .def_property(
          "stop", [](const ExplicitOptions& o) { return static_cast<bool>(o.stop); },
          [](ExplicitOptions& o, const py::object& f) { o.stop = stop_rule(f); });
  bind_integrator<ExplicitOptions>(
      m, "integrate_explicit",
      [](const Model& model, const VectorX& masses, const TimeLoad& load,
         const ExplicitOptions& options, const VectorX& u0, const VectorX& v0) {
        return integrate_explicit(model, masses, load, options, u0, v0);
      },
      "Explicit central differences with lumped masses under load terms");
  py::class_<StableStep>(m, "StableStep")
      .def_readonly("time_step", &StableStep::time_step)
      .def_readonly("omega_max", &StableStep::omega_max)
      .def_readonly("omega_bound", &StableStep::omega_bound)
      .def_readonly("iterations", &StableStep::iterations);
  m.def(
      "stable_time_step",
      [](const Model& model, const VectorX& masses, const VectorX& u, double mass_damping,
         double stiffness_damping) {
        py::gil_scoped_release release;
        return stable_time_step(model, masses, u, mass_damping, stiffness_damping);
      },
      py::arg("model"), py::arg("masses"), py::arg("u"), py::arg("mass_damping"),
      py::arg("stiffness_damping"));

  bind_integrator<TimeIntegrationOptions>(
      m, "integrate_newmark",
      [](const Model& model, const VectorX& masses, const TimeLoad& load,
         const TimeIntegrationOptions& options, const VectorX& u0, const VectorX& v0) {
        return integrate_newmark(model, masses, load, options, u0, v0);
      },
      "Newmark / HHT-alpha time integration under load terms (forces, times, factors, "
      "amplitude, frequency_hz)");

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

  // What the tangent solver decides for a matrix's pattern, and one factorisation's outcome
  // (benchmarks report the fill and the choice; tests check the paths).
  m.def(
      "factorization_plan",
      [](const SparseMatrix& K) {
        FactorizationPlan plan;
        FactorizeInfo info;
        {
          py::gil_scoped_release release;
          TangentSolver solver;
          info = solver.factorize(K);
          plan = solver.plan();
        }
        static const char* choices[] = {"auto", "dense", "simplicial", "supernodal"};
        static const char* orderings[] = {"none", "amd", "nested dissection", "other"};
        static const char* methods[] = {"none", "cholesky", "ldlt", "lu", "dense cholesky",
                                        "supernodal cholesky"};
        py::dict out;
        out["cholesky"] = choices[static_cast<int>(plan.cholesky)];
        out["ordering"] = orderings[static_cast<int>(plan.ordering)];
        out["factor_nonzeros"] = plan.factor_nonzeros;
        out["flops"] = plan.flops;
        out["analysis_seconds"] = plan.analysis_seconds;
        out["ok"] = info.ok;
        out["method"] = methods[static_cast<int>(info.method)];
        out["negative_eigenvalues"] = info.negative_eigenvalues;
        return out;
      },
      py::arg("K"),
      "The factorisation chosen for the symmetric K (its lower triangle is read; scipy CSC), "
      "as a dict: cholesky, ordering, factor_nonzeros, flops, analysis_seconds, and the "
      "first factorisation's ok, method and negative_eigenvalues.");
}

}  // namespace kresling::python
