// kresling._core.analyses: what kresling/analyses/snap_through.hpp declares.
#include "analyses/analyses_bindings.hpp"
#include "kresling/analyses/arm_analysis.hpp"
#include "kresling/analyses/bending_test.hpp"
#include "kresling/analyses/snap_through.hpp"

namespace kresling::python {

namespace {

void bind_snap_result(py::module_& m) {
  using R = analyses::SnapThroughResult;
  py::class_<R> c(m, "SnapThroughResult",
                  "One snap-through test's result (read-only; "
                  "kresling.analyses.SnapThroughResult reads it field by field)");
  field(c, "snap_force", &R::snap_force, "first local maximum of F [N]; NaN if none");
  field(c, "snap_displacement", &R::snap_displacement, "d at that maximum [mm]");
  field(c, "unstable_displacement", &R::unstable_displacement,
        "first zero of F after the peak [mm]");
  field(c, "energy_barrier", &R::energy_barrier, "strain energy at the unstable state [N mm]");
  field(c, "minimum_force", &R::minimum_force, "smallest F after the peak [N]");
  field(c, "bistable", &R::bistable, "the released cell rests at a second energy minimum");
  field(c, "stable_displacement", &R::stable_displacement,
        "travel of the second stable state (mean of the top perimeter) [mm]");
  field(c, "stable_height", &R::stable_height, "its cell height, Le - d [mm]");
  field(c, "stable_energy", &R::stable_energy, "its strain energy [N mm]");
  field(c, "stable_tilt", &R::stable_tilt, "its top polygon's tilt from horizontal [rad]");
  field(c, "stable_negative_eigenvalues", &R::stable_negative_eigenvalues,
        "of its tangent (0 when found; -1: not reached)");
  field(c, "stable_state", &R::stable_state,
        "its displacement, every DOF (3N,) [mm]; empty if none");
  field(c, "bistability", &R::bistability, "why the cell is (not) bistable, in words");
  field(c, "extended_height", &R::extended_height, "Le [mm]");
  field(c, "contracted_height", &R::contracted_height, "Lc [mm]");
  field(c, "displacement", &R::displacement, "the path's travel d (S + 1,) [mm], from 0");
  field(c, "force", &R::force, "the path's force F (S + 1,) [N]");
  field(c, "energy", &R::energy, "the path's strain energy (S + 1,) [N mm]");
  field(c, "iterations", &R::iterations, "Newton iterations per increment (S + 1,)");
  field(c, "completed", &R::completed, "the drive reached Lc");
  field(c, "message", &R::message, "why the path stopped early");
}

}  // namespace

void bind_snap_through(py::module_& m) {
  bind_snap_result(m);
  m.def("check_snap_design", &analyses::check_snap_design, py::arg("design"));

  py::class_<analyses::SnapThroughTest>(m, "SnapThroughTest")
      .def(py::init([](int n, int steps, const SpecimenParameters& parameters,
                       const solvers::DisplacementControlOptions& solver) {
             analyses::SnapThroughOptions o;
             o.steps = steps;
             o.specimen = parameters;
             o.solver = solver;
             return analyses::SnapThroughTest(n, o);
           }),
           py::arg("n"), py::arg("steps"), py::arg("parameters"), py::arg("solver"))
      .def(
          "run",
          [](analyses::SnapThroughTest& test, const Design& design) {
            analyses::SnapThroughResult r;
            {
              py::gil_scoped_release release;
              r = test.run(design);
            }
            return r;
          },
          py::arg("design"))
      .def(
          "setup",
          [](analyses::SnapThroughTest& test, const Design& design) {
            analyses::DriveSetup s = test.setup(design);
            return py::make_tuple(std::move(s.specimen), std::move(s.prescribed));
          },
          py::arg("design"),
          "(specimen, prescribed): the specimen with the test's supports and the motion");
}

}  // namespace kresling::python
