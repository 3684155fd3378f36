#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <string>
#include <type_traits>
#include <vector>

#include "bindings.hpp"
#include "kresling/analyses/arm_analysis.hpp"
#include "kresling/analyses/arm_crease_switching.hpp"
#include "kresling/analyses/bending_test.hpp"
#include "kresling/analyses/linear_bending.hpp"
#include "kresling/analyses/snap_through.hpp"
#include "kresling/analyses/switching.hpp"
#include "kresling/model/kresling_specimen.hpp"

namespace py = pybind11;
using kresling::geometry::Design;
using kresling::model::SpecimenParameters;
using kresling::model::Arm;
using namespace kresling::analyses;

namespace kresling::python {

namespace {

// A copy of `v` as a numpy array (the Python side owns its arrays).
template <typename T>
py::array_t<T> array(const std::vector<T>& v) {
  return py::array_t<T>(v.size(), v.data());
}

// A field of a result struct as a read-only property: vectors as numpy arrays (copies: the
// Python side owns its arrays), the rest as they are. The docstring is the C++ comment's.
template <typename Class, typename T, typename Result>
void field(py::class_<Result>& c, const char* name, T Class::*member, const char* doc) {
  c.def_property_readonly(
      name,
      [member](const Result& r) {
        if constexpr (std::is_same_v<T, std::vector<double>> || std::is_same_v<T, std::vector<int>>) {
          return array((r.*member));
        } else if constexpr (std::is_same_v<T, VectorX>) {
          return py::array_t<double>((r.*member).size(), (r.*member).data());
        } else {
          return r.*member;
        }
      },
      doc);
}

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

// Every path-following call runs without the GIL (the interrupt check takes it back).
template <typename F>
auto unlocked(F&& f) {
  py::gil_scoped_release release;
  return f();
}

// The crease-actuated switch of one cell (analyses/switching.hpp).
void bind_switching(py::module_& m) {
  using R = analyses::SwitchResult;
  py::class_<R> c(m, "SwitchResult",
                  "One crease group's switch (read-only; kresling.analyses.switching reads it)");
  c.def_property_readonly("group", [](const R& r) { return crease_group_name(r.group); });
  field(c, "forward", &R::forward, "extended -> contracted (False: the other way)");
  field(c, "creases", &R::creases, "driven creases (stiffness > 0)");
  field(c, "switched", &R::switched, "the start state ceased to exist and the cell landed");
  field(c, "snap_change", &R::snap_change, "rest-angle change at the snap [rad]");
  field(c, "resolution", &R::resolution, "the snap lies within this above snap_change [rad]");
  field(c, "moment", &R::moment, "summed crease moment at the snap [N mm]");
  field(c, "max_crease_moment", &R::max_crease_moment, "largest crease moment there [N mm]");
  field(c, "work", &R::work, "integral of the moment over the change up to the snap [N mm]");
  field(c, "snap_energy", &R::snap_energy, "strain energy at the snap [N mm]");
  field(c, "start_energy", &R::start_energy, "strain energy of the start state [N mm]");
  field(c, "start_height", &R::start_height, "height of the start state [mm]");
  field(c, "snap_height", &R::snap_height, "height at the snap [mm]");
  field(c, "landing_height", &R::landing_height, "released, the height at rest [mm]");
  field(c, "landing_energy", &R::landing_energy, "its strain energy [N mm]");
  field(c, "landing_tilt", &R::landing_tilt, "its top polygon's tilt [rad]");
  field(c, "landing_negative_eigenvalues", &R::landing_negative_eigenvalues,
        "of its tangent (0: a minimum)");
  field(c, "change", &R::change, "the path's rest-angle change (S,) [rad]");
  field(c, "moments", &R::moments, "the path's summed moment (S,) [N mm]");
  field(c, "energy", &R::energy, "the path's strain energy (S,) [N mm]");
  field(c, "height", &R::height, "the path's cell height (S,) [mm]");
  field(c, "message", &R::message, "what happened, in words");
  py::class_<analyses::SwitchingResult>(m, "SwitchingResult")
      .def_readonly("snap", &analyses::SwitchingResult::snap)
      .def_readonly("forward", &analyses::SwitchingResult::forward)
      .def_readonly("backward", &analyses::SwitchingResult::backward);
  m.def(
      "switching",
      [](const Design& design, const SpecimenParameters& parameters, int snap_through_steps,
         double scan_step, double max_change, double resolution, double overshoot,
         double tolerance, int max_iterations) {
        SwitchingOptions o;
        o.specimen = parameters;
        o.snap_through_steps = snap_through_steps;
        o.scan_step = scan_step, o.max_change = max_change;
        o.resolution = resolution, o.overshoot = overshoot;
        o.newton.tolerance = tolerance, o.newton.max_iterations = max_iterations;
        return unlocked([&] { return analyses::switching(design, o); });
      },
      py::arg("design"), py::arg("parameters"), py::arg("snap_through_steps"),
      py::arg("scan_step"), py::arg("max_change"), py::arg("resolution"), py::arg("overshoot"),
      py::arg("tolerance"), py::arg("max_iterations"));
}


// The manipulator as one structure (analyses/arm_analysis.hpp): tip loads, pulls, capacity.
void bind_arm_analysis(py::module_& m) {
  py::class_<ArmOptions> arm_options(m, "ArmOptions");
  arm_options.def(py::init<>());
  def_newton_controls(arm_options)
      .def_readwrite("steps", &ArmOptions::steps)
      .def_readwrite("max_bisections", &ArmOptions::max_bisections)
      .def_readwrite("shift", &ArmOptions::shift);

  py::class_<ArmState>(m, "ArmState")
      .def_readonly("displacement", &ArmState::displacement)
      .def_readonly("pulls", &ArmState::pulls)
      .def_readonly("load", &ArmState::load)
      .def_readonly("tip_position", &ArmState::tip_position)
      .def_readonly("tip_displacement", &ArmState::tip_displacement)
      .def_readonly("tension", &ArmState::tension)
      .def_readonly("tendon_length", &ArmState::tendon_length)
      .def_readonly("cell_height", &ArmState::cell_height)
      .def_readonly("module_length", &ArmState::module_length)
      .def_readonly("cell_states", &ArmState::cell_states)
      .def_readonly("negative_eigenvalues", &ArmState::negative_eigenvalues)
      .def_readonly("energy", &ArmState::energy)
      .def_readonly("iterations", &ArmState::iterations);

  py::class_<ArmPath>(m, "ArmPath")
      .def_readonly("parameter", &ArmPath::parameter)
      .def_readonly("states", &ArmPath::states)
      .def_readonly("completed", &ArmPath::completed)
      .def_readonly("event", &ArmPath::event)
      .def_readonly("lost", &ArmPath::lost)
      .def_readonly("end_parameter", &ArmPath::end_parameter)
      .def_readonly("message", &ArmPath::message)
      .def_readonly("attempted_increments", &ArmPath::attempted_increments)
      .def_readonly("critical_cell", &ArmPath::critical_cell);

  py::class_<ArmRelease>(m, "ArmRelease")
      .def_readonly("converged", &ArmRelease::converged)
      .def_readonly("state", &ArmRelease::state)
      .def_readonly("message", &ArmRelease::message);

  py::class_<ArmSolver>(m, "ArmSolver")
      .def(py::init<const Arm&, ArmOptions>(), py::arg("arm"), py::arg("options"),
           py::keep_alive<1, 2>())
      .def("built", [](ArmSolver& s) { return unlocked([&] { return s.built(); }); })
      .def(
          "evaluate",
          [](ArmSolver& s, const VectorX& u, const Pulls& pulls, const Vector3& load) {
            return unlocked([&] { return s.evaluate(u, pulls, load); });
          },
          py::arg("u"), py::arg("pulls"), py::arg("load"))
      .def(
          "ramp",
          [](ArmSolver& s, const ArmState& start, const Pulls& pulls, const Vector3& load) {
            return unlocked([&] { return s.ramp(start, pulls, load); });
          },
          py::arg("start"), py::arg("pulls"), py::arg("load"))
      .def(
          "release",
          [](ArmSolver& s, const ArmState& from, const Pulls& pulls) {
            return unlocked([&] { return s.release(from, pulls); });
          },
          py::arg("start"), py::arg("pulls"))
      .def(
          "tip_compliance",
          [](ArmSolver& s, const ArmState& state) {
            return unlocked([&] { return Eigen::Matrix3d(s.tip_compliance(state)); });
          },
          py::arg("state"))
      .def(
          "tension_sensitivity",
          [](ArmSolver& s, const ArmState& state) {
            return unlocked([&] { return Eigen::Matrix3d(s.tension_sensitivity(state)); });
          },
          py::arg("state"))
      .def(
          "pretension",
          [](ArmSolver& s, const ArmState& start, double tension) {
            return unlocked([&] { return s.pretension(start, tension); });
          },
          py::arg("start"), py::arg("tension"));

  py::class_<ArmLoadResult>(m, "ArmLoadResult")
      .def_readonly("path", &ArmLoadResult::path)
      .def_readonly("pretensioned", &ArmLoadResult::pretensioned)
      .def_readonly("pretension_pulls", &ArmLoadResult::pretension_pulls)
      .def_readonly("completed", &ArmLoadResult::completed)
      .def_readonly("message", &ArmLoadResult::message);
  m.attr("DEFAULT_PRETENSION") = kDefaultPretension;
  m.attr("MAX_BENDING_NODES") = kresling::analyses::kMaxBendingNodes;
  m.def(
      "arm_tip_load",
      [](ArmSolver& s, const Vector3& load, const Pulls& pulls, double pretension) {
        return unlocked([&] { return arm_tip_load(s, load, pulls, pretension); });
      },
      py::arg("solver"), py::arg("load"), py::arg("pulls"), py::arg("pretension"));

  py::class_<ArmSnapResult>(m, "ArmSnapResult")
      .def_readonly("path", &ArmSnapResult::path)
      .def_readonly("snapped", &ArmSnapResult::snapped)
      .def_readonly("pull", &ArmSnapResult::pull)
      .def_readonly("pulls", &ArmSnapResult::pulls)
      .def_readonly("tension", &ArmSnapResult::tension)
      .def_readonly("tension_sum", &ArmSnapResult::tension_sum)
      .def_readonly("snapped_module", &ArmSnapResult::snapped_module)
      .def_readonly("snapped_cells", &ArmSnapResult::snapped_cells)
      .def_readonly("cell_states_after", &ArmSnapResult::cell_states_after)
      .def_readonly("configuration_after", &ArmSnapResult::configuration_after)
      .def_readonly("after", &ArmSnapResult::after)
      .def_readonly("release_converged", &ArmSnapResult::release_converged)
      .def_readonly("message", &ArmSnapResult::message);
  m.def(
      "arm_pull_until_snap",
      [](ArmSolver& s, const ArmState& start, const Pulls& direction, double max_pull) {
        return unlocked([&] { return arm_pull_until_snap(s, start, direction, max_pull); });
      },
      py::arg("solver"), py::arg("start"), py::arg("direction"), py::arg("max_pull"));

  py::class_<ArmCapacityResult>(m, "ArmCapacityResult")
      .def_readonly("load", &ArmCapacityResult::load)
      .def_readonly("limit", &ArmCapacityResult::limit)
      .def_readonly("tendon", &ArmCapacityResult::tendon)
      .def_readonly("module", &ArmCapacityResult::module)
      .def_readonly("path", &ArmCapacityResult::path)
      .def_readonly("message", &ArmCapacityResult::message);
  m.def(
      "arm_load_capacity",
      [](ArmSolver& s, const ArmState& start, const Vector3& direction, double max_load) {
        return unlocked([&] { return arm_load_capacity(s, start, direction, max_load); });
      },
      py::arg("solver"), py::arg("start"), py::arg("direction"), py::arg("max_load"));
}

// One module of the arm switched by its creases (analyses/arm_crease_switching.hpp).
void bind_arm_crease_switch(py::module_& m) {
  using R = ArmCreaseSwitchResult;
  py::class_<R> c(m, "ArmCreaseSwitchResult",
                  "A module switched by its creases (read-only; kresling.arm reads it)");
  field(c, "module", &R::module, "the driven module, 0-based from the base");
  field(c, "forward", &R::forward, "extended -> contracted (False: the other way)");
  field(c, "let_out", &R::let_out, "tendon let-out [mm]");
  field(c, "hinges", &R::hinges, "the driven hinges");
  field(c, "scan", &R::scan, "the crease path (heights: the module's length)");
  field(c, "start", &R::start, "the built arm");
  field(c, "snap", &R::snap, "the last state on the start branch (actuated)");
  field(c, "after", &R::after, "where the released arm rests");
  field(c, "configuration_before", &R::configuration_before, "module states before");
  field(c, "configuration_after", &R::configuration_after, "after ('x': half-switched)");
  m.def(
      "arm_crease_switch",
      [](const Design& design, const std::vector<int>& states,
         const model::ArmParameters& parameters, int module, const std::vector<int>& cells,
         const VectorX& start, bool extend, const std::string& group,
         double scan_step, double max_change, double resolution, double overshoot,
         double tolerance, int max_iterations, double let_out) {
        ArmCreaseSwitchOptions o;
        const char* names[] = {"valley", "mountain", "polygon", "fold"};
        const CreaseGroup groups[] = {CreaseGroup::Valley, CreaseGroup::Mountain,
                                      CreaseGroup::PolygonEdge, CreaseGroup::Folds};
        bool known = false;
        for (int k = 0; k < 4; ++k) {
          if (group == names[k]) o.group = groups[k], known = true;
        }
        if (!known) {
          throw std::invalid_argument("group = '" + group + "' is invalid: must be 'valley', "
                                      "'mountain', 'polygon' or 'fold'");
        }
        o.scan.scan_step = scan_step, o.scan.max_change = max_change;
        o.scan.resolution = resolution, o.scan.overshoot = overshoot;
        o.scan.newton.tolerance = tolerance, o.scan.newton.max_iterations = max_iterations;
        o.let_out = let_out;
        return unlocked(
            [&] { return arm_crease_switch(design, states, parameters, module, cells, start, extend, o); });
      },
      py::arg("design"), py::arg("states"), py::arg("parameters"), py::arg("module"),
      py::arg("cells"), py::arg("start"), py::arg("extend"), py::arg("group"), py::arg("scan_step"), py::arg("max_change"), py::arg("resolution"),
      py::arg("overshoot"), py::arg("tolerance"), py::arg("max_iterations"), py::arg("let_out"));
}

}  // namespace

void bind_analyses(py::module_& m) {
  bind_bending_result(m);
  bind_snap_result(m);
  bind_arm_analysis(m);
  bind_switching(m);
  bind_arm_crease_switch(m);
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
          [](analyses::BendingTest& test, const std::vector<std::array<double, 3>>& designs) {
            // A sweep's chunk in one call, the GIL released throughout: per design (lam, Lc,
            // R) the extended then the contracted run, exactly as two run() calls, keeping
            // only what the K_B-ratio metric reads. A design whose construction or run throws
            // (bad input) gets ok = false and is left to the caller to rerun alone, so that
            // its error reads as it would there; an interrupt is not caught.
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
          },
          py::arg("designs"),
          "Per design (lam, Lc, R): (K_ext, K_con, iterations summed over both runs, "
          "extended completed, its message, contracted completed, its message), or None "
          "where the design or a run raised (rerun it alone for the error).");

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
  // The linearised bending test (kresling.analyses.LinearBendingTester wraps it): runs
  // without the GIL, so threads of a sweep evaluate designs in parallel.
  py::class_<analyses::LinearBendingTest>(m, "LinearBendingTest")
      .def(py::init<int, int, SpecimenParameters>(), py::arg("n"), py::arg("cells"),
           py::arg("parameters"))
      .def(
          "run",
          [](analyses::LinearBendingTest& test, const Design& design, int state, double angle,
             double pin_offset) {
            analyses::LinearBendingResult r;
            {
              py::gil_scoped_release release;
              r = test.run(design, state, angle, pin_offset);
            }
            return py::make_tuple(r.stiffness, r.condensed_force, r.cancelled);
          },
          py::arg("design"), py::arg("state"), py::arg("angle"), py::arg("pin_offset"),
          "(K_B [N m/rad], condensed force F [N/mm], e^T K_pp e [N/mm] of which F is the "
          "remainder).");
  m.def("check_snap_design", &analyses::check_snap_design, py::arg("design"));
  m.def("check_bending_state", &analyses::check_bending_state, py::arg("design"),
        py::arg("state"));

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
