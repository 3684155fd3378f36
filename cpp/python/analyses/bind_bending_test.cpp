// kresling._core.analyses: what kresling/analyses/bending_test.hpp declares.
#include "analyses/analyses_bindings.hpp"
#include "kresling/analyses/arm_analysis.hpp"
#include "kresling/analyses/bending_test.hpp"
#include "kresling/analyses/linear_bending.hpp"

namespace kresling::python {

namespace {

void bind_bending_result(py::module_& m) {
  using R = analyses::BendingResult;
  py::class_<R> c(m, "BendingResult",
                  "One bending test's result (read-only; kresling.analyses.BendingResult reads "
                  "it field by field)");
  field(c, "stiffness", &R::stiffness, "K_B, slope of M(delta) through the origin [N m/rad]");
  field(c, "stiffness_intercept", &R::stiffness_intercept,
        "K_B of the least-squares line with intercept [N m/rad]");
  field(c, "intercept", &R::intercept, "that line's moment at delta = 0 [N m]");
  field(c, "module_length", &R::module_length, "L = two cells' height [mm]");
  field(c, "deflection", &R::deflection, "centre of the middle polygon, downward (S,) [mm]");
  field(c, "force", &R::force, "summed reaction at the driven nodes (S,) [N]");
  field(c, "angle", &R::angle, "deflection angle delta (S,) [rad]");
  field(c, "moment", &R::moment, "bending moment M (S,) [N m]");
  field(c, "iterations", &R::iterations, "Newton iterations per increment (S,)");
  field(c, "negative_eigenvalues", &R::negative_eigenvalues,
        "negative eigenvalues of the free tangent per increment (S,)");
  field(c, "final_displacement", &R::final_displacement,
        "every DOF's displacement at the last converged step (3N,) [mm]; empty if none");
  field(c, "completed", &R::completed, "the drive reached its full travel");
  field(c, "message", &R::message, "why the run stopped early");
  field(c, "num_dofs", &R::num_dofs, "DOFs of the specimen");
  field(c, "num_free_dofs", &R::num_free_dofs, "DOFs neither supported nor driven");
}

// A sweep's chunk in one call, the GIL released throughout: per design (lam, Lc, R) the
// extended then the contracted run, exactly as two run() calls, keeping only what the
// K_B-ratio metric reads. A design whose construction or run throws (bad input) gets
// ok = false and is left to the caller to rerun alone, so that its error reads as it would
// there; an interrupt is not caught.
py::list run_both_states(analyses::BendingTest& test,
                         const std::vector<std::array<double, 3>>& designs) {
  struct Pair {
    bool ok = false;
    double extended = 0.0, contracted = 0.0;
    long long iterations = 0;
    bool extended_completed = false, contracted_completed = false;
    std::string extended_message, contracted_message;
  };
  std::vector<Pair> pairs(designs.size());
  {
    py::gil_scoped_release release;
    for (std::size_t i = 0; i < designs.size(); ++i) {
      Pair& p = pairs[i];
      try {
        const Design design(test.n(), designs[i][2], designs[i][0], designs[i][1], 1);
        const analyses::BendingResult e = test.run(design, 1);
        const analyses::BendingResult c = test.run(design, 0);
        for (int k : e.iterations) p.iterations += k;
        for (int k : c.iterations) p.iterations += k;
        p.extended = e.stiffness, p.contracted = c.stiffness;
        p.extended_completed = e.completed, p.contracted_completed = c.completed;
        p.extended_message = e.message, p.contracted_message = c.message;
        p.ok = true;
      } catch (const py::error_already_set&) {
        throw;  // Ctrl-C (the interrupt check): stop the chunk
      } catch (const std::exception&) {
        p.ok = false;
      }
    }
  }
  py::list out;
  for (const Pair& p : pairs) {
    if (!p.ok) {
      out.append(py::none());
    } else {
      out.append(py::make_tuple(p.extended, p.contracted, p.iterations,
                                p.extended_completed, p.extended_message,
                                p.contracted_completed, p.contracted_message));
    }
  }
  return out;
}

// The bending test's checks of its inputs.
void bind_bending_checks(py::module_& m) {
  m.def(
      "bending_drive",
      [](const Design& design, int state, int cells, double deflection, double deflection_angle,
         int steps) {
        analyses::BendingOptions o;
        o.deflection = deflection;
        o.deflection_angle = deflection_angle;
        o.steps = steps;
        o.cells = cells;
        return analyses::bending_drive(design, state, o);
      },
      py::arg("design"), py::arg("state"), py::arg("cells"), py::arg("deflection"),
      py::arg("deflection_angle"), py::arg("steps"),
      "The bending test's checks of its inputs; returns the imposed motion [mm].");
  m.def("check_bending_state", &analyses::check_bending_state, py::arg("design"),
        py::arg("state"));
}

}  // namespace

void bind_bending_test(py::module_& m) {
  bind_bending_result(m);
  py::class_<analyses::BendingTest>(m, "BendingTest")
      .def(py::init([](int n, double deflection, double deflection_angle, int steps, int cells,
                       const SpecimenParameters& parameters,
                       const solvers::DisplacementControlOptions& solver) {
             analyses::BendingOptions o;
             o.deflection = deflection;
             o.deflection_angle = deflection_angle;
             o.steps = steps;
             o.cells = cells;
             o.specimen = parameters;
             o.solver = solver;
             return analyses::BendingTest(n, o);
           }),
           py::arg("n"), py::arg("deflection"), py::arg("deflection_angle"), py::arg("steps"),
           py::arg("cells"),
           py::arg("parameters"), py::arg("solver"))
      .def(
          "run",
          [](analyses::BendingTest& test, const Design& design, int state) {
            analyses::BendingResult r;
            {
              py::gil_scoped_release release;
              r = test.run(design, state);
            }
            return r;
          },
          py::arg("design"), py::arg("state"))
      .def(
          "setup",
          [](analyses::BendingTest& test, const Design& design, int state) {
            analyses::DriveSetup s = test.setup(design, state);
            return py::make_tuple(std::move(s.specimen), std::move(s.prescribed));
          },
          py::arg("design"), py::arg("state"),
          "(specimen, prescribed): the specimen with the test's supports and the motion")
      .def(
          "run_both_states",
          &run_both_states,
          py::arg("designs"),
          "Per design (lam, Lc, R): (K_ext, K_con, iterations summed over both runs, "
          "extended completed, its message, contracted completed, its message), or None "
          "where the design or a run raised (rerun it alone for the error).");
  bind_bending_checks(m);
}

}  // namespace kresling::python
