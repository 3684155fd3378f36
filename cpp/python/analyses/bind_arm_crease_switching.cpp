// kresling._core.analyses: what kresling/analyses/arm_crease_switching.hpp declares.
#include "analyses/analyses_bindings.hpp"
#include "kresling/analyses/arm_crease_switching.hpp"
#include "kresling/analyses/linear_bending.hpp"

namespace kresling::python {

namespace {

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

void bind_arm_crease_switching(py::module_& m) {
  bind_arm_crease_switch(m);
}

}  // namespace kresling::python
