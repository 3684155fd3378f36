// kresling._core.analyses: what kresling/analyses/switching.hpp declares.
#include "analyses/analyses_bindings.hpp"
#include "kresling/analyses/switching.hpp"

namespace kresling::python {

namespace {

// The crease-actuated switch of one cell (analyses/switching.hpp).
void bind_crease_switch(py::module_& m) {
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

}  // namespace

void bind_switching(py::module_& m) {
  bind_crease_switch(m);
}

}  // namespace kresling::python
